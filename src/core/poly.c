/* Real roots of polynomials of degree <= 8 (the single owner of gsl_poly_complex_solve in prox).
 * Sources: closed forms: stable quadratic (Numerical Recipes 5.6 style
 * q = -(b + sgn(b) sqrt(b^2 - 4ac))/2), GSL's closed-form cubic (gsl_poly_complex_solve_cubic),
 * Ferrari's quartic through the resolvent cubic 8m^3 + 8p m^2 + (2p^2 - 8r) m - q^2 = 0
 * (docs/algorithms/poly.md); degree 5..8 through GSL's balanced companion-matrix QR with a
 * workspace on the stack. Every candidate is polished by Newton on the original polynomial, and
 * near-real complex pairs are tested for a near-double real root at a stationary point of p.
 * prox_poly_real_roots_fast: degree 5..8 by the derivative chain (real roots of p' bound the
 * monotone pieces of p, recursively down to the linear p^(n-1); safeguarded Newton per piece),
 * docs/algorithms/poly.md; opt-in, see there why it is not the default. */
#include "core/poly.h"

#include <float.h>
#include <math.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>

#define POLY_EPS DBL_EPSILON
/* Leading coefficients below this fraction of the largest coefficient deflate the degree (and
 * negligible at the root scale too, see poly_leading_negligible). */
#define POLY_DEFLATE_REL 1e-14
/* A complex root with |imag| <= this x |root| is treated as a real root directly. */
#define POLY_REAL_IM_REL 1e-12
/* A near-double real root is accepted where |p| <= this x (sum |c_k| |x|^k) at the stationary point. */
#define POLY_DOUBLE_REL 1e-10
/* After deflation a root must make the full polynomial vanish to this x sum |c_k| |x|^k. */
#define POLY_ARTIFACT_REL 1e-8

/* A complex candidate root. */
typedef struct poly_cand {
    double re, im;
} poly_cand;

double prox_poly_eval(const double *c, int degree, double x, double *deriv)
{
    double p = c[degree], d = 0.0;
    for (int k = degree - 1; k >= 0; --k) {
        d = d * x + p;
        p = p * x + c[k];
    }
    if (deriv) *deriv = d;
    return p;
}

/* p and sum |c_k| |x|^k at x in one Horner pass. */
static double poly_eval_abs(const double *c, int degree, double x, double *scale)
{
    double p = c[degree], ax = fabs(x), s = fabs(c[degree]);
    for (int k = degree - 1; k >= 0; --k) {
        p = p * x + c[k];
        s = s * ax + fabs(c[k]);
    }
    *scale = s;
    return p;
}

/* p, p' and p'' at x in one Horner pass. */
static double poly_eval2(const double *c, int degree, double x, double *d1, double *d2)
{
    double p = c[degree], d = 0.0, dd = 0.0;
    for (int k = degree - 1; k >= 0; --k) {
        dd = dd * x + d;
        d = d * x + p;
        p = p * x + c[k];
    }
    *d1 = d;
    *d2 = 2.0 * dd;
    return p;
}

/* sum |c_k| |x|^k: the scale of the rounding error of evaluating p at x. */
static double poly_abs_scale(const double *c, int degree, double x)
{
    double ax = fabs(x), s = fabs(c[degree]);
    for (int k = degree - 1; k >= 0; --k) s = s * ax + fabs(c[k]);
    return s;
}

/* Newton on p from x, never moving farther than maxmove from the start and stopping as soon as |p|
 * stops decreasing (so clustered roots do not jump onto a neighbour). */
static double poly_polish(const double *c, int degree, double x, double maxmove)
{
    double d, p = prox_poly_eval(c, degree, x, &d);
    const double x0 = x;
    for (int it = 0; it < 30 && p != 0.0 && d != 0.0; ++it) {
        double step = p / d, xn = x - step, dn;
        if (!isfinite(xn) || fabs(xn - x0) > maxmove) break;
        double pn = prox_poly_eval(c, degree, xn, &dn);
        if (!(fabs(pn) < fabs(p))) break;
        x = xn, p = pn, d = dn;
        if (fabs(step) <= 2.0 * POLY_EPS * fabs(x)) break;
    }
    return x;
}

/* Near-double real root behind a complex pair z = re +- i im: the stationary point x* of p next to
 * re (Newton on p'), accepted when p(x*) vanishes to within a rounding-level tolerance. */
static int poly_double_root(const double *c, int degree, poly_cand z, double *root)
{
    double x = z.re, d1, d2, p = poly_eval2(c, degree, x, &d1, &d2);
    /* a split double root (x - r)^2 + d has its stationary point at re = r exactly */
    const double maxmove = 0.25 * fabs(z.im) + 4.0 * POLY_EPS * fabs(z.re);
    for (int it = 0; it < 40 && d1 != 0.0 && d2 != 0.0; ++it) {
        double step = d1 / d2, xn = x - step;
        if (!isfinite(xn) || fabs(xn - z.re) > maxmove) break;
        double e1, e2, pn = poly_eval2(c, degree, xn, &e1, &e2);
        if (!(fabs(e1) < fabs(d1))) break;
        x = xn, p = pn, d1 = e1, d2 = e2;
        if (fabs(step) <= 2.0 * POLY_EPS * fabs(x)) break;
    }
    if (!(fabs(p) <= POLY_DOUBLE_REL * poly_abs_scale(c, degree, x))) return 0;
    *root = x;
    return 1;
}

/* Both roots of a x^2 + b x + c (a != 0), complex ones as a conjugate pair; stable form. */
static void poly_quadratic(double a, double b, double c, poly_cand z[2])
{
    double disc = b * b - 4.0 * a * c;
    if (disc >= 0.0) {
        double q = -0.5 * (b + copysign(sqrt(disc), b));
        z[0].re = q / a;
        z[1].re = q != 0.0 ? c / q : 0.0;
        z[0].im = z[1].im = 0.0;
    } else {
        double re = -b / (2.0 * a), im = sqrt(-disc) / (2.0 * fabs(a));
        z[0].re = z[1].re = re;
        z[0].im = im, z[1].im = -im;
    }
}

/* The four roots of the monic x^4 + a x^3 + b x^2 + c x + d by Ferrari: depress (x = y - a/4) to
 * y^4 + p y^2 + q y + r, take the largest root m >= 0 of the resolvent cubic, split into the
 * quadratics y^2 -+ sqrt(2m) y + (p/2 + m +- q / (2 sqrt(2m))). */
static void poly_quartic(double a, double b, double c, double d, poly_cand z[4])
{
    const double s = a / 4.0, a2 = a * a;
    const double p = b - 3.0 * a2 / 8.0;
    const double q = c - a * b / 2.0 + a2 * a / 8.0;
    const double r = d - a * c / 4.0 + a2 * b / 16.0 - 3.0 * a2 * a2 / 256.0;
    double m[3];
    int nm = gsl_poly_solve_cubic(p, (p * p - 4.0 * r) / 4.0, -q * q / 8.0, &m[0], &m[1], &m[2]);
    double mm = m[nm - 1] > 0.0 ? m[nm - 1] : 0.0;
    if (mm <= 0.0 || q == 0.0) { /* biquadratic: y^2 = roots of w^2 + p w + r */
        poly_cand w[2];
        poly_quadratic(1.0, p, r, w);
        for (int i = 0; i < 2; ++i) { /* complex square roots of w[i] */
            double mod = hypot(w[i].re, w[i].im);
            double sr = sqrt(0.5 * (mod + w[i].re)), si = copysign(sqrt(0.5 * (mod - w[i].re)), w[i].im);
            z[2 * i].re = sr - s, z[2 * i].im = si;
            z[2 * i + 1].re = -sr - s, z[2 * i + 1].im = -si;
        }
        return;
    }
    const double k = sqrt(2.0 * mm), h = q / (2.0 * k);
    poly_quadratic(1.0, -k, p / 2.0 + mm + h, &z[0]);
    poly_quadratic(1.0, k, p / 2.0 + mm - h, &z[2]);
    for (int i = 0; i < 4; ++i) z[i].re -= s;
}

/* Is the leading coefficient negligible? Two relative tests must both hold:
 * (1) |c_n| <= 1e-14 max_k |c_k| (the plain coefficient test), and
 * (2) at the root scale R of the remaining polynomial (Fujiwara's bound of c_0..c_m, m the highest
 *     coefficient not negligible by (1)) the leading term is negligible: |c_n| R^n <= 1e-14 max |c_k| R^k.
 * (1) alone would deflate genuine leading terms of polynomials whose roots are all large (c_n x^n
 * dominates there although c_n << max c_k); (2) alone would drop a root of size 1 next to tiny ones. */
static int poly_leading_negligible(const double *w, int n)
{
    double big = 0.0;
    for (int k = 0; k < n; ++k) big = fmax(big, fabs(w[k]));
    if (!(fabs(w[n]) <= POLY_DEFLATE_REL * big)) return 0;
    if (w[n] == 0.0) return 1;
    int m = n - 1;
    while (m > 0 && fabs(w[m]) <= POLY_DEFLATE_REL * big) --m;
    if (m == 0) return 1;
    double R = 0.0;
    for (int k = 0; k < m; ++k) R = fmax(R, pow(fabs(w[k] / w[m]), 1.0 / (m - k)));
    R *= 2.0;
    if (R == 0.0) return 1;
    /* compare in logarithms: R^n may overflow */
    const double lr = log2(R);
    double lmax = -INFINITY;
    for (int k = 0; k < n; ++k)
        if (w[k] != 0.0) lmax = fmax(lmax, log2(fabs(w[k])) + k * lr);
    return log2(fabs(w[n])) + n * lr <= lmax + log2(POLY_DEFLATE_REL);
}

/* Checks arguments, scales the coefficients by a power of two and drops negligible leading terms.
 * Writes the scaled coefficients to w[] and the effective degree to *deg. */
static prox_status poly_prepare(const double *c, int degree, double *roots, int *count, double w[9], int *deg)
{
    if (!c || !roots || !count || degree < 0 || degree > PROX_POLY_MAX_DEGREE) return PROX_EINVAL_ARG;
    *count = 0;
    double big = 0.0;
    for (int k = 0; k <= degree; ++k) {
        if (!isfinite(c[k])) return PROX_EINVAL_NONFINITE;
        if (fabs(c[k]) > big) big = fabs(c[k]);
    }
    *deg = 0;
    if (big == 0.0) return PROX_OK; /* the zero polynomial: no isolated roots */
    int e;
    frexp(big, &e);
    for (int k = 0; k <= degree; ++k) w[k] = ldexp(c[k], -e);
    int n = degree;
    while (n > 0 && poly_leading_negligible(w, n)) --n;
    *deg = n;
    return PROX_OK;
}

/* The test hook of prox_poly_test_fail_qr: per thread, so that it cannot disturb other threads. */
static _Thread_local int poly_fail_qr;

void prox_poly_test_fail_qr(int on) { poly_fail_qr = on; }

/* Complex roots by GSL's companion-matrix QR, with the workspace on the stack (no allocation). */
static prox_status poly_gsl_roots(const double *w, int n, poly_cand *z)
{
    if (poly_fail_qr) return PROX_ENUMERIC; /* test hook: a QR that did not converge */
    double matrix[PROX_POLY_MAX_DEGREE * PROX_POLY_MAX_DEGREE];
    double packed[2 * PROX_POLY_MAX_DEGREE];
    gsl_poly_complex_workspace ws;
    ws.nc = (size_t)n;
    ws.matrix = matrix;
    /* n >= 1 and w[n] != 0 here, so GSL's argument checks (which would call the handler) pass. */
    int st = gsl_poly_complex_solve(w, (size_t)n + 1, &ws, packed);
    if (st != GSL_SUCCESS) return PROX_ENUMERIC;
    for (int i = 0; i < n; ++i) z[i].re = packed[2 * i], z[i].im = packed[2 * i + 1];
    return PROX_OK;
}

/* Closed-form complex roots for n = 1..4 of w[0..n] (w[n] != 0). */
static void poly_closed_roots_dir(const double *w, int n, poly_cand *z)
{
    if (n == 1) {
        z[0].re = -w[0] / w[1], z[0].im = 0.0;
    } else if (n == 2) {
        poly_quadratic(w[2], w[1], w[0], z);
    } else if (n == 3) {
        gsl_complex r[3];
        gsl_poly_complex_solve_cubic(w[2] / w[3], w[1] / w[3], w[0] / w[3], &r[0], &r[1], &r[2]);
        for (int i = 0; i < 3; ++i) z[i].re = GSL_REAL(r[i]), z[i].im = GSL_IMAG(r[i]);
    } else {
        poly_quartic(w[3] / w[4], w[2] / w[4], w[1] / w[4], w[0] / w[4], z);
    }
}

/* Closed forms lose small roots when one root is far larger than the others (the shift by the mean
 * root swamps them). Solve the reversed polynomial (roots 1/x) instead when its mean-root shift is
 * smaller relative to the geometric-mean root size: |c_{n-1}/c_n| / G versus |c_1/c_0| G. */
static void poly_closed_roots(const double *w, int n, poly_cand *z)
{
    if (n >= 3 && w[0] != 0.0) {
        double g = pow(fabs(w[0] / w[n]), 1.0 / n);
        if (fabs(w[1] / w[0]) * g < fabs(w[n - 1] / w[n]) / g) {
            double rev[PROX_POLY_MAX_DEGREE + 1];
            for (int k = 0; k <= n; ++k) rev[k] = w[n - k];
            poly_closed_roots_dir(rev, n, z);
            for (int i = 0; i < n; ++i) { /* 1/z = conj(z)/|z|^2, scaled against overflow */
                double m = fmax(fabs(z[i].re), fabs(z[i].im));
                if (m == 0.0) {
                    z[i].re = INFINITY, z[i].im = 0.0;
                    continue;
                }
                double a = z[i].re / m, b = z[i].im / m, d = (a * a + b * b) * m;
                z[i].re = a / d, z[i].im = -b / d;
            }
            return;
        }
    }
    poly_closed_roots_dir(w, n, z);
}

/* Backward-error check of the closed-form candidates: the monic polynomial prod (x - z_i) must
 * reproduce w[k]/w[n] to within 1e-7 of prod (x + |z_i|) coefficient by coefficient; otherwise the
 * closed form lost a root and the caller falls back to GSL's QR. */
static int poly_closed_ok(const double *w, int n, const poly_cand *z)
{
    double pr[PROX_POLY_MAX_DEGREE + 1] = {1.0}, pi[PROX_POLY_MAX_DEGREE + 1] = {0.0};
    double pa[PROX_POLY_MAX_DEGREE + 1] = {1.0};
    for (int i = 0; i < n; ++i) {
        if (!isfinite(z[i].re) || !isfinite(z[i].im)) return 0;
        double am = hypot(z[i].re, z[i].im);
        for (int k = i + 1; k >= 0; --k) { /* multiply by (x - z_i) */
            double lr = k > 0 ? pr[k - 1] : 0.0, li = k > 0 ? pi[k - 1] : 0.0, la = k > 0 ? pa[k - 1] : 0.0;
            double cr = k <= i ? pr[k] : 0.0, ci = k <= i ? pi[k] : 0.0, ca = k <= i ? pa[k] : 0.0;
            pr[k] = lr - (z[i].re * cr - z[i].im * ci);
            pi[k] = li - (z[i].re * ci + z[i].im * cr);
            pa[k] = la + am * ca;
        }
    }
    for (int k = 0; k < n; ++k)
        if (!(hypot(pr[k] - w[k] / w[n], pi[k]) <= 1e-7 * pa[k])) return 0;
    return 1;
}

/* After deflation (the degree-n part solved, polished on the full polynomial of degree deg > n):
 * drops roots where the full polynomial does not vanish, |p| > 1e-8 sum |c_k| |x|^k. Those are
 * roots of the deflated part out where the dropped leading terms dominate (e.g. the quartic root
 * -c_3/c_4 of a quintic whose c_4 and c_5 are both below 1e-14 x max |c_k| but only c_5 was
 * deflated), not roots of the input. Keeps the order; returns the new count. */
static int poly_drop_artifacts(const double *c, int deg, double *roots, int m)
{
    int k = 0;
    for (int i = 0; i < m; ++i) {
        double s, p = poly_eval_abs(c, deg, roots[i], &s);
        if (fabs(p) <= POLY_ARTIFACT_REL * s) roots[k++] = roots[i];
    }
    return k;
}

/* Turns complex candidates into polished real roots, sorted ascending. */
static void poly_finish(const double *c, int degree, const poly_cand *z, int n, double *roots, int *count)
{
    int m = 0;
    for (int i = 0; i < n; ++i) {
        double modz = hypot(z[i].re, z[i].im);
        if (!isfinite(modz)) continue;
        double gap = INFINITY; /* half the distance to the nearest other candidate bounds the polish */
        for (int j = 0; j < n; ++j)
            if (j != i) {
                double dj = hypot(z[i].re - z[j].re, z[i].im - z[j].im);
                if (dj > 0.0 && dj < gap) gap = dj;
            }
        if (fabs(z[i].im) <= POLY_REAL_IM_REL * modz) {
            roots[m++] = poly_polish(c, degree, z[i].re, 0.5 * gap);
        } else if (z[i].im > 0.0) {
            double x;
            if (poly_double_root(c, degree, z[i], &x)) roots[m++] = x;
        }
    }
    for (int i = 1; i < m; ++i) /* insertion sort, m <= 8 */
        for (int j = i; j > 0 && roots[j - 1] > roots[j]; --j) {
            double t = roots[j];
            roots[j] = roots[j - 1], roots[j - 1] = t;
        }
    *count = n < degree ? poly_drop_artifacts(c, degree, roots, m) : m;
}

/* ---- Fast real-root path for degree 5..8: derivative chain (docs/algorithms/poly.md) ----------
 * The real roots of q_{j+1} = q_j' / (j+1) split the real line into pieces where q_j is monotone,
 * so each piece holds at most one root of q_j, found by safeguarded Newton inside the sign-change
 * bracket. Starting from the linear q_{n-1}, every level gives the breakpoints of the next one up
 * to p itself. All real roots of p and its derivatives lie in [-B, B] (Gauss-Lucas), B a
 * Fujiwara-type bound of p. Only real roots are ever computed. */

/* Iteration cap of one bracketed solve; hitting it is "trouble" (fallback to QR). */
#define POLY_FAST_MAXIT 120
/* Touching tolerance at the derivative levels: a breakpoint too many is harmless, one missing is not. */
#define POLY_FAST_TOUCH_LOW 1e-8
/* Newton at the derivative levels stops after a step below this x |x|: the accepted point is then
 * within ~(step)^2 of the critical point (quadratic convergence), and a breakpoint error e changes
 * p there only by p'' e^2 / 2, far below the touching tolerances. */
#define POLY_FAST_STEP_LOW 1e-7
/* An extremum of p crossing zero by less than this x sum |c_k| |x|^k (a bound of Horner's rounding
 * error at degree 8, 2n eps, doubled) is one double root: the sign of p there is noise. */
#define POLY_FAST_SNAP (32.0 * POLY_EPS)

/* p, p' and sum |c_k| |x|^k (the rounding scale of p) at x in one Horner pass. */
static double poly_eval_d1s(const double *c, int degree, double x, double *d1, double *scale)
{
    double p = c[degree], d = 0.0, ax = fabs(x), s = fabs(c[degree]);
    for (int k = degree - 1; k >= 0; --k) {
        d = d * x + p;
        p = p * x + c[k];
        s = s * ax + fabs(c[k]);
    }
    *d1 = d;
    *scale = s;
    return p;
}

/* A bisection point of (a, b): geometric when both ends have one sign and differ by a large ratio
 * (roots spread over decades), with an end at or inside +-L (L > 0 a lower bound of the root
 * moduli of p, a scale for the derivatives) replaced by +-L; 0 when the interval straddles it
 * widely; else the midpoint. Always strictly inside (a, b) for a < b not adjacent doubles. */
static double poly_mid(double a, double b, double L)
{
    if (a >= 0.0) {
        const double lo = a > L ? a : L;
        if (b > 16.0 * lo) return sqrt(lo) * sqrt(b);
    } else if (b <= 0.0) {
        const double hi = -b > L ? -b : L;
        if (-a > 16.0 * hi) return -(sqrt(hi) * sqrt(-a));
    } else if (b > -16.0 * a || a < -16.0 * b) {
        return 0.0;
    }
    return 0.5 * a + 0.5 * b;
}

/* The root of q (degree d) in the open interval (lo, hi) where q is monotone and q(lo) q(hi) < 0
 * (only the sign of flo = q(lo) is used), from the start x0 (ignored unless inside): Newton, replaced by bisection whenever
 * its step leaves the bracket or fails to halve the step before last (rtsafe-style). Stops after one
 * more Newton step once |q| is within the rounding bound 2 d eps sum |c_k| |x|^k (the bound is
 * pessimistic; the last step recovers the digits it would cost), or when the step is at the last
 * bits (|step| <= steptol |x|). Returns 0 when
 * the cap is hit or a value is not finite. */
static int poly_bracket(const double *q, int d, double lo, double flo, double hi, double x0, double steptol, double L,
                        double *root)
{
    double xn = lo, xp = hi; /* q(xn) < 0 < q(xp) */
    if (flo > 0.0) xn = hi, xp = lo;
    double x = x0 > lo && x0 < hi ? x0 : poly_mid(lo, hi, L), df, s, f = poly_eval_d1s(q, d, x, &df, &s);
    double step = hi - lo, step_old = step;
    const double noise = 2.0 * d * POLY_EPS;
    for (int it = 0;; ++it) {
        if (!isfinite(f) || it == POLY_FAST_MAXIT) return 0;
        if (f < 0.0) xn = x;
        else xp = x;
        const double a = xn < xp ? xn : xp, b = xn < xp ? xp : xn; /* not fmin/fmax: libm calls */
        double nx = x - f / df;
        if (fabs(f) <= noise * s) { /* at the rounding level: one last Newton step, if it stays inside */
            if (nx > a && nx < b) x = nx;
            break;
        }
        if (!(nx > a && nx < b) || !(fabs(f) <= 0.5 * fabs(step_old * df))) nx = poly_mid(a, b, L);
        step_old = step;
        step = nx - x;
        x = nx;
        if (fabs(step) <= steptol * fabs(x) || x == a || x == b) break;
        f = poly_eval_d1s(q, d, x, &df, &s);
    }
    *root = x;
    return 1;
}

/* p, p'' / 2 and sum |c_k| |x|^k at x in one Horner pass (p' is not needed at a breakpoint). */
static double poly_eval_brk(const double *c, int degree, double x, double *half_d2, double *scale)
{
    double p = c[degree], d = 0.0, dd = 0.0, ax = fabs(x), s = fabs(c[degree]);
    for (int k = degree - 1; k >= 0; --k) {
        dd = dd * x + d;
        d = d * x + p;
        p = p * x + c[k];
        s = s * ax + fabs(c[k]);
    }
    *half_d2 = dd;
    *scale = s;
    return p;
}

/* -1, 0, +1. */
static int poly_sign(double v) { return (v > 0.0) - (v < 0.0); }

/* Newton start for the root of a piece beside breakpoint x (q' = 0 there): the root of the Taylor
 * quadratic q(x) + (q''/2) t^2 on the side dir (+1 right, -1 left); NaN when it has none. */
static double poly_taylor_start(double x, double v, double half_d2, int dir)
{
    double t2 = -v / half_d2;
    return t2 > 0.0 ? x + dir * sqrt(t2) : NAN;
}

/* Real roots of q (degree d >= 1) given the sorted breakpoints brk[0..nb-1] (the real roots of q',
 * possibly with extras), the bound B and the bisection scale L: one bracketed solve per monotone piece with a sign change.
 * A breakpoint is itself a root when q vanishes there exactly, or when it is an extremum (both
 * neighbours of one sign) with |q| <= tol x sum |c_k| |x|^k, tol = touch if it does not cross zero
 * (the touching case: a complex pair with a tiny imaginary part) and tol = snap if it does (the sign
 * of q there is rounding noise: one double root, not a noise-split pair). A breakpoint root counts
 * as a zero of q, so the pieces beside it hold no other root.
 * Writes the roots in increasing order and returns their number, -1 on trouble. */
static int poly_level(const double *q, int d, const double *brk, int nb, double B, double L, double touch,
                      double snap, double steptol, double *out)
{
    double val[PROX_POLY_MAX_DEGREE], scl[PROX_POLY_MAX_DEGREE], h2[PROX_POLY_MAX_DEGREE];
    int sg[PROX_POLY_MAX_DEGREE + 2], at[PROX_POLY_MAX_DEGREE]; /* signs at -inf, breakpoints, +inf */
    const int slead = poly_sign(q[d]);
    sg[0] = d % 2 ? -slead : slead;
    sg[nb + 1] = slead;
    for (int i = 0; i < nb; ++i) {
        val[i] = poly_eval_brk(q, d, brk[i], &h2[i], &scl[i]);
        if (!isfinite(val[i])) return -1;
        sg[i + 1] = poly_sign(val[i]);
    }
    for (int i = 0; i < nb; ++i) { /* breakpoint roots, from the signs before any is zeroed */
        const int s = sg[i + 1], side = sg[i] == sg[i + 2] ? sg[i] : 0;
        const double tol = side == 0 ? 0.0 : side == s ? touch : snap;
        at[i] = s == 0 || fabs(val[i]) <= tol * scl[i];
    }
    for (int i = 0; i < nb; ++i)
        if (at[i]) sg[i + 1] = 0;
    int m = 0;
    for (int i = 0; i <= nb; ++i) {
        /* the piece (left, right) between breakpoints i-1 and i */
        if (sg[i] * sg[i + 1] < 0) {
            /* beyond the bound q has the sign of its leading term: no evaluation needed there */
            double left = i > 0 ? brk[i - 1] : -B, right = i < nb ? brk[i] : B, x0;
            const double fl = i > 0 ? val[i - 1] : sg[0];
            if (!(left < right)) return -1;
            /* start from the Taylor quadratic of the breakpoint end where |q| is smaller */
            if (i > 0 && (i == nb || fabs(val[i - 1]) <= fabs(val[i])))
                x0 = poly_taylor_start(left, val[i - 1], h2[i - 1], 1);
            else if (i < nb)
                x0 = poly_taylor_start(right, val[i], h2[i], -1);
            else
                x0 = NAN;
            if (!poly_bracket(q, d, left, fl, right, x0, steptol, L, &out[m])) return -1;
            ++m;
        }
        if (i < nb && at[i]) out[m++] = brk[i];
    }
    return m;
}

/* Power-of-two Fujiwara-type bound on the moduli of all roots of w[0..n] (w[n] != 0), walking the
 * coefficients in direction dir (+1: upper bound of the roots of w; -1 with w pointing at the last
 * coefficient: upper bound of the reciprocal roots): 2 max_k |w_k / w_n|^(1/(n-k)), each term
 * rounded up to a power of two, times 2 for margin. Returns the binary exponent. */
static int poly_bound_exp(const double *w, int n, int dir)
{
    int e = -1074;
    const int en = ilogb(w[dir * n]);
    for (int k = 0; k < n; ++k) {
        if (w[dir * k] == 0.0) continue;
        int ek = ilogb(w[dir * k]) - en + 2; /* |w_k / w_n| < 2^ek */
        int r = ek >= 0 ? (ek + (n - k) - 1) / (n - k) : -((-ek) / (n - k));
        if (r > e) e = r;
    }
    return e + 2;
}

/* Ends of the noise zone of a root cluster. Where several roots of p coalesce to within rounding
 * (a triple or higher root, or a double root of a large polynomial), the derivative chain reports
 * one root x, but the roots of the stored polynomial may lie anywhere in the zone around x where
 * |p| <= T = 32 eps sum |c_k| |x|^k, and QR reports points spread over it. Callers that polish on
 * another form (circle_circle) need starts across the zone, so its two ends are reported too: in
 * the monotone pieces beside x (between the neighbouring breakpoints brk[], or +-B), the roots of
 * p -+ T, when the zone is wider than 1e-6 relative (estimated as T / |p'(x)|). Edges are added in
 * order while the count stays <= 8; returns the new count. */
static int poly_cluster_edges(const double *q, int d, const double *brk, int nb, double B, double L, double *r,
                              int m)
{
    double extra[2 * PROX_POLY_MAX_DEGREE];
    int ne = 0;
    for (int i = 0; i < m; ++i) {
        const double x = r[i], width = 1e-6 * fmax(fabs(x), L);
        double dp, s, px = poly_eval_d1s(q, d, x, &dp, &s);
        const double T = POLY_FAST_SNAP * s;
        if (!(fabs(px) <= T) || fabs(dp) * width >= T) continue; /* not a cluster or too narrow */
        double a = -B, b = B;
        for (int k = 0; k < nb; ++k) {
            if (brk[k] < x) a = brk[k];
            if (brk[k] > x && b == B) b = brk[k];
        }
        for (int side = -1; side <= 1; side += 2) {
            const double end = side < 0 ? a : b, fe = prox_poly_eval(q, d, end, NULL);
            if (!(fabs(fe) > T)) continue; /* the zone reaches past the piece */
            double qs[PROX_POLY_MAX_DEGREE + 1], e;
            for (int k = 0; k <= d; ++k) qs[k] = q[k];
            qs[0] -= copysign(T, fe); /* p - T sign(p(end)): changes sign between x and end */
            const double lo = side < 0 ? end : x, hi = side < 0 ? x : end;
            const double flo = side < 0 ? fe : px - copysign(T, fe);
            if (!(lo < hi) || !poly_bracket(qs, d, lo, flo, hi, NAN, 4.0 * POLY_EPS, L, &e)) continue;
            if (fabs(e - x) > width && ne < 2 * PROX_POLY_MAX_DEGREE) extra[ne++] = e;
        }
    }
    for (int k = 0; k < ne && m < PROX_POLY_MAX_DEGREE; ++k) { /* insert in order */
        int j = m++;
        for (; j > 0 && r[j - 1] > extra[k]; --j) r[j] = r[j - 1];
        r[j] = extra[k];
    }
    return m;
}

/* Real roots of w[0..n] (5 <= n <= 8, w[n] != 0) by the derivative chain, polished on full[0..deg]
 * when the degree was deflated. Returns the count, -1 on trouble (the caller falls back to QR). */
static int poly_fast_roots(const double *w, int n, const double *full, int deg, double *roots)
{
    static const double binom[PROX_POLY_MAX_DEGREE + 1][PROX_POLY_MAX_DEGREE + 1] = {
        {1}, {1, 1}, {1, 2, 1}, {1, 3, 3, 1}, {1, 4, 6, 4, 1}, {1, 5, 10, 10, 5, 1},
        {1, 6, 15, 20, 15, 6, 1}, {1, 7, 21, 35, 35, 21, 7, 1}, {1, 8, 28, 56, 70, 56, 28, 8, 1}};
    const double B = ldexp(1.0, poly_bound_exp(w, n, 1));
    int k0 = 0; /* p = x^k0 r(x), r(0) != 0: the nonzero roots are at least L in modulus */
    while (w[k0] == 0.0) ++k0;
    const double L = k0 < n ? ldexp(1.0, -poly_bound_exp(w + n, n - k0, -1)) : 1.0;
    if (!isfinite(B) || !(L > 0.0)) return -1;
    double q[PROX_POLY_MAX_DEGREE + 1], brk[PROX_POLY_MAX_DEGREE], cur[PROX_POLY_MAX_DEGREE];
    /* q_{n-1} = p^(n-1) / (n-1)!: linear */
    brk[0] = -(binom[n - 1][n - 1] * w[n - 1]) / (binom[n][n - 1] * w[n]);
    int nb = 1;
    for (int j = n - 2; j >= 0; --j) {
        const int d = n - j;
        for (int k = 0; k <= d; ++k) q[k] = binom[k + j][j] * w[k + j]; /* q_j = p^(j) / j! */
        int m = j > 0 ? poly_level(q, d, brk, nb, B, L, POLY_FAST_TOUCH_LOW, 0.0, POLY_FAST_STEP_LOW, cur)
                      : poly_level(q, d, brk, nb, B, L, POLY_DOUBLE_REL, POLY_FAST_SNAP, 4.0 * POLY_EPS, cur);
        if (m < 0) return -1;
        if (j == 0) m = poly_cluster_edges(q, d, brk, nb, B, L, cur, m);
        for (int i = 0; i < m; ++i) brk[i] = cur[i];
        nb = m;
    }
    if (deg > n) { /* polish on the undeflated polynomial, never past half the gap to a neighbour */
        for (int i = 0; i < nb; ++i) {
            double gap = INFINITY;
            if (i > 0) gap = fmin(gap, brk[i] - brk[i - 1]);
            if (i + 1 < nb) gap = fmin(gap, brk[i + 1] - brk[i]);
            roots[i] = poly_polish(full, deg, brk[i], 0.5 * gap);
        }
        for (int i = 1; i < nb; ++i) /* polish keeps the order up to ties; re-sort cheaply */
            for (int k = i; k > 0 && roots[k - 1] > roots[k]; --k) {
                double t = roots[k];
                roots[k] = roots[k - 1], roots[k - 1] = t;
            }
        nb = poly_drop_artifacts(full, deg, roots, nb);
    } else {
        for (int i = 0; i < nb; ++i) roots[i] = brk[i];
    }
    return nb;
}

prox_status prox_poly_real_roots(const double *c, int degree, double *roots, int *count)
{
    double w[PROX_POLY_MAX_DEGREE + 1];
    int n;
    prox_status st = poly_prepare(c, degree, roots, count, w, &n);
    if (st != PROX_OK || n == 0) return st;
    poly_cand z[PROX_POLY_MAX_DEGREE];
    int closed = 0;
    if (n <= 4) {
        poly_closed_roots(w, n, z);
        closed = poly_closed_ok(w, n, z);
    }
    if (!closed && (st = poly_gsl_roots(w, n, z)) != PROX_OK) return st;
    poly_finish(w, degree, z, n, roots, count);
    return PROX_OK;
}

prox_status prox_poly_real_roots_fast(const double *c, int degree, double *roots, int *count)
{
    double w[PROX_POLY_MAX_DEGREE + 1];
    int n;
    prox_status st = poly_prepare(c, degree, roots, count, w, &n);
    if (st != PROX_OK || n == 0) return st;
    if (n >= 5) { /* derivative chain; QR only when it reports trouble */
        int m = poly_fast_roots(w, n, w, degree, roots);
        if (m >= 0) {
            *count = m;
            return PROX_OK;
        }
    }
    return prox_poly_real_roots(c, degree, roots, count);
}

prox_status prox_poly_real_roots_gsl(const double *c, int degree, double *roots, int *count)
{
    double w[PROX_POLY_MAX_DEGREE + 1];
    int n;
    prox_status st = poly_prepare(c, degree, roots, count, w, &n);
    if (st != PROX_OK || n == 0) return st;
    poly_cand z[PROX_POLY_MAX_DEGREE];
    if ((st = poly_gsl_roots(w, n, z)) != PROX_OK) return st;
    poly_finish(w, degree, z, n, roots, count);
    return PROX_OK;
}

prox_status prox_poly_real_roots_by(prox_root_method m, const double *c, int degree, double *roots, int *count)
{
    return m == PROX_ROOTS_GSL ? prox_poly_real_roots_gsl(c, degree, roots, count)
                               : prox_poly_real_roots_fast(c, degree, roots, count);
}
