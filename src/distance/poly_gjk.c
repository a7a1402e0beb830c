/* GJK on two vertex sets: the closest point to the origin of the Minkowski difference M = A - B of
 * two convex polytopes given by their corners (E. G. Gilbert, D. W. Johnson, S. S. Keerthi, "A fast
 * procedure for computing the distance between complex objects in three-dimensional space", IEEE J.
 * Robotics and Automation 4(2), 1988). The support point of a polytope is one of its corners, so
 * every simplex point is a difference a_i - b_j of two corners held by their indices: the answer is a
 * convex combination of corner pairs, and p1 = sum l_k a_(i_k), p2 = sum l_k b_(j_k) lie in A and B
 * up to rounding. The sub-algorithm is the region analysis of the closest point on a segment,
 * triangle or tetrahedron (C. Ericson, Real-Time Collision Detection, 2005, sections 5.1.2-5.1.6).
 *
 * Nothing here proves the result: the caller certifies a distance by weak duality and a common point
 * by membership, and falls back to the feature enumeration otherwise. */
#include <math.h>

#include "distance/poly_internal.h"

/* Largest iteration count: a converging run on two 12-corner solids takes about six; a run that has
 * not converged by then is cycling on rounding and is handed to the exact enumeration. */
#define GJK_MAX_ITER 48

/* Stopping rule: the duality gap |v|^2 - v.w below GJK_REL_STOP S |v| (the bound gap is then under
 * 1e-15 S, well inside the certificate's slack PROX_TOL_CERT S). */
#define GJK_REL_STOP 1e-15

typedef struct simplex {
    int n;
    prox_vec3 w[4];
    int ia[4], ib[4];
    double l[4];
} simplex;

static int argmax(const prox_vec3 *v, int n, prox_vec3 d)
{
    int best = 0;
    double m = prox_v3_dot(d, v[0]);
    for (int i = 1; i < n; ++i) { /* selects, not branches: the winner is unpredictable */
        double t = prox_v3_dot(d, v[i]);
        int gt = t > m;
        best = gt ? i : best;
        m = gt ? t : m;
    }
    return best;
}

/* Keeps the points of s listed in idx with weights l (count k). */
static void keep(simplex *s, const int *idx, const double *l, int k)
{
    simplex t = *s;
    s->n = k;
    for (int i = 0; i < k; ++i) {
        s->w[i] = t.w[idx[i]];
        s->ia[i] = t.ia[idx[i]];
        s->ib[i] = t.ib[idx[i]];
        s->l[i] = l[i];
    }
}

static void keep1(simplex *s, int a) { keep(s, (int[]){a}, (double[]){1.0}, 1); }

static void keep2(simplex *s, int a, int b, double t) { keep(s, (int[]){a, b}, (double[]){1.0 - t, t}, 2); }

/* Closest point of the segment (w[a], w[b]) to the origin. */
static void segment(simplex *s, int a, int b)
{
    prox_vec3 A = s->w[a], ab = prox_v3_sub(s->w[b], A);
    double t = -prox_v3_dot(A, ab), l2 = prox_v3_norm2(ab);
    if (!(t > 0.0)) keep1(s, a);
    else if (t >= l2) keep1(s, b);
    else keep2(s, a, b, t / l2);
}

static prox_vec3 combo(const simplex *s);

/* The nearest of the three sides of a triangle with no interior. */
static void flat_triangle(simplex *s, int a, int b, int c)
{
    const int side[3][2] = {{a, b}, {b, c}, {a, c}};
    simplex best = *s;
    double bd = INFINITY;
    for (int i = 0; i < 3; ++i) {
        simplex t = *s;
        segment(&t, side[i][0], side[i][1]);
        double d = prox_v3_norm2(combo(&t));
        if (d < bd) bd = d, best = t;
    }
    *s = best;
}

/* Closest point of the triangle (w[a], w[b], w[c]) to the origin (Ericson 5.1.5 with p = 0). */
static void triangle(simplex *s, int a, int b, int c)
{
    prox_vec3 A = s->w[a], B = s->w[b], C = s->w[c];
    prox_vec3 ab = prox_v3_sub(B, A), ac = prox_v3_sub(C, A);
    double d1 = -prox_v3_dot(ab, A), d2 = -prox_v3_dot(ac, A);
    if (d1 <= 0.0 && d2 <= 0.0) {
        keep1(s, a);
        return;
    }
    double d3 = -prox_v3_dot(ab, B), d4 = -prox_v3_dot(ac, B);
    if (d3 >= 0.0 && d4 <= d3) {
        keep1(s, b);
        return;
    }
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        keep2(s, a, b, d1 / (d1 - d3));
        return;
    }
    double d5 = -prox_v3_dot(ab, C), d6 = -prox_v3_dot(ac, C);
    if (d6 >= 0.0 && d5 <= d6) {
        keep1(s, c);
        return;
    }
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        keep2(s, a, c, d2 / (d2 - d6));
        return;
    }
    double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
        keep2(s, b, c, (d4 - d3) / ((d4 - d3) + (d5 - d6)));
        return;
    }
    double den = va + vb + vc;
    if (!(den > 0.0)) { /* a flat triangle (rounding): the nearest of its sides */
        flat_triangle(s, a, b, c);
        return;
    } /* a flat triangle: rounding; its longest side will do */
    double v = vb / den, w = vc / den;
    keep(s, (int[]){a, b, c}, (double[]){1.0 - v - w, v, w}, 3);
}

static double triple(prox_vec3 a, prox_vec3 b, prox_vec3 c) { return prox_v3_dot(a, prox_v3_cross(b, c)); }

static prox_vec3 combo(const simplex *s)
{
    prox_vec3 v = prox_v3(0, 0, 0);
    for (int i = 0; i < s->n; ++i) v = prox_v3_mad(v, s->l[i], s->w[i]);
    return v;
}

/* Closest point of the tetrahedron to the origin: 1 when the origin lies inside (weights by signed
 * volumes, Ericson 5.1.6), else the nearest of the faces the origin lies beyond. */
static int tetrahedron(simplex *s)
{
    prox_vec3 *w = s->w;
    double V = triple(prox_v3_sub(w[1], w[0]), prox_v3_sub(w[2], w[0]), prox_v3_sub(w[3], w[0]));
    double l[4] = {triple(w[1], w[2], w[3]), -triple(w[0], w[2], w[3]), triple(w[0], w[1], w[3]),
                   -triple(w[0], w[1], w[2])};
    int out[4], k = 0;
    for (int i = 0; i < 4; ++i) {
        l[i] = V != 0.0 ? l[i] / V : -1.0;
        if (!(l[i] >= 0.0)) out[k++] = i;
    }
    if (!k) {
        keep(s, (int[]){0, 1, 2, 3}, l, 4);
        return 1;
    }
    static const int face[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    simplex best = *s;
    double bd = INFINITY;
    for (int i = 0; i < (V != 0.0 ? k : 4); ++i) {
        int f = V != 0.0 ? out[i] : i;
        simplex t = *s;
        triangle(&t, face[f][0], face[f][1], face[f][2]);
        double d = prox_v3_norm2(combo(&t));
        if (d < bd) bd = d, best = t;
    }
    *s = best;
    return 0;
}

static void copy_out(const simplex *s, prox_gjk_simplex *out)
{
    out->n = s->n;
    for (int i = 0; i < s->n; ++i) out->ia[i] = s->ia[i], out->ib[i] = s->ib[i], out->l[i] = s->l[i];
}

int prox_gjk_polytopes(const prox_vec3 *va, int na, const prox_vec3 *vb, int nb, prox_vec3 dir, double S, double touch,
                       prox_gjk_simplex *out)
{
    simplex s = {0};
    s.n = 1;
    s.ia[0] = argmax(va, na, dir);
    s.ib[0] = argmax(vb, nb, prox_v3_neg(dir));
    s.w[0] = prox_v3_sub(va[s.ia[0]], vb[s.ib[0]]);
    s.l[0] = 1.0;
    prox_vec3 v = s.w[0];
    double vv = prox_v3_norm2(v);
    for (int it = 0; it < GJK_MAX_ITER; ++it) {
        if (vv <= touch * touch) {
            copy_out(&s, out);
            return PROX_GJK_OVERLAP;
        }
        int ia = argmax(va, na, prox_v3_neg(v)), ib = argmax(vb, nb, v);
        for (int i = 0; i < s.n; ++i)
            if (s.ia[i] == ia && s.ib[i] == ib) {
                copy_out(&s, out);
                return PROX_GJK_DISJOINT;
            }
        prox_vec3 w = prox_v3_sub(va[ia], vb[ib]);
        if (vv - prox_v3_dot(v, w) <= GJK_REL_STOP * S * sqrt(vv)) {
            copy_out(&s, out);
            return PROX_GJK_DISJOINT;
        }
        simplex prev = s;
        s.w[s.n] = w, s.ia[s.n] = ia, s.ib[s.n] = ib, s.n++;
        int inside = 0;
        if (s.n == 2) segment(&s, 0, 1);
        else if (s.n == 3) triangle(&s, 0, 1, 2);
        else inside = tetrahedron(&s);
        if (inside) {
            copy_out(&s, out);
            return PROX_GJK_OVERLAP;
        }
        prox_vec3 v2 = combo(&s);
        double vv2 = prox_v3_norm2(v2);
        if (!(vv2 < vv)) { /* no progress: the previous simplex is the answer */
            copy_out(&prev, out);
            return PROX_GJK_DISJOINT;
        }
        v = v2, vv = vv2;
    }
    copy_out(&s, out);
    return PROX_GJK_FAIL;
}
