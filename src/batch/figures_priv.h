/* acbb — shared by src/figures*.c only (not installed). */
#ifndef ACBB_FIGURES_PRIV_H
#define ACBB_FIGURES_PRIV_H

#include <stddef.h>

/* Call fn(ctx, i) once for each i < n on `jobs` threads (0: one per CPU,
 * at most 16; the caller's thread works too), in any order. */
typedef void (*acbb_figures_par_fn)(void *ctx, size_t i);
void acbb_figures_par_for(size_t n, int jobs, acbb_figures_par_fn fn, void *ctx);

#endif
