/* prox pairs --method: each of the three cylinder methods, run through the command-line tool on the
 * reference sets of tests/data, prints distances and proximal points that meet the accuracy bar
 * (1e-12 S, S = prox_rcc_pair_scale, plus 16 eps times the largest coordinate: tests/data/README.md
 * notes that the input doubles of pairs placed far from the origin carry that rounding themselves):
 * |d - sd_ref| <= tol for disjoint pairs, |p2 - p1| = d, p1 in
 * A and p2 in B within 1e-12 S; d = 0 and p1 = p2 in both solids for overlapping pairs. Also the
 * option's errors and `prox --version`. */
#define _POSIX_C_SOURCE 200809L
#include "test_refsets.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <float.h>

static char dir[256];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/prox_cli_methods_%ld", (long)getpid());
    char cmd[512];
    snprintf(cmd, sizeof cmd, "mkdir -p %s", dir);
    return system(cmd) == 0 ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    return system(cmd) == 0 ? 0 : -1;
}

/* Runs `prox ARGS < input > dir/out.txt 2> dir/err.txt`; returns the exit status. */
static int run_cli(const char *args, const char *input)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "'%s' %s < '%s' > %s/out.txt 2> %s/err.txt", PROX_CLI_PATH, args, input, dir, dir);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/* Distance from x to the solid cylinder (0 inside), in long double. */
static double outside(const prox_rcc *c, prox_vec3 x)
{
    long double ax = c->axis.x, ay = c->axis.y, az = c->axis.z;
    long double h = sqrtl(ax * ax + ay * ay + az * az);
    long double wx = ax / h, wy = ay / h, wz = az / h;
    long double dx = (long double)x.x - c->base.x, dy = (long double)x.y - c->base.y,
                dz = (long double)x.z - c->base.z;
    long double t = dx * wx + dy * wy + dz * wz;
    long double rx = dx - t * wx, ry = dy - t * wy, rz = dz - t * wz;
    long double rho = sqrtl(rx * rx + ry * ry + rz * rz);
    long double dr = rho > c->radius ? rho - c->radius : 0.0L;
    long double dt = t < 0 ? -t : (t > h ? t - h : 0.0L);
    return (double)sqrtl(dr * dr + dt * dt);
}

/* Largest absolute coordinate of a cylinder's base and top centres. */
static double coord_size(const prox_rcc *c)
{
    prox_vec3 t = prox_v3_add(c->base, c->axis);
    return fmax(prox_v3_maxabs(c->base), prox_v3_maxabs(t));
}

/* Runs the method on one reference set and checks every line against the bar. */
static void check_set(const char *method, const char *set)
{
    char pairs[512], ref[512], out[512], args[128];
    snprintf(pairs, sizeof pairs, "%s/%s.pairs", PROX_VALIDATION_DIR, set);
    snprintf(ref, sizeof ref, "%s/%s.ref", PROX_VALIDATION_DIR, set);
    snprintf(out, sizeof out, "%s/out.txt", dir);
    snprintf(args, sizeof args, "pairs --method %s", method);
    assert_int_equal(run_cli(args, pairs), 0);
    double *P, *R, *O;
    size_t n = read_table(pairs, 14, &P), m = read_table(ref, 7, &R), k = read_table(out, 7, &O);
    assert_int_equal(n, m);
    assert_int_equal(n, k);
    double worst = 0.0;
    size_t bad = 0;
    for (size_t i = 0; i < n; ++i) {
        prox_rcc a = rcc_of(P + 14 * i), b = rcc_of(P + 14 * i + 7);
        const double *r = R + 7 * i, *o = O + 7 * i;
        double S = prox_rcc_pair_scale(&a, &b);
        double tol = 1e-12 * S + 16.0 * DBL_EPSILON * fmax(coord_size(&a), coord_size(&b));
        prox_vec3 p1 = prox_v3(o[1], o[2], o[3]), p2 = prox_v3(o[4], o[5], o[6]);
        double err = fmax(outside(&a, p1), outside(&b, p2));
        if (r[0] > tol) { /* disjoint beyond the tolerance: the distance and a valid pair */
            err = fmax(err, fabs(o[0] - r[0]));
            err = fmax(err, fabs(prox_v3_dist(p1, p2) - o[0]));
        } else if (r[0] <= -tol) { /* overlapping: a common point */
            err = fmax(err, o[0]);
            err = fmax(err, prox_v3_dist(p1, p2));
        } else { /* touching within the tolerance: either answer, at most tol apart */
            err = fmax(err, fmax(o[0] - tol, 0.0));
        }
        if (err / S > worst) worst = err / S;
        if (err > tol) {
            if (bad < 5)
                print_error("%s %s line %zu: error %.3g S (ref sd %.17g, got %.17g)\n", method, set, i + 1,
                            err / S, r[0], o[0]);
            ++bad;
        }
    }
    printf("prox pairs --method %s on %s: %zu pairs, worst error %.3g S\n", method, set, n, worst);
    free(P);
    free(R);
    free(O);
    assert_int_equal(bad, 0);
}

static void test_fast(void **st)
{
    (void)st;
    check_set("fast", "paper_cases");
    check_set("fast", "agarwal_public");
    check_set("fast", "stress_public");
}

static void test_closed_form(void **st)
{
    (void)st;
    check_set("closed-form", "paper_cases");
    check_set("closed-form", "agarwal_public");
    check_set("closed-form", "stress_public");
}

static void test_support(void **st)
{
    (void)st;
    check_set("support", "paper_cases");
    check_set("support", "agarwal_public");
    check_set("support", "stress_public");
}

/* An unknown or missing method name is a usage error (exit 2), named on stderr. */
static void test_bad_method(void **st)
{
    (void)st;
    char pairs[512];
    snprintf(pairs, sizeof pairs, "%s/paper_cases.pairs", PROX_VALIDATION_DIR);
    assert_int_equal(run_cli("pairs --method gjk", pairs), 2);
    assert_int_equal(run_cli("pairs --method", pairs), 2);
    assert_int_equal(run_cli("pairs --method=closed-form", pairs), 0);
}

/* prox --version prints the library's version, which is the header's. */
static void test_version(void **st)
{
    (void)st;
    assert_int_equal(run_cli("--version", "/dev/null"), 0);
    char path[512], line[128] = {0}, want[128];
    snprintf(path, sizeof path, "%s/out.txt", dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    assert_non_null(fgets(line, sizeof line, f));
    fclose(f);
    snprintf(want, sizeof want, "prox %s\n", PROX_VERSION_STRING);
    assert_string_equal(line, want);
    assert_string_equal(prox_version(), PROX_VERSION_STRING);
}

int main(void)
{
    gsl_set_error_handler_off();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fast),       cmocka_unit_test(test_closed_form), cmocka_unit_test(test_support),
        cmocka_unit_test(test_bad_method), cmocka_unit_test(test_version),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
