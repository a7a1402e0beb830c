/* Tests of the fast paths of the cell check against the slow exact ones:
 * - the plane shortcut of the box classification (classify.c) against the general Taylor form, verdict
 *   for verdict on random planes and boxes, and both against the plane's exact range at the corners;
 * - the plane shortcut of exact membership (prox_surf_eval) against the general quadric sum written
 *   out here, bit for bit;
 * - the pair classification (prox_cc_classify_pair) against dense sampling of its box in long double
 *   (concentric spheres and coaxial cylinders written in different local origins, parallel planes of
 *   any scale and orientation, random quadrics): a claimed empty sign assignment must have no sample;
 *   on thin shells it must decide the boxes that straddle both surfaces;
 * - whole checks of thin concentric shells (the models whose every box straddles two surfaces): clean
 *   with few boxes, and a real overlap and a real gap inside a thin shell found, each witness checked
 *   against the radii here; two pins in a moderator, deeply subdivided (inherited classifications),
 *   clean, overlapping and with a gap. */
#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "cells/check_internal.h"
#include "prox/cellcheck.h"

/* f in long double from the coefficients (the sum of cells.h, written here). */
static long double feval(const prox_surf *s, long double x, long double y, long double z)
{
    const double *q = s->q;
    x -= s->o.x, y -= s->o.y, z -= s->o.z;
    return q[0] * x * x + q[1] * y * y + q[2] * z * z + q[3] * x * y + q[4] * y * z + q[5] * z * x + q[6] * x + q[7] * y +
           q[8] * z + q[9];
}

/* The quadric |A (x - c)|^2-like surface with unit quadratic part diag(k) around centre c, written in
 * local origin o: sum_i k_i (y_i + d_i)^2 - r^2, y = x - o, d = o - c (k_i = 1 a sphere; k = (1,1,0) a
 * cylinder along z). */
static prox_surf centred_quadric(prox_vec3 c, prox_vec3 o, const double k[3], double r)
{
    prox_surf s = {.kind = PROX_SURF_QUADRIC, .o = o};
    const double d[3] = {o.x - c.x, o.y - c.y, o.z - c.z};
    s.q[9] = -r * r;
    for (int i = 0; i < 3; ++i) {
        s.q[i] = k[i];
        s.q[6 + i] = 2.0 * k[i] * d[i];
        s.q[9] += k[i] * d[i] * d[i];
    }
    return s;
}

/* A general quadric rotated by R: f(x) = g(R^T (x - c)) with g = sum k_i y_i^2 - r^2 (coaxial
 * cylinders along any axis), written in origin c. */
static prox_surf rotated_quadric(const test_rot *R, prox_vec3 c, const double k[3], double r)
{
    prox_surf s = {.kind = PROX_SURF_QUADRIC, .o = c};
    double A[3][3] = {{0}};
    prox_vec3 e[3] = {prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1)};
    prox_vec3 col[3];
    for (int j = 0; j < 3; ++j) col[j] = test_rot_apply(R, e[j]); /* columns of R */
    const double cc[3][3] = {{col[0].x, col[1].x, col[2].x}, {col[0].y, col[1].y, col[2].y}, {col[0].z, col[1].z, col[2].z}};
    for (int a = 0; a < 3; ++a) /* A = R diag(k) R^T */
        for (int b = 0; b < 3; ++b)
            for (int j = 0; j < 3; ++j) A[a][b] += cc[a][j] * k[j] * cc[b][j];
    s.q[0] = A[0][0], s.q[1] = A[1][1], s.q[2] = A[2][2];
    s.q[3] = 2.0 * A[0][1], s.q[4] = 2.0 * A[1][2], s.q[5] = 2.0 * A[2][0];
    s.q[9] = -r * r;
    return s;
}

static prox_surf plane_through(prox_vec3 n, double d, prox_vec3 o, double scale)
{
    prox_surf s = {.kind = PROX_SURF_QUADRIC, .o = o};
    s.q[6] = scale * n.x, s.q[7] = scale * n.y, s.q[8] = scale * n.z;
    s.q[9] = scale * (prox_v3_dot(n, o) - d);
    return s;
}

/* A random box of edge up to `size` (log-uniform down to size 1e-4) around p. */
static prox_ccbox box_around(test_rng *g, prox_vec3 p, double size)
{
    const double pc[3] = {p.x, p.y, p.z};
    prox_ccbox b;
    for (int i = 0; i < 3; ++i) {
        double e = size * pow(10.0, -4.0 * test_uniform(g));
        double f = test_uniform(g);
        b.lo[i] = pc[i] - f * e, b.hi[i] = pc[i] + (1.0 - f) * e;
    }
    return b;
}

/* ---- the plane shortcut ---- */

static void plane_shortcut_matches_taylor(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(11);
    size_t decided = 0;
    for (int it = 0; it < 100000; ++it) {
        prox_vec3 n = test_unit(&g);
        if (it % 3 == 0) n = it % 2 ? prox_v3(0, 0, 1) : prox_v3(-1, 0, 0); /* axis planes: faces on them */
        prox_vec3 o = prox_v3_scale(test_unit(&g), test_range(&g, 0, 1000));
        double d = test_range(&g, -50, 50), scale = pow(10.0, test_range(&g, -3, 3)) * (it % 5 ? 1 : -1);
        prox_surf s = plane_through(n, d, o, scale);
        prox_vec3 p = prox_v3_add(prox_v3_scale(n, d), prox_v3_scale(test_unit(&g), test_range(&g, 0, 2)));
        prox_ccbox b = box_around(&g, p, 4.0);
        if (it % 7 == 0) b.hi[2] = b.lo[2] = (it % 2 ? d : b.lo[2]); /* flat boxes and faces on the plane */
        int fast = prox_cc_classify(&s, &b), slow = prox_cc_classify_taylor(&s, &b);
        if (fast != slow) {
            print_error("plane %d: shortcut %d, Taylor form %d\n", it, fast, slow);
            fail();
        }
        decided += fast != 0;
        /* Both against the exact range of f: its extremes are at corners. */
        long double lo = INFINITY, hi = -INFINITY, mag = 0;
        for (int c = 0; c < 8; ++c) {
            long double v = feval(&s, c & 1 ? b.hi[0] : b.lo[0], c & 2 ? b.hi[1] : b.lo[1], c & 4 ? b.hi[2] : b.lo[2]);
            lo = fminl(lo, v), hi = fmaxl(hi, v);
        }
        for (int i = 6; i < 10; ++i) mag += fabsl((long double)s.q[i]) * (i < 9 ? 2000.0L : 1.0L);
        const long double layer = 1e-12L * mag; /* the classification's rounding layer is far thinner */
        if ((fast < 0 && hi > layer) || (fast > 0 && lo < -layer)) {
            print_error("plane %d: verdict %d but f ranges over [%Lg, %Lg]\n", it, fast, lo, hi);
            fail();
        }
    }
    assert_true(decided > 25000); /* the comparison covers both answers */
}

static void plane_membership_matches_general(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(12);
    for (int it = 0; it < 100000; ++it) {
        prox_vec3 o = prox_v3_scale(test_unit(&g), test_range(&g, 0, 1e4));
        prox_surf s = plane_through(test_unit(&g), test_range(&g, -100, 100), o, test_range(&g, -10, 10));
        if (it % 4 == 0) s.q[6] = s.q[7] = 0.0; /* PZ-like */
        prox_vec3 x = prox_v3_add(o, prox_v3_scale(test_unit(&g), pow(10.0, test_range(&g, -6, 4))));
        prox_vec3 y = prox_v3_sub(x, s.o);
        const double *q = s.q; /* the general sum of membership.c, every term kept */
        double general = y.x * (q[0] * y.x + q[3] * y.y + q[5] * y.z + q[6]) + y.y * (q[1] * y.y + q[4] * y.z + q[7]) +
                         y.z * (q[2] * y.z + q[8]) + q[9];
        double fast = prox_surf_eval(&s, x);
        if (!(fast == general)) {
            print_error("plane %d: %.17g against the general %.17g\n", it, fast, general);
            fail();
        }
    }
}

/* ---- pair classification ---- */

/* Samples of box b: a 9 x 9 x 9 grid with its corners and faces, and random points. */
static int sample_point(test_rng *g, const prox_ccbox *b, int k, long double x[3])
{
    if (k < 729) {
        int idx[3] = {k % 9, (k / 9) % 9, k / 81};
        for (int i = 0; i < 3; ++i) x[i] = b->lo[i] + (b->hi[i] - b->lo[i]) * (long double)idx[i] / 8.0L;
        return 1;
    }
    if (k < 729 + 300) {
        for (int i = 0; i < 3; ++i) x[i] = b->lo[i] + (b->hi[i] - b->lo[i]) * (long double)test_uniform(g);
        return 1;
    }
    return 0;
}

/* Checks the claim of prox_cc_classify_pair on b by sampling; returns its verdict. */
static int check_pair(test_rng *g, const prox_surf *u, const prox_surf *v, const prox_ccbox *b, const char *what, int it)
{
    double lam = 0.0;
    int k = prox_cc_classify_pair(u, v, b, &lam);
    if (!k) return 0;
    assert_true(lam != 0.0 && isfinite(lam));
    long double x[3];
    for (int j = 0; sample_point(g, b, j, x); ++j) {
        long double fu = feval(u, x[0], x[1], x[2]), fv = feval(v, x[0], x[1], x[2]);
        int bad = k < 0 ? (fv >= 0 && lam * fu <= 0) : (fv <= 0 && lam * fu >= 0);
        /* Rounding of the sample itself: a point this close to both surfaces proves nothing. */
        long double tiny = 1e-9L * (1.0L + fabsl(fu) + fabsl(fv));
        if (bad && fabsl(fv) > tiny && fabsl(fu) > tiny) {
            print_error("%s %d: pair verdict %d (lambda %g) but f_u = %Lg, f_v = %Lg at (%Lg %Lg %Lg)\n", what, it, k, lam,
                        fu, fv, x[0], x[1], x[2]);
            fail();
        }
        /* The stronger statement it proves: g = f_v - lambda f_u keeps its sign. */
        long double gg = fv - (long double)lam * fu;
        if ((k < 0 && gg > tiny) || (k > 0 && gg < -tiny)) {
            print_error("%s %d: pair verdict %d but g = %Lg\n", what, it, k, gg);
            fail();
        }
    }
    return k;
}

/* Concentric spheres and coaxial cylinders (the second written in a far local origin), boxes on the
 * inner surface: the pair verdict must be sound, and must decide nearly every box that straddles the
 * two surfaces of the shell. */
static void pair_nested(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(13);
    size_t straddle = 0, decided = 0;
    for (int it = 0; it < 4000; ++it) {
        const double ksph[3] = {1, 1, 1}, kcyl[3] = {1, 1, 0};
        const double *k = it % 2 ? ksph : kcyl;
        prox_vec3 c = prox_v3_scale(test_unit(&g), test_range(&g, 0, 100));
        double r1 = test_range(&g, 0.5, 50), dr = r1 * pow(10.0, test_range(&g, -5, -1));
        prox_vec3 ofar = prox_v3_add(c, prox_v3_scale(test_unit(&g), test_range(&g, 0, 500)));
        prox_surf a = centred_quadric(c, c, k, r1), b2 = centred_quadric(c, ofar, k, r1 + dr);
        if (it % 3 == 0) { /* any axis */
            test_rot R = test_random_rot(&g);
            a = rotated_quadric(&R, c, k, r1), b2 = rotated_quadric(&R, c, k, r1 + dr);
        }
        prox_vec3 dir = test_unit(&g);
        if (k == kcyl && it % 3) dir.z = 0.0, dir = prox_v3_scale(dir, 1.0 / prox_v3_norm(dir));
        prox_vec3 p = prox_v3_add(c, prox_v3_scale(dir, r1 + test_range(&g, -1, 2) * dr));
        prox_ccbox bx = box_around(&g, p, 20.0 * dr);
        int k1 = check_pair(&g, &a, &b2, &bx, "nested", it);
        int k2 = check_pair(&g, &b2, &a, &bx, "nested swapped", it);
        if (prox_cc_classify(&a, &bx) == 0 && prox_cc_classify(&b2, &bx) == 0) {
            ++straddle;
            decided += k1 != 0 && k2 != 0;
        }
    }
    print_message("nested: %zu of %zu boxes straddling both surfaces decided\n", decided, straddle);
    assert_true(straddle > 500);
    assert_true(decided >= straddle * 99 / 100);
}

/* Parallel planes of any scale and sign, planes at an angle, plane against sphere, random quadrics:
 * every verdict sound. */
static void pair_random(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(14);
    size_t decided = 0;
    for (int it = 0; it < 4000; ++it) {
        prox_surf u, v;
        prox_vec3 p = prox_v3_scale(test_unit(&g), test_range(&g, 0, 50));
        prox_vec3 n = test_unit(&g), o1 = prox_v3_scale(test_unit(&g), 300), o2 = prox_v3_scale(test_unit(&g), 30);
        switch (it % 4) {
        case 0: /* parallel */
            u = plane_through(n, prox_v3_dot(n, p), o1, test_range(&g, -5, 5));
            v = plane_through(n, prox_v3_dot(n, p) + test_range(&g, -0.1, 0.1), o2, test_range(&g, -5, 5));
            break;
        case 1: /* at an angle */
            u = plane_through(n, prox_v3_dot(n, p), o1, 1.0);
            v = plane_through(test_unit(&g), test_range(&g, -1, 1), o2, 2.0);
            break;
        case 2: { /* sphere and plane: no multiplier */
            const double k[3] = {1, 1, 1};
            u = centred_quadric(p, p, k, 3.0);
            v = plane_through(n, prox_v3_dot(n, p), o2, 1.0);
            double lam = 1.0;
            prox_ccbox bx = box_around(&g, p, 5.0);
            assert_int_equal(prox_cc_classify_pair(&v, &u, &bx, &lam), 0);
            assert_true(lam == 0.0);
            break;
        }
        default: /* random quadrics */
            u = (prox_surf){.kind = PROX_SURF_QUADRIC, .o = o2};
            v = (prox_surf){.kind = PROX_SURF_QUADRIC, .o = o1};
            for (int i = 0; i < 10; ++i) u.q[i] = test_range(&g, -1, 1), v.q[i] = u.q[i] * 1.5 + test_range(&g, -0.1, 0.1);
            break;
        }
        prox_ccbox bx = box_around(&g, p, 2.0);
        decided += check_pair(&g, &u, &v, &bx, "random", it) != 0;
    }
    assert_true(decided > 100);
}

/* A torus in a pair: never a verdict. */
static void pair_torus(void **state)
{
    (void)state;
    prox_surf t = {.kind = PROX_SURF_TORUS, .w = prox_v3(0, 0, 1), .ta = 5, .tb = 1, .tc = 1};
    const double k[3] = {1, 1, 1};
    prox_surf s = centred_quadric(prox_v3(0, 0, 0), prox_v3(0, 0, 0), k, 3.0);
    prox_ccbox b = {{4.9, -0.1, -0.1}, {5.1, 0.1, 0.1}};
    double lam = 1.0;
    assert_int_equal(prox_cc_classify_pair(&t, &s, &b, &lam), 0);
    assert_int_equal(prox_cc_classify_pair(&s, &t, &b, &lam), 0);
}

/* ---- whole checks of thin shells ---- */

static void check_deck(const char *text, prox_cells_report *r)
{
    prox_cell_model m = {0};
    assert_int_equal(prox_cells_parse(text, &m), PROX_OK);
    assert_int_equal(m.nerrors, 0);
    prox_cells_check_opts o = {.threads = 2};
    assert_int_equal(prox_cells_check(&m, &o, r), PROX_OK);
    prox_cells_free(&m);
}

/* A sphere of solution in a steel shell 0.127 thick in a cadmium cover 0.05 thick (an ICSBEP
 * sphere), and coaxial cylinders 0.127 apart written around a far origin: clean, and every box that
 * straddles the shell is decided at once (before pair classification these took millions of boxes). */
static void shells_clean(void **state)
{
    (void)state;
    static const char *const decks[] = {
        "spheres\n1 1 -1 -1 imp:n=1\n2 2 -8 1 -2 imp:n=1\n3 3 -8 2 -3 imp:n=1\n4 0 3 imp:n=0\n\n"
        "1 so 22.6974\n2 so 22.8244\n3 so 22.8752\n\n",
        "cylinders\n1 1 -1 -1 -4 5 imp:n=1\n2 2 -8 1 -2 -4 5 imp:n=1\n3 0 2 -3 -4 5 imp:n=1\n"
        "4 0 3:4:-5 imp:n=0\n\n"
        "1 c/z 1000 -700 26.67\n2 c/z 1000 -700 26.797\n3 c/z 1000 -700 40\n4 pz 100\n5 pz 0\n\n",
    };
    for (size_t d = 0; d < 2; ++d) {
        prox_cells_report r;
        check_deck(decks[d], &r);
        print_message("shell %zu: %zu boxes\n", d, r.stats.boxes);
        assert_int_equal(r.noverlaps, 0);
        assert_int_equal(r.ngaps, 0);
        assert_int_equal(r.nundecided, 0);
        assert_true(r.stats.boxes < 20000);
        prox_cells_report_free(&r);
    }
}

/* The same sphere with the solution reaching into the steel (an overlap 0.05 thick) or stopping short
 * of it (a gap): found, with witnesses checked against the radii. */
static void shells_findings(void **state)
{
    (void)state;
    prox_cells_report r;
    check_deck("overlap\n1 1 -1 -4 imp:n=1\n2 2 -8 1 -2 imp:n=1\n3 3 -8 2 -3 imp:n=1\n4 0 3 imp:n=0\n\n"
               "1 so 22.6974\n2 so 22.8244\n3 so 22.8752\n4 so 22.7474\n\n",
               &r);
    assert_int_equal(r.noverlaps, 1);
    assert_int_equal(r.ngaps, 0);
    assert_true(r.overlaps[0].cells[0] == 1 && r.overlaps[0].cells[1] == 2);
    double d = prox_v3_norm(r.overlaps[0].point);
    assert_true(d > 22.6974 && d < 22.7474);
    assert_true(r.overlaps[0].volume_min > 0.0);
    assert_true(r.overlaps[0].volume_min < 4.0 * acos(-1.0) * 22.75 * 22.75 * 0.05); /* the shell's volume */
    prox_cells_report_free(&r);

    check_deck("gap\n1 1 -1 -4 imp:n=1\n2 2 -8 1 -2 imp:n=1\n3 3 -8 2 -3 imp:n=1\n4 0 3 imp:n=0\n\n"
               "1 so 22.6974\n2 so 22.8244\n3 so 22.8752\n4 so 22.6474\n\n",
               &r);
    assert_int_equal(r.noverlaps, 0);
    assert_true(r.ngaps >= 1);
    d = prox_v3_norm(r.gaps[0].point);
    assert_true(d > 22.6474 && d < 22.6974);
    prox_cells_report_free(&r);
}

/* Two pins in a moderator box, subdivided deeply (the children inherit their parents' surface
 * classifications): clean; a pin wider than its hole in the moderator (overlap in the annulus
 * 0.9 < r < 1 around (3, 0)); a pin narrower than its hole (gap in the same annulus). */
static void pins_subdivided(void **state)
{
    (void)state;
    static const char *const pin2[3] = {"-2 -10", "-2 -10", "-3 -10"}, *const hole2[3] = {"2", "3", "2"};
    for (int v = 0; v < 3; ++v) {
        char text[1024];
        snprintf(text, sizeof text,
                 "pins\n1 1 -1 -1 -10 imp:n=1\n2 1 -1 %s imp:n=1\n3 2 -1 1 %s -10 imp:n=1\n4 0 10 imp:n=0\n\n"
                 "1 c/z 0 0 1\n2 c/z 3 0 1\n3 c/z 3 0 0.9\n10 rpp -2 5 -2 2 0 4\n\n",
                 pin2[v], hole2[v]);
        prox_cells_report r;
        check_deck(text, &r);
        print_message("pins %d: %zu boxes\n", v, r.stats.boxes);
        if (v) assert_true(r.stats.boxes > 200); /* findings are subdivided: children inherit */
        if (v == 0) assert_true(r.noverlaps == 0 && r.ngaps == 0 && r.nundecided == 0);
        prox_vec3 p = v == 1 ? (r.noverlaps ? r.overlaps[0].point : prox_v3(0, 0, 0)) : (r.ngaps ? r.gaps[0].point : prox_v3(0, 0, 0));
        if (v == 1) {
            assert_true(r.noverlaps == 1 && r.ngaps == 0);
            assert_true(r.overlaps[0].cells[0] == 2 && r.overlaps[0].cells[1] == 3);
        }
        if (v == 2) assert_true(r.noverlaps == 0 && r.ngaps == 1);
        double d = hypot(p.x - 3.0, p.y);
        if (v) assert_true(d > 0.9 && d < 1.0 && p.z > 0.0 && p.z < 4.0);
        prox_cells_report_free(&r);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plane_shortcut_matches_taylor),
        cmocka_unit_test(plane_membership_matches_general),
        cmocka_unit_test(pair_nested),
        cmocka_unit_test(pair_random),
        cmocka_unit_test(pair_torus),
        cmocka_unit_test(shells_clean),
        cmocka_unit_test(shells_findings),
        cmocka_unit_test(pins_subdivided),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
