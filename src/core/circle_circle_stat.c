/* Stationary points of the distance between two circles (core/circle.h), P(C,C) of Agarwal et al. (2016) Sec. 3.5: the distance function of
 * P(D,C) (Sec. 3.4, Eq. (17)) with s1 = 1, stationarity reduced to one univariate polynomial of
 * degree eight in v1 = tan(theta1/2) (the paper's g3), rooted numerically.
 * Instead of the paper's 700 kB symbolic g3 this file eliminates theta2 geometrically (the partner of
 * a point is its closest point on the other circle) and builds g3 numerically in a normalised frame
 * (docs/algorithms/circle_circle.md):
 *   circle a: P(th) = (cos th, sin th, 0) (centre at the origin, unit radius);
 *   circle b: centre C, unit normal N, radius r (all divided by r_a, in a's frame);
 *   D = P - C, dn = N.D, rho = |D x N| (distance of P from b's axis);
 *   g(th) = dist^2(P, b) = (rho - r)^2 + dn^2,
 *   g'(th)/2 = h(th) = (1 - r/rho) (D_perp.P') + dn (N.P'),          (stationarity)
 *   equivalently (C.P') rho = r (C.P' + dn N.P'); squared and multiplied by (1 + t^2)^4:
 *   F(t) = A(t)^2 R(t) - r^2 (A(t)(1 + t^2) + dn(t) B(t))^2 = 0, degree 8, with A = C.P',
 *   B = N.P', R = rho^2, each trig-linear factor k0 + kc cos + ks sin written as
 *   k0 (1 + t^2) + kc (1 - t^2) + 2 ks t.
 * Squaring adds the stationary points of the far-point distance; those are filtered by |h|. A circle
 * b of negative radius -r turns g into the far-point distance (rho + r)^2 + dn^2 with the same
 * polynomial: its stationary points are those the filter keeps then.
 * Every root (and the starts 0, pi/2, pi, 3pi/2, which cover th = pi, sent to infinity by t) is
 * polished by safeguarded Newton on h. */
#include "core/angle.h"
#include "core/circle.h"
#include "core/poly.h"
#include "core/tol.h"

#include <float.h>

/* Circle b in the normalised frame of circle a. */
typedef struct cc_prob {
    double cx, cy, cz; /* C */
    double nx, ny, nz; /* N */
    double r;
    double kx, ky, kz; /* C x N */
    double scale;      /* 1 + |C| + r */
} cc_prob;

/* Values at one angle: h = g'/2, dh = h', g = dist^2 (normalised units). */
typedef struct cc_eval {
    double h, dh, g;
    int axis; /* P on b's axis: h undefined */
} cc_eval;

static cc_prob cc_make(const prox_fcircle *a, const prox_fcircle *b)
{
    cc_prob p;
    prox_vec3 d = prox_v3_sub(b->c, a->c);
    double ir = 1.0 / a->r;
    p.cx = prox_v3_dot(d, a->u) * ir, p.cy = prox_v3_dot(d, a->v) * ir, p.cz = prox_v3_dot(d, a->n) * ir;
    p.nx = prox_v3_dot(b->n, a->u), p.ny = prox_v3_dot(b->n, a->v), p.nz = prox_v3_dot(b->n, a->n);
    double nn = sqrt(p.nx * p.nx + p.ny * p.ny + p.nz * p.nz);
    p.nx /= nn, p.ny /= nn, p.nz /= nn;
    p.r = b->r * ir;
    p.kx = p.cy * p.nz - p.cz * p.ny, p.ky = p.cz * p.nx - p.cx * p.nz, p.kz = p.cx * p.ny - p.cy * p.nx;
    p.scale = 1.0 + sqrt(p.cx * p.cx + p.cy * p.cy + p.cz * p.cz) + fabs(p.r);
    return p;
}

/* h, h' and g at the angle (c, s) = (cos th, sin th) (formulas in the file comment; P'' = -P,
 * |P'| = 1). */
static cc_eval cc_at_cs(const cc_prob *p, double c, double s)
{
    cc_eval e = {0, 0, 0, 0};
    double dx = c - p->cx, dy = s - p->cy, dz = -p->cz;
    double dn = p->nx * dx + p->ny * dy + p->nz * dz;
    double qx = dx - dn * p->nx, qy = dy - dn * p->ny, qz = dz - dn * p->nz; /* D_perp */
    double rho = sqrt(qx * qx + qy * qy + qz * qz);
    double np1 = -p->nx * s + p->ny * c;  /* N.P' */
    double qp1 = -qx * s + qy * c;        /* D_perp.P' */
    double qp0 = qx * c + qy * s;         /* D_perp.P */
    double np0 = p->nx * c + p->ny * s;   /* N.P */
    e.g = (rho - p->r) * (rho - p->r) + dn * dn;
    if (!(rho > 0.0)) {
        e.axis = 1;
        return e;
    }
    double f = 1.0 - p->r / rho;
    e.h = f * qp1 + dn * np1;
    e.dh = p->r * qp1 * qp1 / (rho * rho * rho) + f * (1.0 - np1 * np1 - qp0) + np1 * np1 - dn * np0;
    return e;
}

static cc_eval cc_at(const cc_prob *p, double th) { return cc_at_cs(p, cos(th), sin(th)); }

/* Safeguarded Newton on h from the angle's unit vector u: steps clamped to 0.5 rad, halved until |h|
 * decreases (prox_unit2_step: no trigonometric call per step); returns the best unit vector found
 * and its evaluation. */
static prox_unit2 cc_polish_u(const cc_prob *p, prox_unit2 u, cc_eval *out)
{
    cc_eval e = cc_at_cs(p, u.c, u.s);
    for (int it = 0; it < 50 && !e.axis && e.h != 0.0; ++it) {
        if (e.dh == 0.0) break;
        double step = e.h / e.dh;
        if (step > 0.5) step = 0.5;
        if (step < -0.5) step = -0.5;
        int moved = 0;
        /* A Newton step below PROX_TOL_NEWTON_QUAD rad is in the quadratic regime: |h| there is rounding noise, so
         * a failed decrease means convergence, not a step to halve (halving would only cost six
         * more evaluations per call). */
        int tiny = fabs(step) <= PROX_TOL_NEWTON_QUAD;
        for (int k = 0; k < (tiny ? 1 : 6); ++k, step *= 0.5) {
            prox_unit2 un = prox_unit2_step(u, step);
            cc_eval en = cc_at_cs(p, un.c, un.s);
            if (!en.axis && fabs(en.h) < fabs(e.h)) {
                u = un, e = en, moved = 1;
                break;
            }
        }
        if (!moved || fabs(step) <= 4.0 * DBL_EPSILON) break; /* a step at the rounding of the angle */
    }
    *out = e;
    return u;
}

/* Local refinement used by the RCC-RCC fast path: a local MINIMUM of g near u (Newton on h alone
 * may stop at a maximum or saddle of the rim-rim distance).  Safeguarded Newton on the unit vector of
 * the angle (prox_unit2_step, no trigonometric call): the Newton step where h' > 0, else a descent
 * step of 0.5 rad, halved until g decreases; below PROX_TOL_DESCENT_ROUND rad (quadratic regime, where the decrease is
 * rounding) until |h| does. */
prox_unit2 prox_circle_circle_local(const prox_fcircle *a, const prox_fcircle *b, prox_unit2 u)
{
    cc_prob p = cc_make(a, b);
    cc_eval e = cc_at_cs(&p, u.c, u.s);
    for (int it = 0; it < 50 && !e.axis && e.h != 0.0; ++it) {
        double step = e.dh > 0.0 ? e.h / e.dh : (e.h > 0.0 ? 0.5 : -0.5);
        if (!(fabs(step) <= 0.5)) step = step > 0.0 ? 0.5 : -0.5;
        /* A Newton step in the quadratic regime leaves an error of order step^2: take it and stop. */
        if (e.dh > 0.0 && fabs(step) <= PROX_TOL_NEWTON_QUAD) return prox_unit2_step(u, step);
        int moved = 0;
        for (int k = 0; k < 8 && !moved; ++k, step *= 0.5) {
            prox_unit2 un = prox_unit2_step(u, step);
            cc_eval en = cc_at_cs(&p, un.c, un.s);
            if (!en.axis && (en.g < e.g || (fabs(step) <= PROX_TOL_DESCENT_ROUND && fabs(en.h) < fabs(e.h)))) {
                u = un, e = en, moved = 1;
                break;
            }
            if (fabs(step) <= PROX_TOL_DESCENT_ROUND) break; /* quadratic regime: no decrease means converged */
        }
        if (!moved) break;
    }
    return u;
}

/* Quadratic in t for k0 + kc cos + ks sin, times (1 + t^2). */
static void cc_lin(double k0, double kc, double ks, double q[3])
{
    q[0] = k0 + kc, q[1] = 2.0 * ks, q[2] = k0 - kc;
}

/* out = a * b (degrees da, db). */
static void cc_mul(const double *a, int da, const double *b, int db, double *out)
{
    for (int k = 0; k <= da + db; ++k) out[k] = 0.0;
    for (int i = 0; i <= da; ++i)
        for (int j = 0; j <= db; ++j) out[i + j] += a[i] * b[j];
}

/* The degree-8 polynomial F(t) of the file comment. */
static void cc_poly(const cc_prob *p, double F[9])
{
    double A[3], B[3], Dn[3], X[3], Y[3], Z[3], one[3] = {1.0, 0.0, 1.0};
    cc_lin(0.0, p->cy, -p->cx, A);
    cc_lin(0.0, p->ny, -p->nx, B);
    cc_lin(-(p->nx * p->cx + p->ny * p->cy + p->nz * p->cz), p->nx, p->ny, Dn);
    cc_lin(-p->kx, 0.0, p->nz, X); /* D x N = P x N - C x N */
    cc_lin(-p->ky, -p->nz, 0.0, Y);
    cc_lin(-p->kz, p->ny, -p->nx, Z);
    double R[5], t4[5], A2[5], L[5], M[5], L1[9], L2[9];
    cc_mul(X, 2, X, 2, R);
    cc_mul(Y, 2, Y, 2, t4);
    for (int k = 0; k < 5; ++k) R[k] += t4[k];
    cc_mul(Z, 2, Z, 2, t4);
    for (int k = 0; k < 5; ++k) R[k] += t4[k];
    cc_mul(A, 2, A, 2, A2);
    cc_mul(A, 2, one, 2, L);
    cc_mul(Dn, 2, B, 2, M);
    for (int k = 0; k < 5; ++k) L[k] += M[k];
    cc_mul(A2, 4, R, 4, L1);
    cc_mul(L, 4, L, 4, L2);
    for (int k = 0; k < 9; ++k) F[k] = L1[k] - p->r * p->r * L2[k];
}

/* Adds th to the list unless an equal angle is there; beyond 8 keeps the 8 of smallest g. */
static void cc_add(double th, double g, double *ths, double *gs, int *n)
{
    for (int i = 0; i < *n; ++i) {
        double d = fabs(th - ths[i]);
        if (fmin(d, 2.0 * PROX_PI - d) <= PROX_TOL_CC_DEDUP) {
            if (g < gs[i]) ths[i] = th, gs[i] = g;
            return;
        }
    }
    int at = *n;
    if (at == 8) { /* replace the largest g if th is better */
        at = 0;
        for (int i = 1; i < 8; ++i)
            if (gs[i] > gs[at]) at = i;
        if (!(g < gs[at])) return;
    } else {
        ++*n;
    }
    ths[at] = th, gs[at] = g;
}

/* Angles where circle a meets (or, axis parallel to a's plane, comes closest to) b's axis
 * C + s N. There g has a cusp (h is undefined) that Newton cannot polish; when a is tangent to the
 * axis the cusp is a minimum attained on the whole of b (the degenerate contact). */
static int cc_axis_points(const cc_prob *p, double ax[2])
{
    if (fabs(p->nz) > PROX_TOL_FLAT) { /* the axis crosses a's plane at one point */
        double s = -p->cz / p->nz, x = p->cx + s * p->nx, y = p->cy + s * p->ny;
        if (!(fabs(prox_hypot2(x, y) - 1.0) <= PROX_TOL_CC_AXIS_MEET)) return 0;
        ax[0] = atan2(y, x);
        return 1;
    }
    /* Axis (nearly) parallel to a's plane: work with its projection, direction (nx, ny)/|.|. */
    double m = prox_hypot2(p->nx, p->ny), ex = p->nx / m, ey = p->ny / m;
    double along = p->cx * ex + p->cy * ey, fx = p->cx - along * ex, fy = p->cy - along * ey;
    double delta = prox_hypot2(fx, fy);
    if (delta >= 1.0 || delta == 0.0) { /* no crossing: nearest point, or the axis through a's centre */
        ax[0] = delta > 0.0 ? atan2(fy, fx) : atan2(ey, ex);
        ax[1] = ax[0] + PROX_PI;
        return delta > 0.0 ? 1 : 2;
    }
    double w = sqrt((1.0 - delta) * (1.0 + delta));
    ax[0] = atan2(fy + w * ey, fx + w * ex);
    ax[1] = atan2(fy - w * ey, fx - w * ex);
    return 2;
}

/* The problem with circle a's frame turned by a quarter turn: angles th' = th - pi/2. */
static cc_prob cc_quarter_turn(const cc_prob *p)
{
    cc_prob q = *p;
    q.cx = p->cy, q.cy = -p->cx;
    q.nx = p->ny, q.ny = -p->nx;
    q.kx = p->ky, q.ky = -p->kx;
    return q;
}

/* Starting angles from the real roots of the degree-8 polynomial F, shifted by `turn`. Returns how
 * many, or -PROX_ENUMERIC when the root finder m fails (the grid starts alone could miss a pair of
 * close stationary points, so the failure is reported, not papered over). */
static int cc_starts(const double F[9], prox_root_method m, double turn, double *starts)
{
    double roots[8];
    int nr = 0;
    if (prox_poly_real_roots_by(m, F, 8, roots, &nr) != PROX_OK) return -(int)PROX_ENUMERIC;
    for (int i = 0; i < nr; ++i) starts[i] = 2.0 * atan(roots[i]) + turn;
    return nr;
}

/* 1 when F's leading coefficient is at least PROX_TOL_CC_LEAD of its largest (tol.h): the frame
 * represents every angle well, pi included. */
static int cc_lead_ok(const double F[9])
{
    double big = 0.0;
    for (int k = 0; k < 9; ++k) big = fmax(big, fabs(F[k]));
    return fabs(F[8]) >= PROX_TOL_CC_LEAD * big;
}

int prox_circle_circle_stationary(const prox_fcircle *a, const prox_fcircle *b, prox_root_method m, double th[8],
                                  int *count)
{
    *count = 0;
    cc_prob p = cc_make(a, b);
    /* b's offset in units of r_a overflows (sizes 1e200 apart): no stationary point can be trusted,
     * and the tests below would compare inf with inf. */
    if (!isfinite(p.scale) || !isfinite(p.nx + p.ny + p.nz)) return -(int)PROX_ENUMERIC;
    double cxy = prox_hypot2(p.cx, p.cy), nxy = prox_hypot2(p.nx, p.ny);
    if (nxy <= PROX_TOL_COAXIAL && cxy <= PROX_TOL_COAXIAL * p.scale) return 1; /* g is constant */
    /* The half-angle substitution represents angles near pi badly (t -> infinity, coefficients
     * dominated by rounding): the polynomial is solved in a frame whose leading coefficient shows no
     * root there, a quarter turn away if need be, and in both frames when neither does (every angle
     * is then far from pi in one of them). */
    double starts[24], F[9], G[9];
    int ns = 0, nq = 0;
    cc_poly(&p, F);
    if (cc_lead_ok(F)) {
        ns = cc_starts(F, m, 0.0, starts);
    } else {
        cc_prob q = cc_quarter_turn(&p);
        cc_poly(&q, G);
        if (!cc_lead_ok(G) && (ns = cc_starts(F, m, 0.0, starts)) < 0) return ns;
        nq = cc_starts(G, m, 0.5 * PROX_PI, starts + ns);
    }
    if (ns < 0) return ns;
    if (nq < 0) return nq;
    ns += nq;
    for (int k = 0; k < 8; ++k) starts[ns++] = 0.25 * PROX_PI * k; /* grid: safety net */
    double gs[8];
    const double tol = PROX_TOL_CC_STAT * p.scale;
    for (int i = 0; i < ns; ++i) {
        cc_eval e;
        prox_unit2 u = cc_polish_u(&p, (prox_unit2){cos(starts[i]), sin(starts[i])}, &e);
        double t = atan2(u.s, u.c);
        if (e.axis || !(fabs(e.h) <= tol)) continue; /* spurious root of the squared equation */
        cc_add(prox_prim_wrap_2pi(t), e.g, th, gs, count);
    }
    double ax[2];
    int na = cc_axis_points(&p, ax);
    for (int i = 0; i < na; ++i) cc_add(prox_prim_wrap_2pi(ax[i]), cc_at(&p, ax[i]).g, th, gs, count);
    return 0;
}

