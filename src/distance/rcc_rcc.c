/* Exact minimum distance and proximal points of two solid right circular cylinders.
 *
 * Source: Agarwal, Srivatsan & Bandyopadhyay, "Analytical determination of the proximity of two
 * right-circular cylinders in space", J. Mech. Robot. 8 (2016), Sec. 2 (Figs. 3-5) and Sec. 3.
 *
 * How a query flows (docs/design.md has the long version):
 *  1. Both cylinders are prepared once (unit axis, height, rims, disks) in a frame centred on A's
 *     centre, so that pairs far from the origin keep their relative precision.
 *  2. Agarwal's first level: P(S1,S2) from the common perpendicular of the axes gives the case
 *     (1, 2.1/2.2, 3) and the ends of each cylinder nearest to the feet.
 *  3. Candidates.  For two DISJOINT convex solids the closest pair (p1, p2) lies on a pair of features
 *     (lateral surface S, end-disk interior D, rim circle C) where the distance is stationary, so it is
 *     one of: S-S on the common perpendicular, C-S (stationary points of circle-to-axis distance),
 *     C-D (extreme points of a rim with respect to the other disk's plane), C-C (degree-8 stationary
 *     points).  D-D and D-S contacts (parallel faces, perpendicular axes) are limits that always also
 *     attain their minimum at a C-D or C-S candidate.  Every candidate is a genuine pair of points of
 *     A x B, so min over candidates = the distance exactly, whatever subset of candidates was wrong.
 *  4. Agarwal's hierarchy picks the candidates it believes decide (Case 1: S-S; Case 2/3: the ends
 *     nearest to the feet).  Its pick is CERTIFIED by duality: along the contact normal n of the best
 *     candidate the projections of A and B are separated by gap(n) = -h_B(-n) - h_A(n) <= distance
 *     <= |p2 - p1|; when the two agree within a few ulps of the scale, the answer is exact and no other
 *     candidate can be better.  Otherwise (the hierarchy is a heuristic: docs/errata.md) every other
 *     candidate group is evaluated, skipping groups whose cheap lower bound cannot beat the best.
 *  5. Overlap: any candidate point that lies inside the other solid is a common point; failing that,
 *     alternating projections between the solids find one.  Containment (Agarwal Fig. 2) is decided
 *     exactly: A lies in B iff both rims of A lie in B (B convex, A the hull of its rims).
 */
#include <float.h>
#include <stddef.h>

#include "distance/stationary.h"
#include "prox/distance.h"

/* A cylinder prepared for the query (coordinates relative to the query origin). */
typedef struct cyl {
    prox_vec3 b, w, c; /* base centre, unit axis, centre */
    double h, r;
    prox_fcircle rim[2]; /* 0: base circle, 1: top circle */
    prox_vec3 cap[2];    /* disk centres */
} cyl;

/* One candidate pair of points (p1 on A, p2 on B). */
typedef struct cand {
    double d;
    prox_vec3 p1, p2, n; /* n: unit contact normal from A to B as the feature pair defines it */
    prox_pair_kind kind;
    prox_feature f1, f2;
} cand;

/* Query state: best candidate so far and overlap witness. */
typedef struct query {
    cyl A, B;
    double scale, eps; /* eps: absolute tolerance for ties and certificates, a few ulps of scale */
    cand best;
    int have_best;
    int overlap;
    prox_vec3 common; /* a point of A and B when overlap */
    int parallel;     /* axes parallel to working precision */
} query;

static cyl cyl_make(const prox_rcc *c, prox_vec3 origin)
{
    cyl k;
    k.h = prox_v3_norm(c->axis);
    k.w = prox_v3_scale(c->axis, 1.0 / k.h);
    k.r = c->radius;
    k.b = prox_v3_sub(c->base, origin);
    k.c = prox_v3_mad(k.b, 0.5 * k.h, k.w);
    k.cap[0] = k.b;
    k.cap[1] = prox_v3_mad(k.b, k.h, k.w);
    k.rim[0] = prox_fcircle_make(k.cap[0], k.w, k.r);
    k.rim[1] = prox_fcircle_make(k.cap[1], k.w, k.r);
    return k;
}

static prox_rcc cyl_as_rcc(const cyl *k)
{
    prox_rcc r = {k->b, prox_v3_scale(k->w, k->h), k->r};
    return r;
}

/* Support function of a prepared cylinder (see rcc_support.c; same formula, prepared data). */
static double cyl_support(const cyl *k, prox_vec3 d)
{
    double dw = prox_v3_dot(d, k->w);
    return prox_v3_dot(d, k->c) + k->r * prox_v3_norm(prox_v3_mad(d, -dw, k->w)) + 0.5 * k->h * fabs(dw);
}

/* Separation of the projections of A and B on unit n: a lower bound on the distance (duality). */
static double gap_along(const query *q, prox_vec3 n)
{
    return -cyl_support(&q->B, prox_v3_neg(n)) - cyl_support(&q->A, n);
}

/* Signed distance of x outside the solid cylinder k (<= 0 inside), with x's axial coordinate. */
static int cyl_contains(const cyl *k, prox_vec3 x, double tol)
{
    prox_vec3 d = prox_v3_sub(x, k->b);
    double t = prox_v3_dot(d, k->w);
    if (t < -tol || t > k->h + tol) return 0;
    return prox_v3_norm(prox_v3_mad(d, -t, k->w)) <= k->r + tol;
}

static void note_common(query *q, prox_vec3 x)
{
    if (!q->overlap) {
        q->overlap = 1;
        q->common = x;
    }
}

/* Offers a candidate pair; keeps the shortest. Points inside the other solid witness overlap. */
static void offer(query *q, prox_vec3 p1, prox_vec3 p2, prox_vec3 n, prox_pair_kind kind, prox_feature f1,
                  prox_feature f2)
{
    if (cyl_contains(&q->B, p1, 0.0)) note_common(q, p1);
    if (cyl_contains(&q->A, p2, 0.0)) note_common(q, p2);
    double d = prox_v3_dist(p1, p2);
    if (q->have_best && !(d < q->best.d)) return;
    cand c = {d, p1, p2, n, kind, f1, f2};
    q->best = c;
    q->have_best = 1;
}

/* ---- S-S: common perpendicular of the axes (Agarwal Sec. 3.1, case (a)) ---- */

/* Feet of the common perpendicular: s on A's axis, t on B's axis (lengths from the bases).
 * Uses n = wA x wB, s = ((bB-bA) x wB).n / |n|^2, t = ((bB-bA) x wA).n / |n|^2 (no 1 - (wA.wB)^2). */
static void axis_feet(const query *q, double *s, double *t)
{
    prox_vec3 n = prox_v3_cross(q->A.w, q->B.w);
    double nn = prox_v3_norm2(n);
    prox_vec3 d0 = prox_v3_sub(q->B.b, q->A.b);
    *s = prox_v3_dot(prox_v3_cross(d0, q->B.w), n) / nn;
    *t = prox_v3_dot(prox_v3_cross(d0, q->A.w), n) / nn;
}

/* S-S candidate when both feet lie on the finite axes; an overlap witness when the axes are closer
 * than rA + rB there (the point between the feet at distance <= rA from A's axis, <= rB from B's). */
static void cand_lat_lat(query *q, double s, double t)
{
    if (s < 0.0 || s > q->A.h || t < 0.0 || t > q->B.h) return;
    prox_vec3 f1 = prox_v3_mad(q->A.b, s, q->A.w), f2 = prox_v3_mad(q->B.b, t, q->B.w);
    prox_vec3 u = prox_v3_sub(f2, f1);
    double L = prox_v3_norm(u);
    if (L <= q->A.r + q->B.r) {
        double lo = L - q->B.r > 0.0 ? L - q->B.r : 0.0, hi = q->A.r < L ? q->A.r : L;
        double a = 0.5 * (L + q->A.r - q->B.r);
        a = a < lo ? lo : (a > hi ? hi : a);
        note_common(q, L > 0.0 ? prox_v3_mad(f1, a / L, u) : f1);
        return;
    }
    u = prox_v3_scale(u, 1.0 / L);
    offer(q, prox_v3_mad(f1, q->A.r, u), prox_v3_mad(f2, -q->B.r, u), u, PROX_PAIR_SS, PROX_FEAT_LATERAL,
          PROX_FEAT_LATERAL);
}

/* ---- C-S: a rim of one cylinder against the lateral surface of the other (Sec. 3.3) ---- */

static prox_feature rim_feature(int end) { return end ? PROX_FEAT_RIM_TOP : PROX_FEAT_RIM_BASE; }
static prox_feature cap_feature(int end) { return end ? PROX_FEAT_TOP : PROX_FEAT_BASE; }

/* Rim `end` of cylinder `rc` against the lateral surface of `lc`; `rim_is_a` orders the output. */
static void cand_rim_lat(query *q, const cyl *rc, int end, const cyl *lc, int rim_is_a)
{
    double th[4];
    int cnt = 0;
    const prox_fcircle *C = &rc->rim[end];
    int constant = prox_circle_line_stationary(C, lc->b, lc->w, th, &cnt);
    if (constant) { /* the rim is coaxial with the other axis: every point is equivalent */
        th[0] = 0.0;
        cnt = 1;
    }
    for (int i = 0; i < cnt; ++i) {
        prox_vec3 x = prox_fcircle_point(C, th[i]);
        prox_vec3 dx = prox_v3_sub(x, lc->b);
        double t = prox_v3_dot(dx, lc->w);
        if (t < 0.0 || t > lc->h) continue;
        prox_vec3 radial = prox_v3_mad(dx, -t, lc->w);
        double rho = prox_v3_norm(radial);
        if (rho <= lc->r) {
            note_common(q, x);
            continue;
        }
        prox_vec3 u = prox_v3_scale(radial, 1.0 / rho); /* outward normal of lc at its closest point */
        prox_vec3 y = prox_v3_add(prox_v3_mad(lc->b, t, lc->w), prox_v3_scale(u, lc->r));
        if (rim_is_a)
            offer(q, x, y, prox_v3_neg(u), PROX_PAIR_CS, rim_feature(end), PROX_FEAT_LATERAL);
        else
            offer(q, y, x, u, PROX_PAIR_CS, PROX_FEAT_LATERAL, rim_feature(end));
    }
}

/* ---- C-D: a rim against the interior of the other cylinder's end disk (Sec. 3.4) ---- */

/* The rim's points extreme in the disk's normal direction project onto the disk plane; a projection
 * inside the disk gives a candidate.  Parallel planes: the rim point nearest the disk's axis. */
static void cand_rim_disk(query *q, const cyl *rc, int rend, const cyl *dc, int dend, int rim_is_a)
{
    const prox_fcircle *C = &rc->rim[rend];
    prox_vec3 m = dc->w, D = dc->cap[dend];
    double outward = dend ? 1.0 : -1.0; /* outward normal of the disk is outward * m */
    double mu = prox_v3_dot(m, C->u), mv = prox_v3_dot(m, C->v);
    double amp = hypot(mu, mv);
    prox_vec3 dirs[2];
    int nd;
    if (amp > 64.0 * DBL_EPSILON) { /* the two extreme points */
        prox_vec3 e = prox_v3_add(prox_v3_scale(C->u, mu / amp), prox_v3_scale(C->v, mv / amp));
        dirs[0] = e;
        dirs[1] = prox_v3_neg(e);
        nd = 2;
    } else { /* parallel faces: towards the disk's axis (any point if coaxial) */
        prox_vec3 g0 = prox_v3_sub(D, C->c);
        prox_vec3 g = prox_v3_reject(prox_v3_reject(g0, C->n), C->n); /* twice: no residual along n */
        double gl = prox_v3_norm(g);
        /* A radial offset at rounding level is noise in a random direction: any rim point is then as
         * good (coaxial faces), so take the frame's u. */
        dirs[0] = gl > 64.0 * DBL_EPSILON * (prox_v3_norm(g0) + C->r) ? prox_v3_scale(g, 1.0 / gl) : C->u;
        nd = 1;
    }
    for (int i = 0; i < nd; ++i) {
        prox_vec3 x = prox_v3_mad(C->c, C->r, dirs[i]);
        double g = prox_v3_dot(prox_v3_sub(x, D), m);
        prox_vec3 y = prox_v3_mad(x, -g, m);
        if (prox_v3_dist(y, D) > dc->r) continue;
        prox_vec3 nB = prox_v3_scale(m, outward); /* outward normal of dc's face */
        if (rim_is_a)
            offer(q, x, y, prox_v3_neg(nB), PROX_PAIR_CD, rim_feature(rend), cap_feature(dend));
        else
            offer(q, y, x, nB, PROX_PAIR_CD, cap_feature(dend), rim_feature(rend));
    }
}

/* ---- C-C: rim against rim (Sec. 3.5, degree 8) ---- */

static prox_status cand_rim_rim(query *q, int ea, int eb)
{
    const prox_fcircle *CA = &q->A.rim[ea], *CB = &q->B.rim[eb];
    double th[8];
    int cnt = 0;
    int rc = prox_circle_circle_stationary(CA, CB, th, &cnt);
    if (rc < 0) return (prox_status)(-rc);
    if (rc == 1) { /* coaxial rims: every point is equivalent */
        th[0] = 0.0;
        cnt = 1;
    }
    for (int i = 0; i < cnt; ++i) {
        prox_vec3 x = prox_fcircle_point(CA, th[i]);
        prox_vec3 y = prox_fcircle_closest(CB, x, NULL);
        /* Normal from the two tangents (accurate when |y - x| is tiny); else from the points. */
        prox_vec3 ta = prox_v3_add(prox_v3_scale(CA->u, -sin(th[i])), prox_v3_scale(CA->v, cos(th[i])));
        prox_vec3 tb = prox_v3_cross(CB->n, prox_v3_sub(y, CB->c));
        prox_vec3 n = prox_v3_cross(ta, tb);
        double nl = prox_v3_norm(n), tbl = prox_v3_norm(tb);
        prox_vec3 yx = prox_v3_sub(y, x);
        if (nl > 1e-6 * tbl) {
            n = prox_v3_scale(n, 1.0 / nl);
            if (prox_v3_dot(n, yx) < 0.0) n = prox_v3_neg(n);
        } else {
            n = prox_v3_normalize(yx);
        }
        offer(q, x, y, n, PROX_PAIR_CC, rim_feature(ea), rim_feature(eb));
    }
    return PROX_OK;
}

/* ---- certificates and lower bounds ---- */

/* 1 when the best candidate is proven optimal: gap along its normal (or along p2 - p1) matches. */
static int certified(const query *q, double *gap_out)
{
    if (!q->have_best) return 0;
    double g = gap_along(q, q->best.n);
    if (q->best.d > 0.0) {
        double g2 = gap_along(q, prox_v3_scale(prox_v3_sub(q->best.p2, q->best.p1), 1.0 / q->best.d));
        if (g2 > g) g = g2;
    }
    *gap_out = g;
    return g >= q->best.d - q->eps;
}

/* Lower bound on the distance between rim circles: centre distance minus radii, and the range of
 * one circle's heights over the other's plane (half-width r sqrt(1 - (wA.wB)^2) = r |wA x wB|). */
static double rim_rim_lower_bound(const query *q, int ea, int eb)
{
    const prox_fcircle *CA = &q->A.rim[ea], *CB = &q->B.rim[eb];
    prox_vec3 d = prox_v3_sub(CB->c, CA->c);
    double lb = prox_v3_norm(d) - CA->r - CB->r;
    double sn = prox_v3_norm(prox_v3_cross(CA->n, CB->n));
    double hb = fabs(prox_v3_dot(d, CA->n)) - CB->r * sn; /* B's rim above/below A's rim plane */
    double ha = fabs(prox_v3_dot(d, CB->n)) - CA->r * sn;
    if (hb > lb) lb = hb;
    if (ha > lb) lb = ha;
    return lb;
}

/* Lower bound for a rim against the other lateral surface: distance from the rim's centre to the
 * other axis line minus both radii (the surface lies within r of its axis). */
static double rim_lat_lower_bound(const prox_fcircle *C, const cyl *lc)
{
    prox_vec3 d = prox_v3_sub(C->c, lc->b);
    double rho = prox_v3_norm(prox_v3_mad(d, -prox_v3_dot(d, lc->w), lc->w));
    return rho - C->r - lc->r;
}

/* ---- containment (Agarwal Fig. 2), exact ---- */

/* 1 when circle C lies in the closed solid cylinder k (within tol): its axial range within [0, h]
 * and its farthest point from k's axis (a stationary point of the circle-line distance) within r. */
static int circle_in_cyl(const prox_fcircle *C, const cyl *k, double tol)
{
    double tc = prox_v3_dot(prox_v3_sub(C->c, k->b), k->w);
    double half = C->r * prox_v3_norm(prox_v3_cross(C->n, k->w));
    if (tc - half < -tol || tc + half > k->h + tol) return 0;
    double th[4];
    int cnt = 0;
    if (prox_circle_line_stationary(C, k->b, k->w, th, &cnt)) {
        th[0] = 0.0;
        cnt = 1;
    }
    for (int i = 0; i < cnt; ++i) {
        prox_vec3 d = prox_v3_sub(prox_fcircle_point(C, th[i]), k->b);
        if (prox_v3_norm(prox_v3_mad(d, -prox_v3_dot(d, k->w), k->w)) > k->r + tol) return 0;
    }
    return 1;
}

static int cyl_in_cyl(const cyl *in, const cyl *out, double tol)
{
    return circle_in_cyl(&in->rim[0], out, tol) && circle_in_cyl(&in->rim[1], out, tol);
}

/* ---- overlap search ---- */

/* Alternating projections between the solids starting from x: returns 1 with a common point when
 * the iterates enter both solids (the solids overlap), 0 otherwise. */
static int find_common_point(query *q, prox_vec3 x, int iters, prox_vec3 *last)
{
    prox_rcc a = cyl_as_rcc(&q->A), b = cyl_as_rcc(&q->B);
    for (int i = 0; i < iters; ++i) {
        x = prox_rcc_closest_point(&a, x);
        if (cyl_contains(&q->B, x, 0.0)) {
            note_common(q, x);
            return 1;
        }
        x = prox_rcc_closest_point(&b, x);
        if (cyl_contains(&q->A, x, 0.0)) {
            note_common(q, x);
            return 1;
        }
    }
    *last = x;
    return 0;
}

/* ---- the hierarchy and the complete search ---- */

/* End of a cylinder nearest to the axial parameter t (Agarwal: "the disk closest to the point"). */
static int nearest_end(double t, double h) { return t > 0.5 * h; }

/* Agarwal's first level (Fig. 3): the case from the feet of P(S1,S2), and its candidates. */
static prox_agarwal_case hierarchy(query *q, int *ea, int *eb)
{
    double s = 0.5 * q->A.h, t = 0.5 * q->B.h;
    prox_agarwal_case cs = PROX_CASE_NONE;
    if (!q->parallel) {
        axis_feet(q, &s, &t);
        int on1 = s >= 0.0 && s <= q->A.h, on2 = t >= 0.0 && t <= q->B.h;
        cs = on1 && on2 ? PROX_CASE_1 : (on1 || on2 ? PROX_CASE_2_1 : PROX_CASE_3);
        cand_lat_lat(q, s, t);
    }
    *ea = nearest_end(s, q->A.h);
    *eb = nearest_end(t, q->B.h);
    if (cs == PROX_CASE_1 && q->have_best) return cs;
    /* Case 2/3: disk-axis then disk-disk through disk-circle (Figs. 4, 5) at the nearest ends. */
    cand_rim_lat(q, &q->B, *eb, &q->A, 0);
    cand_rim_lat(q, &q->A, *ea, &q->B, 1);
    cand_rim_disk(q, &q->A, *ea, &q->B, *eb, 1);
    cand_rim_disk(q, &q->B, *eb, &q->A, *ea, 0);
    return cs;
}

/* Every remaining candidate group, skipping groups whose lower bound cannot beat the best. */
static prox_status complete_search(query *q, int ea0, int eb0, int rr_done)
{
    for (int e = 0; e < 2; ++e) {
        if (e != eb0 && (!q->have_best || rim_lat_lower_bound(&q->B.rim[e], &q->A) < q->best.d))
            cand_rim_lat(q, &q->B, e, &q->A, 0);
        if (e != ea0 && (!q->have_best || rim_lat_lower_bound(&q->A.rim[e], &q->B) < q->best.d))
            cand_rim_lat(q, &q->A, e, &q->B, 1);
    }
    for (int ea = 0; ea < 2; ++ea)
        for (int eb = 0; eb < 2; ++eb) {
            if (ea == ea0 && eb == eb0) continue;
            cand_rim_disk(q, &q->A, ea, &q->B, eb, 1);
            cand_rim_disk(q, &q->B, eb, &q->A, ea, 0);
        }
    for (int k = 0; k < 4; ++k) { /* nearest ends first: they most often hold the minimum */
        int ea = k < 2 ? ea0 : !ea0, eb = (k % 2) == 0 ? eb0 : !eb0;
        if (rr_done && ea == ea0 && eb == eb0) continue;
        if (q->have_best && rim_rim_lower_bound(q, ea, eb) >= q->best.d) continue;
        prox_status st = cand_rim_rim(q, ea, eb);
        if (st != PROX_OK) return st;
    }
    return PROX_OK;
}

static void fill_overlap(const query *q, prox_rcc_result *res, prox_vec3 origin)
{
    res->distance = 0.0;
    res->p1 = res->p2 = prox_v3_add(q->common, origin);
    res->pair = PROX_PAIR_OVERLAP;
    res->feature1 = res->feature2 = PROX_FEAT_INSIDE;
    res->interfere = 1;
    res->certificate_gap = 0.0;
}

/* Decides containment and, for nested pairs, reports the inner centre as the common point. */
static void containment(query *q, prox_rcc_result *res)
{
    double tol = 0.0;
    if (cyl_contains(&q->B, q->A.c, tol)) res->a_in_b = cyl_in_cyl(&q->A, &q->B, tol);
    if (cyl_contains(&q->A, q->B.c, tol)) res->b_in_a = cyl_in_cyl(&q->B, &q->A, tol);
    if (res->a_in_b) q->common = q->A.c;
    else if (res->b_in_a) q->common = q->B.c;
}

/* Flags a positive-dimensional set of proximal points: parallel axes with a side contact, or
 * parallel faces whose projections overlap in more than a point (Agarwal Fig. 9 (b), (d), (e)). */
static int is_point_set(const query *q)
{
    const cand *b = &q->best;
    double sn = prox_v3_norm(prox_v3_cross(q->A.w, q->B.w));
    if (b->kind == PROX_PAIR_CD && sn <= 1e-12) {
        const cyl *rc = b->f1 == PROX_FEAT_RIM_BASE || b->f1 == PROX_FEAT_RIM_TOP ? &q->A : &q->B;
        const cyl *dc = rc == &q->A ? &q->B : &q->A;
        prox_vec3 g = prox_v3_reject(prox_v3_sub(dc->c, rc->c), rc->w);
        return prox_v3_norm(g) < rc->r + dc->r - q->eps; /* the face projections share an area */
    }
    if ((b->kind == PROX_PAIR_CS || b->kind == PROX_PAIR_SS) && sn <= 1e-12) {
        /* axial overlap of the two lateral surfaces, measured along A's axis */
        double t0 = prox_v3_dot(prox_v3_sub(q->B.b, q->A.b), q->A.w);
        double t1 = t0 + q->B.h * prox_v3_dot(q->B.w, q->A.w);
        double lo = fmax(0.0, fmin(t0, t1)), hi = fmin(q->A.h, fmax(t0, t1));
        return hi - lo > q->eps;
    }
    return b->kind == PROX_PAIR_CC && sn <= 1e-12 &&
           prox_v3_norm(prox_v3_reject(prox_v3_sub(q->B.c, q->A.c), q->A.w)) <= q->eps;
}

PROX_API prox_rcc_result prox_rcc_distance(const prox_rcc *a, const prox_rcc *b)
{
    prox_rcc_result res = {0};
    if ((res.status = prox_rcc_validate(a)) != PROX_OK) return res;
    if ((res.status = prox_rcc_validate(b)) != PROX_OK) return res;

    prox_vec3 origin = prox_v3_mad(a->base, 0.5, a->axis);
    query q;
    q.A = cyl_make(a, origin);
    q.B = cyl_make(b, origin);
    q.scale = prox_rcc_pair_scale(a, b);
    q.eps = 64.0 * DBL_EPSILON * q.scale;
    q.have_best = 0;
    q.overlap = 0;
    q.parallel = prox_v3_norm2(prox_v3_cross(q.A.w, q.B.w)) <= 1e-30;

    /* Cheap overlap witnesses first: either centre inside the other solid. */
    if (cyl_contains(&q.B, q.A.c, 0.0)) note_common(&q, q.A.c);
    else if (cyl_contains(&q.A, q.B.c, 0.0)) note_common(&q, q.B.c);

    int ea, eb;
    res.agarwal = hierarchy(&q, &ea, &eb);
    double gap = -INFINITY;
    int ok = !q.overlap && certified(&q, &gap);
    res.hierarchy_exact = ok;
    if (!ok && !q.overlap) { /* the hierarchy's pair of nearest rims, then everything else */
        if ((res.status = cand_rim_rim(&q, ea, eb)) != PROX_OK) return res;
        ok = !q.overlap && certified(&q, &gap);
        if (ok) res.hierarchy_exact = 1;
    }
    if (!ok && !q.overlap) {
        if ((res.status = complete_search(&q, ea, eb, 1)) != PROX_OK) return res;
        ok = !q.overlap && certified(&q, &gap);
    }
    prox_vec3 last = q.A.c;
    if (!ok && !q.overlap && q.have_best) /* not certified: look for a common point */
        find_common_point(&q, prox_v3_scale(prox_v3_add(q.best.p1, q.best.p2), 0.5), 200, &last);
    if (!q.overlap && !q.have_best) { /* no candidate at all: only possible when overlapping */
        if (!find_common_point(&q, q.A.c, 1000, &last)) note_common(&q, last); /* touching limit */
    }

    if (q.overlap) {
        containment(&q, &res);
        fill_overlap(&q, &res, origin);
        return res;
    }
    if (res.agarwal == PROX_CASE_2_1 && q.best.kind != PROX_PAIR_CS && q.best.kind != PROX_PAIR_SS)
        res.agarwal = PROX_CASE_2_2; /* the foot of P(D, z) fell beyond the axis segment (Fig. 7 (b)) */
    res.distance = q.best.d;
    res.p1 = prox_v3_add(q.best.p1, origin);
    res.p2 = prox_v3_add(q.best.p2, origin);
    res.pair = q.best.kind;
    res.feature1 = q.best.f1;
    res.feature2 = q.best.f2;
    res.certificate_gap = gap;
    res.point_set = is_point_set(&q);
    return res;
}
