/* Witness points of the signed distance: for every answer p1 lies on A's boundary, p2 on B's, and
 * p2 - p1 = sd * normal with a unit normal. The goal is 1e-12 x S when disjoint and 1e-9 x S when
 * overlapping (S the pair's scale, tests/data/README.md); the bars below are that goal where it is
 * met and the measured worst where it is not yet (near-touching disjoint pairs of stress_public, whose
 * fast-method points reach 1.7e-11 S after polishing; a face against a side tilted by < 1e-9 rad,
 * 1.9e-9 S), so that a regression fails. The boundary distances are computed here,
 * independently of the library (cyl_sdf of test_refsets.h, a box's own signed distance below); sd is
 * compared with the quad-precision references of tests/data, and the BOX-RCC depth with a brute-force
 * minimum of the support functions over a fine grid of directions, refined locally. */
#include "test_refsets.h"

#include <stdlib.h>

#include "prox/distance.h"
#include "prox/pairs.h"
#include "sat/sat_internal.h"

/* S: the largest of the centre distance, heights and radii. */
static double pair_scale(const prox_rcc *a, const prox_rcc *b)
{
    prox_vec3 ca = prox_v3_mad(a->base, 0.5, a->axis), cb = prox_v3_mad(b->base, 0.5, b->axis);
    double s = fmax(prox_v3_dist(ca, cb), fmax(prox_v3_norm(a->axis), prox_v3_norm(b->axis)));
    return fmax(s, fmax(a->radius, b->radius));
}

/* Worst witness defect of r over S: |p2 - p1 - sd n|, ||n| - 1|, the boundary distances of p1, p2
 * (sdf_a, sdf_b: the signed distances of the points to the boundaries). */
static double defect(const prox_signed_result *r, double sdf_a, double sdf_b, double S)
{
    double e = prox_v3_norm(prox_v3_sub(prox_v3_sub(r->p2, r->p1), prox_v3_scale(r->normal, r->sd))) / S;
    e = fmax(e, fabs(prox_v3_norm(r->normal) - 1.0));
    return fmax(e, fmax(fabs(sdf_a), fabs(sdf_b)) / S);
}

typedef prox_signed_result (*rcc_signed_fn)(const prox_rcc *, const prox_rcc *);

/* Disjoint witnesses of the support method alone are not held to the bar here (its disjoint points
 * come from a searched direction; the public signed distance takes the fast method's). */
static int g_check_disjoint = 1;
static double g_disjoint_bar = 1e-12;

/* Both orders of every pair of a reference set: sd against the reference, the witnesses against the
 * bar of their sign. Returns the worst overlapping witness defect (disjoint ones are asserted). */
static double check_set(const char *name, rcc_signed_fn fn, double overlap_bar)
{
    double *P, *R;
    size_t n = load_set(name, &P, &R);
    double worst = 0.0;
    int bad = 0;
    for (size_t i = 0; i < n; ++i)
        for (int swap = 0; swap < 2; ++swap) {
            prox_rcc a = rcc_of(P + 14 * i + (swap ? 7 : 0)), b = rcc_of(P + 14 * i + (swap ? 0 : 7));
            double S = pair_scale(&a, &b), ref = R[7 * i];
            prox_signed_result r = fn(&a, &b);
            assert_int_equal(r.status, PROX_OK);
            int overl = ref <= 0.0;
            double esd = fabs(r.sd - ref) / S;
            double w = defect(&r, cyl_sdf(&a, r.p1), cyl_sdf(&b, r.p2), S);
            double bar = r.sd > 0.0 ? (g_check_disjoint ? g_disjoint_bar : INFINITY) : overlap_bar;
            if (esd > (overl ? 1e-9 : 1e-12) || w > bar) {
                if (bad++ < 12)
                    print_error("%s pair %zu/%d: sd %.17g ref %.17g (error %.3g S), witness defect %.3g S\n",
                                name, i, swap, r.sd, ref, esd, w);
            }
            if (r.sd <= 0.0) worst = fmax(worst, w);
        }
    free(P);
    free(R);
    if (bad) print_error("%s: %d answers off\n", name, bad);
    assert_int_equal(bad, 0);
    return worst;
}

static void public_signed_agarwal(void **state)
{
    (void)state;
    check_set("agarwal_public", prox_rcc_signed_distance, 1e-9);
}

static void public_signed_stress(void **state)
{
    (void)state;
    g_disjoint_bar = 2e-11;
    check_set("stress_public", prox_rcc_signed_distance, 2e-9);
    g_disjoint_bar = 1e-12;
}

static void support_signed_sets(void **state)
{
    (void)state;
    g_check_disjoint = 0;
    check_set("agarwal_public", prox_sat_rcc_signed, 1e-9);
    check_set("stress_public", prox_sat_rcc_signed, 2e-9);
    g_check_disjoint = 1;
}

/* Signed distance of x to the boundary of box b (negative inside), from its own edges. */
static double box_sdf(const prox_box *b, prox_vec3 x)
{
    prox_vec3 c = b->corner;
    double out2 = 0.0, in = -INFINITY;
    for (int k = 0; k < 3; ++k) {
        double L = prox_v3_norm(b->edge[k]);
        double t = prox_v3_dot(prox_v3_sub(x, c), b->edge[k]) / L;
        double e = fmax(-t, t - L); /* > 0 outside this slab */
        if (e > 0.0) out2 += e * e;
        in = fmax(in, e);
    }
    return out2 > 0.0 ? sqrt(out2) : in;
}

/* h_box(D) + h_rcc(-D): support functions from the definitions (corners; Eberly's Eq. 4). */
static double phi_box_rcc(const prox_box *a, const prox_rcc *b, prox_vec3 d)
{
    double ha = -INFINITY;
    for (int m = 0; m < 8; ++m) {
        prox_vec3 p = a->corner;
        for (int k = 0; k < 3; ++k)
            if (m >> k & 1) p = prox_v3_add(p, a->edge[k]);
        ha = fmax(ha, prox_v3_dot(d, p));
    }
    double h = prox_v3_norm(b->axis);
    prox_vec3 w = prox_v3_scale(b->axis, 1.0 / h), nd = prox_v3_neg(d);
    double dw = prox_v3_dot(nd, w);
    double hb = prox_v3_dot(nd, b->base) + fmax(0.0, dw * h) + b->radius * prox_v3_norm(prox_v3_reject(nd, w));
    return ha + hb;
}

/* The minimum of phi over unit directions by a grid of the sphere then shrinking pattern search
 * from the best few grid points: an independent (slow) upper bound of the depth that reaches it to
 * ~1e-12 when the pattern converges onto the minimiser. */
static double brute_depth(const prox_box *a, const prox_rcc *b)
{
    enum { NG = 36, KEEP = 4 };
    double kv[KEEP];
    prox_vec3 kd[KEEP];
    for (int k = 0; k < KEEP; ++k) kv[k] = INFINITY, kd[k] = prox_v3(0, 0, 1);
    for (int i = 0; i <= NG; ++i)
        for (int j = 0; j < 2 * NG; ++j) {
            double th = PROX_PI * i / NG, ph = PROX_PI * j / NG;
            prox_vec3 d = prox_v3(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
            double f = phi_box_rcc(a, b, d);
            int worst = 0;
            for (int k = 1; k < KEEP; ++k)
                if (kv[k] > kv[worst]) worst = k;
            if (f < kv[worst]) kv[worst] = f, kd[worst] = d;
        }
    double best = INFINITY;
    for (int k = 0; k < KEEP; ++k) {
        prox_vec3 d = kd[k];
        double f = kv[k];
        for (double st = 0.1; st > 1e-12; st *= 0.25)
            for (int moved = 1; moved;) {
                moved = 0;
                prox_vec3 u = prox_v3_any_perp(d), v = prox_v3_cross(d, u);
                for (int q = 0; q < 8; ++q) {
                    double an = q * PROX_PI / 4;
                    prox_vec3 t = prox_v3_add(prox_v3_scale(u, cos(an)), prox_v3_scale(v, sin(an)));
                    prox_vec3 dn = prox_v3_normalize(prox_v3_mad(d, st, t));
                    double fn = phi_box_rcc(a, b, dn);
                    if (fn < f) f = fn, d = dn, moved = 1;
                }
            }
        best = fmin(best, f);
    }
    return -best;
}

/* h_A(D) + h_B(-D) of two cylinders from Eberly's Eq. (4), written out here. */
static double phi_rcc(const prox_rcc *a, const prox_rcc *b, prox_vec3 d)
{
    const prox_rcc *c[2] = {a, b};
    double f = 0.0;
    for (int k = 0; k < 2; ++k) {
        prox_vec3 dd = k ? prox_v3_neg(d) : d;
        double h = prox_v3_norm(c[k]->axis);
        prox_vec3 w = prox_v3_scale(c[k]->axis, 1.0 / h);
        double dw = prox_v3_dot(dd, w);
        f += prox_v3_dot(dd, c[k]->base) + fmax(0.0, dw * h) + c[k]->radius * prox_v3_norm(prox_v3_reject(dd, w));
    }
    return f;
}

/* The smallest phi found by a grid of the sphere, the candidate directions of the features (axes,
 * their cross product, the centre line) and a shrinking pattern search from the best few: an
 * independent upper bound of the depth. */
static double brute_phi_rcc(const prox_rcc *a, const prox_rcc *b)
{
    enum { NG = 32, KEEP = 4 };
    double kv[KEEP];
    prox_vec3 kd[KEEP];
    for (int k = 0; k < KEEP; ++k) kv[k] = INFINITY, kd[k] = prox_v3(0, 0, 1);
    prox_vec3 wa = prox_v3_normalize(a->axis), wb = prox_v3_normalize(b->axis), x = prox_v3_cross(wa, wb);
    prox_vec3 extra[4] = {wa, wb, x, prox_v3_sub(b->base, a->base)};
    for (int i = -8; i <= NG; ++i)
        for (int j = 0; j < (i < 0 ? 2 : 2 * NG); ++j) {
            prox_vec3 d;
            if (i < 0) {
                if (!(prox_v3_norm(extra[(-i - 1) / 2]) > 1e-12)) continue;
                d = prox_v3_normalize(extra[(-i - 1) / 2]);
                if (((-i - 1) & 1) ^ j) d = prox_v3_neg(d);
            } else {
                double th = PROX_PI * i / NG, ph = PROX_PI * j / NG;
                d = prox_v3(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
            }
            double f = phi_rcc(a, b, d);
            int worst = 0;
            for (int k = 1; k < KEEP; ++k)
                if (kv[k] > kv[worst]) worst = k;
            if (f < kv[worst]) kv[worst] = f, kd[worst] = d;
        }
    double best = INFINITY;
    for (int k = 0; k < KEEP; ++k) {
        prox_vec3 d = kd[k];
        double f = kv[k];
        for (double st = 0.1; st > 1e-12; st *= 0.25)
            for (int moved = 1; moved;) {
                moved = 0;
                prox_vec3 u = prox_v3_any_perp(d), v = prox_v3_cross(d, u);
                for (int q = 0; q < 8; ++q) {
                    double an = q * PROX_PI / 4;
                    prox_vec3 t = prox_v3_add(prox_v3_scale(u, cos(an)), prox_v3_scale(v, sin(an)));
                    prox_vec3 dn = prox_v3_normalize(prox_v3_mad(d, st, t));
                    double fn = phi_rcc(a, b, dn);
                    if (fn < f) f = fn, d = dn, moved = 1;
                }
            }
        best = fmin(best, f);
    }
    return best;
}

/* The depth of overlapping pairs posed for the ridges solved in their plane: random poses, axes
 * nearly parallel (the shadow a near-circle), nearly perpendicular (around the thin-ellipse limit
 * where the rims' quartics take over), and a wide flat B centred on A's axis (the shadow's point near
 * its centre, where the minimum of a half of the ridge is a foot on the far side of the ellipse).
 * Any reported depth is phi at some direction, so it is never below the true depth; it must
 * not exceed the brute-force upper bound, and its witnesses must hold. */
static void rcc_depth_ridge_poses(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(77);
    int nover = 0, bad = 0;
    for (int it = 0; it < 240; ++it) {
        int kind = it % 4;
        prox_vec3 wa = test_unit(&g), wb = test_unit(&g);
        if (kind == 1) wb = prox_v3_normalize(prox_v3_mad(wa, pow(10.0, test_range(&g, -7, -1)), prox_v3_any_perp(wa)));
        if (kind == 2) {
            prox_vec3 p = prox_v3_any_perp(wa);
            double tilt = (test_uniform(&g) < 0.5 ? -1 : 1) * pow(10.0, test_range(&g, -5, -1));
            wb = prox_v3_normalize(prox_v3_mad(p, tilt, wa));
        }
        double ha = test_range(&g, 0.2, 5), hb = test_range(&g, 0.2, 5);
        double ra = test_range(&g, 0.1, 3), rb = test_range(&g, 0.1, 3);
        if (kind == 3) hb = test_range(&g, 0.02, 0.5), rb = test_range(&g, 1, 3); /* a wide flat B on A's axis */
        prox_vec3 ca = prox_v3_scale(test_unit(&g), test_range(&g, 0, 2));
        prox_rcc a = {prox_v3_mad(ca, -0.5 * ha, wa), prox_v3_scale(wa, ha), ra};
        prox_vec3 cb = kind == 3 ? prox_v3_mad(ca, test_range(&g, -0.5, 0.5) * ha, wa)
                                 : prox_v3_scale(test_unit(&g), test_range(&g, 0, 2));
        prox_rcc b = {prox_v3_mad(cb, -0.5 * hb, wb), prox_v3_scale(wb, hb), rb};
        prox_signed_result r = prox_rcc_signed_distance(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        if (r.sd > 0.0) continue;
        ++nover;
        double S = pair_scale(&a, &b), bf = brute_phi_rcc(&a, &b);
        double w = defect(&r, cyl_sdf(&a, r.p1), cyl_sdf(&b, r.p2), S);
        if ((-r.sd > bf + 1e-9 * S || w > 1e-9) && bad++ < 12)
            print_error("pose %d (kind %d): depth %.17g brute %.17g, witness defect %.3g S\n", it, kind, -r.sd, bf, w);
    }
    assert_int_equal(bad, 0);
    assert_true(nover > 90);
}

/* Rim-rim cells: two thin wide disks of random tilt whose rims cross, where the depth's minimiser is
 * often a rim point against a rim point, the stratum whose degree-8 solve the certified exclusion of
 * rcc_depth.c (dp_cell_may) skips: a wrongly skipped cell makes the depth too large, which the
 * brute-force minimum of phi over directions (an upper bound of the true depth) catches. */
static void rcc_depth_rim_cells(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(4242);
    int nover = 0, bad = 0;
    for (int it = 0; it < 160; ++it) {
        prox_vec3 wa = test_unit(&g), wb = test_unit(&g);
        double ha = test_range(&g, 0.01, 0.6), hb = test_range(&g, 0.01, 0.6);
        double ra = test_range(&g, 1, 3), rb = test_range(&g, 1, 3);
        prox_vec3 ca = prox_v3(0, 0, 0), cb = prox_v3_scale(test_unit(&g), test_range(&g, 0.5 * ra, ra + rb));
        prox_rcc a = {prox_v3_mad(ca, -0.5 * ha, wa), prox_v3_scale(wa, ha), ra};
        prox_rcc b = {prox_v3_mad(cb, -0.5 * hb, wb), prox_v3_scale(wb, hb), rb};
        prox_signed_result r = prox_rcc_signed_distance(&a, &b);
        assert_int_equal(r.status, PROX_OK);
        if (r.sd > 0.0) continue;
        ++nover;
        double S = pair_scale(&a, &b), bf = brute_phi_rcc(&a, &b);
        double w = defect(&r, cyl_sdf(&a, r.p1), cyl_sdf(&b, r.p2), S);
        if ((-r.sd > bf + 1e-9 * S || w > 1e-9) && bad++ < 12)
            print_error("disks %d: depth %.17g brute %.17g, witness defect %.3g S\n", it, -r.sd, bf, w);
    }
    assert_int_equal(bad, 0);
    assert_true(nover > 40);
}

/* BOX-RCC: random overlapping and disjoint pairs as in the bench's query group (a 4 x 4 x 5 box at
 * the origin, a random cylinder near it): witnesses within the bar, and the depth no worse than the
 * brute-force bound (never deeper than it by more than 1e-9 S: the brute force only bounds it, its
 * pattern search can stall on a kink). */
static void box_rcc_witnesses(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(61);
    prox_box A = {prox_v3(-2, -2, -2.5), {prox_v3(4, 0, 0), prox_v3(0, 4, 0), prox_v3(0, 0, 5)}};
    int nover = 0, bad = 0;
    for (int it = 0; it < 200; ++it) {
        test_rot R = test_random_rot(&g);
        prox_vec3 o = prox_v3_scale(test_unit(&g), 12.0 * test_uniform(&g));
        prox_vec3 w = test_rot_apply(&R, prox_v3(0, 0, 1));
        /* every 4th axis nearly along a box edge (a circular shadow), every 4th nearly in a face plane
         * (a needle shadow: the global search's case below PROX_TOL_RIDGE_THIN) */
        double tilt = pow(10.0, test_range(&g, -8, -1));
        prox_vec3 wh = prox_v3_normalize(prox_v3(w.x, w.y, 0));
        if (it % 4 == 1) w = prox_v3_normalize(prox_v3_mad(prox_v3(0, 0, 1), tilt, wh));
        if (it % 4 == 2) w = prox_v3_normalize(prox_v3(w.x, w.y, tilt));
        prox_rcc b = {o, prox_v3_scale(w, test_range(&g, 0.5, 20)), test_range(&g, 0.2, 8)};
        prox_signed_result r = prox_box_rcc_signed_distance(&A, &b);
        assert_int_equal(r.status, PROX_OK);
        double S = fmax(prox_v3_norm(b.base) + prox_v3_norm(b.axis), fmax(b.radius, 7.0));
        double wd = defect(&r, box_sdf(&A, r.p1), cyl_sdf(&b, r.p2), S);
        double bar = r.sd > 0.0 ? 1e-12 : 1e-9;
        if (wd > bar && bad++ < 12) print_error("box-rcc pair %d: sd %.6g witness defect %.3g x S\n", it, r.sd, wd);
        if (r.sd > 0.0) continue;
        ++nover;
        double bf = brute_depth(&A, &b); /* -depth upper bound: the true sd is >= bf */
        if (r.sd < bf - 1e-9 * S) print_error("box-rcc pair %d: sd %.17g brute %.17g\n", it, r.sd, bf);
        assert_true(r.sd >= bf - 1e-9 * S);
    }
    assert_int_equal(bad, 0);
    assert_true(nover > 30);
}

int main(void)
{
    gsl_set_error_handler_off();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(public_signed_agarwal),
        cmocka_unit_test(public_signed_stress),
        cmocka_unit_test(support_signed_sets),
        cmocka_unit_test(rcc_depth_ridge_poses),
        cmocka_unit_test(rcc_depth_rim_cells),
        cmocka_unit_test(box_rcc_witnesses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
