/* Circle to circle distance, P(C,C) of Agarwal et al. (2016) Sec. 3.5: the minimum over the
 * stationary angles of prox_circle_circle_stationary (core/circle_circle_stat.c, which derives the
 * degree-8 equation), each point of a with its closest point on b. */
#include "core/poly.h"
#include "distance/prim_common.h"

/* Validates a circle and returns its frame with a unit normal. The normal is scaled by 1 / |n|
 * (not divided as in prox_prim_circle_frame): kept so that results stay bitwise what they were. */
static prox_status cc_check(const prox_circle *c, prox_fcircle *out)
{
    double n;
    prox_status st = prox_prim_circle_check(c, &n);
    if (st != PROX_OK) return st;
    *out = prox_fcircle_make(c->center, prox_v3_scale(c->normal, 1.0 / n), c->radius);
    return PROX_OK;
}

/* The point of b closest to the point of a at angle th, with its angle on b and the distance
 * computed relative to a's centre (so far-from-origin inputs keep their relative accuracy). */
static double cc_partner(const prox_fcircle *a, const prox_fcircle *b, double th, prox_vec3 *q, double *thb,
                         double *rho_out)
{
    prox_vec3 pa = prox_v3_add(prox_v3_scale(a->u, a->r * cos(th)), prox_v3_scale(a->v, a->r * sin(th)));
    prox_vec3 d = prox_v3_sub(pa, prox_v3_sub(b->c, a->c)); /* point of a relative to b's centre */
    double du = prox_v3_dot(d, b->u), dv = prox_v3_dot(d, b->v), dh = prox_v3_dot(d, b->n);
    double rho = prox_hypot2(du, dv);
    *rho_out = rho;
    double cu = rho > 0.0 ? du / rho : 1.0, cv = rho > 0.0 ? dv / rho : 0.0;
    *thb = prox_prim_wrap_2pi(atan2(cv, cu));
    *q = prox_v3_add(b->c, prox_v3_add(prox_v3_scale(b->u, b->r * cu), prox_v3_scale(b->v, b->r * cv)));
    return prox_hypot2(rho - b->r, dh);
}

PROX_API prox_prim_result prox_circle_circle(const prox_circle *a, const prox_circle *b)
{
    prox_prim_result res = {0};
    prox_fcircle fa, fb;
    if ((res.status = cc_check(a, &fa)) != PROX_OK) return res;
    if ((res.status = cc_check(b, &fb)) != PROX_OK) return res;
    double th[8];
    int n = 0;
    int rc = prox_circle_circle_stationary(&fa, &fb, PROX_ROOTS_CHAIN, th, &n);
    if (rc < 0) {
        res.status = (prox_status)(-rc);
        return res;
    }
    double best_th = 0.0, best = INFINITY;
    if (rc == 1) {
        res.set = 1; /* coaxial: every point of a is equidistant from b */
    } else {
        for (int i = 0; i < n; ++i) {
            prox_vec3 q;
            double thb, rho, d = cc_partner(&fa, &fb, th[i], &q, &thb, &rho);
            if (d < best) best = d, best_th = th[i];
        }
    }
    prox_vec3 q;
    double thb, rho;
    res.distance = cc_partner(&fa, &fb, best_th, &q, &thb, &rho);
    /* Closest point of a on b's axis: every point of b is equidistant (degenerate contact). */
    double scale = fmax(fmax(fa.r, fb.r), prox_v3_dist(fa.c, fb.c));
    if (rho <= PROX_TOL_AXIS * scale) res.set = 1;
    res.p1 = prox_fcircle_point(&fa, best_th);
    res.p2 = q;
    res.s1[0] = best_th;
    res.s2[0] = thb;
    res.status = PROX_OK;
    return res;
}
