/* The GJK fast path of the polytope pairs (distance/poly_pairs.c, poly_gjk.c) against the exhaustive
 * method of the same file (feature enumeration and every separating axis, forced by
 * prox_poly_distance_exhaustive / prox_poly_signed_exhaustive), on random BOX, RHP, WED and ARB pairs:
 *  - distance: equal within 1e-12 S; the same verdict outside the touching band; witnesses in their
 *    solids with |p2 - p1| the distance; the common point of an overlap in both solids; certified
 *    wherever the exhaustive answer is, with a certificate gap that is a true lower bound;
 *  - signed distance: equal within 1e-9 S (depth) and 1e-12 S (distance); the depth's witnesses on
 *    the boundaries with p2 - p1 = sd normal; the dual bound sd_lower kept;
 * over generic pairs (sizes 0.5-10, centres 0-14 apart), contacts built by moving B along a face
 * normal of A or a random direction until the supports meet (faces in contact, face twisted on
 * face, edge or corner on face, corner on corner) at offsets 0, +-1e-13 S and 1e-9 S, thin and
 * near-degenerate solids, and pairs 1e7 from the origin. */
#include "core/polytope.h"
#include "distance/poly_internal.h"
#include "test_util.h"

enum { K_BOX, K_RHP, K_WED, K_ARB, NKINDS };

/* Sizes of a solid: edge lengths or apothem/height, a WED's opening angle, an ARB's taper. */
typedef struct dims {
    double a, b, h, t;
} dims;

static dims random_dims(test_rng *g, int thin)
{
    dims d = {test_range(g, 0.5, 10), test_range(g, 0.5, 10), test_range(g, 0.5, 10), test_uniform(g)};
    if (thin == 1) d.h *= 1e-5;
    if (thin == 2) d.t = 1.0 - 1e-7 * d.t; /* WED angle near pi, ARB nearly a box */
    return d;
}

/* A solid of kind k centred near c under the rotation R. */
static prox_shape solid(int k, dims d, const test_rot *R, prox_vec3 c)
{
    prox_vec3 ex = test_rot_apply(R, prox_v3(1, 0, 0)), ey = test_rot_apply(R, prox_v3(0, 1, 0));
    prox_vec3 ez = test_rot_apply(R, prox_v3(0, 0, 1));
    switch (k) {
    case K_BOX: {
        prox_box b = {c, {prox_v3_scale(ex, d.a), prox_v3_scale(ey, d.b), prox_v3_scale(ez, d.h)}};
        for (int i = 0; i < 3; ++i) b.corner = prox_v3_mad(b.corner, -0.5, b.edge[i]);
        return prox_shape_from_box(b);
    }
    case K_RHP: {
        prox_rhp x;
        assert_int_equal(prox_rhp_regular(prox_v3_mad(c, -0.5 * d.h, ez), prox_v3_scale(ez, d.h),
                                          prox_v3_scale(ex, 0.5 * d.a), &x),
                         PROX_OK);
        return prox_shape_from_rhp(x);
    }
    case K_WED: {
        double th = d.t > 1.0 - 1e-6 ? 3.14159 : 0.3 + 2.5 * d.t;
        prox_vec3 v1 = prox_v3_scale(ex, d.a), v2 = prox_v3_add(prox_v3_scale(ex, d.b * cos(th)), prox_v3_scale(ey, d.b * sin(th)));
        prox_vec3 v3 = prox_v3_scale(ez, d.h);
        prox_vec3 v = prox_v3_sub(c, prox_v3_scale(prox_v3_add(prox_v3_add(v1, v2), v3), 1.0 / 3.0));
        return prox_shape_from_wed((prox_wed){v, v1, v2, v3});
    }
    default: { /* a truncated rectangular pyramid */
        static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        static const int faces[6] = {1234, 5678, 1265, 2376, 3487, 4158};
        double s = 0.3 + 0.7 * d.t;
        prox_arb x;
        for (int i = 0; i < 4; ++i) {
            prox_vec3 lo = prox_v3_add(prox_v3_scale(ex, 0.5 * sx[i] * d.a), prox_v3_scale(ey, 0.5 * sy[i] * d.b));
            prox_vec3 hi = prox_v3_add(prox_v3_scale(ex, 0.5 * s * sx[i] * d.a), prox_v3_scale(ey, 0.5 * s * sy[i] * d.b));
            x.corner[i] = prox_v3_add(c, prox_v3_mad(lo, -0.5 * d.h, ez));
            x.corner[4 + i] = prox_v3_add(c, prox_v3_mad(hi, 0.5 * d.h, ez));
        }
        for (int i = 0; i < 6; ++i) x.face[i] = faces[i];
        return prox_shape_from_arb(x);
    }
    }
}

typedef struct tally {
    int pairs, overlap, disjoint, band;
} tally;

/* p (absolute) within tol of the polytope with reference point c. */
static int in_poly(const prox_polytope *p, prox_vec3 c, prox_vec3 x, double tol)
{
    return prox_polytope_contains(p, prox_v3_sub(x, c), tol);
}

/* The fast and the exhaustive answers of one pair agree (see the file's comment). */
static void compare_pair(const prox_shape *sa, const prox_shape *sb, tally *t)
{
    if (prox_shape_validate(sa) != PROX_OK || prox_shape_validate(sb) != PROX_OK) return;
    prox_polytope a, b;
    prox_vec3 ca = prox_polytope_make(sa, &a), cb = prox_polytope_make(sb, &b);
    double S = fmax(prox_v3_dist(ca, cb), fmax(a.size, b.size)), tol = 1e-12 * S;
    /* the coordinates' own rounding: far from the origin an ARB's corners are planar only to it, and
     * the vertex hull and the face planes differ by as much */
    double wtol = tol + 1e-15 * (prox_v3_maxabs(ca) + prox_v3_maxabs(cb));
    prox_distance_result f = prox_poly_distance(&a, ca, &b, cb), e = prox_poly_distance_exhaustive(&a, ca, &b, cb);
    t->pairs++;
    assert_near(f.distance, e.distance, wtol);
    if (f.intersect != e.intersect) { /* allowed only in the touching band */
        assert_true(fmax(f.distance, e.distance) <= 1e-12 * S);
        t->band++;
    }
    if (e.certified) assert_true(f.certified);
    if (f.intersect) {
        t->overlap++;
        assert_true(f.p1.x == f.p2.x && f.p1.y == f.p2.y && f.p1.z == f.p2.z);
        assert_true(in_poly(&a, ca, f.p1, wtol) && in_poly(&b, cb, f.p1, wtol));
    } else {
        t->disjoint++;
        assert_near(prox_v3_dist(f.p1, f.p2), f.distance, wtol);
        assert_true(in_poly(&a, ca, f.p1, wtol));
        assert_true(in_poly(&b, cb, f.p2, wtol));
        if (f.certified) { /* a lower bound within the certificate's slack */
            assert_true(f.certificate_gap <= e.distance + wtol);
            assert_true(f.distance - f.certificate_gap <= 1e-13 * S);
        }
    }
    prox_signed_result fs = prox_poly_signed(&a, ca, &b, cb), es = prox_poly_signed_exhaustive(&a, ca, &b, cb);
    assert_near(fs.sd, es.sd, fs.sd <= 0.0 || es.sd <= 0.0 ? 1e-9 * S : wtol);
    assert_near(prox_v3_norm(fs.normal), 1.0, 1e-12);
    if (fs.sd > 0.0) {
        assert_near(prox_v3_dist(fs.p1, fs.p2), fs.sd, wtol);
        assert_true(fs.sd_lower <= fs.sd + tol);
        if (es.sd_lower > 0.0) assert_true(fs.sd_lower > 0.0 && fs.sd - fs.sd_lower <= 1e-13 * S);
    } else { /* the depth's witnesses: p2 - p1 = sd n, on the two boundaries */
        prox_vec3 r = prox_v3_sub(prox_v3_sub(fs.p2, fs.p1), prox_v3_scale(fs.normal, fs.sd));
        assert_true(prox_v3_norm(r) <= 1e-9 * S);
        double bd;
        prox_vec3 q;
        bd = prox_polytope_boundary(&a, prox_v3_sub(fs.p1, ca), &q);
        assert_true(fabs(bd) <= 1e-9 * S);
        bd = prox_polytope_boundary(&b, prox_v3_sub(fs.p2, cb), &q);
        assert_true(fabs(bd) <= 1e-9 * S);
    }
}

/* Generic pairs of every kind pair, thin and near-degenerate ones, and far from the origin. */
static void test_random_pairs(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(0x6a4b);
    tally t = {0};
    for (int ka = 0; ka < NKINDS; ++ka)
        for (int kb = 0; kb < NKINDS; ++kb)
            for (int i = 0; i < 400; ++i) {
                int thin = i % 8 == 7 ? 1 + (i / 8) % 2 : 0;
                test_rot Ra = test_random_rot(&g), Rb = test_random_rot(&g);
                prox_vec3 far = i % 5 == 4 ? prox_v3_scale(test_unit(&g), 1e7) : prox_v3(0, 0, 0);
                prox_vec3 cb = prox_v3_add(far, prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 14.0)));
                prox_shape sa = solid(ka, random_dims(&g, thin), &Ra, far);
                prox_shape sb = solid(kb, random_dims(&g, i % 8 == 3 ? 1 : 0), &Rb, cb);
                compare_pair(&sa, &sb, &t);
            }
    assert_true(t.pairs >= 6000);
    assert_true(t.overlap > t.pairs / 5 && t.disjoint > t.pairs / 5); /* both branches exercised */
}

/* Support value of the shape along n (absolute). */
static double support(const prox_shape *s, prox_vec3 n)
{
    prox_polytope p;
    prox_vec3 c = prox_polytope_make(s, &p);
    return prox_polytope_hc(&p, n) + prox_v3_dot(c, n);
}

/* Contacts: B moved along n until h_A(n) + h_B(-n) = -offset (the gap along n is offset). Modes:
 * 0 n a face normal of A and B with A's rotation (parallel faces in contact), 1 the same with B
 * twisted about n, 2 n a face normal of A and B at random (edge or corner on face), 3 n random. */
static void contact_pair(test_rng *g, int ka, int kb, int mode, double offset_rel, tally *t)
{
    test_rot Ra = test_random_rot(g), Rb = mode <= 1 ? Ra : test_random_rot(g);
    prox_shape sa = solid(ka, random_dims(g, 0), &Ra, prox_v3(0, 0, 0));
    prox_shape sb0 = solid(kb, random_dims(g, 0), &Rb, prox_v3(0, 0, 0));
    prox_polytope pa;
    prox_polytope_make(&sa, &pa);
    prox_vec3 n = mode == 3 ? test_unit(g) : pa.n[(int)(test_uniform(g) * pa.nf)];
    if (mode == 1) { /* B turned about n: Rodrigues' rotation of its defining vectors */
        double th = test_range(g, 0, 6.283), c = cos(th), s = sin(th);
        test_rot T;
        for (int i = 0; i < 3; ++i) {
            prox_vec3 col = test_rot_apply(&Ra, prox_v3(i == 0, i == 1, i == 2));
            prox_vec3 r = prox_v3_add(prox_v3_add(prox_v3_scale(col, c), prox_v3_scale(prox_v3_cross(n, col), s)),
                                      prox_v3_scale(n, prox_v3_dot(n, col) * (1 - c)));
            T.m[0][i] = r.x, T.m[1][i] = r.y, T.m[2][i] = r.z;
        }
        sb0 = solid(kb, random_dims(g, 0), &T, prox_v3(0, 0, 0));
    }
    double S0 = 30.0; /* the offset's scale: S is of the order of the sizes here */
    double move = support(&sa, n) + support(&sb0, prox_v3_neg(n)) + offset_rel * S0;
    prox_shape sb = test_translate(&sb0, prox_v3_scale(n, move));
    compare_pair(&sa, &sb, t);
}

static void test_contacts(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(0x70c4);
    tally t = {0};
    static const double offs[5] = {0.0, 1e-13, -1e-13, 1e-9, -1e-9};
    for (int ka = 0; ka < NKINDS; ++ka)
        for (int kb = 0; kb < NKINDS; ++kb)
            for (int mode = 0; mode < 4; ++mode)
                for (int o = 0; o < 5; ++o)
                    for (int i = 0; i < 6; ++i) contact_pair(&g, ka, kb, mode, offs[o], &t);
    assert_true(t.pairs >= 1900);
}

/* Identical solids and a solid inside another: the common point and the depth. */
static void test_nested(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(0x5e57);
    tally t = {0};
    for (int ka = 0; ka < NKINDS; ++ka)
        for (int kb = 0; kb < NKINDS; ++kb)
            for (int i = 0; i < 10; ++i) {
                test_rot Ra = test_random_rot(&g), Rb = i % 2 ? test_random_rot(&g) : Ra;
                dims da = random_dims(&g, 0), db = da;
                if (i % 3) db.a *= 0.1, db.b *= 0.1, db.h *= 0.1;
                prox_shape sa = solid(ka, da, &Ra, prox_v3(0, 0, 0));
                prox_shape sb = solid(kb, db, &Rb, prox_v3_scale(test_unit(&g), 0.01));
                compare_pair(&sa, &sb, &t);
            }
    assert_int_equal(t.overlap, t.pairs);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_pairs),
        cmocka_unit_test(test_contacts),
        cmocka_unit_test(test_nested),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
