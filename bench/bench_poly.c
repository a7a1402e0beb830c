/* prox_bench group "poly": real roots of polynomials (src/core/poly.c) at degree 4 and 8, the
 * library path (closed-form quartic; GSL companion QR plus polishing at degree 8) against the
 * always-GSL reference path. The polynomials are built from known roots (product of (x - x_k) and
 * of (x^2 - 2 re x + |z|^2) for complex pairs), so the accuracy columns are exact: err = worst
 * |found - true| / max(1, |true|) over the true real roots; a mismatch is a wrong number of
 * distinct real roots found. Simple roots are kept at least 1e-3 apart so both counts are defined. */
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#ifdef PROX_BENCH_HAVE_POLY
#include "core/poly.h"

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

static double q_fast(const void *data, size_t i)
{
    const poly_set *s = data;
    double roots[PROX_POLY_MAX_DEGREE];
    int count = 0;
    prox_poly_real_roots(s->coef + i * (size_t)(s->degree + 1), s->degree, roots, &count);
    return count ? roots[0] : 0.0;
}

static double q_gsl(const void *data, size_t i)
{
    const poly_set *s = data;
    double roots[PROX_POLY_MAX_DEGREE];
    int count = 0;
    prox_poly_real_roots_gsl(s->coef + i * (size_t)(s->degree + 1), s->degree, roots, &count);
    return count ? roots[0] : 0.0;
}

/* Counts distinct values (a near-double root reported twice counts once). */
static int distinct(const double *v, int n)
{
    int d = 0;
    for (int k = 0; k < n; ++k) d += (k == 0 || fabs(v[k] - v[k - 1]) > 1e-9 * (1 + fabs(v[k])));
    return d;
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
        prox_status st = gsl ? prox_poly_real_roots_gsl(c, s->degree, roots, &count)
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

static void add_pair(const bench_opts *o, int degree, size_t n, uint64_t seed)
{
    char name[96];
    snprintf(name, sizeof name, "poly/deg%d", degree);
    if (!bench_selected(o, name)) return;
    poly_set *s = bench_xmalloc(sizeof *s); /* lives until exit */
    *s = make_set(degree, n, seed);
    snprintf(name, sizeof name, "poly/deg%d/%s", degree, degree <= 4 ? "closed" : "fast");
    bench_case *c = bench_add(name, q_fast, s, NULL, n);
    c->acc = poly_accuracy(s, 0), c->has_acc = 1;
    bench_note(c, "prox_poly_real_roots");
    snprintf(name, sizeof name, "poly/deg%d/gsl", degree);
    c = bench_add(name, q_gsl, s, NULL, n);
    c->acc = poly_accuracy(s, 1), c->has_acc = 1;
    bench_note(c, "prox_poly_real_roots_gsl");
}

void bench_group_poly(const bench_opts *o)
{
    size_t n = o->quick ? 2000 : 100000;
    add_pair(o, 4, n, 41);
    add_pair(o, 8, n, 81);
}
#else
void bench_group_poly(const bench_opts *o) { (void)o; }
#endif
