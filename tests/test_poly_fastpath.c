/* The polytope validator's fast path (core/polytope.h: prox_polytope_fast) against the ordered
 * checks (prox_polytope_checked_full) on valid, perturbed and degenerate RHP, WED and ARB cards:
 * the fast path may only accept a card the ordered checks accept, and then with the very polytope
 * they build; prox_polytope_checked returns the ordered checks' status on every card. Also: the
 * RHP hexagon's sides come out in atan2 order, a prism's diameter is the largest corner distance
 * of a brute-force search, and its edge table matches its face loops. */
#include <string.h>

#include "core/polytope.h"
#include "test_util.h"

/* ---- cards ---- */

/* Relative perturbations, from rounding through the tolerances (1e-9) to gross. */
static double pert_size(test_rng *g)
{
    static const double m[] = {0, 1e-16, 1e-13, 1e-10, 5e-10, 9e-10, 1e-9, 1.1e-9, 2e-9, 1e-8, 1e-6, 1e-3, 0.1, 1};
    return m[test_rng_next(g) % (sizeof m / sizeof m[0])];
}

static prox_vec3 rvec(test_rng *g, double s) { return prox_v3_scale(test_unit(g), s * test_range(g, 0.0, 1.0)); }

/* A card's scale: mostly near 1, sometimes near the ends of the supported range. */
static double card_scale(test_rng *g)
{
    int k = (int)(test_rng_next(g) % 10);
    return k == 0 ? pow(10.0, test_range(g, -99.0, 99.0)) : pow(10.0, test_range(g, -3.0, 3.0));
}

/* An RHP: regular or with independent r, s, t in the base plane; then one fault or perturbation. */
static prox_shape rhp_card(test_rng *g, int plain)
{
    double sc = card_scale(g);
    prox_vec3 o = rvec(g, 10 * sc), w = test_unit(g), ax = prox_v3_scale(w, sc * test_range(g, 0.2, 3.0));
    prox_vec3 r = prox_v3_scale(prox_v3_normalize(prox_v3_reject(test_unit(g), w)), sc * test_range(g, 0.2, 3.0));
    prox_rhp h;
    if (prox_rhp_regular(o, ax, r, &h) != PROX_OK) h = (prox_rhp){o, ax, {r, r, r}};
    if (test_uniform(g) < 0.3) /* irregular: s and t turned and stretched within the plane */
        for (int i = 1; i < 3; ++i) {
            prox_vec3 u = prox_v3_normalize(h.r[i]), v = prox_v3_cross(prox_v3_normalize(ax), u);
            double t = test_range(g, -0.15, 0.15);
            h.r[i] = prox_v3_scale(prox_v3_add(prox_v3_scale(u, cos(t)), prox_v3_scale(v, sin(t))),
                                   prox_v3_norm(h.r[i]) * test_range(g, 0.85, 1.2));
        }
    if (plain) return prox_shape_from_rhp(h);
    double e = pert_size(g), L = prox_v3_norm(r);
    int i = (int)(test_rng_next(g) % 3), j = (int)(test_rng_next(g) % 3);
    switch (test_rng_next(g) % 10) {
    case 0: h.r[i] = prox_v3_add(h.r[i], rvec(g, e * L)); break;
    case 1: h.axis = prox_v3_add(h.axis, rvec(g, e * prox_v3_norm(ax))); break;
    case 2: h.r[i] = prox_v3_scale(h.r[i], test_range(g, 0.0, 2.5)); break;
    case 3: h.r[i] = prox_v3_add(h.r[j], rvec(g, e * L)); break; /* two sides (nearly) parallel */
    case 4: h.axis = prox_v3_scale(h.axis, pow(10.0, -test_range(g, 0.0, 14.0))); break; /* a plate */
    case 5: for (int k = 0; k < 3; ++k) h.r[k] = prox_v3_scale(h.r[k], pow(10.0, -test_range(g, 0.0, 14.0))); break;
    case 6: h.r[i] = prox_v3_add(h.r[i], prox_v3_scale(h.axis, e)); break; /* tilted off the base plane */
    case 7: h.r[i] = test_uniform(g) < 0.5 ? prox_v3(NAN, 0, 0) : prox_v3(0, 0, 0); break;
    case 8: h.base.x = test_uniform(g) < 0.5 ? INFINITY : 2e100; break;
    default: break;
    }
    return prox_shape_from_rhp(h);
}

/* A WED: v3 along the normal of v1, v2; then one fault or perturbation. */
static prox_shape wed_card(test_rng *g, int plain)
{
    double sc = card_scale(g);
    prox_wed w = {rvec(g, 10 * sc), prox_v3_scale(test_unit(g), sc), prox_v3_scale(test_unit(g), sc), prox_v3(0, 0, 0)};
    w.v3 = prox_v3_scale(prox_v3_normalize(prox_v3_cross(w.v1, w.v2)), sc * test_range(g, 0.05, 2.0));
    if (plain) return prox_shape_from_wed(w);
    double e = pert_size(g);
    switch (test_rng_next(g) % 5) {
    case 0: w.v3 = prox_v3_add(w.v3, rvec(g, e * sc)); break;
    case 1: w.v2 = prox_v3_add(prox_v3_scale(w.v1, test_range(g, -2.0, 2.0)), rvec(g, e * sc)); break;
    case 2: w.v3 = prox_v3_scale(w.v3, pow(10.0, -test_range(g, 0.0, 14.0))); break;
    case 3: w.v1 = prox_v3(0, 0, 0); break;
    default: break;
    }
    return prox_shape_from_wed(w);
}

/* An ARB: a truncated rectangular pyramid (corners 1-4 at the base, 5-8 on top) or a pyramid on
 * five corners, under a random rotation; then one fault or perturbation of corners or faces. */
static prox_shape arb_card(test_rng *g, int plain)
{
    static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    static const int hexa[6] = {1234, 5678, 1265, 2376, 3487, 4158}, pyra[6] = {1234, 1250, 2350, 3450, 4150, 0};
    double sc = card_scale(g), A = sc * test_range(g, 0.3, 2.0), B = sc * test_range(g, 0.3, 2.0);
    double H = sc * test_range(g, 0.3, 2.0), s = test_range(g, 0.2, 1.0);
    test_rot R = test_random_rot(g);
    prox_vec3 o = rvec(g, 10 * sc);
    prox_arb a;
    int pyramid = test_uniform(g) < 0.2;
    for (int i = 0; i < 4; ++i) {
        a.corner[i] = prox_v3_add(o, test_rot_apply(&R, prox_v3(sx[i] * A, sy[i] * B, -H)));
        a.corner[4 + i] = prox_v3_add(o, test_rot_apply(&R, prox_v3(s * sx[i] * A, s * sy[i] * B, H)));
    }
    if (pyramid) a.corner[4] = prox_v3_add(o, test_rot_apply(&R, prox_v3(0, 0, H)));
    memcpy(a.face, pyramid ? pyra : hexa, sizeof a.face);
    for (int f = 0; f < 6; ++f) /* list some loops the other way round */
        if (a.face[f] && !pyramid && test_uniform(g) < 0.3) {
            int x = a.face[f];
            a.face[f] = (x % 10) * 1000 + (x / 10 % 10) * 100 + (x / 100 % 10) * 10 + x / 1000;
        }
    if (plain) return prox_shape_from_arb(a);
    double e = pert_size(g);
    int i = (int)(test_rng_next(g) % 8), j = (int)(test_rng_next(g) % 8), f = (int)(test_rng_next(g) % 6);
    switch (test_rng_next(g) % 10) {
    case 0: a.corner[i] = prox_v3_add(a.corner[i], rvec(g, e * sc)); break; /* out of its faces' planes */
    case 1: a.corner[i] = prox_v3_add(a.corner[j], rvec(g, e * sc)); break; /* two corners (nearly) one */
    case 2: /* two corners of a loop swapped: a crossed loop */
        if (a.face[f] >= 1000) a.face[f] = (a.face[f] / 100 % 10) * 1000 + (a.face[f] / 1000) * 100 + a.face[f] % 100;
        break;
    case 3: a.face[f] = test_uniform(g) < 0.5 ? 0 : 4321; break;
    case 4: a.face[f] = test_uniform(g) < 0.5 ? 1239 : 1123; break;
    case 5: for (int k = 0; k < 8; ++k) a.corner[k] = prox_v3_add(a.corner[k], rvec(g, e * sc)); break;
    case 6: /* flattened towards a plate */
        for (int k = 4; k < 8; ++k)
            a.corner[k] = prox_v3_mad(a.corner[k - 4], e, prox_v3_sub(a.corner[k], a.corner[k - 4]));
        break;
    case 7: a.corner[i].y = test_uniform(g) < 0.5 ? NAN : -3e100; break;
    case 8: a.corner[i] = prox_v3_add(o, prox_v3_scale(prox_v3_sub(a.corner[i], o), 0.3 + e)); break; /* a dent */
    default: break;
    }
    return prox_shape_from_arb(a);
}

static prox_shape card(test_rng *g, int kind, int plain)
{
    return kind == 0 ? rhp_card(g, plain) : (kind == 1 ? wed_card(g, plain) : arb_card(g, plain));
}

/* ---- comparisons ---- */

static int same_vec(prox_vec3 a, prox_vec3 b) { return !memcmp(&a, &b, sizeof a); }

/* Bit for bit the same polytope on every slot its counts cover. */
static void assert_same_polytope(const prox_polytope *p, prox_vec3 cp, const prox_polytope *q, prox_vec3 cq)
{
    assert_true(same_vec(cp, cq));
    assert_int_equal(p->nv, q->nv);
    assert_int_equal(p->nf, q->nf);
    assert_int_equal(p->ne, q->ne);
    assert_true(!memcmp(&p->size, &q->size, sizeof p->size));
    for (int i = 0; i < p->nv; ++i) assert_true(same_vec(p->v[i], q->v[i]));
    for (int f = 0; f < p->nf; ++f) {
        assert_true(same_vec(p->n[f], q->n[f]));
        assert_true(!memcmp(&p->d[f], &q->d[f], sizeof p->d[f]));
        assert_int_equal(p->facet[f], q->facet[f]);
        assert_int_equal(p->fnv[f], q->fnv[f]);
        assert_true(!memcmp(p->fv[f], q->fv[f], (size_t)p->fnv[f]));
    }
    assert_true(!memcmp(p->e, q->e, sizeof p->e[0] * (size_t)p->ne));
    assert_true(!memcmp(p->ef, q->ef, sizeof p->ef[0] * (size_t)p->ne));
}

/* One card through both halves; returns 1 when the fast path accepted it. */
static int compare_card(const prox_shape *s)
{
    prox_polytope pf, pr;
    prox_vec3 cf = prox_v3(0, 0, 0), cr = prox_v3(0, 0, 0);
    prox_status full = prox_polytope_checked_full(s, &pr, &cr);
    int fast = prox_polytope_fast(s, &pf, &cf);
    prox_polytope pc;
    prox_vec3 cc;
    assert_int_equal(prox_polytope_checked(s, &pc, &cc), full);
    if (!fast) return 0;
    if (full != PROX_OK) {
        print_error("fast path accepted a card the checks reject with %s\n", prox_status_str(full));
        fail();
    }
    assert_same_polytope(&pf, cf, &pr, cr);
    return 1;
}

/* Plain valid cards: the checks accept them, and the fast path takes nearly all of them. */
static void test_plain_cards(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(11);
    for (int kind = 0; kind < 3; ++kind) {
        int fast = 0, n = 1500;
        for (int k = 0; k < n; ++k) {
            prox_shape s = card(&g, kind, 1);
            prox_polytope p;
            prox_vec3 c;
            assert_int_equal(prox_polytope_checked_full(&s, &p, &c), PROX_OK);
            fast += compare_card(&s);
        }
        assert_true(fast >= 0.95 * n);
    }
}

/* Perturbed and degenerate cards: the same status from both, the fast path never wrong, and the
 * ordered checks reached for cards the fast path leaves (some valid, some not). */
static void test_perturbed_cards(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(12);
    for (int kind = 0; kind < 3; ++kind) {
        int fast = 0, left_ok = 0, bad = 0, n = 8000;
        for (int k = 0; k < n; ++k) {
            prox_shape s = card(&g, kind, 0);
            prox_polytope p;
            prox_vec3 c;
            prox_status full = prox_polytope_checked_full(&s, &p, &c);
            int f = compare_card(&s);
            fast += f;
            left_ok += !f && full == PROX_OK;
            bad += full != PROX_OK;
        }
        assert_true(bad > n / 20);
        assert_true(fast > n / 4 && left_ok > 0);
    }
}

/* The RHP's sides sorted by angle: atan2 of consecutive normals increases (an independent order). */
static void test_hexagon_order(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(13);
    for (int k = 0; k < 3000; ++k) {
        prox_shape s = rhp_card(&g, 1);
        prox_rhp_section hx;
        prox_rhp_hexagon(&s.u.rhp, &hx);
        for (int i = 0; i + 1 < 6; ++i)
            assert_true(atan2(hx.nl[i][1], hx.nl[i][0]) < atan2(hx.nl[i + 1][1], hx.nl[i + 1][0]));
        for (int i = 0; i < 6; ++i) { /* corner i on side lines i and i + 1 */
            int j = (i + 1) % 6;
            double r1 = hx.nl[i][0] * hx.x[i][0] + hx.nl[i][1] * hx.x[i][1] - hx.dl[i];
            double r2 = hx.nl[j][0] * hx.x[i][0] + hx.nl[j][1] * hx.x[i][1] - hx.dl[j];
            assert_true(fabs(r1) <= 1e-12 * hx.dl[i] && fabs(r2) <= 1e-12 * hx.dl[j]);
        }
    }
}

/* Prisms (RHP, WED, BOX, flat ones included): the size is the brute-force largest corner distance,
 * and every edge joins two corners that follow each other in both its faces' loops, in opposite
 * directions, each edge once. */
static void test_prism_tables(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(14);
    for (int k = 0; k < 6000; ++k) {
        int kind = k % 3;
        prox_shape s;
        if (kind == 2) {
            test_rot R = test_random_rot(&g);
            prox_vec3 e[3];
            for (int i = 0; i < 3; ++i)
                e[i] = test_rot_apply(&R, prox_v3(i == 0, i == 1, i == 2));
            for (int i = 0; i < 3; ++i) e[i] = prox_v3_scale(e[i], pow(10.0, test_range(&g, -5.0, 2.0)));
            s = prox_shape_from_box((prox_box){rvec(&g, 5), {e[0], e[1], e[2]}});
        } else {
            s = card(&g, kind, test_uniform(&g) < 0.5);
        }
        prox_polytope p;
        prox_vec3 c;
        if (prox_polytope_checked(&s, &p, &c) != PROX_OK) continue;
        double s2 = 0.0;
        for (int i = 0; i < p.nv; ++i)
            for (int j = 0; j < p.nv; ++j) s2 = fmax(s2, prox_v3_norm2(prox_v3_sub(p.v[i], p.v[j])));
        assert_true(p.size == sqrt(s2));
        assert_int_equal(p.nv - p.ne + p.nf, 2);
        for (int e = 0; e < p.ne; ++e) {
            int a = p.e[e][0], b = p.e[e][1], dir[2] = {0, 0};
            assert_true(a < b);
            for (int side = 0; side < 2; ++side) {
                int f = p.ef[e][side], m = p.fnv[f];
                for (int i = 0; i < m; ++i) {
                    int x = p.fv[f][i], y = p.fv[f][(i + 1) % m];
                    if (x == a && y == b) dir[side] = 1;
                    if (x == b && y == a) dir[side] = -1;
                }
            }
            assert_true(dir[0] == 1 && dir[1] == -1);
            for (int e2 = 0; e2 < e; ++e2) assert_false(p.e[e2][0] == a && p.e[e2][1] == b);
        }
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plain_cards),
        cmocka_unit_test(test_perturbed_cards),
        cmocka_unit_test(test_hexagon_order),
        cmocka_unit_test(test_prism_tables),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
