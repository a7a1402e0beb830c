/* The generic entry point: one set of queries for any pair of the ten macrobodies, each pair sent to
 * the cheapest exact solver for it (docs/algorithms/dispatch.md):
 *  - RCC, BOX, RPP, SPH among themselves: the specialised pair solvers of pairs.h (an RPP answered as
 *    the BOX it describes);
 *  - a sphere against anything: the sphere's centre against the other solid (sphere_any.c);
 *  - two polytopes (BOX, RPP, RHP, WED, ARB), one of them new: the exact polytope solver
 *    (src/distance/poly_internal.h);
 *  - every other pair: the certified support-function method of any two bodies (src/sat/convex.h).
 * A pair whose solver is written the other way round is swapped and its answer mirrored (p1 <-> p2,
 * normal negated). Each shape is validated once: by the specialised solver itself, or here before a
 * solver that takes prepared bodies. The relation and the repositioning of the TRX report
 * (LA-UR-13-26757, Sec. 4: "a prescription to reposition an object that is determined to collide")
 * are built on the signed distance: moving B by (margin - sd) along the signed-distance normal leaves
 * the supporting planes at the witnesses exactly `margin` apart, so dist(A, B') = margin. */
#include "core/body.h"
#include "distance/box_internal.h"
#include "distance/curved_internal.h"
#include "distance/poly_internal.h"
#include "query/query_internal.h"
#include "prox/distance.h"
#include "prox/sat.h"
#include "prox/solid.h"
#include "prox/support.h"
#include "sat/convex.h"
#include "sat/sat_internal.h"

#include <float.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* ---- routes ---- */

typedef enum route {
    ROUTE_OLD,    /* both of RCC, BOX, RPP, SPH, not a sphere against a non-sphere */
    ROUTE_SPH_A,  /* A a sphere, B not */
    ROUTE_SPH_B,  /* B a sphere, A not */
    ROUTE_POLY,   /* two polytopes, one of them RHP, WED or ARB */
    ROUTE_POLY_BODY, /* a polytope and a curved body (RCC, TRC, REC, ELL), not BOX-RCC */
    ROUTE_CONVEX  /* the rest: the support-function method */
} route;

static int kind_old(prox_shape_kind k) { return k <= PROX_SHAPE_SPH; }
static int kind_poly(prox_shape_kind k)
{
    return k == PROX_SHAPE_BOX || k == PROX_SHAPE_RPP || k >= PROX_SHAPE_RHP;
}

static int kind_curved(prox_shape_kind k)
{
    return k == PROX_SHAPE_RCC || k == PROX_SHAPE_TRC || k == PROX_SHAPE_REC || k == PROX_SHAPE_ELL;
}

/* The route of a pair of known kinds. */
static route route_of(prox_shape_kind ka, prox_shape_kind kb)
{
    int sa = ka == PROX_SHAPE_SPH, sb = kb == PROX_SHAPE_SPH;
    if (sa != sb) return sa ? ROUTE_SPH_A : ROUTE_SPH_B;
    if (kind_old(ka) && kind_old(kb)) return ROUTE_OLD;
    if (kind_poly(ka) && kind_poly(kb)) return ROUTE_POLY;
    if ((kind_poly(ka) && kind_curved(kb)) || (kind_curved(ka) && kind_poly(kb))) return ROUTE_POLY_BODY;
    return ROUTE_CONVEX;
}

/* A BOX or RPP (no aspect limit, shapes.h) whose polytope keeps its shape: at most one edge shorter
 * than 1/PROX_MAX_ASPECT of the longest. Relative to its centroid a box with two such edges loses
 * both to rounding (a 7e-67 and a 7e-62 edge beside a 3e-33 one leave a segment, with face planes
 * through it), so it goes to the support-function method, which takes its edges and half extents
 * exactly; a plate (one such edge) stays a consistent flat polytope. */
static int poly_fits(const prox_shape *s)
{
    double l[3];
    if (s->kind == PROX_SHAPE_BOX) {
        for (int i = 0; i < 3; ++i) l[i] = prox_v3_norm(s->u.box.edge[i]);
    } else if (s->kind == PROX_SHAPE_RPP) {
        const prox_rpp *r = &s->u.rpp;
        l[0] = r->xmax - r->xmin, l[1] = r->ymax - r->ymin, l[2] = r->zmax - r->zmin;
    } else {
        return 1;
    }
    double hi = fmax(l[0], fmax(l[1], l[2]));
    int thin = 0;
    for (int i = 0; i < 3; ++i) thin += l[i] * PROX_MAX_ASPECT < hi; /* NaN sizes pass on to the validator */
    return thin < 2;
}

/* The polytope route r (ROUTE_POLY, ROUTE_POLY_BODY) of a pair whose polytopes keep their shape or
 * not (fa, fb: poly_fits; A of kind ka): a polytope pair with a box too thin for its polytope goes to
 * the support-function method. */
static route route_fitted(route r, prox_shape_kind ka, int fa, int fb)
{
    if (r == ROUTE_POLY_BODY) return (kind_poly(ka) ? fa : fb) ? r : ROUTE_CONVEX;
    return fa && fb ? r : ROUTE_CONVEX;
}

/* The route of a pair of shapes; a box's edge lengths are read for the polytope routes alone (the
 * sphere and BOX-RCC routes take any box). */
static route route_shapes(const prox_shape *a, const prox_shape *b)
{
    route r = route_of(a->kind, b->kind);
    if (r != ROUTE_POLY && r != ROUTE_POLY_BODY) return r;
    return route_fitted(r, a->kind, poly_fits(a), poly_fits(b));
}

/* PROX_OK when both pointers and kinds can be dispatched (the shapes themselves are validated by
 * the route). */
static prox_status check_kinds(const prox_shape *a, const prox_shape *b)
{
    if (!a || !b) return PROX_EINVAL_ARG;
    if ((unsigned)a->kind >= PROX_SHAPE_KIND_COUNT_ || (unsigned)b->kind >= PROX_SHAPE_KIND_COUNT_)
        return PROX_EINVAL_SHAPE_KIND;
    return PROX_OK;
}

/* First failing validation in the order of the call. */
static prox_status validate2(const prox_shape *a, const prox_shape *b)
{
    prox_status st = prox_shape_validate(a);
    return st != PROX_OK ? st : prox_shape_validate(b);
}

static prox_distance_result mirror_d(prox_distance_result r)
{
    prox_vec3 t = r.p1;
    r.p1 = r.p2;
    r.p2 = t;
    int x = r.a_in_b;
    r.a_in_b = r.b_in_a;
    r.b_in_a = x;
    return r;
}

static prox_signed_result mirror_s(prox_signed_result r)
{
    prox_vec3 t = r.p1;
    r.p1 = r.p2;
    r.p2 = t;
    r.normal = prox_v3_neg(r.normal);
    return r;
}

static prox_test_result mirror_t(prox_test_result r)
{
    r.direction = prox_v3_neg(r.direction);
    return r;
}

/* ---- the specialised pairs of RCC, BOX (RPP), SPH ---- */

/* Kind after RPP -> BOX, and the box itself (an RPP validated first: its box would pass as a box). */
typedef struct norm_shape {
    prox_shape_kind kind; /* RCC, BOX or SPH */
    prox_box box;
    const prox_shape *s;
} norm_shape;

static prox_status normalise(const prox_shape *s, norm_shape *n)
{
    n->s = s;
    n->kind = s->kind == PROX_SHAPE_RPP ? PROX_SHAPE_BOX : s->kind;
    if (s->kind == PROX_SHAPE_RPP) {
        prox_status st = prox_rpp_validate(&s->u.rpp);
        if (st != PROX_OK) return st;
        n->box = prox_rpp_to_box(&s->u.rpp);
    } else if (s->kind == PROX_SHAPE_BOX) {
        n->box = s->u.box;
    }
    return PROX_OK;
}

static prox_status normalise2(const prox_shape *a, const prox_shape *b, norm_shape *na, norm_shape *nb)
{
    prox_status st = normalise(a, na);
    return st != PROX_OK ? st : normalise(b, nb);
}

/* Order of kinds for the canonical pair: BOX < RCC < SPH (the solvers take them in that order). */
static int rank(prox_shape_kind k) { return k == PROX_SHAPE_BOX ? 0 : (k == PROX_SHAPE_RCC ? 1 : 2); }

/* RCC-RCC distance by the default method (prox_rcc_distance: prediction and certificate, the
 * closed-form method when that cannot certify). The cylinder-pair details (Agarwal's case, feature
 * pair) are left out, as for every other shape pair; the certificate, the method and the nesting
 * flags are kept. */
static prox_distance_result rcc_rcc_distance(const prox_rcc *a, const prox_rcc *b)
{
    prox_distance_result r = {0};
    prox_distance_result e = prox_rcc_distance(a, b);
    r.status = e.status;
    if (r.status != PROX_OK) return r;
    r.intersect = e.intersect;
    r.distance = e.distance;
    r.p1 = e.p1;
    r.p2 = e.p2;
    r.certificate_gap = e.intersect ? 0.0 : e.certificate_gap;
    r.certified = e.certified;
    r.method = e.method;
    r.a_in_b = e.a_in_b;
    r.b_in_a = e.b_in_a;
    return r;
}

/* Canonical-order distance (rank(a) <= rank(b)); the solvers validate their shapes. */
static prox_distance_result dist_canon(const norm_shape *a, const norm_shape *b)
{
    const prox_shape *sa = a->s, *sb = b->s;
    switch (a->kind * 4 + b->kind) {
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_BOX: return prox_box_box_distance(&a->box, &b->box);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_RCC: return prox_query_box_rcc_distance(&a->box, &sb->u.rcc);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_SPH: return prox_box_sph_distance(&a->box, &sb->u.sph);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_RCC: return rcc_rcc_distance(&sa->u.rcc, &sb->u.rcc);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_SPH: return prox_rcc_sph_distance(&sa->u.rcc, &sb->u.sph);
    default: return prox_sph_sph_distance(&sa->u.sph, &sb->u.sph);
    }
}

static prox_signed_result signed_canon(const norm_shape *a, const norm_shape *b)
{
    const prox_shape *sa = a->s, *sb = b->s;
    switch (a->kind * 4 + b->kind) {
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_BOX: return prox_box_box_signed_distance(&a->box, &b->box);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_RCC: return prox_box_rcc_signed_distance(&a->box, &sb->u.rcc);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_SPH: return prox_box_sph_signed_distance(&a->box, &sb->u.sph);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_RCC: return prox_rcc_signed_distance(&sa->u.rcc, &sb->u.rcc);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_SPH: return prox_rcc_sph_signed_distance(&sa->u.rcc, &sb->u.sph);
    default: return prox_sph_sph_signed_distance(&sa->u.sph, &sb->u.sph);
    }
}

static prox_test_result test_canon(const norm_shape *x, const norm_shape *y)
{
    prox_test_result r = {0};
    if (x->kind == PROX_SHAPE_BOX && y->kind == PROX_SHAPE_BOX) return prox_box_box_test(&x->box, &y->box);
    if (x->kind == PROX_SHAPE_BOX && y->kind == PROX_SHAPE_RCC) return prox_box_rcc_test(&x->box, &y->s->u.rcc);
    if (x->kind == PROX_SHAPE_RCC && y->kind == PROX_SHAPE_RCC) { /* the certified SAT: ~6x cheaper */
        prox_test_result v = prox_rcc_sat(&x->s->u.rcc, &y->s->u.rcc);
        r.status = v.status;
        r.intersect = v.intersect;
        return r;
    }
    prox_distance_result d = dist_canon(x, y);
    r.status = d.status;
    r.intersect = d.intersect;
    return r;
}

/* ---- the polytope pairs and the support-function method ----
 * Each route runs on built bodies, so that a prepared solid (prox_solid, built once) and a shape
 * (built on every call) take the very same solver: the shape queries build, then call the same
 * functions as the solid queries. */

/* The polytope of a polytope shape as a support body (kind PROX_BODY_POLY, reference point b->c),
 * validated as it is built. Only the fields the support-function side reads for that kind are set:
 * the head zeroed, the polytope itself written once. */
static prox_status poly_body_checked(const prox_shape *s, prox_body *b)
{
    memset(b, 0, offsetof(prox_body, x));
    b->kind = PROX_BODY_POLY;
    prox_status st = prox_polytope_checked(s, &b->x.poly, &b->c);
    b->size = b->x.poly.size;
    return st;
}

static prox_distance_result convex_distance(const prox_shape *a, const prox_shape *b, const prox_body *ba,
                                            const prox_body *bb);
static prox_signed_result convex_signed(const prox_shape *a, const prox_shape *b, const prox_body *ba,
                                        const prox_body *bb);

/* The support bodies of two valid shapes, for the support-function method. */
static void bodies(const prox_shape *a, const prox_shape *b, prox_body *ba, prox_body *bb)
{
    *ba = prox_body_make(a), *bb = prox_body_make(b);
}

/* The polytope solver's answer on the polytopes of pa, pb (POLY bodies of the shapes a, b), or, when
 * it could not certify it (a speck of a box 1e-24 of the pair's scale beside an ARB: its features
 * collapse in the pair's frame, and one order of the pair answered 1e-47 for 1e-42; a common point
 * outside a speck's own planes), the support-function method's certified one. */
static prox_distance_result poly_distance(const prox_shape *a, const prox_shape *b, const prox_body *pa,
                                          const prox_body *pb)
{
    prox_distance_result r = prox_poly_distance(&pa->x.poly, pa->c, &pb->x.poly, pb->c);
    if (r.certified) return r;
    prox_body ba, bb;
    bodies(a, b, &ba, &bb);
    return convex_distance(a, b, &ba, &bb);
}

static prox_signed_result poly_signed_engine(const prox_shape *a, const prox_shape *b)
{
    prox_body ba, bb;
    bodies(a, b, &ba, &bb);
    return convex_signed(a, b, &ba, &bb);
}

static prox_signed_result poly_signed(const prox_shape *a, const prox_shape *b, const prox_body *pa,
                                      const prox_body *pb)
{
    const prox_polytope *P = &pa->x.poly, *Q = &pb->x.poly;
    prox_vec3 ca = pa->c, cb = pb->c;
    prox_signed_result r = prox_poly_signed(P, ca, Q, cb);
    if (r.sd > 0.0 && !(r.sd_lower > 0.0)) return poly_signed_engine(a, b); /* a disjoint answer not certified */
    /* witnesses that miss p2 - p1 = sd n by more than the touching band (a needle's support edge
     * against a plate's face, 1e-10 S deep: 2e-8 S off): the support-function engine's */
    double S = fmax(prox_v3_dist(ca, cb), fmax(P->size, Q->size));
    if (prox_v3_norm(prox_v3_sub(prox_v3_sub(r.p2, r.p1), prox_v3_scale(r.normal, r.sd))) > PROX_TOL_TOUCH * S)
        return poly_signed_engine(a, b);
    /* and witnesses off their solids (a sliver wedge 1e-78 S across touching a box: p1 3.5e-8 S away) */
    if (!prox_polytope_contains(P, prox_v3_sub(r.p1, ca), PROX_TOL_TOUCH * S) ||
        !prox_polytope_contains(Q, prox_v3_sub(r.p2, cb), PROX_TOL_TOUCH * S))
        return poly_signed_engine(a, b);
    r.certified = 1; /* every separating axis of the two polytopes examined */
    prox_body_signed_bounds(pa, pb, &r);
    /* a disjoint answer whose witnesses the enclosure finds off their solids (a sliver 5.5e-48 thin
     * 1.4e-5 S from a speck: p1 off the wedge by its thickness, sd 8e-11 S short): the engine's */
    if (r.sd > 0.0 && !r.certified) return poly_signed_engine(a, b);
    return r;
}

/* The two polytopes of a polytope pair, each validated as it is built (one construction serves
 * both): A's status first, as every query reports. */
static prox_status poly_pair(const prox_shape *a, const prox_shape *b, prox_body *pa, prox_body *pb)
{
    prox_status st = poly_body_checked(a, pa);
    return st != PROX_OK ? st : poly_body_checked(b, pb);
}

/* A common point of two overlapping bodies found cheaply, before the support-function engine: each
 * body's centre (inside it) in the other; then, unless the pair stands plainly apart along the line
 * of the centres (max over A of d.x below min over B of d.y, d = c_B - c_A: weak duality), the
 * midpoint of each body's closest point to the other's centre. A point is taken only when both
 * membership tests pass with no tolerance: a common point checked in both solids, the certificate
 * of every overlap in prox. On random overlapping pairs of two ellipsoids these find 93 % of the
 * common points (59 % the centres) for two closest-point solves, where the engine's GJK takes its
 * iterations; a pair they miss goes to the engine as before. */
static int convex_meet(const prox_body *ba, const prox_body *bb, prox_distance_result *r)
{
    prox_vec3 x = ba->c;
    int hit = prox_body_contains(bb, x, 0.0);
    if (!hit) hit = prox_body_contains(ba, x = bb->c, 0.0);
    if (!hit) {
        prox_vec3 d = prox_v3_sub(bb->c, ba->c);
        if (prox_body_support(ba, d) < -prox_body_support(bb, prox_v3_neg(d))) return 0; /* apart */
        x = prox_v3_scale(prox_v3_add(prox_body_closest(ba, bb->c), prox_body_closest(bb, ba->c)), 0.5);
        hit = prox_body_contains(ba, x, 0.0) && prox_body_contains(bb, x, 0.0);
    }
    if (!hit) return 0;
    *r = (prox_distance_result){.status = PROX_OK, .intersect = 1, .p1 = x, .p2 = x, .certified = 1,
                                .method = PROX_METHOD_SUPPORT};
    return 1;
}

/* Coaxial solids of revolution (RCC, TRC, ELL, SPH on one axis) have a whole circle of optimal
 * directions, where the support method is degenerate: their meridian sections answer in closed form
 * (distance/curved_internal.h). ba, bb: the shapes' support bodies (prox_body_make). */
static prox_distance_result convex_distance(const prox_shape *a, const prox_shape *b, const prox_body *ba,
                                            const prox_body *bb)
{
    if (prox_coaxial_pair(a, b)) return prox_coaxial_distance(a, b);
    prox_distance_result r;
    if (convex_meet(ba, bb, &r)) return r;
    if (prox_rim_pair_distance(ba, bb, &r, NULL)) return r;
    return prox_convex_distance(ba, bb);
}

/* The support method's normal of a disjoint pair is the maximiser of -phi, where -phi is flat: it
 * can stand ~1e-10 rad off the line of the witnesses (p2 - p1 then misses sd normal by sd x that).
 * The witnesses are the exact closest pair, so their direction is the normal: taken when they are
 * more than PROX_TOL_WITNESS_DIR S apart (its rounding then below 1e-12 rad). */
static prox_signed_result convex_signed_bodies(const prox_body *ba, const prox_body *bb);

static prox_signed_result convex_signed(const prox_shape *a, const prox_shape *b, const prox_body *ba,
                                        const prox_body *bb)
{
    if (prox_coaxial_pair(a, b)) {
        prox_signed_result c = prox_coaxial_signed_distance(a, b);
        c.certified = 1; /* the closed forms of the meridian sections */
        prox_body_signed_bounds(ba, bb, &c);
        return c;
    }
    return convex_signed_bodies(ba, bb);
}

/* A disjoint TRC pair's signed distance from its certified distance (distance/rim_pair.c); 0 when the
 * prediction declined or found a common point (the depth is the support method's). */
static int rim_signed(const prox_body *ba, const prox_body *bb, prox_signed_result *s)
{
    prox_distance_result d;
    prox_vec3 n;
    if (!prox_rim_pair_distance(ba, bb, &d, &n) || d.intersect) return 0;
    *s = (prox_signed_result){.status = PROX_OK, .sd = d.distance, .normal = n, .p1 = d.p1, .p2 = d.p2,
                              .sd_lower = d.certificate_gap};
    return 1;
}

static prox_signed_result convex_signed_bodies(const prox_body *ba, const prox_body *bb)
{
    prox_signed_result s;
    if (!rim_signed(ba, bb, &s)) s = prox_convex_signed(ba, bb);
    if (s.status == PROX_OK && s.sd > 0.0) {
        prox_vec3 v = prox_v3_sub(s.p2, s.p1);
        double len = prox_v3_norm(v), S = fmax(prox_v3_dist(ba->c, bb->c), fmax(ba->size, bb->size));
        if (len > PROX_TOL_WITNESS_DIR * S) s.normal = prox_v3_scale(v, 1.0 / len);
    }
    prox_body_signed_bounds(ba, bb, &s);
    return s;
}

/* The pair scale of valid shapes. */
static double pair_scale(const prox_shape *a, const prox_shape *b)
{
    prox_vec3 ca, cb;
    double sa, sb;
    prox_query_center_size(a, &ca, &sa);
    prox_query_center_size(b, &cb, &sb);
    return fmax(prox_v3_dist(ca, cb), fmax(sa, sb));
}

/* A polytope against a curved body, built: P the polytope (a POLY body), sp the polytope as the
 * support-function engine takes it (a box as its frame, else P itself), body the curved one; first:
 * the polytope is A. The projections and feature pairs of distance/poly_body.c, answered in the
 * call's order of the pair; returns the outcome (PROX_PB_*). The pair's scale is the engine's,
 * max(|cA - cB|, size_A, size_B). */
typedef struct poly_curved {
    const prox_body *P, *sp, *body;
    int first;
} poly_curved;

static int poly_body_fast(const poly_curved *q, prox_distance_result *r)
{
    const prox_polytope *P = &q->P->x.poly;
    double S = fmax(prox_v3_dist(q->P->c, q->body->c), fmax(P->size, q->body->size));
    *r = (prox_distance_result){0};
    int v = prox_poly_body_fast(P, q->P->c, q->body, S, r);
    if (!q->first) *r = mirror_d(*r);
    return v;
}

static prox_distance_result poly_body_distance(const poly_curved *q)
{
    prox_distance_result r;
    int v = poly_body_fast(q, &r);
    if (v != PROX_PB_OPEN) return r; /* settled */
    /* never coaxial: a polytope is no solid of revolution */
    return q->first ? prox_convex_distance(q->sp, q->body) : prox_convex_distance(q->body, q->sp);
}

/* A disjoint pair from the fast path, with its enclosure (core/signed_bounds.c); an overlapping or
 * unsettled one from the depth's strata when the curved body is an RCC or an ELL
 * (src/sat/poly_curved_depth.c), else, or when the strata do not settle it, from the engine. */
static prox_signed_result poly_body_signed(const poly_curved *q)
{
    prox_distance_result d;
    int v = poly_body_fast(q, &d);
    const prox_body *ba = q->first ? q->sp : q->body, *bb = q->first ? q->body : q->sp;
    if (v != PROX_PB_DISJOINT) {
        prox_signed_result e;
        int strata = q->body->kind == PROX_BODY_CYL || q->body->kind == PROX_BODY_ELL;
        if (strata && prox_sat_poly_curved_depth(q->P, q->body, &e)) {
            if (!q->first) e = mirror_s(e);
            prox_body_signed_bounds(ba, bb, &e);
            return e;
        }
        return convex_signed_bodies(ba, bb);
    }
    prox_signed_result r = prox_signed_from_disjoint(&d);
    prox_body_signed_bounds(ba, bb, &r);
    return r;
}

/* The bodies of a polytope-curved pair of shapes: both validated in the call's order (the polytope as
 * it is built, once). *P the polytope, *sp its engine body (a box's frame, or P), *body the curved. */
static prox_status poly_curved_make(const prox_shape *a, const prox_shape *b, prox_body *P, prox_body *sp,
                                    prox_body *body, poly_curved *q)
{
    int first = kind_poly(a->kind);
    const prox_shape *ps = first ? a : b, *cs = first ? b : a;
    prox_status st = first ? poly_body_checked(a, P) : prox_shape_validate(a);
    if (st == PROX_OK) st = first ? prox_shape_validate(b) : poly_body_checked(b, P);
    if (st != PROX_OK) return st;
    int box = ps->kind == PROX_SHAPE_BOX || ps->kind == PROX_SHAPE_RPP;
    if (box) *sp = prox_body_make(ps);
    *body = prox_body_make(cs);
    *q = (poly_curved){P, box ? sp : P, body, first};
    return PROX_OK;
}

/* ---- public queries ---- */

PROX_API double prox_shape_pair_scale(const prox_shape *a, const prox_shape *b)
{
    if (prox_shape_validate(a) != PROX_OK || prox_shape_validate(b) != PROX_OK) return 0.0;
    return pair_scale(a, b);
}

PROX_API prox_distance_result prox_shape_distance(const prox_shape *a, const prox_shape *b)
{
    prox_distance_result r = {0};
    if ((r.status = check_kinds(a, b)) != PROX_OK) return r;
    if (a->kind == PROX_SHAPE_SPH && b->kind == PROX_SHAPE_SPH) return prox_sph_sph_distance(&a->u.sph, &b->u.sph);
    switch (route_of(a->kind, b->kind)) {
    case ROUTE_SPH_B: return prox_query_sph_distance(a, &b->u.sph, 0);
    case ROUTE_SPH_A: return mirror_d(prox_query_sph_distance(b, &a->u.sph, 1));
    case ROUTE_OLD: {
        norm_shape na, nb;
        if ((r.status = normalise2(a, b, &na, &nb)) != PROX_OK) return r;
        if (rank(na.kind) <= rank(nb.kind)) return dist_canon(&na, &nb);
        r = mirror_d(dist_canon(&nb, &na));
        if (r.status != PROX_OK) r.status = validate2(a, b);
        return r;
    }
    default: break;
    }
    route rt = route_shapes(a, b);
    prox_body x, y, z;
    if (rt == ROUTE_POLY) { /* validates as it builds */
        if ((r.status = poly_pair(a, b, &x, &y)) != PROX_OK) return r;
        return poly_distance(a, b, &x, &y);
    }
    if (rt == ROUTE_POLY_BODY) {
        poly_curved q;
        if ((r.status = poly_curved_make(a, b, &x, &y, &z, &q)) != PROX_OK) return r;
        return poly_body_distance(&q);
    }
    if ((r.status = validate2(a, b)) != PROX_OK) return r;
    bodies(a, b, &x, &y);
    return convex_distance(a, b, &x, &y);
}

/* A sphere s against any shape b: the exact point-to-body distance (closed form, its enclosure set by
 * prox_query_sph_signed). */
static prox_signed_result sph_signed(const prox_shape *b, const prox_shape *s, int sphere_first)
{
    return prox_query_sph_signed(b, &s->u.sph, sphere_first);
}

PROX_API prox_signed_result prox_shape_signed_distance(const prox_shape *a, const prox_shape *b)
{
    prox_signed_result r = {0};
    if ((r.status = check_kinds(a, b)) != PROX_OK) return r;
    switch (route_of(a->kind, b->kind)) {
    case ROUTE_SPH_B: return sph_signed(a, b, 0);
    case ROUTE_SPH_A: return mirror_s(sph_signed(b, a, 1));
    case ROUTE_OLD: {
        norm_shape na, nb;
        if ((r.status = normalise2(a, b, &na, &nb)) != PROX_OK) return r;
        if (rank(na.kind) <= rank(nb.kind)) return signed_canon(&na, &nb);
        r = mirror_s(signed_canon(&nb, &na));
        if (r.status != PROX_OK) r.status = validate2(a, b);
        return r;
    }
    default: break;
    }
    route rt = route_shapes(a, b);
    prox_body x, y, z;
    if (rt == ROUTE_POLY) { /* validates as it builds */
        if ((r.status = poly_pair(a, b, &x, &y)) != PROX_OK) return r;
        return poly_signed(a, b, &x, &y);
    }
    if (rt == ROUTE_POLY_BODY) {
        poly_curved q;
        if ((r.status = poly_curved_make(a, b, &x, &y, &z, &q)) != PROX_OK) return r;
        return poly_body_signed(&q);
    }
    if ((r.status = validate2(a, b)) != PROX_OK) return r;
    bodies(a, b, &x, &y);
    return convex_signed(a, b, &x, &y);
}

/* The verdict of the exact distance: its common point is checked in both solids, its separation
 * certified by a gap (the sign of the distance is the verdict). */
static prox_test_result verdict_of(prox_distance_result d)
{
    prox_test_result r = {0};
    r.status = d.status;
    r.intersect = d.intersect;
    if (d.status == PROX_OK && !d.intersect && d.distance > 0.0) {
        r.direction = prox_v3_normalize(prox_v3_sub(d.p2, d.p1));
        r.value = d.certificate_gap;
    }
    return r;
}

PROX_API prox_test_result prox_shape_test(const prox_shape *a, const prox_shape *b)
{
    prox_test_result r = {0};
    if ((r.status = check_kinds(a, b)) != PROX_OK) return r;
    switch (route_of(a->kind, b->kind)) {
    case ROUTE_SPH_B: return prox_query_sph_test(a, &b->u.sph, 0);
    case ROUTE_SPH_A: return mirror_t(prox_query_sph_test(b, &a->u.sph, 1));
    case ROUTE_OLD: {
        norm_shape na, nb;
        if ((r.status = normalise2(a, b, &na, &nb)) != PROX_OK) return r;
        if (rank(na.kind) <= rank(nb.kind)) return test_canon(&na, &nb);
        r = mirror_t(test_canon(&nb, &na));
        if (r.status != PROX_OK) r.status = validate2(a, b);
        return r;
    }
    default: break;
    }
    return verdict_of(prox_shape_distance(a, b));
}

/* Containment of the specialised pairs (kinds RCC, BOX, SPH after RPP -> BOX). */
static prox_contain_result contains_old(const norm_shape *na, const norm_shape *nb)
{
    const prox_shape *a = na->s, *b = nb->s;
    const prox_rcc *ra = &a->u.rcc, *rb = &b->u.rcc;
    const prox_sph *pa = &a->u.sph, *pb = &b->u.sph;
    switch (na->kind * 4 + nb->kind) {
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_BOX: return prox_box_in_box(&na->box, &nb->box);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_RCC: return prox_box_in_rcc(&na->box, rb);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_SPH: return prox_box_in_sph(&na->box, pb);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_BOX: return prox_rcc_in_box(ra, &nb->box);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_RCC: return prox_rcc_in_rcc(ra, rb);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_SPH: return prox_rcc_in_sph(ra, pb);
    case PROX_SHAPE_SPH * 4 + PROX_SHAPE_BOX: return prox_sph_in_box(pa, &nb->box);
    case PROX_SHAPE_SPH * 4 + PROX_SHAPE_RCC: return prox_sph_in_rcc(pa, rb);
    default: return prox_sph_in_sph(pa, pb);
    }
}

PROX_API prox_contain_result prox_shape_contains(const prox_shape *a, const prox_shape *b)
{
    prox_contain_result r = {0};
    if ((r.status = check_kinds(a, b)) != PROX_OK) return r;
    if (kind_old(a->kind) && kind_old(b->kind)) {
        norm_shape na, nb;
        if ((r.status = normalise2(a, b, &na, &nb)) != PROX_OK) return r;
        return contains_old(&na, &nb);
    }
    if ((r.status = validate2(a, b)) != PROX_OK) return r;
    int certified;
    r.clearance = prox_query_clearance(a, b, &certified);
    r.inside = r.clearance >= -PROX_QUERY_REL_TOL * pair_scale(a, b);
    return r;
}

prox_relation_result prox_shape_relation_with_signed(const prox_shape *a, const prox_shape *b, double tol,
                                                     prox_signed_result *s_out)
{
    prox_relation_result r = {0};
    if (isnan(tol) || isinf(tol)) {
        r.status = PROX_EINVAL_ARG;
        return r;
    }
    prox_signed_result s = prox_shape_signed_distance(a, b);
    if (s_out) *s_out = s;
    r.status = s.status;
    if (r.status != PROX_OK) return r;
    r.tol = tol >= 0.0 ? tol : PROX_QUERY_REL_TOL * pair_scale(a, b);
    r.signed_distance = s.sd;
    if (s.sd > r.tol) {
        r.relation = PROX_REL_DISJOINT;
        return r;
    }
    /* Nested first: an inner solid touching the outer boundary from inside is nested (contact = 1), so
     * a pair is never both "touching" and nested; identical solids are A_IN_B. */
    prox_contain_result ab = prox_shape_contains(a, b), ba = prox_shape_contains(b, a);
    if (ab.clearance >= -r.tol) {
        r.relation = PROX_REL_A_IN_B;
        r.clearance = ab.clearance;
        r.contact = ab.clearance <= r.tol;
    } else if (ba.clearance >= -r.tol) {
        r.relation = PROX_REL_B_IN_A;
        r.clearance = ba.clearance;
        r.contact = ba.clearance <= r.tol;
    } else {
        r.relation = s.sd >= -r.tol ? PROX_REL_TOUCHING : PROX_REL_CROSSING;
        r.contact = 1;
    }
    return r;
}

PROX_API prox_relation_result prox_shape_relation(const prox_shape *a, const prox_shape *b, double tol)
{
    return prox_shape_relation_with_signed(a, b, tol, NULL);
}

static prox_shape translate(const prox_shape *s, prox_vec3 t);

PROX_API prox_reposition_result prox_shape_reposition(const prox_shape *a, const prox_shape *b, double margin)
{
    prox_reposition_result r = {0};
    if (!(margin >= 0.0) || isinf(margin)) {
        r.status = PROX_EINVAL_ARG;
        return r;
    }
    prox_signed_result s = prox_shape_signed_distance(a, b);
    r.status = s.status;
    if (r.status != PROX_OK) return r;
    r.signed_distance = s.sd;
    r.normal = s.normal;
    if (s.sd >= margin) return r;
    r.moved = 1;
    r.translation = prox_v3_scale(s.normal, margin - s.sd);
    /* One correction, measured: the move is only as good as its direction.  A near-touching pair's
     * normal comes from witness points a tiny gap apart (accurate to 1e-12 x scale each), and a
     * move much longer than that gap along a direction off by alpha misses the margin by about
     * length x alpha^2 / 2 (1.6e-11 x scale seen); the depth of an overlapping box-cylinder pair
     * comes from a multi-start search (docs/algorithms/sat.md 2 (f)).  After the move the pair is
     * about margin apart, where its witness direction is accurate, and moving B along it changes
     * the distance by exactly the step. */
    prox_shape b2 = translate(b, r.translation);
    prox_distance_result d = prox_shape_distance(a, &b2);
    double tol = 4.0 * DBL_EPSILON * prox_shape_pair_scale(a, &b2);
    if (d.status == PROX_OK && d.distance > 0.0 && fabs(d.distance - margin) > tol) {
        prox_vec3 n2 = prox_v3_normalize(prox_v3_sub(d.p2, d.p1));
        r.translation = prox_v3_mad(r.translation, margin - d.distance, n2);
        r.normal = prox_v3_normalize(r.translation);
    }
    return r;
}

/* The ARB's corners named by its faces (an unused corner stays zero, as the card leaves it). */
static unsigned arb_used(const prox_arb *a)
{
    unsigned m = 0;
    for (int f = 0; f < 6; ++f)
        for (int x = a->face[f]; x > 0; x /= 10)
            if (x % 10 >= 1 && x % 10 <= 8) m |= 1u << (x % 10 - 1);
    return m;
}

/* s moved by t, by kind (no validation). */
static prox_shape translate(const prox_shape *s, prox_vec3 t)
{
    prox_shape o = *s;
    switch (s->kind) {
    case PROX_SHAPE_RCC: o.u.rcc.base = prox_v3_add(o.u.rcc.base, t); break;
    case PROX_SHAPE_BOX: o.u.box.corner = prox_v3_add(o.u.box.corner, t); break;
    case PROX_SHAPE_SPH: o.u.sph.center = prox_v3_add(o.u.sph.center, t); break;
    case PROX_SHAPE_RPP:
        o.u.rpp.xmin += t.x, o.u.rpp.xmax += t.x;
        o.u.rpp.ymin += t.y, o.u.rpp.ymax += t.y;
        o.u.rpp.zmin += t.z, o.u.rpp.zmax += t.z;
        break;
    case PROX_SHAPE_TRC: o.u.trc.base = prox_v3_add(o.u.trc.base, t); break;
    case PROX_SHAPE_REC: o.u.rec.base = prox_v3_add(o.u.rec.base, t); break;
    case PROX_SHAPE_ELL: o.u.ell.center = prox_v3_add(o.u.ell.center, t); break;
    case PROX_SHAPE_RHP: o.u.rhp.base = prox_v3_add(o.u.rhp.base, t); break;
    case PROX_SHAPE_WED: o.u.wed.vertex = prox_v3_add(o.u.wed.vertex, t); break;
    case PROX_SHAPE_ARB: {
        unsigned m = arb_used(&s->u.arb);
        for (int i = 0; i < 8; ++i)
            if (m >> i & 1u) o.u.arb.corner[i] = prox_v3_add(o.u.arb.corner[i], t);
        break;
    }
    default: break;
    }
    return o;
}

PROX_API prox_status prox_shape_translated(const prox_shape *s, prox_vec3 t, prox_shape *out)
{
    if (!s || !out) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(t)) return PROX_EINVAL_NONFINITE;
    prox_shape o = translate(s, t);
    prox_status st = prox_shape_validate(&o);
    if (st == PROX_OK) *out = o;
    return st;
}

/* ---- prepared solids (prox/solid.h) ----
 * A solid keeps what the routes above build on every call: its polytope (a POLY body) when it is a
 * polytope kind that keeps its shape, and its support body (prox_body_make's; for RHP, WED and ARB
 * the polytope itself, as the polytope-curved route takes it). The routes that build nothing dear
 * (the specialised pairs of RCC, BOX, RPP, SPH and a sphere against anything) take the shapes. */
struct prox_solid {
    prox_shape shape;
    int fits;       /* a polytope kind whose polytope keeps its shape (poly_fits): poly is built */
    prox_body poly; /* the polytope (kind PROX_BODY_POLY) */
    prox_body body; /* the support body */
};

PROX_API prox_solid *prox_solid_new(const prox_shape *s, prox_status *status)
{
    prox_status st = !s ? PROX_EINVAL_ARG : check_kinds(s, s);
    prox_solid *o = NULL;
    if (st == PROX_OK && !(o = malloc(sizeof *o))) st = PROX_ENOMEM;
    if (st == PROX_OK) {
        o->shape = *s;
        o->fits = kind_poly(s->kind) && poly_fits(s);
        st = o->fits ? poly_body_checked(s, &o->poly) : prox_shape_validate(s);
        if (st == PROX_OK) {
            int prism = o->fits && s->kind != PROX_SHAPE_BOX && s->kind != PROX_SHAPE_RPP;
            if (prism) o->body = o->poly;
            else o->body = prox_body_make(s);
        }
    }
    if (st != PROX_OK) free(o), o = NULL;
    if (status) *status = st;
    return o;
}

PROX_API void prox_solid_free(prox_solid *s) { free(s); }

PROX_API const prox_shape *prox_solid_shape(const prox_solid *s) { return s ? &s->shape : NULL; }

/* The route of a pair of solids: route_shapes on what the solids know. */
static route solid_route(const prox_solid *a, const prox_solid *b)
{
    route r = route_of(a->shape.kind, b->shape.kind);
    return r == ROUTE_POLY || r == ROUTE_POLY_BODY ? route_fitted(r, a->shape.kind, a->fits, b->fits) : r;
}

/* The polytope-curved pair of two solids. */
static poly_curved solid_poly_curved(const prox_solid *a, const prox_solid *b)
{
    int first = kind_poly(a->shape.kind);
    const prox_solid *p = first ? a : b, *c = first ? b : a;
    return (poly_curved){&p->poly, &p->body, &c->body, first};
}

/* An RCC's squared height |axis|^2 as its validation computes it (0 for another kind). */
static double rcc_h2(const prox_shape *s) { return s->kind == PROX_SHAPE_RCC ? prox_v3_norm2(s->u.rcc.axis) : 0.0; }

PROX_API prox_distance_result prox_solid_distance(const prox_solid *a, const prox_solid *b)
{
    if (!a || !b) return (prox_distance_result){.status = PROX_EINVAL_ARG};
    const prox_shape *sa = &a->shape, *sb = &b->shape;
    if (sa->kind == PROX_SHAPE_SPH && sb->kind == PROX_SHAPE_SPH) return prox_sph_sph_distance_valid(&sa->u.sph, &sb->u.sph);
    switch (solid_route(a, b)) {
    case ROUTE_POLY: return poly_distance(sa, sb, &a->poly, &b->poly);
    case ROUTE_POLY_BODY: {
        poly_curved q = solid_poly_curved(a, b);
        return poly_body_distance(&q);
    }
    case ROUTE_CONVEX: return convex_distance(sa, sb, &a->body, &b->body);
    case ROUTE_SPH_B: return prox_query_sph_distance_valid(sa, &sb->u.sph, rcc_h2(sa));
    case ROUTE_SPH_A: return mirror_d(prox_query_sph_distance_valid(sb, &sa->u.sph, rcc_h2(sb)));
    default: return prox_shape_distance(sa, sb);
    }
}

PROX_API prox_signed_result prox_solid_signed_distance(const prox_solid *a, const prox_solid *b)
{
    if (!a || !b) return (prox_signed_result){.status = PROX_EINVAL_ARG};
    const prox_shape *sa = &a->shape, *sb = &b->shape;
    if (sa->kind == PROX_SHAPE_SPH && sb->kind == PROX_SHAPE_SPH) return prox_sph_sph_signed_valid(&sa->u.sph, &sb->u.sph);
    switch (solid_route(a, b)) {
    case ROUTE_POLY: return poly_signed(sa, sb, &a->poly, &b->poly);
    case ROUTE_POLY_BODY: {
        poly_curved q = solid_poly_curved(a, b);
        return poly_body_signed(&q);
    }
    case ROUTE_CONVEX: return convex_signed(sa, sb, &a->body, &b->body);
    case ROUTE_SPH_B: return prox_query_sph_signed_valid(sa, &sb->u.sph, rcc_h2(sa));
    case ROUTE_SPH_A: return mirror_s(prox_query_sph_signed_valid(sb, &sa->u.sph, rcc_h2(sb)));
    default: return prox_shape_signed_distance(sa, sb);
    }
}

PROX_API prox_test_result prox_solid_test(const prox_solid *a, const prox_solid *b)
{
    if (!a || !b) return (prox_test_result){.status = PROX_EINVAL_ARG};
    route r = route_of(a->shape.kind, b->shape.kind);
    if (r == ROUTE_OLD || r == ROUTE_SPH_A || r == ROUTE_SPH_B) return prox_shape_test(&a->shape, &b->shape);
    return verdict_of(prox_solid_distance(a, b));
}
