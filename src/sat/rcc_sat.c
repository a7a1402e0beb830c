/* Intersection verdict for two solid cylinders: Eberly's separating-axis tests where they decide, then
 * Minkowski portal refinement (MPR) with a certified bound for every other direction, and Eberly's
 * bisection on the axis-perpendicular directions only as a last resort in the touching band.
 *
 * Source: D. Eberly, "Intersection of Cylinders" (2000, rev. 2017), Secs. 4-8:
 *   Eq. (6)  f(D) = r0|P0 D| + r1|P1 D| + (h0/2)|D.W0| + (h1/2)|D.W1| - |D.Delta|; D separates iff
 *            f(D) < 0 (Eberly allows = 0; here touching counts as intersecting).
 * Order of the tests (prox_sat_cyl):
 *   1. Sec. 5: the axis directions W0, W1, W0 x W1 and the parallel case (Eberly's tests as written).
 *   2. Every other direction by MPR, not Eberly's Sec. 7 (octant triangles and an unspecified
 *      minimiser): the open hemisphere D.Delta > 0 is parameterised by its tangent plane at
 *      n = Delta/|Delta|: D = n + z, z in n^perp, G(z) = f(n + z) = h_K(n + z) - |Delta| with
 *      K = (A - C0) + (B - C1) (Minkowski sum of the centred cylinders), one convex function on the
 *      whole plane. Every support point k of K gives the cutting plane G(z) >= k.(n + z) - |Delta|;
 *      on a triangle ("portal") of support points whose projection along n surrounds the origin the
 *      model's minimum is t_low - |Delta|, t_low n the point of the portal on the line R n, and the
 *      portal normal N is the next trial direction: G(N / N.n) = t_up - |Delta|, t_up = h_K(N) / N.n.
 *      t_low <= t* <= t_up bracket the exit t* of the line from K; stop when t_up < |Delta| (N
 *      separates), t_low > |Delta| (certified: no separating direction exists; t_low is taken
 *      rounding-safe, portal_low), or t_up - t_low <= PROX_TOL_SEARCH x scale (touching within
 *      tolerance). This is Minkowski portal refinement of the ray from the centre of K (Snethen's
 *      XenoCollide), read as a certified minimisation of Eberly's G over the tangent plane. An
 *      overlapping pair's final portal also yields a common point (portal_apart).
 *   3. Only when MPR ends undecided within the tolerance: Sec. 6, directions perpendicular to an
 *      axis, F(t) of Eqs. (8)-(9), convex on [0, 1]; bisection on F' with a certified lower bound
 *      (tangent lines at the bracket ends), errata fixed. A lateral contact's separating direction
 *      lies exactly on such a kink, where MPR converges slowly. */
#include "prox/sat.h"

#include "core/body.h"
#include "core/cyl.h"
#include "core/tol.h"
#include "sat_internal.h"

#include <float.h>

/* Iteration cap of the portal refinement: it converges linearly and the certified stop ends it in a
 * few tens of steps; the cap only guards against a rounding cycle. */
#define SAT_MAX_IT 100

/* Centred support function and support point of one cylinder (Eberly Eq. (4) without D.C): the core's
 * prepared cylinder. */
static double hc(const prox_cyl *s, prox_vec3 d) { return prox_cyl_hc(s, d); }
static prox_vec3 pc(const prox_cyl *s, prox_vec3 d) { return prox_cyl_support_point_c(s, d); }

/* Gap along the unit direction of d: -f(d)/|d|; > 0 separates. */
static double gap(const prox_cyl *a, const prox_cyl *b, prox_vec3 delta, prox_vec3 d)
{
    double n2 = prox_v3_norm2(d), n = n2 >= DBL_MIN && n2 <= DBL_MAX ? sqrt(n2) : prox_v3_norm(d);
    prox_vec3 u = prox_v3_scale(d, 1.0 / n);
    return fabs(prox_v3_dot(u, delta)) - hc(a, u) - hc(b, u);
}

static prox_test_result separated(prox_vec3 d, prox_vec3 delta, double value, prox_sat_axis by)
{
    prox_test_result r = {0};
    r.status = PROX_OK;
    r.intersect = 0;
    double n2 = prox_v3_norm2(d);
    d = n2 >= DBL_MIN && n2 <= DBL_MAX ? prox_v3_scale(d, 1.0 / sqrt(n2)) : prox_v3_normalize(d);
    r.direction = prox_v3_dot(d, delta) < 0.0 ? prox_v3_neg(d) : d; /* from A towards B */
    r.value = value;
    r.decided_by = by;
    return r;
}

/* ---- Sec. 6: directions perpendicular to W0 (Eqs. (8)-(9)) ------------------------------------ */

typedef struct perp_f {
    double r0, r1, h1b1, c1sqr, a2, b2;
} perp_f;

static double F(const perp_f *p, double t)
{
    double omt = 1.0 - t;
    return p->r0 * sqrt(omt * omt + t * t) + p->r1 * sqrt(omt * omt + p->c1sqr * t * t) + p->h1b1 * t -
           fabs(omt * p->a2 + t * p->b2);
}
static double sgnd(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }
static double Fder(const perp_f *p, double t)
{
    double omt = 1.0 - t;
    return p->r0 * (2.0 * t - 1.0) / sqrt(omt * omt + t * t) +
           p->r1 * ((1.0 + p->c1sqr) * t - 1.0) / sqrt(omt * omt + p->c1sqr * t * t) + p->h1b1 -
           (p->b2 - p->a2) * sgnd(omt * p->a2 + t * p->b2);
}

/* Minimises the convex F on [0, 1] until F(t) < -tol (returns t, a separating parameter) or a
 * certified lower bound min F > tol (returns -1); -2 when undecided within the tolerance. */
static double perp_quarter(const perp_f *p, double tol)
{
    double f0 = F(p, 0.0), f1 = F(p, 1.0);
    if (f0 < -tol) return 0.0;
    if (f1 < -tol) return 1.0;
    double t0 = 0.0, t1 = 1.0, d0 = Fder(p, 0.0), d1 = Fder(p, 1.0);
    if (d0 >= 0.0) return f0 > tol ? -1.0 : -2.0; /* F increasing: min at 0 */
    if (d1 <= 0.0) return f1 > tol ? -1.0 : -2.0;
    for (int it = 0; it < 60; ++it) {
        /* tangent lines at t0 and t1 meet at the lower bound of F on [t0, t1] (convexity) */
        double tx = (f1 - f0 + d0 * t0 - d1 * t1) / (d0 - d1);
        double lb = f0 + d0 * (tx - t0);
        if (lb > tol) return -1.0;
        double tm = 0.5 * (t0 + t1), fm = F(p, tm);
        if (fm < -tol) return tm;
        double dm = Fder(p, tm);
        if (dm > 0.0) { t1 = tm; f1 = fm; d1 = dm; }
        else if (dm < 0.0) { t0 = tm; f0 = fm; d0 = dm; }
        else return fm > tol ? -1.0 : -2.0;
    }
    return -2.0;
}

/* Eberly's SeparatedByCylinderPerpendiculars with the errata fixed: both quarter circles
 * (U0 -> V0 and -U0 -> V0) are examined; the first one's "no separation" does not end the test. */
static int perp_test(const prox_cyl *c0, const prox_cyl *c1, prox_vec3 delta, double tol, prox_vec3 *dir)
{
    double c1d = prox_v3_dot(c0->w, c1->w);
    prox_vec3 v0 = prox_v3_mad(c1->w, -c1d, c0->w);
    double b1 = prox_v3_norm(v0);
    if (!(b1 > 0.0)) return 0;
    v0 = prox_v3_scale(v0, 1.0 / b1);
    prox_vec3 u0 = prox_v3_cross(v0, c0->w);
    perp_f p = {c0->r, c1->r, 0.5 * c1->h * b1, c1d * c1d, prox_v3_dot(delta, u0), prox_v3_dot(delta, v0)};
    for (int side = 0; side < 2; ++side) {
        double t = perp_quarter(&p, tol);
        if (t >= 0.0) {
            prox_vec3 u = side ? prox_v3_neg(u0) : u0;
            *dir = prox_v3_add(prox_v3_scale(u, 1.0 - t), prox_v3_scale(v0, t));
            return 1;
        }
        p.a2 = -p.a2;
    }
    return 0;
}

/* ---- Sec. 7: other directions, certified cutting planes on the tangent plane ------------------ */

typedef struct sat_k {
    const prox_cyl *a, *b;
    prox_vec3 n, u, v; /* n = Delta/|Delta|, (u, v) basis of the tangent plane */
} sat_k;

static double kh(const sat_k *k, prox_vec3 d) { return hc(k->a, d) + hc(k->b, d); }
/* 2D cross product of the tangent-plane projections of p and q. */
static double cross2(const sat_k *k, prox_vec3 p, prox_vec3 q)
{
    return prox_v3_dot(p, k->u) * prox_v3_dot(q, k->v) - prox_v3_dot(p, k->v) * prox_v3_dot(q, k->u);
}
/* 1 when the projection of the origin lies in the projected triangle (p, q, r) (closed). */
static int contains0(const sat_k *k, prox_vec3 p, prox_vec3 q, prox_vec3 r)
{
    double s1 = cross2(k, p, q), s2 = cross2(k, q, r), s3 = cross2(k, r, p);
    return (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || (s1 <= 0.0 && s2 <= 0.0 && s3 <= 0.0);
}
/* Tangential direction normal to the projected edge (p, q) pointing to the origin's side. */
static prox_vec3 edge_dir(const sat_k *k, prox_vec3 p, prox_vec3 q)
{
    double px = prox_v3_dot(p, k->u), py = prox_v3_dot(p, k->v);
    double ex = prox_v3_dot(q, k->u) - px, ey = prox_v3_dot(q, k->v) - py;
    double nx = -ey, ny = ex;
    if (nx * (-px) + ny * (-py) < 0.0) { nx = -nx; ny = -ny; }
    return prox_v3_add(prox_v3_scale(k->u, nx), prox_v3_scale(k->v, ny));
}

/* A vertex of the portal: the support point p of K in some direction and its part pa from A
 * (p = pa + pb, pa a point of A - cA): the A-parts give the common point of an overlapping pair. */
static void kvert(const sat_k *k, prox_vec3 d, prox_vec3 *p, prox_vec3 *pa)
{
    *pa = pc(k->a, d);
    *p = prox_v3_add(*pa, pc(k->b, d));
}

/* Phase 1: three support points of K whose projections along n surround the origin (2D GJK for
 * a point interior to the projection of K), with their A-parts. Returns 0 on failure. */
static int find_portal(const sat_k *k, prox_vec3 p[3], prox_vec3 pa[3])
{
    kvert(k, k->n, &p[0], &pa[0]);
    prox_vec3 t = prox_v3_mad(p[0], -prox_v3_dot(p[0], k->n), k->n);
    if (prox_v3_norm2(t) == 0.0) { p[1] = p[2] = p[0]; pa[1] = pa[2] = pa[0]; return 1; } /* on the line itself */
    kvert(k, prox_v3_neg(t), &p[1], &pa[1]);
    for (int it = 0; it < 64; ++it) {
        prox_vec3 d = edge_dir(k, p[0], p[1]);
        if (prox_v3_norm2(d) == 0.0) { p[2] = p[1]; pa[2] = pa[1]; return 1; } /* origin on the projected edge */
        kvert(k, d, &p[2], &pa[2]);
        if (contains0(k, p[0], p[1], p[2])) return 1;
        /* the origin is beyond edge (p0, p2) or beyond edge (p2, p1): keep that edge */
        prox_vec3 e = prox_v3_sub(p[2], p[0]);
        double so = cross2(k, e, prox_v3_neg(p[0])), s1 = cross2(k, e, prox_v3_sub(p[1], p[0]));
        int j = so * s1 < 0.0 ? 1 : 0;
        p[j] = p[2];
        pa[j] = pa[2];
    }
    return 0;
}

/* The A-part of Delta from the final portal of an intersecting pair. The line R n meets the portal at
 * t n = sum l_i p_i, l_i the barycentric coordinates of the origin in the projected triangle (ratios
 * of the 2D orientations); with s = |Delta| / t <= 1 (certified), Delta = sum s l_i (pa_i + pb_i) splits
 * into a' = s sum l_i pa_i in A - cA and b' in B - cB (convex sets containing 0), so that
 * cA + a' = cB - b' lies in A and, B being centrally symmetric, in B. In the touching band (s slightly
 * above 1) the point is off by |Delta| - t <= the search tolerance. 0 when the portal is degenerate. */
static int portal_apart(const sat_k *k, const prox_vec3 p[3], const prox_vec3 pa[3], double L, prox_vec3 *apart)
{
    double l[3], sum = 0.0;
    for (int i = 0; i < 3; ++i) sum += l[i] = cross2(k, p[(i + 1) % 3], p[(i + 2) % 3]);
    if (!(fabs(sum) > 0.0)) {
        /* collapsed portal: a vertex on the line itself */
        for (int i = 0; i < 3; ++i)
            if (prox_v3_norm2(prox_v3_mad(p[i], -prox_v3_dot(p[i], k->n), k->n)) == 0.0 && prox_v3_dot(p[i], k->n) > 0.0) {
                *apart = prox_v3_scale(pa[i], fmin(1.0, L / prox_v3_dot(p[i], k->n)));
                return 1;
            }
        return 0;
    }
    prox_vec3 x = {0, 0, 0}, y = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        double li = l[i] / sum;
        if (li < 0.0) li = 0.0; /* rounding of a vertex on the line */
        x = prox_v3_mad(x, li, p[i]);
        y = prox_v3_mad(y, li, pa[i]);
    }
    double t = prox_v3_dot(x, k->n);
    if (!(t > 0.0)) return 0;
    *apart = prox_v3_scale(y, fmin(1.0, L / t));
    return 1;
}

/* Rounding-safe lower bound of t* from the portal (p0, p1, p2) with computed normal N, nn = N.n > 0.
 * In exact arithmetic the plane through the portal meets the line R n at t n = sum l_i p_i, a point of
 * conv(p) inside K, and t = N.p0 / nn. The computed N of a sliver portal (two vertices 1e-6 apart, the
 * lateral segment of a side-by-side contact) is off by eps |e1||e2| / |N| ~ 1e-9 in direction, and
 * N.p0 / nn then overshoots t by up to that times |p|: a false certificate (-1.5e-11 on a pair 4.5e-12
 * apart). For any N, N.(sum l_i p_i) >= min_i N.p_i, so min_i N.p_i / nn (less the rounding of the dot
 * products) is a true bound, provided the origin is robustly inside the projected portal: each 2D
 * orientation must exceed its rounding bound, else no bound is claimed (-inf). */
static double portal_low(const sat_k *k, const prox_vec3 p[3], prox_vec3 N, double nn)
{
    double s[3], m[3];
    for (int i = 0; i < 3; ++i) {
        const prox_vec3 *x = &p[i], *y = &p[(i + 1) % 3];
        s[i] = cross2(k, *x, *y);
        m[i] = 16.0 * DBL_EPSILON * sqrt(prox_v3_norm2(*x) * prox_v3_norm2(*y));
    }
    int pos = s[0] > m[0] && s[1] > m[1] && s[2] > m[2], neg = s[0] < -m[0] && s[1] < -m[1] && s[2] < -m[2];
    if (!pos && !neg) return -INFINITY;
    double lo = INFINITY, pm = 0.0;
    for (int i = 0; i < 3; ++i) {
        lo = fmin(lo, prox_v3_dot(N, p[i]));
        pm = fmax(pm, fabs(N.x * p[i].x) + fabs(N.y * p[i].y) + fabs(N.z * p[i].z));
    }
    return (lo - 4.0 * DBL_EPSILON * pm) / nn;
}

/* Certified minimisation of G; returns 1 separated (dir, value = gap), 0 intersecting (value = the
 * certified lower bound of G, > 0, or 0 when undecided within the tolerance). When intersecting and
 * apart is not NULL, *apart receives the A-part of Delta (portal_apart) and *has_apart = 1. */
static int other_dirs(const prox_cyl *a, const prox_cyl *b, prox_vec3 delta, double scale, prox_vec3 *dir, double *value,
                      prox_vec3 *apart, int *has_apart)
{
    double L = sqrt(prox_v3_norm2(delta));
    sat_k k = {a, b, prox_v3_scale(delta, 1.0 / L), {0, 0, 0}, {0, 0, 0}};
    k.u = prox_v3_any_perp(k.n);
    k.v = prox_v3_cross(k.n, k.u);
    prox_vec3 p[3], pa[3];
    double tol = PROX_TOL_SEARCH * scale, t_up = INFINITY, t_low = -INFINITY;
    if (has_apart) *has_apart = 0;
    /* the pole itself: G(0) */
    t_up = kh(&k, k.n);
    if (t_up < L) { *dir = k.n; *value = L - t_up; return 1; }
    if (!find_portal(&k, p, pa)) { *value = 0.0; return 0; }
    for (int it = 0; it < SAT_MAX_IT; ++it) {
        prox_vec3 N = prox_v3_cross(prox_v3_sub(p[1], p[0]), prox_v3_sub(p[2], p[0]));
        double nn = prox_v3_dot(N, k.n);
        if (nn < 0.0) { N = prox_v3_neg(N); nn = -nn; }
        if (!(nn > 1e-300 * sqrt(prox_v3_norm2(N)))) N = k.n, nn = 1.0; /* degenerate portal: use the pole */
        else t_low = fmax(t_low, portal_low(&k, p, N, nn));
        if (t_low > L) { /* certified: no separating direction */
            *value = t_low - L;
            if (apart) *has_apart = portal_apart(&k, p, pa, L, apart);
            return 0;
        }
        double tu = kh(&k, N) / nn;
        if (tu < t_up) t_up = tu;
        if (tu < L) {
            /* separated, unless the gap along N, computed the other way, is not positive: a
             * touching pair within rounding (touching counts as intersecting) */
            double g = gap(a, b, delta, N);
            if (g > 0.0) {
                *dir = N;
                *value = g;
                return 1;
            }
        }
        if (t_up - t_low <= tol) break;
        prox_vec3 q, qa;
        kvert(&k, N, &q, &qa);
        int j = contains0(&k, q, p[1], p[2]) ? 0 : contains0(&k, p[0], q, p[2]) ? 1 : contains0(&k, p[0], p[1], q) ? 2 : -1;
        if (j < 0) break;
        p[j] = q;
        pa[j] = qa;
    }
    *value = fmax(0.0, t_low - L);
    if (apart) *has_apart = portal_apart(&k, p, pa, L, apart);
    return 0;
}

prox_test_result prox_sat_cyl(const prox_cyl *pa, const prox_cyl *pb)
{
    prox_test_result r = {0};
    prox_cyl c0 = *pa, c1 = *pb;
    r.status = PROX_OK;
    prox_vec3 delta = prox_v3_sub(c1.c, c0.c);
    double g;
    r.intersect = 1;
    if (prox_v3_norm2(delta) == 0.0) { r.decided_by = PROX_SAT_CERTIFIED; return r; } /* same centre */
    /* Sec. 5: the axes */
    if ((g = gap(&c0, &c1, delta, c0.w)) > 0.0) return separated(c0.w, delta, g, PROX_SAT_W0);
    if ((g = gap(&c0, &c1, delta, c1.w)) > 0.0) return separated(c1.w, delta, g, PROX_SAT_W1);
    prox_vec3 x = prox_v3_cross(c0.w, c1.w);
    if (prox_v3_norm2(x) == 0.0) {
        /* parallel axes: the radial direction decides (the height test was W0 above) */
        prox_vec3 rad = prox_v3_mad(delta, -prox_v3_dot(delta, c0.w), c0.w);
        if (prox_v3_norm2(rad) > 0.0 && (g = gap(&c0, &c1, delta, rad)) > 0.0)
            return separated(rad, delta, g, PROX_SAT_PARALLEL);
        r.value = prox_v3_norm2(rad) > 0.0 ? fmax(gap(&c0, &c1, delta, c0.w), gap(&c0, &c1, delta, rad))
                                           : gap(&c0, &c1, delta, c0.w);
        r.decided_by = PROX_SAT_PARALLEL;
        return r;
    }
    if ((g = gap(&c0, &c1, delta, x)) > 0.0) return separated(x, delta, g, PROX_SAT_W0xW1);
    /* Sec. 7 first: the certified minimisation covers every direction of the hemisphere,
     * the perpendicular ones included, and is cheaper than Sec. 6's bisections. */
    prox_vec3 d;
    double v;
    double scale = fmax(sqrt(prox_v3_norm2(delta)), fmax(fmax(c0.h, c1.h), fmax(c0.r, c1.r)));
    int other = other_dirs(&c0, &c1, delta, scale, &d, &v, NULL, NULL);
    if (other) return separated(d, delta, v, PROX_SAT_OTHER);
    if (v == 0.0) {
        /* undecided within tolerance (touching): Sec. 6 on the kinks D.W0 = 0 and D.W1 = 0,
         * where a lateral contact's separating direction lies exactly */
        if (perp_test(&c0, &c1, delta, 0.0, &d) && (g = gap(&c0, &c1, delta, d)) > 0.0)
            return separated(d, delta, g, PROX_SAT_PERP_W0);
        if (perp_test(&c1, &c0, delta, 0.0, &d) && (g = gap(&c0, &c1, delta, d)) > 0.0)
            return separated(d, delta, g, PROX_SAT_PERP_W1);
    }
    r.value = -v;
    r.decided_by = PROX_SAT_CERTIFIED;
    return r;
}

PROX_API prox_test_result prox_rcc_sat(const prox_rcc *a, const prox_rcc *b)
{
    prox_test_result r = {0};
    r.status = prox_rcc_validate(a); /* the library's one validator (finite, positive, in range) */
    if (r.status == PROX_OK) r.status = prox_rcc_validate(b);
    if (r.status != PROX_OK) return r;
    /* both relative to A's base (a pair far from the origin keeps its relative precision), then at
     * unit scale (exact: a power of two), where no product in the tests can overflow or underflow */
    prox_cyl c0 = prox_cyl_make(a, a->base), c1 = prox_cyl_make(b, a->base);
    double f = prox_unit_scale(fmax(prox_v3_dist(c0.c, c1.c), fmax(fmax(c0.h, c1.h), fmax(c0.r, c1.r))));
    c0 = prox_cyl_scaled(&c0, f);
    c1 = prox_cyl_scaled(&c1, f);
    r = prox_sat_cyl(&c0, &c1);
    r.value /= f;
    return r;
}

int prox_sat_common_point(const prox_cyl *a, const prox_cyl *b, prox_vec3 *x)
{
    prox_vec3 delta = prox_v3_sub(b->c, a->c), d, apart;
    if (prox_v3_norm2(delta) == 0.0) { *x = a->c; return 1; } /* same centre */
    double v, scale = fmax(prox_v3_norm(delta), fmax(fmax(a->h, b->h), fmax(a->r, b->r)));
    int has = 0;
    if (other_dirs(a, b, delta, scale, &d, &v, &apart, &has)) return 0; /* separated */
    if (!has) return 0;
    *x = prox_v3_add(a->c, apart);
    return 1;
}
