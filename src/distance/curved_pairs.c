/* Coaxial solids of revolution (distance/curved_internal.h): RCC, TRC, ELL and SPH on one axis.
 * Everything happens in the meridian plane (t, r) of the common axis, where each body is its full,
 * mirror-symmetric section: a convex polygon (RCC rectangle, TRC isosceles trapezoid or triangle) or
 * an ellipse centred on the axis (ELL, SPH). With K = A - B (the Minkowski difference, itself a solid
 * of revolution whose section is the difference of the sections: a body symmetric about a plane has
 * that plane section equal to its projection, so sections and support functions agree in-plane),
 *   sd(A, B) = -min over unit n of g(n),   g(n) = h_A(n) + h_B(-n),
 * n running over the unit circle of the plane (docs/algorithms/curved.md, "Coaxial pairs"). g is,
 * between the directions where a polygon's supporting vertex changes (its edge normals), of the form
 * v.n + (the other body's support): its minimum over such an arc is at an end or at the stationary
 * direction of that form, which is the vertex-vertex direction (two polygons) or the normal of the
 * ellipse at its nearest point to the vertex (core/ellipse2.h). Evaluating g exactly at all these
 * directions gives its minimum. Two ellipses: g is smooth; its minimum is found by a safeguarded
 * Newton iteration on g'(theta) from samples placed along both ellipses. */
#include "distance/curved_internal.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "core/body.h"
#include "core/ellipse2.h"
#include "core/tol.h"

/* A meridian section: an ellipse centred at (tc, 0) with semi-axes a (along t) and b (along r), or a
 * convex polygon, counter-clockwise in (t, r). */
typedef struct sec2 {
    int ell;
    double tc, hl, a, b; /* hl: half length along the axis */
    int nv;
    double v[4][2];
} sec2;

/* A solid of revolution as its card gives it: an anchor point on its axis (the base centre of an RCC
 * or TRC, the centre of an ELL or SPH: input points, not rounded sums), the half axis hv from the
 * anchor to the centre (zero for ELL and SPH), the unit axis w (zero for a sphere) and the size.
 * Working from the anchors keeps the pair's relative precision far from the origin, where a centre
 * base + axis / 2 is rounded to the ulp of its coordinates. 0 for another kind. */
typedef struct rev3 {
    prox_vec3 anchor, hv, w;
    double size;
} rev3;

static int rev_shape(const prox_shape *s, rev3 *r)
{
    switch (s->kind) {
    case PROX_SHAPE_RCC:
    case PROX_SHAPE_TRC: {
        prox_vec3 ax = s->kind == PROX_SHAPE_RCC ? s->u.rcc.axis : s->u.trc.axis;
        double h = prox_v3_norm(ax);
        r->anchor = s->kind == PROX_SHAPE_RCC ? s->u.rcc.base : s->u.trc.base;
        r->hv = prox_v3_scale(ax, 0.5);
        r->w = prox_v3_scale(ax, 1.0 / h);
        r->size = s->kind == PROX_SHAPE_RCC ? fmax(h, 2.0 * s->u.rcc.radius) : fmax(h, 2.0 * fmax(s->u.trc.r1, s->u.trc.r2));
        return 1;
    }
    case PROX_SHAPE_ELL: {
        double a = prox_v3_norm(s->u.ell.axis);
        r->anchor = s->u.ell.center, r->hv = prox_v3(0, 0, 0);
        r->w = prox_v3_scale(s->u.ell.axis, 1.0 / a);
        r->size = 2.0 * fmax(a, s->u.ell.radius);
        return 1;
    }
    case PROX_SHAPE_SPH:
        r->anchor = s->u.sph.center, r->hv = r->w = prox_v3(0, 0, 0);
        r->size = 2.0 * s->u.sph.radius;
        return 1;
    default: return 0;
    }
}

/* The common frame of a pair: origin o on the axis, unit axis w, unit u across it; the sections. */
typedef struct coax {
    prox_vec3 o, w, u;
    double scale;
    sec2 s[2];
} coax;

/* Section of s in the frame: tc its centre's axial coordinate; a TRC seen against w has its radii
 * in the order of w. A zero radius leaves a vertex, not an edge. */
static void make_section(const prox_shape *s, const rev3 *v, const coax *f, sec2 *x)
{
    *x = (sec2){0};
    x->tc = prox_v3_dot(prox_v3_sub(v->anchor, f->o), f->w) + prox_v3_dot(v->hv, f->w);
    x->ell = s->kind == PROX_SHAPE_ELL || s->kind == PROX_SHAPE_SPH;
    if (s->kind == PROX_SHAPE_ELL) {
        x->a = x->hl = prox_v3_norm(s->u.ell.axis), x->b = s->u.ell.radius;
        return;
    }
    if (s->kind == PROX_SHAPE_SPH) {
        x->a = x->b = x->hl = s->u.sph.radius;
        return;
    }
    prox_vec3 ax = s->kind == PROX_SHAPE_RCC ? s->u.rcc.axis : s->u.trc.axis;
    double hh = x->hl = 0.5 * prox_v3_norm(ax);
    double r1 = s->kind == PROX_SHAPE_RCC ? s->u.rcc.radius : s->u.trc.r1;
    double r2 = s->kind == PROX_SHAPE_RCC ? s->u.rcc.radius : s->u.trc.r2;
    if (prox_v3_dot(ax, f->w) < 0.0) {
        double t = r1;
        r1 = r2, r2 = t;
    }
    const double p[4][2] = {{x->tc - hh, -r1}, {x->tc + hh, -r2}, {x->tc + hh, r2}, {x->tc - hh, r1}};
    x->nv = 0;
    for (int i = 0; i < 4; ++i) {
        if ((i == 2 && r2 == 0.0) || (i == 0 && r1 == 0.0)) continue; /* apex: one vertex */
        x->v[x->nv][0] = p[i][0], x->v[x->nv][1] = p[i][1];
        x->nv++;
    }
}

/* Builds the frame and sections when a and b are coaxial; 0 otherwise. The frame's origin is the
 * anchor of the body whose axis it takes. */
static int make_coax(const prox_shape *a, const prox_shape *b, coax *f)
{
    rev3 v[2];
    if (!rev_shape(a, &v[0]) || !rev_shape(b, &v[1])) return 0;
    int k = prox_v3_norm2(v[0].w) > 0.0 ? 0 : 1; /* the body whose axis is the frame's */
    if (!(prox_v3_norm2(v[k].w) > 0.0)) return 0;  /* two spheres */
    /* axes not parallel, the common case: no frame to build */
    if (prox_v3_norm2(v[1 - k].w) > 0.0 && prox_v3_norm(prox_v3_cross(v[1 - k].w, v[k].w)) > PROX_TOL_COAXIAL_REV) return 0;
    f->o = v[k].anchor, f->w = v[k].w;
    f->u = prox_v3_any_perp(f->w);
    prox_vec3 dc = prox_v3_add(prox_v3_sub(v[1].anchor, v[0].anchor), prox_v3_sub(v[1].hv, v[0].hv));
    f->scale = fmax(fmax(v[0].size, v[1].size), prox_v3_norm(dc));
    for (int i = 0; i < 2; ++i) {
        if (prox_v3_norm2(v[i].w) > 0.0 && prox_v3_norm(prox_v3_cross(v[i].w, f->w)) > PROX_TOL_COAXIAL_REV) return 0;
        /* the anchor off the axis by more than the tolerance and a few ulps of the coordinates (the
         * precision of the input points themselves: a deck's base = centre - axis / 2 is rounded) */
        double tol = PROX_TOL_COAXIAL_REV * f->scale + 8.0 * DBL_EPSILON * (prox_v3_maxabs(v[i].anchor) + prox_v3_maxabs(f->o));
        if (prox_v3_norm(prox_v3_reject(prox_v3_sub(v[i].anchor, f->o), f->w)) > tol) return 0;
    }
    make_section(a, &v[0], f, &f->s[0]);
    make_section(b, &v[1], f, &f->s[1]);
    return 1;
}

/* The axis vector of an RCC, TRC or ELL as its card gives it; 0 for another kind. */
static int card_axis(const prox_shape *s, prox_vec3 *v)
{
    switch (s->kind) {
    case PROX_SHAPE_RCC: *v = s->u.rcc.axis; return 1;
    case PROX_SHAPE_TRC: *v = s->u.trc.axis; return 1;
    case PROX_SHAPE_ELL: *v = s->u.ell.axis; return 1;
    default: return 0;
    }
}

int prox_coaxial_pair(const prox_shape *a, const prox_shape *b)
{
    /* two axes plainly not parallel (|va x vb| above the tolerance with a margin, in squares: no
     * root, no division), the common case: no frame to build */
    prox_vec3 va, vb;
    if (card_axis(a, &va) && card_axis(b, &vb)) {
        double t = 2.0 * PROX_TOL_COAXIAL_REV;
        if (prox_v3_norm2(prox_v3_cross(va, vb)) > t * t * prox_v3_norm2(va) * prox_v3_norm2(vb)) return 0;
    }
    coax f;
    return make_coax(a, b, &f);
}

/* ---- 2D: support functions, candidates, witnesses ---- */

static double h_sec(const sec2 *s, double nt, double nr)
{
    if (s->ell) return s->tc * nt + prox_hypot2(s->a * nt, s->b * nr);
    double m = s->v[0][0] * nt + s->v[0][1] * nr;
    for (int i = 1; i < s->nv; ++i) m = fmax(m, s->v[i][0] * nt + s->v[i][1] * nr);
    return m;
}

/* Outward unit normal of edge i (from v[i] to v[i+1]) of a counter-clockwise polygon. */
static void edge_normal(const sec2 *s, int i, double *nt, double *nr)
{
    const double *p = s->v[i], *q = s->v[(i + 1) % s->nv];
    double dt = q[0] - p[0], dr = q[1] - p[1], l = prox_hypot2(dt, dr);
    *nt = dr / l, *nr = -dt / l;
}

/* The best direction so far, with its witnesses when the candidate came with them (a vertex and the
 * foot of its normal on an ellipse: more accurate than the support point of the ellipse along the
 * rounded normal, which moves by the radius of curvature (a^2/b for a needle) per radian). */
typedef struct best2 {
    double g, nt, nr;
    int has_w;
    double pa[2], pb[2];
} best2;

static void try_dir_w(const coax *f, best2 *b, double nt, double nr, const double *pa, const double *pb)
{
    double l = prox_hypot2(nt, nr);
    if (!(l > 0.0)) return;
    nt /= l, nr /= l;
    double g = h_sec(&f->s[0], nt, nr) + h_sec(&f->s[1], -nt, -nr), tie = PROX_TOL_CERT * f->scale;
    /* the witnesses count only when they realise g (the vertex supports A or B along n: a mirror
     * vertex's candidate direction may be optimal for the other vertex) */
    int w = pa != NULL && fabs((pa[0] - pb[0]) * nt + (pa[1] - pb[1]) * nr - g) <= tie;
    if (!(g < b->g - tie || (g < b->g + tie && (w > b->has_w || (w == b->has_w && g < b->g))))) return;
    b->g = g, b->nt = nt, b->nr = nr;
    b->has_w = w;
    if (w) b->pa[0] = pa[0], b->pa[1] = pa[1], b->pb[0] = pb[0], b->pb[1] = pb[1];
}
static void try_dir(const coax *f, best2 *b, double nt, double nr) { try_dir_w(f, b, nt, nr, NULL, NULL); }

/* Root of the decreasing function F(x) = (c0 / (m0 - x))^2 + (c1 / x)^2 - 1 on (0, hi) (F(0+) =
 * +inf, F(hi) <= 0), by bisection to the rounding of x. */
static double bisect_root(double c0, double m0, double c1, double hi)
{
    double lo = 0.0;
    for (int it = 0; it < 200; ++it) {
        double x = 0.5 * (lo + hi), a = c0 / (m0 - x), b = c1 / x;
        if (x <= lo || x >= hi) break;
        if (a * a + b * b - 1.0 > 0.0)
            lo = x;
        else
            hi = x;
    }
    return 0.5 * (lo + hi);
}

/* Outward normals of the ellipse (y0/e0)^2 + (y1/e1)^2 = 1 (e0 >= e1) at the feet of the normals
 * from (y0, y1) that can be local minima of h_{E - y}: the roots of the secular equation
 * F(tau) = (z0 / (tau + 1))^2 + (Z / (tau + r^2))^2 - 1 (t = tau e0^2, z0 = y0/e0, Z = (y1/e0) r,
 * r = e1/e0) between its poles, where F is convex with its minimum at p = tau + 1 = D / (1 + k),
 * k = (Z/z0)^(2/3), D = 1 - r^2; and, for y on an axis, the feet off that axis. The nearest foot
 * (the root beyond -r^2) is core/ellipse2's; the root below -1 is the farthest foot, a maximum. */
static int inner_normals(double e0, double e1, double y0, double y1, double nv[4][2], double ft[4][2])
{
    double r = e1 / e0, D = (1.0 - r) * (1.0 + r), z0 = y0 / e0, w1 = y1 / e0, Z = w1 * r;
    int n = 0;
    if (!(D > 0.0)) return 0; /* a circle: every normal passes through its centre */
    if (z0 != 0.0 && Z != 0.0) {
        double k = cbrt((Z / z0) * (Z / z0)), pm = D / (1.0 + k), qm = D - pm;
        double fa = z0 / pm, fb = Z / qm;
        if (fa * fa + fb * fb - 1.0 < 0.0) {
            double p = bisect_root(Z, D, z0, pm); /* left root in p: F = (Z/(D - p))^2 + (z0/p)^2 - 1 */
            double q = bisect_root(z0, D, Z, qm); /* right root in q = D - p */
            /* feet x0 = e0^2 y0 / (t + e0^2) = y0 / p, x1 = e1^2 y1 / (t + e1^2) = -r^2 y1 / (D - p) */
            nv[n][0] = z0 / p, nv[n][1] = -w1 / (D - p), ft[n][0] = y0 / p, ft[n][1] = -r * r * y1 / (D - p), ++n;
            nv[n][0] = z0 / (D - q), nv[n][1] = -w1 / q, ft[n][0] = y0 / (D - q), ft[n][1] = -r * r * y1 / q, ++n;
        }
    } else if (Z == 0.0 && fabs(z0) < D) { /* on the major axis: x0 = y0 / D, x1 = +-e1 sqrt(..) */
        double xd = z0 / D, x1 = sqrt((1.0 - xd) * (1.0 + xd));
        nv[n][0] = xd / e0, nv[n][1] = x1 / e1, ft[n][0] = e0 * xd, ft[n][1] = e1 * x1, ++n;
        nv[n][0] = xd / e0, nv[n][1] = -x1 / e1, ft[n][0] = e0 * xd, ft[n][1] = -e1 * x1, ++n;
    } else if (z0 == 0.0) { /* on the minor axis: x1 / e1 = -(y1/e1) r^2 / D */
        double xd = -(y1 / e1) * r * r / D;
        if (fabs(xd) < 1.0) {
            double x0 = sqrt((1.0 - xd) * (1.0 + xd));
            nv[n][0] = x0 / e0, nv[n][1] = xd / e1, ft[n][0] = e0 * x0, ft[n][1] = e1 * xd, ++n;
            nv[n][0] = -x0 / e0, nv[n][1] = xd / e1, ft[n][0] = -e0 * x0, ft[n][1] = e1 * xd, ++n;
        }
    }
    return n;
}

/* Direction candidates of a vertex (t, r) of one body against the ellipse e of the other: the
 * outward normals of e at the feet of the normals from the vertex that can minimise
 * h_e(nu) - (t, r).nu (the nearest foot, core/ellipse2, and inner_normals), and the normals at e's
 * vertices; each taken as n = sign nu (sign -1 when e is B). */
static void try_vertex_ellipse(const coax *f, best2 *b, const sec2 *e, double t, double r, double rad, double sign)
{
    double y0 = t - e->tc, nv[5][2], ft[5][2], v[2], x[2];
    int ea = sign > 0.0; /* the ellipse is A */
    prox_ellipse2_closest(e->a, e->b, y0, r, &ft[0][0], &ft[0][1]);
    nv[0][0] = ft[0][0] / (e->a * e->a), nv[0][1] = ft[0][1] / (e->b * e->b);
    int swap = e->a < e->b, n = 1;
    double nv2[4][2], ft2[4][2];
    int m = swap ? inner_normals(e->b, e->a, r, y0, nv2, ft2) : inner_normals(e->a, e->b, y0, r, nv2, ft2);
    for (int i = 0; i < m; ++i, ++n)
        nv[n][0] = nv2[i][swap], nv[n][1] = nv2[i][!swap], ft[n][0] = ft2[i][swap], ft[n][1] = ft2[i][!swap];
    for (int i = 0; i < n; ++i) {
        double l = prox_hypot2(nv[i][0], nv[i][1]);
        if (!(l > 0.0)) continue;
        double nt = sign * nv[i][0] / l, nr = sign * nv[i][1] / l;
        /* the vertex side: the point itself, or a circle's support point (centre +- rad n) */
        v[0] = t + (ea ? -rad : rad) * nt, v[1] = r + (ea ? -rad : rad) * nr;
        x[0] = e->tc + ft[i][0], x[1] = ft[i][1];
        try_dir_w(f, b, nt, nr, ea ? x : v, ea ? v : x);
    }
    try_dir(f, b, 0.0, -1.0);
}

/* g and its first two derivatives at angle th for two ellipses (n = (cos th, sin th)). */
static double g_ee(const coax *f, double th, double *d1, double *d2)
{
    double c = cos(th), s = sin(th), g = (f->s[0].tc - f->s[1].tc) * c;
    *d1 = -(f->s[0].tc - f->s[1].tc) * s, *d2 = -(f->s[0].tc - f->s[1].tc) * c;
    for (int k = 0; k < 2; ++k) {
        double a = f->s[k].a, bb = f->s[k].b, h = prox_hypot2(a * c, bb * s);
        double dd = (bb - a) * (bb + a), h1 = dd * s * c / h;
        g += h;
        *d1 += h1;
        *d2 += (dd * (c - s) * (c + s) - h1 * h1) / h;
    }
    return g;
}

/* Two ellipses: g(theta) over [0, pi] (g is even in theta), sampled uniformly and at the normals of
 * points spread evenly along each ellipse (where its support point sweeps fast), then each sampled
 * local minimum polished by Newton on g' inside its bracket, bisecting when a step leaves it. */
static void ellipse_pair(const coax *f, best2 *b)
{
    enum { NU = 48, NS = 2 * NU + 9 };
    double th[NS], gv[NS], d1, d2;
    int n = 0;
    for (int i = 0; i <= NU; ++i) th[n++] = PROX_PI * i / NU;
    for (int k = 0; k < 2; ++k)
        for (int i = 1; i < NU; i += 2) {
            double phi = PROX_PI * i / NU;
            th[n++] = atan2(f->s[k].a * sin(phi), f->s[k].b * cos(phi));
        }
    /* seeds: normals of each ellipse at its nearest points to the other's vertices and co-vertices */
    for (int k = 0; k < 2; ++k) {
        const sec2 *e = &f->s[k], *o = &f->s[1 - k];
        const double y[4][2] = {{o->tc - o->a - e->tc, 0.0}, {o->tc + o->a - e->tc, 0.0}, {o->tc - e->tc, o->b}, {o->tc - e->tc, 0.0}};
        for (int i = 0; i < 4; ++i) {
            double q0, q1;
            prox_ellipse2_closest(e->a, e->b, y[i][0], y[i][1], &q0, &q1);
            th[n++] = fabs(atan2(q1 / (e->b * e->b), (k ? -1.0 : 1.0) * q0 / (e->a * e->a)));
        }
    }
    for (int i = 1; i < n; ++i) /* insertion sort of ~50 angles */
        for (int j = i; j > 0 && th[j] < th[j - 1]; --j) {
            double t = th[j];
            th[j] = th[j - 1], th[j - 1] = t;
        }
    for (int i = 0; i < n; ++i) gv[i] = g_ee(f, th[i], &d1, &d2);
    for (int i = 0; i < n; ++i) {
        if ((i > 0 && gv[i] > gv[i - 1]) || (i < n - 1 && gv[i] > gv[i + 1])) continue;
        try_dir(f, b, cos(th[i]), sin(th[i]));
        double lo = th[i > 0 ? i - 1 : 0], hi = th[i < n - 1 ? i + 1 : n - 1], x = th[i];
        for (int it = 0; it < 100 && hi > lo; ++it) {
            g_ee(f, x, &d1, &d2);
            if (d1 == 0.0) break;
            if (d1 > 0.0)
                hi = x;
            else
                lo = x;
            double nx = d2 > 0.0 ? x - d1 / d2 : 0.5 * (lo + hi);
            if (!(nx > lo && nx < hi)) nx = 0.5 * (lo + hi);
            if (fabs(nx - x) <= 4.0 * DBL_EPSILON * fmax(1.0, fabs(x))) {
                x = nx;
                break;
            }
            x = nx;
        }
        try_dir(f, b, cos(x), sin(x));
    }
}

/* The minimiser of g over the candidate directions. */
static best2 minimise(const coax *f)
{
    best2 b = {INFINITY, 1.0, 0.0, 0, {0, 0}, {0, 0}};
    const sec2 *A = &f->s[0], *B = &f->s[1];
    try_dir(f, &b, 1.0, 0.0);
    try_dir(f, &b, -1.0, 0.0);
    try_dir(f, &b, 0.0, 1.0);
    for (int k = 0; k < 2; ++k) {
        const sec2 *s = &f->s[k];
        if (s->ell) continue;
        for (int i = 0; i < s->nv; ++i) {
            double nt, nr;
            edge_normal(s, i, &nt, &nr);
            try_dir(f, &b, k ? -nt : nt, k ? -nr : nr);
        }
    }
    if (!A->ell && !B->ell) {
        for (int i = 0; i < A->nv; ++i)
            for (int j = 0; j < B->nv; ++j) try_dir(f, &b, B->v[j][0] - A->v[i][0], B->v[j][1] - A->v[i][1]);
    } else if (!A->ell) {
        for (int i = 0; i < A->nv; ++i) try_vertex_ellipse(f, &b, B, A->v[i][0], A->v[i][1], 0.0, -1.0);
    } else if (!B->ell) {
        for (int j = 0; j < B->nv; ++j) try_vertex_ellipse(f, &b, A, B->v[j][0], B->v[j][1], 0.0, 1.0);
    } else if (A->a == A->b) { /* a circle (SPH): its centre against the ellipse, offset by its radius */
        try_vertex_ellipse(f, &b, B, A->tc, 0.0, A->a, -1.0);
    } else if (B->a == B->b) {
        try_vertex_ellipse(f, &b, A, B->tc, 0.0, B->a, 1.0);
    } else {
        ellipse_pair(f, &b);
    }
    return b;
}

/* Support set of a section in direction n: a point (*is_edge = 0, in p) or an edge (p, q) whose
 * normal is within PROX_TOL_PARALLEL of n. */
static void support_set(const sec2 *s, double nt, double nr, double p[2], double q[2], int *is_edge)
{
    *is_edge = 0;
    if (s->ell) {
        double h = prox_hypot2(s->a * nt, s->b * nr);
        p[0] = s->tc + s->a * (s->a * nt / h), p[1] = s->b * (s->b * nr / h);
        return;
    }
    int im = 0;
    double m = -INFINITY;
    for (int i = 0; i < s->nv; ++i) {
        double en, er;
        edge_normal(s, i, &en, &er);
        if (en * nt + er * nr > 0.0 && fabs(en * nr - er * nt) <= PROX_TOL_PARALLEL) {
            *is_edge = 1;
            p[0] = s->v[i][0], p[1] = s->v[i][1];
            q[0] = s->v[(i + 1) % s->nv][0], q[1] = s->v[(i + 1) % s->nv][1];
            return;
        }
        double v = s->v[i][0] * nt + s->v[i][1] * nr;
        if (v > m) m = v, im = i;
    }
    p[0] = s->v[im][0], p[1] = s->v[im][1];
}

/* Radius of curvature of a section's boundary at its support point along n (0 at a vertex): an
 * error e in the direction n moves that support point by about radius x e. For an ellipse,
 * a^2 b^2 / h^3 with h = |(a nt, b nr)|. */
static double radius(const sec2 *s, double nt, double nr)
{
    if (!s->ell) return 0.0;
    double h = prox_hypot2(s->a * nt, s->b * nr);
    return (s->a / h) * (s->b / h) * (s->a * s->b / h);
}

/* Parameter of the point of segment p..q nearest to x, clamped to [0, 1]. */
static double seg_param(const double p[2], const double q[2], const double x[2])
{
    double dt = q[0] - p[0], dr = q[1] - p[1], l2 = dt * dt + dr * dr;
    double s = ((x[0] - p[0]) * dt + (x[1] - p[1]) * dr) / l2;
    return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
}

/* Witnesses for the minimiser: pa on A's support set in n, pb on B's in -n, pb - pa = sd n; *set when
 * a whole segment of pairs is optimal (parallel edges). */
static void witnesses(const coax *f, const best2 *b, double sd, double pa[2], double pb[2], int *set)
{
    double qa[2], qb[2];
    int ea, eb;
    support_set(&f->s[0], b->nt, b->nr, pa, qa, &ea);
    support_set(&f->s[1], -b->nt, -b->nr, pb, qb, &eb);
    *set = 0;
    if (ea && eb) { /* parallel edges: the middle of the overlap of A's edge and B's shifted by -sd n */
        double x0[2] = {pb[0] - sd * b->nt, pb[1] - sd * b->nr}, x1[2] = {qb[0] - sd * b->nt, qb[1] - sd * b->nr};
        double s0 = seg_param(pa, qa, x0), s1 = seg_param(pa, qa, x1), s = 0.5 * (s0 + s1);
        *set = s0 != s1;
        double p0[2] = {pa[0], pa[1]};
        pa[0] = p0[0] + s * (qa[0] - p0[0]), pa[1] = p0[1] + s * (qa[1] - p0[1]);
        pb[0] = pa[0] + sd * b->nt, pb[1] = pa[1] + sd * b->nr;
    } else if (ea) {
        double x[2] = {pb[0] - sd * b->nt, pb[1] - sd * b->nr}, p0[2] = {pa[0], pa[1]};
        double s = seg_param(p0, qa, x);
        pa[0] = p0[0] + s * (qa[0] - p0[0]), pa[1] = p0[1] + s * (qa[1] - p0[1]);
    } else if (eb) {
        double x[2] = {pa[0] + sd * b->nt, pa[1] + sd * b->nr}, p0[2] = {pb[0], pb[1]};
        double s = seg_param(p0, qb, x);
        pb[0] = p0[0] + s * (qb[0] - p0[0]), pb[1] = p0[1] + s * (qb[1] - p0[1]);
    } else if (radius(&f->s[0], b->nt, b->nr) <= radius(&f->s[1], b->nt, b->nr)) {
        /* two points: the support point of the body with the smaller radius of curvature along n
         * is the better conditioned (a vertex: exact); the other follows from p2 - p1 = sd n */
        pb[0] = pa[0] + sd * b->nt, pb[1] = pa[1] + sd * b->nr;
    } else {
        pa[0] = pb[0] - sd * b->nt, pa[1] = pb[1] - sd * b->nr;
    }
}

static prox_vec3 to3(const coax *f, const double p[2])
{
    return prox_v3_mad(prox_v3_mad(f->o, p[0], f->w), p[1], f->u);
}

/* The signed answer of a coaxial frame; *set as in witnesses(), also raised for witnesses off the
 * axis (every rotation of them about the axis is optimal too). */
static prox_signed_result coax_signed(const coax *f, int *set)
{
    prox_signed_result r = {0};
    best2 b = minimise(f);
    double pa[2], pb[2];
    r.sd = -b.g;
    if (b.has_w) {
        pa[0] = b.pa[0], pa[1] = b.pa[1], pb[0] = b.pb[0], pb[1] = b.pb[1];
        *set = 0;
    } else {
        witnesses(f, &b, r.sd, pa, pb, set);
    }
    if (fabs(pa[1]) > PROX_TOL_NOISE * f->scale || fabs(pb[1]) > PROX_TOL_NOISE * f->scale) *set = 1;
    r.normal = prox_v3_mad(prox_v3_scale(f->w, b.nt), b.nr, f->u);
    r.p1 = to3(f, pa);
    r.p2 = to3(f, pb);
    return r;
}

prox_signed_result prox_coaxial_signed_distance(const prox_shape *a, const prox_shape *b)
{
    prox_signed_result r = {0};
    coax f;
    int set;
    r.status = prox_shape_validate(a);
    if (r.status == PROX_OK) r.status = prox_shape_validate(b);
    if (r.status != PROX_OK) return r;
    if (!make_coax(a, b, &f)) {
        r.status = PROX_EUNSUPPORTED;
        return r;
    }
    return coax_signed(&f, &set);
}

prox_distance_result prox_coaxial_distance(const prox_shape *a, const prox_shape *b)
{
    prox_distance_result r = {0};
    coax f;
    r.status = prox_shape_validate(a);
    if (r.status == PROX_OK) r.status = prox_shape_validate(b);
    if (r.status != PROX_OK) return r;
    if (!make_coax(a, b, &f)) {
        r.status = PROX_EUNSUPPORTED;
        return r;
    }
    prox_body ba = prox_body_make(a), bb = prox_body_make(b);
    rev3 va, vb;
    rev_shape(a, &va), rev_shape(b, &vb);
    /* The sections meet exactly when their axis segments do: a common point on the axis. */
    double lo = fmax(f.s[0].tc - f.s[0].hl, f.s[1].tc - f.s[1].hl);
    double hi = fmin(f.s[0].tc + f.s[0].hl, f.s[1].tc + f.s[1].hl);
    if (lo <= hi) {
        r.intersect = 1;
        r.p1 = r.p2 = prox_v3_mad(f.o, 0.5 * (lo + hi), f.w);
        double tol = PROX_TOL_TOUCH * f.scale;
        r.certified = prox_body_contains(&ba, r.p1, tol) && prox_body_contains(&bb, r.p1, tol);
        return r;
    }
    int set;
    prox_signed_result s = coax_signed(&f, &set);
    r.distance = fmax(s.sd, 0.0);
    r.p1 = s.p1, r.p2 = s.p2;
    r.point_set = set;
    /* -h_B(-n) - h_A(n), with the centres' difference taken from the anchors (no cancellation against
     * the position of the pair) */
    prox_vec3 dc = prox_v3_add(prox_v3_sub(vb.anchor, va.anchor), prox_v3_sub(vb.hv, va.hv));
    r.certificate_gap = prox_v3_dot(s.normal, dc) - prox_body_hc(&bb, prox_v3_neg(s.normal)) - prox_body_hc(&ba, s.normal);
    r.certified = r.distance - r.certificate_gap <= PROX_TOL_CERT * f.scale;
    return r;
}
