/* A polytope (BOX, RPP, RHP/HEX, WED, ARB) against a curved body (RCC, TRC, REC, ELL): the distance by
 * alternating projections and the feature pairs they land on, certified by weak duality; the BOX-RCC
 * fast path of box_rcc.c (br_fast) carried over to any convex polytope and any body with an exact
 * closest point (core/body.h).
 *
 * Every pair (x in P, y in B) bounds the distance from above by |y - x| and every unit n from below
 * by gap(n) = -h_B(-n) - h_P(n) (weak duality; Gilbert, Johnson & Keerthi 1988): a pair whose own
 * direction n = (y - x) / |y - x| has gap(n) >= |y - x| - PROX_TOL_CERT S is the closest pair to a
 * few ulps of S, the certificate of every disjoint answer in prox. A closest pair lies on a corner, an
 * edge or the interior of a face of P:
 * - an edge x(t) = a + t (b - a), t in [0, 1]: the distance from x(t) to the convex body is convex in t
 *   and G(t) = (x(t) - P_B(x(t))).(b - a) (half its squared derivative; P_B the closest point of B) is
 *   continuous and nondecreasing, so the closest pair is at the root of G or at an end (the secant
 *   inside the bracket, core/edge_root.h);
 * - a face with outward normal n: B's point lowest along n (its support point at -n), when its foot
 *   on the face's plane lies in the face; otherwise the closest pair lies on the face's border;
 * - a corner: the closest point of B to it, which the projections compute.
 * A projection or a feature pair that lands in both solids (to PROX_TOL_TOUCH S, as the engine checks
 * its common points) is a common point. What the projections and the feature pairs do not settle
 * goes to the certified support-function engine (src/sat/convex.c), so the answer is never weaker
 * than its: a round that comes no nearer than the last (the feature pair solved, its certificate
 * short: a corner or a rim 1e-8 S from the other body knows the normal only to eps S / 1e-8 S, where
 * the engine searches the kinks), PB_ROUNDS rounds, or a pair whose gap(n) stays negative (most
 * likely overlapping: the engine's GJK decides sooner than the projections' slow approach). */
#include <float.h>

#include "core/body.h"
#include "core/edge_root.h"
#include "core/tol.h"
#include "distance/poly_internal.h"
#include "prox/query.h"

#define PB_ROUNDS 8     /* rounds of projections before the engine takes over */
#define PB_NEG_ROUNDS 2 /* rounds after which a negative gap(n) gives up (the pair most likely overlaps) */

/* gap(n) = -h_B(-n) - h_P(n), the lower bound of the distance along the unit n (P centred). */
static double pb_gap(const prox_polytope *p, const prox_body *b, prox_vec3 n)
{
    return -prox_body_support(b, prox_v3_neg(n)) - prox_polytope_hc(p, n);
}

/* G(t) = (x(t) - P_B(x(t))).e at x(t) = a + t e, with x and y = P_B(x); warm carries B's closest-point
 * iteration from one point of the edge to the next (prox_body_closest_warm). */
typedef struct pb_edge_ctx {
    const prox_body *b;
    prox_vec3 a, e, *x, *y;
    double warm;
} pb_edge_ctx;

static double pb_edge_g(void *ctx, double t)
{
    pb_edge_ctx *q = ctx;
    *q->x = prox_v3_mad(q->a, t, q->e);
    *q->y = prox_body_closest_warm(q->b, *q->x, &q->warm);
    return prox_v3_dot(prox_v3_sub(*q->x, *q->y), q->e);
}

/* A corner v of P with B's closest point to it, pv, and the closest-point iteration's state there
 * (prox_body_closest_warm): the ends of the edges that meet at v share them. */
typedef struct pb_corner {
    prox_vec3 v, pv;
    double warm;
} pb_corner;

static pb_corner pb_corner_at(const prox_body *b, prox_vec3 v)
{
    pb_corner k = {v, v, NAN};
    k.pv = prox_body_closest_warm(b, v, &k.warm);
    return k;
}

/* The segment between corners a and c against the body: an end when G does not change sign, else the
 * root of G (core/edge_root.h) from t0, to a bracket a few ulps wide, warm from the end a. Returns
 * |y - x| of the pair (x on the segment, y on B). */
static double pb_edge_from(const prox_body *b, const pb_corner *a, const pb_corner *c, double t0, prox_vec3 *x, prox_vec3 *y)
{
    prox_vec3 e = prox_v3_sub(c->v, a->v);
    double glo = prox_v3_dot(prox_v3_sub(a->v, a->pv), e), ghi = prox_v3_dot(prox_v3_sub(c->v, c->pv), e);
    if (glo >= 0.0 || ghi <= 0.0) {
        const pb_corner *k = glo >= 0.0 ? a : c;
        *x = k->v, *y = k->pv;
        return prox_v3_dist(*x, *y);
    }
    pb_edge_ctx q = {b, a->v, e, x, y, a->warm};
    prox_edge_root(pb_edge_g, &q, 0.0, 1.0, glo, ghi, t0 > 0.0 && t0 < 1.0 ? t0 : 0.5, 4.0 * DBL_EPSILON);
    return prox_v3_dist(*x, *y);
}

/* The segment [a, c] against the body (pb_edge_from with both ends solved here). */
static double pb_edge(const prox_body *b, prox_vec3 a, prox_vec3 c, double t0, prox_vec3 *x, prox_vec3 *y)
{
    pb_corner ka = pb_corner_at(b, a), kc = pb_corner_at(b, c);
    return pb_edge_from(b, &ka, &kc, t0, x, y);
}

/* Face f against the body: B's point lowest along the face's normal and its foot, when that lies in
 * the face; else the nearest pair of the face's border edges. */
static double pb_face(const prox_polytope *p, const prox_body *b, int f, prox_vec3 *x, prox_vec3 *y)
{
    prox_vec3 n = p->n[f], low = prox_body_support_point(b, prox_v3_neg(n));
    double h = prox_v3_dot(n, low) - p->d[f];
    if (h > 0.0 && prox_polytope_face_foot(p, f, low, x)) {
        *y = low;
        return prox_v3_dist(*x, *y);
    }
    /* The border edges, least bound first: edge k's distance is at least the gap of the support
     * functions along the unit n_k from its point nearest to B's lowest point towards that point
     * (weak duality), so an edge whose bound is no less than the nearest pair found holds none
     * nearer, and a pair that meets (distance 0) ends the search. */
    int m = p->fnv[f], ord[PROX_POLY_MAXFV];
    double lb[PROX_POLY_MAXFV], t0[PROX_POLY_MAXFV]; /* t0: the edge's point nearest B's lowest, the root's start */
    for (int k = 0; k < m; ++k) {
        prox_vec3 a = p->v[p->fv[f][k]], c = p->v[p->fv[f][k + 1 < m ? k + 1 : 0]];
        t0[k] = prox_seg_param(a, c, low);
        prox_vec3 w = prox_v3_sub(low, prox_v3_mad(a, t0[k], prox_v3_sub(c, a)));
        double len = prox_v3_norm(w);
        lb[k] = -INFINITY;
        if (len > 0.0) {
            prox_vec3 nk = prox_v3_scale(w, 1.0 / len);
            double sa = prox_v3_dot(nk, a), sc = prox_v3_dot(nk, c);
            lb[k] = -prox_body_support(b, prox_v3_neg(nk)) - (sa > sc ? sa : sc);
        }
        int at = k;
        for (; at > 0 && lb[ord[at - 1]] > lb[k]; --at) ord[at] = ord[at - 1];
        ord[at] = k;
    }
    /* the corners' closest points, each solved once for the two edges that meet there */
    pb_corner corner[PROX_POLY_MAXFV];
    int solved[PROX_POLY_MAXFV] = {0};
    double best = INFINITY;
    for (int i = 0; i < m && lb[ord[i]] < best; ++i) {
        int k = ord[i], k1 = k + 1 < m ? k + 1 : 0;
        if (!solved[k]) corner[k] = pb_corner_at(b, p->v[p->fv[f][k]]), solved[k] = 1;
        if (!solved[k1]) corner[k1] = pb_corner_at(b, p->v[p->fv[f][k1]]), solved[k1] = 1;
        prox_vec3 u, v;
        double d = pb_edge_from(b, &corner[k], &corner[k1], t0[k], &u, &v);
        if (d < best) best = d, *x = u, *y = v;
        if (!(best > 0.0)) break;
    }
    return best;
}

/* Is (x in P, y in B, d = |y - x| > 0) its own certificate? *gap receives gap(n). d is an upper bound
 * only for x in P (y is a closest point of B), which is tested too, to tin (the touching band and the
 * rounding of P's planes where it lies far from the origin): a feature point put off P by a collapsed
 * face must not certify. */
static int pb_certified(const prox_polytope *p, const prox_body *b, prox_vec3 x, prox_vec3 y, double d, double S,
                        double tin, double *gap)
{
    *gap = pb_gap(p, b, prox_v3_scale(prox_v3_sub(y, x), 1.0 / d));
    return *gap >= d - PROX_TOL_CERT * S && prox_polytope_contains(p, x, tin);
}

/* The result of a certified pair, moved back by o. */
static int pb_disjoint(prox_vec3 x, prox_vec3 y, double d, double gap, prox_vec3 o, prox_distance_result *r)
{
    r->intersect = 0, r->distance = d, r->certificate_gap = gap, r->certified = 1;
    r->p1 = prox_v3_add(x, o), r->p2 = prox_v3_add(y, o);
    return PROX_PB_DISJOINT;
}

/* The result of a common point (checked in both solids), moved back by o. */
static int pb_meet(prox_vec3 c, prox_vec3 o, prox_distance_result *r)
{
    r->intersect = 1, r->distance = 0.0, r->certified = 1;
    r->p1 = r->p2 = prox_v3_add(c, o);
    return PROX_PB_MEET;
}

int prox_poly_body_fast(const prox_polytope *p, prox_vec3 cp, const prox_body *body, double S, prox_distance_result *r)
{
    prox_body b = *body;
    b.c = prox_v3_sub(body->c, cp); /* relative to the polytope's reference point */
    double tol8 = 2.0 * PROX_QUERY_REL_TOL * S, touch = PROX_TOL_TOUCH * S, gap;
    double tin = touch + 16.0 * DBL_EPSILON * prox_v3_norm(cp); /* x in P: the band, P's planes' rounding */
    /* cheap common points first: each body's reference point (inside it) in the other */
    if (prox_body_contains(&b, prox_v3(0, 0, 0), 0.0)) return pb_meet(prox_v3(0, 0, 0), cp, r);
    if (prox_polytope_contains(p, b.c, 0.0)) return pb_meet(b.c, cp, r);
    prox_vec3 y = prox_body_closest(&b, prox_v3(0, 0, 0));
    double last = INFINITY; /* the nearest pair so far: a round that comes no nearer has stalled */
    for (int it = 0; it < PB_ROUNDS; ++it) {
        prox_vec3 x;
        int i, j;
        double t;
        int feat = prox_polytope_closest_feature(p, y, &x, &i, &j, &t);
        prox_vec3 q = feat == PROX_POLY_INSIDE ? y : prox_body_closest(&b, x);
        if (feat == PROX_POLY_INSIDE || (q.x == x.x && q.y == x.y && q.z == x.z)) { /* a common point */
            prox_vec3 c = feat == PROX_POLY_INSIDE ? y : x;
            if (!prox_polytope_contains(p, c, touch) || !prox_body_contains(&b, c, touch)) return PROX_PB_OPEN;
            return pb_meet(c, cp, r);
        }
        double d = prox_v3_dist(x, q);
        if (!(d > 0.0)) return PROX_PB_OPEN;
        if (pb_certified(p, &b, x, q, d, S, tin, &gap)) return gap > tol8 ? pb_disjoint(x, q, d, gap, cp, r) : PROX_PB_OPEN;
        if (it >= PB_NEG_ROUNDS && gap < 0.0) return PROX_PB_OPEN;
        /* the feature pair the projection landed on, whose pair is the next round's start when nearer */
        prox_vec3 u, v;
        double e = feat == PROX_POLY_FACE ? pb_face(p, &b, i, &u, &v)
                   : feat == PROX_POLY_EDGE ? pb_edge(&b, p->v[i], p->v[j], t, &u, &v) : INFINITY;
        if (e < d) {
            if (!(e > 0.0)) /* the feature pair met: its point in both solids is a common point */
                return prox_polytope_contains(p, u, touch) && prox_body_contains(&b, u, touch) ? pb_meet(u, cp, r) : PROX_PB_OPEN;
            if (pb_certified(p, &b, u, v, e, S, tin, &gap)) return gap > tol8 ? pb_disjoint(u, v, e, gap, cp, r) : PROX_PB_OPEN;
            q = v, d = e;
        }
        if (!(d < last)) return PROX_PB_OPEN;
        last = d;
        y = q;
    }
    return PROX_PB_OPEN;
}
