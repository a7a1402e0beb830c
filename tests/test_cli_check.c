/* Tests of `prox check` (src/cli/check.c) through the built executable (PROX_CLI_PATH): exit codes
 * 0 / 1 / 2, the JSON document on the bundled example deck (bodies, pairs, errors, unsupported),
 * --clearance and --all, and bad decks and options. The crossing pair's repositioning vector is
 * checked independently: moving the body by it must leave the pair touching. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test_cli_util.h"
#include "prox/deck.h"
#include "prox/query.h"

#define EXAMPLE PROX_SOURCE_DIR "/examples/cask.mcnp"

static void test_check_example_json(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char *out;
    assert_int_equal(run_cli("check '" EXAMPLE "' --bodies --json", &out), 1);
    assert_int_equal(count(out, "\"surface\":"), 11);
    assert_non_null(strstr(out, "{\"surface\": 50, \"type\": \"RCC\", \"line\": 27}"));
    assert_int_equal(count(out, "\"relation\": \"crossing\""), 1);
    assert_int_equal(count(out, "\"relation\": \"touching\""), 3);
    assert_int_equal(count(out, "\"relation\": \"disjoint\""), 0);
    assert_non_null(strstr(out, "{\"a\": 31, \"b\": 32, \"relation\": \"nested\""));
    assert_non_null(strstr(out, "\"inner\": 32"));
    assert_non_null(strstr(out, "{\"line\": 31, \"card\": \"70 PZ\"}"));
    assert_non_null(strstr(out, "\"errors\": [\n  ]"));
    /* The reposition of the lug (b = 50) against the shell (a = 10) makes them touch. */
    const char *pair = strstr(out, "{\"a\": 10, \"b\": 50, \"relation\": \"crossing\"");
    assert_non_null(pair);
    prox_vec3 t = json_vec_after(pair, "\"reposition\"");
    prox_deck d = {0};
    assert_int_equal(prox_deck_read_file(EXAMPLE, &d), PROX_OK);
    const prox_shape *shell = NULL, *lug = NULL;
    for (size_t i = 0; i < d.nbodies; ++i) {
        if (d.bodies[i].surface == 10) shell = &d.bodies[i].shape;
        if (d.bodies[i].surface == 50) lug = &d.bodies[i].shape;
    }
    assert_non_null(shell);
    assert_non_null(lug);
    assert_true(prox_shape_signed_distance(shell, lug).sd < -1.0);
    prox_shape moved = test_translate(lug, t);
    assert_near(prox_shape_signed_distance(shell, &moved).sd, 0, 1e-9 * 100);
    prox_deck_free(&d);
    free(out);
}

static void test_check_clearance_and_all(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char *out;
    assert_int_equal(run_cli("check '" EXAMPLE "' --json --clearance 8", &out), 1);
    assert_non_null(strstr(out, "{\"a\": 10, \"b\": 41, \"relation\": \"disjoint\", \"distance\": 7,"));
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --json --clearance 6.5", &out), 1);
    assert_null(strstr(out, "\"b\": 41, \"relation\": \"disjoint\""));
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --json --all", &out), 1);
    assert_int_equal(count(out, "\"relation\""), 55); /* 11 bodies: every pair */
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --bodies", &out), 1); /* the table */
    assert_non_null(strstr(out, "crossing"));
    assert_non_null(strstr(out, "1 crossing pair\n"));
    assert_non_null(strstr(out, "unsupported: line 31: 70 PZ"));
    free(out);
}

static void test_check_clean_deck(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char path[64], args[128], *out;
    temp_deck("two spheres, \"quoted\" title\n1 0 -1 -2 -3\n\n1 SO 1\n2 SX 2 1\n3 SX 2.5 1e-1\n\nnps 1\n", path);
    snprintf(args, sizeof args, "check %s --bodies --json", path);
    assert_int_equal(run_cli(args, &out), 0);
    assert_non_null(strstr(out, "\"title\": \"two spheres, \\\"quoted\\\" title\""));
    assert_int_equal(count(out, "\"relation\": \"touching\""), 1); /* 1 and 2 touch at x = 1 */
    assert_non_null(strstr(out, "{\"a\": 2, \"b\": 3, \"relation\": \"nested\""));
    free(out);
    snprintf(args, sizeof args, "check %s --bodies", path);
    assert_int_equal(run_cli(args, &out), 0);
    assert_non_null(strstr(out, "0 crossing pairs"));
    free(out);
    unlink(path);
}

static void test_check_bad_input(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char path[64], args[128], *out;
    temp_deck("bad\n1 0 -1\n\n1 SO 1\n2 RCC 0 0 0 0 0 1\n3 SO 0.5\n\n", path);
    snprintf(args, sizeof args, "check %s --json", path);
    assert_int_equal(run_cli(args, &out), 2);
    assert_non_null(strstr(out, "{\"line\": 5, \"message\": \"surface 2 RCC: needs 7 entries, has 6\"}"));
    assert_non_null(strstr(out, "\"inner\": 3")); /* the good bodies are still checked */
    free(out);
    unlink(path);
    assert_int_equal(run_cli("check /nonexistent/deck.mcnp --json", &out), 2);
    assert_non_null(strstr(out, "cannot read"));
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --clearance -1", &out), 2);
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --bogus", &out), 2);
    free(out);
    assert_int_equal(run_cli("check", &out), 2);
    free(out);
    assert_int_equal(run_cli("check --help", &out), 0);
    assert_non_null(strstr(out, "usage: prox check"));
    free(out);
}

/* A deck whose blank line right after the title empties its cell and surface blocks is an input
 * error, never a clean verdict on nothing; a bare NONU card (fission as capture in every cell) is
 * no error. */
static void test_check_empty_blocks_and_bare_nonu(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char path[64], args[128], *out;
    temp_deck("no cells\n\nc none\n\nmode n\nnps 10\n", path);
    snprintf(args, sizeof args, "check %s", path);
    assert_int_equal(run_cli(args, &out), 2);
    assert_non_null(strstr(out, "no cell and no surface cards"));
    free(out);
    unlink(path);
    temp_deck("bare nonu\n1 0 -1 imp:n=1\n2 0 1 imp:n=0\n\n1 SO 1\n\nnonu\n", path);
    snprintf(args, sizeof args, "check %s --threads 1", path);
    assert_int_equal(run_cli(args, &out), 0);
    assert_non_null(strstr(out, "0 overlapping cell pairs, 0 gaps, 0 undecided"));
    free(out);
    unlink(path);
}

/* A sphere crossing an axis-aligned cylinder sideways: the repositioning vector has exact zero
 * components that the solver may produce as -0; neither the table nor the JSON prints "-0". */
static void test_check_no_negative_zero(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char path[64], args[128], *out;
    temp_deck("minus zero\n1 0 -1\n\n1 RCC 0 0 0 0 0 1 0.2\n2 SPH 0 0.4 0.5 0.3\n3 BOX 0 0 0 1 0 0 0 1 0 0 0 1\n\n",
              path);
    snprintf(args, sizeof args, "check %s", path);
    assert_int_equal(run_cli(args, &out), 1);
    assert_null(strstr(out, "-0,"));
    assert_null(strstr(out, "-0)"));
    free(out);
    snprintf(args, sizeof args, "check %s --json", path);
    assert_int_equal(run_cli(args, &out), 1);
    assert_null(strstr(out, "-0,"));
    assert_null(strstr(out, "-0]"));
    free(out);
    unlink(path);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_check_example_json),
        cmocka_unit_test(test_check_clearance_and_all),
        cmocka_unit_test(test_check_clean_deck),
        cmocka_unit_test(test_check_bad_input),
        cmocka_unit_test(test_check_no_negative_zero),
        cmocka_unit_test(test_check_empty_blocks_and_bare_nonu),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
