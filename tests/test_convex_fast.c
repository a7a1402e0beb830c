/* The early exits of the support-function distance query (src/sat/convex.c: GJK's own certificate,
 * then Newton and the support sets at the best direction alone) against the full engine (the local
 * search and every candidate normal, prox_convex_distance_full), on random pairs of every curved kind
 * (TRC, REC, ELL) against every kind, in both orders: near pairs, touching pairs (moved into contact
 * along the full engine's normal), near-touching pairs (1e-13 S apart), and pairs 1e6 sizes from the
 * origin. Both answers must agree on the verdict, be certified, give the same distance within 1e-12 S,
 * and the early answer's witnesses must lie in the solids with |p2 - p1| = distance and its proven
 * lower bound within PROX_TOL_CERT S of it. The early exits must be taken for most disjoint pairs.
 * The signed query likewise (prox_convex_signed_full: no early exit, the depth proved by the cover),
 * whose overlaps the quick search proves (an inner polytope of A - B, epa.h, or tangent balls at the
 * witnesses, or for two ellipsoids an ellipsoid inside A - B): each proven lower bound must stay below
 * the other search's depth. A cone overlapping a box on which the inner polytope once stalled, two
 * deeply overlapping ellipsoids, a cone against a cylinder whose first polytope stalls and two cones
 * whose first two stall must be proved without the cover. */
#include "test_util.h"

#include <float.h>

#include "core/body.h"
#include "core/tol.h"
#include "prox/query.h"
#include "sat/convex.h"

#define BAR 1e-12 /* the accuracy bar of distances and points, in units of S */

typedef struct stats {
    int pairs, disjoint, early;
    double err_d, err_w, err_c;
} stats;

/* Compares the distance query with its early exits against the full engine on one pair. */
static void check_pair(const prox_shape *sa, const prox_shape *sb, stats *st)
{
    assert_int_equal(prox_shape_validate(sa), PROX_OK);
    assert_int_equal(prox_shape_validate(sb), PROX_OK);
    prox_body a = prox_body_make(sa), b = prox_body_make(sb);
    double S = prox_shape_pair_scale(sa, sb);
    prox_convex_info fi, gi;
    unsigned long e0 = prox_convex_gjk_certified_count();
    prox_distance_result f = prox_convex_distance_ex(&a, &b, &fi);
    int early = prox_convex_gjk_certified_count() != e0;
    prox_distance_result g = prox_convex_distance_full(&a, &b, &gi);
    assert_int_equal(f.status, PROX_OK);
    assert_int_equal(g.status, PROX_OK);
    st->pairs++;
    /* the verdict is GJK's, the same for both */
    assert_int_equal(f.intersect, g.intersect);
    if (f.intersect) {
        assert_false(early);
        assert_int_equal(f.certified, g.certified);
        return;
    }
    st->disjoint++, st->early += early;
    /* the bar, and the rounding of the input coordinates of a pair far from the origin (an ARB's
     * corners there are coplanar only to 1e-9 S: its vertices and its face planes, which the full
     * engine's projections use, disagree by that much) */
    double tol = BAR * S + 16.0 * DBL_EPSILON * prox_v3_norm(f.p1);
    /* an early exit is a certificate; otherwise the query certifies whenever the full engine does (a
     * far ARB's fuzzy corners can leave both short of PROX_TOL_CERT S) */
    if (!((early ? f.certified : f.certified >= g.certified) && fabs(f.distance - g.distance) <= tol)) {
        print_error("kinds %d %d: S %g lower %.17g full lower %.17g\n", sa->kind, sb->kind, S, f.certificate_gap, g.certificate_gap);
        print_error("kinds %d %d: early %d certified %d/%d distance %.17g full %.17g (diff/S %.3g)\n", sa->kind, sb->kind, early,
                    f.certified, g.certified, f.distance, g.distance, fabs(f.distance - g.distance) / S);
        fail();
    }
    /* the early answer's proof: its lower bound within PROX_TOL_CERT S, and below the full answer */
    if (f.certified) assert_true(f.distance - f.certificate_gap <= PROX_TOL_CERT * S * 1.0001);
    assert_true(f.certificate_gap <= g.distance + PROX_TOL_CERT * S + tol);
    assert_true(g.certificate_gap <= f.distance + PROX_TOL_CERT * S);
    /* its witnesses: in the solids (within the bar and the rounding of their absolute coordinates: a
     * pair 1e6 sizes from the origin), |p2 - p1| = distance */
    assert_true(prox_body_contains(&a, f.p1, tol));
    assert_true(prox_body_contains(&b, f.p2, tol));
    /* an early answer's witnesses: their own direction is the normal, the gap of the support functions
     * along it (weak duality, from the bodies' support functions) meets the distance. Not 1e6 sizes
     * from the origin: there the absolute witnesses' rounding (1e-9) turns their direction by up to
     * 1e-7 rad, which costs a face's kink first order (the engine checks it in relative coordinates) */
    if (early && prox_v3_norm(f.p1) < 1e3 * S) {
        prox_vec3 v = prox_v3_sub(f.p2, f.p1), n = prox_v3_scale(v, 1.0 / prox_v3_norm(v));
        double gap = -prox_body_support(&b, prox_v3_neg(n)) - prox_body_support(&a, n);
        if (!(gap >= f.distance - tol)) {
            print_error("kinds %d %d: gap along the witnesses %.17g distance %.17g (diff/S %.3g)\n", sa->kind, sb->kind, gap, f.distance,
                        (f.distance - gap) / S);
            fail();
        }
    }
    /* the early answer's witnesses are the closest pair: each its body's closest point to the other
     * (GJK's pair, convex combinations of support points, can certify the distance ~1e-8 S off it
     * where a surface is curved, and so can the support points at Newton's last iterate, 1e-10 S) */
    if (early) {
        double ra = prox_v3_dist(prox_body_closest(&a, f.p2), f.p1), rb = prox_v3_dist(prox_body_closest(&b, f.p1), f.p2);
        if (!(ra <= tol && rb <= tol)) {
            print_error("kinds %d %d: early witnesses %.3g S and %.3g S from the closest points\n", sa->kind, sb->kind, ra / S, rb / S);
            fail();
        }
        st->err_c = fmax(st->err_c, fmax(ra, rb) / S);
    }
    double ew = fabs(prox_v3_dist(f.p1, f.p2) - f.distance);
    assert_true(ew <= 2.0 * tol);
    ew /= S;
    st->err_d = fmax(st->err_d, fabs(f.distance - g.distance) / S);
    st->err_w = fmax(st->err_w, ew);
}

/* Families: 0 near (B 0.05 .. 2 sizes of A away: disjoint and overlapping), 1 touching, 2
 * near-touching (1e-13 S), 3 near pairs 1e6 sizes from the origin, 4 close (1e-10 .. 1e-3 S apart,
 * log-uniform: just outside the touching band, where a pair off the normal shows most). */
static void make_pair(test_rng *g, int fam, int ka, int kb, prox_shape *a, prox_shape *b)
{
    prox_vec3 o = fam == 3 ? prox_v3_scale(test_unit(g), 1e6 * test_range(g, 1.0, 10.0)) : prox_v3(0, 0, 0);
    *a = test_any_shape(g, ka, o);
    double sz = prox_shape_size(a);
    *b = test_any_shape(g, kb, prox_v3_mad(o, sz * exp(test_range(g, log(0.05), log(2.0))), test_unit(g)));
    if (fam == 0 || fam == 3) return;
    prox_body ba = prox_body_make(a), bb = prox_body_make(b);
    prox_signed_result r = prox_convex_signed(&ba, &bb);
    if (!(r.sd > 0.0)) return; /* overlapping: kept as it is (the verdict is still compared) */
    double S = prox_shape_pair_scale(a, b), gap = fam == 2 ? 1e-13 * S : (fam == 4 ? S * exp(test_range(g, log(1e-10), log(1e-3))) : 0.0);
    *b = test_translate(b, prox_v3_scale(r.normal, gap - r.sd));
}

static void run_family(int fam, int per_kind, uint64_t seed)
{
    static const char *const names[] = {"near", "touching", "near-touching", "far-from-origin", "close"};
    test_rng g = test_rng_seed(seed);
    stats st = {0, 0, 0, 0.0, 0.0, 0.0};
    for (int kc = PROX_SHAPE_TRC; kc <= PROX_SHAPE_ELL; ++kc)
        for (int k = 0; k < PROX_SHAPE_KIND_COUNT_; ++k)
            for (int i = 0; i < per_kind; ++i) {
                prox_shape a, b;
                int swap = i & 1;
                make_pair(&g, fam, swap ? k : kc, swap ? kc : k, &a, &b);
                check_pair(&a, &b, &st);
            }
    printf("%-16s pairs %5d disjoint %5d early exits %5d  max |distance - full|/S %.2g  max ||p2-p1| - distance|/S %.2g"
           "  early witnesses from the closest points %.2g S\n",
           names[fam], st.pairs, st.disjoint, st.early, st.err_d, st.err_w, st.err_c);
    /* the point of the early exits: most disjoint pairs take them (not touching and near-touching
     * pairs, within the touching band, where the direction of p2 - p1 is rounding: they decline) */
    assert_true(st.disjoint > 0);
    if (fam == 0 || fam == 3) assert_true(st.early * 2 > st.disjoint);
    if (fam == 4) assert_true(st.early * 4 > st.disjoint); /* the smallest gaps decline more often */
}

typedef struct sstats {
    int pairs, overlapping, quick, disjoint, early;
    double err_sd;
} sstats;

/* The signed query with its early exits (the distance's certificates for a disjoint pair, the quick
 * search's proofs of a depth) against the full search and its cover on one pair: the same answer
 * (1e-12 S disjoint, 1e-9 S overlapping), each one's proven bound on the other's side, witnesses with
 * p2 - p1 = sd n. */
static void check_signed_pair(const prox_shape *sa, const prox_shape *sb, sstats *st)
{
    prox_body a = prox_body_make(sa), b = prox_body_make(sb);
    double S = prox_shape_pair_scale(sa, sb), o = 16.0 * DBL_EPSILON * prox_v3_norm(a.c);
    prox_convex_info fi, gi;
    unsigned long e0 = prox_convex_gjk_certified_count();
    prox_signed_result f = prox_convex_signed_ex(&a, &b, &fi);
    int early = prox_convex_gjk_certified_count() != e0;
    prox_signed_result g = prox_convex_signed_full(&a, &b, &gi);
    assert_int_equal(fi.intersect, gi.intersect);
    double bar = (fi.intersect ? 1e-9 : BAR) * S + o;
    st->pairs++;
    if (!(fabs(f.sd - g.sd) <= bar)) {
        print_error("kinds %d %d: sd %.17g full %.17g (diff/S %.3g) intersect %d global %d\n", sa->kind, sb->kind, f.sd, g.sd,
                    fabs(f.sd - g.sd) / S, fi.intersect, fi.global);
        fail();
    }
    st->err_sd = fmax(st->err_sd, fabs(f.sd - g.sd) / S);
    assert_true(prox_v3_norm(prox_v3_mad(prox_v3_sub(f.p2, f.p1), -f.sd, f.normal)) <= bar);
    if (fi.intersect) {
        st->overlapping++;
        st->quick += !fi.global;
        /* both proofs: each lower bound of the depth at most the other's depth */
        /* a sphere's depth is answered in closed form by the queries: against a cone tip the cover
         * can run out of cells (both searches then say so) */
        assert_true(fi.certified >= gi.certified);
        assert_true(fi.lower <= -g.sd + o + PROX_TOL_PHI_ROUND * S);
        assert_true(gi.lower <= -f.sd + o + PROX_TOL_PHI_ROUND * S);
        if (fi.certified) assert_true(-f.sd - fi.lower <= PROX_TOL_DEPTH_CERT * S * 1.0001 + PROX_TOL_TOUCH * S);
        return;
    }
    st->disjoint++, st->early += early;
    assert_true(fi.lower <= g.sd + bar);
    assert_true(prox_body_contains(&a, f.p1, bar) && prox_body_contains(&b, f.p2, bar));
}

/* Overlapping pairs by depth: B moved along the full engine's normal to a depth of 1e-4 .. 0.1 S
 * (shallow) or left where the near family puts it; the quick search proves most of either. */
static void run_signed(int shallow, int per_kind, uint64_t seed)
{
    test_rng g = test_rng_seed(seed);
    sstats st = {0, 0, 0, 0, 0, 0.0};
    for (int kc = PROX_SHAPE_TRC; kc <= PROX_SHAPE_ELL; ++kc)
        for (int k = 0; k < PROX_SHAPE_KIND_COUNT_; ++k)
            for (int i = 0; i < per_kind; ++i) {
                prox_shape a, b;
                int swap = i & 1;
                make_pair(&g, 0, swap ? k : kc, swap ? kc : k, &a, &b);
                if (shallow) {
                    prox_body ba = prox_body_make(&a), bb = prox_body_make(&b);
                    prox_signed_result r = prox_convex_signed_full(&ba, &bb, NULL);
                    double S = prox_shape_pair_scale(&a, &b), depth = S * exp(test_range(&g, log(1e-4), log(0.1)));
                    b = test_translate(&b, prox_v3_scale(r.normal, -depth - r.sd));
                }
                check_signed_pair(&a, &b, &st);
            }
    printf("signed %-8s pairs %4d overlapping %4d (proved by the quick search %4d) disjoint %4d (early %4d)  max |sd - full|/S %.2g\n",
           shallow ? "shallow" : "near", st.pairs, st.overlapping, st.quick, st.disjoint, st.early, st.err_sd);
    assert_true(st.overlapping > 0);
    /* what the early exits are for: most depths proved by the quick search, most disjoint pairs by
     * the distance's certificates */
    assert_true(st.quick * 2 > st.overlapping);
    if (!shallow) assert_true(st.early * 2 > st.disjoint);
}

static void test_signed_near(void **state)
{
    (void)state;
    run_signed(0, 8, 306);
}

static void test_signed_shallow(void **state)
{
    (void)state;
    run_signed(1, 8, 307);
}

static void test_fast_near(void **state)
{
    (void)state;
    run_family(0, 60, 301);
}

static void test_fast_touching(void **state)
{
    (void)state;
    run_family(1, 16, 302);
}

static void test_fast_near_touching(void **state)
{
    (void)state;
    run_family(2, 16, 303);
}

static void test_fast_far_from_origin(void **state)
{
    (void)state;
    run_family(3, 20, 304);
}

static void test_fast_close(void **state)
{
    (void)state;
    run_family(4, 20, 305);
}

/* Two disjoint ellipsoids (2.6 apart, sizes ~2.8 and ~9.7) against their closest pair computed in
 * 40-digit arithmetic (alternating exact projections to convergence): the distance query's early exit
 * (Newton on the sphere from the centres' direction) must put its witnesses within 1e-14 S of it. Newton
 * stopped on phi's rounding leaves the direction ~1e-8 rad off, the support points 1.5e-8 S off here;
 * its last steps are judged by the gradient across the direction. */
static void test_smooth_witness_reference(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_ell((prox_ell){{0, 0, 0}, {0.69348784607972525, -1.2343040373115752, 0.30726945136629352}, 0.35646097167994623});
    prox_shape b = prox_shape_from_ell((prox_ell){{-1.3128752692124426, -2.6112279678928543, -3.308140160110574},
                                                  {2.5704714309445444, -3.4278060537862238, -2.5717451312295689}, 0.3388415072186407});
    const prox_vec3 r1 = {-0.63578551934309955719, 0.61825398019979577479, -0.31045037556328192747};
    const prox_vec3 r2 = {-2.7709110710768141505, -0.29714544727392292899, -1.5205524811456921136};
    prox_body ba = prox_body_make(&a), bb = prox_body_make(&b);
    double S = prox_shape_pair_scale(&a, &b);
    unsigned long e0 = prox_convex_gjk_certified_count();
    prox_distance_result f = prox_convex_distance(&ba, &bb), q = prox_shape_distance(&a, &b);
    assert_true(prox_convex_gjk_certified_count() != e0); /* the early exit answered */
    assert_true(f.certified && q.certified);
    double ef = fmax(prox_v3_dist(f.p1, r1), prox_v3_dist(f.p2, r2)) / S, eq = fmax(prox_v3_dist(q.p1, r1), prox_v3_dist(q.p2, r2)) / S;
    printf("ELL-ELL 40-digit reference: witnesses %.2g S (early exit), %.2g S (query) off\n", ef, eq);
    assert_true(ef <= 1e-14 && eq <= 1e-14);
}

/* An overlapping pair whose depth the quick search must prove without the cover (the global search),
 * deeper than -sd_max, and equal to the cover's within the bar, each proof on the other answer's side. */
static void check_quick_proof(const prox_shape *a, const prox_shape *b, double sd_max)
{
    assert_int_equal(prox_shape_validate(a), PROX_OK);
    assert_int_equal(prox_shape_validate(b), PROX_OK);
    prox_body ba = prox_body_make(a), bb = prox_body_make(b);
    double S = prox_shape_pair_scale(a, b);
    prox_convex_info fi, gi;
    prox_signed_result f = prox_convex_signed_ex(&ba, &bb, &fi), g = prox_convex_signed_full(&ba, &bb, &gi);
    assert_int_equal(f.status, PROX_OK);
    assert_int_equal(g.status, PROX_OK);
    assert_int_equal(fi.global, 0); /* proved by the quick search */
    assert_true(fi.certified && gi.certified);
    assert_true(f.sd < sd_max);
    assert_true(fabs(f.sd - g.sd) <= PROX_TOL_DEPTH_BAR * S);
    assert_true(fi.lower <= -g.sd + PROX_TOL_DEPTH_BAR * S);
    assert_true(gi.lower <= -f.sd + PROX_TOL_DEPTH_BAR * S);
}

/* A cone (a TRC whose top radius is 0) overlapping a box 2.26 deep. The quick search's inner polytope
 * once stalled here: its nearest triangle was bounded by a side passing 0.13 from the origin, and the
 * fan from each new support point kept that side, so the same bound came back until the point budget
 * ran out and the cover (the global search) had to prove the depth. The triangle across that side now
 * goes with it: the quick search must prove the depth, equal to the cover's within the bar. */
static void test_signed_cone_box_quick(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_trc((prox_trc){{4.1156162303954975, 0.8878579411085139, 0.7091756409110217},
                                                  {-8.231232460790995, -1.7757158822170278, -1.4183512818220434},
                                                  2.7616003340814923, 0.0});
    prox_shape b = prox_shape_from_box((prox_box){{5.8457437491264566, -0.20850486275721702, -0.40812611834270707},
                                                  {{-0.29226235478420698, 0.075080397046360853, -1.3741444575193742},
                                                   {-8.0232898754669737, -3.2391095834234767, 1.5294694433467328},
                                                   {-1.0031057539728445, 2.6539069977712662, 0.3583512913623414}}});
    check_quick_proof(&a, &b, -2.0);
}

/* Two ellipsoids 4.37 deep, their centres 0.8 apart. No ball of that radius fits at their witnesses;
 * the inner polytope needs more than 140 support points here (the budget of a kinked pair; a pair
 * without kinks may take 300), and the ellipsoid inside the Minkowski difference (ell_depth.c) proves
 * it at once. The quick search must prove the depth, equal to the cover's within the bar. */
static void test_signed_deep_ellipsoids_quick(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_ell((prox_ell){{0, 0, 0}, {-0.44367351733321675, -2.6066696263702784, -0.52083466175701165}, 3.1087779404156204});
    prox_shape b = prox_shape_from_ell((prox_ell){{-0.69342827264032936, -0.29131422203628976, 0.34463023937756698},
                                                  {-1.682209355841674, -3.1342140956643902, -0.26039884837141469},
                                                  1.9280693604295682});
    check_quick_proof(&a, &b, -4.0);
}

/* A cone (a TRC whose top radius is 0) overlapping a cylinder 1.35 deep. The inner polytope built
 * from the icosahedron stalls on this pair before its bound reaches the depth; a second one, from the
 * icosahedron turned to the best direction, proves it: the quick search must prove it
 * without the cover, equal to the cover's within the bar. */
static void test_signed_cone_cylinder_turned(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_trc((prox_trc){{-3.0578884529373007, 2.2421649216194894, -3.0139786289348738},
                                                  {6.1157769058746014, -4.4843298432389789, 6.0279572578697476},
                                                  4.6780937539325969, 0.0});
    prox_shape b = prox_shape_from_rcc((prox_rcc){{0.67958150550933705, 0.0071257036235869986, 1.4418447920164907},
                                                  {-2.4912530166407785, -2.7904352414363691, 6.4876215803204547},
                                                  2.6509019858029998});
    check_quick_proof(&a, &b, -1.0);
}

/* Two cones (TRCs whose top radii are 0) overlapping 3.92 deep. The inner polytope from the
 * icosahedron stalls on this pair, and so does the one turned to put a vertex at the best direction;
 * the third, twisted by pi/5 about that vertex, proves the depth: the quick search must prove it
 * without the cover, equal to the cover's within the bar. */
static void test_signed_cones_twisted(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_trc((prox_trc){{-0.20482612394085981, -0.33003910488742094, 1.0297976979798389},
                                                  {0.40965224788171961, 0.66007820977484188, -2.0595953959596778},
                                                  2.7906197441980449, 0.0});
    prox_shape b = prox_shape_from_trc((prox_trc){{-2.1036012593753797, -3.2271676649378271, 0.099488325070228978},
                                                  {-1.8209231377391462, 6.9294808208632963, -3.3189240078511948},
                                                  7.0870681991298037, 0.0});
    check_quick_proof(&a, &b, -3.0);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fast_near),
        cmocka_unit_test(test_fast_touching),
        cmocka_unit_test(test_fast_near_touching),
        cmocka_unit_test(test_fast_far_from_origin),
        cmocka_unit_test(test_fast_close),
        cmocka_unit_test(test_signed_near),
        cmocka_unit_test(test_signed_shallow),
        cmocka_unit_test(test_smooth_witness_reference),
        cmocka_unit_test(test_signed_cone_box_quick),
        cmocka_unit_test(test_signed_deep_ellipsoids_quick),
        cmocka_unit_test(test_signed_cone_cylinder_turned),
        cmocka_unit_test(test_signed_cones_twisted),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
