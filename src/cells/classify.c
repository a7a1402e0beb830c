/* Certified classification of an axis-aligned box against one surface of the cell model: the box
 * lies wholly on the negative side (f < 0), wholly on the positive side (f > 0), or the check cannot
 * tell (the surface may cross it). A verdict of -1 or +1 is a proof up to rounding: the bounds below
 * enclose f on the box exactly, and the comparison is made against a rounding allowance
 * (PROX_TOL_CLASSIFY, see verdict()).
 *
 * Quadric (centred or Taylor form, exact for a quadratic): with m the box centre relative to the
 * surface's origin o and t in [-h, h] the offset from the centre,
 *   f(m + t) = f(m) + grad f(m) . t + t^T Q t,
 * so f ranges over f(m) +- sum |g_i| h_i plus the range of the quadratic form, whose square terms
 * q_ii t_i^2 lie in [min(0, q_ii) h_i^2, max(0, q_ii) h_i^2] and cross terms q_ij t_i t_j in
 * +-|q_ij| h_i h_j. The enclosure is tight to O(h^2) (the mean value form with the exact remainder),
 * so a box near a surface but not on it is decided once it is a little smaller than its distance.
 *
 * Torus (cells.h): f = (a/B)^2 + ((rho - A)/C)^2 - 1 with a = y.w the axial and rho = |y x w| the
 * radial coordinate of y = x - o. a is linear in y (range a(m) +- sum |w_i| h_i) and rho is
 * 1-Lipschitz (a distance to the axis line): rho in [rho(m) - |h|, rho(m) + |h|]; the squares of
 * those intervals bound f. */
#include <float.h>
#include <math.h>

#include "cells/check_internal.h"
#include "core/tol.h"

/* Centre relative to the surface origin and half-widths, widened so that [m - h, m + h] holds every
 * point of the box minus o despite the rounding of the centre and of the subtraction. */
static void centred(const prox_ccbox *b, prox_vec3 o, double m[3], double h[3])
{
    const double oo[3] = {o.x, o.y, o.z};
    for (int i = 0; i < 3; ++i) {
        double c = 0.5 * b->lo[i] + 0.5 * b->hi[i];
        m[i] = c - oo[i];
        h[i] = 0.5 * (b->hi[i] - b->lo[i]);
        h[i] += 4.0 * DBL_EPSILON * (fabs(b->lo[i]) + fabs(b->hi[i]) + fabs(oo[i]) + h[i]) + DBL_TRUE_MIN;
    }
}

/* Sign verdict from an enclosure [lo, hi] of f and its rounding allowance. A box whose face lies on
 * the surface (a plane through a subdivision boundary: common) has hi = 0 exactly, which rounding
 * cannot prove negative; the verdict therefore takes f <= allow as the negative side (and f >= -allow
 * as the positive side): the cell check is a statement about volumes, the zero set of f has none,
 * and what this can misjudge is a layer PROX_TOL_CLASSIFY x the terms' scale thin around the
 * surface, far below any resolution. */
static int verdict(double lo, double hi, double allow)
{
    if (lo >= -allow && !(hi <= allow)) return 1;
    if (hi <= allow && !(lo >= -allow)) return -1;
    return 0;
}

static int classify_quadric(const prox_surf *s, const prox_ccbox *b)
{
    const double *q = s->q;
    double m[3], h[3];
    centred(b, s->o, m, h);
    const double x = m[0], y = m[1], z = m[2];
    /* f(m) and the sum of its terms' magnitudes. */
    const double terms[10] = {q[0] * x * x, q[1] * y * y, q[2] * z * z, q[3] * x * y, q[4] * y * z,
                              q[5] * z * x, q[6] * x,     q[7] * y,     q[8] * z,     q[9]};
    double f = 0.0, mag = 0.0;
    for (int i = 0; i < 10; ++i) {
        f += terms[i];
        mag += fabs(terms[i]);
    }
    /* Gradient at m: g_x = 2 q0 x + q3 y + q5 z + q6, ... and the magnitudes of its parts. */
    const double gp[3][4] = {{2.0 * q[0] * x, q[3] * y, q[5] * z, q[6]},
                             {2.0 * q[1] * y, q[3] * x, q[4] * z, q[7]},
                             {2.0 * q[2] * z, q[4] * y, q[5] * x, q[8]}};
    double lin = 0.0;
    for (int i = 0; i < 3; ++i) {
        double g = gp[i][0] + gp[i][1] + gp[i][2] + gp[i][3];
        double gm = fabs(gp[i][0]) + fabs(gp[i][1]) + fabs(gp[i][2]) + fabs(gp[i][3]);
        lin += fabs(g) * h[i];
        mag += gm * h[i];
    }
    /* Range of the quadratic form t^T Q t over the box of half-widths h. */
    double qlo = 0.0, qhi = 0.0;
    for (int i = 0; i < 3; ++i) {
        double v = q[i] * h[i] * h[i];
        if (v < 0.0) qlo += v;
        else qhi += v;
        mag += fabs(v);
    }
    const double cross = fabs(q[3]) * h[0] * h[1] + fabs(q[4]) * h[1] * h[2] + fabs(q[5]) * h[2] * h[0];
    qlo -= cross;
    qhi += cross;
    mag += cross;
    return verdict(f - lin + qlo, f + lin + qhi, PROX_TOL_CLASSIFY * mag);
}

/* Enclosure of t^2 for t in [lo, hi]. */
static void square_range(double lo, double hi, double *slo, double *shi)
{
    if (lo >= 0.0) *slo = lo * lo, *shi = hi * hi;
    else if (hi <= 0.0) *slo = hi * hi, *shi = lo * lo;
    else *slo = 0.0, *shi = fmax(lo * lo, hi * hi);
}

static int classify_torus(const prox_surf *s, const prox_ccbox *b)
{
    double m[3], h[3];
    centred(b, s->o, m, h);
    const prox_vec3 w = s->w;
    const double a = m[0] * w.x + m[1] * w.y + m[2] * w.z;
    const double da = fabs(w.x) * h[0] + fabs(w.y) * h[1] + fabs(w.z) * h[2];
    const double cx = m[1] * w.z - m[2] * w.y, cy = m[2] * w.x - m[0] * w.z, cz = m[0] * w.y - m[1] * w.x;
    const double rho = sqrt(cx * cx + cy * cy + cz * cz);
    const double hn = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
    double alo, ahi, rlo, rhi;
    square_range((a - da) / s->tb, (a + da) / s->tb, &alo, &ahi);
    square_range((fmax(rho - hn, 0.0) - s->ta) / s->tc, (rho + hn - s->ta) / s->tc, &rlo, &rhi);
    /* Rounding: every quantity is a few operations on lengths up to |m| + |h| + A; w is unit to a few
     * ulps. Relative to the squares' scale the error is a few hundred eps. */
    const double len = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) + hn + s->ta;
    const double scale = 1.0 + (len / s->tb) * (len / s->tb) + (len / s->tc) * (len / s->tc);
    return verdict(alo + rlo - 1.0, ahi + rhi - 1.0, 4.0 * PROX_TOL_CLASSIFY * scale);
}

int prox_cc_classify(const prox_surf *s, const prox_ccbox *b)
{
    int v = s->kind == PROX_SURF_TORUS ? classify_torus(s, b) : classify_quadric(s, b);
    return v;
}
