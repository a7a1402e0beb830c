/* The ridge D.w = 0 of one cylinder in the depth of two cylinders, solved in the plane of the ridge
 * (an accelerator of rcc_depth.c's ridges; the derivation is below).
 *
 * On the ridge of cylinder k (axis w, radius r) phi(D) = hc_k(D) + hc_o(D) - D.Delta = r + h_Q(D)
 * - D.delta, where Q is the shadow of the other cylinder o (centred) along w on the plane of the
 * ridge and delta the shadow of Delta: the minimum of phi over the ridge is r minus the signed
 * distance of the point delta to Q, a problem of the plane. The shadow of a cylinder is an ellipse
 * swept along a segment: E + [-d, d], E the shadow of a rim disk (semi-axes a = r_o along
 * e1 = unit(w x w_o), b = r_o |w.w_o| along e2 = w x e1) and d = hh_o (w_o.e2) e2 the shadow of the
 * half axis. On the half circle D.d >= 0, h_Q(D) - D.delta = h_E(D) - D.(delta - d), on the other
 * h_E(D) - D.(delta + d); their ends are D = +-e1 (both lateral lines: the point +-(w x w_o)).
 * Inside a half the stationary directions of h_E(D) - D.p are the normals of E at the feet of the
 * perpendiculars from p to E (the classical point-ellipse problem; Eberly, "Distance from a Point to
 * an Ellipse, an Ellipsoid, or a Hyperellipsoid", 2013): with p = (y0, y1) in E's axes, the foot
 * x = (a^2 y0 / (t + a^2), b^2 y1 / (t + b^2)) for each root t of
 *     G(t) = (a y0 / (t + a^2))^2 + (b y1 / (t + b^2))^2 - 1,
 * and the normal there is proportional to (y0 / (t + a^2), y1 / (t + b^2)). G has one root beyond
 * -b^2 (the foot in p's quadrant), none or two in (-a^2, -b^2), where G is convex with its minimum
 * in closed form, and one below -a^2 (the farthest point: the maximum of h_E(D) - D.p, never a
 * minimum). Every root is bracketed and found by Newton kept in its bracket, to full precision;
 * every direction is a candidate of the enumeration, which evaluates phi there exactly (any
 * direction is an upper bound), so the candidates hold every stationary point of phi on the ridge:
 * two rims' quartics replaced by a few safeguarded Newton solves without a trigonometric call. */
#include "sat_internal.h"
#include "sup_engine.h"

#include "core/tol.h"

#include <float.h>

/* G of the outer branch (u = t + b^2 > 0) or the middle one (v = t + a^2 in (0, c), u = v - c) as
 * one form: G(x) = S(x) - 1, S(x) = (A / (x + p))^2 + (B / (x + q))^2, returned as the function
 * 1 - 1 / sqrt(S(x)) of the same sign and the same roots, with its derivative S' / (2 S^(3/2)).
 * Where one term of S dominates (near a pole, or far out where S ~ (A^2 + B^2) / x^2), 1 / sqrt(S)
 * is nearly linear in x, so Newton's steps on it land close to the root from anywhere in the
 * bracket (a few steps instead of the ten or so that G itself takes down its poles). */
static double rs_g(double A, double B, double p, double q, double x, double *dg)
{
    double f0 = A / (x + p), f1 = B / (x + q), S = f0 * f0 + f1 * f1, is = 1.0 / sqrt(S);
    *dg = -(f0 * f0 / (x + p) + f1 * f1 / (x + q)) * is / S;
    return 1.0 - is;
}

/* The root of G in the bracket (lo, hi) where G changes sign once (G(lo) has the sign slo), from
 * x: Newton's steps on rs_g's form kept inside the bracket, else the secant of the bracket's ends
 * when both were evaluated, else bisection (Press et al., rtsafe), to full precision; quadratic once
 * near the (simple) root. The secant matters when an iterate lands on the root itself with the far
 * sign by rounding: that end then blocks every Newton step toward it (bisection alone would take
 * some forty halvings to full precision), and the secant puts the root there. */
static double rs_root(double A, double B, double p, double q, double lo, double hi, double slo, double x)
{
    double glo = NAN, ghi = NAN;
    for (int it = 0; it < 40; ++it) {
        double dg, g = rs_g(A, B, p, q, x, &dg);
        if (g == 0.0) return x;
        if ((g > 0.0) == (slo > 0.0)) lo = x, glo = g; else hi = x, ghi = g;
        double xn = x - g / dg;
        if (!(xn > lo && xn < hi)) { /* Newton left the bracket: the secant, else bisection */
            double xs = lo - glo * ((hi - lo) / (ghi - glo));
            if (xs == lo || xs == hi) return xs; /* the root at an evaluated end, to rounding */
            xn = xs > lo && xs < hi ? xs : 0.5 * (lo + hi);
        }
        if (fabs(xn - x) <= 4.0 * DBL_EPSILON * fabs(x) || !(xn > lo && xn < hi)) return xn;
        x = xn;
    }
    /* not converged in 40 steps (a slow approach down a steep pole): bisection to full precision */
    for (int it = 0; it < 200; ++it) {
        double m = 0.5 * (lo + hi), dg;
        if (!(m > lo && m < hi)) break;
        if ((rs_g(A, B, p, q, m, &dg) > 0.0) == (slo > 0.0)) lo = m; else hi = m;
    }
    return 0.5 * (lo + hi);
}

/* The root u > 0 of the outer branch (A, B >= 0, B > 0): G falls from +inf to -1 on (0, inf);
 * Eberly's bracket [B, sqrt(A^2 + B^2)]. */
static double rs_root_outer(double A, double B, double c)
{
    double hi = sqrt(A * A + B * B); /* G(hi) <= 0; from there one Newton step lands left of the root */
    return rs_root(A, B, c, 0.0, B, hi, 1.0, hi);
}

/* G on the middle branch at v (u = v - c < 0). */
static double rs_mid(double A, double B, double c, double v)
{
    double dg;
    return rs_g(A, B, 0.0, -c, v, &dg);
}

/* A root of the middle branch between v0 (a pole: G = +inf) and v1 (G's minimum, G < 0), started
 * on the positive side: a root has A / v <= 1 (left) or B / (c - v) <= 1 (right), and G > 0 at
 * v = A (left of the left root) and at v = c - B (right of the right one). */
static double rs_root_mid(double A, double B, double c, double v0, double v1)
{
    /* G's quadratic model at its minimum v1, G(v1) + G''(v1) (v - v1)^2 / 2 with G'' = 6 (A^2 / v^4 +
     * B^2 / (v - c)^4), puts the roots at v1 -+ dv: the start when it lies in the bracket. When the two
     * roots nearly merge (a foot near the evolute, G(v1) -> 0-) Newton from afar would approach the
     * near-double root only linearly, halving its error per step; from the model's root it is
     * quadratic at once. */
    double f0 = A / v1, f1 = B / (v1 - c), gm = f0 * f0 + f1 * f1 - 1.0;
    double g2 = 6.0 * (f0 * f0 / (v1 * v1) + f1 * f1 / ((v1 - c) * (v1 - c))), dv = sqrt(fmax(0.0, -2.0 * gm / g2));
    if (v0 < v1) {
        double x = v1 - dv;
        return rs_root(A, B, 0.0, -c, v0, v1, 1.0, x > v0 && x < v1 ? x : (A < v1 ? A : 0.5 * v1));
    }
    double x = v1 + dv;
    return rs_root(A, B, 0.0, -c, v1, v0, -1.0, x > v1 && x < v0 ? x : (c - B > v1 ? c - B : 0.5 * (v1 + c)));
}

/* Adds the direction of E's normal (n0, n1) in the plane frame (e1, e2) to out (3D, not unit). */
static void rs_push(prox_vec3 *out, int *n, int max, prox_vec3 e1, prox_vec3 e2, double n0, double n1)
{
    if (*n >= max || !isfinite(n0) || !isfinite(n1) || (n0 == 0.0 && n1 == 0.0)) return;
    out[(*n)++] = prox_v3_add(prox_v3_scale(e1, n0), prox_v3_scale(e2, n1));
}

/* The normals at the feet from p = (y0, y1) to the ellipse of semi-axes a >= b > 0 (axes e1, e2),
 * except the farthest foot; 0, or -1 when p is E's centre (every direction is stationary for a
 * circle; the caller then takes the general path). `side` 0 asks for all of them; otherwise only for
 * the minimiser of h_E(D) - D.p over the half circle side D.e2 >= 0 (side +-1; its ends +-e1 are the
 * caller's) or over the whole circle (side 2). The feet's quadrants decide which are needed: the
 * outer foot (t > -b^2) lies in p's quadrant, so its normal's e2 component has the sign s1 of y1,
 * while the middle branch's feet (t + b^2 < 0) have x1 = b^2 y1 / (t + b^2) of the sign -s1 (and the
 * farthest foot is never a minimum). A half's minimiser is at an end or at an interior stationary
 * point, a foot whose normal lies in the half: the outer foot alone when side = s1, the middle
 * branch alone when side = -s1. Over the whole circle the outer foot is the nearest point of E's
 * boundary (Eberly 2013: the largest root of G), so its normal is the minimiser. */
static int ellipse_feet(double a, double b, double y0, double y1, prox_vec3 e1, prox_vec3 e2, prox_vec3 *out, int *n,
                        int max, int side)
{
    double s0 = y0 < 0.0 ? -1.0 : 1.0, s1 = y1 < 0.0 ? -1.0 : 1.0, z0 = fabs(y0), z1 = fabs(y1);
    double c = (a - b) * (a + b), A = a * z0, B = b * z1;
    if (z0 == 0.0 && z1 == 0.0) { /* the centre: the four vertices of an ellipse, any of a circle */
        if (!(c > 0.0)) return -1;
        rs_push(out, n, max, e1, e2, 0.0, 1.0);
        rs_push(out, n, max, e1, e2, 1.0, 0.0);
        return 0;
    }
    int outer = side == 0 || side == 2 || side * s1 > 0.0, middle = side == 0 || (side != 2 && side * s1 < 0.0);
    /* the foot in p's quadrant: t > -b^2 */
    if (z1 > 0.0) {
        if (outer) {
            double u = rs_root_outer(A, B, c);
            rs_push(out, n, max, e1, e2, s0 * z0 / (u + c), s1 * z1 / u);
        }
    } else { /* p on the major axis: the near vertex (t = a z0 - a^2), and when that lies below
              * -b^2 (a z0 < c) the two feet of the limit t -> -b^2 (closed forms: all kept) */
        rs_push(out, n, max, e1, e2, s0, 0.0);
        if (A < c) {
            double x0 = a * a * z0 / c, r = 1.0 - (x0 / a) * (x0 / a); /* foot (x0, +-b sqrt(r)) */
            double x1 = b * sqrt(fmax(0.0, r));
            rs_push(out, n, max, e1, e2, s0 * x0 / (a * a), x1 / (b * b));
            rs_push(out, n, max, e1, e2, s0 * x0 / (a * a), -x1 / (b * b));
        }
    }
    if (!(c > 0.0) || !middle) return 0;
    /* the middle branch t in (-a^2, -b^2), v = t + a^2 in (0, c) */
    if (z0 > 0.0 && z1 > 0.0) {
        double k = cbrt((A / B) * (A / B)), vm = c / (1.0 + 1.0 / k); /* G' = 0: v / -u = (A / B)^(2/3) */
        rs_push(out, n, max, e1, e2, s0 * z0 / vm, s1 * z1 / (vm - c));
        if (rs_mid(A, B, c, vm) < 0.0) {
            double v1 = rs_root_mid(A, B, c, 0.0, vm), v2 = rs_root_mid(A, B, c, c, vm);
            rs_push(out, n, max, e1, e2, s0 * z0 / v1, s1 * z1 / (v1 - c));
            rs_push(out, n, max, e1, e2, s0 * z0 / v2, s1 * z1 / (v2 - c));
        }
    } else if (z0 == 0.0) { /* z0 = 0: vertices (0, +-b), and the feet at t -> -a^2 when |x1| < b */
        rs_push(out, n, max, e1, e2, 0.0, -s1);
        double x1 = b * b * z1 / c, r = 1.0 - (x1 / b) * (x1 / b);
        if (r > 0.0) {
            double x0 = a * sqrt(r);
            rs_push(out, n, max, e1, e2, x0 / (a * a), -s1 * x1 / (b * b));
            rs_push(out, n, max, e1, e2, -x0 / (a * a), -s1 * x1 / (b * b));
        }
    }
    return 0;
}

int sup_ellipse_feet(double a, double b, double y0, double y1, prox_vec3 e1, prox_vec3 e2, prox_vec3 *out, int *n,
                     int max)
{
    return ellipse_feet(a, b, y0, y1, e1, e2, out, n, max, 0);
}

/* The shadow of cylinder oth on the plane of lat's ridge (file comment): E's semi-axes a along e1 and
 * b along e2 (b = a for parallel axes, where E is the disk's own circle), the half axis's component
 * d2 along e2, and delta's coordinates (p0, p1). */
typedef struct rs_shadow {
    prox_vec3 e1, e2;
    double a, b, d2, p0, p1;
} rs_shadow;

static rs_shadow rs_shadow_of(const prox_body *lat, const prox_body *oth, prox_vec3 delta)
{
    rs_shadow S;
    prox_vec3 w = lat->cyl.w, wo = oth->cyl.w, x = prox_v3_cross(w, wo);
    double xn = prox_v3_norm(x);
    S.a = oth->cyl.r;
    S.b = oth->cyl.r * fabs(prox_v3_dot(w, wo));
    S.e1 = xn > PROX_TOL_PARALLEL ? prox_v3_scale(x, 1.0 / xn) : prox_v3_any_perp(w);
    S.e2 = prox_v3_cross(w, S.e1);
    if (!(xn > PROX_TOL_PARALLEL)) S.b = S.a;
    S.d2 = oth->cyl.hh * prox_v3_dot(wo, S.e2);
    S.p0 = prox_v3_dot(delta, S.e1), S.p1 = prox_v3_dot(delta, S.e2);
    return S;
}

/* The ridge's candidates (sup_ridge_shadow, sat_internal.h's sup_ridge_shadow_min when `minimum`). */
static int ridge_shadow(const prox_body *lat, const prox_body *oth, prox_vec3 delta, prox_vec3 *out, int max,
                        int minimum)
{
    rs_shadow S = rs_shadow_of(lat, oth, delta);
    /* the other axis nearly in the ridge plane: E is a needle (its tips curve at b^2 / a), the
     * general path (rims' quartics) decides */
    if (!(S.b > PROX_TOL_RIDGE_THIN * S.a)) return -1;
    int n = 0;
    rs_push(out, &n, max, S.e1, S.e2, 1.0, 0.0); /* the ends of the halves: both lateral lines */
    /* the half of p = delta + h d is D.d <= 0 for h = +1, D.d >= 0 for h = -1: side -h sign(d2) of e2;
     * with d2 = 0 both halves are one function on the whole circle */
    for (int h = -1; h <= 1; h += 2) {
        int side = !minimum ? 0 : S.d2 == 0.0 ? 2 : (h * S.d2 > 0.0 ? -1 : 1);
        if (ellipse_feet(S.a, S.b, S.p0, S.p1 + h * S.d2, S.e1, S.e2, out, &n, max, side) < 0) return -1;
        if (side == 2) break;
    }
    return n;
}

int sup_ridge_shadow(const prox_body *lat, const prox_body *oth, prox_vec3 delta, prox_vec3 *out, int max)
{
    return ridge_shadow(lat, oth, delta, out, max, 0);
}

int sup_ridge_shadow_min(const prox_body *lat, const prox_body *oth, prox_vec3 delta, prox_vec3 *out, int max)
{
    return ridge_shadow(lat, oth, delta, out, max, 1);
}

/* Lower bound of phi over the ridge D.w = 0 of cylinder `lat` (radius r): its minimum is r minus the
 * distance from delta's shadow to Q = E + [-d, d], or plus delta's depth in Q. Two bounds, the larger
 * taken: E holds the disk of radius b about Q's centre, so h_Q >= b and phi >= r + b - |delta|; and
 * E + t d lies in Q for |t| <= 1, so the distance is at most that from y = delta - t d, t the point
 * of [-1, 1] nearest to delta along d, to E along the ray from E's centre: |y| (1 - 1 / k),
 * k = |(y0 / a, y1 / b)|, when k > 1, else 0. */
double sup_ridge_shadow_lb(const struct prox_body *lat, const struct prox_body *oth, prox_vec3 delta)
{
    rs_shadow S = rs_shadow_of(lat, oth, delta);
    double r = lat->cyl.r, disk = r + S.b - prox_hypot2(S.p0, S.p1);
    if (!(S.b > 0.0)) return disk;
    double t = S.d2 != 0.0 ? fmax(-1.0, fmin(1.0, S.p1 / S.d2)) : 0.0;
    double y0 = S.p0, y1 = S.p1 - t * S.d2, k = prox_hypot2(y0 / S.a, y1 / S.b);
    return fmax(disk, k <= 1.0 ? r : r - prox_hypot2(y0, y1) * (1.0 - 1.0 / k));
}
