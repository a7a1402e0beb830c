/* Containment A inside B for the 9 ordered pairs of {BOX/RPP, RCC, SPH}, any position and orientation.
 * Generalises the TRX report's Set 1 (LA-UR-13-26757, Sec. 2, Eqs. (1)-(18): local "optimal"
 * orientation only, with the errata listed in docs/errata-trx.md).
 * B is convex, so A lies in B iff A's extreme points do: box vertices, cylinder rim circles, the sphere.
 * The clearance returned is min over A of the distance to B's boundary (signed: < 0 when A sticks out):
 * inside B that distance is concave, so its minimum over A is attained at an extreme point of A.
 * Point clearances: box min_k (h_k - |l_k|); cylinder min(t, h - t, r - rho); sphere R - |x - c|.
 * A rim in a cylinder: axial extent t_c +- r |w_A x w_B|, and the largest distance of the rim from the
 * axis, attained at a stationary angle of the circle-to-line distance (quartic of Agarwal Sec. 3.3). */
#include "distance/box_internal.h"
#include "distance/stationary.h"
#include "prox/support.h"

typedef struct cyl_geom {
    prox_vec3 base, w, u, v;
    double h, r;
} cyl_geom;

static cyl_geom cyl_geom_make(const prox_rcc *c)
{
    cyl_geom g;
    g.base = c->base;
    g.h = prox_v3_norm(c->axis);
    g.w = prox_v3_divs(c->axis, g.h);
    g.u = prox_v3_any_perp(g.w);
    g.v = prox_v3_cross(g.w, g.u);
    g.r = c->radius;
    return g;
}

static double box_point_clear(const prox_bframe *B, prox_vec3 x)
{
    double l[3], m = INFINITY;
    prox_bframe_local(B, x, l);
    for (int k = 0; k < 3; ++k) m = fmin(m, B->h[k] - fabs(l[k]));
    return m;
}

static double cyl_point_clear(const cyl_geom *c, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, c->base);
    double t = prox_v3_dot(d, c->w);
    double rho = prox_v3_norm(prox_v3_mad(d, -t, c->w));
    return fmin(fmin(t, c->h - t), c->r - rho);
}

/* Finishes a result: inside when the clearance is >= -tol (tol relative to the pair's scale). */
static prox_contain_result finish(prox_status st, double clear, const prox_shape *a, const prox_shape *b)
{
    prox_contain_result r = {0};
    r.status = st;
    if (st != PROX_OK) return r;
    double s = prox_v3_dist(prox_shape_center(a), prox_shape_center(b));
    s = fmax(s, fmax(prox_shape_size(a), prox_shape_size(b)));
    r.clearance = clear;
    r.inside = clear >= -PROX_QUERY_REL_TOL * s;
    return r;
}

static prox_status valid2(prox_status x, prox_status y) { return x != PROX_OK ? x : y; }

/* Result of invalid input. */
static prox_contain_result fail(prox_status st)
{
    prox_contain_result r = {0};
    r.status = st;
    return r;
}

PROX_API prox_contain_result prox_box_in_box(const prox_box *a, const prox_box *b)
{
    prox_status st = valid2(prox_box_validate(a), prox_box_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) {
        prox_bframe A = prox_bframe_make(a), B = prox_bframe_make(b);
        for (int i = 0; i < 8; ++i) c = fmin(c, box_point_clear(&B, prox_bframe_vertex(&A, i)));
    }
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_box(*b);
    return finish(st, c, &sa, &sb);
}

PROX_API prox_contain_result prox_box_in_rcc(const prox_box *a, const prox_rcc *b)
{
    prox_status st = valid2(prox_box_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) {
        prox_bframe A = prox_bframe_make(a);
        cyl_geom g = cyl_geom_make(b);
        for (int i = 0; i < 8; ++i) c = fmin(c, cyl_point_clear(&g, prox_bframe_vertex(&A, i)));
    }
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_rcc(*b);
    return finish(st, c, &sa, &sb);
}

PROX_API prox_contain_result prox_box_in_sph(const prox_box *a, const prox_sph *b)
{
    prox_status st = valid2(prox_box_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) {
        prox_bframe A = prox_bframe_make(a);
        for (int i = 0; i < 8; ++i) c = fmin(c, b->radius - prox_v3_dist(prox_bframe_vertex(&A, i), b->center));
    }
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_sph(*b);
    return finish(st, c, &sa, &sb);
}

PROX_API prox_contain_result prox_sph_in_box(const prox_sph *a, const prox_box *b)
{
    prox_status st = valid2(prox_sph_validate(a), prox_box_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) {
        prox_bframe B = prox_bframe_make(b);
        c = box_point_clear(&B, a->center) - a->radius;
    }
    prox_shape sa = prox_shape_from_sph(*a), sb = prox_shape_from_box(*b);
    return finish(st, c, &sa, &sb);
}

PROX_API prox_contain_result prox_sph_in_rcc(const prox_sph *a, const prox_rcc *b)
{
    prox_status st = valid2(prox_sph_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) {
        cyl_geom g = cyl_geom_make(b);
        c = cyl_point_clear(&g, a->center) - a->radius;
    }
    prox_shape sa = prox_shape_from_sph(*a), sb = prox_shape_from_rcc(*b);
    return finish(st, c, &sa, &sb);
}

PROX_API prox_contain_result prox_sph_in_sph(const prox_sph *a, const prox_sph *b)
{
    prox_status st = valid2(prox_sph_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) c = b->radius - prox_v3_dist(a->center, b->center) - a->radius;
    prox_shape sa = prox_shape_from_sph(*a), sb = prox_shape_from_sph(*b);
    return finish(st, c, &sa, &sb);
}

/* Rim circle `top` of A: centre. */
static prox_vec3 rim_center(const cyl_geom *g, int top) { return prox_v3_mad(g->base, top ? g->h : 0.0, g->w); }

PROX_API prox_contain_result prox_rcc_in_box(const prox_rcc *a, const prox_box *b)
{
    prox_status st = valid2(prox_rcc_validate(a), prox_box_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) { /* support of the rim along +-a_k: |gamma_k| + r |a_k - (a_k.w) w| */
        cyl_geom g = cyl_geom_make(a);
        prox_bframe B = prox_bframe_make(b);
        for (int top = 0; top < 2; ++top) {
            double l[3];
            prox_bframe_local(&B, rim_center(&g, top), l);
            for (int k = 0; k < 3; ++k)
                c = fmin(c, B.h[k] - fabs(l[k]) - g.r * prox_v3_norm(prox_v3_reject(B.a[k], g.w)));
        }
    }
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_box(*b);
    return finish(st, c, &sa, &sb);
}

PROX_API prox_contain_result prox_rcc_in_sph(const prox_rcc *a, const prox_sph *b)
{
    prox_status st = valid2(prox_rcc_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) { /* farthest rim point from the centre: sqrt(axial^2 + (rho + r)^2) */
        cyl_geom g = cyl_geom_make(a);
        for (int top = 0; top < 2; ++top) {
            prox_vec3 d = prox_v3_sub(b->center, rim_center(&g, top));
            double ax = prox_v3_dot(d, g.w), rho = prox_v3_norm(prox_v3_mad(d, -ax, g.w));
            c = fmin(c, b->radius - hypot(ax, rho + g.r));
        }
    }
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_sph(*b);
    return finish(st, c, &sa, &sb);
}

/* Max over the rim circle C of the distance to the line (base, unit w): the squared distance is smooth
 * and 2pi-periodic in the angle, so its maximum is at a stationary angle, and prox_circle_line_stationary
 * returns every one of them (Agarwal Sec. 3.3 quartic, polished; the same test as circle_in_cyl of
 * rcc_rcc.c). A constant distance (the line is C's axis) is read at any angle. */
static double rim_max_axis_dist(const prox_fcircle *C, prox_vec3 base, prox_vec3 w)
{
    double th[4] = {0.0};
    int cnt = 0;
    if (prox_circle_line_stationary(C, base, w, th, &cnt) != 0 || cnt == 0) {
        th[0] = 0.0;
        cnt = 1;
    }
    double best = 0.0;
    for (int i = 0; i < cnt; ++i) {
        prox_vec3 d = prox_v3_sub(prox_fcircle_point(C, th[i]), base);
        best = fmax(best, prox_v3_norm(prox_v3_reject(d, w)));
    }
    return best;
}

PROX_API prox_contain_result prox_rcc_in_rcc(const prox_rcc *a, const prox_rcc *b)
{
    prox_status st = valid2(prox_rcc_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    if (st == PROX_OK) { /* each rim: axial extent t_c +- r |w_B - (w_B.w_A) w_A|, radial max distance */
        cyl_geom A = cyl_geom_make(a), B = cyl_geom_make(b);
        double s = A.r * prox_v3_norm(prox_v3_reject(B.w, A.w));
        for (int top = 0; top < 2; ++top) {
            prox_vec3 ctr = rim_center(&A, top);
            double tc = prox_v3_dot(prox_v3_sub(ctr, B.base), B.w);
            c = fmin(c, fmin(tc - s, B.h - tc - s));
            prox_fcircle C = prox_fcircle_make(ctr, A.w, A.r);
            c = fmin(c, B.r - rim_max_axis_dist(&C, B.base, B.w));
        }
    }
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_rcc(*b);
    return finish(st, c, &sa, &sb);
}
