/* Independent geometry for tests/test_deck_all_bodies.c: a minimal reader of the test's own deck
 * (one card a line or one continuation line of five blanks, plain numbers), the TRn placement of the
 * MCNP manual (Sec. 3.3.1.7: r = O + B r' for M = 1, r = B (r' - O) for M = -1; B1..B9 are the
 * cosines xx' yx' zx' xy' yy' zy' xz' yz' zz', so B's columns are the auxiliary axes in main
 * coordinates; *TRn gives angles in degrees; with 6 B entries z' = x' x y'), and per body kind its
 * own support function h(d), a support point, a membership function f(x) (<= 0 inside; where
 * positive it never exceeds the distance to the body) and corner/facet lists of the polytopes.
 * Nothing here calls a prox solver: only the vec3.h arithmetic and the prox_shape struct layout. */
#ifndef PROX_TEST_DECK_ALL_BODIES_REF_H
#define PROX_TEST_DECK_ALL_BODIES_REF_H

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "prox/shapes.h"
#include "prox/vec3.h"

#define REF_PI 3.14159265358979323846
#define REF_MAX_CARDS 32
#define REF_MAX_ENTRIES 64

/* One surface or TR card of the deck, as written. */
typedef struct ref_card {
    long number;       /* surface or TR number */
    long tr;           /* surface: TR number (0 none) */
    int degrees;       /* TR: *TRn or TRn* */
    char mnem[8];      /* surface: upper-case mnemonic */
    int n;             /* entries */
    double e[REF_MAX_ENTRIES];
} ref_card;

typedef struct ref_deck {
    ref_card surf[REF_MAX_CARDS], tr[REF_MAX_CARDS];
    int nsurf, ntr;
} ref_deck;

/* Reads the tokens of one card into c (after the name tokens). */
static inline void ref_entries(const char *s, ref_card *c)
{
    char *end;
    while (*s) {
        while (*s == ' ') ++s;
        if (!*s || *s == '\n') break;
        double v = strtod(s, &end);
        if (end == s) break;
        c->e[c->n++] = v;
        s = end;
    }
}

/* Splits text into blocks at blank lines: title+cells, surfaces, data. Lines starting with five
 * blanks continue the previous card. */
static inline void ref_read_deck(const char *text, ref_deck *d)
{
    memset(d, 0, sizeof *d);
    int block = 0;
    ref_card *cur = NULL;
    const char *p = text;
    while (*p) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        char line[512];
        memcpy(line, p, len);
        line[len] = 0;
        p += len + (eol ? 1 : 0);
        if (len == 0) { ++block; cur = NULL; continue; }
        if (block == 0) continue;
        if (strncmp(line, "     ", 5) == 0 && cur) { ref_entries(line, cur); continue; }
        char *s = line, *end;
        if (block == 1) {
            cur = &d->surf[d->nsurf++];
            cur->number = strtol(s, &end, 10);
            s = end;
            long t = strtol(s, &end, 10);
            if (end != s) { cur->tr = t; s = end; }
            while (*s == ' ') ++s;
            int k = 0;
            while (isalpha((unsigned char)*s) && k < 7) cur->mnem[k++] = (char)toupper((unsigned char)*s++);
            ref_entries(s, cur);
        } else if (block == 2) {
            cur = &d->tr[d->ntr++];
            if (*s == '*') { cur->degrees = 1; ++s; }
            s += 2; /* "tr" */
            cur->number = strtol(s, &end, 10);
            s = end;
            if (*s == '*') { cur->degrees = 1; ++s; }
            ref_entries(s, cur);
        }
    }
}

/* A TRn as a map: O, B (columns = x', y', z' in main coordinates), M. */
typedef struct ref_tr {
    prox_vec3 o, col[3];
    int m;
} ref_tr;

static inline ref_tr ref_tr_of(const ref_card *c)
{
    ref_tr t;
    t.o = prox_v3(c->e[0], c->e[1], c->e[2]);
    double b[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; /* 3 entries: no rotation */
    int nb = c->n >= 12 ? 9 : c->n - 3;
    for (int i = 0; i < nb; ++i) b[i] = c->degrees ? cos(c->e[3 + i] * (REF_PI / 180.0)) : c->e[3 + i];
    t.col[0] = prox_v3(b[0], b[1], b[2]);
    t.col[1] = prox_v3(b[3], b[4], b[5]);
    t.col[2] = nb == 9 ? prox_v3(b[6], b[7], b[8]) : prox_v3_cross(t.col[0], t.col[1]);
    t.m = c->n == 13 ? (int)c->e[12] : 1;
    return t;
}

static inline prox_vec3 ref_tr_vec(const ref_tr *t, prox_vec3 v)
{
    return prox_v3_add(prox_v3_add(prox_v3_scale(t->col[0], v.x), prox_v3_scale(t->col[1], v.y)),
                       prox_v3_scale(t->col[2], v.z));
}

static inline prox_vec3 ref_tr_point(const ref_tr *t, prox_vec3 p)
{
    return t->m == -1 ? ref_tr_vec(t, prox_v3_sub(p, t->o)) : prox_v3_add(t->o, ref_tr_vec(t, p));
}

static inline prox_vec3 ref_v(const double *e) { return prox_v3(e[0], e[1], e[2]); }

/* p turned by angle th about the unit vector u (Rodrigues; p perpendicular to u). */
static inline prox_vec3 ref_turn(prox_vec3 p, prox_vec3 u, double th)
{
    return prox_v3_add(prox_v3_scale(p, cos(th)), prox_v3_scale(prox_v3_cross(u, p), sin(th)));
}

/* The shape the card defines (MCNP manual Sec. 3.2.2.4 and Table 3-4), in the card's own frame. */
static inline int ref_local_shape(const ref_card *c, prox_shape *s)
{
    const double *e = c->e;
    memset(s, 0, sizeof *s);
    if (!strcmp(c->mnem, "RPP")) {
        s->kind = PROX_SHAPE_RPP;
        s->u.rpp = (prox_rpp){e[0], e[1], e[2], e[3], e[4], e[5]};
    } else if (!strcmp(c->mnem, "BOX")) {
        s->kind = PROX_SHAPE_BOX;
        s->u.box.corner = ref_v(e);
        for (int k = 0; k < 3; ++k) s->u.box.edge[k] = ref_v(e + 3 + 3 * k);
    } else if (!strcmp(c->mnem, "SPH") || !strcmp(c->mnem, "S")) {
        s->kind = PROX_SHAPE_SPH;
        s->u.sph = (prox_sph){ref_v(e), e[3]};
    } else if (!strcmp(c->mnem, "SO")) {
        s->kind = PROX_SHAPE_SPH;
        s->u.sph = (prox_sph){prox_v3(0, 0, 0), e[0]};
    } else if (!strcmp(c->mnem, "RCC")) {
        s->kind = PROX_SHAPE_RCC;
        s->u.rcc = (prox_rcc){ref_v(e), ref_v(e + 3), e[6]};
    } else if (!strcmp(c->mnem, "TRC")) {
        s->kind = PROX_SHAPE_TRC;
        s->u.trc = (prox_trc){ref_v(e), ref_v(e + 3), e[6], e[7]};
    } else if (!strcmp(c->mnem, "REC")) {
        s->kind = PROX_SHAPE_REC;
        prox_vec3 h = ref_v(e + 3), a1 = ref_v(e + 6);
        prox_vec3 a2 = c->n == 12 ? ref_v(e + 9) : prox_v3_scale(prox_v3_normalize(prox_v3_cross(h, a1)), e[9]);
        s->u.rec = (prox_rec){ref_v(e), h, a1, a2};
    } else if (!strcmp(c->mnem, "ELL")) {
        s->kind = PROX_SHAPE_ELL;
        prox_vec3 v1 = ref_v(e), v2 = ref_v(e + 3);
        if (e[6] > 0) { /* foci and major radius */
            prox_vec3 f = prox_v3_sub(v2, v1);
            double half = 0.5 * prox_v3_norm(f);
            s->u.ell = (prox_ell){prox_v3_scale(prox_v3_add(v1, v2), 0.5), prox_v3_scale(prox_v3_normalize(f), e[6]),
                                  sqrt((e[6] - half) * (e[6] + half))};
        } else { /* centre, major semi-axis vector, minor radius */
            s->u.ell = (prox_ell){v1, v2, -e[6]};
        }
    } else if (!strcmp(c->mnem, "RHP") || !strcmp(c->mnem, "HEX")) {
        s->kind = PROX_SHAPE_RHP;
        prox_vec3 h = ref_v(e + 3), r = ref_v(e + 6), u = prox_v3_normalize(h);
        s->u.rhp.base = ref_v(e);
        s->u.rhp.axis = h;
        s->u.rhp.r[0] = r;
        s->u.rhp.r[1] = c->n == 15 ? ref_v(e + 9) : ref_turn(r, u, REF_PI / 3);
        s->u.rhp.r[2] = c->n == 15 ? ref_v(e + 12) : ref_turn(r, u, 2 * REF_PI / 3);
    } else if (!strcmp(c->mnem, "WED")) {
        s->kind = PROX_SHAPE_WED;
        s->u.wed = (prox_wed){ref_v(e), ref_v(e + 3), ref_v(e + 6), ref_v(e + 9)};
    } else if (!strcmp(c->mnem, "ARB")) {
        s->kind = PROX_SHAPE_ARB;
        for (int k = 0; k < 8; ++k) s->u.arb.corner[k] = ref_v(e + 3 * k);
        for (int k = 0; k < 6; ++k) s->u.arb.face[k] = (int)e[24 + k];
    } else {
        return 0;
    }
    return 1;
}

/* The shape moved by a TR: points through O + B p (or B (p - O)), vectors through B v. */
static inline void ref_move(prox_shape *s, const ref_tr *t)
{
#define P_(x) (x) = ref_tr_point(t, (x))
#define V_(x) (x) = ref_tr_vec(t, (x))
    switch (s->kind) {
    case PROX_SHAPE_BOX: P_(s->u.box.corner); for (int k = 0; k < 3; ++k) V_(s->u.box.edge[k]); break;
    case PROX_SHAPE_SPH: P_(s->u.sph.center); break;
    case PROX_SHAPE_RCC: P_(s->u.rcc.base); V_(s->u.rcc.axis); break;
    case PROX_SHAPE_TRC: P_(s->u.trc.base); V_(s->u.trc.axis); break;
    case PROX_SHAPE_REC: P_(s->u.rec.base); V_(s->u.rec.axis); V_(s->u.rec.a1); V_(s->u.rec.a2); break;
    case PROX_SHAPE_ELL: P_(s->u.ell.center); V_(s->u.ell.axis); break;
    case PROX_SHAPE_RHP: P_(s->u.rhp.base); V_(s->u.rhp.axis); for (int k = 0; k < 3; ++k) V_(s->u.rhp.r[k]); break;
    case PROX_SHAPE_WED: P_(s->u.wed.vertex); V_(s->u.wed.v1); V_(s->u.wed.v2); V_(s->u.wed.v3); break;
    case PROX_SHAPE_ARB: for (int k = 0; k < 8; ++k) P_(s->u.arb.corner[k]); break;
    case PROX_SHAPE_RPP: { /* under a rotation that is not an axis permutation: the BOX it describes */
        prox_rpp r = s->u.rpp;
        s->kind = PROX_SHAPE_BOX;
        s->u.box.corner = ref_tr_point(t, prox_v3(r.xmin, r.ymin, r.zmin));
        s->u.box.edge[0] = ref_tr_vec(t, prox_v3(r.xmax - r.xmin, 0, 0));
        s->u.box.edge[1] = ref_tr_vec(t, prox_v3(0, r.ymax - r.ymin, 0));
        s->u.box.edge[2] = ref_tr_vec(t, prox_v3(0, 0, r.zmax - r.zmin));
    } break;
    default: break;
    }
#undef P_
#undef V_
}

/* ---- geometry of one body ---- */

#define REF_MAX_CORNERS 16
#define REF_MAX_PLANES 600

typedef struct ref_body {
    prox_shape_kind kind;
    int poly; /* 1: convex polytope given by corners and planes */
    int ncorner, nplane;
    prox_vec3 corner[REF_MAX_CORNERS];
    prox_vec3 pn[REF_MAX_PLANES]; /* unit outward normals */
    double pb[REF_MAX_PLANES];    /* n . x <= b inside */
    prox_vec3 c, w;               /* centre (mid-axis), unit axis */
    double hh, r, r1, r2;         /* half height; radius; TRC base and top radii */
    prox_vec3 base, a1, a2;       /* TRC base centre; REC semi-axes */
    double a, b;                  /* ELL: semi-axis along w, equatorial radius */
} ref_body;

/* Facet planes of the hull of the corners: every plane through three corners with all corners on
 * one side (brute force; duplicates are harmless). */
static inline void ref_hull_planes(ref_body *g)
{
    g->nplane = 0;
    double L = 0;
    for (int i = 0; i < g->ncorner; ++i) L = fmax(L, prox_v3_maxabs(g->corner[i]));
    for (int i = 0; i < g->ncorner; ++i)
        for (int j = i + 1; j < g->ncorner; ++j)
            for (int k = j + 1; k < g->ncorner; ++k) {
                prox_vec3 n = prox_v3_cross(prox_v3_sub(g->corner[j], g->corner[i]), prox_v3_sub(g->corner[k], g->corner[i]));
                double nn = prox_v3_norm(n);
                if (nn < 1e-9 * L * L) continue;
                n = prox_v3_scale(n, 1.0 / nn);
                double b = prox_v3_dot(n, g->corner[i]), lo = 0, hi = 0;
                for (int m = 0; m < g->ncorner; ++m) {
                    double s = prox_v3_dot(n, g->corner[m]) - b;
                    lo = fmin(lo, s), hi = fmax(hi, s);
                }
                if (lo < -1e-12 * L && hi > 1e-12 * L) continue;
                if (lo < -1e-12 * L) { /* all below: n is outward */
                } else { n = prox_v3_neg(n); b = -b; }
                if (g->nplane < REF_MAX_PLANES) g->pn[g->nplane] = n, g->pb[g->nplane++] = b;
            }
}

static inline void ref_add_corner(ref_body *g, prox_vec3 p) { g->corner[g->ncorner++] = p; }

/* Corners of the hexagon: the meeting point of adjacent side lines x.q_k = |q_k|^2. */
static inline void ref_rhp_corners(ref_body *g, const prox_rhp *h)
{
    prox_vec3 q[6] = {h->r[0], h->r[1], h->r[2], prox_v3_neg(h->r[0]), prox_v3_neg(h->r[1]), prox_v3_neg(h->r[2])};
    for (int k = 0; k < 6; ++k) {
        prox_vec3 p = q[k], s = q[(k + 1) % 6];
        double pp = prox_v3_dot(p, p), ss = prox_v3_dot(s, s), ps = prox_v3_dot(p, s), det = pp * ss - ps * ps;
        double al = (pp * ss - ps * ss) / det, be = (pp * ss - ps * pp) / det;
        prox_vec3 x = prox_v3_add(prox_v3_add(h->base, prox_v3_scale(p, al)), prox_v3_scale(s, be));
        ref_add_corner(g, x);
        ref_add_corner(g, prox_v3_add(x, h->axis));
    }
}

static inline ref_body ref_body_of(const prox_shape *s)
{
    ref_body g;
    memset(&g, 0, sizeof g);
    g.kind = s->kind;
    switch (s->kind) {
    case PROX_SHAPE_RPP: {
        const prox_rpp *r = &s->u.rpp;
        for (int k = 0; k < 8; ++k)
            ref_add_corner(&g, prox_v3(k & 1 ? r->xmax : r->xmin, k & 2 ? r->ymax : r->ymin, k & 4 ? r->zmax : r->zmin));
        g.poly = 1;
    } break;
    case PROX_SHAPE_BOX: {
        const prox_box *b = &s->u.box;
        for (int k = 0; k < 8; ++k) {
            prox_vec3 p = b->corner;
            for (int i = 0; i < 3; ++i)
                if (k & (1 << i)) p = prox_v3_add(p, b->edge[i]);
            ref_add_corner(&g, p);
        }
        g.poly = 1;
    } break;
    case PROX_SHAPE_WED: {
        const prox_wed *w = &s->u.wed;
        prox_vec3 t[3] = {w->vertex, prox_v3_add(w->vertex, w->v1), prox_v3_add(w->vertex, w->v2)};
        for (int k = 0; k < 3; ++k) ref_add_corner(&g, t[k]), ref_add_corner(&g, prox_v3_add(t[k], w->v3));
        g.poly = 1;
    } break;
    case PROX_SHAPE_RHP: ref_rhp_corners(&g, &s->u.rhp); g.poly = 1; break;
    case PROX_SHAPE_ARB: {
        int used[8] = {0};
        for (int f = 0; f < 6; ++f)
            for (int v = s->u.arb.face[f]; v > 0; v /= 10)
                if (v % 10) used[v % 10 - 1] = 1;
        for (int k = 0; k < 8; ++k)
            if (used[k]) ref_add_corner(&g, s->u.arb.corner[k]);
        g.poly = 1;
    } break;
    case PROX_SHAPE_SPH: g.c = s->u.sph.center; g.r = s->u.sph.radius; break;
    case PROX_SHAPE_RCC:
        g.hh = 0.5 * prox_v3_norm(s->u.rcc.axis);
        g.w = prox_v3_normalize(s->u.rcc.axis);
        g.c = prox_v3_mad(s->u.rcc.base, 0.5, s->u.rcc.axis);
        g.r = s->u.rcc.radius;
        break;
    case PROX_SHAPE_TRC:
        g.hh = 0.5 * prox_v3_norm(s->u.trc.axis);
        g.w = prox_v3_normalize(s->u.trc.axis);
        g.c = prox_v3_mad(s->u.trc.base, 0.5, s->u.trc.axis);
        g.base = s->u.trc.base;
        g.r1 = s->u.trc.r1, g.r2 = s->u.trc.r2;
        break;
    case PROX_SHAPE_REC:
        g.hh = 0.5 * prox_v3_norm(s->u.rec.axis);
        g.w = prox_v3_normalize(s->u.rec.axis);
        g.c = prox_v3_mad(s->u.rec.base, 0.5, s->u.rec.axis);
        g.a1 = s->u.rec.a1, g.a2 = s->u.rec.a2;
        break;
    case PROX_SHAPE_ELL:
        g.c = s->u.ell.center;
        g.a = prox_v3_norm(s->u.ell.axis);
        g.w = prox_v3_normalize(s->u.ell.axis);
        g.b = s->u.ell.radius;
        break;
    default: break;
    }
    if (g.poly) {
        ref_hull_planes(&g);
        g.c = prox_v3(0, 0, 0);
        for (int k = 0; k < g.ncorner; ++k) g.c = prox_v3_add(g.c, g.corner[k]);
        g.c = prox_v3_scale(g.c, 1.0 / g.ncorner);
    }
    return g;
}

/* Support function h(d) = max over the body of d.x, and a point where it is reached. */
static inline double ref_h(const ref_body *g, prox_vec3 d, prox_vec3 *at)
{
    prox_vec3 p;
    if (g->poly) {
        int best = 0;
        for (int k = 1; k < g->ncorner; ++k)
            if (prox_v3_dot(d, g->corner[k]) > prox_v3_dot(d, g->corner[best])) best = k;
        p = g->corner[best];
    } else if (g->kind == PROX_SHAPE_SPH) {
        p = prox_v3_mad(g->c, g->r / prox_v3_norm(d), d);
    } else if (g->kind == PROX_SHAPE_ELL) { /* c + M d / sqrt(d.M d), M = b^2 I + (a^2 - b^2) w w^T */
        prox_vec3 md = prox_v3_mad(prox_v3_scale(d, g->b * g->b), (g->a * g->a - g->b * g->b) * prox_v3_dot(d, g->w), g->w);
        p = prox_v3_mad(g->c, 1.0 / sqrt(prox_v3_dot(d, md)), md);
    } else if (g->kind == PROX_SHAPE_REC) { /* c + hh sgn(d.w) w + (a1 (d.a1) + a2 (d.a2)) / sqrt(...) */
        double s1 = prox_v3_dot(d, g->a1), s2 = prox_v3_dot(d, g->a2), q = hypot(s1, s2);
        p = prox_v3_mad(g->c, prox_v3_dot(d, g->w) >= 0 ? g->hh : -g->hh, g->w);
        if (q > 0) p = prox_v3_add(p, prox_v3_scale(prox_v3_add(prox_v3_scale(g->a1, s1), prox_v3_scale(g->a2, s2)), 1.0 / q));
    } else { /* RCC, TRC: the better of the two rims */
        prox_vec3 rad = prox_v3_reject(d, g->w);
        double q = prox_v3_norm(rad);
        prox_vec3 e = q > 0 ? prox_v3_scale(rad, 1.0 / q) : prox_v3(0, 0, 0);
        double rb = g->kind == PROX_SHAPE_RCC ? g->r : g->r1, rt = g->kind == PROX_SHAPE_RCC ? g->r : g->r2;
        prox_vec3 pb = prox_v3_mad(prox_v3_mad(g->c, -g->hh, g->w), rb, e);
        prox_vec3 pt = prox_v3_mad(prox_v3_mad(g->c, g->hh, g->w), rt, e);
        p = prox_v3_dot(d, pt) >= prox_v3_dot(d, pb) ? pt : pb;
    }
    if (at) *at = p;
    return prox_v3_dot(d, p);
}

/* Closed-form support functions of the brief, as a second evaluation of h for the curved kinds:
 * RCC d.c + r|P_w d| + hh|d.w|; REC d.c + hh|d.w| + sqrt((d.a1)^2 + (d.a2)^2);
 * ELL d.c + sqrt(b^2 |d|^2 + (a^2 - b^2)(d.w)^2); TRC the larger of its rims' supports. */
static inline double ref_h_formula(const ref_body *g, prox_vec3 d)
{
    double dw = prox_v3_dot(d, g->w), pd = prox_v3_norm(prox_v3_reject(d, g->w)), dc = prox_v3_dot(d, g->c);
    switch (g->kind) {
    case PROX_SHAPE_RCC: return dc + g->r * pd + g->hh * fabs(dw);
    case PROX_SHAPE_TRC: return fmax(dc - g->hh * dw + g->r1 * pd, dc + g->hh * dw + g->r2 * pd);
    case PROX_SHAPE_REC: return dc + g->hh * fabs(dw) + hypot(prox_v3_dot(d, g->a1), prox_v3_dot(d, g->a2));
    case PROX_SHAPE_ELL: return dc + sqrt(g->b * g->b * prox_v3_norm2(d) + (g->a * g->a - g->b * g->b) * dw * dw);
    case PROX_SHAPE_SPH: return dc + g->r * prox_v3_norm(d);
    default: return ref_h(g, d, NULL);
    }
}

/* Distance from (y0, y1) >= 0 to the ellipse (x0/e0)^2 + (x1/e1)^2 = 1, e0 >= e1 > 0, negative
 * inside (D. Eberly, "Distance from a point to an ellipse, an ellipsoid, or a hyperellipsoid",
 * Geometric Tools 2013: bisection for the root of F(s) on the scaled problem). */
static inline double ref_ellipse_sd(double e0, double e1, double y0, double y1)
{
    double d;
    if (y1 > 0) {
        if (y0 > 0) {
            double z0 = y0 / e0, z1 = y1 / e1, g = z0 * z0 + z1 * z1 - 1;
            if (g == 0) return 0;
            double r0 = (e0 / e1) * (e0 / e1), n0 = r0 * z0, s0 = z1 - 1, s1 = g < 0 ? 0 : hypot(n0, z1) - 1, s = 0;
            for (int i = 0; i < 1100; ++i) {
                s = 0.5 * (s0 + s1);
                if (s == s0 || s == s1) break;
                double q0 = n0 / (s + r0), q1 = z1 / (s + 1), gg = q0 * q0 + q1 * q1 - 1;
                if (gg > 0) s0 = s;
                else if (gg < 0) s1 = s;
                else break;
            }
            double x0 = r0 * y0 / (s + r0), x1 = y1 / (s + 1);
            d = hypot(x0 - y0, x1 - y1);
            return g < 0 ? -d : d;
        }
        return y1 - e1;
    }
    double num = e0 * y0, den = e0 * e0 - e1 * e1;
    if (num < den) {
        double xd = num / den, x0 = e0 * xd, x1 = e1 * sqrt(1 - xd * xd);
        d = hypot(x0 - y0, x1);
        return -d; /* only points inside reach the ellipse off the axis */
    }
    return y0 - e0;
}

/* Membership: <= 0 inside; where positive, at most the distance to the body (a lower bound). For
 * SPH, ELL and the polytopes' interior it is the exact signed distance inside. */
static inline double ref_f(const ref_body *g, prox_vec3 x)
{
    if (g->poly) {
        double m = -INFINITY;
        for (int k = 0; k < g->nplane; ++k) m = fmax(m, prox_v3_dot(g->pn[k], x) - g->pb[k]);
        return m;
    }
    prox_vec3 d = prox_v3_sub(x, g->c);
    double t = prox_v3_dot(d, g->w), rho = prox_v3_norm(prox_v3_reject(d, g->w)), cap = fabs(t) - g->hh;
    switch (g->kind) {
    case PROX_SHAPE_SPH: return prox_v3_norm(d) - g->r;
    case PROX_SHAPE_RCC: return fmax(rho - g->r, cap);
    case PROX_SHAPE_TRC: { /* distance to the slant line, times its cosine */
        double h = 2 * g->hh, rt = g->r1 + (g->r2 - g->r1) * (t + g->hh) / h;
        return fmax((rho - rt) * h / hypot(h, g->r1 - g->r2), cap);
    }
    case PROX_SHAPE_REC: { /* homothetic ellipses are at least (k - 1) b_min apart */
        double n1 = prox_v3_norm2(g->a1), n2 = prox_v3_norm2(g->a2);
        double u1 = prox_v3_dot(d, g->a1) / n1, u2 = prox_v3_dot(d, g->a2) / n2;
        return fmax((hypot(u1, u2) - 1) * sqrt(fmin(n1, n2)), cap);
    }
    case PROX_SHAPE_ELL:
        return g->a >= g->b ? ref_ellipse_sd(g->a, g->b, fabs(t), rho) : ref_ellipse_sd(g->b, g->a, rho, fabs(t));
    default: return NAN;
    }
}

#endif
