/* The facets of a macrobody as surfaces, numbered as MCNP numbers them for `n.k` references (MCNP6
 * manual, Sec. 3.2.2.4, "Macrobodies"; the numbering is listed in docs/deck.md):
 *   RPP  1 +x, 2 -x, 3 +y, 4 -y, 5 +z, 6 -z          BOX  1 end of a1, 2 its start, 3/4 a2, 5/6 a3
 *   SPH  1 the sphere                                 ELL  1 the ellipsoid
 *   RCC, TRC, REC  1 the lateral surface, 2 the top (end of h), 3 the base
 *   RHP  1 end of r, 2 opposite, 3 end of s, 4 opposite, 5 end of t, 6 opposite, 7 top, 8 base
 *   WED  1 the slant face, 2 the face of v2 and v3, 3 the face of v1 and v3, 4 top, 5 base
 *   ARB  facet k is the k-th face entry (an unused face inside the list: all space)
 * Every facet's negative side holds the body; the body is their intersection. A TRC's lateral
 * facet is the double cone: the other nappe lies beyond the apex, outside the two end planes. */
#include <math.h>
#include <string.h>

#include "cells/cells_internal.h"
#include "core/polytope.h"

/* Plane through p with outward normal n (facet k). */
static void facet_plane(prox_surf *out, int k, prox_vec3 p, prox_vec3 n)
{
    cells_plane(&out[k - 1], p, n);
    out[k - 1].facet = k;
}

/* The axis-end facets of a body along h from base b: top (facet kt) and base (facet kb). */
static void ends(prox_surf *out, int kt, int kb, prox_vec3 b, prox_vec3 h)
{
    facet_plane(out, kt, prox_v3_add(b, h), h);
    facet_plane(out, kb, b, prox_v3_neg(h));
}

static int box_facets(prox_vec3 c, const prox_vec3 e[3], prox_surf *out)
{
    for (int i = 0; i < 3; ++i) {
        facet_plane(out, 2 * i + 1, prox_v3_add(c, e[i]), e[i]);
        facet_plane(out, 2 * i + 2, c, prox_v3_neg(e[i]));
    }
    return 6;
}

/* Lateral surface of an RCC: |y|^2 - (y.w)^2 - r^2 about the base. */
static void rcc_side(const prox_rcc *c, prox_surf *s)
{
    prox_vec3 w = prox_v3_normalize(c->axis);
    double A[3][3], u[3] = {w.x, w.y, w.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = (i == j) - u[i] * u[j];
    cells_quadric(s, c->base, A, prox_v3(0, 0, 0), -c->radius * c->radius);
}

/* Lateral surface of a TRC: |y|^2 - (y.w)^2 - (r1 + k y.w)^2, k = (r2 - r1) / H, about the base. */
static void trc_side(const prox_trc *t, prox_surf *s)
{
    double H = prox_v3_norm(t->axis), k = (t->r2 - t->r1) / H;
    prox_vec3 w = prox_v3_scale(t->axis, 1.0 / H);
    double A[3][3], u[3] = {w.x, w.y, w.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = (i == j) - (1.0 + k * k) * u[i] * u[j];
    cells_quadric(s, t->base, A, prox_v3_scale(w, -2.0 * t->r1 * k), -t->r1 * t->r1);
}

/* Lateral surface of a REC: (a2/a1) (y.u1)^2 + (a1/a2) (y.u2)^2 - a1 a2 (a length squared). */
static void rec_side(const prox_rec *r, prox_surf *s)
{
    double a1 = prox_v3_norm(r->a1), a2 = prox_v3_norm(r->a2);
    prox_vec3 u1 = prox_v3_scale(r->a1, 1.0 / a1), u2 = prox_v3_scale(r->a2, 1.0 / a2);
    double A[3][3], p[3] = {u1.x, u1.y, u1.z}, q[3] = {u2.x, u2.y, u2.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = (a2 / a1) * p[i] * p[j] + (a1 / a2) * q[i] * q[j];
    cells_quadric(s, r->base, A, prox_v3(0, 0, 0), -a1 * a2);
}

/* Ellipsoid of revolution: (b/a) (y.w)^2 + (a/b) (|y|^2 - (y.w)^2) - a b about the centre. */
static void ell_surface(const prox_ell *e, prox_surf *s)
{
    double a = prox_v3_norm(e->axis), b = e->radius;
    prox_vec3 w = prox_v3_scale(e->axis, 1.0 / a);
    double A[3][3], u[3] = {w.x, w.y, w.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = (a / b) * (i == j) + (b / a - a / b) * u[i] * u[j];
    cells_quadric(s, e->center, A, prox_v3(0, 0, 0), -a * b);
}

static int wed_facets(const prox_wed *w, prox_surf *out)
{
    prox_vec3 v = w->vertex, p1 = prox_v3_add(v, w->v1);
    prox_vec3 ns = prox_v3_cross(prox_v3_sub(w->v2, w->v1), w->v3); /* slant face normal */
    if (prox_v3_dot(ns, w->v1) < 0) ns = prox_v3_neg(ns);
    facet_plane(out, 1, p1, ns);
    prox_vec3 n2 = prox_v3_cross(w->v2, w->v3); /* face of v2 and v3 through the vertex */
    if (prox_v3_dot(n2, w->v1) > 0) n2 = prox_v3_neg(n2);
    facet_plane(out, 2, v, n2);
    prox_vec3 n3 = prox_v3_cross(w->v1, w->v3); /* face of v1 and v3 */
    if (prox_v3_dot(n3, w->v2) > 0) n3 = prox_v3_neg(n3);
    facet_plane(out, 3, v, n3);
    ends(out, 4, 5, v, w->v3);
    return 5;
}

static int rhp_facets(const prox_rhp *h, prox_surf *out)
{
    for (int i = 0; i < 3; ++i) {
        facet_plane(out, 2 * i + 1, prox_v3_add(h->base, h->r[i]), h->r[i]);
        facet_plane(out, 2 * i + 2, prox_v3_sub(h->base, h->r[i]), prox_v3_neg(h->r[i]));
    }
    ends(out, 7, 8, h->base, h->axis);
    return 8;
}

/* ARB: each used face's plane (Newell normal of its corner loop, through the corners' mean),
 * oriented away from the mean of all used corners. */
static int arb_facets(const prox_arb *a, prox_surf *out)
{
    int used[8] = {0}, last = 0;
    for (int f = 0; f < 6; ++f)
        for (int d = a->face[f]; d; d /= 10)
            if (d % 10) used[d % 10 - 1] = 1;
    prox_vec3 c = prox_v3(0, 0, 0);
    int nu = 0;
    for (int i = 0; i < 8; ++i)
        if (used[i]) c = prox_v3_add(c, a->corner[i]), ++nu;
    if (nu) c = prox_v3_scale(c, 1.0 / nu);
    for (int f = 0; f < 6; ++f) {
        int idx[4], n = prox_arb_face_loop(a, f, idx);
        if (n < 3) { /* unused: all space */
            memset(&out[f], 0, sizeof out[f]);
            out[f].kind = PROX_SURF_QUADRIC, out[f].q[9] = -1.0, out[f].facet = f + 1;
            continue;
        }
        prox_vec3 nrm = prox_v3(0, 0, 0), m = prox_v3(0, 0, 0);
        for (int i = 0; i < n; ++i) {
            prox_vec3 p = prox_v3_sub(a->corner[idx[i]], c), q = prox_v3_sub(a->corner[idx[(i + 1) % n]], c);
            nrm = prox_v3_add(nrm, prox_v3(
                (p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)));
            m = prox_v3_add(m, a->corner[idx[i]]);
        }
        m = prox_v3_scale(m, 1.0 / n);
        if (prox_v3_dot(nrm, prox_v3_sub(m, c)) < 0) nrm = prox_v3_neg(nrm);
        facet_plane(out, f + 1, m, nrm);
        last = f + 1;
    }
    return last;
}

PROX_API int prox_shape_facets(const prox_shape *s, prox_surf out[8])
{
    if (!s || !out) return 0;
    int n = 0;
    switch (s->kind) {
    case PROX_SHAPE_RPP: {
        prox_box b = prox_rpp_to_box(&s->u.rpp);
        n = box_facets(b.corner, b.edge, out);
        break;
    }
    case PROX_SHAPE_BOX: n = box_facets(s->u.box.corner, s->u.box.edge, out); break;
    case PROX_SHAPE_SPH:
        cells_quadric(&out[0], s->u.sph.center, (double[3][3]){{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, prox_v3(0, 0, 0),
                      -s->u.sph.radius * s->u.sph.radius);
        out[0].facet = 1;
        n = 1;
        break;
    case PROX_SHAPE_RCC:
        rcc_side(&s->u.rcc, &out[0]);
        out[0].facet = 1;
        ends(out, 2, 3, s->u.rcc.base, s->u.rcc.axis);
        n = 3;
        break;
    case PROX_SHAPE_TRC:
        trc_side(&s->u.trc, &out[0]);
        out[0].facet = 1;
        ends(out, 2, 3, s->u.trc.base, s->u.trc.axis);
        n = 3;
        break;
    case PROX_SHAPE_REC:
        rec_side(&s->u.rec, &out[0]);
        out[0].facet = 1;
        ends(out, 2, 3, s->u.rec.base, s->u.rec.axis);
        n = 3;
        break;
    case PROX_SHAPE_ELL:
        ell_surface(&s->u.ell, &out[0]);
        out[0].facet = 1;
        n = 1;
        break;
    case PROX_SHAPE_RHP: n = rhp_facets(&s->u.rhp, out); break;
    case PROX_SHAPE_WED: n = wed_facets(&s->u.wed, out); break;
    case PROX_SHAPE_ARB: n = arb_facets(&s->u.arb, out); break;
    default: return 0;
    }
    const char *name = prox_shape_kind_name(s->kind);
    for (int k = 0; k < n; ++k) {
        size_t l = strlen(name);
        if (l > sizeof out[k].card - 1) l = sizeof out[k].card - 1;
        memcpy(out[k].card, name, l);
        out[k].card[l] = 0;
    }
    return n;
}
