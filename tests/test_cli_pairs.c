/* prox pairs: malformed lines are reported with their line number and reason, the other lines are
 * still answered in order, comments produce nothing, and the exit status tells an error happened. */
#define _POSIX_C_SOURCE 200809L
#include "test_util.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[256];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/prox_cli_pairs_%ld", (long)getpid());
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

/* Runs `prox pairs ARGS < input`; returns the exit status; stdout and stderr land in files. */
static int run_pairs(const char *args, const char *input)
{
    char path[512], cmd[1024];
    snprintf(path, sizeof path, "%s/in.txt", dir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(input, f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "'%s' pairs %s < %s/in.txt > %s/out.txt 2> %s/err.txt", PROX_CLI_PATH, args, dir,
             dir, dir);
    int rc = system(cmd);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static char *slurp(const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

static int count_lines(const char *s)
{
    int n = 0;
    for (; *s; ++s) n += *s == '\n';
    return n;
}

static void test_cli_pairs_good(void **state)
{
    (void)state;
    int rc = run_pairs("", "# comment\n\n0 0 0 0 0 4 1  3 0 0 0 0 4 1\n0 0 0 0 0 4 1  0 0 5 0 0 4 1\n");
    assert_int_equal(rc, 0);
    char *out = slurp("out.txt");
    assert_int_equal(count_lines(out), 2);
    double v[7];
    assert_int_equal(sscanf(out, "%lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6]), 7);
    assert_near(v[0], 1.0, 1e-15);
    rc = run_pairs("--test", "0 0 0 0 0 4 1  3 0 0 0 0 4 1\n0 0 0 0 0 4 1  1 0 0 0 0 4 1\n");
    assert_int_equal(rc, 0);
    assert_string_equal(slurp("out.txt"), "0\n1\n");
    rc = run_pairs("--time", "0 0 0 0 0 4 1  3 0 0 0 0 4 1\n");
    assert_int_equal(rc, 0);
    assert_non_null(strstr(slurp("err.txt"), "time_ns_per_pair "));
}

static void test_cli_pairs_malformed(void **state)
{
    (void)state;
    const char *in = "0 0 0 0 0 4 1  3 0 0 0 0 4 1\n"       /* 1 ok */
                     "0 0 0 0 0 4 1  3 0 0 0 0 4\n"         /* 2 thirteen numbers */
                     "0 0 0 0 0 4 1  3 0 x 0 0 4 1\n"       /* 3 not a number */
                     "0 0 0 0 0 0 1  3 0 0 0 0 4 1\n"       /* 4 zero axis */
                     "0 0 0 0 0 4 1  3 0 0 0 0 4 -2\n"      /* 5 negative radius */
                     "0 0 0 0 0 4 nan  3 0 0 0 0 4 1\n"     /* 6 NaN */
                     "0 0 0 0 0 4 1  3 0 0 0 0 4 1 7\n"     /* 7 fifteen numbers */
                     "0 0 0 0 0 4 1  5 0 0 0 0 4 1\n";      /* 8 ok */
    int rc = run_pairs("", in);
    assert_int_equal(rc, 1);
    char *out = slurp("out.txt");
    assert_int_equal(count_lines(out), 2);
    char *err = slurp("err.txt");
    assert_non_null(strstr(err, "line 2: expected 14 numbers"));
    assert_non_null(strstr(err, "line 3: field 10 is not a number"));
    assert_non_null(strstr(err, "line 4: cylinder A"));
    assert_non_null(strstr(err, "zero length"));
    assert_non_null(strstr(err, "line 5: cylinder B"));
    assert_non_null(strstr(err, "radius must be positive"));
    assert_non_null(strstr(err, "line 6: cylinder A"));
    assert_non_null(strstr(err, "NaN"));
    assert_non_null(strstr(err, "line 7: expected 14 numbers"));
    assert_null(strstr(err, "line 1:"));
    assert_null(strstr(err, "line 8:"));
}

static void test_cli_pairs_bad_option(void **state)
{
    (void)state;
    assert_int_equal(run_pairs("--bogus", ""), 2);
    assert_non_null(strstr(slurp("err.txt"), "unknown option"));
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cli_pairs_good),
        cmocka_unit_test(test_cli_pairs_malformed),
        cmocka_unit_test(test_cli_pairs_bad_option),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
