/* Internal (core): the closest pair of a polytope edge and a convex body, by the root of the edge's
 * distance derivative. Along an edge x(t) the distance to a convex body is convex in t, and half its
 * squared derivative, G(t) = (x(t) - P(x(t))).e (P the body's closest point, e the edge's direction),
 * is continuous and nondecreasing: the closest pair is at the root of G or at an end. The root is
 * found by the secant method inside the bracket (Dekker 1969; regula falsi and bisection as its
 * safeguards), which converges superlinearly where G is smooth. BOX-RCC (distance/box_rcc.c) and every
 * polytope against a curved body (distance/poly_body.c) use it. The support-function engine's minimum
 * along a kink circle (sat/convex.c: the root of phi's slope there) uses prox_illinois below, whose
 * bracket, narrowed in place, the engine carries on to the rounding of the angle. */
#ifndef PROX_CORE_EDGE_ROOT_H
#define PROX_CORE_EDGE_ROOT_H

#include <float.h>
#include <math.h>

/* Regula falsi with the Illinois modification on the bracket [*lo, *hi], G(*lo) = *glo < 0 < *ghi =
 * G(*hi), from t: the bracket is narrowed in place. Returns 1 when G(t) = 0 (then *lo = *hi = t), 0
 * when the bracket is at most width wide, -1 after 100 evaluations. g(ctx, t) evaluates G at t and
 * keeps in ctx whatever its caller needs of the evaluations. Inlined, the call through g is direct. */
static inline int prox_illinois(double (*g)(void *ctx, double t), void *ctx, double *lo, double *hi, double *glo,
                                double *ghi, double t, double width)
{
    for (int it = 0, side = 0; it < 100; ++it) {
        double v = g(ctx, t);
        if (v == 0.0) {
            *lo = *hi = t;
            return 1;
        }
        if (v < 0.0) {
            *lo = t, *glo = v;
            if (side == -1) *ghi *= 0.5; /* the same end twice: halve the other's value (Illinois) */
            side = -1;
        } else {
            *hi = t, *ghi = v;
            if (side == 1) *glo *= 0.5;
            side = 1;
        }
        if (*hi - *lo <= width) return 0;
        double tn = *lo - *glo * (*hi - *lo) / (*ghi - *glo);
        t = tn > *lo && tn < *hi ? tn : 0.5 * (*lo + *hi);
    }
    return -1;
}

/* The root of G in [lo, hi], where G(lo) = glo < 0 < ghi = G(hi), from t: the secant through the last
 * two points (Dekker's method: superlinear, order 1.6, where regula falsi keeps a far end and the
 * Illinois halving spends evaluations moving it), regula falsi on the bracket whenever the secant
 * would leave it, a bisection whenever three steps have not halved it. Stops when G(t) = 0, the
 * bracket is at most width wide, or the secant step is at the rounding of t (t is then the root to
 * rounding), after 100 evaluations at the latest; the pair is what g last kept. */
static inline void prox_edge_root(double (*g)(void *ctx, double t), void *ctx, double lo, double hi, double glo,
                                  double ghi, double t, double width)
{
    double tp = NAN, vp = NAN, w0 = hi - lo;
    for (int it = 0, slow = 0; it < 100; ++it) {
        double v = g(ctx, t);
        if (v == 0.0) return;
        if (v < 0.0) lo = t, glo = v;
        else hi = t, ghi = v;
        if (hi - lo <= width) return;
        if (hi - lo <= 0.5 * w0) w0 = hi - lo, slow = 0;
        else ++slow;
        double tn = v != vp ? t - v * (t - tp) / (v - vp) : NAN;
        if (!(tn > lo && tn < hi)) tn = lo - glo * (hi - lo) / (ghi - glo);
        if (slow >= 3 || !(tn > lo && tn < hi)) tn = 0.5 * (lo + hi), slow = 0;
        if (fabs(tn - t) <= 2.0 * DBL_EPSILON * fabs(t)) return;
        tp = t, vp = v, t = tn;
    }
}

#endif
