/* Bounding boxes of the sides of surfaces (the broad phase of the cell check) and the merging of
 * coincident surfaces.
 *
 * Side of a quadric. The side g(y) = y^T Q y + G.y + K < 0 (g = f for the negative side, -f for the
 * positive one, y = x - o) is bounded across the axes it depends on when Q restricted to them is
 * positive definite: with c = -Q^-1 G / 2 it is (y - c)^T Q (y - c) < r, r = G^T Q^-1 G / 4 - K, an
 * ellipsoid (ellipse, interval) whose extent along axis i is sqrt(r (Q^-1)_ii). An axis that g does
 * not depend on (a CZ cylinder's z) is unbounded; a plane normal to an axis bounds that axis on one
 * side; anything else (tilted cylinders and planes, cones, hyperboloids) is left unbounded here:
 * the check bounds such cells by subdivision (check.c).
 *
 * Torus: the negative side lies within B of the mid-plane and A + C of the axis. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cells/check_internal.h"
#include "core/tol.h"

prox_ccbox prox_ccbox_all(void)
{
    prox_ccbox b;
    for (int i = 0; i < 3; ++i) b.lo[i] = -INFINITY, b.hi[i] = INFINITY;
    return b;
}

prox_ccbox prox_ccbox_empty(void)
{
    prox_ccbox b;
    for (int i = 0; i < 3; ++i) b.lo[i] = INFINITY, b.hi[i] = -INFINITY;
    return b;
}

int prox_ccbox_is_empty(const prox_ccbox *b)
{
    return !(b->lo[0] <= b->hi[0] && b->lo[1] <= b->hi[1] && b->lo[2] <= b->hi[2]);
}

int prox_ccbox_bounded(const prox_ccbox *b)
{
    for (int i = 0; i < 3; ++i)
        if (!isfinite(b->lo[i]) || !isfinite(b->hi[i])) return 0;
    return 1;
}

int prox_ccbox_meets(const prox_ccbox *a, const prox_ccbox *b)
{
    return a->lo[0] <= b->hi[0] && b->lo[0] <= a->hi[0] && a->lo[1] <= b->hi[1] && b->lo[1] <= a->hi[1] &&
           a->lo[2] <= b->hi[2] && b->lo[2] <= a->hi[2];
}

prox_ccbox prox_ccbox_and(const prox_ccbox *a, const prox_ccbox *b)
{
    prox_ccbox r;
    for (int i = 0; i < 3; ++i) r.lo[i] = fmax(a->lo[i], b->lo[i]), r.hi[i] = fmin(a->hi[i], b->hi[i]);
    return r;
}

prox_ccbox prox_ccbox_or(const prox_ccbox *a, const prox_ccbox *b)
{
    if (prox_ccbox_is_empty(a)) return *b;
    if (prox_ccbox_is_empty(b)) return *a;
    prox_ccbox r;
    for (int i = 0; i < 3; ++i) r.lo[i] = fmin(a->lo[i], b->lo[i]), r.hi[i] = fmax(a->hi[i], b->hi[i]);
    return r;
}

/* Widens a bounded extent [c - e, c + e] relative (PROX_TOL_CELL_BOX) and returns it in r's axis i. */
static void set_axis(prox_ccbox *r, int i, double c, double e)
{
    double pad = PROX_TOL_CELL_BOX * (fabs(c) + e) + 1e-300;
    r->lo[i] = c - e - pad;
    r->hi[i] = c + e + pad;
}

/* Inverse of the symmetric n x n (n <= 3) matrix a when it is positive definite and well
 * conditioned (leading minors above PROX_TOL_CELL_PD of the product of diagonals); 0 otherwise. */
static int spd_inverse(int n, double a[3][3], double inv[3][3])
{
    if (n == 1) {
        if (!(a[0][0] > 0.0)) return 0;
        inv[0][0] = 1.0 / a[0][0];
        return 1;
    }
    double d1 = a[0][0], d2 = a[0][0] * a[1][1] - a[0][1] * a[0][1];
    if (!(d1 > 0.0) || !(d2 > PROX_TOL_CELL_PD * a[0][0] * a[1][1])) return 0;
    if (n == 2) {
        inv[0][0] = a[1][1] / d2, inv[1][1] = a[0][0] / d2, inv[0][1] = inv[1][0] = -a[0][1] / d2;
        return 1;
    }
    double c00 = a[1][1] * a[2][2] - a[1][2] * a[1][2], c01 = a[0][2] * a[1][2] - a[0][1] * a[2][2],
           c02 = a[0][1] * a[1][2] - a[0][2] * a[1][1], c11 = a[0][0] * a[2][2] - a[0][2] * a[0][2],
           c12 = a[0][1] * a[0][2] - a[0][0] * a[1][2], c22 = d2;
    double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    if (!(det > PROX_TOL_CELL_PD * a[0][0] * a[1][1] * a[2][2])) return 0;
    inv[0][0] = c00 / det, inv[0][1] = inv[1][0] = c01 / det, inv[0][2] = inv[2][0] = c02 / det;
    inv[1][1] = c11 / det, inv[1][2] = inv[2][1] = c12 / det, inv[2][2] = c22 / det;
    return 1;
}

static prox_ccbox quadric_side_box(const prox_surf *s, int sense)
{
    const double sg = sense < 0 ? 1.0 : -1.0, *q = s->q;
    const double Q[3][3] = {{sg * q[0], 0.5 * sg * q[3], 0.5 * sg * q[5]},
                            {0.5 * sg * q[3], sg * q[1], 0.5 * sg * q[4]},
                            {0.5 * sg * q[5], 0.5 * sg * q[4], sg * q[2]}};
    const double G[3] = {sg * q[6], sg * q[7], sg * q[8]}, K = sg * q[9];
    const double o[3] = {s->o.x, s->o.y, s->o.z};
    int axes[3], n = 0, nq = 0;
    for (int i = 0; i < 3; ++i) {
        int row = Q[i][0] != 0.0 || Q[i][1] != 0.0 || Q[i][2] != 0.0;
        if (row || G[i] != 0.0) axes[n++] = i;
        nq += row;
    }
    prox_ccbox r = prox_ccbox_all();
    if (n == 0) return K < 0.0 ? r : prox_ccbox_empty();
    if (nq == 0) { /* a plane: bounded on one side only when it is normal to an axis */
        if (n == 1) {
            int i = axes[0];
            double v = o[i] - K / G[i];
            if (G[i] > 0.0) r.hi[i] = v + PROX_TOL_CELL_BOX * fabs(v) + 1e-300;
            else r.lo[i] = v - PROX_TOL_CELL_BOX * fabs(v) - 1e-300;
        }
        return r;
    }
    double a[3][3] = {{0}}, inv[3][3], g[3];
    for (int i = 0; i < n; ++i) {
        g[i] = G[axes[i]];
        for (int j = 0; j < n; ++j) a[i][j] = Q[axes[i]][axes[j]];
    }
    if (!spd_inverse(n, a, inv)) return r;
    double c[3], rr = -K;
    for (int i = 0; i < n; ++i) {
        c[i] = 0.0;
        for (int j = 0; j < n; ++j) c[i] -= 0.5 * inv[i][j] * g[j];
        rr -= 0.5 * g[i] * c[i]; /* G^T Q^-1 G / 4 = -G.c / 2 */
    }
    if (rr < 0.0) {
        /* Empty unless rounding: keep a tiny box at the centre when r is within rounding of 0. */
        double mag = fabs(K);
        for (int i = 0; i < n; ++i) mag += fabs(0.5 * g[i] * c[i]);
        if (rr < -PROX_TOL_CELL_BOX * mag) return prox_ccbox_empty();
        rr = 0.0;
    }
    for (int i = 0; i < n; ++i) set_axis(&r, axes[i], o[axes[i]] + c[i], sqrt(rr * inv[i][i]));
    return r;
}

static prox_ccbox torus_side_box(const prox_surf *s, int sense)
{
    prox_ccbox r = prox_ccbox_all();
    if (sense > 0 || !(s->tb > 0.0) || !(s->tc > 0.0)) return r;
    const double w[3] = {s->w.x, s->w.y, s->w.z}, o[3] = {s->o.x, s->o.y, s->o.z};
    const double across = fabs(s->ta) + s->tc;
    for (int i = 0; i < 3; ++i) set_axis(&r, i, o[i], s->tb * fabs(w[i]) + across * sqrt(fmax(0.0, 1.0 - w[i] * w[i])));
    return r;
}

prox_ccbox prox_cc_side_box(const prox_surf *s, int sense)
{
    return s->kind == PROX_SURF_TORUS ? torus_side_box(s, sense) : quadric_side_box(s, sense);
}

/* ---- coincident surfaces ---- */

/* Normalised global coefficients of a quadric (origin moved to 0, largest coefficient of the
 * highest degree present made +1) and the sign applied. */
typedef struct canon {
    double c[10];
    int sign;
    size_t index;
} canon;

static void canonical(const prox_surf *s, canon *out)
{
    const double *q = s->q, ox = s->o.x, oy = s->o.y, oz = s->o.z;
    double c[10];
    memcpy(c, q, sizeof c);
    /* f(x - o): linear part G - 2 Q o, constant K - G.o + o^T Q o. */
    c[6] = q[6] - 2.0 * q[0] * ox - q[3] * oy - q[5] * oz;
    c[7] = q[7] - 2.0 * q[1] * oy - q[3] * ox - q[4] * oz;
    c[8] = q[8] - 2.0 * q[2] * oz - q[4] * oy - q[5] * ox;
    c[9] = q[9] - q[6] * ox - q[7] * oy - q[8] * oz + q[0] * ox * ox + q[1] * oy * oy + q[2] * oz * oz +
           q[3] * ox * oy + q[4] * oy * oz + q[5] * oz * ox;
    int lo = 0, hi = 6;
    double big = 0.0;
    for (int i = 0; i < 6; ++i) big = fmax(big, fabs(c[i]));
    if (big == 0.0) lo = 6, hi = 9;
    int at = lo;
    big = 0.0;
    for (int i = lo; i < hi; ++i)
        if (fabs(c[i]) > big) big = fabs(c[i]), at = i;
    out->sign = 1;
    if (big == 0.0) big = 1.0;
    else if (c[at] < 0.0) out->sign = -1;
    for (int i = 0; i < 10; ++i) out->c[i] = out->sign * c[i] / big;
}

/* Order for sorting: exact lexicographic order of the coefficients rounded to 1e-9. */
static int canon_cmp(const void *pa, const void *pb)
{
    const canon *a = pa, *b = pb;
    for (int i = 0; i < 10; ++i) {
        double x = nearbyint(a->c[i] * 1e9), y = nearbyint(b->c[i] * 1e9);
        if (x != y) return x < y ? -1 : 1;
    }
    return a->index < b->index ? -1 : a->index > b->index;
}

static int same(const canon *a, const canon *b)
{
    for (int i = 0; i < 9; ++i)
        if (fabs(a->c[i] - b->c[i]) > PROX_TOL_SURF_SAME) return 0;
    return fabs(a->c[9] - b->c[9]) <= PROX_TOL_SURF_SAME * fmax(1.0, fmax(fabs(a->c[9]), fabs(b->c[9])));
}

prox_status prox_cc_merge_surfaces(const prox_surf *s, size_t n, size_t *rep, signed char *flip)
{
    for (size_t i = 0; i < n; ++i) rep[i] = i, flip[i] = 1;
    canon *cs = malloc((n ? n : 1) * sizeof *cs);
    if (!cs) return PROX_ENOMEM;
    size_t nq = 0;
    for (size_t i = 0; i < n; ++i) {
        if (s[i].kind != PROX_SURF_QUADRIC) continue;
        canonical(&s[i], &cs[nq]);
        cs[nq++].index = i;
    }
    qsort(cs, nq, sizeof *cs, canon_cmp);
    for (size_t i = 0; i < nq;) {
        size_t j = i + 1, first = cs[i].index;
        for (size_t k = i + 1; k < nq && same(&cs[i], &cs[k]); ++k) j = k + 1, first = cs[k].index < first ? cs[k].index : first;
        int fsign = 0;
        for (size_t k = i; k < j; ++k)
            if (cs[k].index == first) fsign = cs[k].sign;
        for (size_t k = i; k < j; ++k) {
            rep[cs[k].index] = first;
            flip[cs[k].index] = (signed char)(cs[k].sign * fsign);
        }
        i = j;
    }
    free(cs);
    return PROX_OK;
}
