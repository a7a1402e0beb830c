/* The reference sets of tests/data (format: tests/data/README.md) and the geometry the tests that
 * read them share: the table reader, a cylinder from 7 numbers, the signed distance of a point to a
 * solid cylinder computed independently of the library. */
#ifndef PROX_TEST_REFSETS_H
#define PROX_TEST_REFSETS_H

#include <stdlib.h>

#include "test_util.h"

/* Signed distance from x to the boundary of the solid cylinder (negative inside). */
static inline double cyl_sdf(const prox_rcc *c, prox_vec3 x)
{
    double h = prox_v3_norm(c->axis);
    prox_vec3 w = prox_v3_scale(c->axis, 1.0 / h);
    prox_vec3 d = prox_v3_sub(x, c->base);
    double t = prox_v3_dot(d, w);
    double rho = prox_v3_norm(prox_v3_reject(d, w));
    double dr = rho - c->radius, dt = fmax(-t, t - h);
    if (dr <= 0 && dt <= 0) return fmax(dr, dt);
    return hypot(fmax(dr, 0.0), fmax(dt, 0.0));
}

/* The cylinder given by 7 numbers: base, axis, radius (MCNP's RCC). */
static inline prox_rcc rcc_of(const double *v)
{
    prox_rcc c = {prox_v3(v[0], v[1], v[2]), prox_v3(v[3], v[4], v[5]), v[6]};
    return c;
}

/* Reads whitespace-separated doubles, `per` to a line; returns the number of lines (*out: malloc'd). */
static inline size_t read_table(const char *path, int per, double **out)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        print_error("cannot open %s (the reference sets live in tests/data)\n", path);
        fail();
    }
    size_t cap = 4096, n = 0;
    double *v = malloc(cap * sizeof *v);
    double x;
    while (fscanf(f, "%lf", &x) == 1) {
        if (n == cap) v = realloc(v, (cap *= 2) * sizeof *v);
        v[n++] = x;
    }
    fclose(f);
    assert_int_equal(n % (size_t)per, 0);
    *out = v;
    return n / (size_t)per;
}

/* Reads reference set `name` of tests/data: *P its pairs (14 numbers a line), *R its reference
 * answers (7 a line: sd, p1, p2); returns the number of pairs (the two files agree, and it is > 0). */
static inline size_t load_set(const char *name, double **P, double **R)
{
    char pp[512], rp[512];
    snprintf(pp, sizeof pp, "%s/%s.pairs", PROX_VALIDATION_DIR, name);
    snprintf(rp, sizeof rp, "%s/%s.ref", PROX_VALIDATION_DIR, name);
    size_t n = read_table(pp, 14, P), m = read_table(rp, 7, R);
    assert_int_equal(n, m);
    assert_true(n > 0);
    return n;
}

#endif
