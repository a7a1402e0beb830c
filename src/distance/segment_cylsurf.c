/* Segment to infinite cylindrical surface. Agarwal et al. (2016) Sec. 3.1 parameterise the surface as
 * base + z w + r (cos th u + sin th v); for a fixed segment point x the conditions f_z = f_th = 0 give
 * z = (x - base).w and th = the angle of x's radial component, so the distance of x from the surface is
 * |rho(x) - r| with rho the distance from the axis. Along the segment rho(t) = |g0 + t g1| (g0, g1 the
 * radial parts of a - base and b - a) is convex, hence:
 *  - min rho >= r: the segment is outside; distance = min rho - r at the clamped foot t0 on the axis;
 *  - max rho <= r: the segment is inside; distance = r - max rho at the farther endpoint;
 *  - otherwise the segment crosses the surface: distance 0 at the first t with rho(t) = r, from the
 *    quadratic |g1|^2 tau^2 + 2 (g.g1) tau + (rho_min^2 - r^2) = 0 about t0 (stable root formula).
 * set = 1 when the segment (positive length) is parallel to the axis (rho constant) or the closest
 * segment point lies on the axis (every angle equidistant).
 * Parameters: s1[0] = t on the segment; s2[0] = axial parameter z (length units), s2[1] = angle in the
 * frame of prox_fcircle_make(base, w, r). Input: radius > 0, dir finite non-zero (normalised); height is
 * ignored (not validated). */
#include "distance/prim_common.h"

/* Validates the segment and the (infinite) surface; returns the unit axis in *w. */
static prox_status check_input(const prox_segment *a, const prox_cylsurf *s, prox_vec3 *w)
{
    if (!a || !s) return PROX_EINVAL_ARG;
    prox_status st = prox_prim_segment_check(a);
    if (st != PROX_OK) return st;
    return prox_prim_cylsurf_check(s, 0, w);
}

/* First t in [0, 1] where rho(t) = r, given the foot t0 with rho(t0) = rho0 < r, g = g0 + t0 g1. */
static double crossing_param(prox_vec3 g, prox_vec3 g1, double t0, double rho0, double r)
{
    double A = prox_v3_norm2(g1), B = prox_v3_dot(g, g1), C = -(r - rho0) * (r + rho0);
    double disc = sqrt(B * B - A * C); /* A C < 0: real */
    double q = -(B + (B >= 0.0 ? disc : -disc));
    double tau[2] = {q / A, C / q}, best = 2.0;
    for (int i = 0; i < 2; ++i) {
        double t = t0 + tau[i];
        if (!(t >= -PROX_TOL_PARAM && t <= 1.0 + PROX_TOL_PARAM)) continue; /* endpoint up to rounding */
        t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
        if (t < best) best = t;
    }
    return best <= 1.0 ? best : t0; /* cannot happen for rho(0) or rho(1) > r; keep t0 then */
}

/* Fills the surface point closest to x (radial projection); sets *on_axis when x is on the axis. */
static void surface_point(const prox_fcircle *f, prox_vec3 x, prox_prim_result *res, int *on_axis)
{
    prox_prim_local l = prox_prim_local_of(f, x);
    double cu = 1.0, cv = 0.0;
    *on_axis = !(l.rho > 0.0);
    if (!*on_axis) {
        cu = l.du / l.rho;
        cv = l.dv / l.rho;
    }
    res->p2 = prox_v3_add(prox_v3_mad(f->c, l.h, f->n), prox_v3_add(prox_v3_scale(f->u, f->r * cu), prox_v3_scale(f->v, f->r * cv)));
    res->s2[0] = l.h;
    res->s2[1] = prox_prim_local_angle(&l);
}

PROX_API prox_prim_result prox_segment_cylsurf_inf(const prox_segment *a, const prox_cylsurf *s)
{
    prox_prim_result res = {0};
    prox_vec3 w;
    if ((res.status = check_input(a, s, &w)) != PROX_OK) return res;
    prox_fcircle f = prox_fcircle_make(s->base, w, s->radius);
    prox_vec3 d = prox_v3_sub(a->b, a->a);
    prox_vec3 g0 = prox_v3_reject(prox_v3_sub(a->a, f.c), w), g1 = prox_v3_reject(d, w);
    double A = prox_v3_norm2(g1);
    double t0 = prox_prim_clamp01(A > 0.0 ? -prox_v3_dot(g0, g1) / A : 0.0); /* foot on the axis */
    prox_vec3 g = prox_v3_mad(g0, t0, g1);
    double rho0 = prox_v3_norm(g), rhoa = prox_v3_norm(g0), rhob = prox_v3_norm(prox_v3_add(g0, g1));
    double t, dist;
    if (rho0 >= f.r) { /* outside */
        t = t0;
        dist = rho0 - f.r;
    } else if (rhoa <= f.r && rhob <= f.r) { /* inside: the endpoint farther from the axis */
        t = rhob > rhoa ? 1.0 : 0.0;
        dist = f.r - (rhob > rhoa ? rhob : rhoa);
    } else {
        t = crossing_param(g, g1, t0, rho0, f.r);
        dist = 0.0;
    }
    res.p1 = prox_prim_segment_point(a, t);
    res.s1[0] = t;
    int on_axis;
    surface_point(&f, res.p1, &res, &on_axis);
    double len = prox_v3_norm(d);
    res.set = on_axis || (len > 0.0 && sqrt(A) <= PROX_TOL_PARALLEL * len);
    res.distance = dist;
    res.status = PROX_OK;
    return res;
}
