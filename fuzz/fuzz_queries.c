/* libFuzzer harness for the public queries: any bytes -> two shapes of the ten kinds -> every query
 * (and, for two cylinders, the distance by the cylinder method chosen by bits 4-5 of the first byte).
 * Contract checked: no crash or hang; an OK status never comes with a NaN; valid shapes of moderate
 * size (|input doubles| <= 1e100) get PROX_OK and finite answers; invalid ones a named error (a status
 * code below PROX_STATUS_COUNT_, and PROX_EINVAL_SHAPE_KIND for a kind that is none); the verdict and
 * the distance agree away from contact. Byte layout: read_layout below (fz_shape in fuzz_common.h
 * builds the shapes; missing bytes read as zero). */
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

/* The kinds and variants of the two shapes, and where their doubles start. Two layouts: byte 0 < 0x80
 * is the original one (kinds RCC, BOX, RPP, SPH in bits 0-1 and 2-3, raw doubles, B from double 13);
 * byte 0 >= 0x80 draws all ten kinds: byte 1 holds kind A (low nibble) and kind B (high nibble), each
 * modulo 11 (10 is no kind: PROX_EINVAL_SHAPE_KIND), bits 0-1 and 2-3 of byte 0 their fz_shape
 * variants, and the doubles start at byte 2, B at double FZ_SHAPE_DOUBLES. */
typedef struct layout {
    int ka, kb, va, vb;
    size_t skip, kb_at, used;
} layout;

static layout read_layout(const uint8_t *data, size_t size)
{
    int sel = data[0];
    if (sel < 0x80) return (layout){sel & 3, (sel >> 2) & 3, 0, 0, 1, 13, 26};
    int b1 = size > 1 ? data[1] : 0;
    return (layout){(b1 & 15) % 11, (b1 >> 4) % 11, sel & 3, (sel >> 2) & 3, 2, FZ_SHAPE_DOUBLES, 2 * FZ_SHAPE_DOUBLES};
}

static int finite3(prox_vec3 v) { return prox_v3_isfinite(v); }

/* Relative margin (x the pair scale) beyond which the verdict, distance and signed distance must agree:
 * far above every tolerance of the library, so that only a wrong answer trips it. */
#define VERDICT_MARGIN 1e-6

/* A query's status on shapes whose validators said va and vb: OK only for valid shapes, else a named
 * error: the validator's own when exactly one is invalid, one of the two when both are. */
static int named(prox_status s, prox_status va, prox_status vb)
{
    if (s < PROX_OK || s >= PROX_STATUS_COUNT_) return 0;
    if (va == PROX_OK && vb == PROX_OK) return s == PROX_OK || s == PROX_ENUMERIC;
    if (va == PROX_OK) return s == vb;
    if (vb == PROX_OK) return s == va;
    return s == va || s == vb;
}

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
    layout L = read_layout(data, size);
    if (size < L.skip) return 0;
    const uint8_t *p = data + L.skip;
    size_t n = size - L.skip;
    int moderate = fz_max_abs(p, n, L.used) <= 1e100;
    prox_shape a = fz_shape(L.ka, L.va, p, n, 0), b = fz_shape(L.kb, L.vb, p, n, L.kb_at);
    if (a.kind == PROX_SHAPE_RCC && b.kind == PROX_SHAPE_RCC) {
        int m = (sel >> 4) & 3;
        fuzz_rcc(&a.u.rcc, &b.u.rcc, m == 3 ? PROX_METHOD_FAST : (prox_method)m, moderate);
    }
    prox_status va = prox_shape_validate(&a), vb = prox_shape_validate(&b);
    int valid = va == PROX_OK && vb == PROX_OK;
    if (a.kind >= PROX_SHAPE_KIND_COUNT_) CHECK(va == PROX_EINVAL_SHAPE_KIND);
    prox_distance_result d = prox_shape_distance(&a, &b);
    CHECK(named(d.status, va, vb));
    if (d.status == PROX_OK) CHECK(!isnan(d.distance) && d.distance >= 0);
    if (valid && moderate) CHECK(d.status == PROX_OK && isfinite(d.distance) && finite3(d.p1) && finite3(d.p2));
    prox_test_result t = prox_shape_test(&a, &b);
    CHECK(named(t.status, va, vb));
    if (valid && moderate) CHECK(t.status == PROX_OK);
    prox_signed_result g = prox_shape_signed_distance(&a, &b);
    CHECK(named(g.status, va, vb));
    if (g.status == PROX_OK) CHECK(!isnan(g.sd));
    if (valid && moderate) CHECK(g.status == PROX_OK && isfinite(g.sd));
    prox_contain_result c = prox_shape_contains(&a, &b);
    CHECK(named(c.status, va, vb));
    if (c.status == PROX_OK) CHECK(!isnan(c.clearance));
    if (valid && moderate && d.status == PROX_OK && t.status == PROX_OK && g.status == PROX_OK) {
        /* away from contact (VERDICT_MARGIN x the pair's scale) the three answers agree */
        double tol = VERDICT_MARGIN * prox_shape_pair_scale(&a, &b);
        if (d.distance > tol) CHECK(!t.intersect && !d.intersect && g.sd > 0);
        if (g.sd < -tol) CHECK(t.intersect && d.distance == 0);
    }
    return 0;
}
