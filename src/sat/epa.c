/* The depth's lower bound by an expanding inner polytope (epa.h). */
#include "epa.h"

#include "core/minmax.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define EPA_MAXV 320  /* points: the engine's largest cap (CVX_EPA_POINTS_SMOOTH, convex.c) fits */
#define EPA_MAXF 1280 /* faces: a closed mesh of n points has 2n - 4, with room for the fans in flight */

typedef struct epa_face {
    int v[3];      /* corners, counter-clockwise seen from outside */
    int adj[3];    /* the face across edge (v[i], v[i+1]) */
    int live;
    int flat;      /* no plane: a zero cross product (two corners equal, or all on a line) */
    int pos;       /* proved counter-clockwise seen from the origin (its plane passes beyond it) */
    prox_vec3 n;   /* unit normal (flat: none) */
    double d;      /* n . v[0] */
    prox_vec3 u;   /* the unit direction of the face's point nearest the origin */
    int edge;      /* the side (v[edge], v[edge + 1]) that point lies on when u is taken along it, else -1 */
} epa_face;

typedef struct epa {
    prox_vec3 p[EPA_MAXV];
    double pn[EPA_MAXV]; /* |p|, once per point (every face at it reads it) */
    int np;
    epa_face f[EPA_MAXF];
    double key[EPA_MAXF]; /* proven: every point of face f is at least key[f] from the origin (INFINITY: gone) */
    int nf;
    int freel[EPA_MAXF];
    int nfree;
} epa;

/* The least and the largest of three values, not NaN, without a library call (core/minmax.h): every
 * new face takes four. */
static inline double min3(double x, double y, double z) { return prox_min2(prox_min2(x, y), z); }
static inline double max3(double x, double y, double z) { return prox_max2(prox_max2(x, y), z); }

/* The point of segment ab nearest the origin. */
static prox_vec3 seg_near(prox_vec3 a, prox_vec3 b)
{
    prox_vec3 e = prox_v3_sub(b, a);
    double ee = prox_v3_norm2(e), t = ee > 0.0 ? -prox_v3_dot(a, e) / ee : 0.0;
    return prox_v3_mad(a, t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t), e);
}

/* The point of triangle abc nearest the origin (approximately: it only chooses the direction of
 * the face's bound): the origin's foot on the plane when it lies inside, else the nearest of the
 * three sides. */
static prox_vec3 tri_near(prox_vec3 a, prox_vec3 b, prox_vec3 c, prox_vec3 n, int flat, int *edge)
{
    *edge = -1;
    if (!flat) {
        prox_vec3 p = prox_v3_scale(n, prox_v3_dot(n, a));
        prox_vec3 pa = prox_v3_sub(a, p), pb = prox_v3_sub(b, p), pc = prox_v3_sub(c, p);
        if (prox_v3_dot(prox_v3_cross(pb, pc), n) >= 0.0 && prox_v3_dot(prox_v3_cross(pc, pa), n) >= 0.0 &&
            prox_v3_dot(prox_v3_cross(pa, pb), n) >= 0.0)
            return p;
    }
    prox_vec3 q[3] = {seg_near(a, b), seg_near(b, c), seg_near(c, a)};
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (prox_v3_norm2(q[i]) < prox_v3_norm2(q[k])) k = i;
    *edge = k;
    return q[k];
}

/* The face's plane and its proven bound. Any unit u gives min(u.a, u.b, u.c) <= u.x <= |x| for every
 * point x of the face (weak duality). u = the normal gives the plane's distance, which is the face's
 * own when the origin's foot lies inside it; a sliver or flat face (whose plane is rounding, or
 * none), or one whose plane passes the origin, takes u along its nearest point instead. The bound
 * holds whatever the rounding of u (only |u| = 1 to 2 eps matters) less the dots' own rounding:
 * 6 eps of the largest corner. The orientation is proved when n . a exceeds its error: the cross
 * product x of the edges e1, e2 is off by 3 eps |e1| |e2| per component, the dot by 3 eps |a| |x|. */
static void face_plane(epa *E, int k)
{
    epa_face *f = &E->f[k];
    prox_vec3 a = E->p[f->v[0]], b = E->p[f->v[1]], c = E->p[f->v[2]];
    prox_vec3 e1 = prox_v3_sub(b, a), e2 = prox_v3_sub(c, a), x = prox_v3_cross(e1, e2);
    double nx = prox_v3_norm(x), la = E->pn[f->v[0]];
    double big = 6.0 * DBL_EPSILON * max3(la, E->pn[f->v[1]], E->pn[f->v[2]]);
    f->flat = !(nx > 0.0);
    f->n = f->flat ? prox_v3(0, 0, 0) : prox_v3_scale(x, 1.0 / nx);
    f->d = prox_v3_dot(f->n, a);
    f->u = f->n;
    f->edge = -1;
    double key = min3(f->d, prox_v3_dot(f->n, b), prox_v3_dot(f->n, c)) - big;
    f->pos = !f->flat && f->d > 6.0 * DBL_EPSILON * la * (sqrt(prox_v3_norm2(e1) * prox_v3_norm2(e2)) / nx + 1.0);
    if (!f->pos || !(key > 1e3 * big)) {
        int edge;
        prox_vec3 q = tri_near(a, b, c, f->n, f->flat, &edge);
        double nq = prox_v3_norm(q);
        if (nq > 0.0) {
            prox_vec3 u = prox_v3_scale(q, 1.0 / nq);
            double m = min3(prox_v3_dot(u, a), prox_v3_dot(u, b), prox_v3_dot(u, c)) - big;
            if (f->flat || m > key) f->u = u, f->edge = edge, key = m;
        }
    }
    E->key[k] = key;
}

static int face_new(epa *E, int a, int b, int c)
{
    int k = E->nfree > 0 ? E->freel[--E->nfree] : (E->nf < EPA_MAXF ? E->nf++ : -1);
    if (k < 0) return -1;
    epa_face *f = &E->f[k];
    f->v[0] = a, f->v[1] = b, f->v[2] = c;
    f->adj[0] = f->adj[1] = f->adj[2] = -1;
    f->live = 1;
    face_plane(E, k);
    return k;
}

/* The edge of face g that runs from b to a (the reverse of a -> b), or -1. */
static int edge_back(const epa_face *g, int a, int b)
{
    for (int j = 0; j < 3; ++j)
        if (g->v[j] == b && g->v[(j + 1) % 3] == a) return j;
    return -1;
}

/* Links the starting faces (corners < 12) across their edges through a table of directed edges;
 * 0 when an edge has no reverse (the mesh is not closed). */
static int link_all(epa *E)
{
    signed char at[12][12];
    memset(at, -1, sizeof at);
    for (int i = 0; i < E->nf; ++i)
        for (int j = 0; j < 3; ++j) at[E->f[i].v[j]][E->f[i].v[(j + 1) % 3]] = (signed char)i;
    for (int i = 0; i < E->nf; ++i)
        for (int j = 0; j < 3; ++j)
            if ((E->f[i].adj[j] = at[E->f[i].v[(j + 1) % 3]][E->f[i].v[j]]) < 0) return 0;
    return 1;
}

/* The live face of least bound (the one that bounds the depth). */
static int nearest(const epa *E)
{
    int best = -1;
    double k = INFINITY;
    for (int i = 0; i < E->nf; ++i)
        if (E->key[i] < k) k = E->key[i], best = i;
    return best;
}

/* Replaces face f0 and the faces point w (index iw) sees from there, across edges (a face is seen
 * when w lies beyond its plane; a flat face reached from a seen one is taken with them), by the fan
 * from w over their rim. The mesh stays closed whatever the faces' orientations (the bound needs
 * only that it wraps the origin, checked at the end). 0 when the rim is not made of simple loops or a
 * face cannot be made. */
static int expand(epa *E, int f0, int iw)
{
    int seen[EPA_MAXF], stack[EPA_MAXF], ns = 0, nseen = 0;
    prox_vec3 w = E->p[iw];
    E->f[f0].live = 2; /* 2: seen in this step */
    stack[ns++] = f0;
    /* a face bounded by its side nearest the origin keeps that bound while the side stays: the face
     * across it goes too (else a fold whose side passes inside P's depth is rebuilt from w again) */
    int across = E->f[f0].edge >= 0 ? E->f[f0].adj[E->f[f0].edge] : -1;
    if (across >= 0 && E->f[across].live == 1) E->f[across].live = 2, stack[ns++] = across;
    while (ns > 0) {
        int i = stack[--ns];
        seen[nseen++] = i;
        for (int j = 0; j < 3; ++j) {
            int g = E->f[i].adj[j];
            if (E->f[g].live != 1) continue;
            if (E->f[g].flat || prox_v3_dot(E->f[g].n, w) > E->f[g].d) E->f[g].live = 2, stack[ns++] = g;
        }
    }
    /* the rim: edges of seen faces whose neighbour stays, each becomes a face (a, b, w) */
    int ra[64], rb[64], rg[64], nr = 0;
    for (int s = 0; s < nseen; ++s) {
        const epa_face *f = &E->f[seen[s]];
        for (int j = 0; j < 3; ++j) {
            int g = f->adj[j];
            if (E->f[g].live != 1) continue;
            if (nr == 64) return 0;
            ra[nr] = f->v[j], rb[nr] = f->v[(j + 1) % 3], rg[nr] = g, ++nr;
        }
    }
    for (int r = 0; r < nr; ++r) /* simple loops: every rim corner starts exactly one rim edge */
        for (int q = r + 1; q < nr; ++q)
            if (ra[r] == ra[q]) return 0;
    for (int s = 0; s < nseen; ++s) E->f[seen[s]].live = 0, E->key[seen[s]] = INFINITY, E->freel[E->nfree++] = seen[s];
    int nf[64];
    for (int r = 0; r < nr; ++r) {
        nf[r] = face_new(E, ra[r], rb[r], iw);
        if (nf[r] < 0) return 0;
        epa_face *g = &E->f[rg[r]];
        int j = edge_back(g, ra[r], rb[r]);
        if (j < 0) return 0;
        g->adj[j] = nf[r];
        E->f[nf[r]].adj[0] = rg[r];
    }
    for (int r = 0; r < nr; ++r) { /* edge (b, w) meets the face of the rim edge starting at b */
        int q = 0;
        while (q < nr && ra[q] != rb[r]) ++q;
        if (q == nr) return 0;
        E->f[nf[r]].adj[1] = nf[q];
        E->f[nf[q]].adj[2] = nf[r];
    }
    return 1;
}

/* Every direction from the origin meets a face. So it does when every face is proved
 * counter-clockwise seen from the origin: the mesh is closed, so its degree about the origin (the
 * number of faces a ray meets, each counted with its orientation's sign) is the same for every ray,
 * and all signs are positive. Else its degree from the triangles' signed solid angles (Van Oosterom
 * and Strackee 1983: they add up to 4 pi times the degree) must be 1 (to within a half turn: the
 * sum's rounding is far smaller); every face is at least the bound > 0 away, so each angle is
 * defined. */
static int covers(const epa *E)
{
    int all = 1;
    for (int i = 0; i < E->nf; ++i) all &= !E->f[i].live || E->f[i].pos;
    if (all) return 1;
    double sum = 0.0;
    for (int i = 0; i < E->nf; ++i) {
        const epa_face *f = &E->f[i];
        if (!f->live) continue;
        prox_vec3 a = E->p[f->v[0]], b = E->p[f->v[1]], c = E->p[f->v[2]];
        double la = E->pn[f->v[0]], lb = E->pn[f->v[1]], lc = E->pn[f->v[2]];
        double num = prox_v3_dot(a, prox_v3_cross(b, c));
        double den = la * lb * lc + prox_v3_dot(a, b) * lc + prox_v3_dot(a, c) * lb + prox_v3_dot(b, c) * la;
        sum += 2.0 * atan2(num, den);
    }
    return fabs(sum - 4.0 * PROX_PI) < PROX_PI;
}

/* Proved: the bound reaches the upper one and the mesh covers every direction. */
static int proved(const epa *E, prox_epa_result *out, double tol)
{
    if (!(out->lower >= out->upper - tol)) return 0;
    if (covers(E)) return 1;
    out->lower = -INFINITY;
    return 0;
}

int prox_epa_depth(prox_epa_support fs, void *ctx, const prox_vec3 *v, int nv, const unsigned char (*tri)[3], int nt,
                   double upper, prox_vec3 dir, double tol, double slack, int max_points, prox_epa_result *out)
{
    epa E;
    E.np = nv, E.nf = 0, E.nfree = 0;
    out->lower = -INFINITY, out->upper = upper, out->dir = dir, out->points = nv;
    if (nv > 12 || nt > 20) return 0;
    for (int i = 0; i < nv; ++i) E.p[i] = v[i], E.pn[i] = prox_v3_norm(v[i]);
    for (int t = 0; t < nt; ++t) face_new(&E, tri[t][0], tri[t][1], tri[t][2]);
    if (!link_all(&E) || !covers(&E)) { out->points = 0; return 0; } /* folded about the origin */
    if (max_points > EPA_MAXV) max_points = EPA_MAXV;
    for (;;) {
        int i = nearest(&E);
        if (i < 0) return 0;
        out->lower = E.key[i] - slack;
        if (out->lower >= out->upper - tol) return proved(&E, out, tol);
        if (E.np >= max_points) break;
        prox_vec3 u = E.f[i].u;
        if (!(prox_v3_norm2(u) > 0.0)) break; /* the origin on a flat face */
        double h;
        prox_vec3 w = fs(ctx, u, &h);
        if (h < out->upper) out->upper = h, out->dir = u;
        if (out->lower >= out->upper - tol) return proved(&E, out, tol);
        if (!(prox_v3_dot(u, w) > E.key[i] + slack) || !prox_v3_isfinite(w)) break; /* no point beyond it */
        E.p[E.np] = w, E.pn[E.np] = prox_v3_norm(w);
        if (!expand(&E, i, E.np++)) break;
        out->points = E.np;
    }
    out->lower = -INFINITY;
    return 0;
}
