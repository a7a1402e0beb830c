/* The minimum over a disk of a convex piecewise-linear function M(x) = max_j a_j + b_j . x
 * (src/core/pl_disk.c), which bounds the support-function depth over a cap of directions: the exact
 * minimum (an enumeration of the arrangement's candidates) against a brute-force polar grid refined by
 * pattern search in long double, and the threshold test prox_pl_disk_above(t) (a polygon clipped from
 * the square around the disk: another algorithm) against the exact minimum at thresholds just above
 * and below it and at random ones. Random
 * planes (1 to 8), and the degenerate families: a flat plane (b = 0), parallel planes, equal planes,
 * planes through one point, and a minimum on the circle or at a vertex inside. */
#include "test_util.h"

#include <float.h>

#include "core/pl_disk.h"

static long double lmax_planes(const double *a, const prox_v2 *b, int n, long double x, long double y)
{
    long double m = -INFINITY;
    for (int j = 0; j < n; ++j) m = fmaxl(m, a[j] + b[j].x * x + b[j].y * y);
    return m;
}

/* Brute force: a polar grid of the disk, then pattern search from the best sample (M is convex, so
 * the refined value approaches the minimum from above). */
static long double brute_min(const double *a, const prox_v2 *b, int n, double r)
{
    long double best = INFINITY, bx = 0, by = 0;
    for (int i = 0; i <= 60; ++i)
        for (int k = 0; k < 120; ++k) {
            long double rr = r * i / 60.0L, th = 2.0L * PROX_PI * k / 120.0L, x = rr * cosl(th), y = rr * sinl(th);
            long double v = lmax_planes(a, b, n, x, y);
            if (v < best) best = v, bx = x, by = y;
        }
    for (long double h = r / 60.0L; h > r * 1e-13L; h *= 0.5L)
        for (int moved = 1; moved;) {
            moved = 0;
            for (int k = 0; k < 16; ++k) {
                long double th = 2.0L * PROX_PI * k / 16.0L, x = bx + h * cosl(th), y = by + h * sinl(th), rn = sqrtl(x * x + y * y);
                if (rn > r) x *= r / rn, y *= r / rn;
                long double v = lmax_planes(a, b, n, x, y);
                if (v < best) best = v, bx = x, by = y, moved = 1;
            }
        }
    return best;
}

/* Planes of family fam: 0 random, 1 one flat plane among them, 2 parallel pairs, 3 repeated planes,
 * 4 all through one point (a vertex of the arrangement), 5 a cone around a point inside the disk. */
static int make_planes(test_rng *g, int fam, double *a, prox_v2 *b)
{
    int n = 1 + (int)(test_uniform(g) * 8.0);
    double px = test_range(g, -1, 1), py = test_range(g, -1, 1);
    for (int j = 0; j < n; ++j) {
        double th = test_range(g, 0, 2.0 * PROX_PI), s = exp(test_range(g, log(1e-3), log(10.0)));
        b[j] = (prox_v2){s * cos(th), s * sin(th)};
        a[j] = test_range(g, -2, 2);
        if (fam == 4 || fam == 5) a[j] = 0.7 - (b[j].x * px + b[j].y * py); /* all through (px, py, 0.7) */
    }
    if (fam == 5 && n >= 3) /* three directions 120 degrees apart: a proper cone, minimum at (px, py) */
        for (int j = 0; j < 3; ++j) {
            double th = 2.0 * PROX_PI * j / 3.0 + 0.3;
            b[j] = (prox_v2){cos(th), sin(th)};
            a[j] = 0.7 - (b[j].x * px + b[j].y * py);
        }
    if (fam == 1) b[0] = (prox_v2){0, 0};
    if (fam == 2 && n >= 2)
        for (int j = 1; j < n; j += 2) b[j] = (prox_v2){b[j - 1].x * 2.0, b[j - 1].y * 2.0};
    if (fam == 3 && n >= 2)
        for (int j = 1; j < n; j += 2) a[j] = a[j - 1], b[j] = b[j - 1];
    return n;
}

static void test_pl_disk_families(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(2024);
    int above_checked = 0;
    for (int fam = 0; fam < 6; ++fam)
        for (int it = 0; it < 150; ++it) {
            double a[8];
            prox_v2 b[8];
            int n = make_planes(&g, fam, a, b);
            double r = exp(test_range(&g, log(1e-6), log(3.0)));
            double m = prox_pl_disk_min(a, b, n, r);
            long double bm = brute_min(a, b, n, r);
            /* the scale of M's values over the disk */
            double sc = 0.0;
            for (int j = 0; j < n; ++j) sc = fmax(sc, fabs(a[j]) + prox_v2_norm(b[j]) * r);
            double tol = 64.0 * DBL_EPSILON * sc;
            /* a lower bound, the property the cover relies on: never above a value M takes; and close
             * to the best the brute force finds (a pattern search can stall on a ridge of M, so this
             * side is loose: the threshold test below pins the minimum itself) */
            if (!(m <= bm + tol && bm - m <= 2e-3 * sc + tol)) {
                print_error("family %d planes %d r %g: min %.17g brute %.17Lg\n", fam, n, r, m, bm);
                fail();
            }
            /* the threshold test agrees with the minimum away from rounding */
            double d = 1e-9 * sc + 1e3 * tol;
            assert_true(prox_pl_disk_above(a, b, n, r, m - d));
            assert_false(prox_pl_disk_above(a, b, n, r, m + d));
            for (int k = 0; k < 4; ++k) {
                double t = m + test_range(&g, -1, 1) * sc;
                if (fabs(t - m) > d) assert_int_equal(prox_pl_disk_above(a, b, n, r, t), t < m), ++above_checked;
                /* and never above a value M takes */
                if (prox_pl_disk_above(a, b, n, r, t)) assert_true(t <= bm + tol);
            }
        }
    assert_true(above_checked > 1000);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_pl_disk_families)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
