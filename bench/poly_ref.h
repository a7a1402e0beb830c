/* The long-double reference for real polynomial roots, shared (header-only) by tests/test_poly.c and
 * the "poly" group of prox_bench (bench/bench_poly.c): evaluation with the rounding scale, and
 * Newton refinement of a root of the double coefficients. */
#ifndef PROX_BENCH_POLY_REF_H
#define PROX_BENCH_POLY_REF_H

#include <math.h>

/* p(x), p'(x) (in *d1) and sum |c_k| |x|^k (in *scale, the rounding scale of p) in long double on
 * the double coefficients c[0..deg]. */
static inline long double poly_ref_eval(const double *c, int deg, long double x, long double *d1,
                                        long double *scale)
{
    long double p = c[deg], d = 0, s = fabsl((long double)c[deg]), ax = fabsl(x);
    for (int k = deg - 1; k >= 0; --k) {
        d = d * x + p;
        p = p * x + c[k];
        s = s * ax + fabsl((long double)c[k]);
    }
    *d1 = d;
    *scale = s;
    return p;
}

/* The root of the double polynomial next to x0, by long-double Newton: stops when |p| stops falling
 * or the move would exceed 1e-6 |x0| (so that it stays with the root x0 approximates).  *p, *d1,
 * *scale: poly_ref_eval at the returned point. */
static inline long double poly_ref_newton(const double *c, int deg, double x0, long double *p,
                                          long double *d1, long double *scale)
{
    long double x = x0;
    *p = poly_ref_eval(c, deg, x, d1, scale);
    for (int it = 0; it < 60 && *p != 0 && *d1 != 0; ++it) {
        long double xn = x - *p / *d1, dn, sn, pn = poly_ref_eval(c, deg, xn, &dn, &sn);
        if (!(fabsl(pn) < fabsl(*p)) || !(fabsl(xn - x0) <= 1e-6L * fabsl((long double)x0))) break;
        x = xn, *p = pn, *d1 = dn, *scale = sn;
    }
    return x;
}

#endif
