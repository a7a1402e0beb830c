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
 * those intervals bound f.
 *
 * Pair (prox_cc_classify_pair): for two quadrics u, v and a multiplier lambda, g = f_v - lambda f_u is
 * a quadric too, enclosed on the box by the same Taylor form built from the two surfaces' own forms
 * at the box centre. A box on which g < 0 holds no point where f_v >= 0 and lambda f_u <= 0: inside
 * the inner of two concentric spheres (coaxial cylinders, parallel planes) is inside the outer one.
 * A box straddling both surfaces of a thin shell learns this at once instead of by subdivision down
 * to the shell's thickness. */
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

/* Taylor pieces of a quadric at the centre m of a box (relative to o): f(m), its gradient, and the
 * magnitudes that scale their rounding. The operations are those of the classification below, in
 * the same order, so that every verdict is the same whichever path computes it. */
typedef struct taylor {
    double m[3], h[3];
    double f, g[3];
    double mag0;  /* sum of |terms| of f(m) */
    double gm[3]; /* sum of |parts| of each gradient component */
} taylor;

static void quad_taylor(const prox_surf *s, const prox_ccbox *b, taylor *T)
{
    const double *q = s->q;
    centred(b, s->o, T->m, T->h);
    const double x = T->m[0], y = T->m[1], z = T->m[2];
    const double terms[10] = {q[0] * x * x, q[1] * y * y, q[2] * z * z, q[3] * x * y, q[4] * y * z,
                              q[5] * z * x, q[6] * x,     q[7] * y,     q[8] * z,     q[9]};
    double f = 0.0, mag = 0.0;
    for (int i = 0; i < 10; ++i) {
        f += terms[i];
        mag += fabs(terms[i]);
    }
    T->f = f, T->mag0 = mag;
    /* Gradient at m: g_x = 2 q0 x + q3 y + q5 z + q6, ... and the magnitudes of its parts. */
    const double gp[3][4] = {{2.0 * q[0] * x, q[3] * y, q[5] * z, q[6]},
                             {2.0 * q[1] * y, q[3] * x, q[4] * z, q[7]},
                             {2.0 * q[2] * z, q[4] * y, q[5] * x, q[8]}};
    for (int i = 0; i < 3; ++i) {
        T->g[i] = gp[i][0] + gp[i][1] + gp[i][2] + gp[i][3];
        T->gm[i] = fabs(gp[i][0]) + fabs(gp[i][1]) + fabs(gp[i][2]) + fabs(gp[i][3]);
    }
}

/* Range [*lo, *hi] of the quadratic form t^T Q t (coefficients q[0..5], GQ order) over the box of
 * half-widths h; adds the magnitudes of its parts to *mag. */
static void form_range(const double *q, const double h[3], double *lo, double *hi, double *mag)
{
    double qlo = 0.0, qhi = 0.0;
    for (int i = 0; i < 3; ++i) {
        double v = q[i] * h[i] * h[i];
        if (v < 0.0) qlo += v;
        else qhi += v;
        *mag += fabs(v);
    }
    const double cross = fabs(q[3]) * h[0] * h[1] + fabs(q[4]) * h[1] * h[2] + fabs(q[5]) * h[2] * h[0];
    *lo = qlo - cross;
    *hi = qhi + cross;
    *mag += cross;
}

/* A plane (no quadratic part): the same operations as prox_cc_classify_taylor with the zero terms left out.
 * Every term left out is an exact zero in that sum, so the verdict is the same bit for bit while no
 * x^2 or h^2 can overflow (|m| + h < PLANE_M_MAX). Beyond that (no model comes near) it gives no
 * verdict, which is always sound. */
#define PLANE_M_MAX 1e150

static int classify_plane(const prox_surf *s, const prox_ccbox *b)
{
    const double *q = s->q;
    double m[3], h[3];
    centred(b, s->o, m, h);
    if (!(fabs(m[0]) + h[0] < PLANE_M_MAX && fabs(m[1]) + h[1] < PLANE_M_MAX && fabs(m[2]) + h[2] < PLANE_M_MAX))
        return 0;
    const double t6 = q[6] * m[0], t7 = q[7] * m[1], t8 = q[8] * m[2];
    const double f = t6 + t7 + t8 + q[9];
    double mag = fabs(t6) + fabs(t7) + fabs(t8) + fabs(q[9]), lin = 0.0;
    for (int i = 0; i < 3; ++i) {
        lin += fabs(q[6 + i]) * h[i];
        mag += fabs(q[6 + i]) * h[i];
    }
    return verdict(f - lin, f + lin, PROX_TOL_CLASSIFY * mag);
}

static int is_plane(const double *q)
{
    return (q[0] == 0.0) & (q[1] == 0.0) & (q[2] == 0.0) & (q[3] == 0.0) & (q[4] == 0.0) & (q[5] == 0.0);
}

int prox_cc_classify_taylor(const prox_surf *s, const prox_ccbox *b)
{
    if (s->kind == PROX_SURF_TORUS) return prox_cc_classify(s, b);
    taylor T;
    quad_taylor(s, b, &T);
    double f = T.f, mag = T.mag0, lin = 0.0;
    for (int i = 0; i < 3; ++i) {
        lin += fabs(T.g[i]) * T.h[i];
        mag += T.gm[i] * T.h[i];
    }
    /* Range of the quadratic form t^T Q t over the box of half-widths h. */
    double qlo, qhi;
    form_range(s->q, T.h, &qlo, &qhi, &mag);
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
    if (s->kind == PROX_SURF_TORUS) return classify_torus(s, b);
    return is_plane(s->q) ? classify_plane(s, b) : prox_cc_classify_taylor(s, b);
}

/* Multiplier of a pair: the ratio of v's quadratic part to u's (least squares over the six
 * coefficients), or of the linear parts when both are planes; 0 when there is none. Any value is
 * sound (prox_cc_classify_pair proves what it claims for every lambda): this one makes
 * f_v - lambda f_u constant for concentric spheres, coaxial cylinders and parallel planes. */
static double pair_lambda(const prox_surf *u, const prox_surf *v)
{
    double uu = 0.0, uv = 0.0;
    for (int k = 0; k < 6; ++k) uu += u->q[k] * u->q[k], uv += u->q[k] * v->q[k];
    if (uu > 0.0) return uv / uu;
    for (int k = 0; k < 6; ++k)
        if (v->q[k] != 0.0) return 0.0; /* a plane against a curved surface */
    for (int k = 6; k < 9; ++k) uu += u->q[k] * u->q[k], uv += u->q[k] * v->q[k];
    return uu > 0.0 ? uv / uu : 0.0;
}

/* Bound on |E|, the error of evaluating v's Taylor form at u's offsets t: the true offsets from the
 * two rounded centres differ by delta, |delta_i| <= D_i, and
 *   f_v(m_v + t + delta) - f_v(m_v) - grad f_v . t - t^T Q_v t = grad f_v . delta + 2 t^T Q_v delta + delta^T Q_v delta. */
static double shift_error(const prox_surf *u, const prox_surf *v, const prox_ccbox *b, const taylor *Tv, const double h[3])
{
    const double *q = v->q;
    const double ou[3] = {u->o.x, u->o.y, u->o.z}, ov[3] = {v->o.x, v->o.y, v->o.z};
    double D[3], dmax = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double c = 0.5 * b->lo[i] + 0.5 * b->hi[i];
        D[i] = 2.0 * DBL_EPSILON * (fabs(c) + fabs(ou[i]) + fabs(ov[i])) + 2.0 * DBL_TRUE_MIN;
        dmax = fmax(dmax, D[i]);
    }
    const double a3 = fabs(q[3]), a4 = fabs(q[4]), a5 = fabs(q[5]);
    const double row[3] = {2.0 * fabs(q[0]) * h[0] + a3 * h[1] + a5 * h[2], 2.0 * fabs(q[1]) * h[1] + a3 * h[0] + a4 * h[2],
                           2.0 * fabs(q[2]) * h[2] + a4 * h[1] + a5 * h[0]};
    double e = 0.0, qs = 0.0;
    for (int i = 0; i < 3; ++i) e += D[i] * (Tv->gm[i] + row[i]);
    for (int k = 0; k < 6; ++k) qs += fabs(q[k]);
    return e + qs * dmax * dmax;
}

/* Magnitude of the terms of a quadric's Taylor form over the half-widths h (its rounding scale). */
static double taylor_mag(const prox_surf *s, const taylor *T, const double h[3])
{
    double mag = T->mag0, lo, hi;
    for (int i = 0; i < 3; ++i) mag += T->gm[i] * h[i];
    form_range(s->q, h, &lo, &hi, &mag);
    return mag;
}

/* Pair classification. g = f_v - lambda f_u is again a quadric; its Taylor form on the box (the two
 * surfaces' forms at the same centre, each in its own origin) encloses g: with t = x - o_u - m_u in
 * [-h_u, h_u], g = [f_v(m_v) - lambda f_u(m_u)] + [grad f_v - lambda grad f_u] . t + t^T (Q_v - lambda Q_u) t
 * + E (shift_error). The verdict is strict: the enclosure must clear zero by the rounding allowance,
 * so that a -1 proves f_v < lambda f_u at every point of the box (no layer is given away). */
int prox_cc_classify_pair(const prox_surf *u, const prox_surf *v, const prox_ccbox *b, double *lambda)
{
    *lambda = 0.0;
    if (u->kind != PROX_SURF_QUADRIC || v->kind != PROX_SURF_QUADRIC) return 0;
    const double lam = pair_lambda(u, v);
    if (lam == 0.0 || !isfinite(lam)) return 0;
    taylor Tu, Tv;
    quad_taylor(u, b, &Tu);
    quad_taylor(v, b, &Tv);
    const double *h = Tu.h;
    double d[6], lin = 0.0, qlo, qhi, dmag = 0.0;
    for (int i = 0; i < 3; ++i) lin += fabs(Tv.g[i] - lam * Tu.g[i]) * h[i];
    for (int k = 0; k < 6; ++k) d[k] = v->q[k] - lam * u->q[k];
    form_range(d, h, &qlo, &qhi, &dmag);
    const double f0 = Tv.f - lam * Tu.f;
    const double lo = f0 - lin + qlo, hi = f0 + lin + qhi;
    const double allow = 2.0 * PROX_TOL_CLASSIFY * (taylor_mag(v, &Tv, h) + fabs(lam) * taylor_mag(u, &Tu, h)) +
                         2.0 * shift_error(u, v, b, &Tv, h);
    if (!isfinite(lo) || !isfinite(hi) || !isfinite(allow)) return 0;
    *lambda = lam;
    if (hi < -allow) return -1;
    if (lo > allow) return 1;
    return 0;
}
