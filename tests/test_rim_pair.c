/* The TRC pairs' feature prediction (src/distance/rim_pair.c) against the full support-function engine
 * (prox_convex_distance_full): TRC against TRC and RCC, in both orders, full cones and frustums
 * (widening either way), on near pairs, close pairs (1e-10 .. 1e-3 S apart along the full engine's
 * normal), pairs 1e6 sizes from the origin, extreme aspects (needles and flat disks, sizes over six
 * decades), and axes parallel or perpendicular. Every answer the prediction gives must be certified
 * and agree with the full engine: the verdict; disjoint, the distance within 1e-12 S, the witnesses
 * in their solids with |p2 - p1| = distance and the support functions' gap along their own direction
 * meeting it (to their rounding), and each within 1e-9 S of the full engine's (where the closest pair
 * is unique); an
 * overlap, a common point in both solids. The prediction must answer most disjoint pairs, and the
 * distance query must take it (method PROX_METHOD_FAST). */
#include "test_util.h"

#include <float.h>

#include "core/body.h"
#include "core/tol.h"
#include "distance/curved_internal.h"
#include "prox/query.h"
#include "sat/convex.h"

#define BAR 1e-12 /* the accuracy bar of distances, in units of S */
#define PT_BAR 1e-9 /* the witnesses against the full engine's (where unique), in units of S */
#define PT_BAR_CLOSE 1e-10 /* the same on pairs 1e-10..1e-3 S apart, where the full engine's own witnesses
                            * lie up to 1.2e-11 S off (test_close_references: three such pairs in 50-digit
                            * arithmetic, the prediction's within 3e-16 S; the full engine's took a pair
                            * aligned with its normal but 1.6e-9 S along the contact before its ties went
                            * to the pair nearest to being mutually closest) */

typedef struct stats {
    int pairs, disjoint, answered, overlaps, compared;
    double err_d, err_p;
} stats;

/* 1 when the pair's closest points may form a set: axes parallel, or an end disk facing the other
 * solid (its normal along the contact normal), where two exact answers may pick different pairs. */
static int maybe_set(const prox_shape *a, const prox_shape *b, prox_vec3 n)
{
    prox_vec3 wa = prox_v3_normalize(a->kind == PROX_SHAPE_RCC ? a->u.rcc.axis : a->u.trc.axis);
    prox_vec3 wb = prox_v3_normalize(b->kind == PROX_SHAPE_RCC ? b->u.rcc.axis : b->u.trc.axis);
    return prox_v3_norm(prox_v3_cross(wa, wb)) < 1e-6 || fabs(fabs(prox_v3_dot(wa, n)) - 1.0) < 1e-6 ||
           fabs(fabs(prox_v3_dot(wb, n)) - 1.0) < 1e-6;
}

static void check_pair(const prox_shape *sa, const prox_shape *sb, stats *st, double pt_bar)
{
    assert_int_equal(prox_shape_validate(sa), PROX_OK);
    assert_int_equal(prox_shape_validate(sb), PROX_OK);
    prox_body a = prox_body_make(sa), b = prox_body_make(sb);
    double S = prox_shape_pair_scale(sa, sb);
    prox_distance_result g = prox_convex_distance_full(&a, &b, NULL), r;
    assert_int_equal(g.status, PROX_OK);
    st->pairs++;
    st->disjoint += !g.intersect;
    if (!prox_rim_pair_distance(&a, &b, &r, NULL)) return;
    double tol = BAR * S + 16.0 * DBL_EPSILON * (prox_v3_norm(r.p1) + S);
    assert_int_equal(r.status, PROX_OK);
    assert_true(r.certified);
    assert_int_equal(r.method, PROX_METHOD_FAST);
    if (r.intersect) { /* a common point, checked in both solids */
        st->overlaps++;
        assert_true(g.intersect || g.distance <= PROX_TOL_TOUCH * S);
        assert_true(prox_body_contains(&a, r.p1, tol) && prox_body_contains(&b, r.p1, tol));
        return;
    }
    st->answered++;
    if (g.intersect || fabs(r.distance - g.distance) > tol) {
        print_error("kinds %d %d: intersect %d/%d distance %.17g full %.17g (diff/S %.3g)\n", sa->kind, sb->kind, r.intersect,
                    g.intersect, r.distance, g.distance, fabs(r.distance - g.distance) / S);
        fail();
    }
    assert_true(r.distance - r.certificate_gap <= PROX_TOL_CERT * S * 1.0001);
    assert_true(prox_body_contains(&a, r.p1, tol));
    assert_true(prox_body_contains(&b, r.p2, tol));
    assert_true(fabs(prox_v3_dist(r.p1, r.p2) - r.distance) <= 2.0 * tol);
    /* the support functions' gap along the witnesses' own direction: their rounding (eps |p| each)
     * turns it by up to delta, which costs at most 2 S delta where a kink of the support functions
     * passes through the normal (a side line, a face: the certificate then took the features' exact
     * normal, core/body.h) */
    prox_vec3 n = prox_v3_scale(prox_v3_sub(r.p2, r.p1), 1.0 / prox_v3_dist(r.p1, r.p2));
    double delta = 32.0 * DBL_EPSILON * (prox_v3_norm(r.p1) + S) / r.distance;
    assert_true(-prox_body_support(&b, prox_v3_neg(n)) - prox_body_support(&a, n) >= r.distance - tol - 2.0 * S * delta);
    st->err_d = fmax(st->err_d, fabs(r.distance - g.distance) / S);
    if (maybe_set(sa, sb, n) || r.distance <= 1e-9 * S) return; /* a set, or a direction near rounding */
    double ep = fmax(prox_v3_dist(r.p1, g.p1), prox_v3_dist(r.p2, g.p2)) / S;
    if (!(ep <= pt_bar)) {
        print_error("kinds %d %d: witnesses %.3g S from the full engine's (distance/S %.3g)\n", sa->kind, sb->kind, ep, r.distance / S);
        fail();
    }
    st->compared++;
    st->err_p = fmax(st->err_p, ep);
}

/* A TRC (a full cone one time in three, either end the wider) or an RCC along unit w, centred at c,
 * height h and radii from the sizes given. */
static prox_shape rim_solid(test_rng *g, int trc, prox_vec3 c, prox_vec3 w, double h, double r1, double r2)
{
    prox_vec3 base = prox_v3_mad(c, -0.5 * h, w), axis = prox_v3_scale(w, h);
    if (!trc) return prox_shape_from_rcc((prox_rcc){base, axis, r1});
    double u = test_uniform(g);
    prox_trc t = {base, axis, r1, u < 1.0 / 3.0 ? 0.0 : r2};
    if (u > 5.0 / 6.0) t.r1 = 0.0, t.r2 = r2; /* the apex at the base */
    if (t.r1 == t.r2) t.r2 *= 0.5;
    return prox_shape_from_trc(t);
}

/* Families: 0 near (B 0.05 .. 2 sizes of A away), 1 close (moved to 1e-10 .. 1e-3 S apart along the
 * full engine's normal), 2 near pairs 1e6 sizes from the origin, 3 extreme aspects (heights and radii
 * log-uniform over 1e-3 .. 1e3), 4 axes parallel or perpendicular (exactly, or 1e-9 rad off). */
static void make_pair(test_rng *g, int fam, int ka, int kb, prox_shape *a, prox_shape *b)
{
    prox_vec3 o = fam == 2 ? prox_v3_scale(test_unit(g), 1e6 * test_range(g, 1.0, 10.0)) : prox_v3(0, 0, 0);
    double s[6];
    for (int k = 0; k < 6; ++k) s[k] = fam == 3 ? pow(10.0, test_range(g, -3, 3)) : test_lsize(g);
    prox_vec3 wa = test_unit(g), wb = test_unit(g);
    if (fam == 4) {
        prox_vec3 p = prox_v3_normalize(prox_v3_cross(wa, test_unit(g)));
        wb = test_uniform(g) < 0.5 ? prox_v3_scale(wa, test_uniform(g) < 0.5 ? 1.0 : -1.0) : p;
        if (test_uniform(g) < 0.5) wb = prox_v3_normalize(prox_v3_mad(wb, 1e-9, test_unit(g)));
    }
    *a = rim_solid(g, ka == PROX_SHAPE_TRC, o, wa, s[0], 0.5 * s[1], 0.5 * s[2]);
    double sz = prox_shape_size(a);
    *b = rim_solid(g, kb == PROX_SHAPE_TRC, prox_v3_mad(o, sz * exp(test_range(g, log(0.05), log(2.0))), test_unit(g)), wb, s[3],
                   0.5 * s[4], 0.5 * s[5]);
    if (fam != 1) return;
    prox_body ba = prox_body_make(a), bb = prox_body_make(b);
    prox_signed_result r = prox_convex_signed(&ba, &bb);
    if (!(r.sd > 0.0)) return;
    double S = prox_shape_pair_scale(a, b);
    *b = test_translate(b, prox_v3_scale(r.normal, S * exp(test_range(g, log(1e-10), log(1e-3))) - r.sd));
}

static void run_family(int fam, int per_kind, uint64_t seed)
{
    static const char *const names[] = {"near", "close", "far-from-origin", "extreme", "parallel/perp"};
    static const int kinds[3][2] = {{PROX_SHAPE_TRC, PROX_SHAPE_RCC}, {PROX_SHAPE_RCC, PROX_SHAPE_TRC}, {PROX_SHAPE_TRC, PROX_SHAPE_TRC}};
    test_rng g = test_rng_seed(seed);
    stats st = {0};
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < per_kind; ++i) {
            prox_shape a, b;
            make_pair(&g, fam, kinds[k][0], kinds[k][1], &a, &b);
            check_pair(&a, &b, &st, fam == 1 ? PT_BAR_CLOSE : PT_BAR);
        }
    printf("%-16s pairs %5d disjoint %5d answered %5d (+%d overlaps)  max |d - full|/S %.2g  max |p - full|/S %.2g (%d compared)\n",
           names[fam], st.pairs, st.disjoint, st.answered, st.overlaps, st.err_d, st.err_p, st.compared);
    /* the point of the prediction: it answers most disjoint pairs */
    assert_true(st.disjoint > 0);
    assert_true(st.answered * 5 > st.disjoint * 4);
}

static void test_near(void **state)
{
    (void)state;
    run_family(0, 400, 701);
}

static void test_close(void **state)
{
    (void)state;
    run_family(1, 200, 702);
}

static void test_far_from_origin(void **state)
{
    (void)state;
    run_family(2, 200, 703);
}

static void test_extreme(void **state)
{
    (void)state;
    run_family(3, 300, 704);
}

static void test_parallel_perpendicular(void **state)
{
    (void)state;
    run_family(4, 300, 705);
}

/* The distance query takes the prediction for a disjoint TRC pair: a cone beside a cylinder. */
static void test_query_route(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_trc((prox_trc){{0, 0, 0}, {0, 0, 2}, 1.0, 0.0});
    prox_shape b = prox_shape_from_rcc((prox_rcc){{3, 0, -1}, {0, 1, 0}, 0.5});
    prox_distance_result r = prox_shape_distance(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(r.method, PROX_METHOD_FAST);
    assert_true(r.certified);
    /* the base rim's point (1, 0, 0) against the cylinder's side: the cylinder's axis runs along y
     * at x = 3, z = -1 with radius 0.5, so the distance is |(3, -1) - (1, 0)| in the xz plane - 0.5
     * when the rim point (1, 0, 0) is the closest (the cone widens downwards to the base at z = 0) */
    double want = sqrt(4.0 + 1.0) - 0.5;
    assert_true(fabs(r.distance - want) <= 1e-14 * 4.0);
}

/* Three close rim-lateral contacts (a flat cone's base rim 3e-8 from a cylinder's side; a cylinder's
 * rim 4.4e-7 and 6.7e-7 from a cone's side) against their closest pairs computed in 50-digit
 * arithmetic (the rim's angle minimising its distance to the other surface, by Newton on its
 * derivative): the prediction's witnesses within 1e-14 S of them (measured 3e-16; the full engine's
 * lie 7e-12, 1.2e-11 and 1.3e-16 S off, its normal found only to the kink search's resolution). */
static void test_close_references(void **state)
{
    (void)state;
    static const struct {
        prox_trc a;
        prox_rcc b;
        double d, p1[3], p2[3];
    } ref[3] = {
        {{{-0.057780550336483723, 0.37187569428369582, 0.24073843527261718},
          {0.11556110067296745, -0.74375138856739165, -0.48147687054523436}, 3.9439266215555446, 0.0},
         {{0.60228354540469609, 1.8457596058410426, -3.2525735978115637}, {-5.0721485056349493, 1.6206689809422477, -0.5445394515327483},
          0.35462044307816387},
         2.9973023644178104467e-8,
         {-0.76172350957795425156, 2.4030461560051024847, -3.065825954207699736},
         {-0.76172350980847039178, 2.4030461458132357487, -3.0658259823937753961}},
        {{{-0.08140068497834882, 0.40457272122915022, -0.27488274443878175},
          {0.16280136995669764, -0.80914544245830045, 0.54976548887756349}, 4.5507597765229795, 0.11218538680366194},
         {{-1.913421519759636, -2.8649139032460051, -3.2789057394587489}, {0.81604218439353016, 0.58773901867487965, 0.10473045367128092},
          0.32612372064107786},
         4.3969009669613760974e-7,
         {-1.2536174607399031419, -2.0334821332160920731, -3.3243765928566085055},
         {-1.253617418284570508, -2.0334825386556852938, -3.3243764281032713235}},
        {{{-1.7702356239655963, -0.8843380928635789, 0.74395681723221818},
          {3.5404712479311926, 1.7686761857271578, -1.4879136344644364}, 0.20704678420831202, 0.34133713292881668},
         {{0.98177404318242689, 0.72399063735955815, -0.92555704597701505}, {-2.4820442959145548, -0.60979279580354928, 0.33017050908377454},
          0.17945892746043138},
         6.7013560311602808925e-7,
         {1.0183671788056058737, 0.66456591888504332043, -0.76022290112421464413},
         {1.0183668404153016949, 0.66456607744199525342, -0.76022345739161580583}},
    };
    for (int i = 0; i < 3; ++i) {
        prox_shape a = prox_shape_from_trc(ref[i].a), b = prox_shape_from_rcc(ref[i].b);
        double S = prox_shape_pair_scale(&a, &b);
        prox_distance_result r = prox_shape_distance(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        assert_int_equal(r.method, PROX_METHOD_FAST);
        assert_true(r.certified);
        prox_vec3 p1 = prox_v3(ref[i].p1[0], ref[i].p1[1], ref[i].p1[2]), p2 = prox_v3(ref[i].p2[0], ref[i].p2[1], ref[i].p2[2]);
        double ed = fabs(r.distance - ref[i].d) / S, ep = fmax(prox_v3_dist(r.p1, p1), prox_v3_dist(r.p2, p2)) / S;
        printf("close reference %d: |d - ref|/S %.2g  |p - ref|/S %.2g\n", i, ed, ep);
        assert_true(ed <= 1e-14);
        assert_true(ep <= 1e-14);
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_near),
        cmocka_unit_test(test_close),
        cmocka_unit_test(test_far_from_origin),
        cmocka_unit_test(test_extreme),
        cmocka_unit_test(test_parallel_perpendicular),
        cmocka_unit_test(test_query_route),
        cmocka_unit_test(test_close_references),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
