/* The curved macrobodies of the core (core/curved.h): TRC, REC and ELL. Every closest point,
 * boundary distance, membership and support point is checked against an independent brute force in
 * long double on the body's own surface parametrisation (built from the card, not from the prepared
 * body): a dense grid of each facet, the best grid points refined by a shrinking compass search.
 * Then the validators' named errors, near-degenerate families, far points, scale and motion. */
#include "test_util.h"

#include <float.h>
#include <string.h>

#include "core/curved.h"
#include "core/curved_normal.h"
#include "core/ellipse2.h"

typedef long double ld;

/* ---- the body as the card describes it, in long double ---- */

typedef struct lv3 {
    ld x, y, z;
} lv3;
static lv3 lv(prox_vec3 v) { return (lv3){v.x, v.y, v.z}; }
static lv3 ladd(lv3 a, lv3 b) { return (lv3){a.x + b.x, a.y + b.y, a.z + b.z}; }
static lv3 lsub(lv3 a, lv3 b) { return (lv3){a.x - b.x, a.y - b.y, a.z - b.z}; }
static lv3 lscale(lv3 a, ld s) { return (lv3){a.x * s, a.y * s, a.z * s}; }
static ld ldot(lv3 a, lv3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ld lnorm(lv3 a) { return sqrtl(ldot(a, a)); }
static lv3 lunit(lv3 a) { return lscale(a, 1.0L / lnorm(a)); }
static lv3 lcross(lv3 a, lv3 b) { return (lv3){a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

enum { K_TRC, K_REC, K_ELL };

/* A body: origin o (base centre, or the ELL's centre), orthonormal frame w (axis), e1, e2, sizes. */
typedef struct lbody {
    int kind;
    lv3 o, w, e1, e2;
    ld h, r1, r2; /* TRC: height, radii; REC: height, semi-axes along e1, e2; ELL: a (along w), b */
    ld size;
} lbody;

static lbody lbody_trc(const prox_trc *t)
{
    lbody b = {.kind = K_TRC, .o = lv(t->base), .h = lnorm(lv(t->axis)), .r1 = t->r1, .r2 = t->r2};
    b.w = lunit(lv(t->axis));
    prox_vec3 p = prox_v3_any_perp(prox_v3(b.w.x, b.w.y, b.w.z));
    b.e1 = lunit(lsub(lv(p), lscale(b.w, ldot(lv(p), b.w))));
    b.e2 = lcross(b.w, b.e1);
    b.size = fmaxl(b.h, 2 * fmaxl(b.r1, b.r2));
    return b;
}
static lbody lbody_rec(const prox_rec *r)
{
    lbody b = {.kind = K_REC, .o = lv(r->base), .h = lnorm(lv(r->axis)), .r1 = lnorm(lv(r->a1)), .r2 = lnorm(lv(r->a2))};
    b.w = lunit(lv(r->axis));
    b.e1 = lunit(lv(r->a1));
    b.e2 = lunit(lv(r->a2));
    b.size = fmaxl(b.h, 2 * fmaxl(b.r1, b.r2));
    return b;
}
static lbody lbody_ell(const prox_ell *e)
{
    lbody b = {.kind = K_ELL, .o = lv(e->center), .h = lnorm(lv(e->axis)), .r1 = e->radius};
    b.w = lunit(lv(e->axis));
    prox_vec3 p = prox_v3_any_perp(prox_v3(b.w.x, b.w.y, b.w.z));
    b.e1 = lunit(lsub(lv(p), lscale(b.w, ldot(lv(p), b.w))));
    b.e2 = lcross(b.w, b.e1);
    b.size = 2 * fmaxl(b.h, b.r1);
    return b;
}

/* Grid points of the boundary (for the support test): facet f at parameters (u, v) in [0, 1]^2. */
static int nfacets(const lbody *b) { return b->kind == K_ELL ? 1 : 3; }
static lv3 facet(const lbody *b, int f, ld u, ld v)
{
    ld th = 2 * 3.14159265358979323846264338327950288L * v, c = cosl(th), s = sinl(th);
    if (b->kind == K_ELL) {
        ld ph = 3.14159265358979323846264338327950288L * u;
        lv3 r = ladd(lscale(b->e1, b->r1 * sinl(ph) * c), lscale(b->e2, b->r1 * sinl(ph) * s));
        return ladd(ladd(b->o, lscale(b->w, b->h * cosl(ph))), r);
    }
    ld ax = f == 0 ? u * b->h : (f == 1 ? 0 : b->h);
    ld c1, c2; /* radial coefficients along e1, e2 */
    if (b->kind == K_TRC) {
        ld r = f == 0 ? b->r1 + (b->r2 - b->r1) * u : (f == 1 ? u * b->r1 : u * b->r2);
        c1 = r * c, c2 = r * s;
    } else {
        ld m = f == 0 ? 1 : u;
        c1 = m * b->r1 * c, c2 = m * b->r2 * s;
    }
    return ladd(ladd(b->o, lscale(b->w, ax)), ladd(lscale(b->e1, c1), lscale(b->e2, c2)));
}

/* Membership of the closed solid, from the card's definition. */
static int linside(const lbody *b, lv3 y)
{
    lv3 d = lsub(y, b->o);
    ld t = ldot(d, b->w), x1 = ldot(d, b->e1), x2 = ldot(d, b->e2);
    if (b->kind == K_ELL) return (t / b->h) * (t / b->h) + (x1 * x1 + x2 * x2) / (b->r1 * b->r1) <= 1;
    if (t < 0 || t > b->h) return 0;
    if (b->kind == K_TRC) {
        ld r = b->r1 + (b->r2 - b->r1) * t / b->h;
        return x1 * x1 + x2 * x2 <= r * r;
    }
    return (x1 / b->r1) * (x1 / b->r1) + (x2 / b->r2) * (x2 / b->r2) <= 1;
}

/* ---- brute force: least distance to the boundary as 1D searches ---- */

/* The point in the body's frame: axial t from the origin, x1, x2 across, rho = |(x1, x2)|. */
typedef struct lpt {
    const lbody *b;
    ld t, x1, x2, rho;
    int cap; /* REC rim: which cap */
} lpt;

/* Least value of f over [lo, hi]: n + 1 samples, then a golden-section search around every sampled
 * local minimum (its two neighbours as the bracket), 110 steps (0.618^110 ~ 1e-23 of the bracket). */
typedef ld (*fn1)(const lpt *p, ld s);
static ld min1d(fn1 f, const lpt *p, ld lo, ld hi, int n)
{
    enum { NMAX = 4096 };
    static ld v[NMAX + 1];
    ld best = INFINITY, step = (hi - lo) / n;
    for (int i = 0; i <= n; ++i) v[i] = f(p, lo + i * step);
    const ld gr = 0.6180339887498948482045868343656381L;
    for (int i = 0; i <= n; ++i) {
        if ((i > 0 && v[i] > v[i - 1]) || (i < n && v[i] > v[i + 1])) continue;
        ld a = lo + (i > 0 ? i - 1 : 0) * step, c = lo + (i < n ? i + 1 : n) * step;
        ld x1 = c - gr * (c - a), x2 = a + gr * (c - a), f1 = f(p, x1), f2 = f(p, x2);
        for (int it = 0; it < 110; ++it) {
            if (f1 < f2)
                c = x2, x2 = x1, f2 = f1, x1 = c - gr * (c - a), f1 = f(p, x1);
            else
                a = x1, x1 = x2, f1 = f2, x2 = a + gr * (c - a), f2 = f(p, x2);
        }
        best = fminl(best, fminl(v[i], fminl(f1, f2)));
    }
    return best;
}

static ld hyp(ld a, ld b) { return sqrtl(a * a + b * b); }
/* TRC generator at u in [0, 1] and ELL meridian at angle s, in the point's half-plane. */
static ld trc_side(const lpt *p, ld u) { return hyp(p->t - u * p->b->h, p->rho - (p->b->r1 + (p->b->r2 - p->b->r1) * u)); }
static ld ell_meridian(const lpt *p, ld s) { return hyp(p->t - p->b->h * cosl(s), p->rho - p->b->r1 * sinl(s)); }
/* REC: the lateral line at angle s (nearest point of its segment 0 <= t <= h) and the cap rim. */
static ld rec_side(const lpt *p, ld s)
{
    ld dt = p->t < 0 ? -p->t : (p->t > p->b->h ? p->t - p->b->h : 0);
    return hyp(dt, hyp(p->x1 - p->b->r1 * cosl(s), p->x2 - p->b->r2 * sinl(s)));
}
static ld rec_rim(const lpt *p, ld s)
{
    return hyp(p->t - (p->cap ? p->b->h : 0), hyp(p->x1 - p->b->r1 * cosl(s), p->x2 - p->b->r2 * sinl(s)));
}

/* Least distance from y to the boundary: each facet by its own 1D search (a disk or an elliptical
 * disk: the foot of the perpendicular when inside it, else its rim). */
#define NS 1024
static ld brute_boundary(const lbody *b, lv3 y)
{
    lv3 d = lsub(y, b->o);
    lpt p = {b, ldot(d, b->w), ldot(d, b->e1), ldot(d, b->e2), 0, 0};
    p.rho = hyp(p.x1, p.x2);
    const ld PI = 3.14159265358979323846264338327950288L;
    if (b->kind == K_ELL) return min1d(ell_meridian, &p, 0, PI, NS);
    if (b->kind == K_TRC) {
        ld best = min1d(trc_side, &p, 0, 1, NS);
        for (int cap = 0; cap < 2; ++cap) {
            ld rc = cap ? b->r2 : b->r1, tc = cap ? b->h : 0;
            best = fminl(best, hyp(p.t - tc, p.rho <= rc ? 0 : p.rho - rc));
        }
        return best;
    }
    ld best = min1d(rec_side, &p, 0, 2 * PI, NS);
    int in = (p.x1 / b->r1) * (p.x1 / b->r1) + (p.x2 / b->r2) * (p.x2 / b->r2) <= 1;
    for (p.cap = 0; p.cap < 2; ++p.cap)
        best = fminl(best, in ? fabsl(p.t - (p.cap ? b->h : 0)) : min1d(rec_rim, &p, 0, 2 * PI, NS));
    return best;
}

/* ---- the prepared body ---- */

typedef struct body {
    int kind;
    prox_vec3 c;
    prox_cone k;
    prox_ecyl e;
    prox_ellb l;
} body;

static body make_trc(const prox_trc *t)
{
    body b = {.kind = K_TRC};
    b.c = prox_cone_make(t, &b.k);
    return b;
}
static body make_rec(const prox_rec *r)
{
    body b = {.kind = K_REC};
    b.c = prox_ecyl_make(r, &b.e);
    return b;
}
static body make_ell(const prox_ell *e)
{
    body b = {.kind = K_ELL};
    b.c = prox_ellb_make(e, &b.l);
    return b;
}
static double b_boundary(const body *b, prox_vec3 x, prox_vec3 *q)
{
    prox_vec3 y = prox_v3_sub(x, b->c), qc;
    double s = b->kind == K_TRC ? prox_cone_boundary(&b->k, y, &qc)
                                : (b->kind == K_REC ? prox_ecyl_boundary(&b->e, y, &qc) : prox_ellb_boundary(&b->l, y, &qc));
    *q = prox_v3_add(b->c, qc);
    return s;
}
static double b_boundary_n(const body *b, prox_vec3 x, prox_vec3 *q, prox_vec3 *n)
{
    prox_vec3 y = prox_v3_sub(x, b->c), qc;
    double s = b->kind == K_TRC ? prox_cone_boundary_n(&b->k, y, &qc, n)
                                : (b->kind == K_REC ? prox_ecyl_boundary_n(&b->e, y, &qc, n) : prox_ellb_boundary_n(&b->l, y, &qc, n));
    *q = prox_v3_add(b->c, qc);
    return s;
}
static prox_vec3 b_closest(const body *b, prox_vec3 x)
{
    prox_vec3 y = prox_v3_sub(x, b->c);
    prox_vec3 q = b->kind == K_TRC ? prox_cone_closest(&b->k, y)
                                   : (b->kind == K_REC ? prox_ecyl_closest(&b->e, y) : prox_ellb_closest(&b->l, y));
    return prox_v3_add(b->c, q);
}
static int b_contains(const body *b, prox_vec3 x, double tol)
{
    prox_vec3 y = prox_v3_sub(x, b->c);
    return b->kind == K_TRC ? prox_cone_contains(&b->k, y, tol)
                            : (b->kind == K_REC ? prox_ecyl_contains(&b->e, y, tol) : prox_ellb_contains(&b->l, y, tol));
}
static double b_hc(const body *b, prox_vec3 d)
{
    return b->kind == K_TRC ? prox_cone_hc(&b->k, d) : (b->kind == K_REC ? prox_ecyl_hc(&b->e, d) : prox_ellb_hc(&b->l, d));
}
static prox_vec3 b_pc(const body *b, prox_vec3 d)
{
    return b->kind == K_TRC ? prox_cone_pc(&b->k, d) : (b->kind == K_REC ? prox_ecyl_pc(&b->e, d) : prox_ellb_pc(&b->l, d));
}

/* ---- axes along (1, 1, 1) ---- */

/* A TRC and an ELL whose axis is (L, L, L): a direction d = +-w or a point on the axis leaves, after
 * the radial part is rejected twice, a residual of three equal components, i.e. along w itself. It
 * is rounding (core/axis.h): the support point along the axis is the cap's centre or the pole, never
 * a "rim point" on the axis r beyond the cap, and a point on the axis has its nearest boundary point
 * on the lateral surface or the equator at the radius, with a normal not along the axis. Lengths L
 * from 1e-3 to 1e20 (the residual's size follows d.w's rounding). */
static void test_axis_diagonal(void **state)
{
    (void)state;
    int fails = 0;
    for (int e = -3; e <= 20; ++e) {
        double L = pow(10.0, e) * 1.37;
        prox_vec3 axis = prox_v3(L, L, L), base = prox_v3(0.3 * L, 0.3 * L, 0.3 * L);
        body bs[2] = {make_trc(&(prox_trc){base, axis, 0.6 * L, 0.3 * L}), make_ell(&(prox_ell){base, axis, 0.5 * L})};
        for (int i = 0; i < 2; ++i) {
            const body *b = &bs[i];
            prox_vec3 w = i == 0 ? b->k.w : b->l.w;
            double size = 4.0 * L, tol = 1e-12 * size;
            for (int sg = -1; sg <= 1; sg += 2) {
                prox_vec3 p = prox_v3_add(b->c, b_pc(b, prox_v3_scale(w, sg)));
                fails += !b_contains(b, p, tol);
                fails += prox_v3_norm(prox_v3_reject(prox_v3_sub(p, b->c), w)) > tol; /* on the axis */
            }
            for (int k = 0; k < 16; ++k) { /* points on the axis near the centre, inside */
                double t = (k - 7.5) * 0.01 * L;
                prox_vec3 x = prox_v3_mad(b->c, t, prox_v3(1, 1, 1)), q, n;
                double sd = b_boundary_n(b, x, &q, &n);
                fails += !(sd < 0.0);
                fails += fabs(prox_v3_dist(x, q) + sd) > tol; /* q at |sd| from x */
                fails += !b_contains(b, q, tol) || fabs(prox_v3_norm(n) - 1.0) > 1e-12;
                fails += fabs(prox_v3_dot(n, w)) > 0.5; /* lateral or equatorial, not a cap */
            }
        }
    }
    assert_int_equal(fails, 0);
}

/* ---- random bodies ---- */

static double logu(test_rng *g, double lo, double hi) { return pow(10.0, test_range(g, log10(lo), log10(hi))); }

static prox_trc rand_trc(test_rng *g, prox_vec3 base)
{
    prox_trc t = {base, prox_v3_scale(test_unit(g), logu(g, 0.1, 10)), logu(g, 0.1, 10), logu(g, 0.1, 10)};
    int m = (int)(test_uniform(g) * 4);
    if (m == 0) t.r2 = 0; /* a full cone, apex at the top */
    if (m == 1) t.r1 = 0; /* apex at the base */
    return t;
}
static prox_rec rand_rec(test_rng *g, prox_vec3 base)
{
    test_rot R = test_random_rot(g);
    prox_rec r = {base, prox_v3_scale(test_rot_apply(&R, prox_v3(0, 0, 1)), logu(g, 0.1, 10)),
                  prox_v3_scale(test_rot_apply(&R, prox_v3(1, 0, 0)), logu(g, 0.1, 10)),
                  prox_v3_scale(test_rot_apply(&R, prox_v3(0, 1, 0)), logu(g, 0.1, 10))};
    return r;
}
static prox_ell rand_ell(test_rng *g, prox_vec3 c)
{
    prox_ell e = {c, prox_v3_scale(test_unit(g), logu(g, 0.1, 10)), logu(g, 0.1, 10)};
    return e;
}

/* A random body of kind k and its long double twin. */
static void rand_body(test_rng *g, int k, prox_vec3 at, body *b, lbody *lb)
{
    if (k == K_TRC) {
        prox_trc t = rand_trc(g, at);
        assert_int_equal(prox_trc_validate(&t), PROX_OK);
        *b = make_trc(&t), *lb = lbody_trc(&t);
    } else if (k == K_REC) {
        prox_rec r = rand_rec(g, at);
        assert_int_equal(prox_rec_validate(&r), PROX_OK);
        *b = make_rec(&r), *lb = lbody_rec(&r);
    } else {
        prox_ell e = rand_ell(g, at);
        assert_int_equal(prox_ell_validate(&e), PROX_OK);
        *b = make_ell(&e), *lb = lbody_ell(&e);
    }
}

/* A test point: inside, near the boundary (either side), on the axis, or far. */
static prox_vec3 rand_point(test_rng *g, const lbody *lb)
{
    lv3 c = lb->kind == K_ELL ? lb->o : ladd(lb->o, lscale(lb->w, lb->h / 2));
    int m = (int)(test_uniform(g) * 5);
    prox_vec3 p;
    if (m == 0) { /* near a random boundary point */
        int f = (int)(test_uniform(g) * nfacets(lb));
        lv3 x = facet(lb, f, test_uniform(g), test_uniform(g));
        lv3 d = lv(test_unit(g));
        x = ladd(x, lscale(d, (ld)lb->size * pow(10.0, test_range(g, -12, -1))));
        p = prox_v3(x.x, x.y, x.z);
    } else if (m == 1) { /* on the axis line */
        lv3 x = ladd(c, lscale(lb->w, lb->size * test_range(g, -1.5, 1.5)));
        p = prox_v3(x.x, x.y, x.z);
    } else {
        double r = lb->size * (m == 2 ? 0.3 : (m == 3 ? 1.5 : 50.0));
        lv3 x = ladd(c, lscale(lv(test_unit(g)), r * test_uniform(g)));
        p = prox_v3(x.x, x.y, x.z);
    }
    return p;
}

/* 1 when q lies on the boundary to within tol (long double residual of the nearest facet). */
static int on_boundary(const lbody *b, prox_vec3 q, ld tol)
{
    lv3 d = lsub(lv(q), b->o);
    ld t = ldot(d, b->w), x1 = ldot(d, b->e1), x2 = ldot(d, b->e2), rho = sqrtl(x1 * x1 + x2 * x2);
    if (b->kind == K_ELL) {
        ld f = (t / b->h) * (t / b->h) + (rho / b->r1) * (rho / b->r1);
        return fabsl(sqrtl(f) - 1) * fminl(b->h, b->r1) <= tol;
    }
    if (t < -tol || t > b->h + tol) return 0;
    if (b->kind == K_TRC) {
        ld r = b->r1 + (b->r2 - b->r1) * t / b->h, slant = sqrtl(b->h * b->h + (b->r2 - b->r1) * (b->r2 - b->r1));
        if (fabsl(rho - r) * b->h / slant <= tol) return 1;
        ld rc = fabsl(t) < fabsl(t - b->h) ? b->r1 : b->r2;
        return fminl(fabsl(t), fabsl(t - b->h)) <= tol && rho <= rc + tol;
    }
    ld f = sqrtl((x1 / b->r1) * (x1 / b->r1) + (x2 / b->r2) * (x2 / b->r2));
    if (fabsl(f - 1) * b->r2 <= tol) return 1;
    return fminl(fabsl(t), fabsl(t - b->h)) <= tol && f <= 1 + tol / b->r2;
}

/* ---- tests ---- */

/* boundary(): the signed distance equals the brute force's least distance (sign from the card's
 * membership), |x - q| equals it, and q is on the boundary. closest(): x itself inside, q outside. */
static void check_boundary_kind(int kind, int n, uint64_t seed)
{
    test_rng g = test_rng_seed(seed);
    for (int i = 0; i < n; ++i) {
        body b;
        lbody lb;
        rand_body(&g, kind, prox_v3(test_range(&g, -5, 5), test_range(&g, -5, 5), test_range(&g, -5, 5)), &b, &lb);
        prox_vec3 x = rand_point(&g, &lb), q;
        double s = b_boundary(&b, x, &q);
        ld S = lb.size + lnorm(lsub(lv(x), lb.o));
        ld bd = brute_boundary(&lb, lv(x));
        int in = linside(&lb, lv(x));
        ld tol = 4e-15L * S;
        if (!(fabsl(fabsl(s) - bd) <= tol) || !(fabsl(lnorm(lsub(lv(x), lv(q))) - fabsl(s)) <= tol) ||
            !on_boundary(&lb, q, tol) || (bd > tol && (s < 0) != in)) {
            print_error("kind %d case %d: s %.17g brute %.17Lg in %d |x-q| %.17Lg on %d\n", kind, i, s, bd, in,
                        lnorm(lsub(lv(x), lv(q))), on_boundary(&lb, q, tol));
            fail();
        }
        prox_vec3 c = b_closest(&b, x);
        if (in && bd > tol) {
            assert_true(lnorm(lsub(lv(c), lv(x))) <= 1e-15L * S); /* x itself, up to (x - c) + c */
        } else if (!in && bd > tol) {
            assert_true(fabsl(lnorm(lsub(lv(x), lv(c))) - bd) <= tol);
            assert_true(on_boundary(&lb, c, tol));
        }
    }
}
static void test_trc_boundary(void **state) { (void)state, check_boundary_kind(K_TRC, 150, 11); }
static void test_rec_boundary(void **state) { (void)state, check_boundary_kind(K_REC, 150, 12); }
static void test_ell_boundary(void **state) { (void)state, check_boundary_kind(K_ELL, 150, 13); }

/* contains(x, tol) is membership of the solid grown by tol: decided by the brute distance. */
static void test_contains(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(21);
    for (int i = 0; i < 300; ++i) {
        int kind = i % 3;
        body b;
        lbody lb;
        rand_body(&g, kind, prox_v3(1, 2, 3), &b, &lb);
        prox_vec3 x = rand_point(&g, &lb);
        double tol = test_uniform(&g) < 0.3 ? 0.0 : lb.size * pow(10.0, test_range(&g, -6, 0));
        ld S = lb.size + lnorm(lsub(lv(x), lb.o));
        ld d = linside(&lb, lv(x)) ? 0 : brute_boundary(&lb, lv(x));
        int got = b_contains(&b, x, tol);
        if (d <= tol - 4e-15L * S) assert_int_equal(got, 1);
        if (d >= tol + 4e-15L * S) assert_int_equal(got, 0);
    }
}

/* The same at the shell itself: tol a hair above or below the point's distance from the solid, where
 * the quadratic forms of the REC and ELL sections (the section enlarged by tol inside, scaled by
 * 1 + tol / least semi-axis outside) must hand over to the closest point; prolate, oblate and flat
 * sections, points off every side. */
static void test_contains_shell(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(22);
    int tested = 0;
    for (int i = 0; i < 1200; ++i) {
        int kind = i % 3;
        body b;
        lbody lb;
        rand_body(&g, kind, prox_v3(-2, 5, 1), &b, &lb);
        prox_vec3 x = rand_point(&g, &lb);
        if (linside(&lb, lv(x))) continue;
        ld S = lb.size + lnorm(lsub(lv(x), lb.o)), d = brute_boundary(&lb, lv(x));
        ld margin = 1e-6L * d > 1e-13L * S ? 1e-6L * d : 1e-13L * S;
        ++tested;
        assert_int_equal(b_contains(&b, x, (double)(d + margin)), 1);
        if (d - margin > 0) assert_int_equal(b_contains(&b, x, (double)(d - margin)), 0);
    }
    assert_true(tested > 300);
}

/* Support point: in the body, d.pc(d) = hc(d) to rounding, and no sampled boundary point beyond. */
static void test_support(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(31);
    for (int i = 0; i < 240; ++i) {
        int kind = i % 3;
        body b;
        lbody lb;
        rand_body(&g, kind, prox_v3(-3, 1, 7), &b, &lb);
        prox_vec3 d = prox_v3_scale(test_unit(&g), logu(&g, 1e-3, 1e3));
        if (i % 12 == 5) d = prox_v3(lb.w.x, lb.w.y, lb.w.z); /* along the axis */
        if (i % 12 == 7) d = prox_v3(lb.e1.x, lb.e1.y, lb.e1.z); /* across it */
        if (i % 12 == 9 && kind == K_TRC) { /* normal to the conical surface: the generator supports */
            ld slope = (lb.r1 - lb.r2) / lb.h;
            lv3 n = lunit(ladd(lb.e1, lscale(lb.w, slope)));
            d = prox_v3(n.x, n.y, n.z);
        }
        double h = b_hc(&b, d);
        prox_vec3 p = b_pc(&b, d);
        ld dn = lnorm(lv(d)), tol = 1e-14L * lb.size * dn;
        assert_true(fabsl((ld)prox_v3_dot(d, p) - h) <= tol);
        assert_true(b_contains(&b, prox_v3_add(b.c, p), 1e-14 * lb.size));
        ld mx = -INFINITY;
        lv3 c = lv(b.c);
        for (int f = 0; f < nfacets(&lb); ++f)
            for (int u = 0; u <= 40; ++u)
                for (int v = 0; v < 64; ++v) {
                    ld val = ldot(lv(d), lsub(facet(&lb, f, u / 40.0L, v / 64.0L), c));
                    if (val > mx) mx = val;
                }
        assert_true(mx <= h + tol);
        assert_true(h <= mx + 1e-2L * lb.size * dn); /* the grid is within a cell of the maximum */
        assert_true(fabs(b_hc(&b, prox_v3(0, 0, 0))) == 0.0);
    }
}

/* The generator's middle on the tie, the cap centre along the axis, the side segment's middle for a
 * REC direction across its axis. */
static void test_support_sets(void **state)
{
    (void)state;
    prox_trc t = {prox_v3(0, 0, 0), prox_v3(0, 0, 2), 2, 1};
    body b = make_trc(&t);
    prox_vec3 n = prox_v3_normalize(prox_v3(2, 0, 1)); /* normal of the generator (1,0,-1)..(2... */
    prox_vec3 p = b_pc(&b, n);
    /* the generator runs from (2, 0, -1) to (1, 0, 1) about the centre: its middle (1.5, 0, 0) */
    assert_near(p.x, 1.5, 1e-15);
    assert_near(p.y, 0.0, 1e-15);
    assert_near(p.z, 0.0, 1e-15);
    p = b_pc(&b, prox_v3(0, 0, 1));
    assert_near(p.x, 0.0, 0.0);
    assert_near(p.z, 1.0, 0.0);
    prox_rec r = {prox_v3(0, 0, 0), prox_v3(0, 0, 4), prox_v3(3, 0, 0), prox_v3(0, 1, 0)};
    body e = make_rec(&r);
    p = b_pc(&e, prox_v3(1, 0, 0));
    assert_near(p.x, 3.0, 1e-15);
    assert_near(p.z, 0.0, 0.0);
    p = b_pc(&e, prox_v3(0, 0, -1));
    assert_near(p.x, 0.0, 0.0);
    assert_near(p.z, -2.0, 0.0);
}

/* Special points: the centre, the axis, the ELL's centre of curvature, a point exactly on the
 * boundary; exact answers by hand. */
static void test_special_points(void **state)
{
    (void)state;
    prox_vec3 q;
    prox_ell e = {prox_v3(0, 0, 0), prox_v3(0, 0, 3), 1}; /* prolate, a = 3 along z, b = 1 */
    body b = make_ell(&e);
    assert_near(b_boundary(&b, prox_v3(0, 0, 0), &q), -1.0, 1e-15);
    assert_near(hypot(q.x, q.y), 1.0, 1e-15);
    assert_near(b_boundary(&b, prox_v3(0, 0, 5), &q), 2.0, 1e-15);
    assert_near(q.z, 3.0, 1e-15);
    /* on the axis inside beyond the centre of curvature a - b^2/a of the vertex: the vertex */
    assert_near(b_boundary(&b, prox_v3(0, 0, 2.9), &q), -0.1, 1e-15);
    /* before it the nearest points leave the axis: x0 = a^2 y0 / (a^2 - b^2) */
    double y0 = 1.0, x0 = 9.0 * y0 / 8.0, x1 = sqrt(1.0 - x0 * x0 / 9.0);
    assert_near(b_boundary(&b, prox_v3(0, 0, y0), &q), -hypot(x0 - y0, x1), 1e-15);
    prox_ell o = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 3}; /* oblate */
    b = make_ell(&o);
    assert_near(b_boundary(&b, prox_v3(0, 0, 0), &q), -1.0, 1e-15);
    assert_near(fabs(q.z), 1.0, 1e-15);
    assert_near(b_boundary(&b, prox_v3(5, 0, 0), &q), 2.0, 1e-15);
    prox_trc t = {prox_v3(0, 0, -1), prox_v3(0, 0, 2), 1, 0}; /* apex at (0, 0, 1) */
    b = make_trc(&t);
    assert_near(b_boundary(&b, prox_v3(0, 0, 3), &q), 2.0, 1e-15);
    assert_near(q.z, 1.0, 1e-15);
    assert_near(b_boundary(&b, prox_v3(0, 0, -3), &q), 2.0, 1e-15);
    /* centre of the cone: the generator at distance (r(0)) cos(alpha), r(0) = 1/2, tan(alpha) = 1/2 */
    assert_near(b_boundary(&b, prox_v3(0, 0, 0), &q), -0.5 * 2.0 / sqrt(5.0), 1e-15);
    prox_rec r = {prox_v3(0, 0, -1), prox_v3(0, 0, 2), prox_v3(4, 0, 0), prox_v3(0, 2, 0)};
    b = make_rec(&r);
    assert_near(b_boundary(&b, prox_v3(0, 0, 0), &q), -1.0, 1e-15); /* the caps, 1 away */
    assert_near(b_boundary(&b, prox_v3(0, 0, 0.5), &q), -0.5, 1e-15);
    assert_near(q.z, 1.0, 1e-15);
    assert_near(b_boundary(&b, prox_v3(0, 5, 0), &q), 3.0, 1e-15);
    assert_near(b_boundary(&b, prox_v3(0, 5, 5), &q), hypot(3.0, 4.0), 1e-15);
    assert_int_equal(b_contains(&b, prox_v3(4, 0, 1), 0.0), 1);
    assert_int_equal(b_contains(&b, prox_v3(4.5, 0, 1.5), 0.5), 0);
    assert_int_equal(b_contains(&b, prox_v3(4.3, 0, 1.4), 0.5), 1);
}

/* Near-degenerate families against closed forms of their limits. */
static void test_near_degenerate(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(41);
    prox_vec3 q;
    for (int i = 0; i < 200; ++i) {
        prox_vec3 x = prox_v3_scale(test_unit(&g), test_range(&g, 0, 4));
        /* an ELL nearly a sphere of radius 1 */
        prox_ell e = {prox_v3(0, 0, 0), prox_v3_scale(test_unit(&g), 1.0 + 1e-14), 1.0};
        body b = make_ell(&e);
        assert_near(b_boundary(&b, x, &q), prox_v3_norm(x) - 1.0, 1e-14);
        /* a REC nearly an RCC of radius 1, height 2 centred at 0 */
        prox_rec r = {prox_v3(0, 0, -1), prox_v3(0, 0, 2), prox_v3(1.0 + 1e-14, 0, 0), prox_v3(0, 1, 0)};
        b = make_rec(&r);
        double rho = hypot(x.x, x.y), dt = fabs(x.z) - 1.0, dr = rho - 1.0;
        double ex = dt > 0 || dr > 0 ? hypot(fmax(dt, 0), fmax(dr, 0)) : fmax(dt, dr);
        assert_near(b_boundary(&b, x, &q), ex, 3e-14);
        /* a TRC nearly that RCC */
        prox_trc t = {prox_v3(0, 0, -1), prox_v3(0, 0, 2), 1.0, 1.0 - 1e-13};
        b = make_trc(&t);
        assert_near(b_boundary(&b, x, &q), ex, 3e-13);
    }
}

/* Very flat and very elongated bodies and the needle cone, against the brute force. */
static void test_extreme_aspect(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(51);
    for (int i = 0; i < 90; ++i) {
        body b;
        lbody lb;
        double f = pow(10.0, -test_range(&g, 3, 6)); /* aspect */
        prox_vec3 w = test_unit(&g), u = prox_v3_any_perp(w), v = prox_v3_cross(w, u);
        switch (i % 6) {
        case 0: { prox_trc t = {prox_v3(0, 0, 0), w, f, 0}; b = make_trc(&t), lb = lbody_trc(&t); break; } /* needle */
        case 1: { prox_trc t = {prox_v3(0, 0, 0), prox_v3_scale(w, f), 1, 0.5}; b = make_trc(&t), lb = lbody_trc(&t); break; } /* flat */
        case 2: { prox_rec r = {prox_v3(0, 0, 0), w, u, prox_v3_scale(v, f)}; b = make_rec(&r), lb = lbody_rec(&r); break; }
        case 3: { prox_rec r = {prox_v3(0, 0, 0), prox_v3_scale(w, f), u, prox_v3_scale(v, 0.5)}; b = make_rec(&r), lb = lbody_rec(&r); break; }
        case 4: { prox_ell e = {prox_v3(0, 0, 0), w, f}; b = make_ell(&e), lb = lbody_ell(&e); break; } /* prolate needle */
        default: { prox_ell e = {prox_v3(0, 0, 0), prox_v3_scale(w, f), 1}; b = make_ell(&e), lb = lbody_ell(&e); break; } /* oblate disk */
        }
        lv3 c = ladd(lb.o, lscale(lb.w, lb.kind == K_ELL ? 0 : lb.h / 2));
        prox_vec3 x = prox_v3(c.x, c.y, c.z);
        x = prox_v3_mad(x, test_range(&g, 0, 1.2) * lb.size, test_unit(&g));
        prox_vec3 q;
        double s = b_boundary(&b, x, &q);
        ld bd = brute_boundary(&lb, lv(x)), S = lb.size;
        if (!(fabsl(fabsl(s) - bd) <= 4e-15L * S) || !on_boundary(&lb, q, 4e-15L * S)) {
            print_error("case %d: s %.17g brute %.17Lg\n", i, s, bd);
            fail();
        }
    }
}

/* Far points (1e8 sizes away) and a body far from the origin: distances to 1e-15 relative. */
static void test_far(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(61);
    for (int i = 0; i < 60; ++i) {
        body b;
        lbody lb;
        rand_body(&g, i % 3, prox_v3(0, 0, 0), &b, &lb);
        prox_vec3 dir = test_unit(&g), q;
        if (i % 4 == 0) dir = prox_v3(lb.w.x, lb.w.y, lb.w.z);
        prox_vec3 x = prox_v3_scale(dir, 1e8 * lb.size);
        double s = b_boundary(&b, x, &q);
        /* far away the distance is |x| - h(x/|x|) + O(size^2/|x|) */
        double hx = prox_v3_dot(dir, b.c) + b_hc(&b, dir);
        assert_near(s, prox_v3_norm(x) - hx, 1e-7 * lb.size);
        assert_near(prox_v3_dist(x, q), s, 1e-15 * prox_v3_norm(x));
        assert_true(on_boundary(&lb, q, 1e-14L * lb.size));
    }
}

/* Scaling by a power of two scales every answer exactly; a rotation and a translation move them. */
static void test_invariance(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(71);
    for (int i = 0; i < 150; ++i) {
        int kind = i % 3;
        double f = ldexp(1.0, (int)test_range(&g, -200, 200));
        prox_vec3 at = prox_v3(test_range(&g, -5, 5), test_range(&g, -5, 5), test_range(&g, -5, 5));
        test_rng g2 = g;
        body b1, b2;
        lbody lb;
        rand_body(&g, kind, at, &b1, &lb);
        prox_vec3 x = rand_point(&g, &lb), q1, q2;
        /* the same body scaled: regenerate from the same stream, scale its card */
        if (kind == K_TRC) {
            prox_trc t = rand_trc(&g2, at);
            t.base = prox_v3_scale(t.base, f), t.axis = prox_v3_scale(t.axis, f), t.r1 *= f, t.r2 *= f;
            b2 = make_trc(&t);
        } else if (kind == K_REC) {
            prox_rec r = rand_rec(&g2, at);
            r.base = prox_v3_scale(r.base, f), r.axis = prox_v3_scale(r.axis, f);
            r.a1 = prox_v3_scale(r.a1, f), r.a2 = prox_v3_scale(r.a2, f);
            b2 = make_rec(&r);
        } else {
            prox_ell e = rand_ell(&g2, at);
            e.center = prox_v3_scale(e.center, f), e.axis = prox_v3_scale(e.axis, f), e.radius *= f;
            b2 = make_ell(&e);
        }
        double s1 = b_boundary(&b1, x, &q1), s2 = b_boundary(&b2, prox_v3_scale(x, f), &q2);
        assert_true(s2 == s1 * f);
        assert_true(q2.x == q1.x * f && q2.y == q1.y * f && q2.z == q1.z * f);
        /* moved: body and point translated by a large offset and rotated */
        test_rot R = test_random_rot(&g);
        prox_vec3 off = prox_v3_scale(test_unit(&g), 1e3);
        body b3;
        if (kind == K_TRC) {
            prox_trc t = {prox_v3(lb.o.x, lb.o.y, lb.o.z), prox_v3_scale(prox_v3(lb.w.x, lb.w.y, lb.w.z), lb.h), lb.r1, lb.r2};
            t.base = prox_v3_add(test_rot_apply(&R, t.base), off), t.axis = test_rot_apply(&R, t.axis);
            b3 = make_trc(&t);
        } else if (kind == K_REC) {
            prox_rec r = {prox_v3(lb.o.x, lb.o.y, lb.o.z), prox_v3_scale(prox_v3(lb.w.x, lb.w.y, lb.w.z), lb.h),
                          prox_v3_scale(prox_v3(lb.e1.x, lb.e1.y, lb.e1.z), lb.r1),
                          prox_v3_scale(prox_v3(lb.e2.x, lb.e2.y, lb.e2.z), lb.r2)};
            r.base = prox_v3_add(test_rot_apply(&R, r.base), off), r.axis = test_rot_apply(&R, r.axis);
            r.a1 = test_rot_apply(&R, r.a1), r.a2 = test_rot_apply(&R, r.a2);
            b3 = make_rec(&r);
        } else {
            prox_ell e = {prox_v3(lb.o.x, lb.o.y, lb.o.z), prox_v3_scale(prox_v3(lb.w.x, lb.w.y, lb.w.z), lb.h), lb.r1};
            e.center = prox_v3_add(test_rot_apply(&R, e.center), off), e.axis = test_rot_apply(&R, e.axis);
            b3 = make_ell(&e);
        }
        double s3 = b_boundary(&b3, prox_v3_add(test_rot_apply(&R, x), off), &q2);
        ld S = lb.size + lnorm(lsub(lv(x), lb.o)) + 1e3;
        assert_true(fabsl((ld)s3 - s1) <= 1e-13L * S);
    }
}

static void test_validators(void **state)
{
    (void)state;
    prox_trc t = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 1, 0.5};
    assert_int_equal(prox_trc_validate(&t), PROX_OK);
    t.r2 = 0;
    assert_int_equal(prox_trc_validate(&t), PROX_OK); /* a full cone */
    t.r1 = 0, t.r2 = 2;
    assert_int_equal(prox_trc_validate(&t), PROX_OK); /* apex at the base, r1 < r2 */
    t.r1 = 0, t.r2 = 0;
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_TRC);
    t.r1 = 1, t.r2 = 1;
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_TRC);
    t.r2 = -0.5;
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_TRC);
    t.r2 = NAN;
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_NONFINITE);
    t.r2 = 0.5, t.axis = prox_v3(0, 0, 0);
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_AXIS);
    t.axis = prox_v3(0, 0, 1e-120);
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_RANGE);
    t.axis = prox_v3(0, 0, 1), t.r2 = 1e-120;
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_RANGE);
    t.r2 = 0.5, t.base = prox_v3(2e100, 0, 0);
    assert_int_equal(prox_trc_validate(&t), PROX_EINVAL_RANGE);
    assert_int_equal(prox_trc_validate(NULL), PROX_EINVAL_ARG);

    prox_rec r = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), prox_v3(2, 0, 0), prox_v3(0, 1, 0)};
    assert_int_equal(prox_rec_validate(&r), PROX_OK);
    r.a2 = prox_v3(0, 3, 0); /* the minor longer than the major: accepted, the prepared body sorts them */
    assert_int_equal(prox_rec_validate(&r), PROX_OK);
    r.a2 = prox_v3(1e-8, 1, 0);
    assert_int_equal(prox_rec_validate(&r), PROX_EINVAL_REC_ORTHO);
    r.a2 = prox_v3(1e-11, 1, 0);
    assert_int_equal(prox_rec_validate(&r), PROX_OK);
    r.a2 = prox_v3(0, 1, 1e-8);
    assert_int_equal(prox_rec_validate(&r), PROX_EINVAL_REC_ORTHO);
    r.a2 = prox_v3(0, 0, 0);
    assert_int_equal(prox_rec_validate(&r), PROX_EINVAL_RADIUS);
    r.a2 = prox_v3(0, 1, 0), r.axis = prox_v3(0, 0, 0);
    assert_int_equal(prox_rec_validate(&r), PROX_EINVAL_AXIS);
    r.axis = prox_v3(0, 0, INFINITY);
    assert_int_equal(prox_rec_validate(&r), PROX_EINVAL_NONFINITE);
    r.axis = prox_v3(0, 0, 1), r.base.y = -1e101;
    assert_int_equal(prox_rec_validate(&r), PROX_EINVAL_RANGE);
    assert_int_equal(prox_rec_validate(NULL), PROX_EINVAL_ARG);

    prox_rec o;
    assert_int_equal(prox_rec_from_radius(prox_v3(1, 2, 3), prox_v3(0, 0, 5), prox_v3(2, 0, 0), 0.5, &o), PROX_OK);
    assert_near(o.a2.x, 0.0, 0.0);
    assert_near(fabs(o.a2.y), 0.5, 1e-16);
    assert_near(o.a2.z, 0.0, 0.0);
    assert_int_equal(prox_rec_from_radius(prox_v3(0, 0, 0), prox_v3(0, 0, 5), prox_v3(0, 0, 2), 0.5, &o), PROX_EINVAL_REC_ORTHO);
    assert_int_equal(prox_rec_from_radius(prox_v3(0, 0, 0), prox_v3(0, 0, 5), prox_v3(2, 0, 0), -0.5, &o), PROX_EINVAL_RADIUS);
    assert_int_equal(prox_rec_from_radius(prox_v3(0, 0, 0), prox_v3(0, 0, 5), prox_v3(2, 0, 1), 0.5, &o), PROX_EINVAL_REC_ORTHO);

    prox_ell e = {prox_v3(0, 0, 0), prox_v3(0, 0, 1), 2};
    assert_int_equal(prox_ell_validate(&e), PROX_OK); /* oblate */
    e.radius = 0;
    assert_int_equal(prox_ell_validate(&e), PROX_EINVAL_RADIUS);
    e.radius = 1, e.axis = prox_v3(0, 0, 0);
    assert_int_equal(prox_ell_validate(&e), PROX_EINVAL_AXIS);
    e.axis = prox_v3(NAN, 0, 0);
    assert_int_equal(prox_ell_validate(&e), PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_ell_validate(NULL), PROX_EINVAL_ARG);
    /* foci (0,0,-3), (0,0,3), major radius 5: semi-axis 5 along z, equatorial radius 4 */
    assert_int_equal(prox_ell_from_foci(prox_v3(0, 0, -3), prox_v3(0, 0, 3), 5, &e), PROX_OK);
    assert_near(e.axis.z, 5.0, 0.0);
    assert_near(e.radius, 4.0, 1e-15);
    assert_near(e.center.z, 0.0, 0.0);
    assert_int_equal(prox_ell_from_foci(prox_v3(0, 0, -3), prox_v3(0, 0, 3), 3, &e), PROX_EINVAL_ELL);
    assert_int_equal(prox_ell_from_foci(prox_v3(0, 0, -3), prox_v3(0, 0, 3), 0, &e), PROX_EINVAL_RADIUS);
    assert_int_equal(prox_ell_from_foci(prox_v3(1, 1, 1), prox_v3(1, 1, 1), 2, &e), PROX_OK); /* a sphere */
    assert_near(e.radius, 2.0, 0.0);
    assert_near(prox_v3_norm(e.axis), 2.0, 0.0);
    assert_int_equal(prox_ell_from_axis(prox_v3(0, 0, 0), prox_v3(0, 4, 0), 1, &e), PROX_OK);
    assert_near(e.axis.y, 4.0, 0.0);
    assert_near(e.radius, 1.0, 0.0);
    assert_int_equal(prox_ell_from_axis(prox_v3(0, 0, 0), prox_v3(0, 0, 0), 1, &e), PROX_EINVAL_AXIS);
    assert_int_equal(prox_ell_from_axis(prox_v3(0, 0, 0), prox_v3(0, 1, 0), -1, &e), PROX_EINVAL_RADIUS);
}

/* The point-ellipse solver alone (core/ellipse2.h): aspect ratios 1 .. 1e12 either way, points
 * inside near the major axis (where the nearest points leave the axis), on the axes, near the curve
 * and far away, against the long double meridian search; then ratios up to 1e180 and points 1e180
 * sizes away, where only finiteness and the sign can be checked cheaply. */
static void test_ellipse2(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(81);
    for (int i = 0; i < 400; ++i) {
        double e0 = 1.0, e1 = pow(10.0, test_range(&g, -12, 0));
        if (i % 2) e0 = e1, e1 = 1.0;
        double y0, y1, big = fmax(e0, e1);
        switch (i % 5) {
        case 0: y0 = test_range(&g, -1, 1) * e0, y1 = e1 * pow(10.0, -test_range(&g, 1, 15)); break;
        case 1: y0 = test_range(&g, -1, 1) * big * 3, y1 = test_range(&g, -1, 1) * big * 3; break;
        case 2: y0 = test_range(&g, -1, 1) * big * 1e8, y1 = test_range(&g, -1, 1) * big * 1e8; break;
        case 3: y0 = 0.0, y1 = test_range(&g, -2, 2) * e1; break;
        default: {
            double th = test_range(&g, 0, 2 * PROX_PI), f = 1.0 + test_range(&g, -1e-6, 1e-6);
            y0 = f * e0 * cos(th), y1 = f * e1 * sin(th);
        }
        }
        double x0, x1, s = prox_ellipse2_closest(e0, e1, y0, y1, &x0, &x1);
        lbody lb = {.kind = K_ELL, .h = e0, .r1 = e1};
        lpt p = {&lb, y0, 0, 0, fabs(y1), 0};
        ld bd = min1d(ell_meridian, &p, 0, 3.14159265358979323846264338327950288L, NS);
        ld S = big + hyp(y0, y1);
        ld q = (x0 / (ld)e0) * (x0 / (ld)e0) + (x1 / (ld)e1) * (x1 / (ld)e1);
        if (!(fabsl(fabsl(s) - bd) <= 1e-15L * S) || !(fabsl(hyp(x0 - (ld)y0, x1 - (ld)y1) - fabsl(s)) <= 1e-15L * S) ||
            !(fabsl(sqrtl(q) - 1) * fminl(e0, e1) <= 1e-15L * S) || (x0 != 0 && (x0 < 0) != (y0 < 0)) ||
            (x1 != 0 && y1 != 0 && (x1 < 0) != (y1 < 0))) {
            print_error("case %d: e %.17g %.17g y %.17g %.17g: s %.17g brute %.17Lg x %.17g %.17g\n", i, e0, e1, y0, y1, s, bd, x0, x1);
            fail();
        }
    }
    for (int i = 0; i < 200; ++i) {
        double e0 = 1.0, e1 = pow(10.0, -test_range(&g, 0, 180)), x0, x1;
        if (i % 2) e0 = e1, e1 = 1.0;
        double sc = pow(10.0, test_range(&g, -180, 180));
        double y0 = test_range(&g, -1, 1) * sc, y1 = test_range(&g, -1, 1) * sc;
        double s = prox_ellipse2_closest(e0, e1, y0, y1, &x0, &x1);
        assert_true(isfinite(s) && isfinite(x0) && isfinite(x1));
        assert_true((s < 0) == !!prox_ellipse2_inside(e0, e1, y0, y1) || fabs(s) <= 1e-15 * (e0 + e1 + sc));
        if (!(fabs(s) <= (hypot(y0, y1) + fmax(e0, e1)) * (1 + 4 * DBL_EPSILON))) { /* within the farthest point */
            print_error("extreme %d: e %.17g %.17g y %.17g %.17g: s %.17g x %.17g %.17g\n", i, e0, e1, y0, y1, s, x0, x1);
            fail();
        }
    }
}

/* boundary_n(): the same signed distance and point as boundary(), and n a unit outward normal at q
 * (the plane through q normal to n supports the body: hc(n) = n.(q - c)) with x = q + sd n; points
 * within 1e-16 .. 1e-9 sizes of the boundary, where x - q is rounding noise, and on rims and apexes. */
static void test_boundary_normal(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(91);
    for (int i = 0; i < 900; ++i) {
        int kind = i % 3;
        body b;
        lbody lb;
        rand_body(&g, kind, prox_v3(test_range(&g, -5, 5), test_range(&g, -5, 5), test_range(&g, -5, 5)), &b, &lb);
        prox_vec3 x;
        if (i % 2) {
            x = rand_point(&g, &lb);
        } else { /* near a boundary point, or a rim point (u = 0 or 1 on a cap facet) */
            int f = (int)(test_uniform(&g) * nfacets(&lb));
            double u = i % 4 == 0 && lb.kind != K_ELL ? (double)(i % 8 == 0) : test_uniform(&g);
            lv3 p = facet(&lb, f, u, test_uniform(&g));
            p = ladd(p, lscale(lv(test_unit(&g)), lb.size * pow(10.0, -test_range(&g, 9, 16))));
            x = prox_v3(p.x, p.y, p.z);
        }
        prox_vec3 q, q2, n;
        double s = b_boundary_n(&b, x, &q, &n), s2 = b_boundary(&b, x, &q2);
        ld S = lb.size + lnorm(lsub(lv(x), lb.o)), tol = 4e-15L * S;
        assert_true(s == s2 && q.x == q2.x && q.y == q2.y && q.z == q2.z);
        ld hn = b_hc(&b, n), nq = ldot(lv(n), lsub(lv(q), lv(b.c)));
        int ok = fabsl(lnorm(lv(n)) - 1) <= 1e-15L && fabsl(hn - nq) <= tol &&
                 lnorm(lsub(lsub(lv(x), lv(q)), lscale(lv(n), s))) <= tol;
        if (!ok) {
            print_error("kind %d case %d: s %.17g |n| %.17Lg hc(n) - n.q %.3Lg |x - q - s n| %.3Lg S %.3Lg\n", kind, i, s,
                        lnorm(lv(n)), hn - nq, lnorm(lsub(lsub(lv(x), lv(q)), lscale(lv(n), s))), S);
            fail();
        }
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_validators),     cmocka_unit_test(test_special_points),
        cmocka_unit_test(test_support_sets),   cmocka_unit_test(test_trc_boundary),
        cmocka_unit_test(test_rec_boundary),   cmocka_unit_test(test_ell_boundary),
        cmocka_unit_test(test_contains), cmocka_unit_test(test_contains_shell),       cmocka_unit_test(test_support),
        cmocka_unit_test(test_near_degenerate), cmocka_unit_test(test_extreme_aspect),
        cmocka_unit_test(test_far),            cmocka_unit_test(test_invariance),
        cmocka_unit_test(test_ellipse2),
        cmocka_unit_test(test_boundary_normal),
        cmocka_unit_test(test_axis_diagonal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
