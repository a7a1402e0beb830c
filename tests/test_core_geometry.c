/* The core's cylinder geometry (src/core/cyl.h, cyl.c, cyl_contain.c) and circle stationary points
 * (src/core/circle.h) against independent long-double brute force (test_brute.h: dense sampling plus
 * golden-section refinement, frames built here, no library solver called by the references):
 *  - the support function is the maximum over the rims and the support point attains it;
 *  - the signed distance, boundary point, normal and closest point of a point;
 *  - the rim circles;
 *  - containment of circles and of cylinders in a cylinder, and their clearances;
 *  - circle-circle stationary points by both root finders, and root failures reported as
 *    PROX_ENUMERIC instead of a made-up answer.
 * Tolerances are 1e-12 of the case's scale S (tests/data/README.md). */
#include "test_brute.h"

#include "core/circle.h"
#include "core/cyl.h"
#include "core/poly.h"

/* A cylinder prepared in long double, with a frame of its own (u from the axis' smallest component). */
typedef struct bf_cyl {
    lv3 b, w, u, v;
    ld h, r;
} bf_cyl;

static lv3 bf_any_perp(lv3 n)
{
    ld a[3] = {fabsl(n.x), fabsl(n.y), fabsl(n.z)};
    lv3 e = {0, 0, 0};
    if (a[0] <= a[1] && a[0] <= a[2]) e.x = 1;
    else if (a[1] <= a[2]) e.y = 1;
    else e.z = 1;
    return lunit(lsub(e, lsc(n, ldot(e, n))));
}

/* The cylinder c in coordinates relative to o. */
static bf_cyl bf_make(const prox_rcc *c, prox_vec3 o)
{
    bf_cyl k;
    k.b = lsub(L(c->base), L(o));
    k.h = lnorm(L(c->axis));
    k.w = lsc(L(c->axis), 1.0L / k.h);
    k.u = bf_any_perp(k.w);
    k.v = lcross(k.w, k.u);
    k.r = c->radius;
    return k;
}

/* Rim point (end 0 base, 1 top) at angle t. */
static lv3 bf_rim(const bf_cyl *k, int end, ld t)
{
    lv3 ctr = ladd(k->b, lsc(k->w, end ? k->h : 0));
    return ladd(ctr, ladd(lsc(k->u, k->r * cosl(t)), lsc(k->v, k->r * sinl(t))));
}

/* Axial coordinate and distance from the axis of x. */
static void bf_coords(const bf_cyl *k, lv3 x, ld *t, ld *rho)
{
    lv3 d = lsub(x, k->b);
    *t = ldot(d, k->w);
    *rho = lnorm(lsub(d, lsc(k->w, *t)));
}

/* ---- support function ---- */

typedef struct bf_dir {
    const bf_cyl *k;
    int end;
    lv3 d;
} bf_dir;

static ld bf_neg_proj(const void *ctx, ld t)
{
    const bf_dir *q = ctx;
    return -ldot(q->d, bf_rim(q->k, q->end, t));
}

/* max over the cylinder of d.x: the cylinder is the hull of its rims, so the maximum over the rims. */
static ld bf_support(const bf_cyl *k, prox_vec3 d)
{
    ld best = -1e300L;
    for (int end = 0; end < 2; ++end) {
        bf_dir q = {k, end, L(d)};
        ld m = -tb_min_periodic(bf_neg_proj, &q, 256);
        if (m > best) best = m;
    }
    return best;
}

/* A random cylinder near o: height and radius in s [0.05, 3], s [0.05, 2]. */
static prox_rcc rand_rcc(test_rng *g, prox_vec3 o, double s)
{
    prox_rcc c = {tb_rp(g, o, s), prox_v3_scale(test_unit(g), s * test_range(g, 0.05, 3)), s * test_range(g, 0.05, 2)};
    return c;
}

static double case_scale(const prox_rcc *c, prox_vec3 o)
{
    return fmax(fmax(prox_v3_dist(c->base, o), prox_v3_norm(c->axis)), c->radius);
}

/* Directions that stress the support point: random, along and against the axis, perpendicular to
 * it, and 1e-9 rad off the axis (the side of the disk whose support point must stay on the rim). */
static prox_vec3 test_dir(test_rng *g, const prox_rcc *c, int j)
{
    prox_vec3 w = prox_v3_normalize(c->axis), p = prox_v3_any_perp(w);
    double m = test_range(g, 0.1, 10);
    switch (j) {
    case 0: return prox_v3_scale(w, m);
    case 1: return prox_v3_scale(w, -m);
    case 2: return prox_v3_scale(p, m);
    case 3: return prox_v3_scale(prox_v3_mad(w, 1e-9, p), m);
    default: return prox_v3_scale(test_unit(g), m);
    }
}

/* h(d) equals the brute-force maximum over the rims, and the support point lies in the cylinder and
 * attains it (the point the signed-distance engines use as a witness). */
static void test_cyl_support(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(101);
    for (int i = 0; i < 150; ++i) {
        double s = tb_random_scale(&g);
        prox_vec3 o = tb_random_origin(&g, i, s);
        prox_rcc c = rand_rcc(&g, o, s);
        prox_cyl k = prox_cyl_make(&c, o);
        bf_cyl bk = bf_make(&c, o);
        double S = case_scale(&c, o);
        for (int j = 0; j < 10; ++j) {
            prox_vec3 d = test_dir(&g, &c, j);
            double tol = 1e-12 * S * prox_v3_norm(d);
            double h = prox_cyl_support(&k, d);
            assert_near(h, (double)bf_support(&bk, d), tol);
            prox_vec3 x = prox_cyl_support_point(&k, d);
            assert_near(prox_v3_dot(d, x), h, tol);
            ld t, rho;
            bf_coords(&bk, L(x), &t, &rho);
            assert_true(t >= -1e-12 * S && t <= bk.h + 1e-12 * S);
            assert_true(rho <= bk.r + 1e-12 * S);
            /* the centred form is the same function without d.c */
            assert_near(prox_cyl_hc(&k, d), h - prox_v3_dot(d, k.c), tol);
        }
    }
}

/* ---- signed distance and closest point ---- */

typedef struct bf_lat {
    const bf_cyl *k;
    lv3 x;
} bf_lat;

/* Distance from x to the side line of the lateral surface at angle t. */
static ld bf_lat_dist(const void *ctx, ld t)
{
    const bf_lat *q = ctx;
    return lseg_dist(q->x, bf_rim(q->k, 0, t), lsc(q->k->w, q->k->h));
}

/* Signed distance of x to the solid cylinder: distance to the boundary (side lines over all angles,
 * both disks), negative inside. */
static ld bf_signed(const bf_cyl *k, lv3 x)
{
    bf_lat q = {k, x};
    ld d = tb_min_periodic(bf_lat_dist, &q, 256);
    for (int end = 0; end < 2; ++end) {
        ld dd = tb_disk_dist(x, ladd(k->b, lsc(k->w, end ? k->h : 0)), k->w, k->r);
        if (dd < d) d = dd;
    }
    ld t, rho;
    bf_coords(k, x, &t, &rho);
    return (t >= 0 && t <= k->h && rho <= k->r) ? -d : d;
}

/* A point near the cylinder: random within 3 s, near the axis, or inside. */
static prox_vec3 test_point(test_rng *g, const prox_rcc *c, int j, double s)
{
    prox_vec3 w = prox_v3_normalize(c->axis), p = prox_v3_any_perp(w);
    prox_vec3 on_axis = prox_v3_mad(c->base, test_range(g, -0.5, 1.5), c->axis);
    switch (j % 4) {
    case 0: return on_axis;
    case 1: return prox_v3_mad(prox_v3_mad(c->base, test_range(g, 0, 1), c->axis), c->radius * test_range(g, 0, 1), p);
    default: return prox_v3_mad(prox_v3_mad(c->base, 0.5, c->axis), 3 * s * test_range(g, 0, 1), test_unit(g));
    }
}

/* prox_cyl_signed against the brute-force boundary distance; its boundary point lies on the boundary
 * at |sd| from x with x = q + sd n; prox_cyl_closest is q outside and x inside; prox_cyl_contains
 * agrees with the sign. */
static void test_cyl_signed_closest(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(202);
    for (int i = 0; i < 120; ++i) {
        double s = tb_random_scale(&g);
        prox_vec3 o = tb_random_origin(&g, i, s);
        prox_rcc c = rand_rcc(&g, o, s);
        prox_cyl k = prox_cyl_make(&c, o);
        bf_cyl bk = bf_make(&c, o);
        for (int j = 0; j < 12; ++j) {
            prox_vec3 xa = test_point(&g, &c, j, s), x = prox_v3_sub(xa, o);
            double S = fmax(case_scale(&c, o), prox_v3_dist(xa, o)), tol = 1e-12 * S;
            prox_vec3 q, n;
            double sd = prox_cyl_signed(&k, x, &q, &n);
            ld ref = bf_signed(&bk, L(x));
            assert_near(sd, (double)ref, tol);
            assert_near(prox_v3_dist(x, q), fabs(sd), tol);
            assert_near(prox_v3_norm(n), 1.0, 1e-12);
            assert_true(prox_v3_dist(x, prox_v3_mad(q, sd, n)) <= tol);
            assert_true(fabsl(bf_signed(&bk, L(q))) <= tol); /* q on the boundary */
            prox_vec3 cl = prox_cyl_closest(&k, x);
            if (sd > 0.0) assert_true(prox_v3_dist(cl, q) <= tol);
            else assert_true(prox_v3_dist(cl, x) == 0.0);
            if (fabs(sd) > tol) assert_int_equal(prox_cyl_contains(&k, x, 0.0), sd < 0.0);
        }
    }
}

/* Rims: centred on the end disks, orthonormal frame in the end plane, points at radius r. */
static void test_cyl_rims(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(303);
    for (int i = 0; i < 100; ++i) {
        double s = tb_random_scale(&g);
        prox_vec3 o = tb_random_origin(&g, i, s);
        prox_rcc c = rand_rcc(&g, o, s);
        prox_cyl k = prox_cyl_make(&c, o);
        bf_cyl bk = bf_make(&c, o);
        double tol = 1e-12 * case_scale(&c, o);
        for (int end = 0; end < 2; ++end) {
            prox_fcircle f = prox_cyl_rim(&k, end);
            assert_near(prox_v3_norm(f.u), 1.0, 1e-15);
            assert_near(prox_v3_norm(f.v), 1.0, 1e-15);
            assert_near(prox_v3_dot(f.u, f.v), 0.0, 1e-15);
            assert_near(prox_v3_dot(f.u, k.w), 0.0, 1e-15);
            assert_true(prox_v3_dist(f.n, k.w) <= 1e-15);
            assert_near(f.r, c.radius, 0.0);
            for (int j = 0; j < 8; ++j) {
                ld t, rho;
                bf_coords(&bk, L(prox_fcircle_point(&f, test_range(&g, 0, 7))), &t, &rho);
                assert_near((double)t, end ? (double)bk.h : 0.0, tol);
                assert_near((double)rho, c.radius, tol);
            }
        }
    }
}

/* ---- containment ---- */

typedef struct bf_circ {
    lv3 c, u, v, w, b;
    ld r, sign;
} bf_circ;

/* sign x the axial coordinate (along w from b) of the circle point at angle t. */
static ld bf_circ_axial(const void *ctx, ld t)
{
    const bf_circ *q = ctx;
    lv3 x = ladd(q->c, ladd(lsc(q->u, q->r * cosl(t)), lsc(q->v, q->r * sinl(t))));
    return q->sign * ldot(lsub(x, q->b), q->w);
}

/* Clearance of the circle (centre cr relative to the cylinder's origin, unit n, r) in the cylinder:
 * min(least height, h - greatest height, radius - farthest distance from the axis), each extreme by
 * sampling and golden section. */
static ld bf_circle_clearance(const bf_cyl *k, prox_vec3 cr, prox_vec3 n, double r)
{
    lv3 u = bf_any_perp(L(n));
    bf_circ q = {L(cr), u, lcross(lunit(L(n)), u), k->w, k->b, r, 1};
    ld tmin = tb_min_periodic(bf_circ_axial, &q, 256);
    q.sign = -1;
    ld tmax = -tb_min_periodic(bf_circ_axial, &q, 256);
    prox_vec3 bb = prox_v3((double)k->b.x, (double)k->b.y, (double)k->b.z);
    prox_vec3 ww = prox_v3((double)k->w.x, (double)k->w.y, (double)k->w.z);
    ld rho = tb_circle_line_max_dist(cr, n, r, bb, ww);
    ld m = tmin;
    if (k->h - tmax < m) m = k->h - tmax;
    if (k->r - rho < m) m = k->r - rho;
    return m;
}

/* A circle near the cylinder, about half of them inside: centre at a random height and radial
 * offset, random normal, radius up to the cylinder's. */
static prox_circle test_circle_near(test_rng *g, const prox_rcc *c)
{
    prox_vec3 w = prox_v3_normalize(c->axis), p = prox_v3_any_perp(w), p2 = prox_v3_cross(w, p);
    double a = test_range(g, 0, 2 * PROX_PI), off = c->radius * test_range(g, 0, 0.6);
    prox_vec3 ctr = prox_v3_mad(c->base, test_range(g, 0.05, 0.95), c->axis);
    ctr = prox_v3_mad(prox_v3_mad(ctr, off * cos(a), p), off * sin(a), p2);
    prox_circle cc = {ctr, test_unit(g), c->radius * test_range(g, 0.05, 1.0)};
    return cc;
}

/* prox_cyl_circle_clearance equals the brute-force clearance; prox_cyl_contains_circle is its sign
 * (away from the boundary) and honours tol. */
static void test_cyl_contains_circle(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(404);
    int in = 0, out = 0;
    for (int i = 0; i < 300; ++i) {
        double s = tb_random_scale(&g);
        prox_vec3 o = tb_random_origin(&g, i, s);
        prox_rcc c = rand_rcc(&g, o, s);
        prox_cyl k = prox_cyl_make(&c, o);
        bf_cyl bk = bf_make(&c, o);
        prox_circle cc = test_circle_near(&g, &c);
        prox_vec3 cr = prox_v3_sub(cc.center, o);
        double S = fmax(case_scale(&c, o), prox_v3_dist(cc.center, o)), tol = 1e-12 * S;
        ld ref = bf_circle_clearance(&bk, cr, cc.normal, cc.radius);
        assert_near(prox_cyl_circle_clearance(&k, cr, cc.normal, cc.radius), (double)ref, tol);
        if (fabsl(ref) <= 1e-10 * S) continue;
        int inside = prox_cyl_contains_circle(&k, cr, cc.normal, cc.radius, 0.0);
        assert_int_equal(inside, ref > 0);
        in += inside, out += !inside;
        if (!inside) /* enlarged by more than it sticks out, it fits */
            assert_true(prox_cyl_contains_circle(&k, cr, cc.normal, cc.radius, (double)-ref + 1e-10 * S));
    }
    assert_true(in >= 30 && out >= 30); /* both outcomes exercised */
}

/* Circles decided by the exact farthest point, not by the quick tests: centre offset + radius beyond
 * the cylinder's radius, yet inside (the projection along the axis is a thin ellipse); and the same
 * circle turned so that the ellipse reaches out. */
static void test_cyl_contains_circle_ellipse(void **state)
{
    (void)state;
    prox_rcc c = {prox_v3(0, 0, 0), prox_v3(0, 0, 4), 1.0};
    prox_cyl k = prox_cyl_make(&c, prox_v3(0, 0, 0));
    prox_vec3 ctr = prox_v3(0.15, 0, 2);
    double r = 0.9;
    assert_true(0.15 + r > 1.0);
    for (int j = 0; j <= 20; ++j) { /* normal tilted from x (thin ellipse) towards z (full circle) */
        double a = 0.5 * PROX_PI * j / 20;
        prox_vec3 n = prox_v3(cos(a), 0, sin(a));
        /* farthest distance from the z axis of the ellipse x = 0.15 + 0.9 sin(a) cos t, y = 0.9 sin t */
        double far = 0.0;
        for (int m = 0; m < 20000; ++m) {
            double t = 2 * PROX_PI * m / 20000;
            far = fmax(far, hypot(0.15 + r * sin(a) * cos(t), r * sin(t)));
        }
        if (fabs(far - 1.0) < 1e-6) continue;
        assert_int_equal(prox_cyl_contains_circle(&k, ctr, n, r, 0.0), far < 1.0);
        assert_near(prox_cyl_circle_clearance(&k, ctr, n, r), fmin(2.0 - r * cos(a), 1.0 - far), 1e-8);
    }
}

/* prox_cyl_in_cyl and its clearance against the brute-force clearances of the rims; a nested
 * cylinder's random points all lie in the outer one. */
static void test_cyl_in_cyl(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(505);
    int in = 0, out = 0;
    for (int i = 0; i < 200; ++i) {
        double s = tb_random_scale(&g);
        prox_vec3 o = tb_random_origin(&g, i, s);
        prox_rcc B = rand_rcc(&g, o, s);
        prox_circle cc = test_circle_near(&g, &B);
        double h = prox_v3_norm(B.axis) * test_range(&g, 0.01, 0.5);
        prox_rcc A = {cc.center, prox_v3_scale(cc.normal, h), cc.radius};
        prox_cyl ka = prox_cyl_make(&A, o), kb = prox_cyl_make(&B, o);
        bf_cyl bb = bf_make(&B, o), ba = bf_make(&A, o);
        double S = fmax(case_scale(&B, o), prox_v3_dist(A.base, o)), tol = 1e-12 * S;
        /* the rims' centres relative to o (the sum in absolute coordinates far from the origin would
         * round by more than the tolerance) */
        prox_vec3 c0 = prox_v3_sub(A.base, o), c1 = prox_v3_add(c0, A.axis);
        ld ref = bf_circle_clearance(&bb, c0, cc.normal, A.radius);
        ld r1 = bf_circle_clearance(&bb, c1, cc.normal, A.radius);
        if (r1 < ref) ref = r1;
        assert_near(prox_cyl_in_cyl_clearance(&ka, &kb), (double)ref, tol);
        if (fabsl(ref) <= 1e-10 * S) continue;
        int inside = prox_cyl_in_cyl(&ka, &kb, 0.0);
        assert_int_equal(inside, ref > 0);
        in += inside, out += !inside;
        if (!inside) continue;
        for (int m = 0; m < 200; ++m) { /* random points of A, in long double */
            lv3 x = ladd(ba.b, lsc(ba.w, ba.h * test_uniform(&g)));
            ld rr = ba.r * sqrtl(test_uniform(&g)), t = 2 * PROX_PI * test_uniform(&g);
            x = ladd(x, ladd(lsc(ba.u, rr * cosl(t)), lsc(ba.v, rr * sinl(t))));
            ld tt, rho;
            bf_coords(&bb, x, &tt, &rho);
            assert_true(tt >= -tol && tt <= bb.h + tol && rho <= bb.r + tol);
        }
    }
    assert_true(in >= 20 && out >= 20);
}

/* ---- circle-circle stationary points ---- */

typedef struct bf_cc {
    lv3 ca, ua, va, cb, nb;
    ld ra, rb;
} bf_cc;

/* Distance from the point of a at angle t to circle b (radial projection onto b). */
static ld bf_cc_dist(const void *ctx, ld t)
{
    const bf_cc *q = ctx;
    lv3 x = ladd(q->ca, ladd(lsc(q->ua, q->ra * cosl(t)), lsc(q->va, q->ra * sinl(t))));
    lv3 d = lsub(x, q->cb);
    ld hn = ldot(d, q->nb), rho = lnorm(lsub(d, lsc(q->nb, hn)));
    return sqrtl(hn * hn + (rho - q->rb) * (rho - q->rb));
}

/* Both root finders give stationary angles whose best point attains the brute-force minimum
 * distance between the circles. */
static void test_circle_circle_methods(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(606);
    prox_root_method ms[2] = {PROX_ROOTS_CHAIN, PROX_ROOTS_GSL};
    for (int i = 0; i < 150; ++i) {
        double s = tb_random_scale(&g);
        prox_vec3 o = tb_random_origin(&g, i, s);
        prox_circle a = tb_random_circle(&g, o, s), b = tb_random_circle(&g, o, s);
        prox_fcircle fa = prox_fcircle_make(prox_v3_sub(a.center, o), a.normal, a.radius);
        prox_fcircle fb = prox_fcircle_make(prox_v3_sub(b.center, o), b.normal, b.radius);
        lv3 ua = bf_any_perp(L(a.normal));
        bf_cc q = {lsub(L(a.center), L(o)), ua, lcross(L(a.normal), ua), lsub(L(b.center), L(o)), L(b.normal),
                   a.radius, b.radius};
        ld ref = tb_min_periodic(bf_cc_dist, &q, 1024);
        double S = fmax(fmax(a.radius, b.radius), prox_v3_dist(a.center, b.center));
        for (int m = 0; m < 2; ++m) {
            double th[8];
            int n = -1;
            assert_int_equal(prox_circle_circle_stationary(&fa, &fb, ms[m], th, &n), 0);
            assert_true(n >= 1 && n <= 8);
            double best = INFINITY;
            for (int j = 0; j < n; ++j) {
                prox_vec3 x = prox_fcircle_point(&fa, th[j]);
                best = fmin(best, prox_v3_dist(x, prox_fcircle_closest(&fb, x, NULL)));
            }
            assert_near(best, (double)ref, 1e-12 * S);
        }
    }
}

/* A root solve that cannot succeed (the problem normalised by a 1e-200 radius overflows) is reported
 * as PROX_ENUMERIC by the stationary-point solvers and by every public primitive built on them,
 * never as a constant-distance case or a distance made up from a partial list. */
static void test_root_failure_reported(void **state)
{
    (void)state;
    prox_fcircle tiny = prox_fcircle_make(prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1e-200);
    prox_fcircle far = prox_fcircle_make(prox_v3(1e200, 0, 0), prox_v3(1, 0, 0), 1.0);
    double th[8];
    int n = -1;
    assert_int_equal(prox_circle_circle_stationary(&tiny, &far, PROX_ROOTS_CHAIN, th, &n), -(int)PROX_ENUMERIC);
    assert_int_equal(prox_circle_circle_stationary(&tiny, &far, PROX_ROOTS_GSL, th, &n), -(int)PROX_ENUMERIC);
    prox_circle ca = {tiny.c, tiny.n, tiny.r}, cb = {far.c, far.n, far.r};
    assert_int_equal(prox_circle_circle(&ca, &cb).status, PROX_ENUMERIC);
    prox_disk da = {tiny.c, tiny.n, tiny.r};
    assert_int_equal(prox_disk_circle(&da, &cb).status, PROX_ENUMERIC);

    prox_fcircle t3 = prox_fcircle_make(prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1e-300);
    n = -1;
    assert_int_equal(prox_circle_line_stationary(&t3, prox_v3(1e10, 0, 0), prox_v3(0, 1, 0), th, &n),
                     -(int)PROX_ENUMERIC);
    assert_int_equal(n, 0);
    prox_circle c3 = {t3.c, t3.n, t3.r};
    prox_segment sg = {prox_v3(1e10, -1, 0), prox_v3(1e10, 1, 0)};
    assert_int_equal(prox_circle_segment(&c3, &sg).status, PROX_ENUMERIC);
    assert_int_equal(prox_disk_segment(&c3, &sg).status, PROX_ENUMERIC);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cyl_support),           cmocka_unit_test(test_cyl_signed_closest),
        cmocka_unit_test(test_cyl_rims),              cmocka_unit_test(test_cyl_contains_circle),
        cmocka_unit_test(test_cyl_contains_circle_ellipse), cmocka_unit_test(test_cyl_in_cyl),
        cmocka_unit_test(test_circle_circle_methods), cmocka_unit_test(test_root_failure_reported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
