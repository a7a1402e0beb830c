/* Internal (core): the generic convex body of the support-function method and of every shape-agnostic
 * query (scene bounds, containment scales): one of the four macrobodies kept as its centre c plus its
 * geometry in coordinates centred at c. Every macrobody is centrally symmetric, so its support function
 * splits as h(d) = d.c + hc(d) with the centred part hc even in d (hc(-d) = hc(d)).
 *
 * The per-kind geometry is the core's: a cylinder is a prox_cyl (core/cyl.h, Eberly's Eq. 4 support
 * function), a box (BOX, and RPP as the box it describes) a prox_bframe (core/box.h), a sphere its
 * radius (hc(d) = r |d|). Both are prepared relative to the centre, so hc and the centred support
 * point carry no cancellation against the body's position. */
#ifndef PROX_CORE_BODY_H
#define PROX_CORE_BODY_H

#include "core/box.h"
#include "core/curved.h"
#include "core/cyl.h"
#include "core/polytope.h"
#include "core/tol.h"
#include "prox/result.h"
#include "prox/shapes.h"

/* CYL, BOX and SPH are centrally symmetric about c (hc even); the macrobodies added after them are
 * kept relative to a reference point c of their own (core/polytope.h, core/curved.h) and their hc
 * need not be even: RHP, WED, ARB are POLY; TRC is CONE; REC is ECYL; ELL is ELL. */
typedef enum prox_body_kind {
    PROX_BODY_CYL = 0,
    PROX_BODY_BOX = 1,
    PROX_BODY_SPH = 2,
    PROX_BODY_POLY = 3,
    PROX_BODY_CONE = 4,
    PROX_BODY_ECYL = 5,
    PROX_BODY_ELL = 6
} prox_body_kind;

typedef struct prox_body {
    prox_body_kind kind;
    prox_vec3 c;     /* centre (absolute coordinates) */
    prox_cyl cyl;    /* PROX_BODY_CYL: the cylinder relative to c (cyl.c = 0) */
    prox_bframe box; /* PROX_BODY_BOX: the box relative to c (box.m = 0) */
    double r;        /* PROX_BODY_SPH: radius */
    double size;     /* largest dimension (tolerance scale): height or diameter, largest edge */
    union {          /* the added kinds, relative to c */
        prox_polytope poly;
        prox_cone cone;
        prox_ecyl ecyl;
        prox_ellb ell;
    } x;
} prox_body;

/* 1 when the body is centrally symmetric about c (hc(-d) = hc(d)): what the support engine's
 * ridge search of the cylinder and box pairs assumes. */
static inline int prox_body_symmetric(const prox_body *b) { return b->kind <= PROX_BODY_SPH; }

/* The body of a valid shape (validate first: this is the hot path of the generic queries). */
prox_body prox_body_make(const prox_shape *s);

/* The body of a valid cylinder written in place, only the fields a PROX_BODY_CYL uses (the head up
 * to the added kinds' union): the depth's hot path builds two for every pair. */
void prox_body_make_cyl(const prox_rcc *c, prox_body *b);

/* The body of a polytope already built (prox_polytope_make or prox_polytope_checked), reference
 * point c. */
prox_body prox_body_of_polytope(const prox_polytope *p, prox_vec3 c);

/* Centred support function hc(d) = h(d) - d.c (d need not be unit; hc(0) = 0). */
static inline double prox_body_hc(const prox_body *b, prox_vec3 d)
{
    switch (b->kind) {
    case PROX_BODY_CYL: return prox_cyl_hc(&b->cyl, d);
    case PROX_BODY_BOX: return prox_bframe_support(&b->box, d); /* box.m = 0: the centred part alone */
    case PROX_BODY_SPH: return b->r * prox_v3_norm(d);
    case PROX_BODY_POLY: return prox_polytope_hc(&b->x.poly, d);
    case PROX_BODY_CONE: return prox_cone_hc(&b->x.cone, d);
    case PROX_BODY_ECYL: return prox_ecyl_hc(&b->x.ecyl, d);
    default: return prox_ellb_hc(&b->x.ell, d);
    }
}

/* Centred support point: x - c for a point x of the body with d.x = h(d). A zero component of d
 * (d along a face or perpendicular to an axis) picks the middle of the support set; d = 0 gives 0. */
prox_vec3 prox_body_pc(const prox_body *b, prox_vec3 d);

/* Support function and support point in absolute coordinates. */
static inline double prox_body_support(const prox_body *b, prox_vec3 d) { return prox_v3_dot(d, b->c) + prox_body_hc(b, d); }
static inline prox_vec3 prox_body_support_point(const prox_body *b, prox_vec3 d)
{
    return prox_v3_add(b->c, prox_body_pc(b, d));
}

/* The cylinder of a PROX_BODY_CYL body in absolute coordinates (its frame moved to the centre). */
static inline prox_cyl prox_body_cyl(const prox_body *b)
{
    prox_cyl k = b->cyl;
    k.c = b->c;
    k.cap[0] = k.b = prox_v3_add(b->c, b->cyl.cap[0]);
    k.cap[1] = prox_v3_add(b->c, b->cyl.cap[1]);
    return k;
}

/* A cylinder scaled by f about the origin (f a power of two: exact). */
static inline prox_cyl prox_cyl_scaled(const prox_cyl *k, double f)
{
    prox_cyl s = *k;
    s.b = prox_v3_scale(k->b, f);
    s.c = prox_v3_scale(k->c, f);
    s.cap[0] = prox_v3_scale(k->cap[0], f);
    s.cap[1] = prox_v3_scale(k->cap[1], f);
    s.h *= f, s.hh *= f, s.r *= f;
    return s;
}

/* The body scaled by f about the origin (f a power of two: exact, barring underflow below 1e-300,
 * which the supported range excludes). The support method runs a pair at unit scale, where no square
 * or product of its coordinates and sizes can overflow or underflow. */
prox_body prox_body_scaled(const prox_body *b, double f);

/* *s = b with centre c, scaled by f about the origin, written in place: the common part and the
 * union's member of b's kind alone are copied (a polytope's 800 bytes only for a polytope). */
void prox_body_scaled_at(prox_body *s, const prox_body *b, prox_vec3 c, double f);

/* The power of two nearest below 1/S: scaling a pair of scale S by it brings S into [1, 2). */
double prox_unit_scale(double S);

/* 1 when x (absolute coordinates) lies in the closed body enlarged by tol (tol >= 0, absolute). */
int prox_body_contains(const prox_body *b, prox_vec3 x, double tol);

/* Closest point of the solid body to x (x itself when inside), absolute coordinates. */
prox_vec3 prox_body_closest(const prox_body *b, prox_vec3 x);
/* The same along a sequence of nearby points: *warm (NAN at first) carries what the body's closest-point
 * iteration can start the next point from (the ELL's secular root, core/ellipse2.h); ignored by the
 * closed forms. */
prox_vec3 prox_body_closest_warm(const prox_body *b, prox_vec3 x, double *warm);

/* The certificate of a disjoint pair x in A, y in B (A's reference point at the origin, B's at delta:
 * the support method's relative frame; S the pair's scale): along the pair's own direction
 * n = (y - x) / |y - x| the weak-duality bound -phi(n) = -(hc_A(n) + hc_B(-n) - n.delta) <= distance
 * <= |y - x| meets |y - x| within PROX_TOL_CERT S, and x and y lie in their solids (within
 * PROX_TOL_TOUCH S: a support point put off its solid by rounding would certify a value below the
 * distance). Along n itself, because a pair that meets -phi only at some other direction can lie
 * ~sqrt(slack x size) off the closest points. A pair within the touching band (its direction is
 * rounding) is never certified. nf (may be NULL): the exact normal of the pair's features (a face's,
 * a side line's), tried when the pair's own direction falls short by no more than rounding can cost
 * and y - x lies along nf to PROX_TOL_CERT S: the rounding of nearby points (4 eps S) turns their
 * direction by up to 4 eps S / |y - x|, which costs the bound first order, up to 2 S times that, where
 * a kink of phi passes through the normal (a side line's great circle, a face's normal).
 * Returns 1 with *lower = -phi at the direction used, *upper = |y - x| and that direction *n. */
int prox_body_pair_certified(const prox_body *a, const prox_body *b, prox_vec3 delta, double S, prox_vec3 x,
                             prox_vec3 y, const prox_vec3 *nf, double *lower, double *upper, prox_vec3 *n);
/* Signed distance from x to the body's boundary (< 0 inside) and the closest boundary point *q,
 * absolute coordinates: the exact sphere-against-anything query is this minus the radius. */
double prox_body_boundary(const prox_body *b, prox_vec3 x, prox_vec3 *q);

/* Sets the proved enclosure of a signed answer (r->sd_lower, sd_upper, certified; result.h) for A and
 * B given as bodies. On entry r->certified = 1 says the method proved its depth (overlapping pairs),
 * a negative r->sd_upper is the method's own proved bound when it has one (a covering), and a positive
 * r->sd_lower of a disjoint answer is the method's duality certificate (certificate_gap), a negative
 * one of an overlapping answer -phi at the method's best direction (both lower bounds of sd). */
void prox_body_signed_bounds(const prox_body *a, const prox_body *b, prox_signed_result *r);
/* The enclosure of a closed-form answer (a sphere against anything: the exact point distance, whose
 * gap along its normal and whose witnesses' separation are sd itself): sd within its rounding,
 * PROX_TOL_BOUND x the scale of the quantities it was computed from; certified. */
static inline void prox_signed_closed_form(prox_signed_result *r, double scale)
{
    double err = 2.0 * PROX_TOL_BOUND * scale;
    r->sd_lower = r->sd - err;
    r->sd_upper = r->sd > 0.0 ? r->sd + err : fmin(r->sd + err, 0.0);
    r->certified = 1;
}

/* The same for two valid shapes. */
void prox_shape_signed_bounds(const prox_shape *a, const prox_shape *b, prox_signed_result *r);

#endif
