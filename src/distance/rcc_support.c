/* Elementary geometry of one solid cylinder: support function and point, closest point, membership.
 * Support function h(D) = D.C + r sqrt(|D|^2 - (D.W)^2) + (h/2)|D.W| (Eberly, Sec. 3), C the centre,
 * W the unit axis, h the height. */
#include "prox/distance.h"

PROX_API double prox_rcc_support(const prox_rcc *c, prox_vec3 d)
{
    double h = prox_v3_norm(c->axis);
    prox_vec3 w = prox_v3_scale(c->axis, 1.0 / h);
    prox_vec3 ctr = prox_v3_mad(c->base, 0.5, c->axis);
    double dw = prox_v3_dot(d, w);
    double perp = prox_v3_norm(prox_v3_mad(d, -dw, w)); /* |D - (D.W)W|: no cancellation */
    return prox_v3_dot(d, ctr) + c->radius * perp + 0.5 * h * fabs(dw);
}

PROX_API prox_vec3 prox_rcc_support_point(const prox_rcc *c, prox_vec3 d)
{
    double h = prox_v3_norm(c->axis);
    prox_vec3 w = prox_v3_scale(c->axis, 1.0 / h);
    double dw = prox_v3_dot(d, w);
    prox_vec3 p = dw >= 0.0 ? prox_v3_add(c->base, c->axis) : c->base;
    /* Rejected twice: for d nearly along the axis one pass leaves a rounding residual along w that
     * normalisation would blow up, putting the point outside the cylinder. */
    prox_vec3 dp = prox_v3_mad(d, -dw, w);
    dp = prox_v3_mad(dp, -prox_v3_dot(dp, w), w);
    double n = prox_v3_norm(dp);
    if (n > 0.0) p = prox_v3_mad(p, c->radius / n, dp);
    return p;
}

PROX_API prox_vec3 prox_rcc_closest_point(const prox_rcc *c, prox_vec3 x)
{
    double h = prox_v3_norm(c->axis);
    prox_vec3 w = prox_v3_scale(c->axis, 1.0 / h);
    prox_vec3 d = prox_v3_sub(x, c->base);
    double t = prox_v3_dot(d, w);
    prox_vec3 radial = prox_v3_mad(d, -t, w);
    double rho = prox_v3_norm(radial);
    double tc = t < 0.0 ? 0.0 : (t > h ? h : t);
    prox_vec3 p = prox_v3_mad(c->base, tc, w);
    if (rho > c->radius) radial = prox_v3_scale(radial, c->radius / rho);
    if (tc == t && rho <= c->radius) return x;
    return prox_v3_add(p, radial);
}

PROX_API int prox_rcc_contains_point(const prox_rcc *c, prox_vec3 x, double tol)
{
    double h = prox_v3_norm(c->axis);
    prox_vec3 w = prox_v3_scale(c->axis, 1.0 / h);
    prox_vec3 d = prox_v3_sub(x, c->base);
    double t = prox_v3_dot(d, w);
    if (t < -tol || t > h + tol) return 0;
    double rho = prox_v3_norm(prox_v3_mad(d, -t, w));
    return rho <= c->radius + tol;
}

PROX_API double prox_rcc_pair_scale(const prox_rcc *a, const prox_rcc *b)
{
    prox_vec3 ca = prox_v3_mad(a->base, 0.5, a->axis), cb = prox_v3_mad(b->base, 0.5, b->axis);
    double s = prox_v3_dist(ca, cb);
    double v[4] = {prox_v3_norm(a->axis), prox_v3_norm(b->axis), a->radius, b->radius};
    for (int i = 0; i < 4; ++i)
        if (v[i] > s) s = v[i];
    return s;
}
