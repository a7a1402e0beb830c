/* The inner-polytope lower bound on a depth (src/sat/epa.c) on convex sets P whose depth (the
 * distance from the origin, inside P, to P's boundary) is known in closed form: a box about an
 * offset centre (depth = min_i h_i - |o_i|), a ball (r - |o|) and a long thin box (a P whose starting
 * support points lie near its ends). What is proved must hold: lower <= depth <= upper, and a proof
 * must be tight: upper - lower <= tol; most started meshes must reach a proof. Starting meshes that
 * do not wrap the origin (P beside the origin; every triangle turned the wrong way; a box's corners
 * tying between directions) must be refused at once. */
#include "test_util.h"

#include <float.h>

#include "sat/epa.h"

typedef struct pset {
    int ball;
    prox_vec3 o, h; /* centre; half extents (box) or h.x = radius (ball) */
} pset;

static prox_vec3 support(void *ctx, prox_vec3 d, double *hv)
{
    const pset *P = ctx;
    prox_vec3 w;
    if (P->ball) w = prox_v3_mad(P->o, P->h.x, d);
    else w = prox_v3_add(P->o, prox_v3(copysign(P->h.x, d.x), copysign(P->h.y, d.y), copysign(P->h.z, d.z)));
    *hv = prox_v3_dot(w, d);
    return w;
}

static double true_depth(const pset *P)
{
    if (P->ball) return P->h.x - prox_v3_norm(P->o);
    return fmin(P->h.x - fabs(P->o.x), fmin(P->h.y - fabs(P->o.y), P->h.z - fabs(P->o.z)));
}

/* The octahedron's corners +-x, +-y, +-z and its faces, counter-clockwise seen from outside. */
static const unsigned char octa[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

/* The octahedron turned off the box's axes (a box's support points at +-x, +-y, +-z would tie). */
static prox_vec3 turned(double x, double y, double z)
{
    const double c = cos(0.3), s = sin(0.3), c2 = cos(0.7), s2 = sin(0.7);
    prox_vec3 a = prox_v3(c * x - s * y, s * x + c * y, z);
    return prox_v3(a.x, c2 * a.y - s2 * a.z, s2 * a.y + c2 * a.z);
}

static int run(pset *P, const unsigned char (*tri)[3], prox_epa_result *e)
{
    static const double dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    prox_vec3 v[6], best = {1, 0, 0};
    double upper = INFINITY, h;
    for (int i = 0; i < 6; ++i) {
        prox_vec3 d = turned(dirs[i][0], dirs[i][1], dirs[i][2]);
        v[i] = support(P, d, &h);
        if (h < upper) upper = h, best = d;
    }
    return prox_epa_depth(support, P, v, 6, tri, 8, upper, best, 1e-10, 16.0 * DBL_EPSILON * 4.0, 140, e);
}

static void check_family(int ball, double thin, int n, uint64_t seed)
{
    test_rng g = test_rng_seed(seed);
    int proved = 0, refused = 0;
    long points = 0;
    for (int i = 0; i < n; ++i) {
        pset P = {ball, {0, 0, 0}, {0, 0, 0}};
        if (ball) {
            P.h.x = test_range(&g, 0.5, 2.0);
            P.o = prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 0.9) * P.h.x);
        } else {
            P.h = prox_v3(test_range(&g, 0.5, 2.0), test_range(&g, 0.5, 2.0) * thin, test_range(&g, 0.5, 2.0) * thin);
            P.o = prox_v3(test_range(&g, -0.9, 0.9) * P.h.x, test_range(&g, -0.9, 0.9) * P.h.y, test_range(&g, -0.9, 0.9) * P.h.z);
        }
        double depth = true_depth(&P), S = 4.0;
        prox_epa_result e;
        int ok = run(&P, octa, &e);
        assert_true(e.upper >= depth - 1e-15 * S); /* an achieved h_P */
        if (!ok) {
            assert_true(e.lower == -INFINITY);
            refused += e.points == 0; /* a start that does not wrap the origin (corners that tie) */
            continue;
        }
        ++proved, points += e.points;
        if (!(e.lower <= depth + 1e-15 * S && e.upper - e.lower <= 1e-10 * 1.0001)) {
            print_error("ball %d thin %g: depth %.17g lower %.17g upper %.17g\n", ball, thin, depth, e.lower, e.upper);
            fail();
        }
    }
    printf("%-10s thin %-6g pairs %4d refused at the start %4d proved %4d mean points %.1f\n", ball ? "ball" : "box", thin,
           n, refused, proved, proved ? (double)points / proved : 0.0);
    /* a box is a polytope: once started, the mesh reaches its faces in a few points; a ball is smooth
     * everywhere, and triangles within 1e-10 of its surface near the deepest direction take about a
     * hundred points, more than the 140 allowed for half of them */
    if (ball) assert_true(proved * 3 >= n - refused);
    else assert_true(proved * 10 >= (n - refused) * 9);
}

static void test_epa_box(void **state)
{
    (void)state;
    check_family(0, 1.0, 400, 11);
}

static void test_epa_thin_box(void **state)
{
    (void)state;
    check_family(0, 1e-3, 400, 12);
}

static void test_epa_ball(void **state)
{
    (void)state;
    check_family(1, 1.0, 400, 13);
}

/* A mesh that does not wrap the origin is refused before any step: P beside the origin (every
 * triangle's distance is positive, yet no ray in the directions away from P meets the mesh), and a
 * valid P with every triangle listed clockwise (degree -1). */
static void test_epa_refuses_unwrapped(void **state)
{
    (void)state;
    prox_epa_result e;
    pset beside = {1, {3, 0, 0}, {1, 0, 0}};
    assert_int_equal(run(&beside, octa, &e), 0);
    assert_int_equal(e.points, 0);
    assert_true(e.lower == -INFINITY);
    unsigned char rev[8][3];
    for (int f = 0; f < 8; ++f) rev[f][0] = octa[f][0], rev[f][1] = octa[f][2], rev[f][2] = octa[f][1];
    pset inside = {0, {0.1, 0.2, -0.1}, {1, 1.5, 2}};
    assert_int_equal(run(&inside, (const unsigned char (*)[3])rev, &e), 0);
    assert_int_equal(e.points, 0);
    assert_int_equal(run(&inside, octa, &e), 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_epa_box),
        cmocka_unit_test(test_epa_thin_box),
        cmocka_unit_test(test_epa_ball),
        cmocka_unit_test(test_epa_refuses_unwrapped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
