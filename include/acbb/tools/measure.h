/* acbb — the one clock and the one median every timing in acbb uses. */
#ifndef ACBB_MEASURE_H
#define ACBB_MEASURE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Monotonic wall clock, milliseconds (CLOCK_MONOTONIC). */
double acbb_now_ms(void);

/* Median of n values; sorts v in place. 0 for n == 0. */
double acbb_median(double *v, size_t n);

#ifdef __cplusplus
}
#endif

#endif
