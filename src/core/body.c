/* The generic convex body (core/body.h) and the public support functions of the four macrobodies
 * (prox/support.h) built on it: the scene's bounds and the generic queries' scales use these, so they
 * belong to the core, not to one method. */
#include "core/body.h"

#include <stddef.h>
#include <string.h>

#include "prox/support.h"

static double sgn(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

/* The cylinder of c centred at the origin: caps at -+hh w, so that its support function is the
 * centred hc exactly. */
static prox_cyl cyl_centred(const prox_rcc *c)
{
    prox_cyl k = prox_cyl_make(c, prox_v3(0, 0, 0));
    k.c = prox_v3(0, 0, 0);
    k.cap[0] = k.b = prox_v3_scale(k.w, -k.hh);
    k.cap[1] = prox_v3_scale(k.w, k.hh);
    return k;
}

void prox_body_make_cyl(const prox_rcc *c, prox_body *b)
{
    memset(b, 0, offsetof(prox_body, x));
    b->kind = PROX_BODY_CYL;
    b->c = prox_rcc_center(c);
    b->cyl = cyl_centred(c);
    b->size = fmax(b->cyl.h, 2.0 * b->cyl.r);
}

prox_body prox_body_of_polytope(const prox_polytope *p, prox_vec3 c)
{
    prox_body b = {0};
    b.kind = PROX_BODY_POLY;
    b.c = c;
    b.x.poly = *p;
    b.size = p->size;
    return b;
}

prox_body prox_body_make(const prox_shape *s)
{
    prox_body b = {0};
    switch (s->kind) {
    case PROX_SHAPE_RCC: prox_body_make_cyl(&s->u.rcc, &b); break;
    case PROX_SHAPE_BOX:
    case PROX_SHAPE_RPP: {
        prox_box bx = s->kind == PROX_SHAPE_BOX ? s->u.box : prox_rpp_to_box(&s->u.rpp);
        b.kind = PROX_BODY_BOX;
        b.box = prox_bframe_make(&bx);
        b.c = b.box.m;
        b.box.m = prox_v3(0, 0, 0);
        b.size = prox_bframe_size(&b.box);
        break;
    }
    case PROX_SHAPE_SPH:
        b.kind = PROX_BODY_SPH;
        b.c = s->u.sph.center;
        b.r = s->u.sph.radius;
        b.size = 2.0 * b.r;
        break;
    case PROX_SHAPE_RHP:
    case PROX_SHAPE_WED:
    case PROX_SHAPE_ARB:
        b.kind = PROX_BODY_POLY;
        b.c = prox_polytope_make(s, &b.x.poly);
        b.size = b.x.poly.size;
        break;
    case PROX_SHAPE_TRC:
        b.kind = PROX_BODY_CONE;
        b.c = prox_cone_make(&s->u.trc, &b.x.cone);
        b.size = fmax(2.0 * b.x.cone.hh, 2.0 * fmax(b.x.cone.r1, b.x.cone.r2));
        break;
    case PROX_SHAPE_REC:
        b.kind = PROX_BODY_ECYL;
        b.c = prox_ecyl_make(&s->u.rec, &b.x.ecyl);
        b.size = fmax(2.0 * b.x.ecyl.hh, 2.0 * b.x.ecyl.a1);
        break;
    case PROX_SHAPE_ELL:
        b.kind = PROX_BODY_ELL;
        b.c = prox_ellb_make(&s->u.ell, &b.x.ell);
        b.size = 2.0 * fmax(b.x.ell.a, b.x.ell.b);
        break;
    default: break;
    }
    return b;
}

prox_vec3 prox_body_pc(const prox_body *b, prox_vec3 d)
{
    switch (b->kind) {
    case PROX_BODY_CYL: return prox_cyl_support_point_c(&b->cyl, d);
    case PROX_BODY_BOX: {
        double l[3];
        for (int k = 0; k < 3; ++k) l[k] = b->box.h[k] * sgn(prox_v3_dot(d, b->box.a[k]));
        return prox_bframe_point(&b->box, l);
    }
    case PROX_BODY_SPH: {
        double n = prox_v3_norm(d);
        return n > 0.0 ? prox_v3_scale(d, b->r / n) : prox_v3(0, 0, 0);
    }
    case PROX_BODY_POLY: return prox_polytope_pc(&b->x.poly, d);
    case PROX_BODY_CONE: return prox_cone_pc(&b->x.cone, d);
    case PROX_BODY_ECYL: return prox_ecyl_pc(&b->x.ecyl, d);
    default: return prox_ellb_pc(&b->x.ell, d);
    }
}

int prox_body_contains(const prox_body *b, prox_vec3 x, double tol)
{
    prox_vec3 y = prox_v3_sub(x, b->c);
    switch (b->kind) {
    case PROX_BODY_CYL: return prox_cyl_contains(&b->cyl, y, tol);
    case PROX_BODY_BOX: {
        double l[3];
        prox_bframe_local(&b->box, y, l);
        for (int k = 0; k < 3; ++k)
            if (fabs(l[k]) > b->box.h[k] + tol) return 0;
        return 1;
    }
    case PROX_BODY_SPH: return prox_v3_norm(y) <= b->r + tol;
    case PROX_BODY_POLY: return prox_polytope_contains(&b->x.poly, y, tol);
    case PROX_BODY_CONE: return prox_cone_contains(&b->x.cone, y, tol);
    case PROX_BODY_ECYL: return prox_ecyl_contains(&b->x.ecyl, y, tol);
    default: return prox_ellb_contains(&b->x.ell, y, tol);
    }
}

static double pair_lower(const prox_body *a, const prox_body *b, prox_vec3 delta, prox_vec3 d)
{
    return -(prox_body_hc(a, d) + prox_body_hc(b, prox_v3_neg(d)) - prox_v3_dot(d, delta));
}

int prox_body_pair_certified(const prox_body *a, const prox_body *b, prox_vec3 delta, double S, prox_vec3 x,
                             prox_vec3 y, const prox_vec3 *nf, double *lower, double *upper, prox_vec3 *n)
{
    prox_vec3 v = prox_v3_sub(y, x);
    double up = prox_v3_norm(v), slack = PROX_TOL_CERT * S;
    if (!(up > PROX_TOL_TOUCH * S)) return 0; /* touching: the direction is rounding */
    prox_vec3 d = prox_v3_scale(v, 1.0 / up);
    double lo = pair_lower(a, b, delta, d);
    /* |y - x| below the lower bound: x and y are not both in the solids (rounding of a support point) */
    if (!(fabs(up - lo) <= slack)) {
        /* the rounding of the points (4 eps S) turns their direction by up to 4 eps S / |y - x|, which
         * costs at most the support sets' extent 2 S times that at a kink: more is no rounding */
        if (!nf || !(up - lo <= slack * (1.0 + 2.0 * S / up))) return 0;
        if (!(prox_v3_norm(prox_v3_sub(v, prox_v3_scale(*nf, up))) <= slack)) return 0;
        d = *nf, lo = pair_lower(a, b, delta, d);
        if (!(fabs(up - lo) <= slack)) return 0;
    }
    double tol = PROX_TOL_TOUCH * S;
    if (!prox_body_contains(a, x, tol) || !prox_body_contains(b, y, tol)) return 0;
    *lower = lo, *upper = up, *n = d;
    return 1;
}

prox_vec3 prox_body_closest(const prox_body *b, prox_vec3 x)
{
    prox_vec3 y = prox_v3_sub(x, b->c);
    switch (b->kind) {
    case PROX_BODY_CYL: y = prox_cyl_closest(&b->cyl, y); break;
    case PROX_BODY_BOX: y = prox_bframe_closest(&b->box, y, NULL); break;
    case PROX_BODY_SPH: {
        double n = prox_v3_norm(y);
        if (n > b->r) y = prox_v3_scale(y, b->r / n);
        break;
    }
    case PROX_BODY_POLY: y = prox_polytope_closest(&b->x.poly, y); break;
    case PROX_BODY_CONE: y = prox_cone_closest(&b->x.cone, y); break;
    case PROX_BODY_ECYL: y = prox_ecyl_closest(&b->x.ecyl, y); break;
    default: y = prox_ellb_closest(&b->x.ell, y); break;
    }
    return prox_v3_add(b->c, y);
}

prox_vec3 prox_body_closest_warm(const prox_body *b, prox_vec3 x, double *warm)
{
    if (b->kind != PROX_BODY_ELL) return prox_body_closest(b, x);
    return prox_v3_add(b->c, prox_ellb_closest_warm(&b->x.ell, prox_v3_sub(x, b->c), warm));
}

/* A unit vector perpendicular to the unit vector w. */
static prox_vec3 any_perp(prox_vec3 w)
{
    prox_vec3 a = fabs(w.x) < 0.6 ? prox_v3(1, 0, 0) : prox_v3(0, 1, 0);
    prox_vec3 p = prox_v3_mad(a, -prox_v3_dot(a, w), w);
    return prox_v3_scale(p, 1.0 / prox_v3_norm(p));
}

/* Boundary of a cylinder from inside: the nearer of the side (r - rho) and the nearer cap (hh - |t|). */
static double cyl_boundary(const prox_cyl *k, prox_vec3 y, prox_vec3 *q)
{
    prox_vec3 x = prox_cyl_closest(k, y);
    prox_vec3 dx = prox_v3_sub(y, x);
    double out = prox_v3_norm(dx);
    if (out > 0.0) {
        *q = x;
        return out;
    }
    double t = prox_v3_dot(y, k->w);
    prox_vec3 perp = prox_v3_mad(y, -t, k->w);
    double rho = prox_v3_norm(perp);
    double side = k->r - rho, cap = k->hh - fabs(t);
    if (side <= cap) {
        prox_vec3 u = rho > 0.0 ? prox_v3_scale(perp, 1.0 / rho) : any_perp(k->w);
        *q = prox_v3_mad(prox_v3_scale(k->w, t), k->r, u);
        return -side;
    }
    *q = prox_v3_mad(perp, t >= 0.0 ? k->hh : -k->hh, k->w);
    return -cap;
}

/* Boundary of a box from inside: the nearest face. */
static double box_boundary(const prox_bframe *f, prox_vec3 y, prox_vec3 *q)
{
    prox_vec3 x = prox_bframe_closest(f, y, NULL);
    double out = prox_v3_norm(prox_v3_sub(y, x));
    if (out > 0.0) {
        *q = x;
        return out;
    }
    double l[3];
    prox_bframe_local(f, y, l);
    int kmin = 0;
    double gap = f->h[0] - fabs(l[0]);
    for (int k = 1; k < 3; ++k)
        if (f->h[k] - fabs(l[k]) < gap) gap = f->h[k] - fabs(l[k]), kmin = k;
    l[kmin] = l[kmin] >= 0.0 ? f->h[kmin] : -f->h[kmin];
    *q = prox_bframe_point(f, l);
    return -gap;
}

double prox_body_boundary(const prox_body *b, prox_vec3 x, prox_vec3 *q)
{
    prox_vec3 y = prox_v3_sub(x, b->c), qc;
    double s;
    switch (b->kind) {
    case PROX_BODY_CYL: s = cyl_boundary(&b->cyl, y, &qc); break;
    case PROX_BODY_BOX: s = box_boundary(&b->box, y, &qc); break;
    case PROX_BODY_SPH: {
        double n = prox_v3_norm(y);
        qc = n > 0.0 ? prox_v3_scale(y, b->r / n) : prox_v3(b->r, 0, 0);
        s = n - b->r;
        break;
    }
    case PROX_BODY_POLY: s = prox_polytope_boundary(&b->x.poly, y, &qc); break;
    case PROX_BODY_CONE: s = prox_cone_boundary(&b->x.cone, y, &qc); break;
    case PROX_BODY_ECYL: s = prox_ecyl_boundary(&b->x.ecyl, y, &qc); break;
    default: s = prox_ellb_boundary(&b->x.ell, y, &qc); break;
    }
    *q = prox_v3_add(b->c, qc);
    return s;
}

void prox_body_scaled_at(prox_body *s, const prox_body *b, prox_vec3 c, double f)
{
    memcpy(s, b, offsetof(prox_body, x)); /* the common part, then the union's member of b's kind alone */
    switch (b->kind) {
    case PROX_BODY_POLY: s->x.poly = b->x.poly; break;
    case PROX_BODY_CONE: s->x.cone = b->x.cone; break;
    case PROX_BODY_ECYL: s->x.ecyl = b->x.ecyl; break;
    case PROX_BODY_ELL: s->x.ell = b->x.ell; break;
    default: break;
    }
    s->c = prox_v3_scale(c, f);
    s->cyl = prox_cyl_scaled(&b->cyl, f);
    for (int k = 0; k < 3; ++k) s->box.h[k] *= f;
    s->r *= f;
    switch (b->kind) {
    case PROX_BODY_POLY:
        for (int i = 0; i < b->x.poly.nv; ++i) s->x.poly.v[i] = prox_v3_scale(b->x.poly.v[i], f);
        for (int i = 0; i < b->x.poly.nf; ++i) s->x.poly.d[i] *= f;
        s->x.poly.size *= f;
        s->x.poly.lo = prox_v3_scale(b->x.poly.lo, f), s->x.poly.hi = prox_v3_scale(b->x.poly.hi, f); /* f > 0 */
        break;
    case PROX_BODY_CONE: s->x.cone.hh *= f, s->x.cone.r1 *= f, s->x.cone.r2 *= f; break;
    case PROX_BODY_ECYL: s->x.ecyl.hh *= f, s->x.ecyl.a1 *= f, s->x.ecyl.a2 *= f; break;
    case PROX_BODY_ELL: s->x.ell.a *= f, s->x.ell.b *= f; break;
    default: break;
    }
    s->size *= f;
}

prox_body prox_body_scaled(const prox_body *b, double f)
{
    prox_body s;
    prox_body_scaled_at(&s, b, b->c, f);
    return s;
}

double prox_unit_scale(double S)
{
    return S > 0.0 && isfinite(S) ? ldexp(1.0, -ilogb(S)) : 1.0;
}

/* ---- public (prox/support.h): the shape is not validated here (hot path) ---- */

PROX_API double prox_shape_support(const prox_shape *s, prox_vec3 d)
{
    prox_body b = prox_body_make(s);
    return prox_body_support(&b, d);
}

PROX_API prox_vec3 prox_shape_support_point(const prox_shape *s, prox_vec3 d)
{
    prox_body b = prox_body_make(s);
    return prox_body_support_point(&b, d);
}

PROX_API prox_vec3 prox_shape_center(const prox_shape *s) { return prox_body_make(s).c; }

PROX_API double prox_shape_size(const prox_shape *s) { return prox_body_make(s).size; }
