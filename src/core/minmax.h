/* Internal (core): the least and the largest of two values by comparison. fmin and fmax are library
 * calls (they order NaNs, so the compiler keeps them as calls), which hot loops cannot afford; for
 * values that are not NaN these give the same result. */
#ifndef PROX_CORE_MINMAX_H
#define PROX_CORE_MINMAX_H

static inline double prox_min2(double x, double y) { return x < y ? x : y; }
static inline double prox_max2(double x, double y) { return x > y ? x : y; }

#endif
