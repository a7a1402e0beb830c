/* Certified support-function method for any pair of convex bodies (convex.h,
 * docs/algorithms/convex_engine.md).
 *
 * Duality (Eberly, "Intersection of Cylinders", Secs. 3-4, turned from a sign test into an
 * optimisation; Gilbert, Johnson & Keerthi 1988 for the distance): with phi(D) = h_A(D) + h_B(-D),
 * the support function of P = A - B,
 *     disjoint:     distance = max_{|D|=1} -phi(D)  = distance from the origin to P,
 *     overlapping:  depth    = min_{|D|=1}  phi(D)  = distance from the origin to the boundary of P.
 * The pair is kept relative to A's reference point (Delta = cB - cA) and at unit scale, so
 * phi(D) = hcA(D) + hcB(-D) - D.Delta, grad phi(D) = pcA(D) - pcB(-D) - Delta (a support point of P,
 * a subgradient on the kinks), Hess phi(D) = HA(D) + HB(-D) where both are smooth.
 *
 * Steps. GJK on P with exact support points (finite for polytope pairs; witnesses as barycentric
 * combinations) decides the verdict and starts the search. Disjoint: Riemannian Newton on the sphere
 * (the Riemannian Hessian T^T H T - phi I is positive definite when phi < 0) in the cells where both
 * hc are smooth, and exact one-dimensional solves on each kink of either body near the optimum (the
 * cone points and face normals, the great circles of side lines and polytope edges, the small circle
 * of a cone's lateral surface) and at their crossings: phi is smooth along each kink circle, so
 * regula falsi with the Illinois halving on its derivative reaches it to rounding; polytope faces and
 * edges are points and circles of this list, so the answer is reached in finitely many steps. The witnesses are the
 * closest pair of the two support sets (points, segments, polygons, disks and ellipses) seen along
 * the normal, polished by exact projections; certified when |p2 - p1| meets -phi within
 * PROX_TOL_CERT S. Overlapping: global sampling, every kink circle searched whole, Newton from the best
 * starts, then a cover of the sphere by geodesic triangles proves a lower bound on the depth: over a
 * cap of radius rho around D_c, phi >= |g| cos(angle(g, D_c) + rho) with g the support point of P at
 * D_c (h_P is convex and g.D <= h_P(D)), and phi >= the sum of each body's exact minimum over the
 * cap (hc of a sphere, ellipsoid, cylinder and cone is a function of D.w alone); Newton and the local
 * kinks run once more from the best direction the cover left (it can be a non-stationary cell centre).
 * Before the global search an overlap tries a quick one (the best of a few starts, Newton and the
 * kinks near it) proved by an inner polytope of P (epa.h: a closed mesh of support points around the
 * origin, whose nearest triangle bounds the depth from below) or by tangent balls at the witnesses.
 * The distance query first tries cheap certificates (GJK's simplex pair; Newton and the support sets
 * at its best direction), each accepted only when -phi along the pair's own direction meets it. */
#include "convex.h"

#include "ell_depth.h"
#include "epa.h"
#include "core/axis.h"
#include "core/edge_root.h"
#include "core/minmax.h"
#include "core/pl_disk.h"
#include "core/plane2.h"
#include "core/tol.h"

#include <float.h>
#include <stdatomic.h>
#include <stddef.h>
#include <string.h>

#define CVX_MAXK 64        /* kinks of a pair: a polytope has <= 8 faces and 18 edges */
#define CVX_TOPK 6         /* distinct starts of the local depth search */
#define CVX_GJK_IT 96      /* GJK iterations (polytopes finish in far fewer) */
#define CVX_CIRCLE_SAMPLES 64
#define CVX_GRAD_HALVINGS 8

#define CVX_LOCAL 0.05     /* radius (rad) of the local kink search around the best direction */
#define CVX_NEAR 1e-5      /* a direction this close (rad) to a kink names it for the witnesses */
#define CVX_BB_DEPTH 40    /* cover of the sphere: icosahedron faces split up to 40 times (1e-12 rad) */
#define CVX_BB_BUDGET 40000
#define CVX_GOLD 1.6180339887498948482 /* the icosahedron (0, +-1, +-golden) and its cyclic shifts */
#define CVX_NEAR_GJK 1e-4  /* radius (rad) of the early kink search around GJK's best direction */
#define CVX_GJK_LOOSE 1e-6 /* every pair's first GJK stops at this relative gap (then Newton, kinks) */
#define CVX_NEAR_LOOSE 1e-3 /* radius (rad) of the early kink search after that loose GJK: its best
                             * direction is ~sqrt(1e-6) off along a rim, ~1e-6 across one */
#define CVX_EPA_POINTS 140 /* support points the depth's inner polytope may take (epa.h) */
#define CVX_EPA_POINTS_SMOOTH 300 /* the same for a pair without kinks, whose polytope is built only
                                   * when the tangent balls fail (a deep overlap) and whose triangles
                                   * must shrink over a curved patch until its sag is within the
                                   * proof's 1e-10 S: at 140 points 18 of 727 overlapping ELL-ELL
                                   * pairs of the bench's mix generator were left to the cover, none
                                   * at 300; kinked pairs stalled there gain nothing from more */
#define CVX_EPA_TURNS 2     /* polytopes a kinked pair may build from the turned icosahedron (depth_quick) */
#define CVX_EPA_LOCAL 1e-3 /* radius (rad) of the kink search around the polytope's deepest direction,
                            * which its proof puts ~1e-5 rad from the optimum (within 1e-10 S of it) */

static atomic_ulong cvx_global_runs;

unsigned long prox_convex_global_count(void) { return atomic_load(&cvx_global_runs); }

static atomic_ulong cvx_gjk_cert; /* distance queries certified by an early exit */

/* ---- the pair --------------------------------------------------------------------------------- */

/* A kink of phi: the point D = w (circle = 0) or the circle D.w = c (great circle when c = 0), of
 * angular radius atan2(sn, c) about w (sn = sqrt(1 - c^2), kept on its own: a flat cone's 2e-10 rad
 * circle has c = -1 in doubles). */
typedef struct cvx_kink {
    int circle;
    prox_vec3 w;
    double c, sn;
} cvx_kink;

typedef struct cvx {
    prox_body a, b;   /* relative to A's reference point, unit scale */
    prox_vec3 delta;  /* b.c - a.c */
    double S;         /* scale of the scaled pair */
    double gjk_rel;   /* GJK also stops at |v| + phi <= gjk_rel |v| (0: only at rounding) */
    double near;      /* radius (rad) of the early kink search around GJK's best direction */
    double best_phi;
    prox_vec3 best_d;
    int halvings;     /* of a gradient step's line search (newton_step) */
    int nhalvings;    /* of a Newton step's line search */
    int nk;
    cvx_kink k[CVX_MAXK];
    int ntop;
    double tphi[CVX_TOPK];
    prox_vec3 td[CVX_TOPK];
} cvx;

static prox_vec3 unit(prox_vec3 d) { return prox_v3_scale(d, 1.0 / prox_v3_norm(d)); }
static double angle(prox_vec3 a, prox_vec3 b) { return atan2(prox_v3_norm(prox_v3_cross(a, b)), prox_v3_dot(a, b)); }

static double phi_eval(const cvx *s, prox_vec3 d)
{
    return prox_body_hc(&s->a, d) + prox_body_hc(&s->b, prox_v3_neg(d)) - prox_v3_dot(d, s->delta);
}

static prox_vec3 phi_grad(const cvx *s, prox_vec3 d)
{
    return prox_v3_sub(prox_v3_sub(prox_body_pc(&s->a, d), prox_body_pc(&s->b, prox_v3_neg(d))), s->delta);
}

/* The Hessian of a body's hc at d as a bilinear form on two tangent vectors t1, t2 of the sphere at
 * d: h[0] += t1.H t1, h[1] += t1.H t2, h[2] += t2.H t2 (newton_step's 2 x 2 system, one call a body
 * instead of one Hessian-vector product per tangent vector). */

/* sqrt(d^T M d): H = (M - (Md)(Md)^T / q^2) / q with q^2 = d.Md, from t1.M t2 (m12 and the diagonal
 * m11, m22) and md.t1, md.t2. */
static void sqrt_form(double q, double m11, double m12, double m22, double e1, double e2, double h[3])
{
    if (!(q > 0.0)) return;
    double iq = 1.0 / q, iq2 = iq * iq;
    h[0] += (m11 - e1 * e1 * iq2) * iq, h[1] += (m12 - e1 * e2 * iq2) * iq, h[2] += (m22 - e2 * e2 * iq2) * iq;
}

/* k (x1.x2) over the projections x1, x2 of the tangent vectors: the form of k times a projection. */
static void proj_form(double k, prox_vec3 x1, prox_vec3 x2, double h[3])
{
    h[0] += k * prox_v3_norm2(x1), h[1] += k * prox_v3_dot(x1, x2), h[2] += k * prox_v3_norm2(x2);
}

/* r |P d| (P the projection across the unit axis w): H = r/|Pd| (P - p p^T), p = Pd / |Pd|, the
 * projection across w and p; each tangent vector projected once. A radius below PROX_TOL_NOISE of the
 * unit-scale pair adds less than rounding to phi, and near the axis r / |Pd| would swamp the other
 * body's curvature (a needle's end against a flat ellipsoid: 4e212, and the Newton polish of the
 * normal could not move): it is left out. */
static void lateral_form(prox_vec3 w, double r, prox_vec3 d, prox_vec3 t1, prox_vec3 t2, double h[3])
{
    prox_vec3 perp = prox_v3_reject(d, w);
    double n = prox_v3_norm(perp);
    if (!(n > 0.0) || !(r > PROX_TOL_NOISE)) return;
    prox_vec3 p = prox_v3_scale(perp, 1.0 / n);
    proj_form(r / n, prox_v3_reject(prox_v3_reject(t1, w), p), prox_v3_reject(prox_v3_reject(t2, w), p), h);
}

/* The form of hc's Hessian at d, where hc is smooth (zero for the polytopes). */
static void hc_form(const prox_body *b, prox_vec3 d, prox_vec3 t1, prox_vec3 t2, double h[3])
{
    switch (b->kind) {
    case PROX_BODY_SPH: { /* r |d|: H = r / |d| (I - d d^T / |d|^2) */
        double n = prox_v3_norm(d);
        prox_vec3 u = prox_v3_scale(d, 1.0 / n);
        proj_form(b->r / n, prox_v3_reject(t1, u), prox_v3_reject(t2, u), h);
        return;
    }
    case PROX_BODY_CYL: lateral_form(b->cyl.w, b->cyl.r, d, t1, t2, h); return;
    case PROX_BODY_CONE: {
        const prox_cone *k = &b->x.cone;
        double t = prox_v3_dot(d, k->w), p = prox_v3_norm(prox_v3_reject(d, k->w));
        double top = k->hh * t + k->r2 * p, base = -k->hh * t + k->r1 * p;
        lateral_form(k->w, top >= base ? k->r2 : k->r1, d, t1, t2, h);
        return;
    }
    case PROX_BODY_ECYL: { /* M = a1^2 u1 u1^T + a2^2 u2 u2^T */
        const prox_ecyl *k = &b->x.ecyl;
        double s1 = k->a1 * k->a1, s2 = k->a2 * k->a2, d1 = prox_v3_dot(d, k->u1), d2 = prox_v3_dot(d, k->u2);
        double p1 = prox_v3_dot(t1, k->u1), p2 = prox_v3_dot(t2, k->u1), q1 = prox_v3_dot(t1, k->u2), q2 = prox_v3_dot(t2, k->u2);
        sqrt_form(sqrt(s1 * d1 * d1 + s2 * d2 * d2), s1 * p1 * p1 + s2 * q1 * q1, s1 * p1 * p2 + s2 * q1 * q2,
                  s1 * p2 * p2 + s2 * q2 * q2, s1 * d1 * p1 + s2 * d2 * q1, s1 * d1 * p2 + s2 * d2 * q2, h);
        return;
    }
    case PROX_BODY_ELL: { /* M = a^2 w w^T + b^2 (I - w w^T), applied by parts: as b^2 I + (a^2 - b^2) w w^T
                           * it loses a^2 below eps b^2 (a flat ellipsoid at its pole: d.Md of 0) */
        const prox_ellb *k = &b->x.ell;
        double a2 = k->a * k->a, b2 = k->b * k->b, dw = prox_v3_dot(d, k->w), w1 = prox_v3_dot(t1, k->w), w2 = prox_v3_dot(t2, k->w);
        prox_vec3 dp = prox_v3_reject(d, k->w), x1 = prox_v3_reject(t1, k->w), x2 = prox_v3_reject(t2, k->w);
        sqrt_form(prox_hypot2(k->a * dw, k->b * prox_v3_norm(dp)), b2 * prox_v3_norm2(x1) + a2 * w1 * w1,
                  b2 * prox_v3_dot(x1, x2) + a2 * w1 * w2, b2 * prox_v3_norm2(x2) + a2 * w2 * w2,
                  b2 * prox_v3_dot(dp, x1) + a2 * dw * w1, b2 * prox_v3_dot(dp, x2) + a2 * dw * w2, h);
        return;
    }
    default: return;
    }
}

/* The tangent Hessian form of phi at d: A's hc at d and B's at -d (two sign changes cancel). */
static void phi_form(const cvx *s, prox_vec3 d, prox_vec3 t1, prox_vec3 t2, double h[3])
{
    h[0] = h[1] = h[2] = 0.0;
    hc_form(&s->a, d, t1, t2, h);
    hc_form(&s->b, prox_v3_neg(d), t1, t2, h);
}

/* Keeps d (unit) with its value: the best, and the list of distinct good starts. */
static void record(cvx *s, prox_vec3 d, double f)
{
    if (f < s->best_phi) s->best_phi = f, s->best_d = d;
    for (int i = 0; i < s->ntop; ++i)
        if (prox_v3_dot(d, s->td[i]) > 1.0 - PROX_TOL_SAME_START) {
            if (f < s->tphi[i]) s->tphi[i] = f, s->td[i] = d;
            return;
        }
    int slot = s->ntop < CVX_TOPK ? s->ntop++ : -1;
    if (slot < 0) {
        slot = 0;
        for (int i = 1; i < CVX_TOPK; ++i)
            if (s->tphi[i] > s->tphi[slot]) slot = i;
        if (!(f < s->tphi[slot])) return;
    }
    s->tphi[slot] = f;
    s->td[slot] = d;
}

static double consider(cvx *s, prox_vec3 d)
{
    double n = prox_v3_norm(d);
    if (!(n > 0.0) || !prox_v3_isfinite(d)) return INFINITY;
    d = prox_v3_scale(d, 1.0 / n);
    double f = phi_eval(s, d);
    record(s, d, f);
    return f;
}

/* ---- kinks -------------------------------------------------------------------------------------- */

static void add_kink_cs(cvx *s, int circle, prox_vec3 w, double c, double sn)
{
    if (s->nk >= CVX_MAXK) return;
    for (int i = 0; i < s->nk; ++i) { /* the same circle or point twice (parallel box edges) */
        const cvx_kink *k = &s->k[i];
        if (k->circle != circle) continue;
        double dw = prox_v3_dot(k->w, w);
        if (!circle && dw > 1.0 - PROX_TOL_SAME_START) return;
        if (circle && ((dw > 1.0 - 1e-15 && fabs(k->c - c) < 1e-15) || (dw < -1.0 + 1e-15 && fabs(k->c + c) < 1e-15))) return;
    }
    cvx_kink *k = &s->k[s->nk++];
    k->circle = circle;
    k->w = w;
    k->c = c;
    k->sn = sn;
}

static void add_kink(cvx *s, int circle, prox_vec3 w, double c) { add_kink_cs(s, circle, w, c, sqrt(fmax(0.0, 1.0 - c * c))); }

/* The kinks of body b in the direction sg D (sg = 1 for A, -1 for B), as kinks in D: where hc is not
 * differentiable. A point u of b is the point sg u in D; a circle E.w = c in E = sg D is D.w = sg c. */
static void body_kinks(cvx *s, const prox_body *b, double sg)
{
    switch (b->kind) {
    case PROX_BODY_CYL:
        add_kink(s, 0, b->cyl.w, 0), add_kink(s, 0, prox_v3_neg(b->cyl.w), 0), add_kink(s, 1, b->cyl.w, 0);
        break;
    case PROX_BODY_BOX:
        for (int i = 0; i < 3; ++i)
            add_kink(s, 0, b->box.a[i], 0), add_kink(s, 0, prox_v3_neg(b->box.a[i]), 0), add_kink(s, 1, b->box.a[i], 0);
        break;
    case PROX_BODY_POLY: {
        const prox_polytope *p = &b->x.poly;
        for (int f = 0; f < p->nf; ++f) add_kink(s, 0, prox_v3_scale(p->n[f], sg), 0);
        for (int e = 0; e < p->ne; ++e) add_kink(s, 1, unit(prox_v3_sub(p->v[p->e[e][1]], p->v[p->e[e][0]])), 0);
        break;
    }
    case PROX_BODY_CONE: {
        const prox_cone *k = &b->x.cone;
        double nt, nr; /* the lateral normal: D.w / |P D| = (r1 - r2) / (2 hh) */
        prox_cone_lateral_normal(k, &nt, &nr);
        add_kink(s, 0, k->w, 0), add_kink(s, 0, prox_v3_neg(k->w), 0);
        add_kink_cs(s, 1, k->w, sg * nt, nr);
        break;
    }
    case PROX_BODY_ECYL:
        add_kink(s, 0, b->x.ecyl.w, 0), add_kink(s, 0, prox_v3_neg(b->x.ecyl.w), 0), add_kink(s, 1, b->x.ecyl.w, 0);
        break;
    default: break;
    }
}

/* Angular distance from unit d to a kink (approximate off the kink, exact on it). */
static double kink_dist(const cvx_kink *k, prox_vec3 d)
{
    if (!k->circle) return angle(d, k->w);
    if (k->sn < 0.1) return fabs(angle(d, k->w) - atan2(k->sn, k->c)); /* a small circle: its radius as an angle */
    return fabs(prox_v3_dot(d, k->w) - k->c) / k->sn;
}

/* The crossings of two kink circles: D = x w1 + y w2 +- z n; returns how many (0 or 2). */
static int circle_cross(const cvx_kink *k1, const cvx_kink *k2, prox_vec3 out[2])
{
    prox_vec3 n = prox_v3_cross(k1->w, k2->w);
    double nn = prox_v3_norm(n);
    if (!(nn > PROX_TOL_PARALLEL)) return 0;
    double m = prox_v3_dot(k1->w, k2->w), det = nn * nn;
    double x = (k1->c - m * k2->c) / det, y = (k2->c - m * k1->c) / det;
    prox_vec3 p = prox_v3_add(prox_v3_scale(k1->w, x), prox_v3_scale(k2->w, y));
    double z2 = 1.0 - prox_v3_norm2(p);
    if (z2 < -1e-12) return 0;
    double z = sqrt(fmax(0.0, z2));
    n = prox_v3_scale(n, 1.0 / nn);
    out[0] = prox_v3_mad(p, z, n);
    out[1] = prox_v3_mad(p, -z, n);
    return 2;
}

/* ---- one-dimensional search along a kink circle ---------------------------------------------- */

/* The circle D(th) = c w + s (cos th u + sin th v), s = sqrt(1 - c^2). */
typedef struct cvx_circ {
    prox_vec3 w, u, v;
    double c, s;
} cvx_circ;

static cvx_circ circ_make(const cvx_kink *k)
{
    cvx_circ C = {k->w, prox_v3_any_perp(k->w), {0, 0, 0}, k->c, k->sn};
    C.v = prox_v3_cross(k->w, C.u);
    return C;
}

static prox_vec3 circ_at(const cvx_circ *C, double th)
{
    return prox_v3_mad(prox_v3_scale(C->w, C->c), C->s, prox_v3_add(prox_v3_scale(C->u, cos(th)), prox_v3_scale(C->v, sin(th))));
}

/* d phi / d th: along the circle the support sets of its own kink are perpendicular to the tangent,
 * so any support point gives the derivative. */
static double circ_slope(const cvx *s, const cvx_circ *C, double th, prox_vec3 d)
{
    prox_vec3 t = prox_v3_scale(prox_v3_sub(prox_v3_scale(C->v, cos(th)), prox_v3_scale(C->u, sin(th))), C->s);
    return prox_v3_dot(phi_grad(s, d), t);
}

/* The slope and, recorded, the value phi(d) = g . d from the same support point g of P (one pair of
 * support points instead of two evaluations). */
static double circ_step(cvx *s, const cvx_circ *C, double th, prox_vec3 d, double *f)
{
    prox_vec3 t = prox_v3_scale(prox_v3_sub(prox_v3_scale(C->v, cos(th)), prox_v3_scale(C->u, sin(th))), C->s);
    prox_vec3 g = phi_grad(s, d);
    *f = prox_v3_dot(g, d);
    record(s, d, *f);
    return prox_v3_dot(g, t);
}

/* The slope at th for the root search (prox_illinois), each point recorded and the lowest kept. */
typedef struct circ_walk {
    cvx *s;
    const cvx_circ *C;
    prox_vec3 bd, last;
    double bf;
} circ_walk;

static double circ_walk_slope(void *ctx, double th)
{
    circ_walk *w = ctx;
    double f;
    w->last = circ_at(w->C, th);
    double g = circ_step(w->s, w->C, th, w->last, &f);
    if (f <= w->bf) w->bf = f, w->bd = w->last;
    return g;
}

/* Minimum of phi along the circle in [lo, hi]: the root of the slope by regula falsi with the
 * Illinois modification (core/edge_root.h; where a kink of another body on the circle makes the slope
 * jump, its steps are bisections), to a bracket of PROX_TOL_ANGLE; exact: then regula falsi with the
 * Illinois halving moves both ends to the rounding of the angle (an answer's witnesses: a needle's
 * support point moves 2e9 S per rad). Every point is recorded; returns the root (the lower endpoint
 * when the slope does not change sign). */
static prox_vec3 circ_min_to(cvx *s, const cvx_circ *C, double lo, double hi, int exact)
{
    prox_vec3 dl = circ_at(C, lo), dh = circ_at(C, hi), bd = dl;
    double fl, fh, gl = circ_step(s, C, lo, dl, &fl), gh = circ_step(s, C, hi, dh, &fh), bf = fl;
    if (fh < bf) bf = fh, bd = dh;
    if (!(gl < 0.0 && gh > 0.0)) return bd;
    circ_walk w = {s, C, bd, bd, bf};
    int rc = prox_illinois(circ_walk_slope, &w, &lo, &hi, &gl, &gh, lo - gl * (hi - lo) / (gh - gl), PROX_TOL_ANGLE);
    if (rc == 1) return w.last;
    if (rc < 0) return w.bd;
    for (int k = 0, side = 0; exact && k < 24; ++k) {
        double th = (lo * gh - hi * gl) / (gh - gl);
        if (!(th > lo && th < hi)) break; /* no angle between them */
        double g = circ_slope(s, C, th, circ_at(C, th));
        if (g > 0.0) hi = th, gh = g, gl *= side == 1 ? 0.5 : 1.0, side = 1;
        else if (g < 0.0) lo = th, gl = g, gh *= side == -1 ? 0.5 : 1.0, side = -1;
        else return circ_at(C, th);
    }
    /* the root of the slope: where the value is flat to rounding (1e-8 rad around a smooth minimum)
     * the stationary point, not the lowest value, gives the support points */
    return circ_at(C, 0.5 * (lo + hi));
}

/* The whole circle: samples with their slopes, every discrete minimum and every sign change of the
 * slope refined (a valley between two samples that no sample's value shows); returns the lowest of
 * the refined minima (exact: each to the rounding of the angle, circ_min_to). */
static prox_vec3 circ_whole(cvx *s, const cvx_circ *C, int exact)
{
    double f[CVX_CIRCLE_SAMPLES], g[CVX_CIRCLE_SAMPLES], bf = INFINITY;
    const double step = 2.0 * PROX_PI / CVX_CIRCLE_SAMPLES;
    prox_vec3 bd = circ_at(C, 0.0);
    for (int i = 0; i < CVX_CIRCLE_SAMPLES; ++i) {
        prox_vec3 d = circ_at(C, i * step);
        g[i] = circ_step(s, C, i * step, d, &f[i]);
    }
    for (int i = 0; i < CVX_CIRCLE_SAMPLES; ++i) {
        int ip = (i + CVX_CIRCLE_SAMPLES - 1) % CVX_CIRCLE_SAMPLES, in = (i + 1) % CVX_CIRCLE_SAMPLES;
        int up = g[i] < 0.0 && g[in] > 0.0, down = g[ip] < 0.0 && g[i] > 0.0; /* a valley next to i */
        prox_vec3 d;
        if (up) d = circ_min_to(s, C, i * step, (i + 1) * step, exact);
        else if (!down && f[i] <= f[ip] && f[i] <= f[in]) d = circ_min_to(s, C, (i - 1) * step, (i + 1) * step, exact);
        else continue;
        double fd = phi_eval(s, d);
        if (fd < bf) bf = fd, bd = d;
    }
    return bd;
}

static void circ_global(cvx *s, const cvx_kink *k)
{
    cvx_circ C = circ_make(k);
    circ_whole(s, &C, 0);
}

/* The minimum on circle C near d (within r): the arc within r of d's projection, or the whole circle
 * when it is small enough to lie within r (a flat cone's lateral kink, 2e-10 rad across: the arc
 * around d's projection, whose angle is then any, would miss its minimum). */
static prox_vec3 circ_near(cvx *s, const cvx_kink *k, prox_vec3 d, double r, int exact)
{
    cvx_circ C = circ_make(k);
    if (C.s * PROX_PI <= r) return circ_whole(s, &C, exact);
    /* angles measured from d's projection: near it they resolve 1e-300 rad, not the 1e-16 of an
     * angle near 1 (a flat REC's support point moves 2e9 S per rad along its kink circle) */
    prox_vec3 u = prox_v3_reject(d, C.w);
    if (prox_v3_norm2(u) > 0.0) C.u = unit(u), C.v = prox_v3_cross(C.w, C.u);
    double dr = r / fmax(C.s, 1e-3);
    if (fabs(prox_v3_dot(d, C.w) - C.c) <= 4.0 * DBL_EPSILON) {
        /* d on the circle with phi rising both ways (at another kink crossing it: a box's face normal
         * on an edge circle, where the slope jumps and the bracket search would bisect ~100 times
         * onto it): the circle's minimum is within e of d */
        double e = 16.0 * DBL_EPSILON, fm, fp;
        if (circ_step(s, &C, -e, circ_at(&C, -e), &fm) <= 0.0 && circ_step(s, &C, e, circ_at(&C, e), &fp) >= 0.0)
            return exact ? circ_min_to(s, &C, -e, e, 1) : d;
    }
    return circ_min_to(s, &C, -dr, dr, exact);
}

/* Kinks within r of d: points evaluated, circles searched within r of d's projection, crossings of
 * two near circles evaluated. */
static prox_vec3 kinks_local(cvx *s, prox_vec3 d, double r)
{
    prox_vec3 best = s->best_d;
    double fb = INFINITY;
    for (int i = 0; i < s->nk; ++i) {
        const cvx_kink *k = &s->k[i];
        if (kink_dist(k, d) > r) continue;
        if (!k->circle) { consider(s, k->w); continue; }
        prox_vec3 c = circ_near(s, k, d, r, 0);
        double fc = phi_eval(s, c);
        if (fc < fb) fb = fc, best = c;
        for (int j = i + 1; j < s->nk; ++j) {
            prox_vec3 x[2];
            if (!s->k[j].circle || kink_dist(&s->k[j], d) > r) continue;
            for (int m = circle_cross(k, &s->k[j], x) - 1; m >= 0; --m)
                if (angle(x[m], d) <= 2.0 * r) consider(s, x[m]);
        }
    }
    /* the lowest circle minimum (the root of phi's slope along its circle, to PROX_TOL_ANGLE) when it
     * ties the best direction to phi's rounding: the best by value is then rounding's pick among the
     * search's points near it, up to ~1e-8 rad off the optimum */
    return fb <= s->best_phi + PROX_TOL_PHI_ROUND * s->S ? best : s->best_d;
}

/* Every kink: points, the crossings of every two circles, every circle searched whole. */
static void kinks_global(cvx *s)
{
    for (int i = 0; i < s->nk; ++i) {
        if (!s->k[i].circle) { consider(s, s->k[i].w); continue; }
        for (int j = i + 1; j < s->nk; ++j) {
            prox_vec3 x[2];
            if (!s->k[j].circle) continue;
            for (int m = circle_cross(&s->k[i], &s->k[j], x) - 1; m >= 0; --m) consider(s, x[m]);
        }
        circ_global(s, &s->k[i]);
    }
}

/* ---- Newton on the sphere ---------------------------------------------------------------------- */

/* One Riemannian Newton step (steepest descent where the Hessian T^T H T - phi I is not positive
 * definite) with backtracking; the accepted length, 0 when nothing decreased phi. *gp is P's support
 * point at *dp (phi's gradient there), and phi(*dp) = *fp = gp . dp: each point of the line search
 * takes its support point, which is the next step's gradient when the point is accepted. */
static double newton_step(cvx *s, prox_vec3 *dp, double *fp, prox_vec3 *gp)
{
    prox_vec3 d = *dp, t1 = prox_v3_any_perp(d), t2 = prox_v3_cross(d, t1), g = *gp;
    double f = *fp, g1 = prox_v3_dot(g, t1), g2 = prox_v3_dot(g, t2), h[3];
    phi_form(s, d, t1, t2, h);
    double a = h[0] - f, b = h[1], c = h[2] - f, det = a * c - b * b, x1, x2;
    if (a > 0.0 && det > 0.0) {
        x1 = -(c * g1 - b * g2) / det;
        x2 = -(a * g2 - b * g1) / det;
        if (-0.5 * (g1 * x1 + g2 * x2) <= PROX_TOL_PHI_ROUND * s->S) {
            /* the decrement within phi's rounding (phi ~ S, its support values ~ S): phi's values no
             * longer judge the step, and stopping here leaves the direction ~sqrt(rounding /
             * curvature) off (1e-8 rad: support points 1e-8 S off the closest pair). The step is
             * quadratic: taken while it lowers the gradient across the direction. */
            prox_vec3 dn = unit(prox_v3_add(d, prox_v3_add(prox_v3_scale(t1, x1), prox_v3_scale(t2, x2))));
            prox_vec3 gn = phi_grad(s, dn);
            if (!(prox_v3_norm(prox_v3_reject(gn, dn)) < prox_hypot2(g1, g2))) return 0.0;
            *dp = dn, *fp = prox_v3_dot(gn, dn), *gp = gn;
            record(s, dn, *fp);
            double len = prox_hypot2(x1, x2);
            return len * len < PROX_TOL_STEP ? 0.0 : len; /* the next step, ~len^2, would be below it */
        }
    } else {
        double sc = fabs(f) > 0.0 ? fabs(f) : 1.0;
        x1 = -g1 / sc;
        x2 = -g2 / sc;
    }
    double len = prox_hypot2(x1, x2);
    if (!(len > 0.0)) return 0.0;
    if (len > 0.5) x1 *= 0.5 / len, x2 *= 0.5 / len, len = 0.5;
    /* among the depth's many starts a gradient step that needs more than CVX_GRAD_HALVINGS halvings
     * has met a kink, where the kink searches take over; elsewhere (the best's own descent) it keeps
     * halving, which a body far thinner than the other needs */
    int halvings = a > 0.0 && det > 0.0 ? s->nhalvings : s->halvings;
    for (int ls = 0; ls < halvings; ++ls) {
        prox_vec3 dn = unit(prox_v3_add(d, prox_v3_add(prox_v3_scale(t1, x1), prox_v3_scale(t2, x2))));
        prox_vec3 gn = phi_grad(s, dn);
        double fn = prox_v3_dot(gn, dn);
        if (fn < f) {
            *dp = dn, *fp = fn, *gp = gn;
            record(s, dn, fn);
            return len;
        }
        x1 *= 0.5, x2 *= 0.5, len *= 0.5;
    }
    return 0.0;
}

static prox_vec3 cell_newton(cvx *s, prox_vec3 d)
{
    prox_vec3 g = phi_grad(s, d);
    double f = prox_v3_dot(g, d);
    record(s, d, f);
    for (int it = 0; it < 60; ++it)
        if (newton_step(s, &d, &f, &g) < PROX_TOL_STEP) break;
    return d; /* the last iterate: its last step judged by the gradient, not by phi's rounding */
}

/* Norm of the tangential gradient. */
static double tgrad(const cvx *s, prox_vec3 d)
{
    prox_vec3 g = phi_grad(s, d);
    return prox_v3_norm(prox_v3_reject(g, d));
}

/* Pure Newton steps on the tangential gradient, kept while its norm decreases: the direction itself
 * to rounding (the value stops improving ~1e-8 rad off the optimum, the support points do not). */
static prox_vec3 polish_cell(const cvx *s, prox_vec3 d)
{
    double gn = tgrad(s, d);
    for (int it = 0; it < 8 && gn > 0.0; ++it) {
        double f = phi_eval(s, d);
        prox_vec3 t1 = prox_v3_any_perp(d), t2 = prox_v3_cross(d, t1), g = phi_grad(s, d);
        double g1 = prox_v3_dot(g, t1), g2 = prox_v3_dot(g, t2), h[3];
        phi_form(s, d, t1, t2, h);
        /* regularised (a touching rim has a rank-one Hessian and phi ~ 0: along the null direction
         * the gradient vanishes too, the shift only keeps the solve defined) */
        double mu = PROX_TOL_SEARCH * s->S;
        double a = h[0] - f + mu, b = h[1], c = h[2] - f + mu, det = a * c - b * b;
        double l1 = 0.5 * (a + c) + prox_hypot2(0.5 * (a - c), b), x1, x2;
        if (l1 > 0.0 && !(det > 1e-12 * l1 * l1)) {
            /* one stiff direction (a needle's axis: 2e9 S per rad) beside a nearly flat one: the
             * determinant, which carries eps l1^2 of rounding, is noise, and so is the 2 x 2 solve;
             * the step along the stiff eigenvector alone */
            double e1 = a >= c ? l1 - c : b, e2 = a >= c ? b : l1 - a, en = prox_hypot2(e1, e2);
            if (!(en > 0.0)) break;
            double t = -(g1 * e1 + g2 * e2) / (en * en * l1);
            x1 = t * e1, x2 = t * e2;
        } else {
            if (!(a > 0.0 && det > 0.0)) break;
            x1 = -(c * g1 - b * g2) / det, x2 = -(a * g2 - b * g1) / det;
        }
        if (!(prox_hypot2(x1, x2) < 0.1)) break;
        prox_vec3 dn = unit(prox_v3_add(d, prox_v3_add(prox_v3_scale(t1, x1), prox_v3_scale(t2, x2))));
        double gnn = tgrad(s, dn);
        if (!(gnn < gn)) break;
        d = dn, gn = gnn;
    }
    return d;
}

/* ---- GJK on P = A - B -------------------------------------------------------------------------- */

/* A vertex of the simplex: w = pa - pb with pa in A and pb in B (relative coordinates). */
typedef struct gjk_pt {
    prox_vec3 w, pa, pb;
} gjk_pt;

/* The foot of the origin on the affine hull of a vertex, an edge or a triangle, with its direction
 * accurate (a second rejection; a cross product): for a long feature passing close to the origin the
 * barycentric combination carries eps |feature| in every direction. */
static prox_vec3 face_foot(const gjk_pt *p, int m)
{
    if (m == 1) return p[0].w;
    prox_vec3 e = prox_v3_sub(p[1].w, p[0].w);
    if (m == 2) {
        double ee = prox_v3_norm2(e);
        prox_vec3 v = prox_v3_mad(p[0].w, -prox_v3_dot(p[0].w, e) / ee, e);
        return prox_v3_mad(v, -prox_v3_dot(v, e) / ee, e);
    }
    prox_vec3 nrm = prox_v3_cross(e, prox_v3_sub(p[2].w, p[0].w));
    return prox_v3_scale(nrm, prox_v3_dot(p[0].w, nrm) / prox_v3_norm2(nrm));
}

/* The point of segment ab nearest the origin: its barycentric coordinates (la, lb). */
static void seg_bary(prox_vec3 a, prox_vec3 b, double *la, double *lb)
{
    prox_vec3 e = prox_v3_sub(b, a);
    double t = -prox_v3_dot(a, e), ee = prox_v3_norm2(e);
    if (!(t > 0.0) || !(ee > 0.0)) *la = 1.0, *lb = 0.0;
    else if (t >= ee) *la = 0.0, *lb = 1.0;
    else *lb = t / ee, *la = 1.0 - *lb;
}

/* The point of triangle abc nearest the origin by its Voronoi regions (Ericson, Real-Time Collision
 * Detection, 5.1.5): barycentric coordinates l[0..2]. A triangle whose face region has no area
 * (collinear corners) takes the nearest of its sides. */
static void tri_bary(prox_vec3 a, prox_vec3 b, prox_vec3 c, double l[3])
{
    prox_vec3 ab = prox_v3_sub(b, a), ac = prox_v3_sub(c, a);
    double d1 = -prox_v3_dot(ab, a), d2 = -prox_v3_dot(ac, a);
    l[0] = 1.0, l[1] = l[2] = 0.0;
    if (d1 <= 0.0 && d2 <= 0.0) return;
    double d3 = -prox_v3_dot(ab, b), d4 = -prox_v3_dot(ac, b);
    if (d3 >= 0.0 && d4 <= d3) { l[0] = 0.0, l[1] = 1.0; return; }
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) { l[1] = d1 / (d1 - d3), l[0] = 1.0 - l[1]; return; }
    double d5 = -prox_v3_dot(ab, c), d6 = -prox_v3_dot(ac, c);
    if (d6 >= 0.0 && d5 <= d6) { l[0] = 0.0, l[2] = 1.0; return; }
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) { l[2] = d2 / (d2 - d6), l[0] = 1.0 - l[2]; return; }
    double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        l[0] = 0.0, l[2] = (d4 - d3) / ((d4 - d3) + (d5 - d6)), l[1] = 1.0 - l[2];
        return;
    }
    double den = va + vb + vc;
    if (den > 0.0 && va >= 0.0 && vb >= 0.0 && vc >= 0.0) {
        l[1] = vb / den, l[2] = vc / den, l[0] = 1.0 - l[1] - l[2];
        return;
    }
    /* no face region to rounding: the nearest side */
    prox_vec3 q[3] = {a, b, c};
    double best = INFINITY;
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        double x, y;
        seg_bary(q[i], q[j], &x, &y);
        double dd = prox_v3_norm2(prox_v3_add(prox_v3_scale(q[i], x), prox_v3_scale(q[j], y)));
        if (dd < best) best = dd, l[0] = l[1] = l[2] = 0.0, l[i] = x, l[j] = y;
    }
}

/* Closest point v to the origin of the hull of the n <= 4 points (the distance subalgorithm by
 * Voronoi regions: a tetrahedron's faces that have the origin outside, each triangle's vertex, edge
 * and face regions); the points are reduced to those with a positive coordinate and lam receives
 * them. Returns 1 when the origin is inside the tetrahedron. Four points nearly in a plane (support
 * points on a flat face of P) never enclose it: their hull is covered by its triangles. */
static int gjk_closest(gjk_pt p[4], int *n, prox_vec3 *v, double lam[4])
{
    double l[4] = {1, 0, 0, 0};
    int inside = 0;
    if (*n == 2) {
        seg_bary(p[0].w, p[1].w, &l[0], &l[1]);
    } else if (*n == 3) {
        tri_bary(p[0].w, p[1].w, p[2].w, l);
    } else if (*n == 4) {
        static const int fc[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}}; /* face, opposite */
        prox_vec3 e0 = prox_v3_sub(p[1].w, p[0].w), e1 = prox_v3_sub(p[2].w, p[0].w), e2 = prox_v3_sub(p[3].w, p[0].w);
        double vol = fabs(prox_v3_dot(e0, prox_v3_cross(e1, e2)));
        int solid = vol > 1e-10 * prox_v3_norm(e0) * prox_v3_norm(e1) * prox_v3_norm(e2), any = 0;
        double best = INFINITY;
        for (int f = 0; f < 4; ++f) {
            prox_vec3 a = p[fc[f][0]].w, b = p[fc[f][1]].w, c = p[fc[f][2]].w, o = p[fc[f][3]].w;
            prox_vec3 nf = prox_v3_cross(prox_v3_sub(b, a), prox_v3_sub(c, a));
            double so = -prox_v3_dot(nf, a), sd = prox_v3_dot(nf, prox_v3_sub(o, a));
            if (solid && !(so * sd < 0.0)) continue; /* the origin on the inner side of this face */
            any = 1;
            double t[3];
            tri_bary(a, b, c, t);
            prox_vec3 x = prox_v3_add(prox_v3_add(prox_v3_scale(a, t[0]), prox_v3_scale(b, t[1])), prox_v3_scale(c, t[2]));
            double xx = prox_v3_norm2(x);
            if (xx < best) {
                best = xx, l[0] = l[1] = l[2] = l[3] = 0.0;
                for (int k = 0; k < 3; ++k) l[fc[f][k]] = t[k];
            }
        }
        if (!any) {
            /* the origin inside: its barycentric coordinates, for the simplex pair (a common point) */
            prox_vec3 q = prox_v3_neg(p[0].w); /* e0 l1 + e1 l2 + e2 l3 = -p0, by Cramer's rule */
            double six = prox_v3_dot(e0, prox_v3_cross(e1, e2));
            l[1] = prox_v3_dot(q, prox_v3_cross(e1, e2)) / six;
            l[2] = prox_v3_dot(e0, prox_v3_cross(q, e2)) / six;
            l[3] = prox_v3_dot(e0, prox_v3_cross(e1, q)) / six;
            l[0] = 1.0 - l[1] - l[2] - l[3];
            inside = 1;
        }
    }
    int m = 0;
    if (inside) {
        for (int i = 0; i < 4; ++i) lam[i] = l[i];
        *v = prox_v3(0, 0, 0);
        return 1;
    }
    for (int i = 0; i < *n; ++i)
        if (l[i] > 0.0) p[m] = p[i], lam[m] = l[i], ++m;
    if (m == 0) lam[0] = 1.0, m = 1; /* not reached: some coordinate is positive */
    *n = m;
    *v = face_foot(p, m);
    return 0;
}

typedef struct gjk_out {
    int verdict;      /* 1 separated, 0 origin enclosed (overlap), 2 undecided (touching band, stall) */
    prox_vec3 xa, xb; /* the simplex's pair: xa in A, xb in B (a common point when enclosed) */
    double vnorm;     /* |xa - xb| (an upper bound on the distance) */
    int n;            /* the final simplex: n points w[] of P (4: a tetrahedron about the origin) */
    prox_vec3 w[4];
} gjk_out;

static gjk_pt gjk_support(const cvx *s, prox_vec3 d)
{
    gjk_pt q;
    q.pa = prox_v3_add(s->a.c, prox_body_pc(&s->a, d));
    q.pb = prox_v3_add(s->b.c, prox_body_pc(&s->b, prox_v3_neg(d)));
    q.w = prox_v3_sub(q.pa, q.pb);
    return q;
}

/* GJK (Gilbert, Johnson & Keerthi 1988) from the point cA - cB of P. Every direction tried is
 * recorded; it stops when |v| and -phi meet to a few ulps of S (polytope pairs: exactly), when the
 * origin is enclosed, or when no new support point appears. */
static gjk_out gjk_run(cvx *s)
{
    gjk_pt p[4];
    p[0].pa = s->a.c, p[0].pb = s->b.c, p[0].w = prox_v3_sub(s->a.c, s->b.c);
    double lam[4] = {1, 0, 0, 0}, tol = PROX_TOL_SNAP * s->S, floor2 = 256.0 * tol * tol;
    prox_vec3 v = p[0].w;
    int n = 1, separated = 0, verdict = -1;
    for (int it = 0; it < CVX_GJK_IT && verdict < 0; ++it) {
        double vv = prox_v3_norm2(v);
        if (!(vv > floor2)) { verdict = 2; break; }
        prox_vec3 d = prox_v3_scale(v, -1.0 / sqrt(vv));
        gjk_pt q = gjk_support(s, d);
        double f = prox_v3_dot(d, q.w); /* phi(d) = h_P(d): q.w is P's support point at d */
        record(s, d, f);
        separated |= f < 0.0;
        double vn = sqrt(vv), stop = s->gjk_rel * vn; /* (no fmax: a library call each iteration) */
        if (separated && vn + f <= (stop > tol ? stop : tol)) { verdict = 1; break; }
        int dup = 0;
        for (int i = 0; i < n; ++i) dup |= prox_v3_norm2(prox_v3_sub(q.w, p[i].w)) <= floor2;
        if (dup) break;
        p[n++] = q;
        double vv0 = vv;
        if (gjk_closest(p, &n, &v, lam)) {
            verdict = separated ? 1 : 0; /* a separating direction outranks a rounded enclosure */
            break;
        }
        if (!(prox_v3_norm2(v) < vv0)) break;
    }
    if (verdict < 0) verdict = separated ? 1 : 2;
    gjk_out o = {verdict, {0, 0, 0}, {0, 0, 0}, 0.0, n, {{0, 0, 0}}};
    for (int i = 0; i < n; ++i) o.xa = prox_v3_mad(o.xa, lam[i], p[i].pa), o.xb = prox_v3_mad(o.xb, lam[i], p[i].pb);
    for (int i = 0; i < n; ++i) o.w[i] = p[i].w;
    o.vnorm = prox_v3_dist(o.xa, o.xb);
    return o;
}

/* ---- support sets ------------------------------------------------------------------------------ */

/* A support set (relative coordinates): the hull of nv points (1 a point, 2 a segment, more a
 * polygon, any order), or an elliptical disk c + x e1 + y e2 with x^2 + y^2 <= 1 (ell = 1). */
typedef struct cvx_set {
    int nv, ell;
    prox_vec3 v[PROX_POLY_MAXV], c, e1, e2;
} cvx_set;

static cvx_set set_point(prox_vec3 p)
{
    cvx_set f = {0};
    f.nv = 1;
    f.v[0] = p;
    return f;
}

/* Coordinates here are in units of the pair scale (pair_make): a segment or a disk no larger than
 * PROX_TOL_NOISE is its centre within rounding, and is kept as that point (a disk of radius 1e-91 has
 * a Gram determinant that underflows, which would make its projections NaN). */
static cvx_set set_segment(prox_vec3 m, prox_vec3 e, double h)
{
    if (!(fabs(h) * prox_v3_norm(e) > PROX_TOL_NOISE)) return set_point(m);
    cvx_set f = {0};
    f.nv = 2;
    f.v[0] = prox_v3_mad(m, -h, e);
    f.v[1] = prox_v3_mad(m, h, e);
    return f;
}

static cvx_set set_ellipse(prox_vec3 c, prox_vec3 e1, prox_vec3 e2)
{
    if (!(fmax(prox_v3_norm(e1), prox_v3_norm(e2)) > PROX_TOL_NOISE)) return set_point(c);
    cvx_set f = {0};
    f.ell = 1, f.c = c, f.e1 = e1, f.e2 = e2;
    return f;
}

/* The side line of a cylinder-like body (axis w, half height hh) through the radial support point
 * rad, when d is within ftol of perpendicular to the axis. */
static int axial_set(prox_vec3 c, prox_vec3 w, double hh, prox_vec3 d, double ftol, prox_vec3 rad, cvx_set *f)
{
    if (!(fabs(prox_v3_dot(d, w)) <= ftol)) return 0;
    *f = set_segment(prox_v3_add(c, rad), w, hh);
    return 1;
}

static cvx_set box_set(const prox_body *b, prox_vec3 d, double ftol)
{
    prox_vec3 c = b->c, e[2];
    double h[2];
    int m = 0;
    for (int i = 0; i < 3; ++i) {
        double di = prox_v3_dot(d, b->box.a[i]);
        if (fabs(di) <= ftol && m < 2) e[m] = b->box.a[i], h[m++] = b->box.h[i];
        else c = prox_v3_mad(c, di >= 0.0 ? b->box.h[i] : -b->box.h[i], b->box.a[i]);
    }
    if (m == 0) return set_point(c);
    if (m == 1) return set_segment(c, e[0], h[0]);
    cvx_set f = {0};
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    f.nv = 4;
    for (int i = 0; i < 4; ++i) f.v[i] = prox_v3_mad(prox_v3_mad(c, sx[i] * h[0], e[0]), sy[i] * h[1], e[1]);
    return f;
}

static cvx_set poly_set(const prox_body *b, prox_vec3 d, double ftol)
{
    const prox_polytope *p = &b->x.poly;
    double hc = prox_polytope_hc(p, d), lim = hc - ftol * p->size;
    cvx_set f = {0};
    for (int i = 0; i < p->nv; ++i)
        if (prox_v3_dot(d, p->v[i]) >= lim) f.v[f.nv++] = prox_v3_add(b->c, p->v[i]);
    return f;
}

static cvx_set cone_set(const prox_body *b, prox_vec3 d, double ftol)
{
    const prox_cone *k = &b->x.cone;
    double t = prox_v3_dot(d, k->w);
    /* rejected twice (core/axis.h): once leaves eps of the axis in it, 2.5e-7 of a 4e-10 perp (a flat
     * cone's lateral normal), which tilted its generator off the surface by that times its radius */
    prox_vec3 perp = prox_axis_across(d, k->w);
    double pn = prox_v3_norm(perp);
    if (pn <= ftol) {
        double r = t >= 0.0 ? k->r2 : k->r1;
        prox_vec3 c = prox_v3_mad(b->c, t >= 0.0 ? k->hh : -k->hh, k->w), u = prox_v3_any_perp(k->w);
        if (!(r > 0.0)) return set_point(c);
        return set_ellipse(c, prox_v3_scale(u, r), prox_v3_scale(prox_v3_cross(k->w, u), r));
    }
    double top = k->hh * t + k->r2 * pn, base = -k->hh * t + k->r1 * pn;
    if (fabs(top - base) <= ftol * (2.0 * k->hh + fabs(k->r1 - k->r2))) {
        prox_vec3 u = prox_v3_scale(perp, 1.0 / pn);
        cvx_set f = {0};
        f.nv = 2;
        f.v[0] = prox_v3_add(b->c, prox_v3_mad(prox_v3_scale(k->w, -k->hh), k->r1, u));
        f.v[1] = prox_v3_add(b->c, prox_v3_mad(prox_v3_scale(k->w, k->hh), k->r2, u));
        return f;
    }
    return set_point(prox_v3_add(b->c, prox_cone_pc(k, d)));
}

/* Support set of body b in unit direction d (relative coordinates), faces within ftol included (|sin|
 * of the angle between d and the face normal, or between d and perpendicular to a side). */
static cvx_set support_set(const prox_body *b, prox_vec3 d, double ftol)
{
    cvx_set f;
    switch (b->kind) {
    case PROX_BODY_CYL: {
        prox_vec3 perp = prox_v3_reject(d, b->cyl.w), w = b->cyl.w;
        double pn = prox_v3_norm(perp), t = prox_v3_dot(d, w);
        if (pn <= ftol) {
            prox_vec3 u = prox_v3_any_perp(w);
            return set_ellipse(prox_v3_mad(b->c, t >= 0.0 ? b->cyl.hh : -b->cyl.hh, w), prox_v3_scale(u, b->cyl.r),
                               prox_v3_scale(prox_v3_cross(w, u), b->cyl.r));
        }
        if (axial_set(b->c, w, b->cyl.hh, d, ftol, prox_v3_scale(perp, b->cyl.r / pn), &f)) return f;
        break;
    }
    case PROX_BODY_ECYL: {
        const prox_ecyl *k = &b->x.ecyl;
        double x1 = prox_v3_dot(d, k->u1), x2 = prox_v3_dot(d, k->u2), t = prox_v3_dot(d, k->w);
        if (prox_hypot2(x1, x2) <= ftol)
            return set_ellipse(prox_v3_mad(b->c, t >= 0.0 ? k->hh : -k->hh, k->w), prox_v3_scale(k->u1, k->a1),
                               prox_v3_scale(k->u2, k->a2));
        double s1 = k->a1 * k->a1 * x1, s2 = k->a2 * k->a2 * x2, q = sqrt(s1 * x1 + s2 * x2);
        prox_vec3 rad = prox_v3_scale(prox_v3_add(prox_v3_scale(k->u1, s1), prox_v3_scale(k->u2, s2)), 1.0 / q);
        if (axial_set(b->c, k->w, k->hh, d, ftol, rad, &f)) return f;
        break;
    }
    case PROX_BODY_BOX: return box_set(b, d, ftol);
    case PROX_BODY_POLY: return poly_set(b, d, ftol);
    case PROX_BODY_CONE: return cone_set(b, d, ftol);
    default: break;
    }
    return set_point(prox_v3_add(b->c, prox_body_pc(b, d)));
}

/* ---- closest pair of two support sets seen along n (in the plane perpendicular to n) ------------ */

/* Points of that plane (coordinates along u, v): core/plane2.h. */
typedef prox_v2 v2;

/* A set seen along n: a convex polygon (hull of the set's points, counter-clockwise, idx naming the
 * 3D points) or an ellipse q + E z, |z| <= 1 (E columns E1, E2). */
typedef struct set2 {
    int nv, ell;
    v2 v[PROX_POLY_MAXV], q, E1, E2;
    int idx[PROX_POLY_MAXV];
    double det;
} set2;

typedef struct frame2 {
    prox_vec3 o, u, v;
} frame2;

static v2 to2(const frame2 *F, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, F->o);
    v2 r = {prox_v3_dot(d, F->u), prox_v3_dot(d, F->v)};
    return r;
}

/* Convex hull of the projected points (core/plane2.h), collinear points dropped. */
static void hull2(const v2 *p, int n, set2 *s)
{
    int h[2 * PROX_POLY_MAXV + 2], m = prox_v2_hull(p, n, h);
    if (m == 2 && prox_v2_norm(prox_v2_sub(p[h[0]], p[h[1]])) == 0.0) m = 1;
    s->nv = m;
    for (int i = 0; i < m; ++i) s->v[i] = p[h[i]], s->idx[i] = h[i];
}

static set2 set_2d(const frame2 *F, const cvx_set *f)
{
    set2 s = {0};
    if (f->ell) {
        s.ell = 1;
        s.q = to2(F, f->c);
        s.E1.x = prox_v3_dot(f->e1, F->u), s.E1.y = prox_v3_dot(f->e1, F->v);
        s.E2.x = prox_v3_dot(f->e2, F->u), s.E2.y = prox_v3_dot(f->e2, F->v);
        s.det = prox_v2_cross(s.E1, s.E2);
        return s;
    }
    v2 p[PROX_POLY_MAXV];
    for (int i = 0; i < f->nv; ++i) p[i] = to2(F, f->v[i]);
    hull2(p, f->nv, &s);
    return s;
}

/* z = E^-1 (x - q): the ellipse's own coordinates (the unit disk). */
static v2 ell_local(const set2 *E, v2 x)
{
    v2 r = prox_v2_sub(x, E->q), z = {(r.x * E->E2.y - r.y * E->E2.x) / E->det, (E->E1.x * r.y - E->E1.y * r.x) / E->det};
    return z;
}

static v2 ell_point(const set2 *E, v2 z)
{
    v2 x = {E->q.x + z.x * E->E1.x + z.y * E->E2.x, E->q.y + z.x * E->E1.y + z.y * E->E2.y};
    return x;
}

/* Nearest point of the elliptical disk to x: z(lambda) = (G + lambda I)^-1 E^T (x - q), G = E^T E,
 * with |z| = 1 (the secular equation, convex and decreasing in lambda: Newton from 0 is monotone). */
static v2 ell_proj(const set2 *E, v2 x)
{
    v2 z0 = ell_local(E, x);
    if (prox_v2_dot(z0, z0) <= 1.0) return x;
    double g11 = prox_v2_dot(E->E1, E->E1), g12 = prox_v2_dot(E->E1, E->E2), g22 = prox_v2_dot(E->E2, E->E2);
    double m = 0.5 * (g11 + g22), dd = prox_hypot2(0.5 * (g11 - g22), g12), l1 = m + dd, l2 = (g11 * g22 - g12 * g12) / l1;
    v2 e1 = {g12, l1 - g11}, e1b = {l1 - g22, g12};
    if (prox_v2_norm(e1b) > prox_v2_norm(e1)) e1 = e1b;
    double en = prox_v2_norm(e1);
    if (!(en > 0.0)) e1.x = g11 >= g22 ? 1.0 : 0.0, e1.y = g11 >= g22 ? 0.0 : 1.0, en = 1.0;
    e1.x /= en, e1.y /= en;
    v2 e2 = {-e1.y, e1.x}, r = prox_v2_sub(x, E->q), bt = {prox_v2_dot(E->E1, r), prox_v2_dot(E->E2, r)};
    double b1 = prox_v2_dot(bt, e1), b2 = prox_v2_dot(bt, e2), lam = 0.0;
    for (int it = 0; it < 200; ++it) {
        double q1 = b1 / (l1 + lam), q2 = b2 / (l2 + lam), F = q1 * q1 + q2 * q2 - 1.0;
        double dF = -2.0 * (q1 * q1 / (l1 + lam) + q2 * q2 / (l2 + lam));
        if (!(F > 0.0) || !(dF < 0.0)) break;
        double step = -F / dF;
        lam += step;
        if (step <= 1e-17 * (lam + l1)) break;
    }
    v2 z = {b1 / (l1 + lam), b2 / (l2 + lam)}, zz = {z.x * e1.x + z.y * e2.x, z.x * e1.y + z.y * e2.y};
    double zn = prox_v2_norm(zz);
    if (zn > 0.0) zz.x /= zn, zz.y /= zn;
    return ell_point(E, zz);
}

/* Closest point of a polygon set to q (q itself when inside). */
static v2 poly2_closest(const set2 *P, v2 q) { return prox_v2_poly_closest(P->v, P->nv, q); }

static v2 set2_proj(const set2 *S, v2 x) { return S->ell ? ell_proj(S, x) : poly2_closest(S, x); }

static int nedges(const set2 *P) { return P->nv == 2 ? 1 : (P->nv >= 3 ? P->nv : 0); }

/* Closest pair of two convex polygons: a vertex of one against the other, or two crossing edges. */
static void poly2_pair(const set2 *P, const set2 *Q, v2 *x, v2 *y)
{
    double bd = INFINITY;
    for (int i = 0; i < P->nv; ++i) prox_v2_pair_offer(P->v[i], poly2_closest(Q, P->v[i]), x, y, &bd);
    for (int j = 0; j < Q->nv; ++j) prox_v2_pair_offer(poly2_closest(P, Q->v[j]), Q->v[j], x, y, &bd);
    for (int i = 0; i < nedges(P); ++i)
        for (int j = 0; j < nedges(Q); ++j) {
            v2 a = P->v[i], b = P->v[(i + 1) % P->nv], c = Q->v[j], d = Q->v[(j + 1) % Q->nv];
            double d1 = prox_v2_cross(prox_v2_sub(b, a), prox_v2_sub(c, a)), d2 = prox_v2_cross(prox_v2_sub(b, a), prox_v2_sub(d, a));
            double d3 = prox_v2_cross(prox_v2_sub(d, c), prox_v2_sub(a, c)), d4 = prox_v2_cross(prox_v2_sub(d, c), prox_v2_sub(b, c));
            if (d1 * d2 < 0.0 && d3 * d4 < 0.0) {
                v2 z = prox_v2_mad(a, d3 / (d3 - d4), prox_v2_sub(b, a));
                prox_v2_pair_offer(z, z, x, y, &bd);
            }
        }
}

/* A common point of a polygon and an ellipse: a polygon point or edge point inside the ellipse (its
 * nearest point to the centre in the ellipse's coordinates), or the centre inside the polygon. */
static int poly_ell_common(const set2 *P, const set2 *E, v2 *x)
{
    v2 o = {0, 0};
    for (int i = 0; i < (P->nv == 1 ? 1 : nedges(P)); ++i) {
        v2 a = ell_local(E, P->v[i]), b = ell_local(E, P->v[(i + 1) % P->nv]), z = prox_v2_seg_closest(a, b, o);
        if (prox_v2_dot(z, z) <= 1.0) {
            v2 ab = prox_v2_sub(b, a);
            double ee = prox_v2_dot(ab, ab), t = ee > 0.0 ? prox_v2_dot(prox_v2_sub(z, a), ab) / ee : 0.0;
            *x = prox_v2_mad(P->v[i], t, prox_v2_sub(P->v[(i + 1) % P->nv], P->v[i]));
            return 1;
        }
    }
    if (P->nv >= 3 && prox_v2_norm(prox_v2_sub(poly2_closest(P, E->q), E->q)) == 0.0) { *x = E->q; return 1; }
    return 0;
}

/* Closest pair (x in S, y in T) of two sets seen along n. Polygons exactly; with an ellipse, a common
 * point when one is found, else alternating projections (they converge to the closest pair). */
static void set2_pair(const set2 *S, const set2 *T, v2 *x, v2 *y)
{
    if (!S->ell && !T->ell) { poly2_pair(S, T, x, y); return; }
    if (!S->ell && poly_ell_common(S, T, x)) { *y = *x; return; }
    if (!T->ell && poly_ell_common(T, S, x)) { *y = *x; return; }
    if (S->ell && T->ell) {
        v2 zt = ell_local(T, S->q), zs = ell_local(S, T->q);
        if (prox_v2_dot(zt, zt) <= 1.0) { *x = *y = S->q; return; }
        if (prox_v2_dot(zs, zs) <= 1.0) { *x = *y = T->q; return; }
    }
    v2 a = S->ell ? S->q : S->v[0], b = set2_proj(T, a);
    double scale = prox_v2_norm(a) + prox_v2_norm(b) + 1.0;
    for (int it = 0; it < 400; ++it) {
        v2 an = set2_proj(S, b), bn = set2_proj(T, an);
        double mv = prox_v2_norm(prox_v2_sub(an, a)) + prox_v2_norm(prox_v2_sub(bn, b));
        a = an, b = bn;
        if (mv <= 1e-17 * scale) break;
    }
    *x = a, *y = b;
}

/* The point of the 3D set f seen at X (X in its 2D image s): the same convex combination. */
static prox_vec3 lift(const cvx_set *f, const set2 *s, v2 X)
{
    if (f->ell) {
        v2 z = ell_local(s, X);
        double zn = prox_v2_norm(z);
        if (zn > 1.0) z.x /= zn, z.y /= zn;
        return prox_v3_mad(prox_v3_mad(f->c, z.x, f->e1), z.y, f->e2);
    }
    if (s->nv == 1) return f->v[s->idx[0]];
    if (s->nv == 2) {
        v2 e = prox_v2_sub(s->v[1], s->v[0]);
        double ee = prox_v2_dot(e, e), t = ee > 0.0 ? prox_v2_dot(prox_v2_sub(X, s->v[0]), e) / ee : 0.0;
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        return prox_v3_mad(f->v[s->idx[0]], t, prox_v3_sub(f->v[s->idx[1]], f->v[s->idx[0]]));
    }
    /* the fan triangle (0, i, i + 1) with the largest smallest barycentric coordinate */
    double best = -INFINITY, bl[3] = {1, 0, 0};
    int bi = 1;
    for (int i = 1; i + 1 < s->nv; ++i) {
        v2 a = s->v[0], b = s->v[i], c = s->v[i + 1];
        double den = prox_v2_cross(prox_v2_sub(b, a), prox_v2_sub(c, a));
        if (!(fabs(den) > 0.0)) continue;
        double l1 = prox_v2_cross(prox_v2_sub(X, a), prox_v2_sub(c, a)) / den, l2 = prox_v2_cross(prox_v2_sub(b, a), prox_v2_sub(X, a)) / den, l0 = 1.0 - l1 - l2;
        double mn = fmin(l0, fmin(l1, l2));
        if (mn > best) best = mn, bi = i, bl[0] = l0, bl[1] = l1, bl[2] = l2;
    }
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) bl[k] = fmax(bl[k], 0.0), sum += bl[k];
    prox_vec3 p = prox_v3_scale(f->v[s->idx[0]], bl[0] / sum);
    p = prox_v3_mad(p, bl[1] / sum, f->v[s->idx[bi]]);
    return prox_v3_mad(p, bl[2] / sum, f->v[s->idx[bi + 1]]);
}

/* The pair of points of sets fa (of A) and fb (of B) closest when seen along n. */
static void sets_pair(const cvx_set *fa, const cvx_set *fb, prox_vec3 n, prox_vec3 *p1, prox_vec3 *p2)
{
    frame2 F = {fa->ell ? fa->c : fa->v[0], prox_v3_any_perp(n), {0, 0, 0}};
    F.v = prox_v3_cross(n, F.u);
    set2 sa = set_2d(&F, fa), sb = set_2d(&F, fb);
    v2 X = {0, 0}, Y = {0, 0};
    set2_pair(&sa, &sb, &X, &Y);
    *p1 = lift(fa, &sa, X);
    *p2 = lift(fb, &sb, Y);
}

/* ---- witnesses ------------------------------------------------------------------------------- */

/* Two readings of each support set: with faces within PROX_TOL_FACE (MCNP decks print directions to
 * ~10 digits: a face that close to the normal is the contact) and within rounding (PROX_TOL_NOISE:
 * a face tilted by more is one extreme point, which is exact where the tilted face's lift is not). */
static const double cvx_ftol[2] = {PROX_TOL_FACE, PROX_TOL_NOISE};

/* The extreme points of A along n and of B along -n: the witnesses when no reading of the support
 * sets gives a finite pair (a support set too small for its projections, e.g. a disk of radius 1e-91,
 * is a point already, set_ellipse). */
static void support_points(const cvx *s, prox_vec3 n, prox_vec3 *p1, prox_vec3 *p2)
{
    *p1 = prox_v3_add(s->a.c, prox_body_pc(&s->a, n));
    *p2 = prox_v3_add(s->b.c, prox_body_pc(&s->b, prox_v3_neg(n)));
}

/* 1 when two readings of a support set are the same set (the same points in the same order). */
static int set_same(const cvx_set *f, const cvx_set *g)
{
    if (f->nv != g->nv || f->ell != g->ell) return 0;
    if (f->ell) return !memcmp(&f->c, &g->c, sizeof f->c) && !memcmp(&f->e1, &g->e1, sizeof f->e1) && !memcmp(&f->e2, &g->e2, sizeof f->e2);
    return !memcmp(f->v, g->v, (size_t)f->nv * sizeof f->v[0]);
}

/* Alternating exact projections of the pair x in A, y in B onto the solids, while they bring it
 * closer (they never move it apart, and keep x in A, y in B); returns |y - x|. A touching corner
 * against a rim off the optimal normal converges at ~0.75 a step. */
static double project_pair(const cvx *s, prox_vec3 *x, prox_vec3 *y)
{
    double d = prox_v3_dist(*x, *y);
    for (int it = 0; it < 96; ++it) {
        prox_vec3 yn = prox_body_closest(&s->b, *x), xn = prox_body_closest(&s->a, yn);
        double dn = prox_v3_dist(xn, yn);
        if (!(dn < d)) break;
        *x = xn, *y = yn, d = dn;
    }
    return d;
}

/* How far x in A and y in B are from being each other's closest points. */
static double pair_residual(const cvx *s, prox_vec3 x, prox_vec3 y)
{
    return fmax(prox_v3_dist(prox_body_closest(&s->a, y), x), prox_v3_dist(prox_body_closest(&s->b, x), y));
}

/* Disjoint: the closest pair of the support sets along n over the readings, polished by alternating
 * exact projections onto the solids (which never increase |p2 - p1| and keep p1 in A, p2 in B). */
static double witness_disjoint(const cvx *s, prox_vec3 n, prox_vec3 *p1, prox_vec3 *p2)
{
    double best = INFINITY;
    cvx_set fa[2], fb[2];
    for (int i = 0; i < 2; ++i) fa[i] = support_set(&s->a, n, cvx_ftol[i]), fb[i] = support_set(&s->b, prox_v3_neg(n), cvx_ftol[i]);
    int na = set_same(&fa[0], &fa[1]) ? 1 : 2, nb = set_same(&fb[0], &fb[1]) ? 1 : 2; /* a reading twice */
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) {
            prox_vec3 x, y;
            sets_pair(&fa[i], &fb[j], n, &x, &y);
            double d = project_pair(s, &x, &y);
            if (d < best) best = d, *p1 = x, *p2 = y;
        }
    if (!(best < INFINITY)) support_points(s, n, p1, p2), best = prox_v3_dist(*p1, *p2);
    return best;
}

/* Overlapping: the pair of the support sets (p1 on A's supporting plane, p2 on B's) whose difference
 * is closest to sd n over the readings (the sets seen along n meet at the optimum); returns that
 * distance. */
static double witness_overlap(const cvx *s, prox_vec3 n, double sd, prox_vec3 *p1, prox_vec3 *p2)
{
    double best = INFINITY;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            cvx_set fa = support_set(&s->a, n, cvx_ftol[i]), fb = support_set(&s->b, prox_v3_neg(n), cvx_ftol[j]);
            prox_vec3 x, y;
            sets_pair(&fa, &fb, n, &x, &y);
            double e = prox_v3_norm(prox_v3_mad(prox_v3_sub(y, x), -sd, n));
            if (e < best) best = e, *p1 = x, *p2 = y;
        }
    if (!(best < INFINITY)) support_points(s, n, p1, p2), best = prox_v3_norm(prox_v3_mad(prox_v3_sub(*p2, *p1), -sd, n));
    return best;
}

/* Candidate normals of an answer: the best direction, its Newton polish, and the kinks it is
 * within CVX_NEAR of (a point; the optimum on a circle; two circles' crossing): a search that ended
 * 1e-8 rad off a kink has the right value but support points off by radius x angle. */
static int answer_candidates(cvx *s, prox_vec3 *c, int max)
{
    int nc = 0;
    prox_vec3 d0 = s->best_d;
    c[nc++] = d0;
    c[nc++] = polish_cell(s, d0);
    for (int i = 0; i < s->nk && nc < max; ++i) {
        const cvx_kink *k = &s->k[i];
        if (kink_dist(k, d0) > CVX_NEAR) continue;
        if (!k->circle) { c[nc++] = k->w; continue; }
        c[nc++] = circ_near(s, k, d0, 2.0 * CVX_NEAR, 1);
        for (int j = i + 1; j < s->nk && nc + 2 <= max; ++j) {
            prox_vec3 x[2];
            if (!s->k[j].circle || kink_dist(&s->k[j], d0) > CVX_NEAR) continue;
            for (int m = circle_cross(k, &s->k[j], x) - 1; m >= 0; --m)
                if (angle(x[m], d0) <= 4.0 * CVX_NEAR) c[nc++] = x[m];
        }
    }
    return nc;
}

typedef struct cvx_answer {
    double lower, upper;  /* -phi at the best direction, |p2 - p1| */
    prox_vec3 n, p1, p2;
} cvx_answer;

/* The closest candidate pair; among pairs equally close to rounding, the one nearest to being the
 * closest pair: p2 - p1 along its normal, and each point its body's closest point to the other (a
 * pair aligned with its own normal to 6e-17 S can still stand 5e-10 S along a flat direction of the
 * contact: a cone against a cylinder's lateral surface). The simplex pair of GJK, polished, is a
 * candidate too. A pair nearer than the proven lower bound -phi(best) (less PROX_TOL_CERT S) cannot
 * lie in both solids (a needle's support point lifted off its rim: 3.8e-13 apart where the distance
 * is 1.9e-10) and is taken only when no other pair is left, uncertified. */
static cvx_answer finish_disjoint(cvx *s, const gjk_out *g)
{
    prox_vec3 c[24];
    int nc = answer_candidates(s, c, 24);
    cvx_answer r = {-s->best_phi, INFINITY, s->best_d, {0, 0, 0}, {0, 0, 0}};
    double align = INFINITY, tie = PROX_TOL_SNAP * s->S, floor = -phi_eval(s, s->best_d) - PROX_TOL_CERT * s->S;
    for (int pass = 0; pass < 2 && !(r.upper < INFINITY); ++pass)
        for (int k = 0; k < nc; ++k) {
            prox_vec3 x = {0, 0, 0}, y = x;
            double dk = witness_disjoint(s, c[k], &x, &y);
            if (pass == 0 && dk < floor) continue;
            if (!(dk <= r.upper + tie)) continue;
            double ak = fmax(prox_v3_norm(prox_v3_mad(prox_v3_sub(y, x), -dk, c[k])), pair_residual(s, x, y));
            if (dk < r.upper - tie || ak < align) {
                if (dk < r.upper) r.upper = dk;
                align = ak, r.p1 = x, r.p2 = y, r.n = c[k];
            }
        }
    if (g && g->verdict == 1 && g->vnorm < r.upper - tie && !(g->vnorm < floor)) {
        prox_vec3 x = g->xa, y = g->xb;
        r.upper = g->vnorm, r.p1 = x, r.p2 = y, r.n = s->best_d;
    }
    r.upper = prox_v3_dist(r.p1, r.p2);
    r.lower = -phi_eval(s, s->best_d); /* from the support functions, whichever way it was found */
    return r;
}

/* Disjoint pairs: phi/|D| has convex sublevel sets below 0, so the local search is global: Newton in
 * the cell, the kinks near the best direction, again until nothing moves. */
static void search_disjoint(cvx *s)
{
    for (int pass = 0; pass < 4; ++pass) {
        prox_vec3 d0 = s->best_d;
        cell_newton(s, d0);
        kinks_local(s, s->best_d, CVX_LOCAL);
        if (pass > 0 && prox_v3_dot(d0, s->best_d) == 1.0) break;
    }
}

static cvx_answer solve_disjoint(cvx *s, const gjk_out *g, prox_convex_info *info)
{
    search_disjoint(s);
    cvx_answer r = finish_disjoint(s, g);
    if (!(fabs(r.upper - r.lower) <= PROX_TOL_CERT * s->S)) {
        /* the slow path: a search stalled on a kink the local list missed; every kink searched whole */
        atomic_fetch_add(&cvx_global_runs, 1);
        info->global = 1;
        kinks_global(s);
        search_disjoint(s);
        cvx_answer r2 = finish_disjoint(s, g);
        if (fabs(r2.upper - r2.lower) < fabs(r.upper - r.lower)) r = r2;
    }
    info->certified = fabs(r.upper - r.lower) <= PROX_TOL_CERT * s->S;
    return r;
}

/* ---- depth: global search and its certificate ----------------------------------------------------- */

static const double cvx_ico_v[12][3] = {
    {-1, CVX_GOLD, 0}, {1, CVX_GOLD, 0}, {-1, -CVX_GOLD, 0}, {1, -CVX_GOLD, 0},
    {0, -1, CVX_GOLD}, {0, 1, CVX_GOLD}, {0, -1, -CVX_GOLD}, {0, 1, -CVX_GOLD},
    {CVX_GOLD, 0, -1}, {CVX_GOLD, 0, 1}, {-CVX_GOLD, 0, -1}, {-CVX_GOLD, 0, 1}};
static const unsigned char cvx_ico_f[20][3] = {
    {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
    {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};

static prox_vec3 ico_vertex(int i) { return unit(prox_v3(cvx_ico_v[i][0], cvx_ico_v[i][1], cvx_ico_v[i][2])); }


/* Over the cap of radius rho around unit c, the range [amin, amax] of the angle to the unit axis w. */
static void cap_angles(prox_vec3 w, prox_vec3 c, double rho, double *amin, double *amax)
{
    double al = angle(c, w);
    *amin = prox_max2(0.0, al - rho);
    *amax = prox_min2(PROX_PI, al + rho);
}

/* min over the angle range of hh |cos a| + r sin a (concave in cos a on each side of a = pi/2). */
static double lateral_min(double hh, double r, double amin, double amax)
{
    double f = prox_min2(hh * fabs(cos(amin)) + r * sin(amin), hh * fabs(cos(amax)) + r * sin(amax));
    return amin < 0.5 * PROX_PI && amax > 0.5 * PROX_PI ? prox_min2(f, r) : f;
}

static double cone_at(const prox_cone *k, double a)
{
    double t = cos(a), p = sin(a);
    return prox_max2(-k->hh * t + k->r1 * p, k->hh * t + k->r2 * p);
}

/* The exact minimum (a lower bound for ECYL and the polytopes) of hc over the cap around unit c. */
static double body_cap(const prox_body *b, prox_vec3 c, double rho)
{
    double amin, amax;
    switch (b->kind) {
    case PROX_BODY_SPH: return b->r;
    case PROX_BODY_ELL: {
        const prox_ellb *k = &b->x.ell;
        cap_angles(k->w, c, rho, &amin, &amax);
        double e = k->a * k->a - k->b * k->b, t2;
        if (e >= 0.0) t2 = amin <= 0.5 * PROX_PI && amax >= 0.5 * PROX_PI ? 0.0 : prox_min2(cos(amin) * cos(amin), cos(amax) * cos(amax));
        else t2 = prox_max2(cos(amin) * cos(amin), cos(amax) * cos(amax));
        return sqrt(prox_max2(0.0, k->b * k->b + e * t2));
    }
    case PROX_BODY_CYL:
        cap_angles(b->cyl.w, c, rho, &amin, &amax);
        return lateral_min(b->cyl.hh, b->cyl.r, amin, amax);
    case PROX_BODY_ECYL:
        cap_angles(b->x.ecyl.w, c, rho, &amin, &amax);
        return lateral_min(b->x.ecyl.hh, prox_min2(b->x.ecyl.a1, b->x.ecyl.a2), amin, amax);
    case PROX_BODY_CONE: {
        const prox_cone *k = &b->x.cone;
        cap_angles(k->w, c, rho, &amin, &amax);
        double f = prox_min2(cone_at(k, amin), cone_at(k, amax)), as = atan2(2.0 * k->hh, k->r1 - k->r2);
        return as > amin && as < amax ? prox_min2(f, cone_at(k, as)) : f;
    }
    case PROX_BODY_BOX: {
        double f = 0.0;
        for (int i = 0; i < 3; ++i) {
            cap_angles(b->box.a[i], c, rho, &amin, &amax);
            double m = amin <= 0.5 * PROX_PI && amax >= 0.5 * PROX_PI ? 0.0 : prox_min2(fabs(cos(amin)), fabs(cos(amax)));
            f += b->box.h[i] * m;
        }
        return f;
    }
    case PROX_BODY_POLY: {
        double f = -INFINITY;
        for (int i = 0; i < b->x.poly.nv; ++i) {
            prox_vec3 v = b->x.poly.v[i];
            f = prox_max2(f, prox_v3_norm(v) * cos(prox_min2(PROX_PI, angle(v, c) + rho)));
        }
        return f;
    }
    default: return -INFINITY;
    }
}

/* A lower bound on phi over the cap of radius rho around unit c, from points g_j of P (support
 * points: h_P(D) >= g_j . D for every D): with D = (c + x) / |c + x|, |x| <= tan rho, x across c,
 * phi(D) >= M(x) / |c + x| for M(x) = max_j g_j . (c + x), so the bound is min M over the disk times
 * cos rho (when positive). The better of that and the sum of each term's own minimum over the cap. */
static double cap_bound(const cvx *s, prox_vec3 c, const prox_vec3 *d, const prox_vec3 *g, int ng, double rho, double T, int need)
{
    /* a sphere is its centre plus a ball: P = P' + ball(rb) and h_P = h_P' + rb on the unit sphere,
     * exactly; only h_P' is bounded by its planes (which would lose rb rho^2 / 2 on the ball) */
    double rb = (s->a.kind == PROX_BODY_SPH ? s->a.r : 0.0) + (s->b.kind == PROX_BODY_SPH ? s->b.r : 0.0);
    double round = PROX_TOL_PHI_ROUND * s->S, lb = -INFINITY, r = 0.0, cr = 1.0;
    prox_vec3 t1 = prox_v3_any_perp(c), t2 = prox_v3_cross(c, t1);
    double a[8];
    v2 b[8];
    for (int j = 0; j < ng; ++j) {
        prox_vec3 gj = prox_v3_mad(g[j], -rb, d[j]);
        a[j] = prox_v3_dot(gj, c), b[j].x = prox_v3_dot(gj, t1), b[j].y = prox_v3_dot(gj, t2);
    }
    /* the bounds from the cheapest up, each returned once it reaches T (the cover's threshold): the
     * best single plane's own minimum a_j - |b_j| r over the disk; whether their combination stays
     * at or above T on the disk; each body's own minimum over the cap. The exact minimum of the
     * combination only when the caller needs the value below T (need). */
    if (rho < 1.5) {
        r = tan(rho), cr = cos(rho);
        double one = -INFINITY;
        for (int j = 0; j < ng; ++j) one = prox_max2(one, a[j] - prox_v2_norm(b[j]) * r);
        lb = (one > 0.0 ? one * cr : one) + rb - round;
        if (lb >= T) return lb;
        double tt = T - rb + round; /* M cr + rb - round >= T for M >= mt (M <= 0: no scaling) */
        if (prox_pl_disk_above(a, b, ng, r, tt > 0.0 ? tt / cr : tt)) return T;
    }
    double dn = prox_v3_norm(s->delta), dl = dn > 0.0 ? -dn * cos(prox_max2(0.0, angle(c, s->delta) - rho)) : 0.0;
    lb = prox_max2(lb, body_cap(&s->a, c, rho) + body_cap(&s->b, prox_v3_neg(c), rho) + dl - round);
    if (lb >= T || !need || !(rho < 1.5)) return lb;
    double comb = prox_pl_disk_min(a, b, ng, r);
    return prox_max2(lb, (comb > 0.0 ? comb * cr : comb) + rb - round);
}

typedef struct cvx_cover {
    double tol, lb;
    long cells;
    int incomplete;
    prox_vec3 bd, gb; /* the best direction and its support point of P */
} cvx_cover;

/* One geodesic triangle q[] (support points of P gq[]) of the cover: pruned when its cap's bound is
 * within tol of the best depth, else split into four (normalised edge midpoints: the children tile
 * it). A centre better than the best starts a local search there. */
static void cover_tri(cvx *s, cvx_cover *cv, const prox_vec3 *q, const prox_vec3 *gq, int depth)
{
    ++cv->cells;
    prox_vec3 c = unit(prox_v3_add(prox_v3_add(q[0], q[1]), q[2])), gc = phi_grad(s, c);
    /* the cap's radius from the longest chord x: the angle 2 asin(x / 2) <= x / sqrt(1 - x^2 / 4) */
    double x2 = prox_max2(prox_v3_norm2(prox_v3_sub(c, q[0])), prox_max2(prox_v3_norm2(prox_v3_sub(c, q[1])), prox_v3_norm2(prox_v3_sub(c, q[2]))));
    double rho = sqrt(x2 / prox_max2(1.0 - 0.25 * x2, 0.25)) * (1.0 + 1e-12) + 4.0 * DBL_EPSILON;
    double f = prox_v3_dot(gc, c), best0 = s->best_phi; /* phi(c) = h_P(c), from its support point */
    record(s, c, f);
    if (f < best0 - cv->tol) {
        cell_newton(s, c);
        kinks_local(s, s->best_d, CVX_LOCAL);
    }
    if (!(prox_v3_dot(cv->bd, s->best_d) == 1.0)) cv->bd = s->best_d, cv->gb = phi_grad(s, s->best_d);
    prox_vec3 g[5] = {gc, gq[0], gq[1], gq[2], cv->gb}, d[5] = {c, q[0], q[1], q[2], cv->bd};
    int last = depth >= CVX_BB_DEPTH || cv->cells >= CVX_BB_BUDGET; /* no split: the bound is kept */
    double lb = cap_bound(s, c, d, g, 5, rho, s->best_phi - cv->tol, last);
    if (lb >= s->best_phi - cv->tol) { cv->lb = prox_min2(cv->lb, lb); return; }
    if (last) {
        cv->lb = prox_min2(cv->lb, lb);
        cv->incomplete = 1;
        return;
    }
    prox_vec3 m[3] = {unit(prox_v3_add(q[0], q[1])), unit(prox_v3_add(q[1], q[2])), unit(prox_v3_add(q[2], q[0]))};
    prox_vec3 gm[3] = {phi_grad(s, m[0]), phi_grad(s, m[1]), phi_grad(s, m[2])};
    prox_vec3 t0[3] = {q[0], m[0], m[2]}, g0[3] = {gq[0], gm[0], gm[2]};
    prox_vec3 t1[3] = {m[0], q[1], m[1]}, g1[3] = {gm[0], gq[1], gm[1]};
    prox_vec3 t2[3] = {m[2], m[1], q[2]}, g2[3] = {gm[2], gm[1], gq[2]};
    cover_tri(s, cv, t0, g0, depth + 1);
    cover_tri(s, cv, t1, g1, depth + 1);
    cover_tri(s, cv, t2, g2, depth + 1);
    cover_tri(s, cv, m, gm, depth + 1);
}

/* Starts of the depth search: the centre line, the icosahedron's vertices and the centres of its
 * faces split once, every kink (points, crossings, circles searched whole); then Newton and the
 * local kinks from the best distinct starts. Returns 1 when a separating direction turned up. */
static int depth_starts(cvx *s)
{
    if (prox_v3_norm2(s->delta) > 0.0) consider(s, s->delta), consider(s, prox_v3_neg(s->delta));
    for (int i = 0; i < 12; ++i) consider(s, ico_vertex(i));
    for (int f = 0; f < 20; ++f) {
        prox_vec3 q0 = ico_vertex(cvx_ico_f[f][0]), q1 = ico_vertex(cvx_ico_f[f][1]), q2 = ico_vertex(cvx_ico_f[f][2]);
        prox_vec3 m01 = unit(prox_v3_add(q0, q1)), m12 = unit(prox_v3_add(q1, q2)), m20 = unit(prox_v3_add(q2, q0));
        consider(s, prox_v3_add(prox_v3_add(q0, m01), m20));
        consider(s, prox_v3_add(prox_v3_add(m01, q1), m12));
        consider(s, prox_v3_add(prox_v3_add(m20, m12), q2));
        consider(s, prox_v3_add(prox_v3_add(m01, m12), m20));
    }
    kinks_global(s);
    if (s->best_phi < 0.0) return 1;
    prox_vec3 st[CVX_TOPK];
    int ns = s->ntop;
    for (int i = 0; i < ns; ++i) st[i] = s->td[i];
    prox_vec3 done = {0, 0, 0}; /* the kinks near the best are searched once per best */
    for (int i = 0; i < ns; ++i) {
        s->halvings = CVX_GRAD_HALVINGS;
        cell_newton(s, st[i]);
        s->halvings = 30;
        if (prox_v3_dot(done, s->best_d) == 1.0) continue;
        done = s->best_d;
        kinks_local(s, s->best_d, CVX_LOCAL);
    }
    cell_newton(s, s->best_d);
    return s->best_phi < 0.0;
}

/* Newton and the local kinks again from the best direction, while they improve it. The starts' last
 * Newton can begin on a kink (a subgradient step that does not descend) and the cover records cell
 * centres, searching locally only from one better than the best by its tolerance, so the best can
 * be left at a non-stationary point of a smooth cell (an ELL against a box vertex: 0.17 rad off, the
 * depth 1e-3 S too large, p2 - p1 1e-2 S off the normal); Newton from there reaches the minimum. */
static void descend_within(cvx *s, double r)
{
    for (int it = 0; it < 4; ++it) {
        double f0 = s->best_phi;
        cell_newton(s, s->best_d);
        kinks_local(s, s->best_d, r);
        if (!(s->best_phi < f0)) break;
    }
}

static void descend_best(cvx *s) { descend_within(s, CVX_LOCAL); }

/* A ball inside body b touching its boundary point x (outward normal n): the largest offset r <= rmax
 * (to 2^-10 of rmax) whose centre x - r n lies at depth >= r less the rounding slack
 * (prox_body_boundary); *rad receives that centre's depth less the slack, a radius proved to fit. The
 * depth in a convex body is concave, so the offsets that fit form an interval [0, r*]; an edge, rim
 * or vertex point fits none (returns 0). */
static double tangent_ball(const prox_body *b, prox_vec3 x, prox_vec3 n, double rmax, double slack, double *rad)
{
    prox_vec3 q;
    *rad = 0.0;
    if (!(rmax > 0.0)) return 0.0;
    double dep = -prox_body_boundary(b, prox_v3_mad(x, -rmax, n), &q) - slack;
    if (dep >= rmax - 2.0 * slack) { *rad = dep; return rmax; }
    double lo = 0.0, hi = rmax;
    for (int i = 0; i < 10; ++i) {
        double m = 0.5 * (lo + hi);
        dep = -prox_body_boundary(b, prox_v3_mad(x, -m, n), &q) - slack;
        if (dep >= m - 2.0 * slack) lo = m, *rad = dep;
        else hi = m;
    }
    return lo;
}

/* A lower bound on the depth from two tangent balls at the witnesses p1 (on A, outward normal n) and
 * p2 (on B, outward normal -n): A - B contains the ball of centre (p1 - ra n) - (p2 + rb n) and radius
 * the sum of the two radii proved, hence the ball about the origin of that radius less |centre|.
 * With p1 - p2 = phi n at the optimum it is phi itself, to rounding, once ra + rb reaches phi: a
 * shallow contact of smooth or flat parts is proved without the cover. -INFINITY when no ball fits. */
static double ball_bound(const cvx *s, prox_vec3 n, prox_vec3 p1, prox_vec3 p2)
{
    double phi = s->best_phi, slack = PROX_TOL_PHI_ROUND * s->S, qa, qb = 0.0;
    double ra = tangent_ball(&s->a, p1, n, phi, slack, &qa);
    double rb = ra < phi ? tangent_ball(&s->b, p2, prox_v3_neg(n), phi - ra, slack, &qb) : 0.0;
    if (!(qa + qb > 0.0)) return -INFINITY;
    prox_vec3 c = prox_v3_sub(prox_v3_mad(p1, -ra, n), prox_v3_mad(p2, rb, n));
    return qa + qb - prox_v3_norm(c) - slack;
}

static double finish_overlap(cvx *s, prox_signed_result *r);

/* 1 when the lower bound lb of the depth proves the answer r (within PROX_TOL_DEPTH_CERT S of the
 * best found); info filled with what was proved. */
static int bound_proves(const cvx *s, const prox_signed_result *r, double lb, prox_convex_info *info)
{
    if (!(lb >= s->best_phi - PROX_TOL_DEPTH_CERT * s->S)) return 0;
    info->lower = fmin(lb, s->best_phi);
    info->upper = -r->sd;
    info->certified = 1;
    return 1;
}

/* 1 when the ellipsoid inside the Minkowski difference of two ellipsoids, touching it along the best
 * direction (ell_depth.h), proves the depth (info filled). Tried before the tangent balls: it proves
 * 96 % of overlapping ellipsoid pairs (the balls 78 %, the shallow ones) at a third of their cost,
 * and deep overlaps, which the inner polytope proves only with hundreds of points. */
static int ellipsoid_certified(const cvx *s, const prox_signed_result *r, prox_convex_info *info)
{
    if (!prox_ell_pair(&s->a, &s->b)) return 0;
    return bound_proves(s, r, prox_ell_depth_lower(&s->a, &s->b, s->delta, s->best_d, s->S), info);
}

/* 1 when the tangent balls at the answer's witnesses prove its depth (info filled). */
static int ball_certified(const cvx *s, const prox_signed_result *r, prox_convex_info *info)
{
    return bound_proves(s, r, ball_bound(s, r->normal, r->p1, r->p2), info);
}

/* The support point of P for the inner polytope (epa.h); its direction is kept as a candidate. */
static prox_vec3 epa_support(void *ctx, prox_vec3 d, double *h)
{
    cvx *s = ctx;
    prox_vec3 g = phi_grad(s, d);
    *h = prox_v3_dot(g, d); /* phi(d) from its support point (the answer re-evaluates its candidates) */
    record(s, d, *h);
    return g;
}

/* The icosahedron's vertex i turned so that vertex 0 lies along the unit pole and then by the angle
 * twist about it (a rotation: both frames are right-handed, so the triangles keep their orientation). */
static prox_vec3 ico_turned(int i, prox_vec3 pole, double twist)
{
    prox_vec3 v0 = ico_vertex(0), a0 = prox_v3_any_perp(v0), b0 = prox_v3_cross(v0, a0);
    prox_vec3 p = prox_v3_any_perp(pole), q = prox_v3_cross(pole, p), x = ico_vertex(i);
    prox_vec3 a1 = prox_v3_add(prox_v3_scale(p, cos(twist)), prox_v3_scale(q, sin(twist)));
    prox_vec3 b1 = prox_v3_cross(pole, a1);
    return prox_v3_add(prox_v3_add(prox_v3_scale(a1, prox_v3_dot(x, a0)), prox_v3_scale(b1, prox_v3_dot(x, b0))),
                       prox_v3_scale(pole, prox_v3_dot(x, v0)));
}

/* An inner polytope of P, refined towards the deepest direction until its nearest triangle proves
 * the best depth found (epa.h); *lower the bound. It starts from the icosahedron's support points
 * (the icosahedron turned to put a vertex at *pole, then twisted, when pole is given); when their
 * mesh folds about the origin (a thin P with the origin near its rim), from GJK's final
 * tetrahedron, which encloses the origin. */
static int epa_proves_at(cvx *s, const gjk_out *go, const prox_vec3 *pole, double twist, double *lower)
{
    static const unsigned char tet[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    prox_vec3 g[12];
    for (int i = 0; i < 12; ++i) g[i] = phi_grad(s, pole ? ico_turned(i, *pole, twist) : ico_vertex(i));
    prox_epa_result e;
    int cap = s->nk == 0 ? CVX_EPA_POINTS_SMOOTH : CVX_EPA_POINTS;
    double tol = PROX_TOL_DEPTH_CERT * s->S, slack = PROX_TOL_PHI_ROUND * s->S;
    int ok = prox_epa_depth(epa_support, s, g, 12, cvx_ico_f, 20, s->best_phi, s->best_d, tol, slack, cap, &e);
    if (!ok && e.points == 0 && go->n == 4) {
        prox_vec3 t[4] = {go->w[0], go->w[1], go->w[2], go->w[3]};
        prox_vec3 x = prox_v3_cross(prox_v3_sub(t[1], t[0]), prox_v3_sub(t[2], t[0]));
        if (prox_v3_dot(x, prox_v3_sub(t[3], t[0])) < 0.0) t[1] = go->w[2], t[2] = go->w[1]; /* w3 behind face 0,2,1 */
        ok = prox_epa_depth(epa_support, s, t, 4, tet, 4, s->best_phi, s->best_d, tol, slack, cap, &e);
    }
    *lower = e.lower;
    return ok;
}

static int epa_proves(cvx *s, const gjk_out *go, double *lower) { return epa_proves_at(s, go, NULL, 0.0, lower); }

/* The depth without the global search, from the best of the centre line and the icosahedron's
 * vertices: Newton and the local kinks give the answer, proved by the inner ellipsoid (two
 * ellipsoids, ell_depth.h), by the tangent balls at its witnesses (a shallow contact of smooth or
 * flat parts) or by the inner polytope. A pair with kinks (a rim, an edge: the balls rarely fit
 * there) builds the polytope first, whose support points bring the descent near the deepest
 * direction; a smooth pair tries the ellipsoid and the balls first. Returns 0 (the best direction
 * left for the global search) when none proves it. */
static int depth_quick(cvx *s, const gjk_out *go, prox_signed_result *r, prox_convex_info *info)
{
    if (prox_v3_norm2(s->delta) > 0.0) consider(s, s->delta), consider(s, prox_v3_neg(s->delta));
    for (int i = 0; i < 12; ++i) consider(s, ico_vertex(i));
    double lower = -INFINITY;
    int epa = s->nk > 0 && s->best_phi > 0.0 && epa_proves(s, go, &lower);
    s->halvings = epa ? CVX_GRAD_HALVINGS : s->halvings; /* after the proof: a step that needs more has met a kink */
    descend_within(s, epa ? CVX_EPA_LOCAL : CVX_LOCAL);
    s->halvings = 30;
    if (!(s->best_phi > 0.0)) return 0;
    double res = finish_overlap(s, r);
    if (epa && !(res <= PROX_TOL_TOUCH * s->S)) {
        /* the proof holds within 1e-10 S, which for a pair whose scale is its far parts (a tall REC
         * against a unit wedge at its side: 1.3e-5 there) leaves the best direction 1e-2 rad off the
         * optimum and its witnesses off the normal: the wider search of the global path, once */
        descend_best(s);
        finish_overlap(s, r);
    }
    if (!epa && ellipsoid_certified(s, r, info)) return 1;
    if (!epa && ball_certified(s, r, info)) return 1;
    if (!epa && s->nk == 0 && epa_proves(s, go, &lower)) { /* its support points may have found a deeper one */
        descend_best(s);
        finish_overlap(s, r);
        epa = 1;
    }
    /* a kinked pair whose polytope stalled (a rim of the fan pinched at a corner, a fold it could
     * not leave) tries again from the icosahedron turned to the best direction, which starts a
     * different mesh with a support point at the deepest direction already, then from that one
     * twisted about it by pi/5 (half the turn that maps the icosahedron onto itself about a vertex):
     * nearly every such pair is then proved without the cover */
    for (int k = 0; !epa && s->nk > 0 && k < CVX_EPA_TURNS; ++k) {
        if (!epa_proves_at(s, go, &s->best_d, k * (PROX_PI / 5.0), &lower)) continue;
        descend_best(s);
        finish_overlap(s, r);
        epa = 1;
    }
    if (!epa) return 0;
    /* the bound holds for the best found since (which is no larger) */
    info->lower = fmin(lower, s->best_phi);
    info->upper = -r->sd;
    info->certified = 1;
    return 1;
}

/* The cover of the sphere: a proven lower bound on the depth (convex.h). */
static void depth_cover(cvx *s, prox_convex_info *info)
{
    cvx_cover cv = {PROX_TOL_DEPTH_CERT * s->S, INFINITY, 0, 0, {0, 0, 0}, {0, 0, 0}};
    atomic_fetch_add(&cvx_global_runs, 1);
    info->global = 1;
    prox_vec3 v[12], gv[12];
    for (int i = 0; i < 12; ++i) v[i] = ico_vertex(i), gv[i] = phi_grad(s, v[i]);
    cv.bd = s->best_d, cv.gb = phi_grad(s, s->best_d);
    for (int f = 0; f < 20; ++f) {
        prox_vec3 q[3], gq[3];
        for (int k = 0; k < 3; ++k) q[k] = v[cvx_ico_f[f][k]], gq[k] = gv[cvx_ico_f[f][k]];
        cover_tri(s, &cv, q, gq, 0);
    }
    descend_best(s);
    info->cells = cv.cells;
    info->lower = fmin(cv.lb, s->best_phi);
    info->upper = s->best_phi;
    /* the pruning test itself (each pruned bound >= the best then less tol >= the best now less tol,
     * rounding being monotone), not best - lower <= tol, which can miss by an ulp */
    info->certified = !cv.incomplete && info->lower >= s->best_phi - cv.tol;
}

/* ---- entry points ------------------------------------------------------------------------------ */

/* The pair relative to A's reference point (exact by Sterbenz when the two are close compared with
 * their distance to the origin) and at unit scale (a power of two: exact); *o, *f receive both. */
static void pair_make(const prox_body *a, const prox_body *b, cvx *s, prox_vec3 *o, double *f)
{
    *o = a->c;
    prox_vec3 cb = prox_v3_sub(b->c, a->c);
    double S = fmax(prox_v3_norm(cb), fmax(a->size, b->size));
    *f = prox_unit_scale(S);
    prox_body_scaled_at(&s->a, a, prox_v3(0, 0, 0), *f); /* A at the origin, B relative to it */
    prox_body_scaled_at(&s->b, b, cb, *f);
    s->delta = prox_v3_sub(s->b.c, s->a.c);
    s->S = S * *f;
    s->gjk_rel = 0.0;
    s->near = CVX_NEAR_GJK;
    s->best_phi = INFINITY;
    s->best_d = prox_v3(0, 0, 1);
    s->halvings = s->nhalvings = 30;
    s->nk = s->ntop = 0;
    body_kinks(s, &s->a, 1.0);
    body_kinks(s, &s->b, -1.0);
}

static prox_vec3 to_abs(prox_vec3 o, double f, prox_vec3 p) { return prox_v3_mad(o, 1.0 / f, p); }

/* The depth answer: among the candidate normals whose depth is within PROX_TOL_TOUCH S of the best,
 * the one whose witnesses meet p2 - p1 = sd n best. The best direction is tried first, alone: its
 * witnesses meet exactly for most pairs (78 % of overlapping TRC-RCC pairs), and the other
 * candidates (its polish, the kinks near it: answer_candidates) are searched only when they do not. */
static double finish_overlap(cvx *s, prox_signed_result *r)
{
    prox_vec3 c[24] = {s->best_d};
    int nc = 1;
    double best = INFINITY, lim = s->best_phi + PROX_TOL_TOUCH * s->S;
    r->sd = -s->best_phi, r->normal = s->best_d;
    support_points(s, s->best_d, &r->p1, &r->p2);
    for (int k = 0; k < nc; ++k) {
        double f = phi_eval(s, c[k]);
        if (f <= lim) {
            prox_vec3 x = {0, 0, 0}, y = x;
            double e = witness_overlap(s, c[k], -f, &x, &y);
            if (e < best) best = e, r->sd = -f, r->normal = c[k], r->p1 = x, r->p2 = y;
            if (best <= PROX_TOL_SEARCH * s->S) break; /* exact to rounding: no other candidate can matter */
        }
        if (k == 0) { /* the other candidates; their searches may lower the best */
            nc = answer_candidates(s, c, 24);
            lim = s->best_phi + PROX_TOL_TOUCH * s->S;
        }
    }
    double e0 = best, e;
    /* each witness replaced by its body's boundary point nearest p_other -+ sd n, in turn, while that
     * brings them nearer (a needle's support point moves 1e10 times faster than the normal: one
     * replacement of each left 5e-9 S) */
    prox_vec3 q, m = prox_v3_scale(r->normal, r->sd);
    for (int it = 0; it < 8 && best > 0.0; ++it) {
        double before = best;
        prox_body_boundary(&s->a, prox_v3_sub(r->p2, m), &q);
        if ((e = prox_v3_norm(prox_v3_sub(prox_v3_sub(r->p2, q), m))) < best) best = e, r->p1 = q;
        prox_body_boundary(&s->b, prox_v3_add(r->p1, m), &q);
        if ((e = prox_v3_norm(prox_v3_sub(prox_v3_sub(q, r->p1), m))) < best) best = e, r->p2 = q;
        if (!(best < before)) break;
    }
    return e0; /* |p2 - p1 - sd n| of the support sets' pair: far from 0 off the optimum */
}

/* A pair that GJK found overlapping but a direction of negative phi separates (touching to
 * rounding): the disjoint answer. */
static prox_signed_result signed_touching(cvx *s, prox_convex_info *info, const gjk_out *g)
{
    prox_signed_result r = {0};
    r.status = PROX_OK;
    cvx_answer a = solve_disjoint(s, g, info);
    r.sd = a.upper, r.normal = a.n, r.p1 = a.p1, r.p2 = a.p2;
    info->intersect = 0, info->lower = a.lower, info->upper = a.upper;
    return r;
}

/* The signed answer of the scaled pair (unit-scale units) after GJK's run g. */
static prox_signed_result signed_scaled(cvx *s, prox_convex_info *info, gjk_out g, int full)
{
    prox_signed_result r = {0};
    r.status = PROX_OK;
    if (!(s->best_phi < 0.0) && g.verdict != 0) depth_starts(s); /* a stalled GJK: look wider */
    if (s->best_phi < 0.0 && g.verdict != 0) {
        cvx_answer a = solve_disjoint(s, &g, info);
        r.sd = a.upper, r.normal = a.n, r.p1 = a.p1, r.p2 = a.p2;
        info->lower = a.lower, info->upper = a.upper;
        return r;
    }
    info->intersect = 1;
    if (!full && g.verdict == 0 && depth_quick(s, &g, &r, info)) return r;
    if (g.verdict == 0 && depth_starts(s)) return signed_touching(s, info, &g);
    descend_best(s);
    finish_overlap(s, &r);
    if (!full && ball_certified(s, &r, info)) return r;
    depth_cover(s, info);
    if (s->best_phi < 0.0) return signed_touching(s, info, &g);
    finish_overlap(s, &r);
    info->upper = -r.sd; /* the depth reported (within PROX_TOL_TOUCH S of the best found) */
    return r;
}

static int gjk_certified(cvx *s, const gjk_out *g, cvx_answer *r);
static int newton_certified(cvx *s, const gjk_out *g, cvx_answer *r);
static int smooth_certified(cvx *s, cvx_answer *r);

/* A disjoint pair certified early: the pair along its own direction, and that direction the normal. */
static prox_signed_result signed_early(cvx *s, prox_convex_info *info, const cvx_answer *e)
{
    (void)s;
    atomic_fetch_add(&cvx_gjk_cert, 1);
    prox_signed_result r = {0};
    r.status = PROX_OK;
    r.sd = e->upper, r.normal = e->n, r.p1 = e->p1, r.p2 = e->p2;
    info->certified = 1, info->lower = e->lower, info->upper = e->upper;
    return r;
}

/* The signed answer of a scaled pair: a disjoint pair first tries the distance query's cheap
 * certificates (GJK stopped at CVX_GJK_LOOSE, Newton and the kinks near its direction; then GJK to
 * rounding, its pair, Newton and the kinks again), whose pair along its own direction is the answer
 * with its normal. */
static prox_signed_result signed_run(const prox_body *a, const prox_body *b, cvx *s, prox_convex_info *info, int full)
{
    if (full) return signed_scaled(s, info, gjk_run(s), 1);
    cvx_answer e;
    if (smooth_certified(s, &e)) return signed_early(s, info, &e);
    s->gjk_rel = CVX_GJK_LOOSE, s->near = CVX_NEAR_LOOSE;
    gjk_out g = gjk_run(s);
    int early = g.verdict == 1 && (gjk_certified(s, &g, &e) || newton_certified(s, &g, &e));
    if (!early && g.verdict == 1) { /* to rounding, from the start */
        prox_vec3 o;
        double f;
        pair_make(a, b, s, &o, &f);
        g = gjk_run(s);
        early = g.verdict == 1 && (gjk_certified(s, &g, &e) || newton_certified(s, &g, &e));
    }
    if (!early) return signed_scaled(s, info, g, 0);
    return signed_early(s, info, &e);
}

static prox_signed_result signed_entry(const prox_body *a, const prox_body *b, prox_convex_info *info, int full)
{
    prox_convex_info tmp;
    if (!info) info = &tmp;
    *info = (prox_convex_info){0};
    cvx s;
    prox_vec3 o;
    double f;
    pair_make(a, b, &s, &o, &f);
    prox_signed_result r = signed_run(a, b, &s, info, full);
    r.sd /= f;
    r.p1 = to_abs(o, f, r.p1);
    r.p2 = to_abs(o, f, r.p2);
    info->lower /= f;
    info->upper /= f;
    /* what it proved, for the enclosure (prox_body_signed_bounds): the cover's lower bound of the
     * depth, or the duality bound of the distance */
    if (r.sd <= 0.0 && info->intersect && info->certified) r.certified = 1, r.sd_upper = -info->lower;
    if (r.sd > 0.0) r.sd_lower = info->lower;
    return r;
}

prox_signed_result prox_convex_signed_ex(const prox_body *a, const prox_body *b, prox_convex_info *info)
{
    return signed_entry(a, b, info, 0);
}

prox_signed_result prox_convex_signed_full(const prox_body *a, const prox_body *b, prox_convex_info *info)
{
    return signed_entry(a, b, info, 1);
}

prox_signed_result prox_convex_signed(const prox_body *a, const prox_body *b) { return prox_convex_signed_ex(a, b, NULL); }

/* Overlap answer of the distance query: a common point, certified when it lies in both solids within
 * the touching band. */
static double outside2(const cvx *s, prox_vec3 x)
{
    return fmax(prox_v3_dist(x, prox_body_closest(&s->a, x)), prox_v3_dist(x, prox_body_closest(&s->b, x)));
}

/* A touching pair's common point: the middle of the witnesses of its signed distance (global starts
 * and local searches, no cover), p2 - p1 = sd n, which is within |sd| / 2 of both solids. */
static prox_vec3 touching_point(cvx *s)
{
    prox_signed_result r = {0};
    if (depth_starts(s)) {
        search_disjoint(s);
        cvx_answer a = finish_disjoint(s, NULL);
        r.p1 = a.p1, r.p2 = a.p2;
    } else finish_overlap(s, &r);
    return prox_v3_scale(prox_v3_add(r.p1, r.p2), 0.5);
}

/* Alternating exact projections from y (they approach A n B), keeping the point least outside
 * either solid; *best and *x updated. */
static void common_polish(const cvx *s, prox_vec3 y, double tol, double *best, prox_vec3 *x)
{
    double prev = INFINITY;
    for (int it = 0; it < 96; ++it) {
        double e = outside2(s, y);
        if (e < *best) *best = e, *x = y;
        if (!(e > 0.01 * tol) || !(e < prev)) return; /* well inside the band, or no progress */
        prev = e;
        y = prox_body_closest(&s->a, prox_body_closest(&s->b, y));
    }
}

static void common_point(cvx *s, const gjk_out *g, prox_distance_result *r, prox_convex_info *info)
{
    /* the simplex's pair (one point of each solid, equal to rounding of its barycentric solve) and
     * its middle, polished; then, for a touching pair whose enclosing simplex is ill-conditioned, the
     * middle of the least overlap's witnesses, polished */
    double tol = PROX_TOL_TOUCH * s->S, best = INFINITY;
    prox_vec3 cand[3] = {prox_v3_scale(prox_v3_add(g->xa, g->xb), 0.5), g->xa, g->xb}, x = cand[0];
    for (int k = 0; k < 3 && best > tol; ++k) common_polish(s, cand[k], tol, &best, &x);
    if (best > tol) common_polish(s, touching_point(s), tol, &best, &x);
    r->intersect = 1;
    r->distance = 0.0;
    r->p1 = r->p2 = x;
    r->certified = prox_body_contains(&s->a, x, tol) && prox_body_contains(&s->b, x, tol);
    info->intersect = 1;
    info->certified = r->certified;
}

/* 1 when both bodies are polytopes (a box or a polytope: their support sets are exact). */
static int polytopes(const cvx *s)
{
    return (s->a.kind == PROX_BODY_BOX || s->a.kind == PROX_BODY_POLY) &&
           (s->b.kind == PROX_BODY_BOX || s->b.kind == PROX_BODY_POLY);
}

/* The early certificate of a disjoint pair x in A, y in B: -phi along the pair's own direction meets
 * |y - x| and both points lie in their solids (prox_body_pair_certified, core/body.h). */
static int pair_certified(const cvx *s, prox_vec3 x, prox_vec3 y, cvx_answer *r)
{
    if (!prox_body_pair_certified(&s->a, &s->b, s->delta, s->S, x, y, NULL, &r->lower, &r->upper, &r->n)) return 0;
    r->p1 = x, r->p2 = y;
    return 1;
}

/* An early pair of a curved part made the closest: kept when each point is its body's closest point
 * to the other (the pair is then the closest one, the solids being convex); else the support sets'
 * pair of the answer's candidate normals (the certified one polished, the kinks near it:
 * finish_disjoint), when it certifies no farther apart. */
static void closest_pair(cvx *s, const gjk_out *g, cvx_answer *r)
{
    if (pair_residual(s, r->p1, r->p2) <= PROX_TOL_SEARCH * s->S) return;
    consider(s, r->n);
    cvx_answer f = finish_disjoint(s, g);
    if (fabs(f.upper - f.lower) <= PROX_TOL_CERT * s->S && f.upper <= r->upper + PROX_TOL_SNAP * s->S) *r = f;
}

/* An early certificate of the pair x in A, y in B (pair_certified). With a curved part the pair
 * certified may still stand off the closest one, flat as the distance is there: GJK's pair (convex
 * combinations of support points) up to its chords' sag inside a curved surface, 8e-9 S for an
 * elliptic cylinder 0.04 S from a cylinder; the support points at Newton's last iterate, ~1e-10 rad
 * off the normal, 4e-11 S; the support sets' pair at a direction on a kink circle, 3e-10 S (two
 * elliptic cylinders): closest_pair makes it the closest. */
static int early_pair(cvx *s, const gjk_out *g, prox_vec3 x, prox_vec3 y, cvx_answer *r)
{
    if (!pair_certified(s, x, y, r)) return 0;
    if (!polytopes(s)) closest_pair(s, g, r);
    return 1;
}

/* GJK's own certificate: most pairs end GJK with its simplex pair (convex combinations of support
 * points) and -phi within a few ulps of S, often close enough to the normal that the pair certifies
 * along its own direction; then the search and the support-set witnesses have nothing to add. */
static int gjk_certified(cvx *s, const gjk_out *g, cvx_answer *r)
{
    return g->verdict == 1 && s->best_phi < 0.0 && early_pair(s, g, g->xa, g->xb, r);
}

/* The next cheapest: Newton on the sphere from GJK's best direction (it reaches the normal of a
 * smooth contact quadratically; each line search gives up after CVX_GRAD_HALVINGS, where a step has
 * met a kink), the kink points near it (a polytope's face normals), the support points there; then
 * the kink circles within s->near of it (an edge or a rim: CVX_NEAR_LOOSE after the loose GJK,
 * CVX_NEAR_GJK after GJK to rounding) and the closest pair of the support sets at the best direction
 * alone (witness_disjoint). */
static int newton_certified(cvx *s, const gjk_out *g, cvx_answer *r)
{
    if (g->verdict != 1 || !(s->best_phi < 0.0)) return 0;
    s->halvings = s->nhalvings = CVX_GRAD_HALVINGS; /* a step that needs more has met a kink */
    prox_vec3 e = cell_newton(s, s->best_d);
    s->halvings = s->nhalvings = 30;
    prox_vec3 x, y;
    support_points(s, e, &x, &y); /* a smooth contact: the support points at Newton's last iterate */
    if (early_pair(s, g, x, y, r)) return 1;
    for (int i = 0; i < s->nk; ++i)
        if (!s->k[i].circle && kink_dist(&s->k[i], s->best_d) <= CVX_LOCAL) consider(s, s->k[i].w);
    support_points(s, s->best_d, &x, &y); /* a face's normal among the kink points */
    if (early_pair(s, g, x, y, r)) return 1;
    prox_vec3 k = kinks_local(s, s->best_d, s->near); /* an edge: the kink circles through the optimum */
    witness_disjoint(s, k, &x, &y);
    return early_pair(s, g, x, y, r);
}

/* A pair with no kinks (ELL and SPH: phi smooth everywhere) whose centres' direction separates them
 * (phi < 0 there): Newton on the sphere from that direction, where the Riemannian Hessian is positive
 * definite (phi < 0) and the step quadratic near the optimum, then the support points there, certified
 * along their own direction; no GJK at all. */
static int smooth_certified(cvx *s, cvx_answer *r)
{
    double dn = prox_v3_norm(s->delta);
    if (s->nk != 0 || !(dn > 0.0)) return 0;
    prox_vec3 d = prox_v3_scale(s->delta, 1.0 / dn);
    if (!(phi_eval(s, d) < 0.0)) return 0;
    prox_vec3 x, y;
    support_points(s, cell_newton(s, d), &x, &y);
    return pair_certified(s, x, y, r);
}

/* The distance query. mode CVX_FAST: GJK stopped at a relative gap of CVX_GJK_LOOSE (it converges
 * only linearly on curved bodies: to rounding it took ~23 iterations a pair on the bench's curved
 * pairs, stopped there ~14), then Newton from its best direction (quadratic on a smooth contact), the
 * kinks within CVX_NEAR_LOOSE of it (a rim or an edge: the loose direction is ~1e-3 rad off along
 * one) and the support sets there; not certified there, the query runs again in mode CVX_TIGHT: GJK
 * to rounding, its own certificate, Newton and the kinks within CVX_NEAR_GJK, then the full search.
 * CVX_FULL: GJK to rounding and the full search (the reference of the tests). */
enum { CVX_FAST, CVX_TIGHT, CVX_FULL };

/* The answer of the unit-scale pair in the caller's units and frame. */
static prox_distance_result distance_scaled_back(prox_distance_result *r, prox_convex_info *info, prox_vec3 o, double f)
{
    r->distance /= f;
    r->certificate_gap /= f;
    r->p1 = to_abs(o, f, r->p1);
    r->p2 = to_abs(o, f, r->p2);
    info->lower /= f;
    info->upper /= f;
    return *r;
}

static prox_distance_result distance_run(const prox_body *a, const prox_body *b, prox_convex_info *info, int mode)
{
    prox_convex_info tmp;
    if (!info) info = &tmp;
    *info = (prox_convex_info){0};
    prox_distance_result r = {0};
    r.status = PROX_OK;
    r.method = PROX_METHOD_SUPPORT;
    cvx s;
    prox_vec3 o;
    double f;
    pair_make(a, b, &s, &o, &f);
    cvx_answer ans = {0};
    if (mode == CVX_FAST && smooth_certified(&s, &ans)) {
        atomic_fetch_add(&cvx_gjk_cert, 1);
        info->certified = r.certified = 1;
        r.distance = ans.upper, r.p1 = ans.p1, r.p2 = ans.p2, r.certificate_gap = ans.lower;
        info->lower = ans.lower, info->upper = ans.upper;
        return distance_scaled_back(&r, info, o, f);
    }
    if (mode == CVX_FAST) s.gjk_rel = CVX_GJK_LOOSE, s.near = CVX_NEAR_LOOSE;
    gjk_out g = gjk_run(&s);
    int early = 0;
    if (mode == CVX_FAST && g.verdict == 1) {
        early = gjk_certified(&s, &g, &ans) || newton_certified(&s, &g, &ans);
        if (!early) return distance_run(a, b, info, CVX_TIGHT);
    }
    if (g.verdict == 2 && !(s.best_phi < 0.0) && g.vnorm > PROX_TOL_TOUCH * s.S) depth_starts(&s);
    if (mode == CVX_TIGHT) early = gjk_certified(&s, &g, &ans) || newton_certified(&s, &g, &ans);
    if (early) {
        atomic_fetch_add(&cvx_gjk_cert, 1);
        info->certified = 1;
    } else if (g.verdict != 0 && s.best_phi < 0.0) ans = solve_disjoint(&s, &g, info);
    if (g.verdict != 0 && s.best_phi < 0.0) {
        r.distance = ans.upper;
        r.p1 = ans.p1, r.p2 = ans.p2;
        r.certificate_gap = ans.lower;
        r.certified = info->certified;
        info->lower = ans.lower, info->upper = ans.upper;
    } else common_point(&s, &g, &r, info);
    return distance_scaled_back(&r, info, o, f);
}

prox_distance_result prox_convex_distance_ex(const prox_body *a, const prox_body *b, prox_convex_info *info)
{
    return distance_run(a, b, info, CVX_FAST);
}

prox_distance_result prox_convex_distance(const prox_body *a, const prox_body *b) { return prox_convex_distance_ex(a, b, NULL); }

void prox_convex_overlap_witnesses(const prox_body *a, const prox_body *b, prox_vec3 n, double sd, prox_vec3 *p1,
                                   prox_vec3 *p2)
{
    cvx s;
    prox_vec3 o, x, y;
    double f;
    pair_make(a, b, &s, &o, &f);
    witness_overlap(&s, n, sd * f, &x, &y);
    *p1 = to_abs(o, f, x), *p2 = to_abs(o, f, y);
}

prox_distance_result prox_convex_distance_full(const prox_body *a, const prox_body *b, prox_convex_info *info)
{
    return distance_run(a, b, info, CVX_FULL);
}

unsigned long prox_convex_gjk_certified_count(void) { return atomic_load(&cvx_gjk_cert); }
