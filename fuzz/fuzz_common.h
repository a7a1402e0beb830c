/* Shared prologue of the libFuzzer harnesses (fuzz_deck.c, fuzz_pairs.c, fuzz_queries.c): the libFuzzer
 * entry-point prototypes, the one-time initialisation, and the shape builder of the two binary harnesses
 * (fuzz_queries.c, fuzz_pairs.c): raw IEEE doubles -> one of the ten macrobodies. Included by exactly one
 * translation unit per harness binary (run.sh links each harness separately), so the non-static
 * definition below is unique. */
#ifndef PROX_FUZZ_COMMON_H
#define PROX_FUZZ_COMMON_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <gsl/gsl_errno.h>

#include "prox/prox.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

/* Like the prox tool, tests and bench: GSL's default handler aborts, prox reports statuses. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    gsl_set_error_handler_off();
    return 0;
}

/* Doubles one shape reads at most (an ARB: eight corners and six face numbers). */
#define FZ_SHAPE_DOUBLES 30

/* The k-th double of the payload (zero beyond the end). */
static inline double fz_get(const uint8_t *p, size_t n, size_t k)
{
    double x = 0.0;
    if (8 * k + 8 <= n) memcpy(&x, p + 8 * k, 8);
    return x;
}

static inline prox_vec3 fz_get3(const uint8_t *p, size_t n, size_t k)
{
    return prox_v3(fz_get(p, n, k), fz_get(p, n, k + 1), fz_get(p, n, k + 2));
}

/* Largest magnitude among doubles [0, count) of the payload (NaN propagates). */
static inline double fz_max_abs(const uint8_t *p, size_t n, size_t count)
{
    double m = 0.0;
    for (size_t k = 0; k < count; ++k) {
        double x = fabs(fz_get(p, n, k));
        if (!(x <= m)) m = x;
    }
    return m;
}

/* v without its component along axis (v itself when axis is zero or not finite): a vector the
 * validators accept as perpendicular, so that the constructed variants reach the solvers. */
static inline prox_vec3 fz_perp(prox_vec3 v, prox_vec3 axis)
{
    double l = prox_v3_norm(axis);
    if (!(l > 0.0) || !isfinite(l)) return v;
    prox_vec3 u = prox_v3_scale(axis, 1.0 / l);
    return prox_v3_sub(v, prox_v3_scale(u, prox_v3_dot(v, u)));
}

/* s scaled to length h along the direction of v (v itself when it has no direction). */
static inline prox_vec3 fz_along(prox_vec3 v, double h)
{
    double l = prox_v3_norm(v);
    return l > 0.0 && isfinite(l) ? prox_v3_scale(v, h / l) : v;
}

/* An ARB face number from a double (-1, which the validator names, when it is not a whole number). */
static inline int fz_face(double x)
{
    return x >= 0.0 && x <= 9999.0 && x == floor(x) ? (int)x : -1;
}

/* An ARB made of the corners c[0..7] and the faces (unused corners stay zero). */
static inline prox_shape fz_arb(const prox_vec3 c[8], const int face[6])
{
    prox_arb a;
    for (int i = 0; i < 8; ++i) a.corner[i] = c[i];
    for (int f = 0; f < 6; ++f) a.face[f] = face[f];
    return prox_shape_from_arb(a);
}

/* ARB variants: 0 raw corners and face numbers; 1 a parallelepiped (corner o and three edges, the
 * MCNP hexahedron numbering); 2 a tetrahedron of four raw corners; 3 a pyramid frustum (base
 * parallelogram o, e1, e2, top the base shrunk by s in (0, 1) towards its centre, lifted by e3). */
static inline prox_shape fz_arb_variant(int variant, const uint8_t *p, size_t n, size_t k)
{
    static const int hexa[6] = {1234, 5678, 1265, 2376, 3487, 4158};
    static const int tetra[6] = {1230, 1240, 1340, 2340, 0, 0};
    prox_vec3 c[8] = {{0}};
    if (variant == 0) {
        int face[6];
        for (int i = 0; i < 8; ++i) c[i] = fz_get3(p, n, k + 3 * (size_t)i);
        for (int f = 0; f < 6; ++f) face[f] = fz_face(fz_get(p, n, k + 24 + (size_t)f));
        return fz_arb(c, face);
    }
    if (variant == 2) {
        for (int i = 0; i < 4; ++i) c[i] = fz_get3(p, n, k + 3 * (size_t)i);
        return fz_arb(c, tetra);
    }
    prox_vec3 o = fz_get3(p, n, k), e1 = fz_get3(p, n, k + 3), e2 = fz_get3(p, n, k + 6), e3 = fz_get3(p, n, k + 9);
    double t = fabs(fz_get(p, n, k + 12)), s = variant == 1 ? 1.0 : t / (1.0 + t);
    const double sq[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
        double x = sq[i][0], y = sq[i][1], xt = 0.5 + s * (x - 0.5), yt = 0.5 + s * (y - 0.5);
        c[i] = prox_v3_add(o, prox_v3_add(prox_v3_scale(e1, x), prox_v3_scale(e2, y)));
        c[i + 4] = prox_v3_add(prox_v3_add(o, e3), prox_v3_add(prox_v3_scale(e1, xt), prox_v3_scale(e2, yt)));
    }
    return fz_arb(c, hexa);
}

/* A shape of kind `kind` (0-9, prox_shape_kind) from doubles k.. of the payload. variant 0 takes the
 * stored layout raw (mostly invalid for the kinds whose vectors must be orthogonal, which exercises the
 * validators); the other variants build the shape the way a card form does, so that most inputs are
 * valid and reach the solvers: BOX edges made orthogonal; REC by prox_rec_from_radius; ELL by
 * prox_ell_from_foci (1) or prox_ell_from_axis (2); RHP by prox_rhp_regular (1, 2) or three facet
 * vectors made perpendicular to the height (3); WED with v3 along v1 x v2; ARB as fz_arb_variant. A
 * card form that fails leaves an invalid shape (the validators name it). */
static inline prox_shape fz_shape(int kind, int variant, const uint8_t *p, size_t n, size_t k)
{
    prox_vec3 v0 = fz_get3(p, n, k), v1 = fz_get3(p, n, k + 3), v2 = fz_get3(p, n, k + 6), v3 = fz_get3(p, n, k + 9);
    double s6 = fz_get(p, n, k + 6), s7 = fz_get(p, n, k + 7), s9 = fz_get(p, n, k + 9);
    variant &= 3;
    switch (kind) {
    case PROX_SHAPE_RCC: return prox_shape_from_rcc((prox_rcc){v0, v1, s6});
    case PROX_SHAPE_BOX:
        if (variant) {
            v2 = fz_perp(v2, v1);
            v3 = fz_along(prox_v3_cross(v1, v2), prox_v3_norm(v3));
        }
        return prox_shape_from_box((prox_box){v0, {v1, v2, v3}});
    case PROX_SHAPE_RPP: {
        prox_rpp r = {fz_get(p, n, k), fz_get(p, n, k + 1), fz_get(p, n, k + 2), fz_get(p, n, k + 3), fz_get(p, n, k + 4), fz_get(p, n, k + 5)};
        return prox_shape_from_rpp(r);
    }
    case PROX_SHAPE_SPH: return prox_shape_from_sph((prox_sph){v0, fz_get(p, n, k + 3)});
    case PROX_SHAPE_TRC: return prox_shape_from_trc((prox_trc){v0, v1, s6, s7});
    case PROX_SHAPE_REC: {
        prox_rec r = {v0, v1, v2, v3};
        if (variant && prox_rec_from_radius(v0, v1, fz_perp(v2, v1), s9, &r) != PROX_OK)
            r = (prox_rec){v0, v1, v2, prox_v3(0, 0, 0)};
        return prox_shape_from_rec(r);
    }
    case PROX_SHAPE_ELL: {
        prox_ell e = {v0, v1, s6};
        prox_status st = PROX_OK;
        if (variant == 1) st = prox_ell_from_foci(v0, v1, s6, &e);
        else if (variant >= 2) st = prox_ell_from_axis(v0, v1, s6, &e);
        if (st != PROX_OK) e = (prox_ell){v0, v1, -1.0};
        return prox_shape_from_ell(e);
    }
    case PROX_SHAPE_RHP: {
        prox_rhp h = {v0, v1, {v2, v3, fz_get3(p, n, k + 12)}};
        if (variant == 3)
            for (int i = 0; i < 3; ++i) h.r[i] = fz_perp(h.r[i], v1);
        else if (variant && prox_rhp_regular(v0, v1, fz_perp(v2, v1), &h) != PROX_OK)
            h = (prox_rhp){v0, v1, {prox_v3(0, 0, 0), v3, v3}};
        return prox_shape_from_rhp(h);
    }
    case PROX_SHAPE_WED: {
        if (variant) v3 = fz_along(prox_v3_cross(v1, v2), prox_v3_norm(v3));
        return prox_shape_from_wed((prox_wed){v0, v1, v2, v3});
    }
    case PROX_SHAPE_ARB: return fz_arb_variant(variant, p, n, k);
    default: { /* not a kind: the queries must answer PROX_EINVAL_SHAPE_KIND */
        prox_shape s = prox_shape_from_sph((prox_sph){v0, 1.0});
        s.kind = (prox_shape_kind)kind;
        return s;
    }
    }
}

#endif
