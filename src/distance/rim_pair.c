/* Distance of two disjoint rim solids, TRC against TRC or RCC, by feature prediction (the TRC pairs'
 * counterpart of the RCC-RCC fast method, rcc_rcc.c; RCC-RCC keeps that method).
 *
 * A rim solid is the hull of its two end circles: a TRC (radii r0 at the base, r1 at the top, either
 * possibly 0: an apex) or an RCC (r0 = r1). Its boundary features are the end disks, the rims, an
 * apex, and the lateral surface, ruled by the generator segments joining the rims at one angle; the
 * outward normal along a generator is N = nu u + nw w (u the generator's radial direction, w the
 * axis, nw = (r0 - r1) / l, nu = h / l, l the generator's length).
 *
 * For two disjoint convex solids the closest pair lies where the features supporting the optimal
 * normal meet, so a normal near it names the feature pair (as in rcc_rcc.c, Agarwal Sec. 3):
 *   rim - rim        Newton on the degree-8 circle-circle distance (prox_circle_circle_local);
 *   rim - disk       the rim's extreme points over the disk's plane, projected on it (closed form);
 *   rim - lateral    Newton on the distance of the rim's points to the cone k t + rho
 *                    (prox_circle_cone_local), the foot on the generator through the point;
 *   lateral-lateral  the common normal: the directions D with D.wA = nwA and -D.wB = nwB (two circles
 *                    of directions, crossing in at most two points), the two generators' closest pair;
 *   apex - any       the other solid's closest point to the apex (prox_body_closest).
 * Disk-disk, disk-lateral and lateral-disk contacts are limits that also attain their minimum at a
 * rim - disk or rim - lateral pair. Every candidate is a pair of points of A x B, so the best of them
 * is an upper bound whatever the prediction got wrong; the answer is taken only when the weak-duality
 * bound along its own direction meets it (prox_body_pair_certified, the support method's early
 * certificate), so it is exactly what the support-function method would prove.
 *
 * The first normal is the capsule's: the closest points of the two axis segments. A round evaluates
 * the predicted feature pair, then every candidate of the same two ends; the next round starts from
 * the best pair's direction, until certified or the ends repeat (three rounds at most). A pair that
 * no round certifies (overlapping, touching, or a prediction that kept missing) goes to the support-
 * function method (sat/convex.c), whose GJK start and kink searches this path skips. */
#include "distance/curved_internal.h"

#include <math.h>
#include <stddef.h>

#include "core/axis.h"
#include "core/box.h"
#include "core/circle.h"
#include "core/tol.h"

/* A rim solid relative to the pair's frame: its centre c and the core's cone about it (an RCC as the
 * cone of equal radii: unit axis w, half height hh, radius r1 at the base c - hh w, r2 at the top),
 * the rims' frame u, v (prox_fcircle_make's), and the lateral normal's components nw along the axis
 * and nu across it (prox_cone_lateral_normal). */
typedef struct rsol {
    prox_vec3 c, u, v;
    prox_cone cone;
    double nw, nu;
} rsol;

static int rsol_of(const prox_body *b, rsol *k)
{
    if (b->kind == PROX_BODY_CYL) k->cone = (prox_cone){b->cyl.w, b->cyl.hh, b->cyl.r, b->cyl.r};
    else if (b->kind == PROX_BODY_CONE) k->cone = b->x.cone;
    else return 0;
    k->c = b->c;
    k->u = prox_v3_any_perp(k->cone.w), k->v = prox_v3_cross(k->cone.w, k->u);
    prox_cone_lateral_normal(&k->cone, &k->nw, &k->nu);
    return 1;
}

/* Radius of end e (0 the base, 1 the top); the radius' decrease per unit height, (r1 - r2) / h. */
static double rad(const rsol *k, int e) { return e ? k->cone.r2 : k->cone.r1; }
static double slope(const rsol *k) { return (k->cone.r1 - k->cone.r2) / (2.0 * k->cone.hh); }

static prox_vec3 end_centre(const rsol *k, int e) { return prox_v3_mad(k->c, e ? k->cone.hh : -k->cone.hh, k->cone.w); }

static prox_fcircle rim(const rsol *k, int e) { return (prox_fcircle){end_centre(k, e), k->u, k->v, k->cone.w, rad(k, e)}; }

/* The feature of k supporting the unit direction n (a guess: every candidate it selects is certified):
 * the lateral surface within PROX_PREDICT_ANGLE of its normals (end: the one nearer to p, the point
 * of k the normal came from), else the end n leans to: its apex, its disk within PROX_PREDICT_ANGLE
 * of the axis, its rim. */
enum { F_RIM, F_DISK, F_LAT, F_APEX };

static int feature(const rsol *k, prox_vec3 n, prox_vec3 p, int *end)
{
    double t = prox_v3_dot(n, k->cone.w);
    if (fabs(t - k->nw) < PROX_PREDICT_ANGLE * k->nu) {
        *end = prox_v3_dot(prox_v3_sub(p, k->c), k->cone.w) > 0.0;
        return F_LAT;
    }
    *end = t > k->nw;
    if (rad(k, *end) == 0.0) return F_APEX;
    if (fabs(t) > 1.0 - 0.5 * PROX_PREDICT_ANGLE * PROX_PREDICT_ANGLE) return F_DISK;
    return F_RIM;
}

/* The pair at unit scale, A's reference point at the origin (the support method's frame), and the
 * best candidate: x in A, y in B, d = |y - x|; done once it is certified. */
typedef struct rpq {
    prox_body b[2];
    rsol k[2];
    prox_vec3 delta, x, y, nf, n; /* n: the direction the certificate used */
    double S, d, lower;
    int fresh, done, common, has_nf, face_of; /* face_of: 1 + the solid whose face normal at its
                                               * point is the pair's, found when needed */
} rpq;

/* A point xi of solid i inside the other (both membership tests passed with no tolerance, as every
 * common point in prox) decides an overlap. */
static int common(rpq *q, int i, prox_vec3 xi)
{
    if (!prox_body_contains(&q->b[1 - i], xi, 0.0) || !prox_body_contains(&q->b[i], xi, 0.0)) return 0;
    q->x = q->y = xi, q->d = 0.0, q->common = q->done = 1;
    return 1;
}

/* A candidate pair: xi on solid i, yj on the other, and the exact normal of their features from i
 * towards the other (NULL: none, the pair's own direction alone certifies it); in: 0 when xi lies
 * outside a half-space or cone that holds the other solid (no common-point test needed). */
static void offer(rpq *q, int i, prox_vec3 xi, prox_vec3 yj, const prox_vec3 *nij, int in)
{
    if (in && common(q, i, xi)) return;
    prox_vec3 x = i ? yj : xi, y = i ? xi : yj;
    double d = prox_v3_dist(x, y);
    if (!(d < q->d)) return;
    q->x = x, q->y = y, q->d = d, q->fresh = 1;
    q->has_nf = nij != NULL, q->face_of = 0;
    if (nij) q->nf = i ? prox_v3_neg(*nij) : *nij;
}

static int face_normal(const rpq *q, const rsol *k, prox_vec3 y, prox_vec3 *n);

/* 1 once the best candidate is certified (a new best is tried once). */
static int settle(rpq *q)
{
    if (q->done || !q->fresh) return q->done;
    q->fresh = 0;
    double up;
    const prox_vec3 *nf = q->has_nf ? &q->nf : NULL;
    q->done = prox_body_pair_certified(&q->b[0], &q->b[1], q->delta, q->S, q->x, q->y, nf, &q->lower, &up, &q->n);
    if (!q->done && q->face_of) { /* the other solid's face normal at its point, from outside it */
        int j = q->face_of - 1;
        if (face_normal(q, &q->k[j], j ? q->y : q->x, &q->nf)) {
            if (j == 1) q->nf = prox_v3_neg(q->nf);
            q->done = prox_body_pair_certified(&q->b[0], &q->b[1], q->delta, q->S, q->x, q->y, &q->nf, &q->lower, &up, &q->n);
        }
    }
    return q->done;
}

static int lateral_foot(const rsol *k, prox_vec3 x, prox_vec3 *y, prox_vec3 *n);

/* The outward normal of k at its boundary point y when y lies inside an end disk or inside a
 * generator (to 64 eps S); 0 on a rim or an apex, where k's support function is smooth. */
static int face_normal(const rpq *q, const rsol *k, prox_vec3 y, prox_vec3 *n)
{
    prox_vec3 d = prox_v3_sub(y, k->c), f;
    double t = prox_v3_dot(d, k->cone.w), rho = prox_v3_norm(prox_axis_across(d, k->cone.w)), tol = PROX_TOL_CERT * q->S;
    for (int e = 0; e < 2; ++e)
        if (fabs(t - (e ? k->cone.hh : -k->cone.hh)) <= tol && rho < rad(k, e) - tol) {
            *n = e ? k->cone.w : prox_v3_neg(k->cone.w);
            return 1;
        }
    return lateral_foot(k, y, &f, n) == 2 && prox_v3_dist(f, y) <= tol;
}

/* The apex of solid i (end e, radius 0) and the other solid's closest point to it; the other's face
 * normal there, when it has one, is the pair's (settle). */
static void cand_apex(rpq *q, int i, int e)
{
    if (rad(&q->k[i], e) != 0.0) return;
    prox_vec3 x = end_centre(&q->k[i], e);
    double d = q->d;
    offer(q, i, x, prox_body_closest(&q->b[1 - i], x), NULL, 1);
    if (q->d < d && !q->common) q->face_of = 2 - i;
}

/* Rim e of solid i against disk f of solid j: the rim's points extreme over the disk's plane (or,
 * planes parallel, the one towards the disk's centre), projected on the plane; a projection inside
 * the disk gives a candidate. */
static void cand_rim_disk(rpq *q, int i, int e, int f)
{
    const rsol *ki = &q->k[i], *kj = &q->k[1 - i];
    if (rad(ki, e) == 0.0 || rad(kj, f) == 0.0) return;
    prox_vec3 cc = end_centre(ki, e), D = end_centre(kj, f), m = kj->cone.w;
    prox_vec3 pm = prox_axis_across(m, ki->cone.w), dir[2];
    double amp = prox_v3_norm(pm);
    int nd = 2;
    if (amp > PROX_TOL_NOISE) {
        dir[0] = prox_v3_scale(pm, 1.0 / amp), dir[1] = prox_v3_neg(dir[0]);
    } else {
        prox_vec3 g = prox_axis_across(prox_v3_sub(D, cc), ki->cone.w);
        double gl = prox_v3_norm(g);
        dir[0] = gl > PROX_TOL_NOISE * (prox_v3_dist(D, cc) + rad(ki, e)) ? prox_v3_scale(g, 1.0 / gl) : ki->u;
        nd = 1;
    }
    for (int s = 0; s < nd; ++s) {
        prox_vec3 x = prox_v3_mad(cc, rad(ki, e), dir[s]);
        prox_vec3 y = prox_v3_mad(x, -prox_v3_dot(prox_v3_sub(x, D), m), m);
        prox_vec3 n = prox_v3_scale(m, f ? -1.0 : 1.0); /* into the disk's face from outside */
        if (prox_v3_dist(y, D) <= rad(kj, f)) offer(q, i, x, y, &n, prox_v3_dot(prox_v3_sub(y, x), n) <= 0.0);
    }
}

/* Rim ea of A against rim eb of B: Newton from A's rim point extreme along n, B's closest rim point;
 * the common normal of the two circles there is across both tangents (as rcc_rcc.c takes it: exact
 * however near the points, where their difference's direction is rounding). */
static void cand_rim_rim(rpq *q, int ea, int eb, prox_vec3 n)
{
    if (rad(&q->k[0], ea) == 0.0 || rad(&q->k[1], eb) == 0.0) return;
    prox_fcircle ca = rim(&q->k[0], ea), cb = rim(&q->k[1], eb);
    prox_unit2 a = prox_circle_circle_local(&ca, &cb, prox_unit2_of(prox_v3_dot(n, ca.u), prox_v3_dot(n, ca.v)));
    prox_vec3 x = prox_fcircle_at(&ca, a), y = prox_fcircle_closest(&cb, x, NULL);
    if (prox_v3_dist(x, y) > PROX_TOL_CC_NEAR * q->S) { /* the points' direction is good to eps S / d */
        offer(q, 0, x, y, NULL, 1);
        return;
    }
    prox_vec3 ta = prox_v3_sub(prox_v3_scale(ca.v, a.c), prox_v3_scale(ca.u, a.s));
    prox_vec3 tb = prox_v3_cross(cb.n, prox_v3_sub(y, cb.c));
    prox_vec3 m = prox_v3_cross(ta, tb);
    double ml = prox_v3_norm(m);
    int tangents = ml > PROX_TOL_TANGENT * prox_v3_norm(tb);
    if (tangents) m = prox_v3_scale(m, (prox_v3_dot(m, prox_v3_sub(y, x)) < 0.0 ? -1.0 : 1.0) / ml);
    offer(q, 0, x, y, tangents ? &m : NULL, 1);
}

/* The point of k's lateral surface nearest to x in x's meridian half-plane and the outward normal
 * there (prox_cone_lateral_foot): 2 for a foot inside the generator, 1 at a rim (the normal is then
 * not unique), 0 when x is on the axis. */
static int lateral_foot(const rsol *k, prox_vec3 x, prox_vec3 *y, prox_vec3 *n)
{
    int foot = prox_cone_lateral_foot(&k->cone, prox_v3_sub(x, k->c), y, n);
    *y = prox_v3_add(k->c, *y);
    return foot;
}

/* Rim e of solid i against the other's lateral surface: Newton from the rim point extreme along g
 * (towards the other solid). */
static void cand_rim_lat(rpq *q, int i, int e, prox_vec3 g)
{
    const rsol *kj = &q->k[1 - i];
    if (rad(&q->k[i], e) == 0.0) return;
    prox_fcircle c = rim(&q->k[i], e);
    prox_unit2 a = prox_circle_cone_local(&c, kj->c, kj->cone.w, slope(kj), prox_unit2_of(prox_v3_dot(g, c.u), prox_v3_dot(g, c.v)));
    prox_vec3 x = prox_fcircle_at(&c, a), y, n;
    int foot = lateral_foot(kj, x, &y, &n);
    n = prox_v3_neg(n); /* into the lateral surface from outside */
    if (foot) offer(q, i, x, y, foot == 2 ? &n : NULL, foot == 1 || prox_v3_dot(prox_v3_sub(y, x), n) <= 0.0);
}

/* The generator of k whose outward normal has the radial direction of d. */
static void generator(const rsol *k, prox_vec3 d, prox_vec3 *p0, prox_vec3 *p1)
{
    prox_vec3 u = prox_v3_normalize(prox_axis_across(d, k->cone.w));
    *p0 = prox_v3_add(end_centre(k, 0), prox_v3_scale(u, rad(k, 0)));
    *p1 = prox_v3_add(end_centre(k, 1), prox_v3_scale(u, rad(k, 1)));
}

/* Lateral surface against lateral surface: the normals D from A to B with D.wA = nwA (A's lateral
 * normals) and -D.wB = nwB (B's), D = al wA + be wB + ga wA x wB; the closest pair of the two
 * generators at each. Axes near parallel: none (a set of contacts, left to the other candidates). */
static void cand_lat_lat(rpq *q)
{
    const rsol *A = &q->k[0], *B = &q->k[1];
    prox_vec3 ab = prox_v3_cross(A->cone.w, B->cone.w);
    double s2 = prox_v3_norm2(ab), c = prox_v3_dot(A->cone.w, B->cone.w);
    if (!(s2 > PROX_TOL_PARALLEL * PROX_TOL_PARALLEL)) return;
    double ta = A->nw, tb = -B->nw, al = (ta - tb * c) / s2, be = (tb - ta * c) / s2;
    double g2 = (1.0 - (al * al + be * be + 2.0 * al * be * c)) / s2;
    if (!(g2 >= 0.0)) return;
    for (int s = -1; s <= 1; s += 2) {
        prox_vec3 D = prox_v3_add(prox_v3_add(prox_v3_scale(A->cone.w, al), prox_v3_scale(B->cone.w, be)), prox_v3_scale(ab, s * sqrt(g2)));
        prox_vec3 a0, a1, b0, b1, x, y;
        generator(A, D, &a0, &a1);
        generator(B, prox_v3_neg(D), &b0, &b1);
        prox_seg_seg(a0, a1, b0, b1, &x, &y);
        offer(q, 0, x, y, &D, 1);
    }
}

/* Candidate kinds, for a round to evaluate each once. */
enum { C_APEX = 1, C_RD = 2, C_DR = 4, C_RR = 8, C_RL = 16, C_LR = 32, C_LL = 64 };

static void evaluate(rpq *q, int kinds, int ea, int eb, prox_vec3 n)
{
    if (q->done) return;
    if (kinds & C_APEX) cand_apex(q, 0, ea), cand_apex(q, 1, eb);
    if (kinds & C_RD) cand_rim_disk(q, 0, ea, eb);
    if (kinds & C_DR) cand_rim_disk(q, 1, eb, ea);
    if (kinds & C_RR) cand_rim_rim(q, ea, eb, n);
    if (kinds & C_RL) cand_rim_lat(q, 0, ea, n);
    if (kinds & C_LR) cand_rim_lat(q, 1, eb, prox_v3_neg(n));
    if (kinds & C_LL) cand_lat_lat(q);
}

/* The candidate the two predicted features name. */
static int predicted_kind(int fa, int fb)
{
    if (fa == F_APEX || fb == F_APEX) return C_APEX;
    if (fa == F_LAT) return fb == F_LAT ? C_LL : (fb == F_RIM ? C_LR : 0);
    if (fb == F_LAT) return fa == F_RIM ? C_RL : 0;
    if (fa == F_RIM) return fb == F_RIM ? C_RR : C_RD;
    return fb == F_RIM ? C_DR : 0;
}

/* One round from normal n (A's point pa, B's pb): the predicted candidate, then the others of the
 * same two ends. 1 when certified; *code names the ends. */
static int round_from(rpq *q, prox_vec3 n, prox_vec3 pa, prox_vec3 pb, int *code)
{
    int ea, eb, fa = feature(&q->k[0], n, pa, &ea), fb = feature(&q->k[1], prox_v3_neg(n), pb, &eb);
    int first = predicted_kind(fa, fb);
    *code = ea * 2 + eb;
    evaluate(q, first, ea, eb, n);
    if (settle(q)) return 1;
    evaluate(q, (C_APEX | C_RD | C_DR | C_RR | C_RL | C_LR | C_LL) & ~first, ea, eb, n);
    return settle(q);
}


static int solve(rpq *q)
{
    const rsol *A = &q->k[0], *B = &q->k[1];
    prox_vec3 pa, pb;
    prox_seg_seg(end_centre(A, 0), end_centre(A, 1), end_centre(B, 0), end_centre(B, 1), &pa, &pb);
    prox_vec3 n = prox_v3_sub(pb, pa);
    double l = prox_v3_norm(n);
    if (!(l > 0.0)) n = q->delta, l = prox_v3_norm(n);
    if (!(l > 0.0 && isfinite(l))) return 0;
    n = prox_v3_scale(n, 1.0 / l);
    /* the axes' closest points lie in their own solids: one inside the other solid is a common point */
    if (common(q, 0, pa) || common(q, 1, pb)) return 1;
    for (int round = 0, tried = 0, code; round < 3; ++round) {
        if (round_from(q, n, pa, pb, &code)) return 1;
        if (!(q->d < INFINITY && q->d > 0.0) || (tried >> code & 1)) return 0;
        tried |= 1 << code;
        n = prox_v3_scale(prox_v3_sub(q->y, q->x), 1.0 / q->d);
        pa = q->x, pb = q->y;
        /* the best pair's direction does not separate the solids: likely an overlap, whose common point
         * is often the pair's midpoint; else the support method decides it at less cost than more rounds */
        if (!(prox_body_hc(&q->b[0], n) + prox_body_hc(&q->b[1], prox_v3_neg(n)) < prox_v3_dot(n, q->delta)))
            return common(q, 0, prox_v3_scale(prox_v3_add(q->x, q->y), 0.5));
    }
    return 0;
}

int prox_rim_pair_distance(const prox_body *a, const prox_body *b, prox_distance_result *r, prox_vec3 *normal)
{
    if (!((a->kind == PROX_BODY_CONE || b->kind == PROX_BODY_CONE) &&
          (a->kind == PROX_BODY_CONE || a->kind == PROX_BODY_CYL) && (b->kind == PROX_BODY_CONE || b->kind == PROX_BODY_CYL)))
        return 0;
    rpq q;
    prox_vec3 cb = prox_v3_sub(b->c, a->c);
    double S = fmax(prox_v3_norm(cb), fmax(a->size, b->size)), f = prox_unit_scale(S);
    prox_body_scaled_at(&q.b[0], a, prox_v3(0, 0, 0), f);
    prox_body_scaled_at(&q.b[1], b, cb, f);
    rsol_of(&q.b[0], &q.k[0]);
    rsol_of(&q.b[1], &q.k[1]);
    q.delta = q.b[1].c;
    q.S = S * f;
    q.d = INFINITY;
    q.fresh = q.done = q.common = q.has_nf = 0;
    if (!solve(&q)) return 0;
    if (q.common) {
        prox_vec3 x = prox_v3_mad(a->c, 1.0 / f, q.x);
        *r = (prox_distance_result){.status = PROX_OK, .intersect = 1, .p1 = x, .p2 = x, .certified = 1,
                                    .method = PROX_METHOD_FAST};
        return 1;
    }
    *r = (prox_distance_result){.status = PROX_OK,
                                .distance = q.d / f,
                                .p1 = prox_v3_mad(a->c, 1.0 / f, q.x),
                                .p2 = prox_v3_mad(a->c, 1.0 / f, q.y),
                                .certificate_gap = q.lower / f,
                                .certified = 1,
                                .method = PROX_METHOD_FAST};
    if (normal) *normal = q.n;
    return 1;
}
