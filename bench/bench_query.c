/* prox_bench group "query": the generic pair API of include/prox/query.h and the query modes of the
 * scene/batch API (include/prox/scene.h) for every pair family.
 * Families BOX-BOX, BOX-RCC, BOX-SPH, RCC-SPH, SPH-SPH, RCC-RCC; kinds: verdict (prox_shape_test),
 * distance (prox_shape_distance), signed distance (prox_shape_signed_distance), containment of A in
 * B and of B in A (prox_shape_contains); then prox_pair_query in each mode on the same pairs.
 * Pairs follow Agarwal's protocol (Sec. 5, as in bench_pairs.c) generalised to every kind: A is a
 * fixed small solid at the origin (RCC r 2, h 5; BOX 4 x 4 x 5 centred on the origin; SPH r 2.5),
 * B has random sizes (RCC r in (0,20], h in (0,50]; BOX edges (0,20] x (0,20] x (0,50]; SPH r in
 * (0,20]), its reference point (RCC base, BOX corner, SPH centre) uniform in the ball |o| <= 25
 * and a uniformly random rotation. RCC-RCC uses the first pairs of protocol A itself. Inputs are
 * seeded (seed 5 + family) and built before timing; each case's note gives the share of
 * intersecting pairs (and of nested pairs for containment). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench_pairs.h"

#if defined(PROX_BENCH_HAVE_QUERY)
#include "prox/query.h"
#include "prox/scene.h"
#define BQ_HAVE_SCENE 1

/* A set of generic pairs of one family. */
typedef struct bq_set {
    size_t n;
    prox_shape *a, *b;
} bq_set;

/* The fixed solid A of a family, centred at the origin. */
static prox_shape bq_fixed(prox_shape_kind k)
{
    if (k == PROX_SHAPE_RCC) return prox_shape_from_rcc((prox_rcc){prox_v3(0, 0, 0), prox_v3(0, 0, 5), 2});
    if (k == PROX_SHAPE_BOX)
        return prox_shape_from_box(
            (prox_box){prox_v3(-2, -2, -2.5), {prox_v3(4, 0, 0), prox_v3(0, 4, 0), prox_v3(0, 0, 5)}});
    return prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 2.5});
}

/* A random solid B of kind k: sizes as in Agarwal's protocol, reference point in the ball of 25. */
static prox_shape bq_random(bench_rng *r, prox_shape_kind k)
{
    prox_vec3 o;
    do {
        o = prox_v3(bench_range(r, -25, 25), bench_range(r, -25, 25), bench_range(r, -25, 25));
    } while (prox_v3_norm(o) > 25.0);
    bench_rot R = bench_random_rot(r);
    if (k == PROX_SHAPE_RCC) {
        double rb = 20.0 * (1.0 - bench_uniform(r)), hb = 50.0 * (1.0 - bench_uniform(r));
        return prox_shape_from_rcc((prox_rcc){o, bench_rot_apply(&R, prox_v3(0, 0, hb)), rb});
    }
    if (k == PROX_SHAPE_BOX) {
        double e0 = 20.0 * (1.0 - bench_uniform(r)), e1 = 20.0 * (1.0 - bench_uniform(r));
        double e2 = 50.0 * (1.0 - bench_uniform(r));
        return prox_shape_from_box((prox_box){o,
                                              {bench_rot_apply(&R, prox_v3(e0, 0, 0)), bench_rot_apply(&R, prox_v3(0, e1, 0)),
                                               bench_rot_apply(&R, prox_v3(0, 0, e2))}});
    }
    return prox_shape_from_sph((prox_sph){o, 20.0 * (1.0 - bench_uniform(r))});
}

/* The pairs of family (ka, kb); RCC-RCC takes protocol A's first n pairs. */
static bq_set bq_build(const bench_opts *o, prox_shape_kind ka, prox_shape_kind kb, size_t n, uint64_t seed)
{
    bq_set s = {n, bench_xmalloc(n * sizeof(prox_shape)), bench_xmalloc(n * sizeof(prox_shape))};
    if (ka == PROX_SHAPE_RCC && kb == PROX_SHAPE_RCC) {
        const bench_pairs *P = bench_pairs_agarwal(o);
        if (s.n > P->n) s.n = P->n;
        for (size_t i = 0; i < s.n; ++i) s.a[i] = prox_shape_from_rcc(P->a[i]), s.b[i] = prox_shape_from_rcc(P->b[i]);
        return s;
    }
    bench_rng r = bench_rng_seed(seed);
    prox_shape A = bq_fixed(ka);
    for (size_t i = 0; i < n; ++i) s.a[i] = A, s.b[i] = bq_random(&r, kb);
    return s;
}

/* One query of each kind; the returned value feeds the sink. */
static double q_test(const void *d, size_t i)
{
    const bq_set *s = d;
    return (double)prox_shape_test(&s->a[i], &s->b[i]).intersect;
}
static double q_distance(const void *d, size_t i)
{
    const bq_set *s = d;
    return prox_shape_distance(&s->a[i], &s->b[i]).distance;
}
static double q_signed(const void *d, size_t i)
{
    const bq_set *s = d;
    return prox_shape_signed_distance(&s->a[i], &s->b[i]).sd;
}
static double q_a_in_b(const void *d, size_t i)
{
    const bq_set *s = d;
    return prox_shape_contains(&s->a[i], &s->b[i]).clearance;
}
static double q_b_in_a(const void *d, size_t i)
{
    const bq_set *s = d;
    return prox_shape_contains(&s->b[i], &s->a[i]).clearance;
}

#ifdef BQ_HAVE_SCENE
/* prox_pair_query in one mode with its threshold. */
typedef struct bq_mode {
    const bq_set *s;
    prox_query_mode mode;
    double d;
} bq_mode;
static double q_mode(const void *d, size_t i)
{
    const bq_mode *m = d;
    prox_pair_result r = prox_pair_query(&m->s->a[i], &m->s->b[i], m->mode, m->d);
    return r.distance + r.signed_distance + (double)r.closer;
}
#endif

static const char *bq_kind_name(prox_shape_kind k)
{
    return k == PROX_SHAPE_RCC ? "RCC" : (k == PROX_SHAPE_BOX ? "BOX" : "SPH");
}

/* Registers the kinds and modes of one family, with the shares of intersecting and nested pairs. */
static void bq_family(const bench_opts *o, prox_shape_kind ka, prox_shape_kind kb, uint64_t seed)
{
    char fam[16], name[96];
    snprintf(fam, sizeof fam, "%s-%s", bq_kind_name(ka), bq_kind_name(kb));
    snprintf(name, sizeof name, "query/%s/", fam);
    if (!bench_selected(o, name)) return;
    size_t n = o->quick ? 5000 : 20000;
    bq_set *s = bench_xmalloc(sizeof *s);
    *s = bq_build(o, ka, kb, n, seed);
    size_t hit = 0, ainb = 0, bina = 0, bad = 0;
    for (size_t i = 0; i < s->n; ++i) {
        prox_test_result t = prox_shape_test(&s->a[i], &s->b[i]);
        prox_contain_result c1 = prox_shape_contains(&s->a[i], &s->b[i]);
        prox_contain_result c2 = prox_shape_contains(&s->b[i], &s->a[i]);
        hit += (size_t)(t.intersect == 1), ainb += (size_t)(c1.inside == 1), bina += (size_t)(c2.inside == 1);
        bad += (size_t)(t.status != PROX_OK || c1.status != PROX_OK || c2.status != PROX_OK);
    }
    double pct = 100.0 / (double)s->n;
    static const struct {
        const char *kind;
        bench_query_fn fn;
    } kinds[] = {{"verdict", q_test}, {"distance", q_distance}, {"signed", q_signed}, {"contains-AinB", q_a_in_b},
                 {"contains-BinA", q_b_in_a}};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
        snprintf(name, sizeof name, "query/%s/%s", fam, kinds[k].kind);
        bench_case *c = bench_add(name, kinds[k].fn, s, NULL, s->n);
        bench_note(c, "intersecting=%.1f%%;A_in_B=%.2f%%;B_in_A=%.2f%%;bad_status=%zu", pct * (double)hit,
                   pct * (double)ainb, pct * (double)bina, bad);
    }
#ifdef BQ_HAVE_SCENE
    /* Query modes of the batch API on the same pairs; CLOSER asks "distance <= 1?" (1 = half of A's radius). */
    static const struct {
        const char *name;
        prox_query_mode mode;
        double d;
    } modes[] = {{"verdict", PROX_MODE_VERDICT, 0.0},   {"closer1", PROX_MODE_CLOSER, 1.0},
                 {"distance", PROX_MODE_DISTANCE, 0.0}, {"points", PROX_MODE_POINTS, 0.0},
                 {"signed", PROX_MODE_SIGNED, 0.0},     {"relation", PROX_MODE_RELATION, 0.0}};
    for (size_t k = 0; k < sizeof modes / sizeof modes[0]; ++k) {
        bq_mode *m = bench_xmalloc(sizeof *m);
        *m = (bq_mode){s, modes[k].mode, modes[k].d};
        size_t rung[5] = {0};
        for (size_t i = 0; i < s->n; ++i) {
            prox_pair_result r = prox_pair_query(&s->a[i], &s->b[i], m->mode, m->d);
            if ((unsigned)r.decided_by < 5) rung[r.decided_by]++;
        }
        snprintf(name, sizeof name, "query/%s/mode-%s", fam, modes[k].name);
        bench_case *c = bench_add(name, q_mode, m, NULL, s->n);
        bench_note(c, "decided_bounds=%.1f%%;support=%.1f%%;test=%.1f%%;exact=%.1f%%", pct * (double)rung[1],
                   pct * (double)rung[2], pct * (double)rung[3], pct * (double)rung[4]);
    }
#endif
}

void bench_group_query(const bench_opts *o)
{
    if (!bench_selected(o, "query/")) return;
    bq_family(o, PROX_SHAPE_BOX, PROX_SHAPE_BOX, 5);
    bq_family(o, PROX_SHAPE_BOX, PROX_SHAPE_RCC, 6);
    bq_family(o, PROX_SHAPE_BOX, PROX_SHAPE_SPH, 7);
    bq_family(o, PROX_SHAPE_RCC, PROX_SHAPE_SPH, 8);
    bq_family(o, PROX_SHAPE_SPH, PROX_SHAPE_SPH, 9);
    bq_family(o, PROX_SHAPE_RCC, PROX_SHAPE_RCC, 10);
}
#else
void bench_group_query(const bench_opts *o) { (void)o; }
#endif
