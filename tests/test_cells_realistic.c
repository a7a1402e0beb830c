/* Tests of `prox check` on the forms real decks take (tests/data/decks/realistic_*.i, small
 * hand-written reproductions): densities and radii written as Fortran reals without the exponent
 * letter (4.5-2), a READ of material cards that are not there in the data block (not an error) and
 * in the cell block (an error), a universe filled into two cells whose windows map to one region
 * (checked once: the proved volume bounds stay below the exact volumes, the overlap not repeated as
 * undecided), a lattice of infinite pins
 * (checked or reported undecided, never silently clean), and a cell naming an undefined surface
 * (listed, exit 2, through the built executable). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "test_cli_util.h"
#include "prox/cellcheck.h"
#include "prox/cells.h"
#include "scene/deck_internal.h"

#define DECKS PROX_SOURCE_DIR "/tests/data/decks/"

static void read_model(const char *name, prox_cell_model *m)
{
    assert_int_equal(prox_cells_read_file(name, m), PROX_OK);
}

static size_t cell_index(const prox_cell_model *m, long number)
{
    for (size_t i = 0; i < m->ncells; ++i)
        if (m->cells[i].number == number) return i;
    fail_msg("cell %ld not found", number);
    return 0;
}

/* 4.5-2 is 4.5e-2, 5.0-1 is 0.5, 1.0+1 is 10: the cell's density as read and the sphere's surface
 * against the radius written out here, on both sides of it. */
static void test_fortran_exponent(void **state)
{
    (void)state;
    double x = 0.0;
    assert_int_equal(prox_deck_number("1.5-3", &x), 0);
    assert_true(x == 1.5e-3);
    assert_int_equal(prox_deck_number("2+2", &x), 0);
    assert_true(x == 200.0);
    assert_int_equal(prox_deck_number("-.25-1", &x), 0);
    assert_true(x == -0.025);
    assert_int_equal(prox_deck_number("2.5E+01", &x), 0);
    assert_true(x == 25.0);
    assert_int_equal(prox_deck_number("2.5d-1", &x), 0);
    assert_true(x == 0.25);
    assert_int_not_equal(prox_deck_number("1.5-", &x), 0);
    assert_int_not_equal(prox_deck_number("1.5-3-2", &x), 0);
    assert_int_not_equal(prox_deck_number("1.5e-3-2", &x), 0);

    prox_cell_model m = {0};
    read_model(DECKS "realistic_fortran_exponent.i", &m);
    assert_int_equal(m.nerrors, 0);
    const prox_cell *c1 = &m.cells[cell_index(&m, 1)], *c2 = &m.cells[cell_index(&m, 2)];
    assert_true(c1->density == 4.5e-2);
    assert_true(c2->density == -7.9);
    const double radius[2] = {0.5, 10.0};
    for (size_t s = 0; s < m.nsurfs; ++s) {
        double r = radius[m.surfs[s].number == 2];
        assert_true(prox_surf_eval(&m.surfs[s], prox_v3(0.99 * r, 0, 0)) < 0);
        assert_true(prox_surf_eval(&m.surfs[s], prox_v3(0, 1.01 * r, 0)) > 0);
    }
    prox_cells_report r = {0};
    assert_int_equal(prox_cells_check(&m, NULL, &r), PROX_OK);
    assert_int_equal(r.noverlaps + r.ngaps, 0);
    prox_cells_report_free(&r);
    prox_cells_free(&m);
}

/* A READ FILE= in the data block whose file is missing leaves the geometry whole: listed as
 * unchecked, the deck is checked. In the cell block it is an error. */
static void test_read_missing(void **state)
{
    (void)state;
    prox_cell_model m = {0};
    read_model(DECKS "realistic_read_data_block.i", &m);
    assert_int_equal(m.nerrors, 0);
    int listed = 0;
    for (size_t i = 0; i < m.nunchecked; ++i) listed |= strstr(m.unchecked[i].what, "READ") != NULL;
    assert_true(listed);
    prox_cells_report r = {0};
    assert_int_equal(prox_cells_check(&m, NULL, &r), PROX_OK);
    assert_int_equal(r.noverlaps + r.ngaps, 0);
    prox_cells_report_free(&r);
    prox_cells_free(&m);

    read_model(DECKS "realistic_read_cell_block.i", &m);
    assert_true(m.nerrors >= 1);
    prox_cells_free(&m);
}

/* Universe 5 (a sphere of radius 2 inside one of radius 3, both claimed: an overlap; nothing
 * between 3 and 5: a gap) fills two spheres of radius 5 that map to the same region. The findings
 * are named once, their witnesses check by the test's own inequalities, and the proved volume
 * bounds stay below the exact volumes (a region counted once per identical window would not). */
static void test_repeated_window(void **state)
{
    (void)state;
    prox_cell_model m = {0};
    read_model(DECKS "realistic_repeated_window.i", &m);
    assert_int_equal(m.nerrors, 0);
    prox_cells_report r = {0};
    assert_int_equal(prox_cells_check(&m, NULL, &r), PROX_OK);
    assert_int_equal(r.stats.windows, 2); /* the real world and the element, once */
    assert_int_equal(r.noverlaps, 1);
    const prox_cells_overlap *v = &r.overlaps[0];
    assert_int_equal(v->universe, 5);
    assert_true(v->cells[0] == 10 && v->cells[1] == 11);
    assert_true(prox_v3_norm(v->point) < 2.0);
    const double pi = 3.14159265358979323846;
    assert_true(v->volume_min > 0 && v->volume_min <= 4.0 / 3.0 * pi * 8.0);
    assert_int_equal(r.ngaps, 1);
    const prox_cells_gap *g = &r.gaps[0];
    double d = prox_v3_norm(g->point);
    assert_true(g->universe == 5 && d > 3.0 && d < 5.0);
    assert_true(g->volume_min > 0 && g->volume_min <= 4.0 / 3.0 * pi * (125.0 - 27.0));
    /* the rim where the overlap's spheres meet the resolution is not listed again as undecided */
    for (size_t i = 0; i < r.nundecided; ++i)
        assert_false(r.undecided[i].ncells == 2 && r.undecided[i].cells[0] == 10 && r.undecided[i].cells[1] == 11);
    prox_cells_report_free(&r);
    prox_cells_free(&m);
}

/* A lattice of infinite pins (every cell of the pin universe, and the lattice element, open along
 * z) filled into a bounded box, the fuel wider than its clad: universe 1 is either checked (the
 * overlap of cells 1 and 3 found, its witness between the radii 0.6 and 0.7) or reported undecided;
 * never a silent clean verdict. */
static void test_infinite_pin_lattice(void **state)
{
    (void)state;
    prox_cell_model m = {0};
    read_model(DECKS "realistic_infinite_pin_lattice.i", &m);
    assert_int_equal(m.nerrors, 0);
    prox_cells_report r = {0};
    assert_int_equal(prox_cells_check(&m, NULL, &r), PROX_OK);
    int found = 0, undecided = 0;
    for (size_t i = 0; i < r.noverlaps; ++i) {
        const prox_cells_overlap *v = &r.overlaps[i];
        double rho = sqrt(v->point.x * v->point.x + v->point.y * v->point.y);
        found |= v->universe == 1 && v->cells[0] == 1 && v->cells[1] == 3 && rho > 0.6 && rho < 0.7;
    }
    for (size_t i = 0; i < r.nundecided; ++i) undecided |= r.undecided[i].universe == 1;
    assert_true(found || undecided);
    assert_int_equal(r.ngaps, 0);
    prox_cells_report_free(&r);
    prox_cells_free(&m);
}

/* A cell on an undefined surface: the deck is not cell-checked, the error is named with its line
 * (in the text report; on stderr after the JSON document) and the exit status is 2. */
static void test_cli_cell_errors(void **state)
{
    (void)state;
    char *out = NULL;
    assert_int_equal(run_cli("check '" DECKS "realistic_undefined_surface.i'", &out), 2);
    assert_non_null(strstr(out, "error: line 4: cell 3: surface 7 is not defined"));
    free(out);
    assert_int_equal(run_cli("check '" DECKS "realistic_undefined_surface.i' --json", &out), 2);
    assert_null(strstr(out, "error: line 4"));
    free(out);
    assert_int_equal(run_cli("check '" DECKS "realistic_read_data_block.i'", &out), 0);
    free(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fortran_exponent),
        cmocka_unit_test(test_read_missing),
        cmocka_unit_test(test_repeated_window),
        cmocka_unit_test(test_infinite_pin_lattice),
        cmocka_unit_test(test_cli_cell_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
