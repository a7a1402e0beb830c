/* Surface cards as quadrics and tori (MCNP6 manual, Sec. 3.2.2.1, Table 3-4 "MCNP Surface Cards",
 * and Sec. 3.2.2.4 for the macrobodies). Every equation is written in x - o with o a natural point
 * of the surface (a point of a plane, the centre of a sphere, a point of a cylinder's axis, a cone's
 * apex), so that a surface far from the global origin keeps its relative precision. The value is
 * negative on MCNP's negative side ("inside"); see docs/deck.md for the conventions and sources. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cells/cells_internal.h"

void cells_quadric(prox_surf *s, prox_vec3 o, double A[3][3], prox_vec3 b, double c)
{
    memset(s, 0, sizeof *s);
    s->kind = PROX_SURF_QUADRIC;
    s->o = o;
    s->q[0] = A[0][0], s->q[1] = A[1][1], s->q[2] = A[2][2];
    s->q[3] = A[0][1] + A[1][0], s->q[4] = A[1][2] + A[2][1], s->q[5] = A[0][2] + A[2][0];
    s->q[6] = b.x, s->q[7] = b.y, s->q[8] = b.z, s->q[9] = c;
}

void cells_plane(prox_surf *s, prox_vec3 o, prox_vec3 n)
{
    double Z[3][3] = {{0}};
    cells_quadric(s, o, Z, prox_v3_normalize(n), 0.0);
}

/* The symmetric matrix of a quadric's second-order part. */
static void quad_matrix(const prox_surf *s, double A[3][3])
{
    A[0][0] = s->q[0], A[1][1] = s->q[1], A[2][2] = s->q[2];
    A[0][1] = A[1][0] = 0.5 * s->q[3];
    A[1][2] = A[2][1] = 0.5 * s->q[4];
    A[0][2] = A[2][0] = 0.5 * s->q[5];
}

/* f'(x) = f(R^T (x - o_t)): with y = x - o', o' = o_t + R o, the matrix becomes R A R^T and the
 * linear part R b; the constant is unchanged. */
prox_surf cells_surf_transform(const prox_surf *s, const prox_deck_tr *t)
{
    if (!t) return *s;
    prox_surf r = *s;
    r.o = prox_deck_tr_point(t, s->o);
    if (s->kind == PROX_SURF_TORUS) {
        r.w = prox_deck_tr_vec(t, s->w);
        return r;
    }
    if (t->identity) return r;
    double A[3][3], B[3][3], C[3][3];
    quad_matrix(s, A);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            B[i][j] = 0;
            for (int k = 0; k < 3; ++k) B[i][j] += t->R[i][k] * A[k][j];
        }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            C[i][j] = 0;
            for (int k = 0; k < 3; ++k) C[i][j] += B[i][k] * t->R[j][k];
        }
    prox_vec3 b = prox_deck_tr_vec(t, prox_v3(s->q[6], s->q[7], s->q[8]));
    double c = s->q[9];
    cells_quadric(&r, r.o, C, b, c);
    r.number = s->number, r.facet = s->facet, r.line = s->line;
    memcpy(r.card, s->card, sizeof r.card);
    return r;
}

prox_deck_tr cells_tr_inverse(const prox_deck_tr *t)
{
    prox_deck_tr r = *t;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.R[i][j] = t->R[j][i];
    for (int i = 0; i < 3; ++i) r.o[i] = -(r.R[i][0] * t->o[0] + r.R[i][1] * t->o[1] + r.R[i][2] * t->o[2]);
    return r;
}

prox_deck_tr cells_tr_compose(const prox_deck_tr *a, const prox_deck_tr *b)
{
    prox_deck_tr r = *a;
    for (int i = 0; i < 3; ++i) {
        r.o[i] = a->o[i];
        for (int k = 0; k < 3; ++k) r.o[i] += a->R[i][k] * b->o[k];
        for (int j = 0; j < 3; ++j) {
            r.R[i][j] = 0;
            for (int k = 0; k < 3; ++k) r.R[i][j] += a->R[i][k] * b->R[k][j];
        }
    }
    r.identity = a->identity && b->identity;
    return r;
}

/* ---- the surfaces of Table 3-4 ---------------------------------------------------------------- */

static const prox_vec3 AXES[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

/* Cylinder |y|^2 - (y.w)^2 - R^2 about the axis through o along unit w. */
static void cylinder(prox_surf *s, prox_vec3 o, prox_vec3 w, double R)
{
    double A[3][3], u[3] = {w.x, w.y, w.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = (i == j) - u[i] * u[j];
    cells_quadric(s, o, A, prox_v3(0, 0, 0), -R * R);
}

/* Double cone |y|^2 - (1 + t2) (y.w)^2 with apex o, unit axis w, t2 = tan^2 of the half angle. */
static void cone(prox_surf *s, prox_vec3 o, prox_vec3 w, double t2)
{
    double A[3][3], u[3] = {w.x, w.y, w.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = (i == j) - (1.0 + t2) * u[i] * u[j];
    cells_quadric(s, o, A, prox_v3(0, 0, 0), 0.0);
}

/* Axis index of the letter in "C/X", "KX", "TX", "X" ... (0, 1, 2) or -1. */
static int axis_of(char c) { return c == 'X' ? 0 : c == 'Y' ? 1 : c == 'Z' ? 2 : -1; }

/* A point with coordinate a along axis ax and (p, q) along the two others in cyclic order as the
 * MCNP cards list them (C/X y z; C/Y x z; C/Z x y: the remaining two in increasing order). */
static prox_vec3 axis_point(int ax, double a, double p, double q)
{
    double c[3];
    c[ax] = a;
    int k = 0;
    for (int i = 0; i < 3; ++i)
        if (i != ax) c[i] = k++ ? q : p;
    return prox_v3(c[0], c[1], c[2]);
}

/* One-sheet cone (entry +1 or -1): the nappe on that side of the apex; its inside is the double
 * cone's negative side AND that side of the plane through the apex across the axis. */
static int cone_card(cells_sdef *out, prox_vec3 apex, prox_vec3 w, double t2, int nsheet, double sheet,
                     char *err, size_t errsz)
{
    if (!(t2 > 0)) {
        snprintf(err, errsz, "t^2 must be positive, not %g", t2);
        return -1;
    }
    cone(&out->part[0], apex, w, t2);
    out->in[0] = -1;
    out->nparts = 1;
    if (nsheet) {
        if (sheet != 1.0 && sheet != -1.0) {
            snprintf(err, errsz, "the sheet entry must be +1 or -1, not %g", sheet);
            return -1;
        }
        cells_plane(&out->part[1], apex, w);
        out->in[1] = sheet > 0 ? 1 : -1;
        out->nparts = 2;
    }
    return 0;
}

/* P with 3 points: n = (p2 - p1) x (p3 - p1), oriented so that the origin is on the negative side;
 * for a plane through the origin, (0,0,inf) is on the positive side, then (0,inf,0), then (inf,0,0)
 * (MCNP6 manual, Sec. 3.2.2.1, planes defined by three points). */
static int plane3(cells_sdef *out, const double *v, char *err, size_t errsz)
{
    prox_vec3 p1 = prox_v3(v[0], v[1], v[2]), p2 = prox_v3(v[3], v[4], v[5]), p3 = prox_v3(v[6], v[7], v[8]);
    prox_vec3 n = prox_v3_cross(prox_v3_sub(p2, p1), prox_v3_sub(p3, p1));
    if (!(prox_v3_norm(n) > 0)) {
        snprintf(err, errsz, "the three points are collinear");
        return -1;
    }
    double d = prox_v3_dot(n, p1);
    int flip = d != 0 ? d < 0 : n.z != 0 ? n.z < 0 : n.y != 0 ? n.y < 0 : n.x < 0;
    if (flip) n = prox_v3_neg(n);
    cells_plane(&out->part[0], p1, n);
    return 0;
}

/* X, Y, Z defined by 1 to 3 (coordinate, radius) pairs about the axis (Table 3-4, "surfaces defined
 * by points"): one pair or equal coordinates: a plane; equal radii: a cylinder; two pairs: the
 * nappe of the cone through both; three pairs: r^2 = a s^2 + b s + c. Negative towards the axis
 * (the plane: towards -axis). */
static int point_surface(cells_sdef *out, int ax, const double *v, size_t nv, char *err, size_t errsz)
{
    prox_vec3 w = AXES[ax];
    if (nv != 2 && nv != 4 && nv != 6) {
        snprintf(err, errsz, "needs 2, 4 or 6 entries (coordinate-radius pairs), has %zu", nv);
        return -1;
    }
    if (nv == 2 || (nv == 4 && v[0] == v[2])) {
        cells_plane(&out->part[0], prox_v3_scale(w, v[0]), w);
        return 0;
    }
    if (nv == 4) {
        double s1 = v[0], r1 = fabs(v[1]), s2 = v[2], r2 = fabs(v[3]);
        if (r1 == r2) {
            if (!(r1 > 0)) goto bad;
            cylinder(&out->part[0], prox_v3(0, 0, 0), w, r1);
            return 0;
        }
        double t = (r2 - r1) / (s2 - s1), apex = s1 - r1 / t;
        return cone_card(out, prox_v3_scale(w, apex), w, t * t, 1, (s1 + s2) / 2 > apex ? 1.0 : -1.0, err, errsz);
    }
    /* three pairs: solve [s^2 s 1] (a b c) = r^2 by Cramer's rule */
    double M[3][3], r[3];
    for (int i = 0; i < 3; ++i) M[i][0] = v[2 * i] * v[2 * i], M[i][1] = v[2 * i], M[i][2] = 1, r[i] = v[2 * i + 1] * v[2 * i + 1];
    double det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                 M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    if (!(fabs(det) > 0)) goto bad;
    double abc[3];
    for (int k = 0; k < 3; ++k) {
        double N[3][3];
        memcpy(N, M, sizeof N);
        for (int i = 0; i < 3; ++i) N[i][k] = r[i];
        abc[k] = (N[0][0] * (N[1][1] * N[2][2] - N[1][2] * N[2][1]) - N[0][1] * (N[1][0] * N[2][2] - N[1][2] * N[2][0]) +
                  N[0][2] * (N[1][0] * N[2][1] - N[1][1] * N[2][0])) / det;
    }
    double A[3][3] = {{0}}, u[3] = {w.x, w.y, w.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A[i][j] = (i == j) - (1.0 + abc[0]) * u[i] * u[j];
    cells_quadric(&out->part[0], prox_v3(0, 0, 0), A, prox_v3_scale(w, -abc[1]), -abc[2]);
    return 0;
bad:
    snprintf(err, errsz, "the points do not define a surface");
    return -1;
}

/* Entry count check. */
static int want(size_t nv, size_t a, size_t b, char *err, size_t errsz)
{
    if (nv == a || nv == b) return 0;
    if (b && b != a) snprintf(err, errsz, "needs %zu or %zu entries, has %zu", a, b, nv);
    else snprintf(err, errsz, "needs %zu entries, has %zu", a, nv);
    return -1;
}

/* The ordinary surfaces (one quadric or torus; the one-sheet cones two parts), in the card's frame. */
static int plain_surface(const char *mn, const double *v, size_t nv, cells_sdef *out, char *err, size_t errsz)
{
    size_t L = strlen(mn);
    prox_surf *s = &out->part[0];
    out->nparts = 1, out->in[0] = -1;
    if (!strcmp(mn, "P")) {
        if (nv == 9) return plane3(out, v, err, errsz);
        if (want(nv, 4, 9, err, errsz)) return -1;
        prox_vec3 n = prox_v3(v[0], v[1], v[2]);
        double n2 = prox_v3_norm2(n);
        if (!(n2 > 0)) {
            snprintf(err, errsz, "the normal (A, B, C) is zero");
            return -1;
        }
        cells_plane(s, prox_v3_scale(n, v[3] / n2), n);
        return 0;
    }
    if (L == 2 && mn[0] == 'P' && axis_of(mn[1]) >= 0) { /* PX D */
        if (want(nv, 1, 1, err, errsz)) return -1;
        int ax = axis_of(mn[1]);
        cells_plane(s, prox_v3_scale(AXES[ax], v[0]), AXES[ax]);
        return 0;
    }
    if (!strcmp(mn, "SQ")) { /* A B C D E F G x y z */
        if (want(nv, 10, 10, err, errsz)) return -1;
        double A[3][3] = {{v[0], 0, 0}, {0, v[1], 0}, {0, 0, v[2]}};
        cells_quadric(s, prox_v3(v[7], v[8], v[9]), A, prox_v3(2 * v[3], 2 * v[4], 2 * v[5]), v[6]);
        return 0;
    }
    if (!strcmp(mn, "GQ")) { /* A B C D E F G H J K */
        if (want(nv, 10, 10, err, errsz)) return -1;
        double A[3][3] = {{v[0], v[3] / 2, v[5] / 2}, {v[3] / 2, v[1], v[4] / 2}, {v[5] / 2, v[4] / 2, v[2]}};
        cells_quadric(s, prox_v3(0, 0, 0), A, prox_v3(v[6], v[7], v[8]), v[9]);
        return 0;
    }
    if (L == 3 && mn[0] == 'C' && mn[1] == '/' && axis_of(mn[2]) >= 0) { /* C/X y z R */
        if (want(nv, 3, 3, err, errsz)) return -1;
        int ax = axis_of(mn[2]);
        if (!(v[2] > 0)) goto radius;
        cylinder(s, axis_point(ax, 0, v[0], v[1]), AXES[ax], v[2]);
        return 0;
    }
    if (L == 2 && mn[0] == 'C' && axis_of(mn[1]) >= 0) { /* CX R */
        if (want(nv, 1, 1, err, errsz)) return -1;
        if (!(v[0] > 0)) goto radius;
        cylinder(s, prox_v3(0, 0, 0), AXES[axis_of(mn[1])], v[0]);
        return 0;
    }
    if (L == 3 && mn[0] == 'K' && mn[1] == '/' && axis_of(mn[2]) >= 0) { /* K/X x y z t^2 [+-1] */
        if (want(nv, 4, 5, err, errsz)) return -1;
        int ax = axis_of(mn[2]);
        return cone_card(out, prox_v3(v[0], v[1], v[2]), AXES[ax], v[3], nv == 5, nv == 5 ? v[4] : 0, err, errsz);
    }
    if (L == 2 && mn[0] == 'K' && axis_of(mn[1]) >= 0) { /* KX x t^2 [+-1] */
        if (want(nv, 2, 3, err, errsz)) return -1;
        int ax = axis_of(mn[1]);
        return cone_card(out, prox_v3_scale(AXES[ax], v[0]), AXES[ax], v[1], nv == 3, nv == 3 ? v[2] : 0, err, errsz);
    }
    if (L == 2 && mn[0] == 'T' && axis_of(mn[1]) >= 0) { /* TX x y z A B C */
        if (want(nv, 6, 6, err, errsz)) return -1;
        if (!(v[3] > 0 && v[4] > 0 && v[5] > 0)) {
            snprintf(err, errsz, "torus radii A, B, C must be positive");
            return -1;
        }
        memset(s, 0, sizeof *s);
        s->kind = PROX_SURF_TORUS;
        s->o = prox_v3(v[0], v[1], v[2]);
        s->w = AXES[axis_of(mn[1])];
        s->ta = v[3], s->tb = v[4], s->tc = v[5];
        return 0;
    }
    if (L == 1 && axis_of(mn[0]) >= 0) return point_surface(out, axis_of(mn[0]), v, nv, err, errsz);
    return 1;
radius:
    snprintf(err, errsz, "radius must be positive");
    return -1;
}

int cells_surface_card(const char *mn, const double *v, size_t nv, const prox_deck_tr *t, cells_sdef *out,
                       char *err, size_t errsz)
{
    memset(out, 0, sizeof *out);
    prox_shape shape;
    int r = prox_deck_body_shape(mn, v, nv, t, &shape, err, errsz);
    if (r < 0) return -1;
    if (r == 0) { /* a macrobody (or a sphere card): the AND of its facets' negative sides */
        out->nparts = prox_shape_facets(&shape, out->part);
        for (int k = 0; k < out->nparts; ++k) out->in[k] = -1;
        out->body = !(mn[0] == 'S' && strcmp(mn, "SPH"));
        for (int k = 0; k < out->nparts; ++k) memcpy(out->part[k].card, mn, strlen(mn) + 1);
        return 0;
    }
    r = plain_surface(mn, v, nv, out, err, errsz);
    if (r) return r;
    for (int k = 0; k < out->nparts; ++k) {
        out->part[k] = cells_surf_transform(&out->part[k], t);
        memcpy(out->part[k].card, mn, strlen(mn) + 1);
    }
    return 0;
}
