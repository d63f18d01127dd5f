/* acbb — ASTM D2270 Table 1: L and H of the reference oils for a 100 C
 * viscosity Y of 2 to 70 mm^2/s (viscosity_index_table.c). */
#ifndef ACBB_VISCOSITY_INDEX_TABLE_H
#define ACBB_VISCOSITY_INDEX_TABLE_H

/* L and H (mm^2/s at 40 C) for Y (mm^2/s at 100 C) by linear
 * interpolation in the table; returns 1, or 0 (L, H untouched) outside
 * 2 <= Y <= 70. */
int acbb_d2270_table(double Y, double *L, double *H);

#endif
