/* Real roots of polynomials of degree <= 8 (the single owner of gsl_poly_complex_solve in prox).
 * Sources: issue 2 Sec. 3; closed forms: stable quadratic (Numerical Recipes 5.6 style
 * q = -(b + sgn(b) sqrt(b^2 - 4ac))/2), GSL's closed-form cubic (gsl_poly_complex_solve_cubic),
 * Ferrari's quartic through the resolvent cubic 8m^3 + 8p m^2 + (2p^2 - 8r) m - q^2 = 0
 * (docs/algorithms/poly.md); degree 5..8 through GSL's balanced companion-matrix QR with a
 * workspace on the stack. Every candidate is polished by Newton on the original polynomial, and
 * near-real complex pairs are tested for a near-double real root at a stationary point of p. */
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

/* Complex roots by GSL's companion-matrix QR, with the workspace on the stack (no allocation). */
static prox_status poly_gsl_roots(const double *w, int n, poly_cand *z)
{
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
    *count = m;
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
