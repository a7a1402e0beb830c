/* The prepared cylinder's closest point, signed point distance and rims (core/cyl.h), and the public
 * elementary geometry of one RCC built on them (distance.h). */
#include "core/cyl.h"
#include "prox/distance.h"

prox_vec3 prox_cyl_closest(const prox_cyl *k, prox_vec3 x)
{
    prox_vec3 d = prox_v3_sub(x, k->b);
    double t = prox_v3_dot(d, k->w);
    prox_vec3 radial = prox_v3_mad(d, -t, k->w);
    double rho = prox_v3_norm(radial);
    double tc = t < 0.0 ? 0.0 : (t > k->h ? k->h : t);
    if (tc == t && rho <= k->r) return x;
    if (rho > k->r) radial = prox_v3_scale(radial, k->r / rho);
    return prox_v3_add(prox_v3_mad(k->b, tc, k->w), radial);
}

double prox_cyl_signed(const prox_cyl *k, prox_vec3 x, prox_vec3 *q, prox_vec3 *n)
{
    prox_vec3 d = prox_v3_sub(x, k->b);
    double t = prox_v3_dot(d, k->w);
    prox_vec3 rad = prox_v3_mad(d, -t, k->w);
    double rho = prox_v3_norm(rad);
    /* Radial unit direction. Near the axis rad is rounding noise with a component along w: below
     * 1e-12 x size any perpendicular direction is as good; above it, re-orthogonalise to w. */
    prox_vec3 e;
    if (rho > 1e-12 * fmax(fmax(fabs(t), rho), k->r))
        e = prox_v3_normalize(prox_v3_reject(prox_v3_scale(rad, 1.0 / rho), k->w));
    else
        e = prox_v3_any_perp(k->w);
    if (t >= 0.0 && t <= k->h && rho <= k->r) { /* inside: nearest of the base, top and side */
        double db = t, dt = k->h - t, ds = k->r - rho;
        if (ds <= db && ds <= dt) {
            *n = e;
            *q = prox_v3_mad(x, ds, e);
            return -ds;
        }
        *n = db <= dt ? prox_v3_neg(k->w) : k->w;
        *q = prox_v3_mad(x, db <= dt ? -db : dt, k->w);
        return -(db <= dt ? db : dt);
    }
    /* outside: clamp axially and radially; the distance from the two offsets */
    double tc = t < 0.0 ? 0.0 : (t > k->h ? k->h : t);
    double rc = rho > k->r ? k->r : rho;
    double dist = prox_hypot2(t - tc, rho - rc);
    *q = prox_v3_mad(prox_v3_mad(k->b, tc, k->w), rc, e);
    *n = prox_v3_normalize(prox_v3_sub(x, *q));
    return dist;
}

prox_fcircle prox_cyl_rim(const prox_cyl *k, int end)
{
    prox_vec3 n = k->w;
    double sg = copysign(1.0, n.z), a = -1.0 / (sg + n.z), bb = n.x * n.y * a;
    prox_fcircle f;
    f.c = k->cap[end ? 1 : 0];
    f.n = n;
    f.u = prox_v3(1.0 + sg * n.x * n.x * a, sg * bb, -sg * n.x);
    f.v = prox_v3_cross(n, f.u);
    f.r = k->r;
    return f;
}

/* ---- public: one RCC (validated by the caller; see distance.h) ---- */

PROX_API double prox_rcc_support(const prox_rcc *c, prox_vec3 d)
{
    prox_cyl k = prox_cyl_make(c, prox_v3(0, 0, 0));
    return prox_cyl_support(&k, d);
}

PROX_API prox_vec3 prox_rcc_support_point(const prox_rcc *c, prox_vec3 d)
{
    prox_cyl k = prox_cyl_make(c, prox_v3(0, 0, 0));
    return prox_cyl_support_point(&k, d);
}

PROX_API prox_vec3 prox_rcc_closest_point(const prox_rcc *c, prox_vec3 x)
{
    prox_cyl k = prox_cyl_make(c, prox_v3(0, 0, 0));
    return prox_cyl_closest(&k, x);
}

PROX_API int prox_rcc_contains_point(const prox_rcc *c, prox_vec3 x, double tol)
{
    prox_cyl k = prox_cyl_make(c, prox_v3(0, 0, 0));
    return prox_cyl_contains(&k, x, tol);
}

PROX_API double prox_rcc_pair_scale(const prox_rcc *a, const prox_rcc *b)
{
    double s = prox_v3_dist(prox_rcc_center(a), prox_rcc_center(b));
    double v[4] = {prox_v3_norm(a->axis), prox_v3_norm(b->axis), a->radius, b->radius};
    for (int i = 0; i < 4; ++i)
        if (v[i] > s) s = v[i];
    return s;
}
