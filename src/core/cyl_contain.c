/* Containment of circles and cylinders in a solid cylinder (core/cyl.h): the one implementation that
 * the RCC-RCC query (Agarwal Fig. 2, nesting) and the containment queries share.
 * A cylinder A lies in the convex solid B iff both rims of A do (A is the convex hull of its rims).
 * A circle (centre c, unit normal n, radius r) lies in the solid cylinder k iff
 *  - axially: its heights over k's base, tc +- r |n x w|, lie in [0, h];
 *  - radially: its farthest point from k's axis is within k's radius. Projected along w the circle
 *    is an ellipse of semi-axes r and r |n.w| centred rho_c from the axis, so it reaches at most
 *    rho_c + r and at least max(rho_c, r) (quick accept and reject); in between, the farthest point of
 *    that ellipse (prox_circle_line_max_dist: one bracketed monotone root) decides. */
#include "core/cyl.h"

double prox_cyl_circle_clearance(const prox_cyl *k, prox_vec3 c, prox_vec3 n, double r)
{
    double tc = prox_v3_dot(prox_v3_sub(c, k->b), k->w);
    double half = r * prox_v3_norm(prox_v3_cross(n, k->w));
    double axial = fmin(tc - half, k->h - tc - half);
    return fmin(axial, k->r - prox_circle_line_max_dist(c, n, r, k->b, k->w));
}

int prox_cyl_contains_circle(const prox_cyl *k, prox_vec3 c, prox_vec3 n, double r, double tol)
{
    prox_vec3 dc = prox_v3_sub(c, k->b);
    double tc = prox_v3_dot(dc, k->w);
    double half = r * prox_v3_norm(prox_v3_cross(n, k->w));
    if (tc - half < -tol || tc + half > k->h + tol) return 0;
    prox_vec3 radial = prox_v3_mad(dc, -tc, k->w);
    double rho_c = prox_v3_norm(radial);
    if (rho_c + r <= k->r + tol) return 1;
    if (fmax(rho_c, r) > k->r + tol) return 0;
    /* Support function along the radial direction m of the centre (perpendicular to k's axis): the
     * circle reaches rho_c + r |m x n| from the axis there; beyond k's radius it is not inside. */
    if (rho_c > 0.0 && rho_c + r * prox_v3_norm(prox_v3_cross(prox_v3_scale(radial, 1.0 / rho_c), n)) > k->r + tol)
        return 0;
    return prox_circle_line_max_dist(c, n, r, k->b, k->w) <= k->r + tol;
}

int prox_cyl_in_cyl(const prox_cyl *in, const prox_cyl *out, double tol)
{
    /* a nested cylinder contains the other's centre: the cheapest rejection */
    return prox_cyl_contains(out, in->c, tol) && prox_cyl_contains_circle(out, in->cap[0], in->w, in->r, tol) &&
           prox_cyl_contains_circle(out, in->cap[1], in->w, in->r, tol);
}

double prox_cyl_in_cyl_clearance(const prox_cyl *in, const prox_cyl *out)
{
    return fmin(prox_cyl_circle_clearance(out, in->cap[0], in->w, in->r),
                prox_cyl_circle_clearance(out, in->cap[1], in->w, in->r));
}
