/* Regression tests that replay fuzzer inputs (fuzz/crashes). Each test opens with the configuration
 * it guards and why it is hard. Contract: valid shapes get PROX_OK with finite answers, never NaN;
 * shapes outside the supported range get PROX_EINVAL_RANGE. */
#include <float.h>

#include "test_util.h"

#include "prox/query.h"
#include "prox/deck.h"
#include "prox/sat.h"

/* fuzz_queries crash-6fd5bd04: an RPP whose extents are subnormal (~3.5e-310) against a sphere
 * whose centre and radius are subnormal. Squares of such sizes underflow, and the solvers would
 * return NaN distances and points with PROX_OK. Sizes that small are outside the supported range
 * (docs/design.md, Tolerances): every query must name that, and never answer with a NaN. */
/* The signed distance of two shapes that must be valid, its status OK and its witnesses on the
 * normal: |p2 - p1 - sd normal| <= bar S (S the pair's scale, returned). */
static prox_signed_result signed_checked(const prox_shape *a, const prox_shape *b, double bar, double *S)
{
    assert_int_equal(prox_shape_validate(a), PROX_OK);
    assert_int_equal(prox_shape_validate(b), PROX_OK);
    *S = prox_shape_pair_scale(a, b);
    prox_signed_result r = prox_shape_signed_distance(a, b);
    assert_int_equal(r.status, PROX_OK);
    assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= bar * *S);
    return r;
}

static void test_fuzz_subnormal_rpp_sph(void **state)
{
    (void)state;
    double t = 3.47328271065196e-310, c = 3.4766779039175e-310, r = 3.47837550055027e-310;
    prox_rpp box = {0, t, 0, t, 0, t};
    prox_sph sph = {prox_v3(c, r, c), r};
    prox_shape a = prox_shape_from_rpp(box), b = prox_shape_from_sph(sph);
    assert_int_equal(prox_shape_validate(&a), PROX_EINVAL_RANGE);
    assert_int_equal(prox_shape_validate(&b), PROX_EINVAL_RANGE);
    prox_distance_result d = prox_shape_distance(&a, &b);
    assert_int_equal(d.status, PROX_EINVAL_RANGE);
    if (d.status == PROX_OK) {
        assert_true(isfinite(d.distance) && d.distance >= 0);
        assert_true(prox_v3_isfinite(d.p1) && prox_v3_isfinite(d.p2));
    }
    prox_signed_result g = prox_shape_signed_distance(&a, &b);
    if (g.status == PROX_OK) assert_true(isfinite(g.sd));
    prox_contain_result k = prox_shape_contains(&a, &b);
    if (k.status == PROX_OK) assert_false(isnan(k.clearance));
}

/* fuzz_queries crash queries-sat-range-5d681c9b: a cylinder of radius 2.8e-312, out of range for
 * prox_rcc_validate. Guards that every entry point (here the SAT verdict, which has a quick path of
 * its own) applies the same validation and returns PROX_EINVAL_RANGE in both argument orders. */
static void test_fuzz_sat_range(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 2.8e-312};
    prox_rcc b = {prox_v3(0.5, 0, 0), prox_v3(0, 1, 0), 1};
    assert_int_equal(prox_rcc_validate(&a), PROX_EINVAL_RANGE);
    assert_int_equal(prox_rcc_sat(&a, &b).status, PROX_EINVAL_RANGE);
    assert_int_equal(prox_rcc_sat(&b, &a).status, PROX_EINVAL_RANGE);
    assert_int_equal(prox_rcc_distance(&a, &b).status, PROX_EINVAL_RANGE);
}

/* fuzz_queries crash-b3b3b7fc: a needle (r 9.4e-97, length 9.3e61) through a disk of radius 5.8e63 and
 * thickness 9.4e-96, valid shapes, where the degree-8 root solve of a rim-rim pair can fail. Guards:
 * a valid pair always gets a finite answer with PROX_OK, never that solver's PROX_ENUMERIC. */
static void test_fuzz_extreme_needle_disk(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(0, -2.3534379293677286e-185, -2.3534382803483239e-185),
                  prox_v3(-2.3534389818985507e-185, -9.2559653443892704e+61, -9.0731789714004204e-231),
                  9.3644955991449635e-97};
    prox_rcc b = {prox_v3(6.578852546238169e-96, -9.0543081646718321e+61, -9.0731789714004204e-231),
                  prox_v3(9.3644955992812182e-97, 6.5947378647064525e-96, 6.5947378298252455e-96),
                  5.7592664921780962e+63};
    assert_int_equal(prox_rcc_validate(&a), PROX_OK);
    assert_int_equal(prox_rcc_validate(&b), PROX_OK);
    prox_distance_result r = prox_rcc_distance(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    assert_true(isfinite(r.distance) && prox_v3_isfinite(r.p1) && prox_v3_isfinite(r.p2));
    prox_signed_result g = prox_rcc_signed_distance(&a, &b);
    assert_int_equal(g.status, PROX_OK);
    assert_true(isfinite(g.sd));
}

/* fuzz_deck crash-62d7c137: a surface-block card made only of '&'-continued blank lines reaches the
 * surface-card parser with no token (reading tok[0] would be an uninitialised read, a SEGV under
 * ASan). Guards: such a card holds nothing and is skipped. */
static void test_fuzz_deck_blank_card(void **state)
{
    (void)state;
    const char text[] = "s\xff;+\xc3\n&\n\xff\xff*\n\n&\n\xff\xff*\n\x0b&";
    prox_deck d = {0};
    prox_status st = prox_deck_parse(text, &d);
    assert_true(st == PROX_OK || st == PROX_ENOMEM);
    prox_deck_free(&d);
    const char deck2[] = "title\n1 0 -1\n\n   &\n     &\n1 so 1\n\n";
    prox_deck e = {0};
    assert_int_equal(prox_deck_parse(deck2, &e), PROX_OK);
    prox_deck_free(&e);
}

/* fuzz_queries crash-95749060: a cylinder of radius 2.8e-86 at the origin against one 1.3e64 away.
 * The rim-rim solve, normalised by the small radius, overflows to NaN; a NaN taken as the first best
 * candidate would refuse every later one (`d < NaN` is false) and the answer would be PROX_OK with a
 * NaN distance. Guards: a non-finite candidate is never taken, in both argument orders. */
static void test_fuzz_rim_rim_overflow(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(4.1445230292290475e-316, 1.0609978954826362e-314, 0), prox_v3(0, 0, 5),
                  2.8324183294453365e-86};
    prox_rcc b = {prox_v3(-1.3278450447320887e+64, 3.0038501333838797e-308, -2.353851178581914e-185),
                  prox_v3(-9.2565287560484838e+61, 0, -17.5), 14};
    prox_distance_result r = prox_rcc_distance(&a, &b), r2 = prox_rcc_distance(&b, &a);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(r2.status, PROX_OK);
    assert_true(isfinite(r.distance) && prox_v3_isfinite(r.p1) && prox_v3_isfinite(r.p2));
    assert_near(r.distance, 1.3278450447320887e+64, 1e-12 * 1.3278450447320887e+64);
    assert_near(r2.distance, r.distance, 1e-12 * r.distance);
    prox_signed_result g = prox_rcc_signed_distance(&a, &b);
    assert_int_equal(g.status, PROX_OK);
    assert_near(g.sd, r.distance, 1e-12 * r.distance);
}

/* fuzz_queries crash queries-needle-depth-f036de42: a needle (radius 7.2e-84, height 46) crossing a
 * cylinder of radius 32.5. The penetration depth's feature enumeration cannot form the degree-8
 * polynomial of two rims ~1e85 apart in size (its coefficients overflow); the signed distance must
 * then come from the global support-function search, not fail with PROX_ENUMERIC: every method
 * agrees that the pair overlaps, and the depth is at most the needle's radius plus rounding. */
static void test_fuzz_needle_depth(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(7.2911185428784936e-304, 2.1219957909652723e-314, 8.8780446954437335e-306),
                  prox_v3(32, 32.501964226947621, 32.501960784313724), 32.501960784313724};
    prox_rcc b = {prox_v3(0, 0, 32.5), prox_v3(32.501960784313724, 32.501956939348474, 6.594809546681169e-96),
                  7.2486056071305163e-84};
    for (int m = 0; m < PROX_METHOD_COUNT_; ++m) {
        prox_distance_result d = prox_rcc_distance_ex(&a, &b, (prox_method)m);
        assert_int_equal(d.status, PROX_OK);
        assert_true(d.intersect);
    }
    prox_signed_result g = prox_rcc_signed_distance(&a, &b), g2 = prox_rcc_signed_distance(&b, &a);
    assert_int_equal(g.status, PROX_OK);
    assert_int_equal(g2.status, PROX_OK);
    assert_true(isfinite(g.sd) && g.sd <= 0.0 && prox_v3_isfinite(g.p1) && prox_v3_isfinite(g.p2));
    assert_near(g2.sd, g.sd, 1e-9 * prox_rcc_pair_scale(&a, &b));
    /* moving the needle by the depth along the normal clears it: the depth is at most how far the
     * needle's axis sits inside A plus its radius, i.e. no more than A's radius */
    assert_true(-g.sd <= a.radius * (1 + 1e-12));
}

/* fuzz_queries crash queries-long-needle-closed-form: a cylinder 1.1e93 long and 32.5 wide crossing
 * a flat one of radius 19716. The closed-form method's rim / lateral-surface quartic cannot be formed
 * for a rim ~1e91 radii from the other axis (its coefficients overflow); that rim then stands in as
 * a point, whose error is below 1e-90 S, instead of failing with PROX_ENUMERIC. Checked on the
 * crossing pair and on the same pair pulled 1000 apart, where the three methods must agree to
 * 1e-12 S (S = 1.1e93: the closed-form verdict may call a gap of 1e-90 S touching). */
static void test_fuzz_long_needle_closed_form(void **state)
{
    (void)state;
    prox_rcc a = {prox_v3(2.2250738585072014e-308, 0, 1.2142157312194475e-319),
                  prox_v3(7.2911220195563975e-304, -1.1040734991732915e+93, 32.501960784313724),
                  32.501960784314576};
    prox_rcc b = {prox_v3(32.501960784313724, 32.501960784314576, 32.501960784313724),
                  prox_v3(1.3906499416903551e-309, 5.4323092248710971e-312, 33.650419235229492),
                  19715.750015318627};
    for (int k = 0; k < 2; ++k) {
        prox_distance_result d[PROX_METHOD_COUNT_];
        for (int m = 0; m < PROX_METHOD_COUNT_; ++m) {
            d[m] = prox_rcc_distance_ex(&a, &b, (prox_method)m);
            assert_int_equal(d[m].status, PROX_OK);
            if (k == 0) assert_true(d[m].intersect);
            assert_true(isfinite(d[m].distance) && prox_v3_isfinite(d[m].p1) && prox_v3_isfinite(d[m].p2));
            assert_near(d[m].distance, d[0].distance, 1e-12 * prox_rcc_pair_scale(&a, &b));
        }
        if (k == 1) { /* the fast and support methods resolve the gap itself */
            assert_near(d[PROX_METHOD_FAST].distance, 1000.0, 1e-9);
            assert_near(d[PROX_METHOD_SUPPORT].distance, 1000.0, 1e-9);
        }
        b.base.z += 1000.0; /* above A's top side (z <= 32.5 there): disjoint by 1000 */
    }
}

/* fuzz/crashes/queries-ell-subnormal-rho-*: a sphere whose centre lies a subnormal distance (6.6e-316)
 * off an ellipsoid's axis. The radial unit vector was the offset times 1 / rho, which overflows for a
 * subnormal rho: the closest point came out (NaN, inf, NaN) under PROX_OK. The answer must be finite
 * and equal (to 1e-12 S) to the same pair with the centre exactly on the axis. */
static void test_fuzz_ell_subnormal_rho(void **state)
{
    (void)state;
    prox_shape e = prox_shape_from_ell((prox_ell){prox_v3(0.5, 0, 0), prox_v3(2, 0, 0), 1.9365});
    const double off[] = {6.6e-316, 0.0};
    double d[2];
    for (int k = 0; k < 2; ++k) {
        prox_shape s = prox_shape_from_sph((prox_sph){prox_v3(2.6, off[k], 0), 1.0});
        prox_distance_result r = prox_shape_distance(&e, &s), t = prox_shape_distance(&s, &e);
        prox_signed_result g = prox_shape_signed_distance(&e, &s);
        assert_int_equal(r.status, PROX_OK);
        assert_int_equal(t.status, PROX_OK);
        assert_int_equal(g.status, PROX_OK);
        assert_true(prox_v3_isfinite(r.p1) && prox_v3_isfinite(r.p2));
        assert_true(prox_v3_isfinite(t.p1) && prox_v3_isfinite(t.p2));
        assert_true(prox_v3_isfinite(g.p1) && prox_v3_isfinite(g.p2) && prox_v3_isfinite(g.normal));
        d[k] = g.sd;
    }
    assert_near(d[0], d[1], 1e-12 * 4.0);
    assert_near(d[1], -(2.5 - (2.6 - 1.0)), 1e-12 * 4.0); /* on the axis: the tip at x = 2.5 is 0.9 deep */
}

/* fuzz/crashes/pairs-sph-rcc-subnormal-normal-*: a sphere centre a subnormal distance (1e-317) below
 * a cylinder's base. The outward normal x - q has a subnormal length, and 1 / |x - q| overflowed: the
 * normal and a witness came out (NaN, NaN, inf) under PROX_OK. The normal must be the unit -z. */
static void test_fuzz_sph_rcc_subnormal_normal(void **state)
{
    (void)state;
    prox_shape s = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 1.0});
    prox_shape c = prox_shape_from_rcc((prox_rcc){prox_v3(0, 0, 1e-317), prox_v3(0, 0, 1), 0.1});
    prox_signed_result r = prox_shape_signed_distance(&s, &c);
    assert_int_equal(r.status, PROX_OK);
    assert_true(prox_v3_isfinite(r.normal) && prox_v3_isfinite(r.p1) && prox_v3_isfinite(r.p2));
    assert_near(r.sd, -1.0, 1e-15);
    assert_near(prox_v3_norm(r.normal), 1.0, 1e-15);
    assert_near(fabs(r.normal.z), 1.0, 1e-15);
}

/* fuzz/crashes/pairs-signed-witness-*: a cone whose base radius is 4e-91 (its apex, in effect, at the
 * origin) against a disk 4e-33 wide and 5e-72 thick sitting on that apex. The signed distance (-0)
 * was right, but the cone's base disk as a support set had a Gram determinant that underflows: its
 * projections were NaN and both witnesses fell back to the pair's centre (0, 0, 1), one unit outside
 * the disk. The witnesses must lie in their solids and p2 - p1 = sd normal. */
static void test_fuzz_signed_witness_tiny_disk(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_trc((prox_trc){prox_v3(0, 0, 0), prox_v3(0, 0, 2), 3.8e-91, 0.0025});
    prox_shape b = prox_shape_from_rcc((prox_rcc){prox_v3(1.3e-71, 0, 0), prox_v3(0, 4.6e-72, 2e-76), 3.9e-33});
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    prox_signed_result r = prox_shape_signed_distance(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    double S = prox_shape_pair_scale(&a, &b), r0 = 1e-12 * S;
    prox_shape ba = prox_shape_from_sph((prox_sph){r.p1, r0}), bb = prox_shape_from_sph((prox_sph){r.p2, r0});
    assert_true(prox_shape_distance(&a, &ba).distance <= r0);
    assert_true(prox_shape_distance(&b, &bb).distance <= r0);
    assert_true(r.sd <= 0.0 && r.sd >= -1e-12 * S);
    assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= 1e-12 * S);
}

/* fuzz/crashes/pairs-speck-rhp-disk-*: an RHP 6e-67 across and 1.4e-76 high at the origin, touching
 * (5.6e-38 apart, 4e-30 of the scale) a cylinder of radius 7e-9 and height 4.6e-72 above it. GJK
 * encloses the origin to rounding, and the depth search's descent from its best start needs many
 * halvings of a gradient step across the speck's faces: stopped after 8 (as the many starts are), it
 * left a depth of 1.2e-6 S with witnesses 0.5 S apart. The best's own descent keeps halving. */
static void test_fuzz_speck_rhp_disk(void **state)
{
    (void)state;
    prox_rhp h = {prox_v3(0, 0, 0), prox_v3(0, 1.80492527548519e-153, 1.3980459370475454e-76),
                  {prox_v3(1.207373746603704e-153, 6.3522879150557213e-67, 0), prox_v3(-5.5012427065911404e-67, 3.1761439575278607e-67, -1.3499265682588742e-230),
                   prox_v3(-5.5012427065911404e-67, -3.1761439575278607e-67, -1.3499265682588742e-230)}};
    prox_shape a = prox_shape_from_rhp(h);
    prox_shape b = prox_shape_from_rcc((prox_rcc){prox_v3(0, 2.4888311715110058e-91, 5.6492506810176948e-38),
                                                  prox_v3(1.3987219298729592e-76, 1.3980432860952889e-76, 4.5810391494743659e-72),
                                                  7.0415073798985561e-09});
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    prox_signed_result r = prox_shape_signed_distance(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    double S = prox_shape_pair_scale(&a, &b);
    assert_true(fabs(r.sd) <= 1e-9 * S); /* touching, within the depth bar */
    assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= 1e-9 * S);
    double r0 = 1e-9 * S;
    prox_shape ba = prox_shape_from_sph((prox_sph){r.p1, r0}), bb = prox_shape_from_sph((prox_sph){r.p2, r0});
    assert_true(prox_shape_distance(&a, &ba).distance <= r0);
    assert_true(prox_shape_distance(&b, &bb).distance <= r0);
}

/* fuzz/crashes/pairs-rhp-needle-ell-*: an RHP about 1e-37 across and a needle ellipsoid (semi-axis
 * 4.8e-38, radius 1.1e-47) overlapping by 7.9e-5 of the scale. With the valleys of the kink circles
 * located only to 1e-6 rad among the depth's starts, the normal stayed that far off and the witnesses
 * missed p2 - p1 = sd n by 5e-9 S; and a cover whose pruned bounds equal the threshold failed its own
 * certificate by an ulp (best - lower <= tol, where the pruning test lower >= best - tol holds). */
static void test_fuzz_rhp_needle_ell(void **state)
{
    (void)state;
    prox_rhp h = {prox_v3(0, 5.0758836746312984e-116, 0), prox_v3(0, 1.7448407937390965e-76, 7.406757887653272e-38),
                  {prox_v3(1.7969872529911386e-52, 5.3542345654239286e-38, -1.2613193290107081e-76),
                   prox_v3(-4.6369031514778472e-38, 2.6771172827119799e-38, -6.3065966450535771e-77),
                   prox_v3(-4.6369031514778649e-38, -2.6771172827119486e-38, 6.3065966450535035e-77)}};
    prox_shape a = prox_shape_from_rhp(h);
    prox_shape b = prox_shape_from_ell((prox_ell){prox_v3(2.1085801683440298e-52, 5.3530955725837765e-38, 6.7683817567755913e-43),
                                                   prox_v3(2.0049418238732789e-76, 1.7253262322270832e-47, 4.7641868958379713e-38),
                                                   1.110049511311543e-47});
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    prox_signed_result r = prox_shape_signed_distance(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    double S = prox_shape_pair_scale(&a, &b);
    assert_true(r.sd < 0.0);
    assert_true(r.certified);
    assert_true(r.sd_lower <= r.sd && r.sd <= r.sd_upper && r.sd_upper - r.sd_lower <= 1e-9 * S);
    assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= 1e-12 * S);
}

/* fuzz/crashes/pairs-rhp-lean-needle-*: an RHP 1e-42 long whose facet vectors, 1.2e-76 long, lean
 * 6e-11 rad towards its height (inside PROX_BOX_ORTHO_TOL). With the card's own vectors as side
 * normals, the corners' spread along each was the lean times the height (6e-53), so the aspect test
 * passed a needle 1e-34 as wide as it is long; its corners then collapsed and a sphere 1e-13 away
 * was given the sphere's centre as a common point, outside the needle. The side normals are the facet vectors'
 * parts across the height, as the hexagon is built, and the needle is outside the supported aspect
 * ratio. The same card with facet vectors 1e-9 of the height is valid, and its side planes pass
 * through the top corners as through the bottom ones. */
static void test_fuzz_rhp_lean_needle(void **state)
{
    (void)state;
    prox_rhp h = {prox_v3(0, 1.7241863383316155e-314, 0), prox_v3(1.3687218047129105e-52, 9.9618511490410413e-43, 2.8963157129448456e-57),
                  {prox_v3(9.8534262643718509e-77, 0, 6.9900236741924278e-77),
                   prox_v3(1.0980251207091207e-76, -8.317091154053073e-87, -5.0383056221666099e-77),
                   prox_v3(1.1268249427193569e-77, -8.317091154053073e-87, -1.2028329296359038e-76)}};
    prox_shape a = prox_shape_from_rhp(h);
    prox_shape b = prox_shape_from_sph((prox_sph){prox_v3(1.3139866747936691e-47, 1.804925276444093e-153, 1.031703574813918e-13),
                                                   1.0387856152602562e-13});
    assert_int_equal(prox_shape_validate(&a), PROX_EINVAL_RANGE);
    assert_int_not_equal(prox_shape_distance(&a, &b).status, PROX_OK);
    assert_int_not_equal(prox_shape_signed_distance(&a, &b).status, PROX_OK);
    /* Facet vectors 1e-9 of the height, leaning the same 6e-11 rad: valid. A point half way in from
     * each side's middle near the top is in the solid, one half way out is that far from it to 1e-3
     * (the lean put the top corners 2.5e-2 of the width off the side planes the card's vectors gave). */
    for (int i = 0; i < 3; ++i) h.r[i] = prox_v3_scale(h.r[i], 1e25);
    a = prox_shape_from_rhp(h);
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    prox_vec3 w = prox_v3_normalize(h.axis), top = prox_v3_add(h.base, prox_v3_scale(h.axis, 0.999));
    for (int i = 0; i < 3; ++i) {
        prox_vec3 u = prox_v3_normalize(prox_v3_sub(h.r[i], prox_v3_scale(w, prox_v3_dot(h.r[i], w))));
        double len = prox_v3_dot(h.r[i], u);
        prox_vec3 in = prox_v3_add(top, prox_v3_scale(u, len * 0.5));
        prox_vec3 out = prox_v3_add(top, prox_v3_scale(u, len * 1.5));
        prox_shape sin = prox_shape_from_sph((prox_sph){in, 1e-6 * len});
        prox_shape sout = prox_shape_from_sph((prox_sph){out, 1e-6 * len});
        prox_distance_result din = prox_shape_distance(&a, &sin), dout = prox_shape_distance(&a, &sout);
        assert_int_equal(din.status, PROX_OK);
        assert_int_equal(dout.status, PROX_OK);
        assert_true(din.distance == 0.0);
        assert_true(fabs(dout.distance - 0.5 * len) <= 1e-3 * len);
    }
}

/* fuzz/crashes/pairs-thin-box-arb-*: an ARB tetrahedron 5e-33 across against a BOX with edges of
 * 3.3e-33, 6.9e-62 and 7.5e-67 (two thin edges: a needle), overlapping by 3.2e-7 S. A BOX has no
 * aspect limit, but its polytope, taken relative to its centroid, lost both thin edges to rounding
 * (a segment with face planes through it), and the polytope solver's witnesses missed
 * p2 - p1 = sd normal by 3.3e-6 S. Such a box goes to the support-function method, whose box
 * support is exact; the same box with its thin edges 5e8 and 4e8 times shorter than the long one
 * stays with the polytope solver and holds too. */
static void test_fuzz_thin_box_arb(void **state)
{
    (void)state;
    prox_arb t = {{prox_v3(3.3155999651021467e-33, 3.3088288881520212e-33, 2.5261980302115356e-52),
                   prox_v3(1.8809654220314158e-153, 8.2373241075824398e-67, 4.9141648237729315e-62),
                   prox_v3(1.0327730911167174e-47, 7.4998296699012955e-67, 4.8563527139589948e-33),
                   prox_v3(1.6563688822829495e-47, 3.7008123681729734e-33, 2.4052345417886232e-57),
                   prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0)},
                  {1230, 1240, 1340, 2340, 0, 0}};
    prox_box x = {prox_v3(5.9351120680648776e-38, 2.4046279508075671e-57, 2.4217931400783491e-52),
                  {prox_v3(1.1771390418072967e-47, 6.2301155223114098e-38, 3.315620559445334e-33),
                   prox_v3(-1.3117348647605852e-71, -6.9424761649311972e-62, 1.3045045301015335e-66),
                   prox_v3(7.4940454005029523e-67, -1.4159502166668002e-76, 5.0295616929504476e-91)}};
    for (int pass = 0; pass < 2; ++pass) {
        prox_shape a = prox_shape_from_arb(t), b = prox_shape_from_box(x);
        assert_int_equal(prox_shape_validate(&a), PROX_OK);
        assert_int_equal(prox_shape_validate(&b), PROX_OK);
        double S = prox_shape_pair_scale(&a, &b);
        prox_signed_result r = prox_shape_signed_distance(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        assert_true(r.sd < 0.0);
        assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= 1e-9 * S);
        prox_distance_result d = prox_shape_distance(&a, &b);
        assert_int_equal(d.status, PROX_OK);
        assert_true(d.intersect);
        x.edge[1] = prox_v3_scale(x.edge[1], 1e20), x.edge[2] = prox_v3_scale(x.edge[2], 1e25);
    }
    /* fuzz/crashes/pairs-plate-box-arb-*: a plate BOX (edges 2.5e-91, 6.9e-33, 7.3e-43: one thin edge)
     * touching a face of an ARB tetrahedron stays with the polytope solver, whose witnesses meet at
     * sd = 0 (the support-function method's were 6.4e-9 S apart). */
    prox_arb t2 = {{prox_v3(0, 2.381983181597897e-38, 7.271344439915647e-43),
                    prox_v3(2.6314121737938698e-52, 3.852025654882619e-34, 4.9141350922803505e-62),
                    prox_v3(5.6492516482548959e-38, 2.829180334625324e-77, 6.9901110068883757e-77),
                    prox_v3(1.65021493253019e-153, 6.3522996091262562e-67, 6.2335817748096524e-38),
                    prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0)},
                   {1230, 1240, 1340, 2340, 0, 0}};
    prox_box plate = {prox_v3(6.9901110068883757e-77, 1.65021493253019e-153, 6.3522996091262562e-67),
                      {prox_v3(1.7219425775536767e-259, 1.2027122125173386e-153, 2.4845848270902153e-91),
                       prox_v3(4.857875059588523e-33, 4.8578750597241048e-33, 0),
                       prox_v3(-5.1366675560706209e-43, 5.1366675559272578e-43, -2.4865050827789592e-105)}};
    prox_shape a = prox_shape_from_arb(t2), b = prox_shape_from_box(plate);
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-12, &S);
    assert_true(fabs(r.sd) <= 1e-12 * S);
}

/* fuzz/crashes/pairs-flat-cone-needle-*: a TRC 1e-42 high with radii 2.5e-91 and 4.2e-33 (a cone so
 * flat that its lateral normals lie 2.35e-10 rad from its axis) crossed by a needle RCC, 8.6e-11 S
 * deep. The lateral surface's kink circle, kept by its cosine alone, had cosine -1 in doubles and
 * collapsed onto the axis: the normal came out the axis and p1 the apex, 8.7e-6 S off p2 - sd normal.
 * Its sine is kept apart, and the circle, smaller than the search radius, is searched whole; the
 * normal tilts by 2.35e-10 rad and p1 moves onto the generator under the needle's tip. */
static void test_fuzz_flat_cone_needle(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_trc((prox_trc){prox_v3(3.3804736801365374e-57, 1.4519044824369659e-47, 4.7537793470492743e-38),
                                                   prox_v3(9.9618512300575918e-43, 7.4955226072778192e-67, 3.5379208477231184e-57),
                                                   2.4876300932210241e-91, 4.2370458799020867e-33});
    prox_shape b = prox_shape_from_rcc((prox_rcc){prox_v3(3.6579625774051142e-86, 1.3701162368078138e-71, 2.3169820794023654e-52),
                                                  prox_v3(7.2643449230955801e-43, 5.6469870271868855e-38, 8.6097277008187327e-67),
                                                  1.7441621087990435e-76});
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-9, &S);
    assert_true(r.sd < 0.0);
    /* the normal leaves the axis by the lateral surface's 2.35e-10 rad */
    double tilt = prox_v3_norm(prox_v3_cross(r.normal, prox_v3(1, 0, 0)));
    assert_true(tilt > 2.0e-10 && tilt < 2.7e-10);
}

/* fuzz/crashes/pairs-flat-rec-speck-*: an REC with semi-axes 4.3e-33 and 1.04e-42 (its support point
 * moves a1^2 / a2, 2e9 S, per rad of the normal) holding a 4e-62 RCC 1.2e-10 S from its flat side. The
 * optimum lies on the REC's kink circle, whose search measured angles from an arbitrary origin, near
 * 1 rad, where they resolve 1e-16: the normal kept 6e-17 off, and p1 stood 1.3e-7 S off p2 - sd normal.
 * Angles are measured from the start direction's projection. */
static void test_fuzz_flat_rec_speck(void **state)
{
    (void)state;
    prox_rec e = {prox_v3(0, 2.1085753642496182e-52, 1.8043426158015814e-153),
                  prox_v3(9.0667447068838282e-43, 3.8903696715447937e-33, 1.312377718283597e-47),
                  prox_v3(4.2785913514001617e-33, -9.9715191006057791e-43, -1.4511562733555997e-58),
                  prox_v3(7.8234627302759869e-67, 3.5082482334713479e-57, -1.0399736552673013e-42)};
    prox_shape a = prox_shape_from_rec(e);
    prox_shape b = prox_shape_from_rcc((prox_rcc){prox_v3(3.2425151552161738e-86, 6.5251640814697118e-38, 4.9084415041371802e-62),
                                                  prox_v3(2.5826636175792067e-57, 4.9094022323932142e-62, 4.5899647488703429e-72),
                                                  4.1801574660598025e-62});
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-9, &S);
    assert_true(r.sd < 0.0 && fabs(r.sd + 1.0399736552673013e-42) <= 1e-9 * S);
}

/* fuzz/crashes/pairs-flat-ell-box-*: a flat oblate ELL (semi-axis 1.7e-52 along its axis, radius
 * 1.09e-42) pierced by a thin bar BOX along its axis, 6.7e-6 S deep. The depth's normal is the axis
 * tilted by 1.6e-15 rad, where the ellipsoid's support point sits over the bar's end; the value of
 * phi differs from the axis's by 1e-20 S, so only the final Newton polish finds it, and the
 * ellipsoid's Hessian, formed as b^2 I + (a^2 - b^2) w w^T, lost a^2 and was 0 at the pole: p1
 * stayed at the pole, 5.1e-6 S off p2 - sd normal. M is applied by parts. */
static void test_fuzz_flat_ell_box(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_ell((prox_ell){prox_v3(1.4501617399449796e-47, 3.2526678336448472e-86, 5.8798602676585853e-62),
                                                   prox_v3(1.6933980572287468e-52, 1.6578004078054256e-76, 2.6385770341584165e-308),
                                                   1.0860413422903723e-42});
    prox_box x = {prox_v3(7.0020766345018471e-77, 1.8322197603314477e-76, 1.1081806845832649e-47),
                  {prox_v3(8.1523834493454327e-43, 1.2444927247846713e-47, 1.2831293658215027e-153),
                   prox_v3(3.5391017144799187e-57, -2.3183852293721245e-52, 1.7317746548165821e-153),
                   prox_v3(2.7629558064904835e-158, -1.8099233395719769e-153, -2.4230055140642997e-52)}};
    prox_shape b = prox_shape_from_box(x);
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-9, &S);
    assert_true(r.sd < 0.0);
}

/* fuzz/crashes/pairs-tall-rec-wedge-*: an REC 131072 high with semi-axes 1.5 and 0.7 against a unit
 * wedge at its side, 0.2998 deep. The inner polytope proves the depth within 1e-10 S, which is 1.3e-5
 * here (the pair's scale is the REC's height): its best direction lay 9e-3 rad from the optimum (the
 * wedge's face normal), outside the 1e-3 rad the descent searched, and the witnesses missed the normal
 * by 1.9e-9 S with a depth 1.1e-6 too large. Such an answer takes the wider search once. */
static void test_fuzz_tall_rec_wedge(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_rec((prox_rec){prox_v3(0, 0, 0), prox_v3(0, 4.7783097267364807e-299, 131071.998046875),
                                                  prox_v3(1.5, 0, 0), prox_v3(0, 0.7, -2.5518927448709041e-304)});
    prox_shape b = prox_shape_from_wed((prox_wed){prox_v3(1.200244140625, 0, 0), prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1)});
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-12, &S);
    assert_true(fabs(r.sd + (1.5 - 1.200244140625)) <= 1e-12 * S);
}

/* fuzz/crashes/pairs-needle-ell-plate-*: a needle ELL (semi-axis 1.25e-47, radius 2.9e-57) through a
 * square plate BOX 3.6e-57 across, 1.2e-10 S deep. The normal must be perpendicular to the needle to
 * 1e-19 (its support point moves 2e9 S per rad along the axis); the Newton polish's 2 x 2 Hessian has
 * that stiff direction beside a nearly flat one, its determinant was rounding and the step was
 * rejected: p1 stood 2.2e-7 S along the needle. The step goes along the stiff eigenvector alone. */
static void test_fuzz_needle_ell_plate(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_ell((prox_ell){prox_v3(1.3906711615670009e-309, 3.4766779039554464e-310, 9.7304506985833561e-72),
                                                   prox_v3(1.1123791639185887e-74, 2.3181975655773565e-52, 1.2469013329346409e-47),
                                                   2.8963084203486748e-57});
    prox_box x = {prox_v3(3.5400537317841486e-62, 1.3980432861758759e-76, 1.3980432860952889e-76),
                  {prox_v3(1.1963084534858382e-153, 1.2027122125173386e-153, 2.4869818447791177e-91),
                   prox_v3(2.4052551140642279e-57, 2.7432344851520733e-57, 0),
                   prox_v3(-2.777625635117845e-57, 2.4354091128497663e-57, 1.5834484125274852e-120)}};
    prox_shape b = prox_shape_from_box(x);
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-9, &S);
    assert_true(r.sd < 0.0);
}

/* fuzz/crashes/pairs-disk-ell-needle-*: a flat ELL (a disk 1.5e-47 thick, radius 6.8e-38) crossed by
 * a needle RCC (radius 3.3e-86) tilted 2.3e-10 rad from the disk's axis. The depth is the disk's
 * thickness along its axis; the search stopped at the needle's end-face normal, 2.3e-10 rad off,
 * where the disk's support point lies on its rim (p1 0.36 S off p2 - sd normal, the depth 5e-11 S too
 * large). The needle's lateral Hessian r / |Pd| was 4e212 there and froze the Newton polish; a
 * radius below rounding is left out of it. */
static void test_fuzz_disk_ell_needle(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_ell((prox_ell){prox_v3(6.9533558078350043e-309, 0, 0),
                                                   prox_v3(0, 4.3458473798968777e-311, 1.5176459167286629e-47),
                                                   6.8224679604400703e-38});
    prox_shape b = prox_shape_from_rcc((prox_rcc){prox_v3(0, 6.3240402667679558e-320, 0),
                                                  prox_v3(0, 3.3804736801365374e-57, 1.4519044620453895e-47),
                                                  3.2526678216597571e-86});
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-9, &S);
    assert_true(fabs(r.sd + 1.5176459167286629e-47) <= 1e-12 * S);
}

/* fuzz/crashes/pairs-speck-box-arb-*: an ARB tetrahedron 7e-38 across with a corner 1.04e-42 from the
 * origin, and a BOX speck (edges 4.4e-62, 1.2e-71, 8.6e-67) at the origin. The polytope solver
 * answered 1.03e-47, uncertified, in the ARB-first order and 1.04e-42 in the other. An uncertified
 * disjoint polytope answer now takes the support-function method's certified one: both orders agree. */
static void test_fuzz_speck_box_arb(void **state)
{
    (void)state;
    prox_arb t = {{prox_v3(5.1965198979161049e-191, 1.0327562839796244e-47, 1.0406736229969097e-42),
                   prox_v3(4.7676443198840789e-38, 1.3694546759344447e-71, 2.177997274330792e-76),
                   prox_v3(1.2576784215361251e-76, 5.6458121783488538e-38, 5.8777587398662055e-39),
                   prox_v3(4.5810391479139079e-72, 4.2796599595423588e-38, 2.3797594711882403e-38),
                   prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0)},
                  {1230, 1240, 1340, 2340, 0, 0}};
    prox_box x = {prox_v3(0, 1.3399466053799959e-206, 2.4045855198813497e-57),
                  {prox_v3(1.7870744721938102e-317, 4.4279843368336191e-62, 2.7815595026546826e-310),
                   prox_v3(1.4916681462400413e-154, 0, 1.1992142135052128e-71),
                   prox_v3(8.6097276566689473e-67, 0, -1.0709393158138347e-149)}};
    prox_shape a = prox_shape_from_arb(t), b = prox_shape_from_box(x);
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    double S = prox_shape_pair_scale(&a, &b);
    prox_distance_result ab = prox_shape_distance(&a, &b), ba = prox_shape_distance(&b, &a);
    assert_int_equal(ab.status, PROX_OK);
    assert_int_equal(ba.status, PROX_OK);
    assert_true(ab.certified && ba.certified);
    assert_true(fabs(ab.distance - ba.distance) <= 1e-12 * S);
    assert_true(ab.distance > 1.04e-42 && ab.distance < 1.041e-42);
    prox_signed_result r = prox_shape_signed_distance(&a, &b);
    assert_true(fabs(r.sd - ab.distance) <= 1e-12 * S);
}

/* fuzz/crashes/pairs-flat-cone-bar-*: a flat TRC (height 1.4e-42, radii 3.3e-86 and 3.3e-33) standing
 * on edge, a plate BOX at its rim, 3e-13 S deep. The normal lies 4.4e-10 rad from the cone's axis; the
 * support set's generator took its radial direction from one rejection (2.5e-7 of the axis left in
 * it: the generator 1.7e-39 off the surface, p1 outside A), and the normal's azimuth about the axis is
 * known only to eps / 4.4e-10, which put p1 6.8e-8 S aside. The direction is rejected twice, and each
 * witness is replaced by its body's boundary point nearest the other witness -+ sd n when that meets
 * p2 - p1 = sd n better. */
static void test_fuzz_flat_cone_bar(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_trc((prox_trc){prox_v3(0, 0, 3.1207617423289324e-33),
                                                   prox_v3(1.0862171861870677e-42, 9.502926062128442e-43, 6.7594656036281756e-67),
                                                   3.2526002378688664e-86, 3.3163728872201404e-33});
    prox_box x = {prox_v3(3.6312827119547861e-43, 2.4864294077192132e-91, 9.7481373691084716e-72),
                  {prox_v3(1.3124110689152746e-71, 3.9616653811780354e-319, 6.8189299973142127e-38),
                   prox_v3(7.7214844432270255e-43, 7.6794591202961698e-43, 0),
                   prox_v3(-5.0174541501353949e-38, 5.0449118301161264e-38, 9.6568851227483034e-72)}};
    prox_shape b = prox_shape_from_box(x);
    double S;
    prox_signed_result r = signed_checked(&a, &b, 1e-9, &S);
    assert_true(r.sd < 0.0);
    /* each witness in its solid: a ball of 1e-12 S about it meets the solid */
    double rr = 1e-12 * S;
    prox_shape w1 = prox_shape_from_sph((prox_sph){r.p1, rr}), w2 = prox_shape_from_sph((prox_sph){r.p2, rr});
    assert_true(prox_shape_distance(&a, &w1).distance <= rr);
    assert_true(prox_shape_distance(&b, &w2).distance <= rr);
}

/* fuzz/crashes/pairs-box-rcc-unit-normal-*: a box and a cylinder 1.8e-43 apart at scale 4.9e-33
 * (4e-11 S): the signed distance's normal, (p2 - p1) divided by the distance, came out 1.03 long (the
 * distance and |p2 - p1| differ by rounding of S). It is normalised by |p2 - p1|. */
static void test_fuzz_box_rcc_unit_normal(void **state)
{
    (void)state;
    prox_box x = {prox_v3(5.2038347277141554e-55, 6.7682715877818666e-43, 1.9005797148876562e-52),
                  {prox_v3(4.8525853120970212e-33, 1.3709971058516578e-71, 5.354216541011549e-38),
                   prox_v3(5.6713997359164896e-43, -1.3161605196790144e-71, -5.14006075943841e-38),
                   prox_v3(0, 4.0170954453763435e-57, -1.0286147725546321e-90)}};
    prox_shape a = prox_shape_from_box(x);
    prox_shape b = prox_shape_from_rcc((prox_rcc){prox_v3(2.3165694317458448e-52, 8.6008126424867274e-43, 1.1760699155797873e-47),
                                                  prox_v3(2.485839516356204e-91, 4.6645179592040898e-33, 6.3798628115946223e-67),
                                                  1.2439549944525115e-47});
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    prox_signed_result r = prox_shape_signed_distance(&a, &b);
    assert_int_equal(r.status, PROX_OK);
    double S = prox_shape_pair_scale(&a, &b);
    assert_true(fabs(prox_v3_norm(r.normal) - 1.0) <= 1e-12);
    assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= 1e-9 * S);
}

/* fuzz/crashes/pairs-box-box-unit-normal-*: two boxes 9.1e-43 apart at scale 4.1e-33 (2.2e-10 S),
 * one a flake (edges 1.1e-47, 1.4e-76, 2.4e-57). The signed distance's normal, (p2 - p1) divided by
 * the certified distance, came out 8.3e-8 short of unit length (the two differ by rounding of S). It
 * is normalised by |p2 - p1| (the shared disjoint result of the box, sphere and polytope pairs). */
static void test_fuzz_box_box_unit_normal(void **state)
{
    (void)state;
    prox_box x = {prox_v3(4.5898827218673197e-72, 9.0544833190134022e-43, 6.1305458782764389e-62),
                  {prox_v3(3.5335622388404566e-57, 1.1097864152093573e-47, 3.540053731783817e-62),
                   prox_v3(1.3980432857307387e-76, -4.4513726587767823e-86, -4.4595503115607228e-91),
                   prox_v3(-7.6724063549193705e-72, 7.6724063553616302e-72, -2.4052551140642281e-57)}};
    prox_box y = {prox_v3(0, 0, 0),
                  {prox_v3(3.3156234292597501e-33, 1.5762945277690138e-52, 6.990111006888342e-77),
                   prox_v3(-3.3449472249974775e-91, -1.5902354772589009e-110, 1.5866107673983866e-47),
                   prox_v3(1.9432500780644715e-52, -4.0874883305346056e-33, -7.0741327462581318e-112)}};
    prox_shape a = prox_shape_from_box(x), b = prox_shape_from_box(y);
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    double S = prox_shape_pair_scale(&a, &b);
    for (int k = 0; k < 2; ++k) {
        prox_signed_result r = k ? prox_shape_signed_distance(&b, &a) : prox_shape_signed_distance(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        assert_true(r.sd > 0.0);
        assert_true(fabs(prox_v3_norm(r.normal) - 1.0) <= 1e-12);
        assert_true(prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) <= 1e-12 * S);
        prox_test_result t = prox_shape_test(k ? &b : &a, k ? &a : &b);
        assert_int_equal(t.status, PROX_OK);
        if (prox_v3_norm(t.direction) > 0.0) assert_true(fabs(prox_v3_norm(t.direction) - 1.0) <= 1e-12);
    }
}

/* fuzz/crashes/pairs-wed-plate-witness-*: a wedge whose triangle has a side 1e-10 of its height (a
 * sliver) 1.4e-10 S deep in a plate (a box with an edge 1.2e-7 of the others). The polytope solver's
 * depth was right (within 1e-11 S of the support-function method's) but its witnesses, from the two
 * support features along the normal, missed p2 - p1 = sd n by 2.1e-8 S. Witnesses off by more than the
 * touching band hand the pair to the support-function engine. */
static void test_fuzz_wed_plate_witness(void **state)
{
    (void)state;
    prox_wed w = {prox_v3(1.2027122116816206e-153, 2.4869818447791177e-91, 3.6579625062864334e-86),
                  prox_v3(1.1319592074145408e-71, 1.5092143548155682e-154, 5.5408093153074158e-48),
                  prox_v3(6.35233319397365e-67, 6.3070501717360453e-38, 1.178477528557165e-47),
                  prox_v3(-4.7641959697253089e-38, 4.7982198275968675e-67, 9.7330104448082804e-62)};
    prox_box x = {prox_v3(0, 0, 1.3568136935417313e-153),
                  {prox_v3(2.3832323009691365e-38, 1.0311923825665205e-71, 6.8159077463737114e-38),
                   prox_v3(-2.7993032747598162e-72, 5.9385647448681623e-38, -8.0057769747949401e-72),
                   prox_v3(-8.8910897635977534e-45, -3.6593981891289865e-84, 3.108834964307688e-45)}};
    prox_shape a = prox_shape_from_wed(w), b = prox_shape_from_box(x);
    double S;
    for (int k = 0; k < 2; ++k) {
        prox_signed_result r = signed_checked(k ? &b : &a, k ? &a : &b, 1e-12, &S);
        assert_true(r.sd < 0.0 && r.sd > -1e-9 * S); /* shallow */
        assert_true(r.sd_lower <= r.sd && r.sd <= r.sd_upper);
    }
}

/* fuzz/crashes/pairs-sliver-wed-speck-box-*: a sliver wedge (a side 5.5e-48 against a height of
 * 4.8e-38) and a box 6.4e-67 across 1.1e-42 from it (1.4e-5 S). In the pair's frame the speck's plane
 * offsets are lost to rounding: the polytope solver took the pair as meeting in one order (distance 0
 * against 1.08e-42 the other way), and its signed distance came out short by the sliver's thickness
 * (8e-11 S) with witnesses off the wedge. A common point is checked again in each polytope's own
 * frame, and a disjoint signed answer its enclosure does not certify goes to the engine. */
static void test_fuzz_sliver_wed_speck_box(void **state)
{
    (void)state;
    prox_wed w = {prox_v3(1.2027122116816206e-153, 2.4869818447791177e-91, 3.6579625062864334e-86),
                  prox_v3(1.1319592074145408e-71, 1.5092143548259025e-154, 5.5408093153074158e-48),
                  prox_v3(6.35233319397365e-67, 6.2335817748096524e-38, 1.178477528557165e-47),
                  prox_v3(-4.7641959697253089e-38, 4.8547711862809753e-67, 9.7330104448082838e-62)};
    prox_box x = {prox_v3(1.2773025056592557e-153, 5.1534160668080408e-62, 1.084642096542917e-42),
                  {prox_v3(4.0569736951545834e-86, 1.3141763152352841e-71, 3.6446862612457667e-86),
                   prox_v3(-9.2727588351129916e-82, -1.7789959029201508e-81, 6.3523221598895622e-67),
                   prox_v3(4.58332338651024e-72, -1.41491078479297e-86, 6.6904749722551006e-87)}};
    prox_shape a = prox_shape_from_wed(w), b = prox_shape_from_box(x);
    double S;
    prox_distance_result ab = prox_shape_distance(&a, &b), ba = prox_shape_distance(&b, &a);
    assert_int_equal(ab.status, PROX_OK);
    assert_false(ab.intersect || ba.intersect);
    for (int k = 0; k < 2; ++k) {
        prox_signed_result r = signed_checked(k ? &b : &a, k ? &a : &b, 1e-12, &S);
        assert_true(r.certified);
        assert_true(fabs(r.sd - ab.distance) <= 1e-12 * S && fabs(ba.distance - ab.distance) <= 1e-12 * S);
    }
}

/* fuzz/crashes/pairs-axis-support-*: an ellipsoid of size 1 at the origin against a cylinder 1e50 away
 * whose axis points exactly along the line of centres. The cylinder's support point along its axis
 * took the radial direction from a residual at rounding level that lay along the axis itself, which
 * put the point r beyond the base disk: the distance witness p2 lay 7.7e49 outside B and the distance
 * came out 5.6e49 instead of 1.33e50. The support point along the axis is the disk's centre. */
static void test_fuzz_axis_support_point(void **state)
{
    (void)state;
    const double v = 7.6846329228755865e+49;
    prox_shape a = prox_shape_from_ell((prox_ell){prox_v3(5.4322263344105125e-312, 0, 2.2652729467712475e-309),
                                                   prox_v3(0, 2.6524947387065904e-315, 2), 1.0});
    prox_shape b = prox_shape_from_rcc((prox_rcc){prox_v3(v, v, v), prox_v3(v, v, v), v});
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    double S = prox_shape_pair_scale(&a, &b), r0 = 1e-12 * S;
    prox_distance_result d = prox_shape_distance(&a, &b);
    assert_int_equal(d.status, PROX_OK);
    assert_near(d.distance, sqrt(3.0) * v, 1e-12 * S); /* the ellipsoid is 1e-50 of it */
    prox_shape ba = prox_shape_from_sph((prox_sph){d.p1, r0}), bb = prox_shape_from_sph((prox_sph){d.p2, r0});
    assert_true(prox_shape_distance(&a, &ba).distance <= r0);
    assert_true(prox_shape_distance(&b, &bb).distance <= r0);
    prox_signed_result g = prox_shape_signed_distance(&a, &b);
    assert_near(g.sd, sqrt(3.0) * v, 1e-12 * S);
    assert_true(g.sd_lower <= g.sd && g.sd <= g.sd_upper);
}

/* fuzz/crashes/pairs-near-cylinder-trc-box-*: a TRC whose radii agree to 4e-10 (nearly an RCC) with
 * its axis along (1, 1, 1), against a box 5e-33 across at the origin, which projects onto the base disk
 * 4.3e20 below it. At the direction exactly along -w the radial part of d, rejected twice, is a residual
 * of three equal components, i.e. along w itself: normalised, it put the rim "support point" on the axis
 * r1 beyond the base, and GJK's pair built from it certified 2.08e20 with p1 2.8e20 outside the TRC. A
 * radial part at rounding is d on the axis (core/axis.h); the early certificate also tests that its
 * pair lies in the solids. The distance is the base plane's: the base's z over sqrt 3. */
static void test_fuzz_near_cylinder_trc_box(void **state)
{
    (void)state;
    const double v = 7.4770802645436046e+20;
    prox_trc t = {prox_v3(0, 1.3548960532517148e-309, 7.4770787633437291e+20), prox_v3(v, v, v), 7.4770802617948255e+20, v};
    prox_box x = {prox_v3(4.8578750597249806e-33, 2.4839856093816511e-91, 1.6588190376278669e-76),
                  {prox_v3(1.3141763152749211e-71, 3.6710701810649192e-62, 1.7475541074180354e-77),
                   prox_v3(-3.8828213118610585e-52, 0, -5.1632648146151874e-58),
                   prox_v3(-6.4568190718651646e-39, -1.0401387832549892e-57, 4.8555856806150451e-33)}};
    prox_shape a = prox_shape_from_trc(t), b = prox_shape_from_box(x);
    double S, want = 7.4770787633437291e+20 / sqrt(3.0);
    for (int k = 0; k < 2; ++k) {
        const prox_shape *p = k ? &b : &a, *q = k ? &a : &b;
        prox_signed_result g = signed_checked(p, q, 1e-12, &S);
        prox_distance_result d = prox_shape_distance(p, q);
        assert_int_equal(d.status, PROX_OK);
        assert_near(d.distance, want, 1e-12 * S);
        assert_near(g.sd, want, 1e-12 * S);
        double r0 = 1e-12 * S;
        prox_shape s1 = prox_shape_from_sph((prox_sph){d.p1, r0}), s2 = prox_shape_from_sph((prox_sph){d.p2, r0});
        assert_true(prox_shape_distance(p, &s1).distance <= r0);
        assert_true(prox_shape_distance(q, &s2).distance <= r0);
    }
}

/* fuzz/crashes/pairs-far-speck-needle-sph-*: a needle (length 4.4e-62, radius 2.1e-76) at the centre
 * of a sphere of radius 3.5e-57, the pair 7e-57 across and 4.7e-33 from the origin. Its depth is the
 * sphere's radius to within the needle's length; the two witnesses, 3.5e-57 apart, cannot be placed
 * near 4.7e-33 (ulp 6e-49), so they satisfy p2 - p1 = sd normal only to the rounding of their own
 * coordinates. Guards: OK, certified, the enclosure, a unit normal, and the witness relation to 1e-12 S
 * plus 8 eps of the largest coordinate. */
static void test_fuzz_far_speck_needle_sph(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_rcc((prox_rcc){prox_v3(5.3542165410115511e-38, 4.6584935735268916e-33, 1.949765603255495e-313),
                                                   prox_v3(4.4194159246042994e-62, 1.1428416299956103e-71, 1.8040490071703454e-153),
                                                   2.0913074576809324e-76});
    prox_shape b = prox_shape_from_sph((prox_sph){prox_v3(5.3542165410115511e-38, 4.6584935735268916e-33, 1.6598377289412965e-76),
                                                  3.5372887656862235e-57});
    for (int k = 0; k < 2; ++k) {
        double S, M = 4.6584935735268916e-33;
        prox_signed_result g = signed_checked(k ? &b : &a, k ? &a : &b, 1e-12 + 8.0 * DBL_EPSILON * M / 7.07e-57, &S);
        assert_true(g.certified);
        assert_true(g.sd_lower <= g.sd && g.sd <= g.sd_upper);
        assert_true(fabs(g.sd + 3.5372887656862235e-57) <= 4.5e-62);
        assert_near(prox_v3_norm(g.normal), 1.0, 1e-12);
        prox_distance_result d = prox_shape_distance(k ? &b : &a, k ? &a : &b);
        assert_int_equal(d.status, PROX_OK);
        assert_true(d.intersect && d.distance == 0.0);
    }
}

/* fuzz/crashes/pairs-subnormal-offset-ell-sph-*: an ELL (a = 2 along z to a subnormal tilt, b = 1)
 * and a sphere of radius 2 whose centre is 1.3e-309 off the ELL's centre. The radial direction of that
 * offset is well defined, but 1 / |offset| overflows: scaling by it gave inf x 0 = NaN witnesses. The
 * depth is b + r = 3, along the offset (the equator). */
static void test_fuzz_subnormal_offset_ell_sph(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_ell((prox_ell){prox_v3(0, 0, 0), prox_v3(1.3091865231939344e-309, 0, 2), 1.0});
    prox_shape b = prox_shape_from_sph((prox_sph){prox_v3(0, 1.3091865234529681e-309, 0), 2.0});
    for (int k = 0; k < 2; ++k) {
        double S;
        prox_signed_result g = signed_checked(k ? &b : &a, k ? &a : &b, 1e-12, &S);
        assert_true(prox_v3_isfinite(g.p1) && prox_v3_isfinite(g.p2) && prox_v3_isfinite(g.normal));
        assert_near(g.sd, -3.0, 1e-12 * S);
        assert_near(fabs(g.normal.y), 1.0, 1e-12);
        prox_vec3 pa = k ? g.p2 : g.p1, pb = k ? g.p1 : g.p2; /* on the ELL's equator, on the sphere */
        assert_near(fabs(pa.y), 1.0, 1e-12 * S);
        assert_near(fabs(pb.y), 2.0, 1e-12 * S);
    }
}

/* fuzz/crashes/pairs-collapsed-plate-ell-*: a box plate 5e-33 thick with corners 1e50 apart (the
 * thickness is below the rounding of its corners, so its side faces collapse to segments) whose plane
 * holds the origin, on the line of one long edge, 1.3e50 beyond the edge's end; an ELL of size 4 and a
 * speck sphere at the origin. The foot of the origin on a collapsed side face passed that face's edge
 * tests: 2.1e34 was certified with a witness 1.3e50 off the box. The distance is the corner's,
 * sqrt 3 x 7.7e49 (the ELL's extent, 1.8, is far below 1e-12 S). */
static void test_fuzz_collapsed_plate_ell(void **state)
{
    (void)state;
    const double v = 7.6846329228755865e+49;
    prox_box x = {prox_v3(v, v, v), {prox_v3(v, v, v), prox_v3(5.1230886152503917e+49, -2.5615443076251953e+49, -2.5615443076251953e+49),
                                     prox_v3(0, 3.4350370219119955e-33, -3.4350370219119955e-33)}};
    prox_shape bx = prox_shape_from_box(x);
    prox_shape others[2] = {prox_shape_from_ell((prox_ell){prox_v3(0, 3.4917537446497729e-251, 0), prox_v3(2, -6.9835074892995458e-251, 0),
                                                           1.7320508075688772}),
                            prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), 1e-3})};
    for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 2; ++k) {
            const prox_shape *p = k ? &others[i] : &bx, *q = k ? &bx : &others[i];
            double S;
            prox_signed_result g = signed_checked(p, q, 1e-12, &S);
            prox_distance_result d = prox_shape_distance(p, q);
            assert_int_equal(d.status, PROX_OK);
            assert_near(d.distance, sqrt(3.0) * v, 1e-12 * S);
            assert_near(g.sd, sqrt(3.0) * v, 1e-12 * S);
            prox_vec3 corner = k ? d.p2 : d.p1; /* the witness on the box is its corner */
            assert_true(prox_v3_dist(corner, prox_v3(v, v, v)) <= 1e-12 * S);
        }
}

/* fuzz/crashes/pairs-tiny-wed-box-*: a wedge and a box 4e-93 across, 3.2e-94 apart. The harness's
 * witness sphere (1e-9 S = 4e-102) was out of range; the answers were right. Guards: OK, the same
 * distance both ways and from the signed distance, witnesses in their solids (by spheres of the
 * least size in range, 1e-100). */
static void test_fuzz_tiny_wed_box(void **state)
{
    (void)state;
    const double v = -1.718333114002038e-93;
    prox_shape a = prox_shape_from_wed((prox_wed){prox_v3(0, 4.973427635074857e-316, 0), prox_v3(-1.2389288385165961e-93, v, v),
                                                  prox_v3(v, v, 7.2911220195563975e-304),
                                                  prox_v3(-2.0647248888583845e-93, 2.0647248888583845e-93, -5.7604543109488089e-94)});
    prox_shape b = prox_shape_from_box((prox_box){prox_v3(v, v, v), {prox_v3(v, 8.4979291084694406e-322, -1.7183331140020016e-93),
                                                                      prox_v3(-2.232216285304993e-103, v, 2.232214156325073e-103),
                                                                      prox_v3(-1.215044997248225e-93, 3.1568290394122729e-103, 1.2150449972482508e-93)}});
    double S;
    prox_signed_result g = signed_checked(&a, &b, 1e-12, &S);
    prox_distance_result ab = prox_shape_distance(&a, &b), ba = prox_shape_distance(&b, &a);
    assert_int_equal(ab.status, PROX_OK);
    assert_int_equal(ba.status, PROX_OK);
    assert_false(ab.intersect);
    assert_near(ab.distance, ba.distance, 1e-12 * S);
    assert_near(g.sd, ab.distance, 1e-12 * S);
    prox_shape s1 = prox_shape_from_sph((prox_sph){ab.p1, PROX_MIN_SIZE}), s2 = prox_shape_from_sph((prox_sph){ab.p2, PROX_MIN_SIZE});
    prox_distance_result d1 = prox_shape_distance(&a, &s1), d2 = prox_shape_distance(&b, &s2);
    assert_int_equal(d1.status, PROX_OK);
    assert_true(d1.distance <= PROX_MIN_SIZE && d2.distance <= PROX_MIN_SIZE);
}

/* fuzz/crashes/pairs-needle-ell-rhp-depth-witness-*: an ELL needle of aspect 1e10 (semi-axes 6.9e-33
 * and 7.3e-43) through a flat hexagonal plate 4e-34 thick. The depth was certified, but its witnesses
 * were 5.3e-9 S off p2 - p1 = sd normal: the needle's support point moves 1e10 times faster than the
 * normal, and one replacement of each witness by its body's boundary point did not close the gap.
 * Guards the overlap's bar, 1e-9 S, in both orders, with the enclosure and its certificate. */
static void test_fuzz_needle_ell_rhp_depth_witness(void **state)
{
    (void)state;
    prox_rhp h = {prox_v3(0, 8.3704497214717782e-306, 0), prox_v3(3.8518598887744717e-34, 1.3993953127464754e-76, 1.5805889573589228e-153),
                  {prox_v3(0, 4.0874883305346056e-33, 2.002543895674692e-52),
                   prox_v3(6.3006101702724259e-95, 2.0437441652673028e-33, 3.5398687319154129e-33),
                   prox_v3(6.3006101702724259e-95, -2.0437441652673028e-33, 3.5398687319154129e-33)}};
    prox_shape a = prox_shape_from_rhp(h);
    prox_shape b = prox_shape_from_ell((prox_ell){prox_v3(3.4732827106519577e-310, 0, 2.4845094613188933e-91),
                                                  prox_v3(4.857875059588523e-33, 4.8578750597249806e-33, 6.5302189100292183e-43),
                                                  7.2643449230955594e-43});
    for (int k = 0; k < 2; ++k) {
        double S;
        prox_signed_result g = signed_checked(k ? &b : &a, k ? &a : &b, 1e-9, &S);
        assert_true(g.sd < 0.0 && g.certified);
        assert_true(g.sd_lower <= g.sd && g.sd <= g.sd_upper);
    }
}

/* fuzz/crashes/pairs-sliver-wed-huge-box-depth-*: a sliver wedge 4e-38 across (1e-78 S) touching a
 * box plate 1e40 wide. The wedge's face planes, cross products of edges 40 orders of magnitude apart,
 * passed a depth witness 1e33 (3.5e-8 S) off the wedge; a polytope's membership now also asks for its
 * corners' box, and the polytope pair's witnesses that fail it go to the support-function engine. */
static void test_fuzz_sliver_wed_huge_box_depth(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_wed((prox_wed){prox_v3(9.2940446411008663e-186, 2.3221085354538588e-321, 1.2909765772127815e-307),
                                                  prox_v3(7.4955226072741057e-67, 3.5379208477231184e-57, 4.4357556401023819e-38),
                                                  prox_v3(1.659827181475229e-76, 9.5011881238158701e-43, 6.0089081935101064e-67),
                                                  prox_v3(-1.312920717511986e-47, 2.2936305077318428e-81, 2.2185683157791105e-76)});
    prox_shape b = prox_shape_from_box((prox_box){prox_v3(1.1071093886279223e-47, 7.866409219332494e-67, 7.1246076521812339e-67),
                                                  {prox_v3(2.088947142791167e-76, 1.658479077322379e-76, 3.2526677619213861e-86),
                                                   prox_v3(-3.1848577427938145e+39, 4.0115064263406278e+39, 1.6525713065970373e+40),
                                                   prox_v3(1.6999958377303583e+40, -2.1412398243773851e+40, 8.4739715414615028e+39)}});
    for (int k = 0; k < 2; ++k) {
        const prox_shape *x = k ? &b : &a, *y = k ? &a : &b;
        double S;
        prox_signed_result g = signed_checked(x, y, 1e-9, &S);
        assert_true(fabs(g.sd) <= 1e-9 * S);
        prox_shape s1 = prox_shape_from_sph((prox_sph){g.p1, 1e-9 * S}), s2 = prox_shape_from_sph((prox_sph){g.p2, 1e-9 * S});
        assert_true(prox_shape_distance(x, &s1).distance == 0.0);
        assert_true(prox_shape_distance(y, &s2).distance == 0.0);
    }
}

/* fuzz/crashes/pairs-ell-subnormal-axis-*: a sphere's centre a subnormal distance (3.7e-315) off an
 * ellipsoid's major axis, inside it. The point-ellipse secular equation's derivative carries
 * 1 / Z and overflowed: Newton stopped at its bracket's end and the nearest boundary point came out
 * at the corner (a, b), 0.77 outside the ellipsoid. Within PROX_ELLIPSE_AXIS_Z b of the axis the
 * point is on it. Here (0.5, 0) is at the vertex's centre of curvature: the vertex is nearest, 1.5 away. */
static void test_fuzz_ell_subnormal_axis(void **state)
{
    (void)state;
    prox_shape a = prox_shape_from_ell((prox_ell){prox_v3(0, 0, 0), prox_v3(2, 0, 0), 1.7320508075688772});
    prox_shape b = prox_shape_from_sph((prox_sph){prox_v3(0.5, 0, 3.7300707263061427e-315), 1.0});
    double S = prox_shape_pair_scale(&a, &b), r0 = 1e-12 * S;
    prox_signed_result g = prox_shape_signed_distance(&a, &b);
    assert_int_equal(g.status, PROX_OK);
    assert_near(g.sd, -2.5, 1e-12 * S);
    prox_shape ba = prox_shape_from_sph((prox_sph){g.p1, r0}), bb = prox_shape_from_sph((prox_sph){g.p2, r0});
    assert_true(prox_shape_distance(&a, &ba).distance <= r0);
    assert_true(prox_shape_distance(&b, &bb).distance <= r0);
}

/* fuzz/crashes/pairs-needle-wed-*, pairs-flat-rhp-rcc-*: a wedge whose triangle sides were 1e-19 of its
 * height and hexagonal plates 1e-23 to 1e-110 as thick as wide gave order-dependent, wrong distances.
 * Such bodies lie outside the supported aspect ratio (PROX_MAX_ASPECT, shapes.h) and are named
 * PROX_EINVAL_RANGE by the validators, every query included; bodies just inside it are accepted. */
static void test_fuzz_degenerate_aspect(void **state)
{
    (void)state;
    const double thin[] = {1e-19, 1e-13, 1e-11};
    const prox_status want[] = {PROX_EINVAL_RANGE, PROX_EINVAL_RANGE, PROX_OK};
    prox_shape box = prox_shape_from_box((prox_box){prox_v3(2, 0, 0), {prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1)}});
    for (int k = 0; k < 3; ++k) {
        prox_wed w = {prox_v3(0, 0, 0), prox_v3(thin[k], 0, 0), prox_v3(0, thin[k], 0), prox_v3(0, 0, 1)};
        assert_int_equal(prox_wed_validate(&w), want[k]);
        prox_shape ws = prox_shape_from_wed(w);
        assert_int_equal(prox_shape_distance(&box, &ws).status, want[k]);
        prox_rhp h;
        prox_status st = prox_rhp_regular(prox_v3(0, 0, 0), prox_v3(0, 0, thin[k]), prox_v3(1, 0, 0), &h);
        assert_int_equal(st, want[k]);
        prox_trc t = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), thin[k], 0.0};
        assert_int_equal(prox_trc_validate(&t), want[k]);
        prox_ell e = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), thin[k]};
        assert_int_equal(prox_ell_validate(&e), want[k]);
        prox_rec r = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), prox_v3(1, 0, 0), prox_v3(0, thin[k], 0)};
        assert_int_equal(prox_rec_validate(&r), want[k]);
    }
    /* a just-inside wedge answers the same both ways */
    prox_wed w = {prox_v3(0, 0, 0), prox_v3(1e-11, 0, 0), prox_v3(0, 1e-11, 0), prox_v3(0, 0, 1)};
    prox_shape ws = prox_shape_from_wed(w);
    prox_distance_result ab = prox_shape_distance(&box, &ws), ba = prox_shape_distance(&ws, &box);
    assert_int_equal(ab.status, PROX_OK);
    assert_near(ab.distance, 2.0 - 1e-11, 1e-12 * 3);
    assert_near(ba.distance, ab.distance, 1e-12 * 3);
}

/* fuzz/crashes/pairs-tiny-arb-huge-box-c20bd280: an ARB tetrahedron 1 across at the origin below a BOX
 * 2e28 across whose top face, tilted by 1.4e-9 rad, lies 1.35e28 beneath it. In the polytope solver's
 * frame (the pair's scale 1) the tetrahedron collapses to one point, and its faces' placed edges had
 * length zero: the face test took the foot of the box's highest corner, 1.65e28 aside, as inside the
 * face z = 0, and BOX-ARB answered, certified, 4.5e19 (1.8e-9 S) short with p2 that far off the ARB.
 * The face test now takes its edge directions from the polytope's own frame. */
static void test_fuzz_tiny_arb_huge_box(void **state)
{
    (void)state;
    prox_arb t = {{prox_v3(0, 0, 0), prox_v3(1, 0, 0), prox_v3(6.2167845438435712e-317, 1, 0),
                   prox_v3(0, 0, 1.000000001891749), prox_v3(0, 0, 0), prox_v3(0, 0, 0), prox_v3(0, 0, 0),
                   prox_v3(0, 0, 0)},
                  {1230, 1240, 1340, 2340, 0, 0}};
    prox_vec3 c = prox_v3(1.7731057309979261e-307, 0, -1.3474687185424657e+28);
    prox_vec3 e2 = prox_v3(1.8446746272732807e+19, -1.8446741874686296e+19, -1.3476555094338099e+28);
    prox_box x = {c,
                  {prox_v3(-1.3476555094338099e+28, -1.3476555094338099e+28, 4.2051705942806448e-270), e2,
                   prox_v3(1.6505341735816776e+28, -1.6505341735816776e+28, 4.5185110396297912e+19)}};
    prox_shape a = prox_shape_from_arb(t), b = prox_shape_from_box(x);
    assert_int_equal(prox_shape_validate(&a), PROX_OK);
    assert_int_equal(prox_shape_validate(&b), PROX_OK);
    double S = prox_shape_pair_scale(&a, &b);
    /* the distance is that of the origin (a corner of the ARB) to the top face's plane, within the
     * ARB's size (1, 4e-29 S); the face's foot lies inside the face */
    double want = fabs(prox_v3_dot(e2, c)) / prox_v3_norm(e2);
    prox_distance_result ab = prox_shape_distance(&a, &b), ba = prox_shape_distance(&b, &a);
    assert_int_equal(ab.status, PROX_OK);
    assert_int_equal(ba.status, PROX_OK);
    assert_true(fabs(ab.distance - want) <= 1e-12 * S);
    assert_true(fabs(ba.distance - want) <= 1e-12 * S);
    assert_true(prox_v3_norm(ab.p1) <= 2.0 && prox_v3_norm(ba.p2) <= 2.0); /* the ARB's witnesses on it */
    prox_signed_result r = prox_shape_signed_distance(&b, &a);
    assert_int_equal(r.status, PROX_OK);
    assert_true(fabs(r.sd - want) <= 1e-12 * S);
    assert_true(prox_v3_norm(r.p2) <= 2.0);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fuzz_subnormal_rpp_sph),
        cmocka_unit_test(test_fuzz_sat_range),
        cmocka_unit_test(test_fuzz_extreme_needle_disk),
        cmocka_unit_test(test_fuzz_deck_blank_card),
        cmocka_unit_test(test_fuzz_rim_rim_overflow),
        cmocka_unit_test(test_fuzz_needle_depth),
        cmocka_unit_test(test_fuzz_long_needle_closed_form),
        cmocka_unit_test(test_fuzz_ell_subnormal_rho),
        cmocka_unit_test(test_fuzz_sph_rcc_subnormal_normal),
        cmocka_unit_test(test_fuzz_degenerate_aspect),
        cmocka_unit_test(test_fuzz_tiny_arb_huge_box),
        cmocka_unit_test(test_fuzz_signed_witness_tiny_disk), cmocka_unit_test(test_fuzz_speck_rhp_disk),
        cmocka_unit_test(test_fuzz_rhp_needle_ell),
        cmocka_unit_test(test_fuzz_box_rcc_unit_normal),
        cmocka_unit_test(test_fuzz_box_box_unit_normal),
        cmocka_unit_test(test_fuzz_wed_plate_witness),
        cmocka_unit_test(test_fuzz_sliver_wed_speck_box),
        cmocka_unit_test(test_fuzz_rhp_lean_needle),
        cmocka_unit_test(test_fuzz_thin_box_arb),
        cmocka_unit_test(test_fuzz_flat_cone_needle),
        cmocka_unit_test(test_fuzz_flat_rec_speck),
        cmocka_unit_test(test_fuzz_flat_ell_box),
        cmocka_unit_test(test_fuzz_tall_rec_wedge),
        cmocka_unit_test(test_fuzz_needle_ell_plate),
        cmocka_unit_test(test_fuzz_disk_ell_needle),
        cmocka_unit_test(test_fuzz_speck_box_arb),
        cmocka_unit_test(test_fuzz_flat_cone_bar),
        cmocka_unit_test(test_fuzz_axis_support_point),
        cmocka_unit_test(test_fuzz_ell_subnormal_axis),
        cmocka_unit_test(test_fuzz_near_cylinder_trc_box),
        cmocka_unit_test(test_fuzz_far_speck_needle_sph),
        cmocka_unit_test(test_fuzz_subnormal_offset_ell_sph),
        cmocka_unit_test(test_fuzz_collapsed_plate_ell),
        cmocka_unit_test(test_fuzz_tiny_wed_box),
        cmocka_unit_test(test_fuzz_needle_ell_rhp_depth_witness),
        cmocka_unit_test(test_fuzz_sliver_wed_huge_box_depth),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
