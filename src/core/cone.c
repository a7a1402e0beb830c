/* The truncated cone TRC (core/curved.h). A solid of revolution: in the half-plane through the axis
 * and a point y, with coordinates (t, rho) = (axial, radial) about the centre, it is the trapezoid
 *   -hh <= t <= hh,  0 <= rho <= r(t) = rm + (r2 - r1) t / (2 hh),  rm = (r1 + r2) / 2,
 * and every query reduces to that trapezoid: the nearest point of the solid (or of its boundary)
 * to y lies in y's half-plane. Its edges are the base (facet 3 of the MCNP card), the top (facet 2)
 * and the slanted generator from (-hh, r1) to (hh, r2) (facet 1, the conical surface). */
#include <math.h>

#include "core/axis.h"
#include "core/curved.h"
#include "core/curved_normal.h"

/* The half-plane coordinates of y: t, rho and the radial unit vector *u (any perpendicular to the
 * axis when y is on it to rounding, core/axis.h). */
static double half_plane(const prox_cone *k, prox_vec3 y, double *rho, prox_vec3 *u)
{
    *u = prox_axis_radial(y, k->w, rho);
    return prox_v3_dot(y, k->w);
}

prox_vec3 prox_cone_make(const prox_trc *t, prox_cone *k)
{
    double h = prox_v3_norm(t->axis);
    k->w = prox_v3(t->axis.x / h, t->axis.y / h, t->axis.z / h);
    k->hh = 0.5 * h;
    k->r1 = t->r1;
    k->r2 = t->r2;
    return prox_v3_mad(t->base, 0.5, t->axis);
}

/* hc(d) = max(-hh d.w + r1 |P d|, hh d.w + r2 |P d|): the cone is the hull of its two rims. */
double prox_cone_hc(const prox_cone *k, prox_vec3 d)
{
    double dw = prox_v3_dot(d, k->w), p = prox_v3_norm(prox_axis_across(d, k->w));
    return fmax(-k->hh * dw + k->r1 * p, k->hh * dw + k->r2 * p);
}

/* The rim point of the larger value; on a tie (d normal to the conical surface) the middle of the
 * generator; d along the axis (to rounding, core/axis.h) the centre of the supporting cap (the apex
 * for a zero radius). */
prox_vec3 prox_cone_pc(const prox_cone *k, prox_vec3 d)
{
    double dw = prox_v3_dot(d, k->w), p;
    prox_vec3 u = prox_axis_radial(d, k->w, &p);
    if (!(p > 0.0)) return prox_v3_scale(k->w, dw > 0.0 ? k->hh : (dw < 0.0 ? -k->hh : 0.0));
    double vb = -k->hh * dw + k->r1 * p, vt = k->hh * dw + k->r2 * p;
    if (vt > vb) return prox_v3_mad(prox_v3_scale(k->w, k->hh), k->r2, u);
    if (vb > vt) return prox_v3_mad(prox_v3_scale(k->w, -k->hh), k->r1, u);
    return prox_v3_scale(u, 0.5 * (k->r1 + k->r2));
}

/* Signed distance of (t, rho) to the line of the generator, positive outside: with the edge vector
 * e = (2 hh, r2 - r1) from its middle (0, rm), n = (r1 - r2, 2 hh) / |e|. */
static double slant_signed(const prox_cone *k, double t, double rho)
{
    double ex = 2.0 * k->hh, ey = k->r2 - k->r1, rm = 0.5 * (k->r1 + k->r2);
    return (ex * (rho - rm) - ey * t) / prox_hypot2(ex, ey);
}

/* Nearest point of the generator segment to (t, rho). */
static void slant_foot(const prox_cone *k, double t, double rho, double *tq, double *rq)
{
    double ex = 2.0 * k->hh, ey = k->r2 - k->r1, rm = 0.5 * (k->r1 + k->r2);
    double s = (ex * t + ey * (rho - rm)) / (ex * ex + ey * ey);
    s = s < -0.5 ? -0.5 : (s > 0.5 ? 0.5 : s);
    *tq = s == 0.5 ? k->hh : (s == -0.5 ? -k->hh : s * ex);
    *rq = s == 0.5 ? k->r2 : (s == -0.5 ? k->r1 : rm + s * ey);
}

/* 1 when (t, rho) lies in the trapezoid. */
static int trap_inside(const prox_cone *k, double t, double rho)
{
    return fabs(t) <= k->hh && slant_signed(k, t, rho) <= 0.0;
}

/* Nearest point of the trapezoid's outer boundary (caps and generator) to an outside (t, rho): the
 * nearest of the three edges' nearest points; returns the distance. */
static double trap_outside(const prox_cone *k, double t, double rho, double *tq, double *rq)
{
    double ts, rs;
    slant_foot(k, t, rho, &ts, &rs);
    double best = prox_hypot2(t - ts, rho - rs);
    *tq = ts, *rq = rs;
    for (int end = 0; end < 2; ++end) {
        double tc = end ? k->hh : -k->hh, rcap = end ? k->r2 : k->r1;
        double rc = rho < rcap ? rho : rcap;
        double dd = prox_hypot2(t - tc, rho - rc);
        if (dd < best) best = dd, *tq = tc, *rq = rc;
    }
    return best;
}

int prox_cone_contains(const prox_cone *k, prox_vec3 y, double tol)
{
    double rho;
    prox_vec3 u;
    double t = half_plane(k, y, &rho, &u);
    if (trap_inside(k, t, rho)) return 1;
    if (fabs(t) > k->hh + tol) return 0;
    double tq, rq;
    return trap_outside(k, t, rho, &tq, &rq) <= tol;
}

prox_vec3 prox_cone_closest(const prox_cone *k, prox_vec3 y)
{
    double rho, tq, rq;
    prox_vec3 u;
    double t = half_plane(k, y, &rho, &u);
    if (trap_inside(k, t, rho)) return y;
    trap_outside(k, t, rho, &tq, &rq);
    return prox_v3_mad(prox_v3_scale(k->w, tq), rq, u);
}

void prox_cone_lateral_normal(const prox_cone *k, double *nt, double *nr)
{
    double l = prox_hypot2(2.0 * k->hh, k->r2 - k->r1);
    *nt = (k->r1 - k->r2) / l, *nr = 2.0 * k->hh / l;
}

int prox_cone_lateral_foot(const prox_cone *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n)
{
    double rho, tq, rq, nt, nr;
    prox_vec3 u;
    double t = half_plane(k, y, &rho, &u);
    if (!(rho > 0.0)) return 0;
    slant_foot(k, t, rho, &tq, &rq);
    prox_cone_lateral_normal(k, &nt, &nr);
    *q = prox_v3_mad(prox_v3_scale(k->w, tq), rq, u);
    *n = prox_v3_mad(prox_v3_scale(k->w, nt), nr, u);
    return fabs(tq) < k->hh ? 2 : 1;
}

/* The unit vector (vt, vr) clamped into the normal cone spanned by the unit normals a and b of the two
 * edges at a vertex (an angle below pi): itself when inside, else the nearer of a and b; the zero
 * vector gives the bisector. Near a vertex the direction from it to the point is rounding noise, and
 * this keeps it a valid outward normal. */
static void clamp_cone(double vt, double vr, const double a[2], const double b[2], double *nt, double *nr)
{
    double cab = a[0] * b[1] - a[1] * b[0], cav = a[0] * vr - a[1] * vt, cvb = vt * b[1] - vr * b[0];
    if (!(vt != 0.0 || vr != 0.0)) {
        double l = prox_hypot2(a[0] + b[0], a[1] + b[1]);
        *nt = (a[0] + b[0]) / l, *nr = (a[1] + b[1]) / l;
    } else if (cav * cab >= 0.0 && cvb * cab >= 0.0) {
        *nt = vt, *nr = vr;
    } else if (vt * a[0] + vr * a[1] >= vt * b[0] + vr * b[1]) {
        *nt = a[0], *nr = a[1];
    } else {
        *nt = b[0], *nr = b[1];
    }
}

/* Signed distance of (t, rho) to the trapezoid's boundary, its nearest boundary point (tq, rq) and the
 * outward unit normal (nt, nr) there. Inside, the distance to the boundary is the least distance to
 * the lines of the three edges (the section is convex); the cap of a zero radius is a vertex, not an
 * edge, and is skipped. Outside, an edge's nearest point inside the edge takes the edge's normal; a
 * vertex (the rims (-hh, r1), (hh, r2)) the direction to the point clamped into its normal cone. */
static double trap_boundary(const prox_cone *k, double t, double rho, double *tq, double *rq, double *nt, double *nr)
{
    double sn[2];
    prox_cone_lateral_normal(k, &sn[0], &sn[1]);
    if (!trap_inside(k, t, rho)) {
        double d = trap_outside(k, t, rho, tq, rq);
        int top = *tq == k->hh && *rq == k->r2, base = *tq == -k->hh && *rq == k->r1;
        if (top || base) {
            const double cap[2] = {top ? 1.0 : -1.0, 0.0};
            double vt = d > 0.0 ? (t - *tq) / d : 0.0, vr = d > 0.0 ? (rho - *rq) / d : 0.0;
            clamp_cone(vt, vr, cap, sn, nt, nr);
        } else if (fabs(*tq) == k->hh) {
            *nt = *tq > 0.0 ? 1.0 : -1.0, *nr = 0.0;
        } else {
            *nt = sn[0], *nr = sn[1];
        }
        return d;
    }
    double best = -slant_signed(k, t, rho);
    slant_foot(k, t, rho, tq, rq);
    *nt = sn[0], *nr = sn[1];
    for (int end = 0; end < 2; ++end) {
        double rcap = end ? k->r2 : k->r1, dd = end ? k->hh - t : t + k->hh;
        if (rcap > 0.0 && dd < best) {
            best = dd, *tq = end ? k->hh : -k->hh, *rq = rho < rcap ? rho : rcap;
            *nt = end ? 1.0 : -1.0, *nr = 0.0;
        }
    }
    return -best;
}

double prox_cone_boundary(const prox_cone *k, prox_vec3 y, prox_vec3 *q)
{
    prox_vec3 n;
    return prox_cone_boundary_n(k, y, q, &n);
}

double prox_cone_boundary_n(const prox_cone *k, prox_vec3 y, prox_vec3 *q, prox_vec3 *n)
{
    double rho, tq, rq, nt, nr;
    prox_vec3 u;
    double t = half_plane(k, y, &rho, &u);
    double s = trap_boundary(k, t, rho, &tq, &rq, &nt, &nr);
    *q = prox_v3_mad(prox_v3_scale(k->w, tq), rq, u);
    *n = prox_v3_mad(prox_v3_scale(k->w, nt), nr, u);
    return s;
}
