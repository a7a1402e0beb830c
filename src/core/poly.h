/* Internal: real roots of polynomials of degree <= 8.
 * All use of gsl_poly_complex_solve in prox goes through prox_poly_real_roots (src/core/poly.c). */
#ifndef PROX_CORE_POLY_H
#define PROX_CORE_POLY_H

#include "prox/status.h"

#define PROX_POLY_MAX_DEGREE 8

/* Real roots of sum_{k=0}^{degree} c[k] x^k (c[0] the constant term), degree <= 8.
 * - Leading coefficients negligible relative to the largest coefficient deflate the degree
 *   (relative test, never == 0).
 * - Near-real roots (|imag| small relative to the root's size) are accepted and polished by Newton
 *   on the original polynomial; a near-double root is kept (reported once or twice, never lost).
 * - Roots are written to roots[] in increasing order; *count receives how many (<= 8).
 * - A GSL failure (GSL_EFAILED, QR not converging) becomes PROX_ENUMERIC; nothing allocates.
 * Quartics and lower use closed forms (no GSL QR); degree 5..8 use GSL's companion-matrix QR. */
prox_status prox_poly_real_roots(const double *c, int degree, double *roots, int *count);

/* Same contract, degree 5..8 without QR: the real roots only, by the derivative chain (the real
 * roots of p' split the line into monotone pieces of p, recursively; Newton inside each sign-change
 * bracket), about 3x faster at degree 8 and at least as accurate on every real root. A root
 * cluster at the rounding level is reported as its centre plus the two ends of its noise zone; a
 * touching extremum (|p| <= 1e-10 x sum |c_k| |x|^k, no crossing) once. Unlike the QR path it does
 * NOT report the real parts of near-real complex pairs where |p| is only 1e-10-small without a
 * stationary point: circle_circle's trig polish relies on those as extra starts (test_rcc_random
 * fails with this path), hence opt-in. Falls back to the QR path on trouble (a failed bracket). */
prox_status prox_poly_real_roots_fast(const double *c, int degree, double *roots, int *count);

/* Same, always through gsl_poly_complex_solve (the reference path, for tests and bench). */
prox_status prox_poly_real_roots_gsl(const double *c, int degree, double *roots, int *count);

/* Which root finder a caller wants for degree 5..8 (quartics and lower always use closed forms). */
typedef enum prox_root_method {
    PROX_ROOTS_CHAIN = 0, /* prox_poly_real_roots_fast: the derivative chain (fast path's complete search) */
    PROX_ROOTS_GSL        /* prox_poly_real_roots_gsl: GSL's companion-matrix QR (the closed-form method) */
} prox_root_method;

/* Real roots by the chosen finder; same contract as prox_poly_real_roots. */
prox_status prox_poly_real_roots_by(prox_root_method m, const double *c, int degree, double *roots, int *count);

/* Test hook: while `on` is nonzero in the calling thread, every use of GSL's companion-matrix QR
 * reports PROX_ENUMERIC as if the QR had not converged. GSL has no input known to fail on demand, and
 * none could be reached through a cylinder pair, so this is how the tests reach the callers' error
 * paths (status PROX_ENUMERIC). The library never sets it. */
void prox_poly_test_fail_qr(int on);

/* Evaluates the polynomial and its derivative at x (Horner). */
double prox_poly_eval(const double *c, int degree, double x, double *deriv);

#endif
