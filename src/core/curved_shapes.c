/* Validators and card-form constructors of the curved macrobodies TRC, REC and ELL (prox/shapes.h).
 * The MCNP card entries and what is accepted are in docs/algorithms/curved.md. Checks run in the
 * order of src/core/shapes.c: non-finite data, then the named fault, then the supported range. */
#include "prox/shapes.h"

static int coord_ok(double x) { return fabs(x) <= PROX_MAX_COORD; }
static int coord3_ok(prox_vec3 v) { return coord_ok(v.x) & coord_ok(v.y) & coord_ok(v.z); }
static int size_ok(double s) { return (s >= PROX_MIN_SIZE) & (s <= PROX_MAX_COORD); }
/* Within the supported aspect ratio (shapes.h): the smallest dimension at least 1/PROX_MAX_ASPECT of the
 * largest. */
static int aspect_ok(double lo, double hi) { return lo * PROX_MAX_ASPECT >= hi; }

/* A TRC is a frustum (r1, r2 > 0, either larger) or a full cone (one radius 0, the apex); equal
 * radii are an RCC and both zero a segment: PROX_EINVAL_TRC. */
PROX_API prox_status prox_trc_validate(const prox_trc *t)
{
    if (!t) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(t->base) || !prox_v3_isfinite(t->axis) || !isfinite(t->r1) || !isfinite(t->r2))
        return PROX_EINVAL_NONFINITE;
    if (!coord3_ok(t->base) || !coord3_ok(t->axis)) return PROX_EINVAL_RANGE;
    double h = prox_v3_norm(t->axis);
    if (!(h > 0.0)) return PROX_EINVAL_AXIS;
    if (t->r1 < 0.0 || t->r2 < 0.0 || t->r1 == t->r2) return PROX_EINVAL_TRC;
    if (!size_ok(h)) return PROX_EINVAL_RANGE;
    if ((t->r1 > 0.0 && !size_ok(t->r1)) || (t->r2 > 0.0 && !size_ok(t->r2))) return PROX_EINVAL_RANGE;
    double rm = fmax(t->r1, t->r2);
    if (!aspect_ok(fmin(h, rm), fmax(h, rm))) return PROX_EINVAL_RANGE;
    return PROX_OK;
}

/* |u . v| <= PROX_BOX_ORTHO_TOL |u| |v|, on unit vectors so that no product overflows. */
static int ortho(prox_vec3 u, double lu, prox_vec3 v, double lv)
{
    return fabs(prox_v3_dot(prox_v3_scale(u, 1.0 / lu), prox_v3_scale(v, 1.0 / lv))) <= PROX_BOX_ORTHO_TOL;
}

PROX_API prox_status prox_rec_validate(const prox_rec *r)
{
    if (!r) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(r->base) || !prox_v3_isfinite(r->axis) || !prox_v3_isfinite(r->a1) ||
        !prox_v3_isfinite(r->a2))
        return PROX_EINVAL_NONFINITE;
    if (!coord3_ok(r->base) || !coord3_ok(r->axis) || !coord3_ok(r->a1) || !coord3_ok(r->a2))
        return PROX_EINVAL_RANGE;
    double h = prox_v3_norm(r->axis), l1 = prox_v3_norm(r->a1), l2 = prox_v3_norm(r->a2);
    if (!(h > 0.0)) return PROX_EINVAL_AXIS;
    if (!(l1 > 0.0) || !(l2 > 0.0)) return PROX_EINVAL_RADIUS;
    if (!ortho(r->axis, h, r->a1, l1) || !ortho(r->axis, h, r->a2, l2) || !ortho(r->a1, l1, r->a2, l2))
        return PROX_EINVAL_REC_ORTHO;
    if (!size_ok(h) || !size_ok(l1) || !size_ok(l2)) return PROX_EINVAL_RANGE;
    if (!aspect_ok(fmin(h, fmin(l1, l2)), fmax(h, fmax(l1, l2)))) return PROX_EINVAL_RANGE;
    return PROX_OK;
}

PROX_API prox_status prox_ell_validate(const prox_ell *e)
{
    if (!e) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(e->center) || !prox_v3_isfinite(e->axis) || !isfinite(e->radius))
        return PROX_EINVAL_NONFINITE;
    if (!(e->radius > 0.0)) return PROX_EINVAL_RADIUS;
    if (!coord3_ok(e->center) || !coord3_ok(e->axis)) return PROX_EINVAL_RANGE;
    double a = prox_v3_norm(e->axis);
    if (!(a > 0.0)) return PROX_EINVAL_AXIS;
    if (!size_ok(a) || !size_ok(e->radius)) return PROX_EINVAL_RANGE;
    if (!aspect_ok(fmin(a, e->radius), fmax(a, e->radius))) return PROX_EINVAL_RANGE;
    return PROX_OK;
}

/* REC of 10 entries: the minor semi-axis r2 along axis x a1 (MCNP: perpendicular to both). */
PROX_API prox_status prox_rec_from_radius(prox_vec3 base, prox_vec3 axis, prox_vec3 a1, double r2, prox_rec *out)
{
    if (!out) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(base) || !prox_v3_isfinite(axis) || !prox_v3_isfinite(a1) || !isfinite(r2))
        return PROX_EINVAL_NONFINITE;
    if (!(r2 > 0.0)) return PROX_EINVAL_RADIUS;
    if (!coord3_ok(base) || !coord3_ok(axis) || !coord3_ok(a1)) return PROX_EINVAL_RANGE;
    double h = prox_v3_norm(axis), l1 = prox_v3_norm(a1);
    if (!(h > 0.0)) return PROX_EINVAL_AXIS;
    if (!(l1 > 0.0)) return PROX_EINVAL_RADIUS;
    prox_vec3 n = prox_v3_cross(prox_v3_scale(axis, 1.0 / h), prox_v3_scale(a1, 1.0 / l1));
    double ln = prox_v3_norm(n);
    if (!(ln > 0.0)) return PROX_EINVAL_REC_ORTHO;
    out->base = base;
    out->axis = axis;
    out->a1 = a1;
    out->a2 = prox_v3_scale(n, r2 / ln);
    return prox_rec_validate(out);
}

/* ELL of the card's R > 0 form: foci f1, f2 and major radius rm: centre (f1 + f2) / 2, the axis of
 * revolution along f2 - f1 with semi-axis rm, equatorial radius sqrt(rm^2 - c^2), c = |f2 - f1| / 2.
 * Coincident foci give a sphere (axis taken along z). */
PROX_API prox_status prox_ell_from_foci(prox_vec3 f1, prox_vec3 f2, double rm, prox_ell *out)
{
    if (!out) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(f1) || !prox_v3_isfinite(f2) || !isfinite(rm)) return PROX_EINVAL_NONFINITE;
    if (!(rm > 0.0)) return PROX_EINVAL_RADIUS;
    if (!coord3_ok(f1) || !coord3_ok(f2)) return PROX_EINVAL_RANGE;
    prox_vec3 half = prox_v3_scale(prox_v3_sub(f2, f1), 0.5);
    double c = prox_v3_norm(half);
    if (!(rm > c)) return PROX_EINVAL_ELL;
    prox_vec3 dir = c > 0.0 ? prox_v3_scale(half, 1.0 / c) : prox_v3(0, 0, 1);
    out->center = prox_v3_add(f1, half);
    out->axis = prox_v3_scale(dir, rm);
    out->radius = sqrt((rm - c) * (rm + c));
    return prox_ell_validate(out);
}

/* ELL of the card's R < 0 form: centre, major semi-axis vector and minor radius |R| (passed > 0). */
PROX_API prox_status prox_ell_from_axis(prox_vec3 center, prox_vec3 major, double rminor, prox_ell *out)
{
    if (!out) return PROX_EINVAL_ARG;
    out->center = center;
    out->axis = major;
    out->radius = rminor;
    return prox_ell_validate(out);
}
