/* PROX_METHOD_CLOSED_FORM: exact minimum distance of two solid right circular cylinders by Agarwal's
 * complete primitive decomposition, every stationary point of every feature pair, with no prediction
 * and no pruning (docs/algorithms/closed_form.md).
 *
 * Source: Agarwal, Srivatsan & Bandyopadhyay, "Analytical determination of the proximity of two
 * right-circular cylinders in space", J. Mech. Robot. 8 (2016), Sec. 2 and 3.
 *
 *  1. Both cylinders are validated and prepared (core/cyl.h) relative to A's centre, so that pairs far
 *     from the origin keep their relative precision; result points are translated back.
 *  2. Candidates. For two disjoint convex solids the closest pair lies on a pair of features (lateral
 *     surface S, end-disk interior D, rim circle C) at which the distance is stationary:
 *       S-S  the common perpendicular of the axes when both feet are on the finite axes (Sec. 3.1,
 *            Eq. (13) case (a)); parallel axes have a set of such pairs, which always contains a rim
 *            point and so is held by C-S;
 *       C-S  every stationary point of a rim's distance to the other axis (Sec. 3.3, Eq. (16) and the
 *            quartic g2), for the 4 rim / lateral-surface pairs;
 *       C-D  the rim points extreme along the other disk's normal (Sec. 3.4: the stationary points of
 *            the height over the disk plane), projected into the disk, for the 8 rim / disk pairs;
 *            plus the rim point towards the disk's centre (parallel planes, Eq. (18)) and the rim's
 *            crossings of the disk plane (overlap witnesses);
 *       C-C  every stationary point of the degree-8 polynomial g3 of Sec. 3.5 for the 4 rim pairs, both
 *            ways round, rooted by GSL's companion-matrix QR (PROX_ROOTS_GSL).
 *     D-D and D-S contacts (parallel faces, perpendicular axes, Eqs. (9), (15)) are sets whose minimum
 *     is also attained at a C-D or C-S candidate. Every candidate is a genuine pair of points of A x B,
 *     so the minimum over the candidates is the distance exactly: a spurious candidate can only lose.
 *     A C-S foot beyond the other axis, or a C-D projection beyond the disk, is pulled back onto the
 *     feature's end: still a genuine pair, and its exact normal certifies contacts at the very edge.
 *  3. Certificate: along the contact normal n of the best candidate and of those tied with it (and
 *     along p2 - p1) the projections of A and B are gap(n) = -h_B(-n) - h_A(n) apart (Eberly's support
 *     function), and gap(n) <= distance <= |p2 - p1| by weak duality; the kinks of the support
 *     functions next to n (n perpendicular to an axis or along it) are evaluated too. The distance is
 *     certified positive when the bound exceeds PROX_TOL_CERT S and is within PROX_TOL_CERT S of d.
 *  4. Overlap (or touching within PROX_TOL_CERT S): when no candidate certifies a positive distance,
 *     a common point is searched (candidate points lying in the other solid, the point between the axes
 *     on the S-S segment, the centres, then prox_cyl_common_point) and checked in both solids;
 *     containment is decided exactly (A lies in B iff both rims of A do). */
#include <stddef.h>

#include "core/circle.h"
#include "core/cyl.h"
#include "core/poly.h"
#include "core/tol.h"
#include "distance/rcc_methods.h"

/* Upper bound on the number of candidates: S-S 1, C-S 4 x 4, C-D 8 x 3, C-C 4 x 2 x 8. */
#define CF_MAX_CANDS 128
/* Douglas-Rachford steps per margin of the overlap search. */
#define CF_DR_ITERS 200

/* One candidate pair of points (p1 on A, p2 on B) and the contact normal its feature pair defines. */
typedef struct cf_cand {
    double d;
    prox_vec3 p1, p2, n; /* n: unit, from A towards B */
    prox_pair_kind kind;
    prox_feature f1, f2;
} cf_cand;

/* Query state: the prepared cylinders (k[0] = A, k[1] = B) and their rims, the candidates, and the
 * overlap witness. */
typedef struct cf_query {
    prox_cyl k[2];
    prox_fcircle rim[2][2]; /* rim[i][end]: end 0 base, 1 top */
    double scale, eps;      /* S (tests/data/README.md) and PROX_TOL_CERT S */
    cf_cand cand[CF_MAX_CANDS];
    int ncand;
    int have_common;
    prox_vec3 common;
} cf_query;

/* gap(n) = -h_B(-n) - h_A(n) along unit n: a lower bound on the distance (weak duality). */
static double cf_gap(const cf_query *q, prox_vec3 n) { return prox_cyl_gap(&q->k[0], &q->k[1], n); }

static prox_feature rim_feature(int end) { return end ? PROX_FEAT_RIM_TOP : PROX_FEAT_RIM_BASE; }
static prox_feature cap_feature(int end) { return end ? PROX_FEAT_TOP : PROX_FEAT_BASE; }

/* Records x as a common point when it lies in both solids (within eps: a point that close to both is
 * at worst a touching contact). Every overlap claim goes through this check. */
static void note_common(cf_query *q, prox_vec3 x)
{
    if (q->have_common || !prox_cyl_contains(&q->k[0], x, q->eps) || !prox_cyl_contains(&q->k[1], x, q->eps))
        return;
    q->have_common = 1;
    q->common = x;
}

/* Adds the candidate (p1 in A, p2 in B, unit normal n from A to B); a point lying in the other solid
 * is an overlap witness. A candidate whose distance is not finite (overflow) is dropped. */
static void offer(cf_query *q, prox_vec3 p1, prox_vec3 p2, prox_vec3 n, prox_pair_kind kind, prox_feature f1,
                  prox_feature f2)
{
    if (prox_cyl_contains(&q->k[1], p1, 0.0)) note_common(q, p1);
    if (prox_cyl_contains(&q->k[0], p2, 0.0)) note_common(q, p2);
    double d = prox_v3_dist(p1, p2);
    if (!(d < INFINITY) || q->ncand >= CF_MAX_CANDS) return;
    q->cand[q->ncand++] = (cf_cand){d, p1, p2, n, kind, f1, f2};
}

/* offer() for a pair generated from cylinder `own` (x on own, y on the other, n from x towards y). */
static void offer_from(cf_query *q, int own, prox_vec3 x, prox_vec3 y, prox_vec3 n, prox_pair_kind kind,
                       prox_feature fx, prox_feature fy)
{
    if (own == 0) offer(q, x, y, n, kind, fx, fy);
    else offer(q, y, x, prox_v3_neg(n), kind, fy, fx);
}

/* ---- S-S: the common perpendicular of the axes (Sec. 3.1, Eq. (13) case (a)) ---- */

/* The S-S candidate when both feet of the common perpendicular lie on the finite axes, or an overlap
 * witness when the axes are closer than rA + rB there; returns Agarwal's case of the feet (Fig. 3).
 * Exactly parallel axes have no isolated S-S pair: their contacts are C-S candidates (a rim of one
 * lies in the other's axial range whenever the ranges overlap). */
static prox_agarwal_case cf_lat_lat(cf_query *q)
{
    const prox_cyl *A = &q->k[0], *B = &q->k[1];
    prox_vec3 nab = prox_v3_cross(A->w, B->w);
    double nn = prox_v3_norm2(nab);
    if (!(nn > 0.0)) return PROX_CASE_NONE;
    /* feet s on A's axis, t on B's: s = ((bB - bA) x wB).n / |n|^2, t = ((bB - bA) x wA).n / |n|^2 */
    prox_vec3 d0 = prox_v3_sub(B->b, A->b);
    double s = prox_v3_dot(prox_v3_cross(d0, B->w), nab) / nn, t = prox_v3_dot(prox_v3_cross(d0, A->w), nab) / nn;
    int on1 = s >= 0.0 && s <= A->h, on2 = t >= 0.0 && t <= B->h;
    prox_agarwal_case cs = nn <= PROX_TOL_PARALLEL * PROX_TOL_PARALLEL
                               ? PROX_CASE_NONE
                               : (on1 && on2 ? PROX_CASE_1 : (on1 || on2 ? PROX_CASE_2_1 : PROX_CASE_3));
    if (!(on1 && on2)) return cs;
    prox_vec3 f1 = prox_v3_mad(A->b, s, A->w), f2 = prox_v3_mad(B->b, t, B->w);
    prox_vec3 u = prox_v3_sub(f2, f1);
    double L = prox_v3_norm(u);
    if (L <= A->r + B->r) { /* the point dividing f1 f2 in the ratio rA : rB is in both */
        note_common(q, prox_v3_mad(f1, A->r / (A->r + B->r), u));
        return cs;
    }
    u = prox_v3_scale(u, 1.0 / L);
    if (nn >= PROX_TOL_WELL_COND2) { /* well-conditioned feet: the unit common normal from wA x wB */
        prox_vec3 v = prox_v3_scale(nab, (prox_v3_dot(u, nab) < 0.0 ? -1.0 : 1.0) / sqrt(nn));
        offer(q, prox_v3_mad(f1, A->r, v), prox_v3_mad(f2, -B->r, v), v, PROX_PAIR_SS, PROX_FEAT_LATERAL,
              PROX_FEAT_LATERAL);
        return cs;
    }
    /* Near-parallel axes: the feet are inaccurate along the axes (~ eps S / |wA x wB|, which moves the
     * distance only to second order), and a normal not perpendicular to an axis costs h |n.w| / 2 in
     * the certificate. So the normal is made perpendicular to both axes to rounding (alternate
     * rejections), the axes' offset is measured along it, and B's point put on that normal from A's
     * foot: it is off B's axis by only (foot error) x |wA x wB| ~ eps S. */
    prox_vec3 v = prox_v3_reject(prox_v3_reject(prox_v3_reject(u, A->w), B->w), A->w);
    double vl = prox_v3_norm(v);
    if (vl > 0.5) {
        v = prox_v3_scale(v, 1.0 / vl);
        double lv = prox_v3_dot(d0, v);
        prox_vec3 p2 = prox_v3_mad(f1, lv - B->r, v);
        double tp = prox_v3_dot(prox_v3_sub(p2, B->b), B->w);
        if (lv > A->r + B->r && tp >= 0.0 && tp <= B->h) {
            offer(q, prox_v3_mad(f1, A->r, v), p2, v, PROX_PAIR_SS, PROX_FEAT_LATERAL, PROX_FEAT_LATERAL);
            return cs;
        }
    }
    offer(q, prox_v3_mad(f1, A->r, u), prox_v3_mad(f2, -B->r, u), u, PROX_PAIR_SS, PROX_FEAT_LATERAL,
          PROX_FEAT_LATERAL);
    return cs;
}

/* ---- C-S: a rim against the other lateral surface (Sec. 3.3) ---- */

/* The quartic of a rim against a line overflows only when the rim's distance from the line is ~1e100
 * times its radius or more (prox_circle_line_stationary): the distance then varies over the rim by
 * at most 2r <= 1e-90 S, so the rim stands in for a point. Its candidates are the rim points nearest
 * to and farthest from the line, along the line's perpendicular through the centre, projected into
 * the rim's plane (any pair of opposite points when that projection vanishes); each is a genuine
 * point of the rim, and the certificate judges the answer as for any other candidate. */
static int cf_rim_far_points(const prox_fcircle *C, const prox_cyl *lc, prox_unit2 a[4])
{
    prox_vec3 e = prox_cyl_perp(lc, prox_v3_sub(C->c, lc->b));
    double du = prox_v3_dot(e, C->u), dv = prox_v3_dot(e, C->v);
    double m = fmax(fabs(du), fabs(dv));
    if (!(m > 0.0) || !isfinite(m)) du = 1.0, dv = 0.0, m = 1.0;
    a[0] = prox_unit2_of(du / m, dv / m);
    a[1] = (prox_unit2){-a[0].c, -a[0].s};
    return 2;
}

/* Every stationary angle of the rim's squared distance to the other axis (Eq. (16) eliminates the
 * axial parameter, the half-angle substitution gives the quartic g2; prox_circle_line_stationary).
 * A stationary point whose foot lies on the finite axis gives the rim point and its closest point of
 * the lateral surface; a rim point within the other radius there is a common point. A foot beyond
 * the axis gives the pair with the surface point at the nearer end (on its rim, so a rim pair): a
 * genuine pair, never shorter than the distance, whose radial normal certifies contacts at the very
 * end of the side (a foot just beyond it by rounding, rims flush with the other's end). */
static prox_status cf_rim_lat(cf_query *q, int own, int end)
{
    const prox_fcircle *C = &q->rim[own][end];
    const prox_cyl *lc = &q->k[1 - own];
    double th[4];
    prox_unit2 a[4] = {{1.0, 0.0}}; /* rim coaxial with the other axis: every point is equivalent */
    int cnt = 0;
    int rc = prox_circle_line_stationary(C, lc->b, lc->w, th, &cnt);
    if (rc < 0) cnt = cf_rim_far_points(C, lc, a); /* the quartic overflows: the rim is a point */
    else if (rc == 1) cnt = 1;
    else
        for (int i = 0; i < cnt; ++i) a[i] = (prox_unit2){cos(th[i]), sin(th[i])};
    for (int i = 0; i < cnt; ++i) {
        prox_vec3 x = prox_fcircle_at(C, a[i]);
        prox_vec3 dx = prox_v3_sub(x, lc->b);
        double t = prox_v3_dot(dx, lc->w), tc = fmin(fmax(t, 0.0), lc->h);
        prox_vec3 radial = prox_cyl_perp(lc, dx); /* rejected twice: the normal is perpendicular to w */
        double rho = prox_v3_norm(radial);
        if (rho <= lc->r) { /* inside the other radius: a common point, or a C-D contact beyond the end */
            if (t == tc) note_common(q, x);
            continue;
        }
        prox_vec3 un = prox_v3_scale(radial, 1.0 / rho); /* outward normal of the surface at y */
        prox_vec3 y = prox_v3_mad(prox_v3_mad(lc->b, tc, lc->w), lc->r, un);
        if (t == tc) offer_from(q, own, x, y, prox_v3_neg(un), PROX_PAIR_CS, rim_feature(end), PROX_FEAT_LATERAL);
        else offer_from(q, own, x, y, prox_v3_neg(un), PROX_PAIR_CC, rim_feature(end), rim_feature(tc > 0.0));
    }
    return PROX_OK;
}

/* ---- C-D: a rim against the interior of the other cylinder's end disk (Sec. 3.4) ---- */

/* Offers the rim point x with its projection y on the disk plane (unit normal m, centre D); a
 * projection beyond the disk (radius rd) is pulled back onto the disk's rim, which keeps the pair
 * genuine (then a rim pair) and its normal m (the contact at the very edge of the disk, beyond it by
 * rounding). */
static void cf_rim_disk_point(cf_query *q, int own, int rend, int dend, prox_vec3 x, prox_vec3 m, prox_vec3 D,
                              double rd)
{
    double g = prox_v3_dot(prox_v3_sub(x, D), m);
    prox_vec3 y = prox_v3_mad(x, -g, m), yd = prox_v3_sub(y, D);
    double l = prox_v3_norm(yd);
    int edge = l > rd; /* then y is on the disk's rim: a rim pair */
    if (edge) y = prox_v3_mad(D, rd / l, yd);
    offer_from(q, own, x, y, g > 0.0 ? prox_v3_neg(m) : m, edge ? PROX_PAIR_CC : PROX_PAIR_CD, rim_feature(rend),
               edge ? rim_feature(dend) : cap_feature(dend));
}

/* Rim `rend` of cylinder `own` against disk `dend` of the other. The height of a rim point over the disk
 * plane is hc + r amp cos(phi) (phi measured from e, the rim-plane direction of the disk normal): its
 * stationary points are the two extreme points c +- r e, whose projections are the candidates where
 * they fall in the disk (the s1 in [0, 1] test after Eq. (17)). Parallel planes (amp = 0, Eq. (18)):
 * the height is constant and the rim point towards the disk's centre is the one whose projection lies
 * in the disk when any does; it is offered always (a genuine pair, harmless when not the minimum).
 * Where the rim crosses the plane (|hc| <= r amp) inside the disk, the crossing is a common point. */
static void cf_rim_disk(cf_query *q, int own, int rend, int dend)
{
    const prox_fcircle *C = &q->rim[own][rend];
    const prox_cyl *dc = &q->k[1 - own];
    prox_vec3 m = dc->w, D = dc->cap[dend];
    double mu = prox_v3_dot(m, C->u), mv = prox_v3_dot(m, C->v), amp = prox_hypot2(mu, mv);
    prox_vec3 g0 = prox_v3_sub(D, C->c);
    prox_vec3 g = prox_v3_reject(prox_v3_reject(g0, C->n), C->n); /* twice: no residual along n */
    double gl = prox_v3_norm(g);
    /* a radial offset at rounding level has no direction (coaxial faces): any rim point serves */
    prox_vec3 towards = gl > PROX_TOL_NOISE * (prox_v3_norm(g0) + C->r) ? prox_v3_scale(g, 1.0 / gl) : C->u;
    cf_rim_disk_point(q, own, rend, dend, prox_v3_mad(C->c, C->r, towards), m, D, dc->r);
    if (!(amp > 0.0)) return;
    prox_vec3 e = prox_v3_add(prox_v3_scale(C->u, mu / amp), prox_v3_scale(C->v, mv / amp));
    cf_rim_disk_point(q, own, rend, dend, prox_v3_mad(C->c, C->r, e), m, D, dc->r);
    cf_rim_disk_point(q, own, rend, dend, prox_v3_mad(C->c, -C->r, e), m, D, dc->r);
    double hc = prox_v3_dot(prox_v3_sub(C->c, D), m), ra = C->r * amp;
    if (!(fabs(hc) <= ra)) return;
    double cphi = -hc / ra, sphi = sqrt(fmax(0.0, 1.0 - cphi * cphi));
    prox_vec3 e2 = prox_v3_cross(C->n, e);
    for (int sg = -1; sg <= 1; sg += 2) {
        prox_vec3 x = prox_v3_mad(prox_v3_mad(C->c, C->r * cphi, e), sg * C->r * sphi, e2);
        if (prox_v3_dist(prox_v3_mad(x, -prox_v3_dot(prox_v3_sub(x, D), m), m), D) <= dc->r) note_common(q, x);
    }
}

/* ---- C-C: rim against rim (Sec. 3.5, degree 8) ---- */

/* Contact normal of a rim pair (x at unit angle a on CA, y its closest point on CB): of the
 * directions below, the one along which the solids' projections are farthest apart (the certificate's
 * gap). At a stationary pair y - x is perpendicular to both rim tangents ta, tb, and the candidates are
 *  - y - x itself: its direction error is eps S / d, harmless when the points are well apart;
 *  - ta x tb: exact as the points meet, when the tangents are not parallel;
 *  - y - x with its component along ta (or tb) removed: when the tangents are (nearly) parallel, as
 *    for nearly coplanar rims touching side by side, the optimal normals fill the plane perpendicular
 *    to the tangent, the gap is linear in n there, and only the error along the tangent, which the
 *    rejection removes, costs more than second order. */
static prox_vec3 cf_rim_rim_normal(const cf_query *q, const prox_fcircle *CA, const prox_fcircle *CB, prox_unit2 a,
                                   prox_vec3 x, prox_vec3 y, int own)
{
    prox_vec3 yx = prox_v3_sub(y, x);
    prox_vec3 ta = prox_v3_add(prox_v3_scale(CA->u, -a.s), prox_v3_scale(CA->v, a.c));
    prox_vec3 tb = prox_v3_normalize(prox_v3_cross(CB->n, prox_v3_sub(y, CB->c)));
    prox_vec3 dirs[4] = {yx, prox_v3_cross(ta, tb), prox_v3_reject(yx, ta), prox_v3_reject(yx, tb)};
    prox_vec3 best = prox_v3_normalize(yx);
    double gbest = -INFINITY;
    for (int i = 0; i < 4; ++i) {
        double l = prox_v3_norm(dirs[i]);
        if (!(l > 0.0)) continue;
        prox_vec3 n = prox_v3_scale(dirs[i], (prox_v3_dot(dirs[i], yx) < 0.0 ? -1.0 : 1.0) / l);
        double g = own == 0 ? cf_gap(q, n) : cf_gap(q, prox_v3_neg(n)); /* gap is measured from A to B */
        if (g > gbest) gbest = g, best = n;
    }
    return best;
}

/* 1 when the degree-8 polynomial of CA against CB can be formed in CA's normalised frame without
 * overflow (PROX_CC_RANGE). */
static int cf_rim_rim_formable(const prox_fcircle *CA, const prox_fcircle *CB)
{
    return prox_v3_dist(CA->c, CB->c) + CA->r + CB->r <= PROX_CC_RANGE * CA->r;
}

/* Every stationary angle on rim `ea` of cylinder `own` of its distance to rim `eb` of the other (the
 * partner of a point is its closest point on the other rim: for fixed x the distance to a circle has
 * one local minimum), from the real roots of the degree-8 polynomial found by GSL. Each jointly
 * stationary pair that can be the closest one appears in the list of either rim, so a rim too small to
 * form its polynomial (cf_rim_rim_formable) is left to the other direction. */
static prox_status cf_rim_rim(cf_query *q, int own, int ea, int eb)
{
    const prox_fcircle *CA = &q->rim[own][ea], *CB = &q->rim[1 - own][eb];
    double th[8];
    int cnt = 0;
    if (!cf_rim_rim_formable(CA, CB)) return PROX_OK;
    int rc = prox_circle_circle_stationary(CA, CB, PROX_ROOTS_GSL, th, &cnt);
    if (rc < 0) return PROX_ENUMERIC; /* any failure to root the polynomial */
    if (rc == 1) { /* coaxial rims: every point is equivalent */
        th[0] = 0.0;
        cnt = 1;
    }
    for (int i = 0; i < cnt; ++i) {
        prox_unit2 a = {cos(th[i]), sin(th[i])};
        prox_vec3 x = prox_fcircle_at(CA, a);
        prox_vec3 y = prox_fcircle_closest(CB, x, NULL);
        offer_from(q, own, x, y, cf_rim_rim_normal(q, CA, CB, a, x, y, own), PROX_PAIR_CC, rim_feature(ea),
                   rim_feature(eb));
    }
    return PROX_OK;
}

/* Both rims smaller than 1e-64 of their distance (no polynomial can be formed): each is a point to
 * within that, so A's rim point towards B's rim centre and its closest point of B's rim stand for the
 * pair, within 2 (rA + rB) <= 1e-63 S of its minimum. */
static void cf_rim_rim_points(cf_query *q, int ea, int eb)
{
    const prox_fcircle *CA = &q->rim[0][ea], *CB = &q->rim[1][eb];
    prox_vec3 g = prox_v3_reject(prox_v3_sub(CB->c, CA->c), CA->n);
    double gl = prox_v3_norm(g);
    prox_vec3 x = prox_v3_mad(CA->c, CA->r, gl > 0.0 ? prox_v3_scale(g, 1.0 / gl) : CA->u);
    prox_vec3 y = prox_fcircle_closest(CB, x, NULL);
    offer(q, x, y, prox_v3_normalize(prox_v3_sub(y, x)), PROX_PAIR_CC, rim_feature(ea), rim_feature(eb));
}

/* ---- the enumeration ---- */

/* Every feature pair: S-S, the 4 rim / lateral-surface pairs, the 8 rim / disk pairs, the 4 rim pairs
 * (each solved from both rims). *cs receives Agarwal's case of the feet. */
static prox_status cf_enumerate(cf_query *q, prox_agarwal_case *cs)
{
    *cs = cf_lat_lat(q);
    for (int own = 0; own < 2; ++own)
        for (int end = 0; end < 2; ++end) {
            prox_status st = cf_rim_lat(q, own, end);
            if (st != PROX_OK) return st;
        }
    for (int own = 0; own < 2; ++own)
        for (int rend = 0; rend < 2; ++rend)
            for (int dend = 0; dend < 2; ++dend) cf_rim_disk(q, own, rend, dend);
    for (int ea = 0; ea < 2; ++ea)
        for (int eb = 0; eb < 2; ++eb) {
            prox_status st = cf_rim_rim(q, 0, ea, eb);
            if (st == PROX_OK) st = cf_rim_rim(q, 1, eb, ea);
            if (st != PROX_OK) return st;
            if (!cf_rim_rim_formable(&q->rim[0][ea], &q->rim[1][eb]) &&
                !cf_rim_rim_formable(&q->rim[1][eb], &q->rim[0][ea]))
                cf_rim_rim_points(q, ea, eb);
        }
    return PROX_OK;
}

/* Index of the shortest candidate (the first of equals: S-S, C-S, C-D, C-C order), -1 when none. */
static int cf_best(const cf_query *q)
{
    int b = -1;
    for (int i = 0; i < q->ncand; ++i)
        if (b < 0 || q->cand[i].d < q->cand[b].d) b = i;
    return b;
}

/* The largest gap along n and along the kinks of the support functions next to it. hc(d) = r |d_perp|
 * + (h/2) |d.w| is not differentiable where d is perpendicular to the axis or along it, and those are
 * exactly the optimal normals of side and face contacts: a normal a few ulps off such a kink loses
 * (h/2) |n.w| or r |n_perp| to first order (1e-12 S from a rim-rim normal measured between points
 * 1e-3 S apart). So n made perpendicular to each axis, to both (alternate rejections: nearly parallel
 * axes, whose cross product is noise), wA x wB, and the two axes are evaluated too, each turned into
 * n's half-space; every unit direction gives a valid lower bound. */
static double cf_gap_snapped(const cf_query *q, prox_vec3 n)
{
    const prox_cyl *A = &q->k[0], *B = &q->k[1];
    prox_vec3 both = prox_cyl_perp(A, prox_cyl_perp(B, prox_cyl_perp(A, n))); /* alternate rejections */
    prox_vec3 dirs[6] = {prox_cyl_perp(A, n), prox_cyl_perp(B, n), both, prox_v3_cross(A->w, B->w), A->w, B->w};
    double g = cf_gap(q, n);
    for (int i = 0; i < 6; ++i) {
        double l = prox_v3_norm(dirs[i]);
        if (!(l > 0.0)) continue;
        prox_vec3 u = prox_v3_scale(dirs[i], (prox_v3_dot(dirs[i], n) < 0.0 ? -1.0 : 1.0) / l);
        g = fmax(g, cf_gap(q, u));
    }
    return g;
}

/* The best lower bound from the normals of the candidates tied with the best (within PROX_TOL_TIE S:
 * a near-parallel S-S normal is poor while the rim against the side tied with it has an exact one)
 * and from the best pair's direction p2 - p1, each with its nearby kinks (cf_gap_snapped). */
static double cf_certificate(const cf_query *q, int best)
{
    const cf_cand *b = &q->cand[best];
    double lower = -INFINITY;
    for (int i = 0; i < q->ncand; ++i)
        if (q->cand[i].d <= b->d + PROX_TOL_TIE * q->scale) lower = fmax(lower, cf_gap_snapped(q, q->cand[i].n));
    if (b->d > 0.0) lower = fmax(lower, cf_gap_snapped(q, prox_v3_scale(prox_v3_sub(b->p2, b->p1), 1.0 / b->d)));
    return lower;
}

/* ---- result ---- */

/* Flags a positive-dimensional set of proximal points: parallel faces whose projections share an
 * area, parallel sides with axial overlap, coaxial rims (Agarwal Fig. 9 (b), (d)). */
static int cf_point_set(const cf_query *q, const cf_cand *b)
{
    const prox_cyl *A = &q->k[0], *B = &q->k[1];
    if (prox_v3_norm(prox_v3_cross(A->w, B->w)) > PROX_TOL_PARALLEL) return 0;
    if (b->kind == PROX_PAIR_CD) {
        int rim_a = b->f1 == PROX_FEAT_RIM_BASE || b->f1 == PROX_FEAT_RIM_TOP;
        const prox_cyl *rc = rim_a ? A : B, *dc = rim_a ? B : A;
        return prox_v3_norm(prox_v3_reject(prox_v3_sub(dc->c, rc->c), rc->w)) < rc->r + dc->r - q->eps;
    }
    if (b->kind == PROX_PAIR_CS || b->kind == PROX_PAIR_SS) { /* axial overlap, along A's axis */
        double t0 = prox_v3_dot(prox_v3_sub(B->b, A->b), A->w), t1 = t0 + B->h * prox_v3_dot(B->w, A->w);
        return fmin(A->h, fmax(t0, t1)) - fmax(0.0, fmin(t0, t1)) > q->eps;
    }
    return b->kind == PROX_PAIR_CC && prox_v3_norm(prox_v3_reject(prox_v3_sub(B->c, A->c), A->w)) <= q->eps;
}

static void cf_fill_disjoint(const cf_query *q, const cf_cand *b, double lower, prox_vec3 origin,
                             prox_distance_result *res)
{
    res->distance = b->d;
    res->p1 = prox_v3_add(b->p1, origin);
    res->p2 = prox_v3_add(b->p2, origin);
    res->pair = b->kind;
    res->feature1 = b->f1;
    res->feature2 = b->f2;
    res->certificate_gap = lower;
    res->certified = lower > 0.0 && lower >= b->d - q->eps;
    res->point_set = cf_point_set(q, b);
    /* Case 2.1 becomes 2.2 when the final pair is off the lateral surfaces (Fig. 7 (b), (c)). */
    if (res->agarwal == PROX_CASE_2_1 && b->kind != PROX_PAIR_CS && b->kind != PROX_PAIR_SS)
        res->agarwal = PROX_CASE_2_2;
}

/* Overlapping pair: containment, and the common point (the inner centre when nested). */
static void cf_fill_overlap(const cf_query *q, prox_vec3 x, int verified, prox_vec3 origin, prox_distance_result *res)
{
    res->intersect = 1;
    res->a_in_b = prox_cyl_in_cyl(&q->k[0], &q->k[1], 0.0); /* Agarwal Fig. 2, exact: both rims inside */
    res->b_in_a = prox_cyl_in_cyl(&q->k[1], &q->k[0], 0.0);
    if (res->a_in_b) x = q->k[0].c, verified = 1;
    else if (res->b_in_a) x = q->k[1].c, verified = 1;
    res->distance = 0.0;
    res->p1 = res->p2 = prox_v3_add(x, origin);
    res->pair = PROX_PAIR_OVERLAP;
    res->feature1 = res->feature2 = PROX_FEAT_INSIDE;
    res->certificate_gap = 0.0;
    res->certified = verified;
}

/* No candidate certified a positive distance: look for a common point (witnesses noted during the
 * enumeration, the best pair's points, the centres, then prox_cyl_common_point). Found: the pair
 * overlaps or touches. Not found with a best candidate: the uncertified minimum is reported
 * (certified = 0). No candidate at all happens only for overlapping solids. */
static void cf_overlap(cf_query *q, int best, double lower, prox_vec3 origin, prox_distance_result *res)
{
    if (best >= 0) {
        note_common(q, q->cand[best].p1);
        note_common(q, q->cand[best].p2);
    }
    note_common(q, q->k[0].c);
    note_common(q, q->k[1].c);
    prox_vec3 x = q->have_common ? q->common : q->k[0].c;
    int found = q->have_common;
    if (!found) {
        prox_vec3 start = best >= 0 ? prox_v3_scale(prox_v3_add(q->cand[best].p1, q->cand[best].p2), 0.5)
                                    : prox_v3_scale(prox_v3_add(q->k[0].c, q->k[1].c), 0.5);
        found = prox_cyl_common_point(&q->k[0], &q->k[1], start, CF_DR_ITERS, q->eps, &x);
    }
    if (found || best < 0) cf_fill_overlap(q, x, found, origin, res);
    else cf_fill_disjoint(q, &q->cand[best], lower, origin, res);
}

prox_distance_result prox_rcc_closed_form(const prox_rcc *a, const prox_rcc *b)
{
    prox_distance_result res = {0};
    prox_status st = prox_rcc_validate(a);
    if (st == PROX_OK) st = prox_rcc_validate(b);
    if (st != PROX_OK) return (prox_distance_result){.status = st};

    cf_query q;
    q.ncand = q.have_common = 0;
    const prox_vec3 origin = prox_rcc_center(a);
    q.k[0] = prox_cyl_make(a, origin);
    q.k[1] = prox_cyl_make(b, origin);
    double dims[4] = {q.k[0].h, q.k[1].h, q.k[0].r, q.k[1].r};
    q.scale = prox_v3_dist(q.k[0].c, q.k[1].c);
    for (int i = 0; i < 4; ++i) q.scale = fmax(q.scale, dims[i]);
    q.eps = PROX_TOL_CERT * q.scale;
    for (int i = 0; i < 2; ++i)
        for (int end = 0; end < 2; ++end) q.rim[i][end] = prox_cyl_rim(&q.k[i], end);

    prox_agarwal_case cs;
    if ((st = cf_enumerate(&q, &cs)) != PROX_OK) return (prox_distance_result){.status = st};
    res.status = PROX_OK;
    res.method = PROX_METHOD_CLOSED_FORM;
    res.agarwal = cs;
    int best = cf_best(&q);
    double lower = best >= 0 ? cf_certificate(&q, best) : -INFINITY;
    if (best >= 0 && lower > q.eps && lower >= q.cand[best].d - q.eps) /* a certified positive distance */
        cf_fill_disjoint(&q, &q.cand[best], lower, origin, &res);
    else
        cf_overlap(&q, best, lower, origin, &res);
    return res;
}
