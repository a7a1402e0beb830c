/* Containment A inside B for the 9 ordered pairs of {BOX/RPP, RCC, SPH}, any position and orientation.
 * Generalises the TRX report's Set 1 (LA-UR-13-26757, Sec. 2, Eqs. (1)-(18): local "optimal"
 * orientation only, with the errata listed in docs/errata-trx.md).
 * B is convex, so A lies in B iff A's extreme points do: box vertices, cylinder rim circles, the sphere.
 * The clearance returned is min over A of the distance to B's boundary (signed: < 0 when A sticks out):
 * inside B that distance is concave, so its minimum over A is attained at an extreme point of A.
 * Point clearances: box min_k (h_k - |l_k|); cylinder min(t, h - t, r - rho); sphere R - |x - c|.
 * A rim in a cylinder: axial extent t_c +- r |w_A x w_B|, and the largest distance of the rim from the
 * axis: the farthest point from the axis of the ellipse the rim projects onto
 * (prox_cyl_in_cyl_clearance, core/cyl_contain.c: the containment the RCC-RCC query shares). */
#include "distance/box_internal.h"

static double box_point_clear(const prox_bframe *B, prox_vec3 x)
{
    double l[3], m = INFINITY;
    prox_bframe_local(B, x, l);
    for (int k = 0; k < 3; ++k) m = fmin(m, B->h[k] - fabs(l[k]));
    return m;
}

static double cyl_point_clear(const prox_cyl *c, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, c->b);
    double t = prox_v3_dot(d, c->w);
    double rho = prox_v3_norm(prox_v3_mad(d, -t, c->w));
    return fmin(fmin(t, c->h - t), c->r - rho);
}

/* A validated cylinder prepared in absolute coordinates. */
static prox_cyl cyl_of(const prox_rcc *c) { return prox_cyl_make(c, prox_v3(0, 0, 0)); }

/* Centre and size of a valid RCC, BOX or SPH as the generic body has them (core/body.c: the pair's
 * scale of every generic query), without building the body. */
static prox_vec3 centre_size(const prox_shape *s, double *size)
{
    if (s->kind == PROX_SHAPE_RCC) {
        *size = fmax(prox_v3_norm(s->u.rcc.axis), 2.0 * s->u.rcc.radius);
        return prox_rcc_center(&s->u.rcc);
    }
    if (s->kind == PROX_SHAPE_SPH) {
        *size = 2.0 * s->u.sph.radius;
        return s->u.sph.center;
    }
    prox_bframe f = prox_bframe_make(&s->u.box);
    *size = prox_bframe_size(&f);
    return f.m;
}

/* Result of valid input: inside when the clearance is >= -tol (tol relative to the pair's scale). */
static prox_contain_result finish(double clear, prox_shape a, prox_shape b)
{
    prox_contain_result r = {0};
    r.status = PROX_OK;
    double sa, sb;
    prox_vec3 ca = centre_size(&a, &sa), cb = centre_size(&b, &sb);
    double s = fmax(prox_v3_dist(ca, cb), fmax(sa, sb));
    r.clearance = clear;
    r.inside = clear >= -PROX_QUERY_REL_TOL * s;
    return r;
}

/* Result of invalid input. */
static prox_contain_result fail(prox_status st)
{
    prox_contain_result r = {0};
    r.status = st;
    return r;
}

PROX_API prox_contain_result prox_box_in_box(const prox_box *a, const prox_box *b)
{
    prox_status st = prox_valid2(prox_box_validate(a), prox_box_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    prox_bframe A = prox_bframe_make(a), B = prox_bframe_make(b);
    for (int i = 0; i < 8; ++i) c = fmin(c, box_point_clear(&B, prox_bframe_vertex(&A, i)));
    return finish(c, prox_shape_from_box(*a), prox_shape_from_box(*b));
}

PROX_API prox_contain_result prox_box_in_rcc(const prox_box *a, const prox_rcc *b)
{
    prox_status st = prox_valid2(prox_box_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    prox_bframe A = prox_bframe_make(a);
    prox_cyl g = cyl_of(b);
    for (int i = 0; i < 8; ++i) c = fmin(c, cyl_point_clear(&g, prox_bframe_vertex(&A, i)));
    return finish(c, prox_shape_from_box(*a), prox_shape_from_rcc(*b));
}

PROX_API prox_contain_result prox_box_in_sph(const prox_box *a, const prox_sph *b)
{
    prox_status st = prox_valid2(prox_box_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = INFINITY;
    prox_bframe A = prox_bframe_make(a);
    for (int i = 0; i < 8; ++i) c = fmin(c, b->radius - prox_v3_dist(prox_bframe_vertex(&A, i), b->center));
    return finish(c, prox_shape_from_box(*a), prox_shape_from_sph(*b));
}

PROX_API prox_contain_result prox_sph_in_box(const prox_sph *a, const prox_box *b)
{
    prox_status st = prox_valid2(prox_sph_validate(a), prox_box_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    prox_bframe B = prox_bframe_make(b);
    double c = box_point_clear(&B, a->center) - a->radius;
    return finish(c, prox_shape_from_sph(*a), prox_shape_from_box(*b));
}

PROX_API prox_contain_result prox_sph_in_rcc(const prox_sph *a, const prox_rcc *b)
{
    prox_status st = prox_valid2(prox_sph_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    prox_cyl g = cyl_of(b);
    double c = cyl_point_clear(&g, a->center) - a->radius;
    return finish(c, prox_shape_from_sph(*a), prox_shape_from_rcc(*b));
}

PROX_API prox_contain_result prox_sph_in_sph(const prox_sph *a, const prox_sph *b)
{
    prox_status st = prox_valid2(prox_sph_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    double c = b->radius - prox_v3_dist(a->center, b->center) - a->radius;
    return finish(c, prox_shape_from_sph(*a), prox_shape_from_sph(*b));
}

PROX_API prox_contain_result prox_rcc_in_box(const prox_rcc *a, const prox_box *b)
{
    prox_status st = prox_valid2(prox_rcc_validate(a), prox_box_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    /* support of the rim along +-a_k: |gamma_k| + r |a_k - (a_k.w) w| */
    double c = INFINITY;
    prox_cyl g = cyl_of(a);
    prox_bframe B = prox_bframe_make(b);
    for (int top = 0; top < 2; ++top) {
        double l[3];
        prox_bframe_local(&B, g.cap[top], l);
        for (int k = 0; k < 3; ++k)
            c = fmin(c, B.h[k] - fabs(l[k]) - g.r * prox_v3_norm(prox_v3_reject(B.a[k], g.w)));
    }
    return finish(c, prox_shape_from_rcc(*a), prox_shape_from_box(*b));
}

PROX_API prox_contain_result prox_rcc_in_sph(const prox_rcc *a, const prox_sph *b)
{
    prox_status st = prox_valid2(prox_rcc_validate(a), prox_sph_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    /* farthest rim point from the centre: sqrt(axial^2 + (rho + r)^2) */
    double c = INFINITY;
    prox_cyl g = cyl_of(a);
    for (int top = 0; top < 2; ++top) {
        prox_vec3 d = prox_v3_sub(b->center, g.cap[top]);
        double ax = prox_v3_dot(d, g.w), rho = prox_v3_norm(prox_v3_mad(d, -ax, g.w));
        c = fmin(c, b->radius - hypot(ax, rho + g.r));
    }
    return finish(c, prox_shape_from_rcc(*a), prox_shape_from_sph(*b));
}

PROX_API prox_contain_result prox_rcc_in_rcc(const prox_rcc *a, const prox_rcc *b)
{
    prox_status st = prox_valid2(prox_rcc_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return fail(st); /* before any dereference: null inputs */
    /* each rim: axial extent t_c +- r |w_A x w_B|, radial max distance (core/cyl_contain.c) */
    prox_cyl A = cyl_of(a), B = cyl_of(b);
    double c = prox_cyl_in_cyl_clearance(&A, &B);
    return finish(c, prox_shape_from_rcc(*a), prox_shape_from_rcc(*b));
}
