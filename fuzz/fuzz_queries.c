/* libFuzzer harness for the public queries: any bytes -> two shapes -> every query (and, for two
 * cylinders, the distance by the cylinder method chosen by bits 4-5 of the first byte). Contract checked: no crash or hang; an OK status never comes with a NaN; valid shapes of
 * moderate size (|coordinates| <= 1e100) get PROX_OK and finite answers; invalid ones a named error.
 * Byte layout: 1 byte selects the pair kinds (bits 0-1 and 2-3) and the cylinder method (bits 4-5:
 * fast, closed-form, support, fast), then raw IEEE doubles (missing bytes read as zero). */
#include <stdio.h>
#include <string.h>

#include "prox/prox.h"
#include "prox/query.h"
#include "prox/sat.h"
#include "fuzz_common.h"

/* A broken contract prints the condition and its line (so a crash file explains itself), then traps. */
#define CHECK(c)                                                                     \
    do {                                                                             \
        if (!(c)) {                                                                  \
            fprintf(stderr, "fuzz_queries.c:%d: contract broken: %s\n", __LINE__, #c); \
            __builtin_trap();                                                        \
        }                                                                            \
    } while (0)

/* Reads the k-th double of the payload (zero beyond the end). */
static double get(const uint8_t *p, size_t n, size_t k)
{
    double x = 0.0;
    if (8 * k + 8 <= n) memcpy(&x, p + 8 * k, 8);
    return x;
}

static prox_vec3 get3(const uint8_t *p, size_t n, size_t k) { return prox_v3(get(p, n, k), get(p, n, k + 1), get(p, n, k + 2)); }

/* Builds a shape of the given kind from 13 doubles starting at k. */
static prox_shape make_shape(int kind, const uint8_t *p, size_t n, size_t k)
{
    switch (kind & 3) {
    case 0: return prox_shape_from_rcc((prox_rcc){get3(p, n, k), get3(p, n, k + 3), get(p, n, k + 6)});
    case 1: {
        prox_box b = {get3(p, n, k), {get3(p, n, k + 3), get3(p, n, k + 6), get3(p, n, k + 9)}};
        return prox_shape_from_box(b);
    }
    case 2: {
        prox_rpp r = {get(p, n, k), get(p, n, k + 1), get(p, n, k + 2), get(p, n, k + 3), get(p, n, k + 4), get(p, n, k + 5)};
        return prox_shape_from_rpp(r);
    }
    default: return prox_shape_from_sph((prox_sph){get3(p, n, k), get(p, n, k + 3)});
    }
}

/* Largest magnitude among the doubles used. */
static double max_abs(const uint8_t *p, size_t n)
{
    double m = 0.0;
    for (size_t k = 0; k < 26; ++k) {
        double x = fabs(get(p, n, k));
        if (!(x <= m)) m = x; /* NaN propagates */
    }
    return m;
}

static int finite3(prox_vec3 v) { return prox_v3_isfinite(v); }

/* The cylinder-only queries. */
static void fuzz_rcc(const prox_rcc *a, const prox_rcc *b, prox_method m, int moderate)
{
    int valid = prox_rcc_validate(a) == PROX_OK && prox_rcc_validate(b) == PROX_OK;
    prox_distance_result r = prox_rcc_distance_ex(a, b, m);
    CHECK(valid || r.status != PROX_OK);
    if (r.status == PROX_OK) CHECK(!isnan(r.distance) && r.distance >= 0);
    if (valid && moderate) CHECK(r.status == PROX_OK && isfinite(r.distance) && finite3(r.p1) && finite3(r.p2));
    prox_test_result s = prox_rcc_sat(a, b);
    CHECK(valid || s.status != PROX_OK);
    if (valid && moderate) CHECK(s.status == PROX_OK);
    prox_signed_result g = prox_rcc_signed_distance(a, b);
    CHECK(valid || g.status != PROX_OK);
    if (g.status == PROX_OK) CHECK(!isnan(g.sd));
    if (valid && moderate) CHECK(g.status == PROX_OK && isfinite(g.sd) && finite3(g.p1) && finite3(g.p2));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    int sel = data[0];
    const uint8_t *p = data + 1;
    size_t n = size - 1;
    int moderate = max_abs(p, n) <= 1e100;
    prox_shape a = make_shape(sel, p, n, 0), b = make_shape(sel >> 2, p, n, 13);
    if (a.kind == PROX_SHAPE_RCC && b.kind == PROX_SHAPE_RCC) {
        int m = (sel >> 4) & 3;
        fuzz_rcc(&a.u.rcc, &b.u.rcc, m == 3 ? PROX_METHOD_FAST : (prox_method)m, moderate);
    }
    int valid = prox_shape_validate(&a) == PROX_OK && prox_shape_validate(&b) == PROX_OK;
    prox_distance_result d = prox_shape_distance(&a, &b);
    CHECK(valid || d.status != PROX_OK);
    if (d.status == PROX_OK) CHECK(!isnan(d.distance) && d.distance >= 0);
    if (valid && moderate) CHECK(d.status == PROX_OK && isfinite(d.distance) && finite3(d.p1) && finite3(d.p2));
    prox_test_result t = prox_shape_test(&a, &b);
    CHECK(valid || t.status != PROX_OK);
    if (valid && moderate) CHECK(t.status == PROX_OK);
    prox_signed_result g = prox_shape_signed_distance(&a, &b);
    CHECK(valid || g.status != PROX_OK);
    if (g.status == PROX_OK) CHECK(!isnan(g.sd));
    if (valid && moderate) CHECK(g.status == PROX_OK && isfinite(g.sd));
    prox_contain_result c = prox_shape_contains(&a, &b);
    CHECK(valid || c.status != PROX_OK);
    if (c.status == PROX_OK) CHECK(!isnan(c.clearance));
    return 0;
}
