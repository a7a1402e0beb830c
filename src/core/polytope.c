/* The prepared convex polytope (core/polytope.h) of BOX, RPP, RHP/HEX, WED and ARB.
 *
 * BOX, RPP, RHP and WED are right prisms over a polygon (rectangle, hexagon, triangle): one builder
 * makes the prism from the polygon's corners (counter-clockwise about the height), the height
 * vector and the MCNP facet number of each side, of the top and of the base. ARB is built from its
 * corners and face loops. Facet numbers follow the MCNP manual's macrobody tables
 * (docs/algorithms/polytopes.md gives them with their source):
 *   BOX 1..6: end of a1, start of a1, end of a2, start of a2, end of a3, start of a3;
 *   RPP 1..6: x = xmax, x = xmin, y = ymax, y = ymin, z = zmax, z = zmin;
 *   RHP 1..6: the side planes at +r, -r, +s, -s, +t, -t, 7 top (base + h), 8 base;
 *   WED 1 slant (through v + v1 and v + v2), 2 the side spanned by v2 and v3, 3 the side spanned by
 *       v1 and v3, 4 top (v + v3), 5 base;
 *   ARB k: the k-th face entry of the card. */
#include "core/minmax.h"
#include "core/polytope.h"
#include "core/tol.h"

#include <math.h>
#include <string.h>

/* ---- topology shared by every kind ---- */

/* Unit outward normal of a face loop by Newell's method (exact for a planar loop, the least-squares
 * plane's normal otherwise). */
static prox_vec3 newell_sum(const prox_polytope *p, int f)
{
    prox_vec3 s = prox_v3(0, 0, 0);
    int m = p->fnv[f];
    for (int i = 0; i < m; ++i) {
        prox_vec3 a = p->v[p->fv[f][i]], b = p->v[p->fv[f][i + 1 < m ? i + 1 : 0]];
        s.x += (a.y - b.y) * (a.z + b.z);
        s.y += (a.z - b.z) * (a.x + b.x);
        s.z += (a.x - b.x) * (a.y + b.y);
    }
    return s;
}

static prox_vec3 newell(const prox_polytope *p, int f)
{
    prox_vec3 s = newell_sum(p, f);
    double l = prox_v3_norm(s);
    return l > 0.0 ? prox_v3_scale(s, 1.0 / l) : s;
}

/* The face of each directed edge a -> b (the first in face order when an invalid loop repeats one),
 * -1 where none: one pass over the loops instead of a search per edge. */
static void edge_faces(const prox_polytope *p, signed char of[PROX_POLY_MAXV][PROX_POLY_MAXV])
{
    memset(of, -1, sizeof(signed char) * PROX_POLY_MAXV * PROX_POLY_MAXV);
    for (int f = 0; f < p->nf; ++f)
        for (int i = 0; i < p->fnv[f]; ++i) {
            int a = p->fv[f][i], b = p->fv[f][i + 1 < p->fnv[f] ? i + 1 : 0];
            if (of[a][b] < 0) of[a][b] = (signed char)f;
        }
}

/* Plane offsets: the mean of n_f . y over the face's corners. */
static void offsets(prox_polytope *p)
{
    for (int f = 0; f < p->nf; ++f) {
        double s = 0.0;
        for (int i = 0; i < p->fnv[f]; ++i) s += prox_v3_dot(p->n[f], p->v[p->fv[f][i]]);
        p->d[f] = p->fnv[f] == 4 ? s * 0.25 : s / p->fnv[f]; /* dividing by 4 is multiplying by 1/4 */
    }
}

/* The diameter: the largest squared distance, one square root (the corners lie within the supported
 * range, where no square overflows or underflows); *least: the smallest squared distance. */
static void diameter(prox_polytope *p, double *least)
{
    double s2 = 0.0, m2 = INFINITY;
    for (int i = 0; i < p->nv; ++i)
        for (int j = i + 1; j < p->nv; ++j) {
            double d2 = prox_v3_norm2(prox_v3_sub(p->v[i], p->v[j]));
            s2 = d2 > s2 ? d2 : s2;
            m2 = d2 < m2 ? d2 : m2;
        }
    p->size = sqrt(s2);
    *least = m2;
}

/* The diameter of a prism over an m-gon with height vector h (corners 0..m-1 at the base, m..2m-1
 * above them): the same largest squared distance as diameter(), found among the m^2 base-to-top
 * pairs alone when |h|^2 exceeds 1e-8 of the base's squared bounding-box diagonal E^2. Then each
 * pair (i, j) within a layer has a partner (i, m + j) longer by |h|^2 less 2 |(v_i - v_j) . h| and
 * rounding: the height may tilt off the polygon's normal by the card's tolerance (1e-9, so at most
 * 2e-9 E |h|) and the rest is rounding (about 1e-15 E |h| and 1e-15 E^2), all far below |h|^2.
 * So the largest pair lies across, and the maximum is the very value the full search returns.
 * Flatter prisms take the full search. */
static void prism_diameter(prox_polytope *p, int m, prox_vec3 h)
{
    prox_vec3 lo = p->v[0], hi = p->v[0];
    for (int i = 1; i < m; ++i) {
        prox_vec3 v = p->v[i];
        lo.x = v.x < lo.x ? v.x : lo.x, hi.x = v.x > hi.x ? v.x : hi.x;
        lo.y = v.y < lo.y ? v.y : lo.y, hi.y = v.y > hi.y ? v.y : hi.y;
        lo.z = v.z < lo.z ? v.z : lo.z, hi.z = v.z > hi.z ? v.z : hi.z;
    }
    double E2 = prox_v3_norm2(prox_v3_sub(hi, lo)), hh = prox_v3_norm2(h);
    if (!(hh > 1e-8 * E2) || !(hh < 1e300)) {
        double least;
        diameter(p, &least);
        return;
    }
    double s2 = 0.0;
    for (int i = 0; i < m; ++i)
        for (int j = m; j < 2 * m; ++j) {
            double d2 = prox_v3_norm2(prox_v3_sub(p->v[i], p->v[j]));
            s2 = d2 > s2 ? d2 : s2;
        }
    p->size = sqrt(s2);
}

/* Normals, plane offsets, edges and size from the corners and the outward face loops (the normals
 * by Newell's method). An ARB whose loops do not close into a surface (an edge without its reverse
 * in another face) gets ne = -1: the validator's test for an open surface. */
static void finish(prox_polytope *p, double *least)
{
    for (int f = 0; f < p->nf; ++f) p->n[f] = newell(p, f);
    offsets(p);
    signed char of[PROX_POLY_MAXV][PROX_POLY_MAXV];
    edge_faces(p, of);
    int ne = 0; /* a local count: the byte stores below may alias every field of p */
    for (int f = 0; f < p->nf; ++f) {
        int m = p->fnv[f];
        for (int i = 0; i < m; ++i) {
            int a = p->fv[f][i], b = p->fv[f][i + 1 < m ? i + 1 : 0];
            int g = of[b][a];
            if (g < 0 || ne < 0) {
                ne = -1;
                continue;
            }
            if (a > b) continue;
            if (ne >= PROX_POLY_MAXE) {
                ne = -1;
                continue;
            }
            p->e[ne][0] = (unsigned char)a;
            p->e[ne][1] = (unsigned char)b;
            p->ef[ne][0] = (unsigned char)f;
            p->ef[ne][1] = (unsigned char)g;
            ne++;
        }
    }
    p->ne = ne;
    diameter(p, least);
}

static void put_edge(prox_polytope *p, int a, int b, int f, int g)
{
    p->e[p->ne][0] = (unsigned char)a;
    p->e[p->ne][1] = (unsigned char)b;
    p->ef[p->ne][0] = (unsigned char)f;
    p->ef[p->ne][1] = (unsigned char)g;
    p->ne++;
}

/* The edges of the prism built by prism() over an m-gon (sides 0..m-1, top m, base m + 1), listed in
 * the order finish() finds them (face by face, each edge from the face where it runs up in corner
 * number): its topology is fixed, so no search is needed. */
static void prism_edges(prox_polytope *p, int m)
{
    p->ne = 0;
    for (int i = 0; i < m; ++i) {
        int k = i + 1 < m ? i + 1 : 0;
        if (i < m - 1) put_edge(p, i, k, i, m + 1); /* base edge, shared with the base */
        put_edge(p, k, m + k, i, k);                /* vertical edge at corner k, shared with side k */
        if (i == m - 1) put_edge(p, m, 2 * m - 1, i, m); /* top edge closing the loop */
    }
    for (int j = 0; j < m - 1; ++j) put_edge(p, m + j, m + j + 1, m, j);
    put_edge(p, 0, m - 1, m + 1, m - 1);
}

/* Moves the corners (given relative to the anchor o) to their centroid; returns the centroid (absolute). */
static prox_vec3 centre(prox_polytope *p, prox_vec3 o)
{
    prox_vec3 g = prox_v3(0, 0, 0);
    for (int i = 0; i < p->nv; ++i) g = prox_v3_add(g, p->v[i]);
    g = prox_v3_scale(g, 1.0 / p->nv);
    for (int i = 0; i < p->nv; ++i) p->v[i] = prox_v3_sub(p->v[i], g);
    return prox_v3_add(o, g);
}

/* The corners' bounding box (empty, lo > hi, without corners): prox_polytope_contains tests it. */
static void corner_box(prox_polytope *p)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < p->nv; ++i) {
        const double v[3] = {p->v[i].x, p->v[i].y, p->v[i].z};
        for (int k = 0; k < 3; ++k) {
            if (v[k] < lo[k]) lo[k] = v[k];
            if (v[k] > hi[k]) hi[k] = v[k];
        }
    }
    p->lo = prox_v3(lo[0], lo[1], lo[2]), p->hi = prox_v3(hi[0], hi[1], hi[2]);
}

/* Right prism over the polygon q[0..m-1] (relative to the anchor o) with height vector h; side i
 * runs from q[i] to q[i+1] and has facet number side[i] and unit outward normal sn[i] (the card's own
 * direction: a normal from the corners of a thin side would carry their rounding divided by its
 * height). The polygon may turn either way about h. */
static prox_vec3 prism(prox_polytope *p, prox_vec3 o, const prox_vec3 *q, const int *side, const prox_vec3 *sn, int m,
                       prox_vec3 h, int top, int base)
{
    prox_vec3 area = prox_v3(0, 0, 0);
    for (int i = 0; i < m; ++i) area = prox_v3_add(area, prox_v3_cross(q[i], q[i + 1 < m ? i + 1 : 0]));
    int rev = prox_v3_dot(area, h) < 0.0;
    p->nv = 2 * m;
    p->nf = m + 2;
    for (int i = 0; i < m; ++i) {
        int j = rev ? m - 1 - i : i;              /* polygon corner i in counter-clockwise order */
        int s = rev ? (2 * m - 2 - i >= m ? m - 2 - i : 2 * m - 2 - i) : i; /* side from corner i to i + 1 */
        p->v[i] = q[j];
        p->v[m + i] = prox_v3_add(q[j], h);
        p->facet[i] = side[s];
        p->n[i] = sn[s];
    }
    for (int i = 0; i < m; ++i) {
        int k = i + 1 < m ? i + 1 : 0;
        p->fnv[i] = 4;
        p->fv[i][0] = (unsigned char)i;
        p->fv[i][1] = (unsigned char)k;
        p->fv[i][2] = (unsigned char)(m + k);
        p->fv[i][3] = (unsigned char)(m + i);
        p->fv[m][i] = (unsigned char)(m + i);          /* top, counter-clockwise about h */
        p->fv[m + 1][i] = (unsigned char)(m - 1 - i);  /* base, clockwise about h */
    }
    p->fnv[m] = p->fnv[m + 1] = m;
    p->facet[m] = top;
    p->facet[m + 1] = base;
    prox_vec3 w = prox_v3_normalize(h);
    p->n[m] = w;
    p->n[m + 1] = prox_v3_neg(w);
    prox_vec3 c = centre(p, o);
    for (int f = p->nf; f < PROX_POLY_MAXF; ++f) p->fnv[f] = p->facet[f] = 0; /* no stale face */
    offsets(p);
    prism_edges(p, m);
    prism_diameter(p, m, h);
    corner_box(p);
    return c;
}

/* ---- the five kinds ---- */

static prox_vec3 make_box(const prox_box *b, const int facet[6], prox_polytope *p)
{
    const prox_vec3 *e = b->edge;
    prox_vec3 q[4] = {prox_v3(0, 0, 0), e[0], prox_v3_add(e[0], e[1]), e[1]};
    /* sides: start of a2 (q0-q1), end of a1 (q1-q2), end of a2 (q2-q3), start of a1 (q3-q0) */
    int side[4] = {facet[3], facet[0], facet[2], facet[1]};
    prox_vec3 u0 = prox_v3_normalize(e[0]), u1 = prox_v3_normalize(e[1]);
    prox_vec3 sn[4] = {prox_v3_neg(u1), u0, u1, prox_v3_neg(u0)};
    return prism(p, b->corner, q, side, sn, 4, e[2], facet[4], facet[5]);
}

/* A stand-in for atan2(y, x) with the same order on (-pi, pi] and the same signed-zero ends (-2 at
 * -pi, 2 at pi): 1 - x / (|x| + |y|) rises with the angle on each half-plane (the "pseudo-angle"),
 * one division instead of a library call. Angles that atan2 would order differently lie within
 * rounding of each other, and the validator rejects any such pair of sides. */
static double pseudo_angle(double x, double y) { return copysign(1.0 - x / (fabs(x) + fabs(y)), y); }

/* The six side lines of an RHP's cross-section sorted by angle (normals nl[k] in 2-D, offsets dl[k],
 * facet numbers fk[k]) and the corners where consecutive lines meet (Cramer's rule). */
void prox_rhp_hexagon(const prox_rhp *h, prox_rhp_section *hx)
{
    prox_vec3 w = prox_v3_normalize(h->axis);
    hx->e1 = prox_v3_normalize(prox_v3_reject(h->r[0], w));
    hx->e2 = prox_v3_cross(w, hx->e1);
    double ang[6], (*nl)[2] = hx->nl, *dl = hx->dl;
    int *fk = hx->fk;
    for (int i = 0; i < 3; ++i) {
        prox_vec3 r = prox_v3_reject(h->r[i], w);
        double len = prox_v3_norm(r);
        double x = prox_v3_dot(r, hx->e1) / len, y = prox_v3_dot(r, hx->e2) / len;
        double a = pseudo_angle(x, y), q = x / (fabs(x) + fabs(y));
        for (int s = 0; s < 2; ++s) {
            int k = 2 * i + s;
            nl[k][0] = s ? -x : x;
            nl[k][1] = s ? -y : y;
            dl[k] = len;
            fk[k] = k + 1;
            /* pseudo_angle(-x, -y), exactly: (-x) / D = -(x / D) and 1 - (-q) = 1 + q */
            ang[k] = s ? copysign(1.0 + q, -y) : a;
        }
    }
    for (int i = 1; i < 6; ++i) /* insertion sort by angle */
        for (int j = i; j > 0 && ang[j - 1] > ang[j]; --j) {
            double t = ang[j], tx = nl[j][0], ty = nl[j][1], td = dl[j];
            int tk = fk[j];
            ang[j] = ang[j - 1], nl[j][0] = nl[j - 1][0], nl[j][1] = nl[j - 1][1], dl[j] = dl[j - 1], fk[j] = fk[j - 1];
            ang[j - 1] = t, nl[j - 1][0] = tx, nl[j - 1][1] = ty, dl[j - 1] = td, fk[j - 1] = tk;
        }
    for (int k = 0; k < 6; ++k) {
        int j = (k + 1) % 6;
        double det = nl[k][0] * nl[j][1] - nl[k][1] * nl[j][0];
        hx->det[k] = det;
        hx->x[k][0] = (dl[k] * nl[j][1] - dl[j] * nl[k][1]) / det;
        hx->x[k][1] = (nl[k][0] * dl[j] - nl[j][0] * dl[k]) / det;
    }
}

prox_vec3 prox_polytope_rhp(const prox_rhp *h, const prox_rhp_section *hx, prox_polytope *p)
{
    int side[6];
    prox_vec3 q[6], sn[6];
    for (int k = 0; k < 6; ++k) {
        int j = (k + 1) % 6;
        q[k] = prox_v3_add(prox_v3_scale(hx->e1, hx->x[k][0]), prox_v3_scale(hx->e2, hx->x[k][1]));
        side[k] = hx->fk[j]; /* side from corner k to corner k + 1 */
        /* The card's +-r[i] as the section has it: its part across the height. The card's r[i] itself
         * may lean up to PROX_BOX_ORTHO_TOL towards the height; its plane would then miss the top
         * corners by that lean times the height, and a needle's spread along it would be the
         * height's, not the hexagon's width (the aspect test would pass a 1e-34 thin one). */
        sn[k] = prox_v3_add(prox_v3_scale(hx->e1, hx->nl[j][0]), prox_v3_scale(hx->e2, hx->nl[j][1]));
    }
    return prism(p, h->base, q, side, sn, 6, h->axis, 7, 8);
}

static prox_vec3 make_rhp(const prox_rhp *h, prox_polytope *p)
{
    prox_rhp_section hx;
    prox_rhp_hexagon(h, &hx);
    return prox_polytope_rhp(h, &hx, p);
}

static prox_vec3 make_wed(const prox_wed *w, prox_polytope *p)
{
    prox_vec3 q[3] = {prox_v3(0, 0, 0), w->v1, w->v2};
    int side[3] = {3, 1, 2}; /* v-v1: side of v1 and v3; v1-v2: slant; v2-v: side of v2 and v3 */
    /* outward normals: each side's edge crossed with the height, turned away from the third corner */
    prox_vec3 sn[3];
    for (int i = 0; i < 3; ++i) {
        prox_vec3 a = q[i], b = q[(i + 1) % 3], third = q[(i + 2) % 3];
        prox_vec3 n = prox_v3_normalize(prox_v3_cross(prox_v3_sub(b, a), w->v3));
        sn[i] = prox_v3_dot(n, prox_v3_sub(third, a)) > 0.0 ? prox_v3_neg(n) : n;
    }
    return prism(p, w->vertex, q, side, sn, 3, w->v3, 4, 5);
}

/* Corner digits of ARB face entry x (four digits; 0 for the missing fourth of a triangle). */
static void arb_digits(int x, int dig[4])
{
    dig[0] = x / 1000 % 10; /* four independent quotients rather than a chain of them */
    dig[1] = x / 100 % 10;
    dig[2] = x / 10 % 10;
    dig[3] = x % 10;
}

/* The sign of n . w for face k's unit Newell normal n: read off the raw Newell sum s when s . w
 * stands clear of its rounding (above 1e-10 of sum |s_i w_i|, where scaling s by 1 / |s| cannot
 * change the sign), else from the unit normal itself. */
static int faces_inwards(const prox_polytope *p, int k, prox_vec3 w)
{
    prox_vec3 s = newell_sum(p, k);
    double D = prox_v3_dot(s, w), M = fabs(s.x * w.x) + fabs(s.y * w.y) + fabs(s.z * w.z);
    if (M > 1e-280 && fabs(D) > 1e-10 * M) return D < 0.0;
    return prox_v3_dot(newell(p, k), w) < 0.0;
}

/* Face k's loop as listed turns inwards: by its first three corners when quick (the validator's
 * fast path confirms the outcome, arb_plainly_ok), else by its Newell normal. */
static int loop_inwards(const prox_polytope *p, int k, prox_vec3 g, int quick)
{
    prox_vec3 a = p->v[p->fv[k][0]], w = prox_v3_sub(a, g);
    if (!quick) return faces_inwards(p, k, w);
    prox_vec3 t = prox_v3_cross(prox_v3_sub(p->v[p->fv[k][1]], a), prox_v3_sub(p->v[p->fv[k][2]], a));
    return prox_v3_dot(t, w) < 0.0;
}

/* Orientation of c about the directed line a -> b, seen along n. */
static double turn(prox_vec3 a, prox_vec3 b, prox_vec3 c, prox_vec3 n)
{
    return prox_v3_dot(prox_v3_cross(prox_v3_sub(b, a), prox_v3_sub(c, a)), n);
}

int prox_sides_cross(prox_vec3 p, prox_vec3 q, prox_vec3 r, prox_vec3 s, prox_vec3 n)
{
    return turn(p, q, r, n) * turn(p, q, s, n) < 0.0 && turn(r, s, p, n) * turn(r, s, q, n) < 0.0;
}

/* A four-corner face named out of order round the face (1256 for the loop 1, 2, 6, 5: MCNP takes a
 * face's plane through its corners, in any order, and published decks write them so) crosses itself:
 * two opposite sides cross, and swapping the two corners between them makes the loop. */
int prox_arb_face_loop(const prox_arb *a, int f, int idx[4])
{
    int dig[4], n = 0;
    if (a->face[f] <= 0) return 0;
    arb_digits(a->face[f], dig);
    for (int i = 0; i < 4; ++i)
        if (dig[i] >= 1 && dig[i] <= 8) idx[n++] = dig[i] - 1;
    if (n != 4) return n;
    prox_vec3 x[4];
    for (int i = 0; i < 4; ++i) x[i] = a->corner[idx[i]];
    prox_vec3 nrm = prox_v3_add(prox_v3_cross(prox_v3_sub(x[1], x[0]), prox_v3_sub(x[2], x[0])),
                                prox_v3_cross(prox_v3_sub(x[2], x[0]), prox_v3_sub(x[3], x[0])));
    prox_vec3 m = prox_v3_cross(prox_v3_sub(x[1], x[0]), prox_v3_sub(x[3], x[0]));
    if (prox_v3_norm2(m) > prox_v3_norm2(nrm)) nrm = m; /* a bow tie's two halves cancel in the sum */
    int t;
    if (prox_sides_cross(x[1], x[2], x[3], x[0], nrm)) t = idx[2], idx[2] = idx[3], idx[3] = t;
    else if (prox_sides_cross(x[0], x[1], x[2], x[3], nrm)) t = idx[1], idx[1] = idx[2], idx[2] = t;
    return 4;
}

prox_vec3 prox_polytope_arb(const prox_arb *a, prox_polytope *p, double *least, int quick)
{
    p->nv = p->nf = p->ne = 0; /* the counts and the small per-face tables; finish() fills the rest */
    memset(p->fnv, 0, sizeof p->fnv);
    memset(p->facet, 0, sizeof p->facet);
    int map[9], loops[6][4], nl[6];
    unsigned used = 0; /* bit c: corner c named by some face */
    for (int f = 0; f < 6; ++f) {
        nl[f] = prox_arb_face_loop(a, f, loops[f]);
        for (int i = 0; i < nl[f]; ++i) used |= 1u << (loops[f][i] + 1);
    }
    prox_vec3 o = prox_v3(0, 0, 0);
    for (int c = 1; c <= 8; ++c)
        if ((used >> c) & 1u) {
            o = a->corner[c - 1];
            break;
        }
    for (int c = 1; c <= 8; ++c) {
        map[c] = -1;
        if (!((used >> c) & 1u)) continue;
        map[c] = p->nv;
        p->v[p->nv++] = prox_v3_sub(a->corner[c - 1], o);
    }
    prox_vec3 g = prox_v3(0, 0, 0);
    for (int i = 0; i < p->nv; ++i) g = prox_v3_add(g, p->v[i]);
    if (p->nv) g = prox_v3_scale(g, 1.0 / p->nv);
    for (int f = 0; f < 6; ++f) {
        const int *loop = loops[f], m = nl[f];
        if (a->face[f] <= 0) continue;
        int k = p->nf;
        for (int i = 0; i < m; ++i) p->fv[k][i] = (unsigned char)map[loop[i] + 1];
        p->fnv[k] = m;
        p->facet[k] = f + 1;
        p->nf++;
        if (m < 3) continue;
        /* Loops may be listed either way round: turn each to face outwards (away from the centroid). */
        if (loop_inwards(p, k, g, quick))
            for (int i = 0; i < m / 2; ++i) {
                unsigned char t = p->fv[k][i];
                p->fv[k][i] = p->fv[k][m - 1 - i];
                p->fv[k][m - 1 - i] = t;
            }
    }
    prox_vec3 c = p->nv ? centre(p, o) : o;
    finish(p, least);
    corner_box(p);
    return c;
}

prox_vec3 prox_polytope_make(const prox_shape *s, prox_polytope *p)
{
    static const int box_facets[6] = {1, 2, 3, 4, 5, 6};
    switch (s->kind) {
    case PROX_SHAPE_BOX: return make_box(&s->u.box, box_facets, p);
    case PROX_SHAPE_RPP: {
        prox_box b = prox_rpp_to_box(&s->u.rpp);
        return make_box(&b, box_facets, p);
    }
    case PROX_SHAPE_RHP: return make_rhp(&s->u.rhp, p);
    case PROX_SHAPE_WED: return make_wed(&s->u.wed, p);
    case PROX_SHAPE_ARB: {
        double least;
        return prox_polytope_arb(&s->u.arb, p, &least, 0);
    }
    default: break;
    }
    memset(p, 0, sizeof *p);
    corner_box(p);
    return prox_v3(0, 0, 0);
}

/* ---- queries ---- */

double prox_polytope_hc(const prox_polytope *p, prox_vec3 d)
{
    double m = prox_v3_dot(d, p->v[0]);
    for (int i = 1; i < p->nv; ++i) m = prox_max2(prox_v3_dot(d, p->v[i]), m);
    return m;
}

prox_vec3 prox_polytope_pc(const prox_polytope *p, prox_vec3 d)
{
    int best = 0;
    double m = prox_v3_dot(d, p->v[0]);
    for (int i = 1; i < p->nv; ++i) {
        double t = prox_v3_dot(d, p->v[i]);
        if (t > m) m = t, best = i;
    }
    return p->v[best];
}

int prox_polytope_contains(const prox_polytope *p, prox_vec3 y, double tol)
{
    for (int f = 0; f < p->nf; ++f)
        if (prox_v3_dot(p->n[f], y) > p->d[f] + tol) return 0;
    /* The corners' box too: a sliver's planes, cross products of edges 1e-40 of their length apart,
     * can pass a point 1e71 times the sliver's size away from it. */
    return y.x >= p->lo.x - tol && y.y >= p->lo.y - tol && y.z >= p->lo.z - tol && y.x <= p->hi.x + tol &&
           y.y <= p->hi.y + tol && y.z <= p->hi.z + tol;
}

/* Closest point of face f (a convex polygon) to y: the foot on its plane when that lies in the face
 * (prox_polytope_face_foot), else the nearest point of its edges. */
static prox_vec3 face_closest(const prox_polytope *p, int f, prox_vec3 y)
{
    prox_vec3 foot;
    if (prox_polytope_face_foot(p, f, y, &foot)) return foot;
    int m = p->fnv[f];
    prox_vec3 best = p->v[p->fv[f][0]];
    double bd = INFINITY;
    for (int i = 0; i < m; ++i) {
        prox_vec3 c = prox_seg_closest(p->v[p->fv[f][i]], p->v[p->fv[f][i + 1 < m ? i + 1 : 0]], y);
        double dd = prox_v3_norm2(prox_v3_sub(c, y));
        if (dd < bd) bd = dd, best = c;
    }
    return best;
}

/* Nearest boundary point of an outside point: the nearest over the faces it sees. */
static prox_vec3 boundary_closest(const prox_polytope *p, prox_vec3 y)
{
    prox_vec3 best = y;
    double bd = INFINITY;
    for (int f = 0; f < p->nf; ++f) {
        if (prox_v3_dot(p->n[f], y) <= p->d[f]) continue; /* a face seen from behind is never nearest */
        prox_vec3 c = face_closest(p, f, y);
        double dd = prox_v3_norm2(prox_v3_sub(c, y));
        if (dd < bd) bd = dd, best = c;
    }
    return best;
}

prox_vec3 prox_polytope_closest(const prox_polytope *p, prox_vec3 y)
{
    if (prox_polytope_contains(p, y, 0.0)) return y;
    return boundary_closest(p, y);
}

/* The foot lies inside every edge's inner half-plane (b - a) x n . (x - a) <= 0. A face collapsed
 * to a segment (a plate 5e-33 thick whose corners 1e50 apart absorb the thickness: its side faces'
 * short edges have length 0) bounds only across that segment, so the foot is also tested against
 * the solid's planes (PROX_TOL_FOOT): a foot in the face lies in the solid. */
int prox_polytope_face_foot(const prox_polytope *p, int f, prox_vec3 y, prox_vec3 *x)
{
    prox_vec3 n = p->n[f];
    *x = prox_v3_mad(y, p->d[f] - prox_v3_dot(n, y), n);
    int m = p->fnv[f];
    for (int i = 0; i < m; ++i) {
        prox_vec3 a = p->v[p->fv[f][i]], b = p->v[p->fv[f][i + 1 < m ? i + 1 : 0]];
        if (prox_v3_dot(prox_v3_cross(prox_v3_sub(b, a), n), prox_v3_sub(*x, a)) > 0.0) return 0;
    }
    return prox_polytope_contains(p, *x, PROX_TOL_FOOT * p->size);
}

int prox_polytope_closest_feature(const prox_polytope *p, prox_vec3 y, prox_vec3 *q, int *i, int *j, double *t)
{
    *q = y, *i = *j = 0, *t = 0.0;
    if (prox_polytope_contains(p, y, 0.0)) return PROX_POLY_INSIDE;
    int kind = PROX_POLY_CORNER;
    double bd = INFINITY;
    for (int f = 0; f < p->nf; ++f) {
        if (prox_v3_dot(p->n[f], y) <= p->d[f]) continue; /* seen from behind: never nearest */
        prox_vec3 x;
        if (prox_polytope_face_foot(p, f, y, &x)) { /* nearer than any point of its border */
            double dd = prox_v3_norm2(prox_v3_sub(x, y));
            if (dd < bd) bd = dd, *q = x, *i = f, kind = PROX_POLY_FACE;
            continue;
        }
        int m = p->fnv[f];
        for (int k = 0; k < m; ++k) {
            int a = p->fv[f][k], b = p->fv[f][k + 1 < m ? k + 1 : 0];
            prox_vec3 e = prox_v3_sub(p->v[b], p->v[a]);
            double l2 = prox_v3_norm2(e), s = l2 > 0.0 ? prox_v3_dot(prox_v3_sub(y, p->v[a]), e) / l2 : 0.0;
            s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
            prox_vec3 z = s == 1.0 ? p->v[b] : prox_v3_mad(p->v[a], s, e);
            double dd = prox_v3_norm2(prox_v3_sub(z, y));
            if (!(dd < bd)) continue;
            bd = dd, *q = z;
            if (s > 0.0 && s < 1.0) *i = a, *j = b, *t = s, kind = PROX_POLY_EDGE;
            else *i = s > 0.0 ? b : a, kind = PROX_POLY_CORNER;
        }
    }
    return kind;
}

double prox_polytope_boundary(const prox_polytope *p, prox_vec3 y, prox_vec3 *q)
{
    if (!prox_polytope_contains(p, y, 0.0)) {
        *q = boundary_closest(p, y);
        return prox_v3_dist(*q, y);
    }
    /* Inside: the nearest face plane; its foot lies in the solid (the inscribed ball of that radius
     * about y touches the plane there). */
    int best = 0;
    double s = p->d[0] - prox_v3_dot(p->n[0], y);
    for (int f = 1; f < p->nf; ++f) {
        double t = p->d[f] - prox_v3_dot(p->n[f], y);
        if (t < s) s = t, best = f;
    }
    *q = prox_v3_mad(y, s, p->n[best]);
    return -s;
}
