/* A sphere against any macrobody: exact distance, proximal points and signed distance from the signed
 * distance of the sphere's centre to the other solid B (core: prox_cyl_signed, prox_bframe_signed and
 * the boundary functions of core/curved.h and core/polytope.h):
 *   sd(B, sphere) = sd_B(c) - r,
 * exact because B is convex: its signed distance function is 1-Lipschitz and decreases at unit rate
 * from c towards the nearest boundary point q (outside: |c - q| - r, the TRX report's Eq. (174)
 * generalised; inside: the ball of radius |sd_B(c)| about c is the largest one in B). The witnesses
 * are q on B and c - r n on the sphere, n the outward normal of B at q (c = q + sd_B(c) n).
 * This is the lean path of every sphere pair: one validation of each shape, B prepared in its own
 * small frame (a polytope only for RHP, WED and ARB), no generic body built. */
#include "core/body.h"
#include "core/curved_normal.h"
#include "core/minmax.h"
#include "core/tol.h"
#include "core/validate.h"
#include "query/query_internal.h"

/* The solid B prepared for point queries (only the member of its kind is set). */
typedef struct sa_solid {
    prox_shape_kind kind;
    prox_vec3 c;   /* reference point (centre) in absolute coordinates; RCC and BOX frames are absolute */
    double size;   /* largest dimension, for the pair's scale */
    union {
        prox_cyl cyl;
        prox_bframe box;
        prox_cone cone;
        prox_ecyl ecyl;
        prox_ellb ell;
        prox_polytope poly;
        double r;
    } g;
} sa_solid;

/* The frame of an RPP without square roots: centre, unit axes, half extents. */
static prox_bframe rpp_frame(const prox_rpp *r)
{
    prox_bframe f;
    f.m = prox_v3(0.5 * (r->xmin + r->xmax), 0.5 * (r->ymin + r->ymax), 0.5 * (r->zmin + r->zmax));
    f.a[0] = prox_v3(1, 0, 0), f.a[1] = prox_v3(0, 1, 0), f.a[2] = prox_v3(0, 0, 1);
    f.h[0] = 0.5 * (r->xmax - r->xmin), f.h[1] = 0.5 * (r->ymax - r->ymin), f.h[2] = 0.5 * (r->zmax - r->zmin);
    return f;
}

static void sa_prepare(const prox_shape *s, sa_solid *b)
{
    b->kind = s->kind;
    switch (s->kind) {
    case PROX_SHAPE_RCC:
        b->g.cyl = prox_cyl_make(&s->u.rcc, prox_v3(0, 0, 0));
        b->c = b->g.cyl.c;
        b->size = fmax(b->g.cyl.h, 2.0 * b->g.cyl.r);
        break;
    case PROX_SHAPE_BOX:
    case PROX_SHAPE_RPP:
        b->kind = PROX_SHAPE_BOX;
        b->g.box = s->kind == PROX_SHAPE_BOX ? prox_bframe_make(&s->u.box) : rpp_frame(&s->u.rpp);
        b->c = b->g.box.m;
        b->size = prox_bframe_size(&b->g.box);
        break;
    case PROX_SHAPE_SPH:
        b->c = s->u.sph.center;
        b->g.r = s->u.sph.radius;
        b->size = 2.0 * b->g.r;
        break;
    case PROX_SHAPE_TRC:
        b->c = prox_cone_make(&s->u.trc, &b->g.cone);
        b->size = fmax(2.0 * b->g.cone.hh, 2.0 * fmax(b->g.cone.r1, b->g.cone.r2));
        break;
    case PROX_SHAPE_REC:
        b->c = prox_ecyl_make(&s->u.rec, &b->g.ecyl);
        b->size = fmax(2.0 * b->g.ecyl.hh, 2.0 * fmax(b->g.ecyl.a1, b->g.ecyl.a2));
        break;
    case PROX_SHAPE_ELL:
        b->c = prox_ellb_make(&s->u.ell, &b->g.ell);
        b->size = 2.0 * fmax(b->g.ell.a, b->g.ell.b);
        break;
    default: /* RHP, WED, ARB */
        b->kind = PROX_SHAPE_ARB;
        b->c = prox_polytope_make(s, &b->g.poly);
        b->size = b->g.poly.size;
        break;
    }
}

void prox_query_center_size(const prox_shape *s, prox_vec3 *c, double *size)
{
    sa_solid b;
    sa_prepare(s, &b);
    *c = b.c;
    *size = b.size;
}

/* Signed distance of x to B (< 0 inside), B's nearest boundary point *q and the outward unit normal *n
 * there (x = q + sd n). The normal comes from the feature q lies on (core/curved_normal.h; a polytope's
 * nearest face), not from x - q, whose direction is rounding noise when x is within ulps of the
 * boundary; a polytope's outside point away from the surface takes (x - q) / |x - q|. */
static double sa_signed(const sa_solid *b, prox_vec3 x, prox_vec3 *q, prox_vec3 *n)
{
    double sd;
    prox_vec3 y = prox_v3_sub(x, b->c), qc;
    switch (b->kind) {
    case PROX_SHAPE_RCC: return prox_cyl_signed(&b->g.cyl, x, q, n);
    case PROX_SHAPE_BOX: {
        sd = prox_bframe_signed(&b->g.box, x, q, n);
        if (!(prox_v3_norm2(*n) > 0.0)) *n = b->g.box.a[2]; /* x on the surface: a face normal is valid */
        return sd;
    }
    case PROX_SHAPE_SPH: {
        double d = prox_v3_norm(y);
        *n = d > 0.0 ? prox_v3_scale(y, 1.0 / d) : prox_v3(0, 0, 1);
        *q = prox_v3_mad(b->c, b->g.r, *n);
        return d - b->g.r;
    }
    case PROX_SHAPE_TRC: sd = prox_cone_boundary_n(&b->g.cone, y, &qc, n); break;
    case PROX_SHAPE_REC: sd = prox_ecyl_boundary_n(&b->g.ecyl, y, &qc, n); break;
    case PROX_SHAPE_ELL: sd = prox_ellb_boundary_n(&b->g.ell, y, &qc, n); break;
    default: {
        sd = prox_polytope_boundary(&b->g.poly, y, &qc);
        prox_vec3 v = prox_v3_sub(y, qc);
        double len = prox_v3_norm(v);
        if (sd > 0.0 && len > 0.0) {
            *n = prox_v3_scale(v, 1.0 / len);
        } else { /* inside or on the boundary: the normal of the face whose plane is nearest (y - q is
                  * along it, but its direction is rounding noise when y is within ulps of the face) */
            int f = 0;
            for (int k = 1; k < b->g.poly.nf; ++k)
                if (prox_v3_dot(b->g.poly.n[k], y) - b->g.poly.d[k] > prox_v3_dot(b->g.poly.n[f], y) - b->g.poly.d[f]) f = k;
            *n = b->g.poly.n[f];
        }
        break;
    }
    }
    *q = prox_v3_add(b->c, qc);
    return sd;
}

double prox_query_point_signed(const prox_shape *s, prox_vec3 x)
{
    sa_solid b;
    prox_vec3 q, n;
    sa_prepare(s, &b);
    return sa_signed(&b, x, &q, &n);
}

/* Support function of B along d (absolute), for the certificate of a disjoint pair. */
static double sa_support(const sa_solid *b, prox_vec3 d)
{
    switch (b->kind) {
    case PROX_SHAPE_RCC: return prox_cyl_support(&b->g.cyl, d);
    case PROX_SHAPE_BOX: return prox_bframe_support(&b->g.box, d);
    case PROX_SHAPE_SPH: return prox_v3_dot(d, b->c) + b->g.r * prox_v3_norm(d);
    case PROX_SHAPE_TRC: return prox_v3_dot(d, b->c) + prox_cone_hc(&b->g.cone, d);
    case PROX_SHAPE_REC: return prox_v3_dot(d, b->c) + prox_ecyl_hc(&b->g.ecyl, d);
    case PROX_SHAPE_ELL: return prox_v3_dot(d, b->c) + prox_ellb_hc(&b->g.ell, d);
    default: return prox_v3_dot(d, b->c) + prox_polytope_hc(&b->g.poly, d);
    }
}

/* Validation in the caller's order: the first shape of the public call reports first. */
static prox_status sa_validate(const prox_shape *b, const prox_sph *s, int sphere_first)
{
    prox_status sb, ss;
    if (sphere_first) {
        ss = prox_sph_validate(s);
        return ss != PROX_OK ? ss : prox_shape_validate(b);
    }
    sb = prox_shape_validate(b);
    return sb != PROX_OK ? sb : prox_sph_validate(s);
}

/* The status of the pair (b and the sphere s, in the caller's order) and, for an RCC, its squared
 * height. */
static prox_status sph_pair_check(const prox_shape *b, const prox_sph *s, int sphere_first, double *h2)
{
    if (b->kind == PROX_SHAPE_RCC || b->kind == PROX_SHAPE_BOX) { /* the commonest pairs: no switch */
        prox_status sb = b->kind == PROX_SHAPE_RCC ? prox_rcc_validate_h2(&b->u.rcc, h2) : prox_box_validate(&b->u.box);
        prox_status ss = prox_sph_validate(s);
        return sphere_first ? (ss != PROX_OK ? ss : sb) : (sb != PROX_OK ? sb : ss);
    }
    return sa_validate(b, s, sphere_first);
}

prox_signed_result prox_query_sph_signed(const prox_shape *b, const prox_sph *s, int sphere_first)
{
    double h2 = 0.0;
    prox_status st = sph_pair_check(b, s, sphere_first, &h2);
    return st != PROX_OK ? (prox_signed_result){.status = st} : prox_query_sph_signed_valid(b, s, h2);
}

prox_signed_result prox_query_sph_signed_valid(const prox_shape *b, const prox_sph *s, double h2)
{
    prox_signed_result r;
    prox_vec3 q, n;
    double sdp, size;
    if (b->kind == PROX_SHAPE_RCC) {
        prox_cyl k = prox_cyl_make_h(&b->u.rcc, sqrt(h2), prox_v3(0, 0, 0));
        sdp = prox_cyl_signed(&k, s->center, &q, &n);
        size = k.h + 2.0 * k.r;
    } else if (b->kind == PROX_SHAPE_BOX) {
        prox_bframe f = prox_bframe_make(&b->u.box);
        sdp = prox_bframe_signed(&f, s->center, &q, &n);
        if (!(prox_v3_norm2(n) > 0.0)) n = f.a[2]; /* the centre on the surface: a face normal is valid */
        size = prox_bframe_size(&f);
    } else {
        sa_solid B;
        sa_prepare(b, &B);
        sdp = sa_signed(&B, s->center, &q, &n);
        size = B.size;
    }
    r.status = PROX_OK;
    r.sd = sdp - s->radius;
    r.normal = n;
    r.p1 = q;
    r.p2 = prox_v3_mad(s->center, -s->radius, n);
    prox_signed_closed_form(&r, fabs(sdp) + 2.0 * s->radius + size);
    return r;
}

/* ---- the lean distance of the two commonest pairs: a cylinder or a box against a sphere ----
 * The distance query needs the boundary point only when the centre is outside, so these work on the
 * card's vectors directly (no unit axis or frame is formed): one square root for the radial offset,
 * one for the distance, one for the scale. */

/* Disjoint result from the nearest point q of B to the centre (dist = |centre - q| > 0), the unit
 * n = (centre - q) / dist and B's support along n, h_n: the witnesses and the gap along n. */
static prox_distance_result sa_disjoint(prox_vec3 q, double dist, const prox_sph *s, double h_n, prox_vec3 n)
{
    prox_distance_result r = {0};
    r.distance = dist - s->radius;
    r.p1 = q;
    r.p2 = prox_v3_mad(s->center, -s->radius, n);
    r.certificate_gap = (prox_v3_dot(n, s->center) - s->radius) - h_n;
    r.certified = 1;
    return r;
}

/* Overlap result with the common point p. */
static prox_distance_result sa_overlap(prox_vec3 p)
{
    prox_distance_result r = {0};
    r.intersect = 1;
    r.certified = 1;
    r.p1 = r.p2 = p;
    return r;
}


/* RCC (validated, |axis|^2 = h2) against the sphere: the centre's height t over the base and its
 * radial offset rho give the nearest point (t, rho) clamped to [0, h] x [0, r]. */
static prox_distance_result rcc_lean(const prox_rcc *c, double h2, const prox_sph *s)
{
    double h = sqrt(h2), r = c->radius;
    prox_vec3 d = prox_v3_sub(s->center, c->base);
    double ta = prox_v3_dot(d, c->axis), t = ta / h;
    prox_vec3 rad = prox_v3_mad(d, -ta / h2, c->axis);
    double rho = prox_v3_norm(rad), tc = t < 0.0 ? 0.0 : (t > h ? h : t);
    if (tc == t && rho <= r) return sa_overlap(s->center); /* the centre is in the cylinder */
    double e = rho > r ? rho - r : 0.0, dist = prox_hypot2(t - tc, e);
    double scale = prox_max2(prox_max2(prox_hypot2(t - 0.5 * h, rho), prox_max2(h, 2.0 * r)), 2.0 * s->radius);
    prox_vec3 q = prox_v3_add(prox_v3_mad(c->base, tc / h, c->axis), rho > r ? prox_v3_scale(rad, r / rho) : rad);
    if (dist - s->radius <= PROX_QUERY_REL_TOL * scale) return sa_overlap(q);
    prox_vec3 n = prox_v3_scale(prox_v3_sub(s->center, q), 1.0 / dist);
    /* support of the cylinder along n: n.centre + (h/2)|n.w| + r |n - (n.w) w| */
    double nw = prox_v3_dot(n, c->axis) / h;
    double h_n = prox_v3_dot(n, prox_v3_mad(c->base, 0.5, c->axis)) + 0.5 * h * fabs(nw) +
                 r * sqrt(prox_max2(0.0, 1.0 - nw * nw));
    return sa_disjoint(q, dist, s, h_n, n);
}

/* BOX (validated) against the sphere: the centre's edge parameters clamped to [0, 1]. */
static prox_distance_result box_lean(const prox_box *b, const prox_sph *s)
{
    prox_vec3 d = prox_v3_sub(s->center, b->corner), q = b->corner, m = b->corner;
    int inside = 1;
    double e2max = 0.0;
    for (int k = 0; k < 3; ++k) {
        double ee = prox_v3_norm2(b->edge[k]), sk = prox_v3_dot(d, b->edge[k]) / ee;
        double ck = sk < 0.0 ? 0.0 : (sk > 1.0 ? 1.0 : sk);
        inside &= ck == sk;
        q = prox_v3_mad(q, ck, b->edge[k]);
        m = prox_v3_mad(m, 0.5, b->edge[k]);
        e2max = prox_max2(e2max, ee);
    }
    if (inside) return sa_overlap(s->center);
    prox_vec3 v = prox_v3_sub(s->center, q);
    double dist = prox_v3_norm(v);
    double scale = prox_max2(prox_max2(prox_v3_dist(m, s->center), sqrt(e2max)), 2.0 * s->radius);
    if (dist - s->radius <= PROX_QUERY_REL_TOL * scale) return sa_overlap(q);
    prox_vec3 n = prox_v3_scale(v, 1.0 / dist);
    double h_n = prox_v3_dot(n, m);
    for (int k = 0; k < 3; ++k) h_n += 0.5 * fabs(prox_v3_dot(n, b->edge[k]));
    return sa_disjoint(q, dist, s, h_n, n);
}

prox_distance_result prox_query_sph_distance(const prox_shape *b, const prox_sph *s, int sphere_first)
{
    double h2 = 0.0;
    prox_status st = sph_pair_check(b, s, sphere_first, &h2);
    return st != PROX_OK ? (prox_distance_result){.status = st} : prox_query_sph_distance_valid(b, s, h2);
}

prox_distance_result prox_query_sph_distance_valid(const prox_shape *b, const prox_sph *s, double h2)
{
    prox_distance_result r = {0};
    if (b->kind == PROX_SHAPE_RCC) return rcc_lean(&b->u.rcc, h2, s);
    if (b->kind == PROX_SHAPE_BOX) return box_lean(&b->u.box, s);
    sa_solid B;
    sa_prepare(b, &B);
    prox_vec3 q, n;
    double sdp = sa_signed(&B, s->center, &q, &n);
    double scale = fmax(fmax(prox_v3_dist(B.c, s->center), B.size), 2.0 * s->radius);
    r.certified = 1;
    if (sdp - s->radius <= PROX_QUERY_REL_TOL * scale) { /* tangency within tol counts as touching */
        r.intersect = 1;
        r.p1 = r.p2 = sdp <= 0.0 ? s->center : q; /* the point of B nearest to the centre */
        return r;
    }
    r.distance = sdp - s->radius;
    r.p1 = q;
    r.p2 = prox_v3_mad(s->center, -s->radius, n);
    r.certificate_gap = (prox_v3_dot(n, s->center) - s->radius) - sa_support(&B, n);
    return r;
}

prox_test_result prox_query_sph_test(const prox_shape *b, const prox_sph *s, int sphere_first)
{
    prox_test_result r = {0};
    prox_distance_result d = prox_query_sph_distance(b, s, sphere_first);
    r.status = d.status;
    r.intersect = d.intersect;
    if (d.status == PROX_OK && !d.intersect) {
        r.direction = prox_v3_normalize(prox_v3_sub(d.p2, d.p1));
        r.value = d.certificate_gap;
    }
    return r;
}
