/* Shape validators (called at every public entry point) and generic-shape constructors. */
#include "core/validate.h"
#include "prox/shapes.h"

static int finite3(prox_vec3 v) { return prox_v3_isfinite(v); }
/* Inside the supported range (shapes.h). */
static int coord_ok(double x) { return fabs(x) <= PROX_MAX_COORD; }
static int coord3_ok(prox_vec3 v) { return coord_ok(v.x) & coord_ok(v.y) & coord_ok(v.z); }
static int size_ok(double s) { return (s >= PROX_MIN_SIZE) & (s <= PROX_MAX_COORD); }

prox_status prox_rcc_validate_h2(const prox_rcc *c, double *h2)
{
    *h2 = 0.0;
    if (!c) return PROX_EINVAL_ARG;
    /* One branch-free pass accepts a valid cylinder with no square root: the range test also fails
     * NaN and infinities, and the squared height is tested strictly inside the size range (by 1e-7
     * relative, so that rounding of the squares cannot accept a height just outside it).  Anything
     * else goes through the ordered checks below, which name the fault or accept a cylinder at the
     * very ends of the range exactly as |axis| would. */
    double hh2 = prox_v3_norm2(c->axis);
    const double lo = (1.0 + 1e-7) * PROX_MIN_SIZE * PROX_MIN_SIZE;
    const double hi = (1.0 - 1e-7) * PROX_MAX_COORD * PROX_MAX_COORD;
    if (coord3_ok(c->base) & coord3_ok(c->axis) & size_ok(c->radius) & (hh2 > lo) & (hh2 < hi)) {
        *h2 = hh2;
        return PROX_OK;
    }
    if (!finite3(c->base) || !finite3(c->axis) || !isfinite(c->radius)) return PROX_EINVAL_NONFINITE;
    if (!(c->radius > 0.0)) return PROX_EINVAL_RADIUS;
    if (!coord3_ok(c->base) || !coord3_ok(c->axis)) return PROX_EINVAL_RANGE;
    double hh = prox_v3_norm(c->axis);
    if (!(hh > 0.0)) return PROX_EINVAL_AXIS;
    if (!size_ok(c->radius) || !size_ok(hh)) return PROX_EINVAL_RANGE;
    *h2 = hh * hh; /* inside the range at its very ends */
    return PROX_OK;
}

PROX_API prox_status prox_rcc_validate(const prox_rcc *c)
{
    double h2;
    return prox_rcc_validate_h2(c, &h2);
}

/* The careful validator's OK at the cost of a few products (the hot path of every box query): every
 * edge's squared length well inside the supported range, where the orthogonality test
 * |e_i.e_j| <= tol |e_i| |e_j| can be squared (with 2 % to spare for its rounding). A box it does not
 * accept (NaN, infinite, near a limit, near the tolerance) goes to box_validate_careful, which names
 * the fault. */
static int box_plainly_valid(const prox_box *b)
{
    double ee[3];
    int ok = fabs(b->corner.x) <= PROX_MAX_COORD && fabs(b->corner.y) <= PROX_MAX_COORD &&
             fabs(b->corner.z) <= PROX_MAX_COORD;
    for (int k = 0; k < 3; ++k) {
        ee[k] = prox_v3_norm2(b->edge[k]);
        ok &= ee[k] >= 1e-140 && ee[k] <= 1e140;
    }
    for (int i = 0; ok && i < 3; ++i) {
        int j = (i + 1) % 3;
        double c = prox_v3_dot(b->edge[i], b->edge[j]), lim = PROX_BOX_ORTHO_TOL * PROX_BOX_ORTHO_TOL * ee[i] * ee[j];
        ok &= c * c <= 0.98 * lim;
    }
    return ok;
}

static prox_status box_validate_careful(const prox_box *b);

PROX_API prox_status prox_box_validate(const prox_box *b)
{
    if (!b) return PROX_EINVAL_ARG;
    return box_plainly_valid(b) ? PROX_OK : box_validate_careful(b);
}

static prox_status box_validate_careful(const prox_box *b)
{
    if (!finite3(b->corner)) return PROX_EINVAL_NONFINITE;
    double len[3];
    for (int i = 0; i < 3; ++i)
        if (!finite3(b->edge[i])) return PROX_EINVAL_NONFINITE;
    if (!coord3_ok(b->corner)) return PROX_EINVAL_RANGE;
    for (int i = 0; i < 3; ++i) {
        if (!coord3_ok(b->edge[i])) return PROX_EINVAL_RANGE;
        len[i] = prox_v3_norm(b->edge[i]);
        if (!(len[i] > 0.0)) return PROX_EINVAL_BOX_EDGE;
        if (!size_ok(len[i])) return PROX_EINVAL_RANGE;
    }
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        /* Relative test on unit vectors so that the product cannot overflow. */
        prox_vec3 ui = prox_v3_scale(b->edge[i], 1.0 / len[i]);
        prox_vec3 uj = prox_v3_scale(b->edge[j], 1.0 / len[j]);
        if (fabs(prox_v3_dot(ui, uj)) > PROX_BOX_ORTHO_TOL) return PROX_EINVAL_BOX_ORTHO;
    }
    return PROX_OK;
}

PROX_API prox_status prox_rpp_validate(const prox_rpp *r)
{
    if (!r) return PROX_EINVAL_ARG;
    const double v[6] = {r->xmin, r->xmax, r->ymin, r->ymax, r->zmin, r->zmax};
    for (int i = 0; i < 6; ++i)
        if (!isfinite(v[i])) return PROX_EINVAL_NONFINITE;
    for (int i = 0; i < 3; ++i)
        if (!(v[2 * i] < v[2 * i + 1])) return PROX_EINVAL_RPP_BOUNDS;
    for (int i = 0; i < 6; ++i)
        if (!coord_ok(v[i])) return PROX_EINVAL_RANGE;
    for (int i = 0; i < 3; ++i)
        if (!size_ok(v[2 * i + 1] - v[2 * i])) return PROX_EINVAL_RANGE;
    return PROX_OK;
}

PROX_API prox_status prox_sph_validate(const prox_sph *s)
{
    if (!s) return PROX_EINVAL_ARG;
    /* One branch-free pass accepts a valid sphere (the range tests also fail NaN and infinities);
     * anything else goes through the ordered checks, which name the fault. */
    if (coord3_ok(s->center) & size_ok(s->radius)) return PROX_OK;
    if (!finite3(s->center) || !isfinite(s->radius)) return PROX_EINVAL_NONFINITE;
    if (!(s->radius > 0.0)) return PROX_EINVAL_RADIUS;
    if (!coord3_ok(s->center) || !size_ok(s->radius)) return PROX_EINVAL_RANGE;
    return PROX_OK;
}

PROX_API prox_status prox_shape_validate(const prox_shape *s)
{
    if (!s) return PROX_EINVAL_ARG;
    switch (s->kind) {
    case PROX_SHAPE_RCC: return prox_rcc_validate(&s->u.rcc);
    case PROX_SHAPE_BOX: return prox_box_validate(&s->u.box);
    case PROX_SHAPE_RPP: return prox_rpp_validate(&s->u.rpp);
    case PROX_SHAPE_SPH: return prox_sph_validate(&s->u.sph);
    case PROX_SHAPE_TRC: return prox_trc_validate(&s->u.trc);
    case PROX_SHAPE_REC: return prox_rec_validate(&s->u.rec);
    case PROX_SHAPE_ELL: return prox_ell_validate(&s->u.ell);
    case PROX_SHAPE_RHP: return prox_rhp_validate(&s->u.rhp);
    case PROX_SHAPE_WED: return prox_wed_validate(&s->u.wed);
    case PROX_SHAPE_ARB: return prox_arb_validate(&s->u.arb);
    default: break;
    }
    return PROX_EINVAL_SHAPE_KIND;
}

PROX_API prox_box prox_rpp_to_box(const prox_rpp *r)
{
    prox_box b;
    b.corner = prox_v3(r->xmin, r->ymin, r->zmin);
    b.edge[0] = prox_v3(r->xmax - r->xmin, 0, 0);
    b.edge[1] = prox_v3(0, r->ymax - r->ymin, 0);
    b.edge[2] = prox_v3(0, 0, r->zmax - r->zmin);
    return b;
}

PROX_API prox_shape prox_shape_from_rcc(prox_rcc c)
{
    prox_shape s = {.kind = PROX_SHAPE_RCC, .u.rcc = c};
    return s;
}
PROX_API prox_shape prox_shape_from_box(prox_box b)
{
    prox_shape s = {.kind = PROX_SHAPE_BOX, .u.box = b};
    return s;
}
PROX_API prox_shape prox_shape_from_rpp(prox_rpp r)
{
    prox_shape s = {.kind = PROX_SHAPE_RPP, .u.rpp = r};
    return s;
}
PROX_API prox_shape prox_shape_from_sph(prox_sph s0)
{
    prox_shape s = {.kind = PROX_SHAPE_SPH, .u.sph = s0};
    return s;
}

#define SHAPE_FROM(name, type, kind_tag)                          \
    PROX_API prox_shape prox_shape_from_##name(type v)            \
    {                                                             \
        prox_shape s = {.kind = kind_tag, .u.name = v};           \
        return s;                                                 \
    }
SHAPE_FROM(trc, prox_trc, PROX_SHAPE_TRC)
SHAPE_FROM(rec, prox_rec, PROX_SHAPE_REC)
SHAPE_FROM(ell, prox_ell, PROX_SHAPE_ELL)
SHAPE_FROM(rhp, prox_rhp, PROX_SHAPE_RHP)
SHAPE_FROM(wed, prox_wed, PROX_SHAPE_WED)
SHAPE_FROM(arb, prox_arb, PROX_SHAPE_ARB)

PROX_API const char *prox_shape_kind_name(prox_shape_kind k)
{
    static const char *const names[PROX_SHAPE_KIND_COUNT_] = {"RCC", "BOX", "RPP", "SPH", "TRC",
                                                              "REC", "ELL", "RHP", "WED", "ARB"};
    return (unsigned)k < PROX_SHAPE_KIND_COUNT_ ? names[k] : "?";
}
