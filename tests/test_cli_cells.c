/* Tests of `prox check` on cells and of `prox plot` (src/cli/check.c, plot.c) through the built
 * executable (PROX_CLI_PATH): exit codes 0 / 1 / 2, the JSON document (overlaps, gaps, undecided,
 * unchecked), --bodies, --strict, --resolution, and the PNG of a slice. The overlap witness on the
 * bundled deck is checked independently against the deck's bodies (lug inside, shell between its
 * outer and inner cylinders) with the body-level distance queries. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test_cli_util.h"
#include "prox/deck.h"
#include "prox/query.h"

#define EXAMPLE PROX_SOURCE_DIR "/examples/cask.mcnp"

/* prox plot under the sanitizers: fontconfig (through cairo's text) keeps caches to the end of the
 * process, which LeakSanitizer reports; they are the system library's, not prox's. */
static int run_plot(const char *args, char **out) { return run_cli_env("ASAN_OPTIONS=detect_leaks=0", args, out); }

/* Whether point x lies in the body of surface `surf` of the deck (distance from a tiny sphere 0). */
static int in_body(const prox_deck *d, long surf, prox_vec3 x)
{
    for (size_t i = 0; i < d->nbodies; ++i) {
        if (d->bodies[i].surface != surf) continue;
        prox_shape p = prox_shape_from_sph((prox_sph){x, 1e-9});
        prox_distance_result r = prox_shape_distance(&p, &d->bodies[i].shape);
        assert_int_equal(r.status, PROX_OK);
        return r.distance == 0.0;
    }
    fail_msg("no body %ld", surf);
    return 0;
}

/* The bundled deck: one overlap, cells 1 (shell) and 8 (lug); the witness is in both solids. */
static void example_overlap(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char *out;
    assert_int_equal(run_cli("check '" EXAMPLE "' --json", &out), 1);
    assert_non_null(strstr(out, "\"check\": \"cells\""));
    assert_int_equal(count(out, "{\"cells\": ["), 1);
    assert_non_null(strstr(out, "{\"cells\": [1, 8], \"universe\": 0, \"point\": ["));
    assert_non_null(strstr(out, "\"gaps\": [\n  ]"));
    assert_non_null(strstr(out, "\"undecided\": ["));
    assert_non_null(strstr(out, "\"unchecked\": ["));
    assert_non_null(strstr(out, "\"volume_min\": "));
    prox_vec3 x = json_vec_after(out, "\"point\":");
    prox_deck d = {0};
    assert_int_equal(prox_deck_read_file(EXAMPLE, &d), PROX_OK);
    assert_true(in_body(&d, 50, x));  /* the lug */
    assert_true(in_body(&d, 10, x));  /* the shell's outer cylinder ... */
    assert_false(in_body(&d, 11, x)); /* ... outside the liner */
    prox_deck_free(&d);
    free(out);
    /* The table. */
    assert_int_equal(run_cli("check '" EXAMPLE "'", &out), 1);
    assert_non_null(strstr(out, "overlapping cells:"));
    assert_non_null(strstr(out, "1 and 8"));
    assert_non_null(strstr(out, "1 overlapping cell pair, 0 gaps, 0 undecided"));
    free(out);
}

/* --bodies: the body-level report of the bodies the cells use; --clearance and --all imply it. */
static void bodies_mode(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char *out;
    assert_int_equal(run_cli("check '" EXAMPLE "' --bodies --json", &out), 1);
    assert_non_null(strstr(out, "\"pairs\": ["));
    assert_int_equal(count(out, "\"relation\": \"crossing\""), 1);
    assert_int_equal(count(out, "\"surface\":"), 11);
    assert_null(strstr(out, "\"overlaps\""));
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --all --json", &out), 1);
    assert_int_equal(count(out, "\"relation\""), 55);
    free(out);
    /* A body no cell uses is left out. */
    char path[64], args[256];
    temp_deck("unused body\n1 0 -1 imp:n=1\n2 0 1 imp:n=0\n\n1 SO 5\n2 SO 50\n\n", path);
    snprintf(args, sizeof args, "check %s --bodies --json", path);
    assert_int_equal(run_cli(args, &out), 0);
    assert_int_equal(count(out, "\"surface\":"), 1);
    free(out);
    unlink(path);
}

/* Two slabs sharing a plane, clean; then the second cell removed: a gap there. */
static void clean_and_gap(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char path[64], args[256], *out;
    temp_deck("two slabs\n1 0 -1 -3 imp:n=1\n2 0 -1 3 imp:n=1\n3 0 1 imp:n=0\n\n1 RPP 0 20 0 10 0 10\n3 PX 10\n\n", path);
    snprintf(args, sizeof args, "check %s --json", path);
    assert_int_equal(run_cli(args, &out), 0);
    assert_non_null(strstr(out, "\"overlaps\": [\n  ]"));
    assert_non_null(strstr(out, "\"gaps\": [\n  ]"));
    free(out);
    unlink(path);
    temp_deck("one slab gone\n1 0 -1 -3 imp:n=1\n3 0 1 imp:n=0\n\n1 RPP 0 20 0 10 0 10\n3 PX 10\n\n", path);
    snprintf(args, sizeof args, "check %s --json", path);
    assert_int_equal(run_cli(args, &out), 1);
    assert_int_equal(count(out, "\"window_cell\":"), 1);
    prox_vec3 x = json_vec_after(out, "\"window_cell\": 0, \"point\":");
    assert_true(x.x > 10 && x.x < 20 && x.y > 0 && x.y < 10 && x.z > 0 && x.z < 10);
    free(out);
    snprintf(args, sizeof args, "check %s", path);
    assert_int_equal(run_cli(args, &out), 1);
    assert_non_null(strstr(out, "gaps (points in no cell):"));
    free(out);
    unlink(path);
}

/* --strict: a card the reader does not model is an error; without it, listed once with a count. */
static void strict_unchecked(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char path[64], args[256], *out;
    temp_deck("unchecked\n1 0 -1 imp:n=1 zzz=1\n2 0 -1 imp:n=1 zzz=2\n3 0 1 imp:n=0\n\n1 SO 5\n\n", path);
    snprintf(args, sizeof args, "check %s --json", path);
    int code = run_cli(args, &out);
    if (!strstr(out, "\"unchecked\": [\n  ]")) { /* the reader lists the keyword as unchecked */
        assert_int_equal(count(out, "\"what\":"), 1);
        assert_non_null(strstr(out, "\"count\": 2"));
        free(out);
        snprintf(args, sizeof args, "check %s --strict", path);
        assert_int_equal(run_cli(args, &out), 2);
    }
    (void)code;
    free(out);
    unlink(path);
}

/* Input errors: exit 2. */
static void input_errors(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char *out;
    assert_int_equal(run_cli("check /nonexistent/deck.mcnp --json", &out), 2);
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --resolution 0", &out), 2);
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --resolution abc", &out), 2);
    free(out);
    assert_int_equal(run_cli("check '" EXAMPLE "' --threads 0", &out), 2);
    free(out);
    char path[64], args[256];
    temp_deck("bad\n1 0 -1 imp:n=1\n\n1 RCC 0 0 0 0 0 1\n\n", path);
    snprintf(args, sizeof args, "check %s --json", path);
    assert_int_equal(run_cli(args, &out), 2); /* not cell-checked: the body report with the error */
    assert_non_null(strstr(out, "\"errors\": [\n    {\"line\": 4"));
    assert_null(strstr(out, "\"overlaps\""));
    free(out);
    unlink(path);
    /* A finer resolution runs and finds the same pair. */
    assert_int_equal(run_cli("check '" EXAMPLE "' --json --resolution 0.05 --threads 1", &out), 1);
    assert_non_null(strstr(out, "\"resolution\": 0.05"));
    assert_non_null(strstr(out, "{\"cells\": [1, 8]"));
    free(out);
}

/* prox plot: a PNG of a slice; bad planes are errors. */
static void plot_slice(void **state)
{
    (void)state;
    if (!have_cli()) skip();
    char *out, args[512];
    const char *png = "/tmp/prox_test_cells_slice.png";
    unlink(png);
    snprintf(args, sizeof args, "plot '" EXAMPLE "' --slice y=0 --extent -70,70,-20,180 --width 200 -o %s", png);
    int code = run_plot(args, &out);
    free(out);
    if (code == 2) { /* built without cairo: the command must say so, and write nothing */
        assert_int_equal(access(png, F_OK), -1);
        return;
    }
    assert_int_equal(code, 0);
    FILE *f = fopen(png, "rb");
    assert_non_null(f);
    unsigned char magic[8];
    assert_int_equal(fread(magic, 1, 8, f), 8);
    fclose(f);
    assert_memory_equal(magic, "\x89PNG\r\n\x1a\n", 8);
    unlink(png);
    snprintf(args, sizeof args, "plot '" EXAMPLE "' --plane 0,0,0,1,1,1,2,2,2 -o %s", png);
    assert_int_equal(run_plot(args, &out), 2); /* three points on a line */
    free(out);
    assert_int_equal(run_plot("plot '" EXAMPLE "' --slice w=3", &out), 2);
    free(out);
    assert_int_equal(run_plot("plot '" EXAMPLE "'", &out), 2);
    free(out);
}

int main(void)
{
    gsl_set_error_handler_off();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(example_overlap), cmocka_unit_test(bodies_mode),  cmocka_unit_test(clean_and_gap),
        cmocka_unit_test(strict_unchecked), cmocka_unit_test(input_errors), cmocka_unit_test(plot_slice),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
