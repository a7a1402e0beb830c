/* Internal (core): the closest pair of a polytope edge and a convex body, by the root of the edge's
 * distance derivative. Along an edge x(t) the distance to a convex body is convex in t, and half its
 * squared derivative, G(t) = (x(t) - P(x(t))).e (P the body's closest point, e the edge's direction),
 * is continuous and nondecreasing: the closest pair is at the root of G or at an end. The root is
 * found by regula falsi with the Illinois modification (Dowell and Jarratt 1971), which keeps a
 * bracket and converges superlinearly where G is smooth. BOX-RCC (distance/box_rcc.c) and every
 * polytope against a curved body (distance/poly_body.c) use it, and the support-function engine's
 * minimum along a kink circle (sat/convex.c: the root of phi's slope there). */
#ifndef PROX_CORE_EDGE_ROOT_H
#define PROX_CORE_EDGE_ROOT_H

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

/* The root of G in [lo, hi], where G(lo) = glo < 0 < ghi = G(hi), from t: stops when G(t) = 0 or the
 * bracket is at most width wide (after 100 evaluations at the latest); the pair is what g last kept. */
static inline void prox_edge_root(double (*g)(void *ctx, double t), void *ctx, double lo, double hi, double glo,
                                  double ghi, double t, double width)
{
    prox_illinois(g, ctx, &lo, &hi, &glo, &ghi, t, width);
}

#endif
