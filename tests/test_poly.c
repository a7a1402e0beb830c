/* Real roots of polynomials (src/core/poly.c): known roots, clustered and double roots, leading-zero
 * deflation, degree 8 with wide coefficient ranges, closed forms against the GSL reference path, the
 * derivative-chain fast path (degree 5..8) against GSL on six random families and on
 * circle-circle-like polynomials, with every GSL root refined in long double as the reference. */
#include "test_util.h"
#include "core/poly.h"
#include "../bench/poly_ref.h"
#include <float.h>

/* Coefficients (constant first) of prod (x - r_i) * prod over pairs (x^2 - 2 re x + re^2 + im^2). */
static int build_poly(const double *real, int nr, const double *cre, const double *cim, int nc, double lead,
                      double c[9])
{
    long double p[9] = {0};
    p[0] = lead;
    int deg = 0;
    for (int i = 0; i < nr; ++i) { /* multiply by (x - r) */
        for (int k = deg + 1; k >= 1; --k) p[k] = p[k - 1] - real[i] * p[k];
        p[0] = -real[i] * p[0];
        ++deg;
    }
    for (int i = 0; i < nc; ++i) { /* multiply by x^2 + b x + q */
        long double b = -2.0L * cre[i], q = (long double)cre[i] * cre[i] + (long double)cim[i] * cim[i];
        for (int k = deg + 2; k >= 0; --k)
            p[k] = (k >= 2 ? p[k - 2] : 0) + b * (k >= 1 ? p[k - 1] : 0) + q * (k <= deg ? p[k] : 0);
        deg += 2;
    }
    for (int k = 0; k <= 8; ++k) c[k] = k <= deg ? (double)p[k] : 0.0;
    return deg;
}

/* Every expected root is within tol*max(1,|r|) of a reported one and every reported root of an
 * expected one. */
static void check_roots(const double *got, int ngot, const double *want, int nwant, double tol)
{
    for (int i = 0; i < nwant; ++i) {
        double best = INFINITY;
        for (int j = 0; j < ngot; ++j) best = fmin(best, fabs(got[j] - want[i]));
        if (!(best <= tol * fmax(1.0, fabs(want[i])))) {
            print_error("root %.17g missing (nearest at %.3g), %d reported\n", want[i], best, ngot);
            fail();
        }
    }
    for (int j = 0; j < ngot; ++j) {
        double best = INFINITY;
        for (int i = 0; i < nwant; ++i) best = fmin(best, fabs(got[j] - want[i]));
        if (!(best <= tol * fmax(1.0, fabs(got[j])))) {
            print_error("spurious root %.17g (nearest expected at %.3g)\n", got[j], best);
            fail();
        }
    }
    for (int j = 1; j < ngot; ++j) assert_true(got[j - 1] <= got[j]);
}

static void test_poly_known(void **state)
{
    (void)state;
    double r[8], n;
    int cnt;
    const double lin[2] = {-3, 2};
    assert_int_equal(prox_poly_real_roots(lin, 1, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 1);
    assert_near(r[0], 1.5, 1e-15);
    const double quad[3] = {2, -3, 1}; /* (x-1)(x-2) */
    assert_int_equal(prox_poly_real_roots(quad, 2, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 2);
    assert_near(r[0], 1, 1e-15);
    assert_near(r[1], 2, 1e-15);
    const double cub[4] = {-6, 11, -6, 1}; /* (x-1)(x-2)(x-3) */
    assert_int_equal(prox_poly_real_roots(cub, 3, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 3);
    for (int i = 0; i < 3; ++i) assert_near(r[i], i + 1, 1e-14);
    const double qua[5] = {24, -50, 35, -10, 1}; /* (x-1)(x-2)(x-3)(x-4) */
    assert_int_equal(prox_poly_real_roots(qua, 4, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 4);
    for (int i = 0; i < 4; ++i) assert_near(r[i], i + 1, 1e-14);
    const double cplx[5] = {1, 0, 0, 0, 1}; /* x^4 + 1: no real roots */
    assert_int_equal(prox_poly_real_roots(cplx, 4, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 0);
    /* Wilkinson-like degree 8: (x-1)...(x-8). */
    double want[8], c[9];
    for (int i = 0; i < 8; ++i) want[i] = i + 1;
    build_poly(want, 8, NULL, NULL, 0, 1.0, c);
    assert_int_equal(prox_poly_real_roots(c, 8, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 8);
    for (int i = 0; i < 8; ++i) assert_near(r[i], want[i], 1e-11);
    n = prox_poly_eval(qua, 4, 5.0, &r[0]);
    assert_near(n, 24.0, 0);
    assert_near(r[0], 4 * 125 - 30 * 25 + 70 * 5 - 50, 0);
}

static void test_poly_bad_input(void **state)
{
    (void)state;
    double c[10] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, r[9];
    int cnt = -1;
    assert_int_equal(prox_poly_real_roots(c, 9, r, &cnt), PROX_EINVAL_ARG);
    assert_int_equal(prox_poly_real_roots(c, -1, r, &cnt), PROX_EINVAL_ARG);
    assert_int_equal(prox_poly_real_roots(NULL, 2, r, &cnt), PROX_EINVAL_ARG);
    assert_int_equal(prox_poly_real_roots_gsl(c, 2, NULL, &cnt), PROX_EINVAL_ARG);
    c[1] = NAN;
    assert_int_equal(prox_poly_real_roots(c, 2, r, &cnt), PROX_EINVAL_NONFINITE);
    c[1] = INFINITY;
    assert_int_equal(prox_poly_real_roots_gsl(c, 6, r, &cnt), PROX_EINVAL_NONFINITE);
    const double zero[5] = {0, 0, 0, 0, 0}, cst[3] = {2, 0, 0};
    assert_int_equal(prox_poly_real_roots(zero, 4, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 0);
    assert_int_equal(prox_poly_real_roots(cst, 2, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 0);
}

/* Leading coefficients negligible relative to the rest deflate the degree instead of producing
 * huge or NaN roots; the remaining roots are exact. */
static void test_poly_deflation(void **state)
{
    (void)state;
    double c[9] = {2, -3, 1, 1e-300, -1e-290, 0, 0, 0, 1e-30}, r[8];
    int cnt;
    for (int deg = 3; deg <= 8; ++deg) {
        assert_int_equal(prox_poly_real_roots(c, deg, r, &cnt), PROX_OK);
        assert_int_equal(cnt, 2);
        assert_near(r[0], 1, 1e-14);
        assert_near(r[1], 2, 1e-14);
        assert_int_equal(prox_poly_real_roots_gsl(c, deg, r, &cnt), PROX_OK);
        assert_int_equal(cnt, 2);
        assert_near(r[0], 1, 1e-14);
        assert_near(r[1], 2, 1e-14);
    }
    /* Not negligible: x^3 + x^2 + 1e-60 keeps its root near -1 (tiny constant, not tiny leading). */
    const double t3[4] = {1e-60, 0, 1, 1};
    assert_int_equal(prox_poly_real_roots(t3, 3, r, &cnt), PROX_OK);
    assert_true(cnt >= 1);
    assert_near(r[0], -1, 1e-14);
    /* Not negligible either: all roots near 100..700 make c_8 = 1.5 tiny next to c_0 = 3e15 but
     * dominant at the roots (a plain max-coefficient test would deflate it). */
    const double w8[8] = {100, 200, -300, 400, 500, -600, 700, 150};
    double c8[9];
    build_poly(w8, 8, NULL, NULL, 0, 1.5, c8);
    assert_int_equal(prox_poly_real_roots(c8, 8, r, &cnt), PROX_OK);
    check_roots(r, cnt, w8, 8, 1e-9);
    /* A huge common factor is harmless (scaled by a power of two). */
    double h[5] = {24e300, -50e300, 35e300, -10e300, 1e300};
    assert_int_equal(prox_poly_real_roots(h, 4, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 4);
    for (int i = 0; i < 4; ++i) assert_near(r[i], i + 1, 1e-13);
}

/* Double roots (the touching case) are never lost, whether rounding makes them a tight real pair
 * or a complex pair with a tiny imaginary part. Both paths. */
static void test_poly_double_roots(void **state)
{
    (void)state;
    double c[9], r[8];
    int cnt;
    for (int deg = 2; deg <= 8; ++deg) {
        for (int trial = 0; trial < 40; ++trial) {
            double want[8];
            test_rng g = test_rng_seed(1000u * (unsigned)deg + (unsigned)trial);
            want[0] = want[1] = test_range(&g, -3, 3) + 0.1 * trial; /* the double root */
            for (int i = 2; i < deg; ++i) want[i] = want[0] + (i % 2 ? 1 : -1) * test_range(&g, 0.5, 4);
            build_poly(want, deg, NULL, NULL, 0, test_range(&g, 0.5, 2), c);
            /* Nudge the constant term by a few ulps either way: a real pair or a complex pair. */
            c[0] += (trial % 3 - 1) * 4 * DBL_EPSILON * fabs(c[0]);
            assert_int_equal(prox_poly_real_roots(c, deg, r, &cnt), PROX_OK);
            check_roots(r, cnt, want, deg, 2e-6);
            assert_int_equal(prox_poly_real_roots_gsl(c, deg, r, &cnt), PROX_OK);
            check_roots(r, cnt, want, deg, 2e-6);
        }
    }
    /* x^2 - 2x + 1 + 1e-20: complex pair 1 +- 1e-10 i, a touching contact -> root 1. */
    const double q[3] = {1 + 1e-20, -2, 1};
    assert_int_equal(prox_poly_real_roots(q, 2, r, &cnt), PROX_OK);
    assert_true(cnt >= 1);
    assert_near(r[0], 1, 1e-9);
    /* A clear complex pair (x^2 - 2x + 1.01) is not reported. */
    const double q2[3] = {1.01, -2, 1};
    assert_int_equal(prox_poly_real_roots(q2, 2, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 0);
}

/* Clustered roots 1, 1 + 1e-4, 1 - 1e-4 and a triple-ish cluster: all found. */
static void test_poly_clustered(void **state)
{
    (void)state;
    double c[9], r[8];
    int cnt;
    const double w3[3] = {1, 1 + 1e-4, 1 - 1e-4};
    build_poly(w3, 3, NULL, NULL, 0, 1, c);
    assert_int_equal(prox_poly_real_roots(c, 3, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 3);
    check_roots(r, cnt, w3, 3, 1e-6); /* condition ~ eps / p'(r) = 1e-16 / 2e-8 */
    const double w6[6] = {2, 2 + 1e-3, 2 - 1e-3, -1, 5, 7};
    const double cre[1] = {0.5}, cim[1] = {2};
    build_poly(w6, 6, cre, cim, 1, 3, c);
    assert_int_equal(prox_poly_real_roots(c, 8, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 6);
    check_roots(r, cnt, w6, 6, 1e-7);
    const double w4[4] = {0.3, 0.3 + 1e-5, 4, -2};
    build_poly(w4, 4, NULL, NULL, 0, 1, c);
    assert_int_equal(prox_poly_real_roots(c, 4, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 4);
    check_roots(r, cnt, w4, 4, 1e-9);
}

/* Random polynomials of every degree with separated real roots over several decades and complex
 * pairs away from the real axis: exactly the real roots, to 1e-10 relative, through both paths. */
static void test_poly_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(42);
    double c[9], r[8], want[8], cre[4], cim[4];
    int cnt;
    for (int trial = 0; trial < 20000; ++trial) {
        int deg = 1 + trial % 8;
        int nc = (int)(test_uniform(&g) * (deg / 2 + 1));
        int nr = deg - 2 * nc;
        double decades = trial % 2 ? 3.0 : 1.0;
        for (int i = 0; i < nr; ++i) {
            for (;;) {
                want[i] = (test_uniform(&g) < 0.5 ? -1 : 1) * pow(10.0, test_range(&g, -decades, decades));
                int ok = 1;
                for (int j = 0; j < i; ++j)
                    if (fabs(want[i] - want[j]) < 0.05 * fmax(fabs(want[i]), fabs(want[j]))) ok = 0;
                if (ok) break;
            }
        }
        for (int i = 0; i < nc; ++i) {
            cre[i] = test_range(&g, -3, 3);
            cim[i] = test_range(&g, 0.3, 3) * fmax(1.0, fabs(cre[i]));
        }
        build_poly(want, nr, cre, cim, nc, pow(10.0, test_range(&g, -3, 3)), c);
        assert_int_equal(prox_poly_real_roots(c, deg, r, &cnt), PROX_OK);
        if (cnt != nr) {
            print_error("trial %d degree %d: %d real roots, %d expected\n", trial, deg, cnt, nr);
            for (int k = 0; k <= deg; ++k) print_error(" c%d=%.17g", k, c[k]);
            for (int k = 0; k < nr; ++k) print_error(" r%d=%.17g", k, want[k]);
            for (int k = 0; k < nc; ++k) print_error(" z%d=%.17g+%.17gi", k, cre[k], cim[k]);
            print_error("\n");
        }
        assert_int_equal(cnt, nr);
        check_roots(r, cnt, want, nr, 1e-10);
        assert_int_equal(prox_poly_real_roots_gsl(c, deg, r, &cnt), PROX_OK);
        assert_int_equal(cnt, nr);
        check_roots(r, cnt, want, nr, 1e-10);
    }
}

/* Degree 8 with coefficients spanning many decades (roots from 1e-4 to 1e4): both paths agree and
 * every root has a tiny residual relative to the evaluation scale. */
static void test_poly_wide_degree8(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(7);
    double c[9], r[8], want[8];
    int cnt;
    for (int trial = 0; trial < 2000; ++trial) {
        for (int i = 0; i < 8; ++i) want[i] = (i % 2 ? -1 : 1) * pow(10.0, -4 + i + test_range(&g, 0, 0.5));
        build_poly(want, 8, NULL, NULL, 0, 1, c);
        assert_int_equal(prox_poly_real_roots(c, 8, r, &cnt), PROX_OK);
        assert_int_equal(cnt, 8);
        check_roots(r, cnt, want, 8, 1e-9);
        /* Random dense coefficients over 1e-6..1e6: every reported root is a root. */
        for (int k = 0; k <= 8; ++k) c[k] = (test_uniform(&g) < 0.5 ? -1 : 1) * pow(10.0, test_range(&g, -6, 6));
        assert_int_equal(prox_poly_real_roots(c, 8, r, &cnt), PROX_OK);
        double r2[8];
        int cnt2;
        assert_int_equal(prox_poly_real_roots_gsl(c, 8, r2, &cnt2), PROX_OK);
        assert_int_equal(cnt, cnt2);
        for (int j = 0; j < cnt; ++j) {
            double s = 0, ax = fabs(r[j]);
            for (int k = 8; k >= 0; --k) s = s * ax + fabs(c[k]);
            assert_true(fabs(prox_poly_eval(c, 8, r[j], NULL)) <= 1e-12 * s);
            assert_near(r[j], r2[j], 1e-12 * fmax(1, fabs(r[j])));
        }
    }
}

/* Closed-form quartics and cubics against the GSL QR reference on random dense coefficients. */
static void test_poly_closed_vs_gsl(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(99);
    double c[5], r[4], r2[4];
    int cnt, cnt2, mism = 0;
    for (int trial = 0; trial < 100000; ++trial) {
        int deg = 3 + trial % 2;
        for (int k = 0; k <= deg; ++k) c[k] = test_range(&g, -1, 1) * pow(10.0, test_range(&g, -2, 2));
        assert_int_equal(prox_poly_real_roots(c, deg, r, &cnt), PROX_OK);
        assert_int_equal(prox_poly_real_roots_gsl(c, deg, r2, &cnt2), PROX_OK);
        if (cnt != cnt2) { /* allowed only for a near-double root reported once vs twice */
            ++mism;
            continue;
        }
        for (int j = 0; j < cnt; ++j) assert_near(r[j], r2[j], 1e-9 * fmax(1, fabs(r[j])));
    }
    assert_true(mism <= 5);
}

/* ---- Fast path (derivative chain, degree 5..8) against the GSL reference path --------------- */

/* The root of the double polynomial next to r, by long-double Newton (poly_ref.h), and its
 * attainable accuracy in double: 64 deg eps sum |c_k| |r|^k / |p'(r)| (infinite at a double root). */
static double refine_ld(const double *c, int deg, double r0, double *attain)
{
    long double p, d, s, x = poly_ref_newton(c, deg, r0, &p, &d, &s);
    *attain = d != 0 ? (double)(64.0L * deg * DBL_EPSILON * s / fabsl(d)) : INFINITY;
    return (double)x;
}

/* Largest error allowed for a root r with attainable accuracy `attain`: 1e-12 relative, or the
 * rounding level when the root is worse conditioned than that. */
static double root_tol(double r, double attain) { return fmax(1e-12 * fabs(r), attain); }

/* The reported root nearest to x (x itself when none). */
static double nearest(const double *r, int n, double x)
{
    double best = x, bd = INFINITY;
    for (int j = 0; j < n; ++j)
        if (fabs(r[j] - x) < bd) bd = fabs(r[j] - x), best = r[j];
    return best;
}

/* Is p within its rounding level 64 deg eps sum |c_k| |y|^k at 9 points of [a, b]? Then double
 * precision cannot tell a root at a from one at b (a root cluster at the noise level). */
static int numerically_zero(const double *c, int deg, double a, double b)
{
    for (int k = 0; k <= 8; ++k) {
        long double y = a + (b - (long double)a) * k / 8, d, s, p = poly_ref_eval(c, deg, y, &d, &s);
        if (!(fabsl(p) <= 64.0L * deg * DBL_EPSILON * s)) return 0;
    }
    return 1;
}

/* Distinct values of a sorted list (closer than 1e-6 relative counts once). */
static int distinct_roots(const double *r, int n)
{
    int d = 0;
    for (int k = 0; k < n; ++k) d += k == 0 || fabs(r[k] - r[k - 1]) > 1e-6 * fmax(1.0, fabs(r[k]));
    return d;
}

/* Is the reported root set r[0..n) right about the true root ref: some reported root within
 * root_tol of it, or p numerically zero between ref and the nearest reported root? Returns the
 * error relative to root_tol (0 when unresolvable noise), or INFINITY when ref is missed. */
static double match(const double *c, int deg, const double *r, int n, double ref, double attain)
{
    double x = nearest(r, n, ref), tol = root_tol(ref, attain), e = fabs(x - ref);
    if (n > 0 && isfinite(tol) && e <= tol) return e / tol;
    return n > 0 && numerically_zero(c, deg, ref, x) ? 0.0 : INFINITY;
}

/* Compares the fast path with the GSL path on c (degree deg) against the true real roots: the
 * construction roots want[0..nw) refined in long double on the double coefficients, or, when want
 * is NULL, the refined roots of both paths where p vanishes to the rounding level. Every true root must be matched by the fast path
 * (match()), and every fast root must match a true root or be a touching root (|p| at the 1e-10
 * level of a near-double root). *worst_fast, *worst_gsl: worst error / root_tol of each path;
 * *gsl_miss counts true roots GSL misses and GSL roots that are not roots. Returns the fast minus the GSL count of distinct roots
 * (1e-6 apart: a multiple root reported once or several times counts once). */
static int fast_vs_gsl(const double *c, int deg, const double *want, int nw, double *worst_fast, double *worst_gsl,
                       int *gsl_miss)
{
    double rf[8], rg[8], ref[16], att[16];
    int nf = -1, ng = -1, nref = 0;
    assert_int_equal(prox_poly_real_roots_fast(c, deg, rf, &nf), PROX_OK);
    assert_int_equal(prox_poly_real_roots_gsl(c, deg, rg, &ng), PROX_OK);
    for (int j = 1; j < nf; ++j) assert_true(rf[j - 1] <= rf[j]);
    const double *src = want ? want : rg;
    int ns = want ? nw : ng;
    for (int pass = 0; pass < (want ? 1 : 2); ++pass, src = rf, ns = nf)
        for (int i = 0; i < ns; ++i) {
            double a, x = refine_ld(c, deg, src[i], &a);
            long double d, s, p = poly_ref_eval(c, deg, x, &d, &s);
            int dup = 0;
            for (int k = 0; k < nref; ++k) dup |= fabs(ref[k] - x) <= 1e-9 * fabs(x);
            /* a path's root is a true root only where p vanishes to the rounding level */
            if (want || (!dup && fabsl(p) <= 64.0L * deg * DBL_EPSILON * s)) ref[nref] = x, att[nref++] = a;
        }
    *worst_fast = *worst_gsl = 0;
    for (int i = 0; i < nref; ++i) {
        double ef = match(c, deg, rf, nf, ref[i], att[i]), eg = match(c, deg, rg, ng, ref[i], att[i]);
        if (isfinite(eg)) *worst_gsl = fmax(*worst_gsl, eg);
        else ++*gsl_miss;
        *worst_fast = fmax(*worst_fast, ef);
        if (!isfinite(ef)) {
            print_error("degree %d: root %.17g (tol %.3g) missed, nearest fast root %.17g\n", deg, ref[i],
                        root_tol(ref[i], att[i]), nearest(rf, nf, ref[i]));
            for (int k = 0; k <= deg; ++k) print_error(" c%d=%.17g", k, c[k]);
            print_error("\n");
            fail();
        }
    }
    for (int j = 0; j < ng; ++j) { /* GSL roots that are not roots (seen with tiny leading terms) */
        long double d, s, p = poly_ref_eval(c, deg, rg[j], &d, &s);
        *gsl_miss += !(fabsl(p) <= 1e-10L * s);
    }
    for (int j = 0; j < nf; ++j) {
        int ok = 0;
        for (int i = 0; i < nref && !ok; ++i) ok = isfinite(match(c, deg, &rf[j], 1, ref[i], att[i]));
        long double d, s, p = poly_ref_eval(c, deg, rf[j], &d, &s);
        if (!ok && !(fabsl(p) <= 1e-10L * s)) {
            print_error("degree %d: fast root %.17g not a root (|p| = %.3Lg of %.3Lg)\n", deg, rf[j], fabsl(p), s);
            for (int k = 0; k <= deg; ++k) print_error(" c%d=%.17g", k, c[k]);
            print_error("\n");
            fail();
        }
    }
    return distinct_roots(rf, nf) - distinct_roots(rg, ng);
}

/* Builds a random polynomial of degree deg from a family; returns the number of its real roots
 * written to want[] (with multiplicity), -1 when they are not known. Families: 0 separated roots spread 1e-4..1e4 with complex
 * pairs; 1 a cluster of 2-3 roots 1e-6..1e-3 apart; 2 an exact double root; 3 a near-double root
 * (a real pair or a complex pair 1e-9..1e-6 apart); 4 dense random coefficients over 1e-6..1e6;
 * 5 a tiny leading coefficient (deflated or not). */
static int random_family(test_rng *g, int fam, int deg, double c[9], double want[8])
{
    double cre[4], cim[4];
    int nr = 0, nc = 0;
    const double lead = pow(10.0, test_range(g, -3, 3));
    if (fam == 4) {
        for (int k = 0; k <= deg; ++k) c[k] = (test_uniform(g) < 0.5 ? -1 : 1) * pow(10.0, test_range(g, -6, 6));
        for (int k = deg + 1; k <= 8; ++k) c[k] = 0;
        return -1;
    }
    int d = fam == 5 ? deg - 1 - (int)(test_uniform(g) * 2) : deg; /* 5: the roots of a lower degree */
    const double base = (test_uniform(g) < 0.5 ? -1 : 1) * pow(10.0, test_range(g, -4, 4));
    if (fam == 1) { /* cluster */
        double delta = pow(10.0, test_range(g, -6, -3));
        int k = 2 + (test_uniform(g) < 0.5);
        for (int i = 0; i < k; ++i) want[nr++] = base * (1 + i * delta);
    } else if (fam == 2) {
        want[nr++] = base, want[nr++] = base;
    } else if (fam == 3) {
        double delta = pow(10.0, test_range(g, -9, -6));
        if (test_uniform(g) < 0.5) {
            want[nr++] = base * (1 - delta), want[nr++] = base * (1 + delta);
        } else {
            cre[nc] = base, cim[nc++] = fabs(base) * delta;
        }
    }
    while (nr + 2 * nc < d) {
        if (d - nr - 2 * nc >= 2 && test_uniform(g) < 0.3) {
            cre[nc] = (test_uniform(g) < 0.5 ? -1 : 1) * pow(10.0, test_range(g, -4, 4));
            cim[nc] = fabs(cre[nc]) * test_range(g, 0.1, 3);
            ++nc;
            continue;
        }
        for (;;) { /* separated from the others by 5 % */
            double r = (test_uniform(g) < 0.5 ? -1 : 1) * pow(10.0, test_range(g, -4, 4));
            int ok = 1;
            for (int j = 0; j < nr; ++j)
                if (fabs(r - want[j]) < 0.05 * fmax(fabs(r), fabs(want[j]))) ok = 0;
            if (ok) {
                want[nr++] = r;
                break;
            }
        }
    }
    build_poly(want, nr, cre, cim, nc, lead, c);
    if (fam == 5) { /* leading terms tiny relative to the largest coefficient */
        double big = 0;
        for (int k = 0; k <= d; ++k) big = fmax(big, fabs(c[k]));
        for (int k = d + 1; k <= deg; ++k) c[k] = (test_uniform(g) < 0.5 ? -1 : 1) * big * pow(10.0, test_range(g, -20, -13));
        return -1; /* the tiny terms may add huge roots: the reference is both paths' roots */
    }
    return nr;
}

/* 60000 random polynomials of degree 5..8 in six families through both paths (fast_vs_gsl): the
 * fast path finds every true root to 1e-12 relative or its rounding level and reports no non-root;
 * the printed figures show GSL's misses and worst errors beside it. */
static void test_poly_fast_vs_gsl(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(2024);
    double c[9], want[8];
    int diff_count[6] = {0}, n[6] = {0}, miss[6] = {0};
    double wf[6] = {0}, wg[6] = {0};
    for (int trial = 0; trial < 60000; ++trial) {
        int fam = trial % 6, deg = 5 + (trial / 6) % 4;
        int nw = random_family(&g, fam, deg, c, want);
        double ef, eg;
        int dc = fast_vs_gsl(c, deg, nw >= 0 ? want : NULL, nw, &ef, &eg, &miss[fam]);
        if (dc != 0) ++diff_count[fam];
        ++n[fam];
        wf[fam] = fmax(wf[fam], ef), wg[fam] = fmax(wg[fam], eg);
    }
    for (int f = 0; f < 6; ++f)
        print_message("family %d: %d polynomials, %d count differences, GSL misses/spurious %d, worst error / tol fast %.3g "
                      "gsl %.3g\n",
                      f, n[f], diff_count[f], miss[f], wf[f], wg[f]);
    /* Separated roots: the same distinct roots. Elsewhere the distinct counts differ where a cluster
     * is at the noise level (QR splits it its way; the fast path reports the centre and the two ends
     * of the noise zone) or GSL's QR is wrong (misses and non-roots counted above); fast_vs_gsl has
     * already failed on any fast-path error. */
    assert_int_equal(diff_count[0], 0);
    assert_true(diff_count[2] <= n[2] / 100);
    assert_true(diff_count[1] <= n[1] / 2 && diff_count[3] <= n[3] / 50);
    assert_true(diff_count[4] <= n[4] / 1000 && diff_count[5] <= n[5] / 100);
    for (int f = 0; f < 6; ++f) assert_true(wf[f] <= 1.0); /* every matched root within root_tol */
}

/* Coefficients of the circle-circle stationarity polynomial F(t) of src/distance/circle_circle.c,
 * rebuilt here independently from its definition: with P = (cos th, sin th, 0), t = tan(th/2),
 * D = P - C, A = C.P', B = N.P', dn = N.D, R = |D x N|^2, F = A^2 R - r^2 (A (1 + t^2) + dn B)^2
 * times (1 + t^2)^4, each trig-linear k0 + kc cos + ks sin as k0 (1 + t^2) + kc (1 - t^2) + 2 ks t. */
static void cc_like_poly(test_rng *g, double F[9])
{
    long double cx = test_range(g, -3, 3), cy = test_range(g, -3, 3), cz = test_range(g, -2, 2);
    prox_vec3 nv = test_unit(g);
    long double nx = nv.x, ny = nv.y, nz = nv.z, r = pow(10.0, test_range(g, -1, 1));
    if (test_uniform(g) < 0.2) cz = 0; /* coplanar-ish and parallel-ish configurations */
    if (test_uniform(g) < 0.1) nx *= 1e-6, ny *= 1e-6, nz = 1;
#define LIN(k0, kc, ks, q) (q[0] = (k0) + (kc), q[1] = 2 * (ks), q[2] = (k0) - (kc))
    long double A[3], B[3], Dn[3], X[3], Y[3], Z[3], one[3] = {1, 0, 1};
    LIN(0, cy, -cx, A);
    LIN(0, ny, -nx, B);
    LIN(-(nx * cx + ny * cy + nz * cz), nx, ny, Dn);
    LIN(-(cy * nz - cz * ny), 0, nz, X);
    LIN(-(cz * nx - cx * nz), -nz, 0, Y);
    LIN(-(cx * ny - cy * nx), ny, -nx, Z);
#undef LIN
    long double R[5] = {0}, A2[5] = {0}, L[5] = {0}, out[9] = {0};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            R[i + j] += X[i] * X[j] + Y[i] * Y[j] + Z[i] * Z[j];
            A2[i + j] += A[i] * A[j];
            L[i + j] += A[i] * one[j] + Dn[i] * B[j];
        }
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) out[i + j] += A2[i] * R[j] - r * r * L[i] * L[j];
    for (int k = 0; k < 9; ++k) F[k] = (double)out[k];
}

/* Circle-circle-like degree-8 polynomials (the callers' case): fast and GSL paths agree. */
static void test_poly_fast_cc_like(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(31337);
    double F[9], wf = 0, wg = 0;
    int diff = 0, miss = 0;
    const int n = 20000;
    for (int trial = 0; trial < n; ++trial) {
        cc_like_poly(&g, F);
        double ef, eg;
        if (fast_vs_gsl(F, 8, NULL, 0, &ef, &eg, &miss) != 0) ++diff;
        wf = fmax(wf, ef), wg = fmax(wg, eg);
    }
    print_message("circle-circle-like: %d polynomials, %d count differences, GSL misses/spurious %d, worst error / tol fast "
                  "%.3g gsl %.3g\n",
                  n, diff, miss, wf, wg);
    assert_true(diff <= n / 100);
}

/* Hand-made degree 5..8 cases of the fast path: an exact double root (touching), a real pair split
 * by rounding, a triple root, roots at 0 and at large |x|, a deflated leading term. */
static void test_poly_fast_special(void **state)
{
    (void)state;
    double c[9], r[8];
    int cnt;
    /* (x - 2)^2 (x + 1)(x - 3)(x - 5)(x^2 + 1): the double root 2 is reported */
    const double w1[5] = {2, 2, -1, 3, 5}, cre[1] = {0}, cim[1] = {1};
    build_poly(w1, 5, cre, cim, 1, 1.0, c);
    assert_int_equal(prox_poly_real_roots_fast(c, 7, r, &cnt), PROX_OK);
    check_roots(r, cnt, w1, 5, 1e-7);
    /* (x^2 - 2x + 1 + 1e-20)(x - 4)(x + 3)(x - 7)(x + 9): a complex pair 1 +- 1e-10 i -> touching at 1 */
    const double w2[4] = {4, -3, 7, -9}, cre2[1] = {1}, cim2[1] = {1e-10};
    build_poly(w2, 4, cre2, cim2, 1, 1.0, c);
    assert_int_equal(prox_poly_real_roots_fast(c, 6, r, &cnt), PROX_OK);
    const double w2all[5] = {4, -3, 7, -9, 1};
    check_roots(r, cnt, w2all, 5, 1e-9);
    /* triple root 1.5 with 0, -2, 10 and 1e4: all found, the triple to its cbrt(eps) level */
    const double w3[7] = {1.5, 1.5, 1.5, 0, -2, 10, 1e4};
    build_poly(w3, 7, NULL, NULL, 0, 0.5, c);
    assert_int_equal(prox_poly_real_roots_fast(c, 7, r, &cnt), PROX_OK);
    check_roots(r, cnt, w3, 7, 1e-4);
    assert_true(cnt >= 5);
    /* x^8 - 1e-32: roots +-1e-4 exactly (c_0 tiny, not negligible) */
    double e8[9] = {-1e-32, 0, 0, 0, 0, 0, 0, 0, 1};
    assert_int_equal(prox_poly_real_roots_fast(e8, 8, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 2);
    assert_near(r[0], -1e-4, 1e-16);
    assert_near(r[1], 1e-4, 1e-16);
    /* x^5 (x - 1e4)(x + 1)(x - 3): the quintuple root 0 is reported, exactly */
    const double w5[8] = {0, 0, 0, 0, 0, 1e4, -1, 3};
    build_poly(w5, 8, NULL, NULL, 0, 2.0, c);
    assert_int_equal(prox_poly_real_roots_fast(c, 8, r, &cnt), PROX_OK);
    check_roots(r, cnt, w5, 8, 1e-12);
    /* degree 8 with c_8 = 1e-300: deflated to the septic, whose 7 roots are found */
    const double w7[7] = {-5, -1, 0.5, 2, 3, 40, 600};
    build_poly(w7, 7, NULL, NULL, 0, 1.0, c);
    c[8] = 1e-300;
    assert_int_equal(prox_poly_real_roots_fast(c, 8, r, &cnt), PROX_OK);
    assert_int_equal(cnt, 7);
    check_roots(r, cnt, w7, 7, 1e-12);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_poly_known),          cmocka_unit_test(test_poly_bad_input),
        cmocka_unit_test(test_poly_deflation),      cmocka_unit_test(test_poly_double_roots),
        cmocka_unit_test(test_poly_clustered),      cmocka_unit_test(test_poly_random),
        cmocka_unit_test(test_poly_wide_degree8),   cmocka_unit_test(test_poly_closed_vs_gsl),
        cmocka_unit_test(test_poly_fast_vs_gsl),    cmocka_unit_test(test_poly_fast_cc_like),
        cmocka_unit_test(test_poly_fast_special),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
