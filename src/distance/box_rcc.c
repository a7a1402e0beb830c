/* BOX-RCC: intersection verdict, exact distance and proximal points, signed distance.
 * Replaces the TRX report's Sec. 3.2 (LA-UR-13-26757, Eqs. (42)-(48): box edge lines against the
 * cylinder quadric, then against the end planes inside the circle), which misses a box inside the
 * cylinder, a cylinder inside the box, and a thin box (or slab) through the cylinder's side with no
 * box edge crossing the surface (the cylinder crosses two faces only).
 * Verdict: the intersection K of box and cylinder is compact convex; an extreme point of K lies on a box
 * edge (two box planes active), on a rim circle (no box plane active: an extreme point of the cylinder),
 * or on a face interior and the lateral surface. In the last case, if no edge meets the cylinder and no
 * rim meets the box, the face's section of the cylinder is a whole ellipse inside the face, and its
 * centre is on the axis: so  K != 0  <=>  an edge meets the cylinder, or a rim meets the box, or the
 * axis segment meets the box.
 * Distance (disjoint): a closest pair lies on (box vertex or edge, solid cylinder) or (rim circle, box
 * face interior); face-lateral and face-disk contacts are parallel and extend to one of those. Edge
 * against solid cylinder: dist(x(s), C) is convex and C^1 in s, minimised by bisection on the sign of
 * (x - proj_C x).x'(s). Rim against face: the circle's lowest point along the face normal. */
#include "distance/box_internal.h"
#include "prox/support.h"

typedef struct cyl_frame {
    prox_vec3 base, w, u, v;
    double h, r;
} cyl_frame;

static cyl_frame cyl_make(const prox_rcc *c)
{
    cyl_frame f;
    f.base = c->base;
    f.h = prox_v3_norm(c->axis);
    f.w = prox_v3_divs(c->axis, f.h);
    f.u = prox_v3_any_perp(f.w);
    f.v = prox_v3_cross(f.w, f.u);
    f.r = c->radius;
    return f;
}

/* Clips p + s (q - p), s in [0,1], to the solid cylinder enlarged by tol. */
static int clip_segment_cyl(const cyl_frame *c, prox_vec3 p, prox_vec3 q, double tol, double *s0, double *s1)
{
    prox_vec3 d = prox_v3_sub(q, p), o = prox_v3_sub(p, c->base);
    double t0 = prox_v3_dot(o, c->w), dt = prox_v3_dot(d, c->w), lo = 0.0, hi = 1.0;
    if (dt != 0.0) { /* slab 0 <= t <= h */
        double a = (-tol - t0) / dt, b = (c->h + tol - t0) / dt;
        if (a > b) { double x = a; a = b; b = x; }
        lo = a > lo ? a : lo;
        hi = b < hi ? b : hi;
    } else if (t0 < -tol || t0 > c->h + tol) return 0;
    if (lo > hi) return 0;
    prox_vec3 ro = prox_v3_mad(o, -t0, c->w), rd = prox_v3_mad(d, -dt, c->w);
    double A = prox_v3_dot(rd, rd), B = prox_v3_dot(ro, rd), R = c->r + tol;
    double C = (prox_v3_norm(ro) - R) * (prox_v3_norm(ro) + R);
    if (!(A > 0.0)) {
        if (C > 0.0) return 0;
    } else {
        double disc = B * B - A * C;
        if (disc < 0.0) return 0;
        double qq = -(B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
        double r1 = qq / A, r2 = qq != 0.0 ? C / qq : r1;
        if (r1 > r2) { double x = r1; r1 = r2; r2 = x; }
        lo = r1 > lo ? r1 : lo;
        hi = r2 < hi ? r2 : hi;
    }
    if (lo > hi) return 0;
    *s0 = lo;
    *s1 = hi;
    return 1;
}

/* Point of the rim circle (top = 0 base, 1 top) at angle th. */
static prox_vec3 rim_point(const cyl_frame *c, int top, double th)
{
    prox_vec3 ctr = prox_v3_mad(c->base, top ? c->h : 0.0, c->w);
    return prox_v3_add(ctr, prox_v3_add(prox_v3_scale(c->u, c->r * cos(th)), prox_v3_scale(c->v, c->r * sin(th))));
}

/* Does the rim circle meet the box enlarged by tol? Each constraint |g_k(th)| <= h_k + tol with
 * g_k = gamma + alpha cos th + beta sin th holds on arcs; a non-empty intersection of arcs contains
 * one of their end angles (or is the whole circle), so those angles and the midpoints between them
 * are the only candidates to test. */
static int rim_meets_box(const cyl_frame *c, int top, const prox_bframe *B, double tol, prox_vec3 *x)
{
    double cand[32];
    int nc = 0;
    cand[nc++] = 0.0;
    prox_vec3 ctr = prox_v3_mad(c->base, top ? c->h : 0.0, c->w);
    double g[3], al[3], be[3];
    for (int k = 0; k < 3; ++k) {
        g[k] = prox_v3_dot(prox_v3_sub(ctr, B->m), B->a[k]);
        al[k] = c->r * prox_v3_dot(c->u, B->a[k]);
        be[k] = c->r * prox_v3_dot(c->v, B->a[k]);
        double R = hypot(al[k], be[k]), phi = atan2(be[k], al[k]);
        for (int sgn = -1; sgn <= 1 && R > 0.0; sgn += 2) {
            double rho = (sgn * (B->h[k] + tol) - g[k]) / R;
            if (fabs(rho) > 1.0) continue;
            double ac = acos(rho);
            cand[nc++] = phi + ac;
            cand[nc++] = phi - ac;
        }
    }
    int nb = nc; /* add midpoints between consecutive sorted boundary angles */
    for (int i = 0; i < nb; ++i) cand[i] = fmod(fmod(cand[i], 2 * PROX_PI) + 2 * PROX_PI, 2 * PROX_PI);
    for (int i = 1; i < nb; ++i)
        for (int j = i; j > 0 && cand[j] < cand[j - 1]; --j) { double t = cand[j]; cand[j] = cand[j - 1]; cand[j - 1] = t; }
    for (int i = 0; i < nb; ++i) cand[nc++] = i + 1 < nb ? 0.5 * (cand[i] + cand[i + 1]) : 0.5 * (cand[i] + cand[0] + 2 * PROX_PI);
    for (int i = 0; i < nc; ++i) {
        int ok = 1;
        for (int k = 0; k < 3 && ok; ++k)
            ok = fabs(g[k] + al[k] * cos(cand[i]) + be[k] * sin(cand[i])) <= B->h[k] + 2.0 * tol;
        if (ok) {
            *x = rim_point(c, top, cand[i]);
            return 1;
        }
    }
    return 0;
}

static double pair_scale(const prox_bframe *B, const cyl_frame *c)
{
    prox_vec3 cc = prox_v3_mad(c->base, 0.5 * c->h, c->w);
    double s = prox_v3_dist(B->m, cc), v[3] = {prox_bframe_size(B), c->h, 2.0 * c->r};
    for (int i = 0; i < 3; ++i) s = v[i] > s ? v[i] : s;
    return s;
}

/* The verdict with a common point when they meet. */
static int box_rcc_meet(const prox_bframe *B, const cyl_frame *c, double tol, prox_vec3 *x)
{
    double s0, s1;
    for (int j = 0; j < 12; ++j) {
        prox_vec3 p, q;
        prox_bframe_edge(B, j, &p, &q);
        if (clip_segment_cyl(c, p, q, tol, &s0, &s1)) {
            *x = prox_v3_mad(p, 0.5 * (s0 + s1), prox_v3_sub(q, p));
            return 1;
        }
    }
    for (int top = 0; top < 2; ++top)
        if (rim_meets_box(c, top, B, tol, x)) return 1;
    prox_vec3 top = prox_v3_mad(c->base, c->h, c->w);
    if (prox_bframe_clip_segment(B, c->base, top, tol, &s0, &s1)) {
        *x = prox_v3_mad(c->base, 0.5 * (s0 + s1) * c->h, c->w);
        return 1;
    }
    return 0;
}

PROX_API prox_test_result prox_box_rcc_test(const prox_box *a, const prox_rcc *b)
{
    prox_test_result r = {0};
    r.status = prox_box_validate(a);
    if (r.status == PROX_OK) r.status = prox_rcc_validate(b);
    if (r.status != PROX_OK) return r;
    prox_bframe B = prox_bframe_make(a);
    cyl_frame c = cyl_make(b);
    prox_vec3 x;
    r.intersect = box_rcc_meet(&B, &c, PROX_QUERY_REL_TOL * pair_scale(&B, &c), &x);
    return r;
}

/* Minimum over s in [0,1] of dist(p + s d, C) for a segment disjoint from C: bisection on the sign of
 * the derivative of the convex squared distance. Returns the distance; *x, *y the points. */
static double edge_cyl(const prox_rcc *cyl, prox_vec3 p, prox_vec3 q, prox_vec3 *x, prox_vec3 *y)
{
    prox_vec3 d = prox_v3_sub(q, p);
    double lo = 0.0, hi = 1.0, s;
#define DERIV(t) prox_v3_dot(prox_v3_sub(prox_v3_mad(p, (t), d), prox_rcc_closest_point(cyl, prox_v3_mad(p, (t), d))), d)
    if (DERIV(0.0) >= 0.0) s = 0.0;
    else if (DERIV(1.0) <= 0.0) s = 1.0;
    else {
        for (int it = 0; it < 80; ++it) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            if (DERIV(mid) < 0.0) lo = mid;
            else hi = mid;
        }
        s = 0.5 * (lo + hi);
    }
#undef DERIV
    prox_vec3 n;
    *x = prox_v3_mad(p, s, d);
    return prox_rcc_point_signed(cyl, *x, y, &n);
}

/* Rim circle against the interior of the box face with outward normal sgn a_k: the circle's lowest
 * point along the normal, when it projects into the face and lies above it. */
static double rim_face(const cyl_frame *c, int top, const prox_bframe *B, int k, int sgn, prox_vec3 *x, prox_vec3 *y)
{
    prox_vec3 nf = prox_v3_scale(B->a[k], (double)sgn);
    prox_vec3 ctr = prox_v3_mad(c->base, top ? c->h : 0.0, c->w);
    prox_vec3 rj = prox_v3_reject(nf, c->w);
    double rn = prox_v3_norm(rj);
    prox_vec3 dir;
    if (rn > 1e-12) dir = prox_v3_neg(prox_v3_divs(rj, rn));
    else { /* circle parallel to the face: every rim point is as low; take the one nearest the centre */
        prox_vec3 t = prox_v3_reject(prox_v3_sub(B->m, ctr), c->w);
        double tn = prox_v3_norm(t);
        dir = tn > 0.0 ? prox_v3_divs(t, tn) : c->u;
    }
    *x = prox_v3_mad(ctr, c->r, dir);
    double l[3];
    prox_bframe_local(B, *x, l);
    for (int j = 0; j < 3; ++j)
        if (j != k && fabs(l[j]) > B->h[j]) return INFINITY;
    double height = sgn * l[k] - B->h[k];
    if (!(height > 0.0)) return INFINITY;
    l[k] = sgn * B->h[k];
    *y = prox_bframe_point(B, l);
    return height;
}

PROX_API prox_distance_result prox_box_rcc_distance(const prox_box *a, const prox_rcc *b)
{
    prox_distance_result r = {0};
    r.status = prox_box_validate(a);
    if (r.status == PROX_OK) r.status = prox_rcc_validate(b);
    if (r.status != PROX_OK) return r;
    prox_bframe B = prox_bframe_make(a);
    cyl_frame c = cyl_make(b);
    prox_vec3 x, y;
    if (box_rcc_meet(&B, &c, PROX_QUERY_REL_TOL * pair_scale(&B, &c), &x)) {
        r.intersect = 1;
        r.p1 = r.p2 = x;
        return r;
    }
    double best = INFINITY;
    for (int j = 0; j < 12; ++j) {
        prox_vec3 p, q;
        prox_bframe_edge(&B, j, &p, &q);
        double d = edge_cyl(b, p, q, &x, &y);
        if (d < best) best = d, r.p1 = x, r.p2 = y;
    }
    for (int top = 0; top < 2; ++top)
        for (int f = 0; f < 6; ++f) {
            double d = rim_face(&c, top, &B, f / 2, (f & 1) ? 1 : -1, &x, &y);
            if (d < best) best = d, r.p1 = y, r.p2 = x;
        }
    r.distance = best;
    prox_vec3 n = prox_v3_normalize(prox_v3_sub(r.p2, r.p1));
    r.certificate_gap = -prox_rcc_support(b, prox_v3_neg(n)) - prox_bframe_support(&B, n);
    return r;
}

PROX_API prox_signed_result prox_box_rcc_signed_distance(const prox_box *a, const prox_rcc *b)
{
    prox_signed_result r = {0};
    prox_distance_result d = prox_box_rcc_distance(a, b);
    r.status = d.status;
    if (r.status != PROX_OK) return r;
    if (!d.intersect && d.distance > 0.0) {
        r.sd = d.distance;
        r.normal = prox_v3_divs(prox_v3_sub(d.p2, d.p1), d.distance);
        r.p1 = d.p1;
        r.p2 = d.p2;
        return r;
    }
    /* overlapping: minimum of h_A(D) + h_B(-D) over unit D (support-function engine) */
    prox_shape sa = prox_shape_from_box(*a), sb = prox_shape_from_rcc(*b);
    return prox_shape_signed_distance_support(&sa, &sb);
}
