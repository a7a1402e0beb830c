/* Generic queries (query.h) on seeded random pairs of every family (BOX/RPP, RCC, SPH), against an
 * independent brute force written here in long double:
 *  - distance: alternating projections onto the two solids (von Neumann) give an upper bound U and the
 *    support-function gap along their direction a lower bound L; the answer must lie in [L, U] and equal
 *    U when the bracket is tight;
 *  - penetration depth: min over unit D of h_A(D) + h_B(-D), dense directions plus pattern search;
 *  - reposition: after the move the distance equals the margin; relation and test agree with these. */
#include "test_util.h"
#include "prox/query.h"
#include "prox/support.h"

typedef long double ld;
typedef struct lv { ld x, y, z; } lv;
static lv L3(prox_vec3 v) { lv r = {v.x, v.y, v.z}; return r; }
static lv lsub(lv a, lv b) { lv r = {a.x - b.x, a.y - b.y, a.z - b.z}; return r; }
static lv ladd(lv a, lv b) { lv r = {a.x + b.x, a.y + b.y, a.z + b.z}; return r; }
static lv lsc(lv a, ld s) { lv r = {a.x * s, a.y * s, a.z * s}; return r; }
static ld ldot(lv a, lv b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static ld lnorm(lv a) { return sqrtl(ldot(a, a)); }

/* Projection of x onto a solid (brute-force side, long double). */
static lv proj(const prox_shape *s, lv x)
{
    if (s->kind == PROX_SHAPE_SPH) {
        lv d = lsub(x, L3(s->u.sph.center));
        ld n = lnorm(d);
        return n <= s->u.sph.radius ? x : ladd(L3(s->u.sph.center), lsc(d, s->u.sph.radius / n));
    }
    if (s->kind == PROX_SHAPE_RCC) {
        lv w = L3(s->u.rcc.axis), b = L3(s->u.rcc.base);
        ld h = lnorm(w);
        w = lsc(w, 1 / h);
        lv d = lsub(x, b);
        ld t = ldot(d, w);
        lv rad = lsub(d, lsc(w, t));
        ld rho = lnorm(rad);
        if (t < 0) t = 0;
        if (t > h) t = h;
        if (rho > s->u.rcc.radius) rad = lsc(rad, s->u.rcc.radius / rho);
        return ladd(ladd(b, lsc(w, t)), rad);
    }
    prox_box bx = s->kind == PROX_SHAPE_RPP ? prox_rpp_to_box(&s->u.rpp) : s->u.box;
    lv p = L3(bx.corner), d = lsub(x, p);
    for (int k = 0; k < 3; ++k) {
        lv e = L3(bx.edge[k]);
        ld l2 = ldot(e, e), t = ldot(d, e) / l2;
        if (t < 0) t = 0;
        if (t > 1) t = 1;
        p = ladd(p, lsc(e, t));
    }
    return p;
}

/* Support function (brute-force side). */
static ld supp(const prox_shape *s, lv d)
{
    if (s->kind == PROX_SHAPE_SPH) return ldot(d, L3(s->u.sph.center)) + s->u.sph.radius * lnorm(d);
    if (s->kind == PROX_SHAPE_RCC) {
        lv w = L3(s->u.rcc.axis), b = L3(s->u.rcc.base);
        ld h = lnorm(w), dw = ldot(d, w) / h;
        lv perp = lsub(d, lsc(w, dw / h));
        ld base = ldot(d, b) + (dw > 0 ? dw * h : 0);
        return base + s->u.rcc.radius * lnorm(perp);
    }
    prox_box bx = s->kind == PROX_SHAPE_RPP ? prox_rpp_to_box(&s->u.rpp) : s->u.box;
    ld v = ldot(d, L3(bx.corner));
    for (int k = 0; k < 3; ++k) {
        ld c = ldot(d, L3(bx.edge[k]));
        if (c > 0) v += c;
    }
    return v;
}

static ld dist_to(const prox_shape *s, lv x) { return lnorm(lsub(x, proj(s, x))); }

/* Alternating projections: upper bound U, points p (A), q (B). */
static ld brute_distance(const prox_shape *a, const prox_shape *b, lv *p, lv *q)
{
    lv x = L3(prox_shape_center(b));
    for (int it = 0; it < 4000; ++it) {
        *p = proj(a, x);
        lv nq = proj(b, *p);
        ld change = lnorm(lsub(nq, x));
        x = nq;
        if (it > 10 && change < 1e-24L) break;
    }
    *q = x;
    return lnorm(lsub(*p, *q));
}

/* Gap -h_B(-n) - h_A(n) along n (lower bound on the distance). */
static ld gap(const prox_shape *a, const prox_shape *b, lv n)
{
    ld nn = lnorm(n);
    if (!(nn > 0)) return -INFINITY;
    n = lsc(n, 1 / nn);
    return -supp(b, lsc(n, -1)) - supp(a, n);
}

static ld phi(const prox_shape *a, const prox_shape *b, lv d) { return supp(a, d) + supp(b, lsc(d, -1)); }

/* Kink axes of a support function: h is smooth off the great circles D.k = 0 (box edges, cylinder
 * axis) and off the cylinder's poles. */
static int kinks(const prox_shape *s, lv k[3], int *pole)
{
    *pole = 0;
    if (s->kind == PROX_SHAPE_SPH) return 0;
    if (s->kind == PROX_SHAPE_RCC) {
        k[0] = lsc(L3(s->u.rcc.axis), 1 / lnorm(L3(s->u.rcc.axis)));
        *pole = 1;
        return 1;
    }
    prox_box bx = s->kind == PROX_SHAPE_RPP ? prox_rpp_to_box(&s->u.rpp) : s->u.box;
    for (int i = 0; i < 3; ++i) k[i] = lsc(L3(bx.edge[i]), 1 / lnorm(L3(bx.edge[i])));
    return 3;
}

static lv lcross(lv a, lv b) { lv r = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; return r; }
static lv lunit(lv a) { return lsc(a, 1 / lnorm(a)); }

/* Pattern search from d (smooth regions). */
static ld pattern(const prox_shape *a, const prox_shape *b, lv d, ld f)
{
    ld step = 0.02L;
    for (int iter = 0; iter < 2000 && step > 1e-14L; ++iter) { /* capped: ridges are searched in 1-D */
        int improved = 0;
        lv t1 = lunit(fabsl(d.x) < 0.6L ? (lv){0, d.z, -d.y} : (lv){d.z, 0, -d.x}), t2 = lcross(d, t1);
        for (int m = 0; m < 16; ++m) {
            ld ang = m * 0.39269908169872414L;
            lv c = lunit(ladd(d, ladd(lsc(t1, step * cosl(ang)), lsc(t2, step * sinl(ang)))));
            ld fc = phi(a, b, c);
            if (fc < f) f = fc, d = c, improved = 1;
        }
        if (!improved) step *= 0.5L;
    }
    return f;
}

/* Minimum of phi on the great circle orthogonal to k: dense samples and golden sections. */
static ld on_circle(const prox_shape *a, const prox_shape *b, lv k)
{
    lv p = lunit(fabsl(k.x) < 0.6L ? (lv){0, k.z, -k.y} : (lv){k.z, 0, -k.x}), q = lcross(k, p);
    enum { N = 720 };
    ld best = INFINITY;
    for (int i = 0; i < N; ++i) {
        ld th = 2 * 3.14159265358979323846L * i / N;
        ld f = phi(a, b, ladd(lsc(p, cosl(th)), lsc(q, sinl(th))));
        ld fl = phi(a, b, ladd(lsc(p, cosl(th - 0.0087266L)), lsc(q, sinl(th - 0.0087266L))));
        ld fr = phi(a, b, ladd(lsc(p, cosl(th + 0.0087266L)), lsc(q, sinl(th + 0.0087266L))));
        if (f > fl || f > fr) { if (f < best) best = f; continue; }
        ld lo = th - 0.0087266L, hi = th + 0.0087266L, g = 0.6180339887498949L;
        for (int it = 0; it < 80; ++it) {
            ld x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            ld f1 = phi(a, b, ladd(lsc(p, cosl(x1)), lsc(q, sinl(x1))));
            ld f2 = phi(a, b, ladd(lsc(p, cosl(x2)), lsc(q, sinl(x2))));
            if (f1 < f2) hi = x2; else lo = x1;
            if (f1 < best) best = f1;
            if (f2 < best) best = f2;
        }
    }
    return best;
}

/* Brute-force depth: min over unit D of h_A(D) + h_B(-D): Fibonacci directions refined by pattern
 * search (smooth parts), every kink great circle searched in 1-D, every intersection of kink circles
 * and every cylinder pole evaluated. */
static ld brute_depth(const prox_shape *a, const prox_shape *b)
{
    enum { N = 2000 };
    ld best[4] = {INFINITY, INFINITY, INFINITY, INFINITY};
    lv bd[4];
    for (int i = 0; i < N; ++i) {
        ld z = 1 - (2.0L * i + 1) / N, r = sqrtl(1 - z * z), th = 2.399963229728653L * i;
        lv d = {r * cosl(th), r * sinl(th), z};
        ld f = phi(a, b, d);
        for (int k = 0; k < 4; ++k)
            if (f < best[k]) {
                for (int m = 3; m > k; --m) best[m] = best[m - 1], bd[m] = bd[m - 1];
                best[k] = f, bd[k] = d;
                break;
            }
    }
    ld res = INFINITY;
    for (int k = 0; k < 4; ++k) res = fminl(res, pattern(a, b, bd[k], best[k]));
    lv K[6];
    int pa, pb, na = kinks(a, K, &pa), nb = kinks(b, K + na, &pb), n = na + nb;
    for (int i = 0; i < n; ++i) {
        res = fminl(res, on_circle(a, b, K[i]));
        for (int j = i + 1; j < n; ++j) {
            lv c = lcross(K[i], K[j]);
            if (lnorm(c) < 1e-9L) continue;
            c = lunit(c);
            res = fminl(res, fminl(phi(a, b, c), phi(a, b, lsc(c, -1))));
        }
    }
    if (pa) res = fminl(res, fminl(phi(a, b, K[0]), phi(a, b, lsc(K[0], -1))));
    if (pb) res = fminl(res, fminl(phi(a, b, K[na]), phi(a, b, lsc(K[na], -1))));
    return res;
}

/* Random shapes of each kind (kind 0 box, 1 rcc, 2 sph, 3 rpp) around the origin. */
static prox_shape rand_shape(test_rng *g, int kind, double spread)
{
    prox_vec3 c = prox_v3(test_range(g, -spread, spread), test_range(g, -spread, spread), test_range(g, -spread, spread));
    if (kind == 0) {
        test_rot R = test_random_rot(g);
        prox_box b;
        double len[3];
        for (int k = 0; k < 3; ++k) len[k] = test_range(g, 0.1, 3.0);
        b.edge[0] = prox_v3_scale(test_rot_apply(&R, prox_v3(1, 0, 0)), len[0]);
        b.edge[1] = prox_v3_scale(test_rot_apply(&R, prox_v3(0, 1, 0)), len[1]);
        b.edge[2] = prox_v3_scale(test_rot_apply(&R, prox_v3(0, 0, 1)), len[2]);
        b.corner = prox_v3_sub(c, prox_v3_scale(prox_v3_add(prox_v3_add(b.edge[0], b.edge[1]), b.edge[2]), 0.5));
        return prox_shape_from_box(b);
    }
    if (kind == 1) {
        prox_rcc r;
        r.axis = prox_v3_scale(test_unit(g), test_range(g, 0.1, 3.0));
        r.base = prox_v3_mad(c, -0.5, r.axis);
        r.radius = test_range(g, 0.05, 1.5);
        return prox_shape_from_rcc(r);
    }
    if (kind == 2) {
        prox_sph s = {c, test_range(g, 0.05, 1.5)};
        return prox_shape_from_sph(s);
    }
    prox_rpp p;
    double w[3];
    for (int k = 0; k < 3; ++k) w[k] = test_range(g, 0.1, 3.0);
    p.xmin = c.x - w[0] / 2, p.xmax = c.x + w[0] / 2;
    p.ymin = c.y - w[1] / 2, p.ymax = c.y + w[1] / 2;
    p.zmin = c.z - w[2] / 2, p.zmax = c.z + w[2] / 2;
    return prox_shape_from_rpp(p);
}

/* One random family: kinds ka, kb; n pairs. */
static void run_family(int ka, int kb, int n, uint64_t seed)
{
    test_rng g = test_rng_seed(seed);
    int tight = 0, disjoint = 0, overl = 0;
    double worst = 0, worst_depth = 0;
    for (int i = 0; i < n; ++i) {
        prox_shape a = rand_shape(&g, ka, 2.5), b = rand_shape(&g, kb, 2.5);
        double S = prox_shape_pair_scale(&a, &b), tol = 1e-12 * S;
        prox_distance_result d = prox_shape_distance(&a, &b);
        assert_int_equal(d.status, PROX_OK);
        lv p, q;
        ld U = brute_distance(&a, &b, &p, &q);
        prox_test_result t = prox_shape_test(&a, &b);
        assert_int_equal(t.status, PROX_OK);
        assert_int_equal(t.intersect, d.intersect);
        /* witnesses lie on their solids */
        assert_true(dist_to(&a, L3(d.p1)) <= 4 * tol);
        assert_true(dist_to(&b, L3(d.p2)) <= 4 * tol);
        if (d.intersect) {
            ++overl;
            /* the common point lies in both solids (checked above with the brute projections): proof */
            assert_true(dist_to(&b, L3(d.p1)) <= 4 * tol);
            /* depth against the brute force */
            prox_signed_result s = prox_shape_signed_distance(&a, &b);
            assert_int_equal(s.status, PROX_OK);
            ld depth = brute_depth(&a, &b);
            assert_near(-s.sd, (double)depth, 1e-9 * S);
            if (fabs(s.sd + (double)depth) > worst_depth) worst_depth = fabs(s.sd + (double)depth);
            /* reposition: after the move the distance is the margin */
            double margin = 0.1 * S;
            prox_reposition_result rp = prox_shape_reposition(&a, &b, margin);
            assert_int_equal(rp.status, PROX_OK);
            assert_true(rp.moved);
            prox_shape b2 = test_translate(&b, rp.translation);
            prox_distance_result d2 = prox_shape_distance(&a, &b2);
            assert_false(d2.intersect);
            assert_near(d2.distance, margin, 1e-9 * S);
            prox_relation_result rel = prox_shape_relation(&a, &b, -1);
            assert_int_equal(rel.status, PROX_OK);
            assert_true(rel.relation != PROX_REL_DISJOINT);
            continue;
        }
        ++disjoint;
        assert_true(d.distance > 0);
        assert_near(prox_v3_dist(d.p1, d.p2), d.distance, 4 * tol);
        ld Lb = gap(&a, &b, lsub(q, p));
        ld Ls = gap(&a, &b, lsub(L3(d.p2), L3(d.p1)));
        if (Ls > Lb) Lb = Ls;
        assert_true(d.distance <= U + tol);   /* never above an attained distance */
        assert_true(d.distance >= Lb - tol);  /* never below a proven lower bound */
        if (U - Lb <= tol) {
            ++tight;
            assert_near(d.distance, (double)U, tol);
        }
        if (fabs(d.distance - (double)Ls) > worst) worst = fabs(d.distance - (double)Ls);
        prox_signed_result s = prox_shape_signed_distance(&a, &b);
        assert_near(s.sd, d.distance, tol);
        prox_relation_result rel = prox_shape_relation(&a, &b, -1);
        assert_int_equal(rel.relation, d.distance > rel.tol ? PROX_REL_DISJOINT : PROX_REL_TOUCHING);
    }
    print_message("family %d-%d: %d disjoint (%d with a tight brute bracket), %d overlapping; "
                  "max |d - certificate| %.3g, max depth error %.3g\n",
                  ka, kb, disjoint, tight, overl, worst, worst_depth);
    assert_true(disjoint > n / 5 && overl > n / 10);
    assert_true(tight > disjoint / 2); /* the strict comparison ran on most disjoint pairs */
}

static void test_random_box_box(void **st) { (void)st; run_family(0, 0, 1500, 11); }
static void test_random_box_rpp(void **st) { (void)st; run_family(3, 0, 500, 12); }
static void test_random_box_sph(void **st) { (void)st; run_family(0, 2, 1500, 13); }
static void test_random_sph_box(void **st) { (void)st; run_family(2, 3, 500, 14); }
static void test_random_sph_sph(void **st) { (void)st; run_family(2, 2, 1500, 15); }
static void test_random_rcc_sph(void **st) { (void)st; run_family(1, 2, 1500, 16); }
static void test_random_sph_rcc(void **st) { (void)st; run_family(2, 1, 500, 17); }
static void test_random_box_rcc(void **st) { (void)st; run_family(0, 1, 1500, 18); }
static void test_random_rcc_box(void **st) { (void)st; run_family(1, 3, 500, 19); }

/* Invalid shapes give their named status from every generic query. */
static void test_invalid_shapes(void **st)
{
    (void)st;
    prox_sph good = {{0, 0, 0}, 1}, bad = {{0, 0, 0}, -1};
    prox_shape a = prox_shape_from_sph(good), b = prox_shape_from_sph(bad);
    assert_int_equal(prox_shape_distance(&a, &b).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_shape_signed_distance(&b, &a).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_shape_test(&a, &b).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_shape_contains(&a, &b).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_shape_relation(&a, &b, -1).status, PROX_EINVAL_RADIUS);
    assert_int_equal(prox_shape_reposition(&a, &b, 0.1).status, PROX_EINVAL_RADIUS);
    prox_shape k = a;
    k.kind = (prox_shape_kind)42;
    assert_int_equal(prox_shape_distance(&a, &k).status, PROX_EINVAL_SHAPE_KIND);
    prox_rpp rp = {0, 1, 0, 1, 1, 0};
    prox_shape r = prox_shape_from_rpp(rp);
    assert_int_equal(prox_shape_distance(&r, &a).status, PROX_EINVAL_RPP_BOUNDS);
    prox_box bx = {{0, 0, 0}, {{1, 0, 0}, {1, 1, 0}, {0, 0, 1}}};
    prox_shape x = prox_shape_from_box(bx);
    assert_int_equal(prox_shape_test(&x, &a).status, PROX_EINVAL_BOX_ORTHO);
    prox_rcc nanc = {{0, 0, NAN}, {0, 0, 1}, 1};
    prox_shape c = prox_shape_from_rcc(nanc);
    assert_int_equal(prox_shape_signed_distance(&a, &c).status, PROX_EINVAL_NONFINITE);
    assert_int_equal(prox_shape_reposition(&a, &a, -1.0).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_shape_distance(NULL, &a).status, PROX_EINVAL_ARG);
}

/* Relation: the four outcomes on hand-made pairs, and which one is inner. */
static void test_relation_cases(void **st)
{
    (void)st;
    prox_rpp big = {-2, 2, -2, 2, -2, 2}, unit = {0, 1, 0, 1, 0, 1}, touch = {1, 2, 0, 1, 0, 1}, far = {3, 4, 0, 1, 0, 1};
    prox_shape B = prox_shape_from_rpp(big), U = prox_shape_from_rpp(unit), T = prox_shape_from_rpp(touch),
               F = prox_shape_from_rpp(far);
    prox_sph s = {{1, 0.5, 0.5}, 0.3};
    prox_shape S = prox_shape_from_sph(s);
    assert_int_equal(prox_shape_relation(&U, &B, -1).relation, PROX_REL_A_IN_B);
    assert_int_equal(prox_shape_relation(&B, &U, -1).relation, PROX_REL_B_IN_A);
    assert_int_equal(prox_shape_relation(&U, &T, -1).relation, PROX_REL_TOUCHING);
    assert_int_equal(prox_shape_relation(&U, &F, -1).relation, PROX_REL_DISJOINT);
    assert_int_equal(prox_shape_relation(&U, &S, -1).relation, PROX_REL_CROSSING);
    prox_relation_result r = prox_shape_relation(&S, &B, -1);
    assert_int_equal(r.relation, PROX_REL_A_IN_B);
    assert_near(r.clearance, 0.7, 1e-15);
    /* already clear by more than the margin: no move */
    prox_reposition_result rp = prox_shape_reposition(&U, &F, 0.5);
    assert_false(rp.moved);
    assert_near(rp.signed_distance, 2.0, 1e-15);
    /* touching, margin 0.25: moved 0.25 along +x */
    rp = prox_shape_reposition(&U, &T, 0.25);
    assert_true(rp.moved);
    assert_near(rp.translation.x, 0.25, 1e-15);
    assert_near(rp.translation.y, 0.0, 1e-15);
}

/* Null pointers: every public entry point of query.h answers PROX_EINVAL_ARG (never a crash). */
static void test_null_args(void **st)
{
    (void)st;
    prox_sph sp = {{0, 0, 0}, 1};
    prox_rcc rc = {{0, 0, 0}, {0, 0, 1}, 1};
    prox_rpp rp = {0, 1, 0, 1, 0, 1};
    prox_box bx = prox_rpp_to_box(&rp);
    prox_shape a = prox_shape_from_sph(sp), out = a;
    assert_int_equal(prox_shape_test(&a, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_shape_signed_distance(NULL, &a).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_shape_contains(NULL, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_shape_relation(&a, NULL, -1).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_shape_reposition(NULL, &a, 0.1).status, PROX_EINVAL_ARG);
    assert_true(prox_shape_pair_scale(NULL, &a) == 0.0);
    assert_int_equal(prox_shape_translated(NULL, prox_v3(1, 2, 3), &out), PROX_EINVAL_ARG);
    assert_int_equal(prox_shape_translated(&a, prox_v3(1, 2, 3), NULL), PROX_EINVAL_ARG);
    assert_int_equal(prox_shape_translated(&a, prox_v3(NAN, 0, 0), &out), PROX_EINVAL_NONFINITE);
    assert_true(out.u.sph.center.x == 0.0); /* untouched on error */
    assert_int_equal(prox_shape_translated(&a, prox_v3(1, 2, 3), &out), PROX_OK);
    assert_near(out.u.sph.center.z, 3.0, 0.0);
    prox_shape r = prox_shape_from_rpp(rp);
    assert_int_equal(prox_shape_translated(&r, prox_v3(-1, 0, 0), &out), PROX_OK);
    assert_true(out.kind == PROX_SHAPE_RPP && out.u.rpp.xmin == -1.0 && out.u.rpp.xmax == 0.0);
    /* the specialised solvers */
    assert_int_equal(prox_box_box_test(NULL, &bx).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_box_distance(&bx, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_box_signed_distance(NULL, &bx).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_sph_distance(NULL, &sp).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_sph_signed_distance(&bx, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_sph_sph_distance(NULL, &sp).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_sph_sph_signed_distance(&sp, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_rcc_sph_distance(NULL, &sp).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_rcc_sph_signed_distance(&rc, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_rcc_test(NULL, &rc).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_rcc_distance(&bx, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_rcc_signed_distance(NULL, &rc).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_in_box(NULL, &bx).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_in_rcc(&bx, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_box_in_sph(NULL, &sp).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_rcc_in_box(&rc, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_rcc_in_rcc(NULL, &rc).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_rcc_in_sph(&rc, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_sph_in_box(NULL, &bx).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_sph_in_rcc(&sp, NULL).status, PROX_EINVAL_ARG);
    assert_int_equal(prox_sph_in_sph(NULL, &sp).status, PROX_EINVAL_ARG);
}

/* Relation convention at internal tangency (docs/algorithms/boxes_spheres.md): an inner solid touching
 * the outer boundary from inside is nested (contact = 1, clearance 0), never "touching"; pushed out
 * by less than tol it stays nested, by more it is crossing; the same contact from outside is touching. */
static void expect_rel(const prox_shape *a, const prox_shape *b, prox_relation rel, int contact, double clearance)
{
    prox_relation_result r = prox_shape_relation(a, b, -1);
    assert_int_equal(r.status, PROX_OK);
    assert_int_equal(r.relation, rel);
    assert_int_equal(r.contact, contact);
    if (rel == PROX_REL_A_IN_B || rel == PROX_REL_B_IN_A) assert_near(r.clearance, clearance, 1e-14);
}

static void test_relation_internal_tangency(void **st)
{
    (void)st;
    prox_rpp big = {-2, 2, -2, 2, -2, 2};
    prox_shape B = prox_shape_from_rpp(big);
    double tol = 1e-12 * 4;
    /* sphere against the face x = 2: inside flush, nudged out by tol/4 and 1e-6, outside tangent */
    double xs[4] = {1.5, 1.5 + tol / 4, 1.5 + 1e-6, 2.5};
    prox_relation want[4] = {PROX_REL_A_IN_B, PROX_REL_A_IN_B, PROX_REL_CROSSING, PROX_REL_TOUCHING};
    for (int i = 0; i < 4; ++i) {
        prox_sph s = {{xs[i], 0.3, -0.2}, 0.5};
        prox_shape S = prox_shape_from_sph(s);
        expect_rel(&S, &B, want[i], 1, 2 - xs[i] - 0.5);
        prox_relation wm = want[i] == PROX_REL_A_IN_B ? PROX_REL_B_IN_A : want[i];
        expect_rel(&B, &S, wm, 1, 2 - xs[i] - 0.5);
    }
    prox_sph deep = {{0, 0, 0}, 0.5};
    prox_shape D = prox_shape_from_sph(deep);
    expect_rel(&D, &B, PROX_REL_A_IN_B, 0, 1.5);
    /* identical solids: A in B with contact everywhere */
    expect_rel(&B, &B, PROX_REL_A_IN_B, 1, 0.0);
    /* box flush in a corner of the big box (three shared face planes) */
    prox_rpp corner = {1, 2, 1, 2, 1, 2};
    prox_shape C = prox_shape_from_rpp(corner);
    expect_rel(&C, &B, PROX_REL_A_IN_B, 1, 0.0);
    /* square inscribed in a cylinder: vertical edges on the lateral surface, ends flush with the caps */
    prox_rcc cyl = {{0, 0, 0}, {0, 0, 3}, 1};
    prox_shape Y = prox_shape_from_rcc(cyl);
    double h = sqrt(0.5);
    prox_rpp sq = {-h, h, -h, h, 0, 3};
    prox_shape Q = prox_shape_from_rpp(sq);
    expect_rel(&Q, &Y, PROX_REL_A_IN_B, 1, 0.0);
    /* cylinder with both rims on a sphere: (h/2)^2 + r^2 = R^2 */
    prox_rcc rod = {{0, 0, -0.6}, {0, 0, 1.2}, 0.8};
    prox_sph ball = {{0, 0, 0}, 1.0};
    prox_shape RO = prox_shape_from_rcc(rod), BA = prox_shape_from_sph(ball);
    expect_rel(&RO, &BA, PROX_REL_A_IN_B, 1, 0.0);
    expect_rel(&BA, &RO, PROX_REL_B_IN_A, 1, 0.0);
    /* sphere on the inside of a cylinder's end face, and on its outside */
    prox_sph cap_in = {{0.2, 0.1, 2.5}, 0.5}, cap_out = {{0.2, 0.1, 3.5}, 0.5};
    prox_shape CI = prox_shape_from_sph(cap_in), CO = prox_shape_from_sph(cap_out);
    expect_rel(&CI, &Y, PROX_REL_A_IN_B, 1, 0.0);
    expect_rel(&CO, &Y, PROX_REL_TOUCHING, 1, 0.0);
    /* far apart: disjoint, no contact */
    prox_sph far = {{10, 0, 0}, 1};
    prox_shape F = prox_shape_from_sph(far);
    expect_rel(&F, &B, PROX_REL_DISJOINT, 0, 0.0);
}

/* Every ordered pair of kinds with extreme sizes (edges, radii, heights log-uniform over 1e-3 .. 1e3):
 * a disjoint pair is moved along its proximal direction to a constructed gap (0 or 1e-12 .. 1e-2 x
 * scale); the distance must equal the gap (1e-12 of the scale, plus the rounding of the move) and
 * the verdict must say disjoint beyond 1e-9 x scale; for overlapping pairs, containment and the
 * relation must agree. Hard cases it covers: a needle beside a long plate at a 2.4e-11 x scale gap
 * (the segment-cylinder clip cancels there), and BOX-RCC's touching band, which must stay within
 * 1e-12 x scale. */
static void test_extreme_near_touching(void **st)
{
    (void)st;
    test_rng g = test_rng_seed(99991);
    for (int ka = 0; ka < 3; ++ka)
        for (int kb = 0; kb < 3; ++kb) {
            int moved = 0, bad = 0;
            for (int i = 0; i < 4000; ++i) {
                prox_shape A, B;
                test_extreme_pair(&g, ka, kb, &A, &B);
                prox_distance_result d = prox_shape_distance(&A, &B);
                assert_int_equal(d.status, PROX_OK);
                double S = prox_shape_pair_scale(&A, &B);
                if (!(d.distance > 0.0)) {
                    prox_contain_result ab = prox_shape_contains(&A, &B), ba = prox_shape_contains(&B, &A);
                    prox_relation_result rel = prox_shape_relation(&A, &B, -1.0);
                    int nested = rel.relation == PROX_REL_A_IN_B || rel.relation == PROX_REL_B_IN_A;
                    if ((ab.inside || ba.inside) != nested) ++bad;
                    continue;
                }
                prox_vec3 n = prox_v3_scale(prox_v3_sub(d.p2, d.p1), 1.0 / d.distance);
                double gap = test_uniform(&g) < 0.2 ? 0.0 : pow(10.0, test_range(&g, -12, -2)) * S;
                prox_shape B2;
                assert_int_equal(prox_shape_translated(&B, prox_v3_scale(n, gap - d.distance), &B2), PROX_OK);
                prox_distance_result e = prox_shape_distance(&A, &B2);
                prox_test_result t = prox_shape_test(&A, &B2);
                double S2 = prox_shape_pair_scale(&A, &B2);
                ++moved;
                if (fabs(e.distance - gap) > 2e-12 * S2 + 1e-12 * S) {
                    if (bad++ < 3) print_error("kinds %d-%d pair %d: gap %.3g x scale, distance %.17g\n", ka, kb, i, gap / S2, e.distance);
                }
                if (gap > 1e-9 * S2 && t.intersect) ++bad;
            }
            print_message("extreme kinds %d-%d: %d moved, %d bad\n", ka, kb, moved, bad);
            assert_int_equal(bad, 0);
        }
}

/* A box (or RPP) and a cylinder overlapping, moved apart by prox_shape_reposition: the translation
 * must leave them exactly `margin` apart.  The depth is the global minimum of h_A(D) + h_B(-D) over
 * unit D, a multi-start search for these kinds: a ridge search that samples too coarsely stops in a
 * shallower valley (depth up to 2e-3 x scale too large, ~6 in 10^4 such pairs with 16 samples per
 * ridge; docs/algorithms/sat.md). The first pair below is such a case, its true depth bounded by a
 * dense scan of directions (0.6215591, against 0.6335954 from the shallower valley); the loop's pair
 * 3059 misses by 3.1e-5 x scale with that search. Reposition's measured correction also covers a
 * depth found too large. */
static void test_reposition_box_cylinder(void **st)
{
    (void)st;
    const prox_rcc c = {prox_v3(0.063308197487468715, 0.065387634997008559, 0.14298464200863908),
                        prox_v3(-0.12661639497493743, -0.13077526999401712, -0.28596928401727817),
                        0.7012712920929266};
    const prox_box b = {prox_v3(-0.70342343543044039, -1.6466105392061141, 0.67620448311453374),
                        {prox_v3(0.74538824020520078, 3.4301494639128238, -1.2346389484990135),
                         prox_v3(0.8067136990550462, -0.11088488658219058, 0.1789698684710741),
                         prox_v3(0.11685024541193813, -0.27667405452327487, -0.69812681841466873)}};
    prox_shape A = prox_shape_from_rcc(c), B = prox_shape_from_box(b);
    prox_signed_result sd = prox_shape_signed_distance(&A, &B);
    assert_int_equal(sd.status, PROX_OK);
    assert_true(-sd.sd <= 0.6215592);
    test_rng g = test_rng_seed(4711);
    int bad = 0, moved = 0;
    for (int i = 0; i < 6000; ++i) {
        int box_first = i & 1;
        double lo = -1.0, hi = 1.0; /* sizes 0.1 .. 10 */
        prox_vec3 ax = prox_v3_scale(test_unit(&g), pow(10.0, test_range(&g, lo, hi)));
        prox_rcc cy = {prox_v3_scale(ax, -0.5), ax, pow(10.0, test_range(&g, lo, hi))};
        test_rot R = test_random_rot(&g);
        prox_box bx;
        prox_vec3 half = prox_v3(0, 0, 0);
        for (int k = 0; k < 3; ++k) {
            bx.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)),
                                       pow(10.0, test_range(&g, lo, hi)));
            half = prox_v3_mad(half, 0.5, bx.edge[k]);
        }
        prox_shape S1 = prox_shape_from_rcc(cy);
        prox_vec3 at = prox_v3_scale(test_unit(&g), test_uniform(&g) * prox_shape_size(&S1));
        bx.corner = prox_v3_sub(at, half);
        prox_shape X = prox_shape_from_box(bx);
        const prox_shape *P = box_first ? &X : &S1, *Q = box_first ? &S1 : &X;
        double S = prox_shape_pair_scale(P, Q);
        double margin = test_uniform(&g) < 0.3 ? 0.0 : S * pow(10.0, test_range(&g, -9, -1));
        prox_reposition_result rp = prox_shape_reposition(P, Q, margin);
        assert_int_equal(rp.status, PROX_OK);
        if (!rp.moved || rp.signed_distance > 0.0) continue;
        ++moved;
        prox_shape Q2;
        assert_int_equal(prox_shape_translated(Q, rp.translation, &Q2), PROX_OK);
        prox_distance_result d = prox_shape_distance(P, &Q2);
        double S2 = prox_shape_pair_scale(P, &Q2);
        if (!(fabs(d.distance - margin) <= 1e-12 * S2) && bad++ < 5)
            print_error("pair %d (%s first): after the move %.17g, margin %.17g (%.3g x scale)\n", i,
                        box_first ? "box" : "cylinder", d.distance, margin, fabs(d.distance - margin) / S2);
    }
    print_message("box-cylinder repositions: %d overlapping pairs moved, %d off the margin\n", moved, bad);
    assert_true(moved > 3000);
    assert_int_equal(bad, 0);
}

/* A near-touching disjoint pair (gap 1.1e-6, a box with a 22-unit edge and an RPP) asked to move to
 * a margin of 0.92: its normal comes from witness points 1.1e-6 apart, off by ~3e-5 rad, so a move
 * along it alone ends 3.5e-10 (1.6e-11 x scale) short of the margin. Guards the correction
 * prox_shape_reposition makes once along the moved pair's own witness direction. */
static void test_reposition_near_touching(void **st)
{
    (void)st;
    const prox_box bx = {prox_v3(10.586387247700177, 1.5779202795442488, -3.3980022477070864),
                         {prox_v3(-21.034838944369277, -3.8957988685380252, 6.7987584329319422),
                          prox_v3(-0.022592913029653678, 0.6136093315138399, 0.2817073545804944),
                          prox_v3(-0.115342638001421, 0.12634897793568786, -0.2844612920982641)}};
    const prox_rpp rp = {6.9480025472597093, 7.3466017258774885, -5.0479823460581272, 0.91836081054760843,
                         -3.5876372643056578, -2.2531639136870312};
    prox_shape A = prox_shape_from_box(bx), B = prox_shape_from_rpp(rp);
    const double margin = 0.9175161328743916;
    prox_reposition_result r = prox_shape_reposition(&A, &B, margin);
    assert_int_equal(r.status, PROX_OK);
    assert_true(r.moved && r.signed_distance > 0.0 && r.signed_distance < 2e-6);
    prox_shape B2;
    assert_int_equal(prox_shape_translated(&B, r.translation, &B2), PROX_OK);
    prox_distance_result d = prox_shape_distance(&A, &B2);
    assert_near(d.distance, margin, 1e-12 * prox_shape_pair_scale(&A, &B2));
    assert_near(prox_v3_norm(r.normal), 1.0, 1e-15);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_box_box), cmocka_unit_test(test_random_box_rpp),
        cmocka_unit_test(test_random_box_sph), cmocka_unit_test(test_random_sph_box),
        cmocka_unit_test(test_random_sph_sph), cmocka_unit_test(test_random_rcc_sph),
        cmocka_unit_test(test_random_sph_rcc), cmocka_unit_test(test_random_box_rcc),
        cmocka_unit_test(test_random_rcc_box), cmocka_unit_test(test_invalid_shapes),
        cmocka_unit_test(test_relation_cases), cmocka_unit_test(test_null_args),
        cmocka_unit_test(test_relation_internal_tangency), cmocka_unit_test(test_extreme_near_touching),
        cmocka_unit_test(test_reposition_box_cylinder),
        cmocka_unit_test(test_reposition_near_touching),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
