/* prox_bench group "poly": real roots of polynomials (src/core/poly.c) at degree 4 and 8, the
 * library path (closed-form quartic; GSL companion QR plus polishing at degree 8), the opt-in
 * derivative-chain path prox_poly_real_roots_fast (degree 8 only) and the always-GSL reference.
 * deg4/deg8: polynomials built from known roots (product of (x - x_k) and of (x^2 - 2 re x + |z|^2)
 * for complex pairs), so the accuracy columns are exact: err = worst |found - true| / max(1, |true|)
 * over the true real roots; a mismatch is a wrong number of distinct real roots found. Simple roots
 * are kept at least 1e-3 apart so both counts are defined. cc8: the circle-circle stationarity
 * polynomial F(t) of src/distance/circle_circle.c for random circle pairs (rebuilt here from its
 * definition); the true roots are the roots of either path refined by long-double Newton and kept
 * where F vanishes to the rounding level. */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#ifdef PROX_BENCH_HAVE_POLY
#include "core/poly.h"
#include "poly_ref.h"

typedef struct poly_set {
    int degree;
    size_t n;
    double *coef;  /* n x (degree + 1) */
    double *roots; /* n x degree true real roots */
    int *nreal;
} poly_set;

/* Multiplies the polynomial c (degree d) by (x^2 + b x + e) or, when quad == 0, by (x - r). */
static int poly_mul(double *c, int d, int quad, double b, double e)
{
    double t[PROX_POLY_MAX_DEGREE + 1] = {0};
    for (int k = 0; k <= d; ++k) {
        if (quad) {
            t[k] += e * c[k], t[k + 1] += b * c[k], t[k + 2] += c[k];
        } else {
            t[k] += -b * c[k], t[k + 1] += c[k];
        }
    }
    int nd = d + (quad ? 2 : 1);
    memcpy(c, t, (size_t)(nd + 1) * sizeof *c);
    return nd;
}

/* Draws `nreal` distinct real roots in [-3, 3] at least 1e-3 apart. */
static void draw_roots(bench_rng *r, double *x, int nreal)
{
    for (int k = 0; k < nreal; ++k) {
        int ok;
        do {
            x[k] = bench_range(r, -3, 3);
            ok = 1;
            for (int j = 0; j < k; ++j) ok &= fabs(x[k] - x[j]) > 1e-3;
        } while (!ok);
    }
}

/* Builds n polynomials of a degree with a mix of real roots and complex pairs, scaled randomly. */
static poly_set make_set(int degree, size_t n, uint64_t seed)
{
    poly_set s = {degree, n, NULL, NULL, NULL};
    s.coef = bench_xmalloc(n * (size_t)(degree + 1) * sizeof *s.coef);
    s.roots = bench_xmalloc(n * (size_t)degree * sizeof *s.roots);
    s.nreal = bench_xmalloc(n * sizeof *s.nreal);
    bench_rng r = bench_rng_seed(seed);
    for (size_t i = 0; i < n; ++i) {
        int npairs = (int)(bench_rng_next(&r) % (uint64_t)(degree / 2 + 1));
        int nreal = degree - 2 * npairs;
        double *x = s.roots + i * (size_t)degree, *c = s.coef + i * (size_t)(degree + 1);
        draw_roots(&r, x, nreal);
        c[0] = bench_logrange(&r, 1e-3, 1e3); /* leading coefficient */
        int d = 0;
        for (int k = 0; k < nreal; ++k) d = poly_mul(c, d, 0, x[k], 0);
        for (int k = 0; k < npairs; ++k) {
            double re = bench_range(&r, -3, 3), im = bench_range(&r, 0.05, 2);
            d = poly_mul(c, d, 1, -2 * re, re * re + im * im);
        }
        s.nreal[i] = nreal;
    }
    return s;
}

/* Query i of a set through the root finder `solve`, called directly by each timed case below (the
 * constant function pointer is inlined away). */
typedef prox_status (*poly_solver)(const double *c, int degree, double *roots, int *count);
static inline double poly_query(poly_solver solve, const void *data, size_t i)
{
    const poly_set *s = data;
    double roots[PROX_POLY_MAX_DEGREE];
    int count = 0;
    solve(s->coef + i * (size_t)(s->degree + 1), s->degree, roots, &count);
    return count ? roots[0] : 0.0;
}

static double q_fast(const void *data, size_t i) { return poly_query(prox_poly_real_roots, data, i); }
static double q_chain(const void *data, size_t i) { return poly_query(prox_poly_real_roots_fast, data, i); }
static double q_gsl(const void *data, size_t i) { return poly_query(prox_poly_real_roots_gsl, data, i); }

/* Counts distinct values (a near-double root reported twice counts once). */
static int distinct(const double *v, int n)
{
    int d = 0;
    for (int k = 0; k < n; ++k) d += (k == 0 || fabs(v[k] - v[k - 1]) > 1e-9 * (1 + fabs(v[k])));
    return d;
}

/* Adds the long-double Newton refinement of x0 (poly_ref.h) to ref[] when F vanishes there to the
 * rounding level and it is not already listed. */
static void add_ref(const double *c, int deg, double x0, double *ref, int *nref)
{
    long double p, d, s, x = poly_ref_newton(c, deg, x0, &p, &d, &s);
    if (!(fabsl(p) <= 64.0L * deg * DBL_EPSILON * s) || *nref >= deg) return;
    for (int k = 0; k < *nref; ++k)
        if (fabs(ref[k] - (double)x) <= 1e-9 * fmax(1.0, fabs(ref[k]))) return;
    ref[(*nref)++] = (double)x;
}

/* n circle-circle polynomials F(t): circle a the unit circle in z = 0, circle b with centre C,
 * unit normal N and radius r; D = P - C, A = C.P', B = N.P', dn = N.D, R = |D x N|^2,
 * F = A^2 R - r^2 (A (1 + t^2) + dn B)^2 times (1 + t^2)^4 (t = tan(th/2)). */
static poly_set make_cc_set(size_t n, uint64_t seed)
{
    poly_set s = {8, n, NULL, NULL, NULL};
    s.coef = bench_xmalloc(n * 9 * sizeof *s.coef);
    s.roots = bench_xmalloc(n * 8 * sizeof *s.roots);
    s.nreal = bench_xmalloc(n * sizeof *s.nreal);
    bench_rng g = bench_rng_seed(seed);
    for (size_t i = 0; i < n; ++i) {
        double cx = bench_range(&g, -3, 3), cy = bench_range(&g, -3, 3), cz = bench_range(&g, -2, 2);
        prox_vec3 nv = bench_unit(&g);
        double nx = nv.x, ny = nv.y, nz = nv.z, r = bench_logrange(&g, 0.1, 10);
        /* trig-linear k0 + kc cos + ks sin as k0 (1 + t^2) + kc (1 - t^2) + 2 ks t */
        double A[3] = {cy, -2 * cx, -cy}, B[3] = {ny, -2 * nx, -ny};
        double k0 = -(nx * cx + ny * cy + nz * cz);
        double Dn[3] = {k0 + nx, 2 * ny, k0 - nx};
        double kx = cy * nz - cz * ny, ky = cz * nx - cx * nz, kz = cx * ny - cy * nx;
        double X[3] = {-kx, 2 * nz, -kx}, Y[3] = {-ky - nz, 0, -ky + nz}, Z[3] = {-kz + ny, -2 * nx, -kz - ny};
        double one[3] = {1, 0, 1}, R[5] = {0}, A2[5] = {0}, L[5] = {0};
        double *c = s.coef + i * 9;
        for (int k = 0; k < 9; ++k) c[k] = 0;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                R[a + b] += X[a] * X[b] + Y[a] * Y[b] + Z[a] * Z[b];
                A2[a + b] += A[a] * A[b];
                L[a + b] += A[a] * one[b] + Dn[a] * B[b];
            }
        for (int a = 0; a < 5; ++a)
            for (int b = 0; b < 5; ++b) c[a + b] += A2[a] * R[b] - r * r * L[a] * L[b];
        double rf[8], rg[8], *ref = s.roots + i * 8;
        int nf = 0, ng = 0, nref = 0;
        prox_poly_real_roots_fast(c, 8, rf, &nf);
        prox_poly_real_roots_gsl(c, 8, rg, &ng);
        for (int k = 0; k < ng; ++k) add_ref(c, 8, rg[k], ref, &nref);
        for (int k = 0; k < nf; ++k) add_ref(c, 8, rf[k], ref, &nref);
        s.nreal[i] = nref;
    }
    return s;
}

/* Accuracy of one root finder over the whole set, against the construction roots. */
static bench_accuracy poly_accuracy(const poly_set *s, int gsl)
{
    bench_accuracy a = {0, 0, 0, 0, 0, 0};
    double *err = bench_xmalloc(s->n * sizeof *err);
    for (size_t i = 0; i < s->n; ++i) {
        double roots[PROX_POLY_MAX_DEGREE];
        int count = 0;
        const double *c = s->coef + i * (size_t)(s->degree + 1);
        prox_status st = gsl == 1   ? prox_poly_real_roots_gsl(c, s->degree, roots, &count)
                         : gsl == 2 ? prox_poly_real_roots_fast(c, s->degree, roots, &count)
                                    : prox_poly_real_roots(c, s->degree, roots, &count);
        if (st != PROX_OK) ++a.failures;
        if (distinct(roots, count) != s->nreal[i]) ++a.mismatches;
        double worst = 0;
        for (int k = 0; k < s->nreal[i]; ++k) {
            double x = s->roots[i * (size_t)s->degree + (size_t)k], best = INFINITY;
            for (int j = 0; j < count; ++j) best = fmin(best, fabs(roots[j] - x) / fmax(1, fabs(x)));
            worst = fmax(worst, best);
        }
        err[i] = worst;
    }
    a.err_median = bench_quantile(err, s->n, 0.5);
    a.err_p99 = bench_quantile(err, s->n, 0.99);
    a.err_max = err[s->n - 1];
    a.wit_max = NAN;
    free(err);
    return a;
}

/* The cases of one polynomial set: the library path, the derivative chain (degree 8) and GSL. */
static void add_cases(const char *set, poly_set *s)
{
    char name[96];
    snprintf(name, sizeof name, "poly/%s/%s", set, s->degree <= 4 ? "closed" : "lib");
    bench_case *c = bench_add(name, q_fast, s, NULL, s->n);
    c->acc = poly_accuracy(s, 0), c->has_acc = 1;
    bench_note(c, "prox_poly_real_roots");
    if (s->degree > 4) {
        snprintf(name, sizeof name, "poly/%s/chain", set);
        c = bench_add(name, q_chain, s, NULL, s->n);
        c->acc = poly_accuracy(s, 2), c->has_acc = 1;
        bench_note(c, "prox_poly_real_roots_fast");
    }
    snprintf(name, sizeof name, "poly/%s/gsl", set);
    c = bench_add(name, q_gsl, s, NULL, s->n);
    c->acc = poly_accuracy(s, 1), c->has_acc = 1;
    bench_note(c, "prox_poly_real_roots_gsl");
}

static void add_pair(const bench_opts *o, int degree, size_t n, uint64_t seed)
{
    char name[96];
    snprintf(name, sizeof name, "poly/deg%d", degree);
    if (!bench_selected(o, name)) return;
    poly_set *s = bench_xmalloc(sizeof *s); /* lives until exit */
    *s = make_set(degree, n, seed);
    add_cases(name + 5, s);
}

void bench_group_poly(const bench_opts *o)
{
    size_t n = o->quick ? 2000 : 100000;
    add_pair(o, 4, n, 41);
    add_pair(o, 8, n, 81);
    if (bench_selected(o, "poly/cc8")) {
        poly_set *s = bench_xmalloc(sizeof *s);
        *s = make_cc_set(n, 88);
        add_cases("cc8", s);
    }
}
#else
void bench_group_poly(const bench_opts *o) { (void)o; }
#endif
