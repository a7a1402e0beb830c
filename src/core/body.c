/* The generic convex body (core/body.h) and the public support functions of the four macrobodies
 * (prox/support.h) built on it: the scene's bounds and the generic queries' scales use these, so they
 * belong to the core, not to one method. */
#include "core/body.h"

#include <stddef.h>

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

prox_body prox_body_make(const prox_shape *s)
{
    prox_body b = {0};
    switch (s->kind) {
    case PROX_SHAPE_RCC:
        b.kind = PROX_BODY_CYL;
        b.c = prox_rcc_center(&s->u.rcc);
        b.cyl = cyl_centred(&s->u.rcc);
        b.size = fmax(b.cyl.h, 2.0 * b.cyl.r);
        break;
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
    default: {
        double n = prox_v3_norm(d);
        return n > 0.0 ? prox_v3_scale(d, b->r / n) : prox_v3(0, 0, 0);
    }
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
    default: return prox_v3_norm(y) <= b->r + tol;
    }
}

prox_vec3 prox_body_closest(const prox_body *b, prox_vec3 x)
{
    prox_vec3 y = prox_v3_sub(x, b->c);
    switch (b->kind) {
    case PROX_BODY_CYL: y = prox_cyl_closest(&b->cyl, y); break;
    case PROX_BODY_BOX: y = prox_bframe_closest(&b->box, y, NULL); break;
    default: {
        double n = prox_v3_norm(y);
        if (n > b->r) y = prox_v3_scale(y, b->r / n);
        break;
    }
    }
    return prox_v3_add(b->c, y);
}

prox_body prox_body_scaled(const prox_body *b, double f)
{
    prox_body s = *b;
    s.c = prox_v3_scale(b->c, f);
    s.cyl = prox_cyl_scaled(&b->cyl, f);
    for (int k = 0; k < 3; ++k) s.box.h[k] *= f;
    s.r *= f;
    s.size *= f;
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
