/* Tests of the cell model reader (src/cells/cells_parse.c): cell cards with material and density,
 * Boolean geometry with complements of cells, LIKE n BUT, TRCL (TR number, inline, *TRCL in
 * degrees), U and FILL (with a TR number or an inline transform: windows mapped into the
 * universe's frame), lattices (one window per universe named), importances and the outside world,
 * cell parameters in the data block (horizontal and vertical input), READ files, and errors with
 * their lines. Every placement is checked by membership against the untransformed cell at points
 * mapped by a transform written out in the test. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "prox/cells.h"

static prox_cell_model parse(const char *text)
{
    prox_cell_model m = {0};
    assert_int_equal(prox_cells_parse(text, &m), PROX_OK);
    return m;
}

static void no_errors(const prox_cell_model *m)
{
    for (size_t i = 0; i < m->nerrors; ++i) print_message("error line %d: %s\n", m->errors[i].line, m->errors[i].text);
    assert_int_equal(m->nerrors, 0);
}

/* Index of cell number n (fails when absent). */
static size_t cell(const prox_cell_model *m, long n)
{
    for (size_t i = 0; i < m->ncells; ++i)
        if (m->cells[i].number == n) return i;
    print_error("cell %ld not found\n", n);
    fail();
    return 0;
}

/* 1 when some error is on `line` and contains `needle`. */
static int has_error(const prox_cell_model *m, int line, const char *needle)
{
    for (size_t i = 0; i < m->nerrors; ++i)
        if (m->errors[i].line == line && strstr(m->errors[i].text, needle)) return 1;
    for (size_t i = 0; i < m->nerrors; ++i) print_message("error line %d: %s\n", m->errors[i].line, m->errors[i].text);
    return 0;
}

/* The unchecked entry whose text is `what` (NULL when absent). */
static const prox_unchecked *unchecked(const prox_cell_model *m, const char *what)
{
    for (size_t i = 0; i < m->nunchecked; ++i)
        if (!strcmp(m->unchecked[i].what, what)) return &m->unchecked[i];
    return NULL;
}

/* The box [0,1] x [0,2] x [0,3]. */
static int in_box(prox_vec3 p) { return p.x > 0 && p.x < 1 && p.y > 0 && p.y < 2 && p.z > 0 && p.z < 3; }

static const char *DECK_PLACE =
    "cells moved by TRCL and LIKE BUT\n"
    "1 1 -7.8 -1 imp:n=1\n"
    "2 like 1 but trcl=(10 0 0) mat=2 rho=-2.5\n"
    "3 0 -1 trcl=5 imp:n=1\n"
    "4 0 -1 *trcl=(0 0 0  90 0 90  180 90 90  90 90 0) imp:n=1\n"
    "5 like 3 but imp:n=0\n"
    "6 0 -1 trcl (0 0 -20  0 1 0  -1 0 0  0 0 1) imp:n=1 vol=6 tmp=2.5e-8\n"
    "99 0 #1 #2 #3 #4 #6 -2 imp:n=1\n"
    "100 0 2 imp:n=0\n"
    "\n"
    "1 RPP 0 1 0 2 0 3\n"
    "2 SO 50\n"
    "\n"
    "tr5 0 0 20\n";

static void test_trcl_and_like(void **state)
{
    (void)state;
    prox_cell_model m = parse(DECK_PLACE);
    no_errors(&m);
    assert_string_equal(m.title, "cells moved by TRCL and LIKE BUT");
    assert_int_equal(m.ncells, 8);
    const prox_cell *c1 = &m.cells[cell(&m, 1)], *c2 = &m.cells[cell(&m, 2)];
    assert_int_equal(c1->material, 1);
    assert_near(c1->density, -7.8, 0);
    assert_int_equal(c2->material, 2);
    assert_near(c2->density, -2.5, 0);
    assert_int_equal(m.cells[cell(&m, 5)].outside, 1);
    assert_int_equal(m.cells[cell(&m, 3)].outside, 0);
    assert_int_equal(m.cells[cell(&m, 100)].outside, 1);
    assert_int_equal(m.cells[cell(&m, 1)].line, 2);
    assert_int_equal(m.cells[cell(&m, 99)].line, 8);
    test_rng r = test_rng_seed(1);
    for (int i = 0; i < 4000; ++i) {
        prox_vec3 p = prox_v3(test_range(&r, -3, 12), test_range(&r, -3, 3), test_range(&r, -25, 25));
        int b1 = in_box(p);
        int b2 = in_box(prox_v3(p.x - 10, p.y, p.z));
        int b3 = in_box(prox_v3(p.x, p.y, p.z - 20));
        int b4 = in_box(prox_v3(p.y, -p.x, p.z));       /* x' = (0,1,0), y' = (-1,0,0): r' = R^T r */
        int b6 = in_box(prox_v3(p.y, -p.x, p.z + 20));  /* the same rotation written with cosines */
        assert_int_equal(prox_cell_contains(&m, cell(&m, 1), p), b1);
        assert_int_equal(prox_cell_contains(&m, cell(&m, 2), p), b2);
        assert_int_equal(prox_cell_contains(&m, cell(&m, 3), p), b3);
        assert_int_equal(prox_cell_contains(&m, cell(&m, 4), p), b4);
        assert_int_equal(prox_cell_contains(&m, cell(&m, 5), p), b3);
        assert_int_equal(prox_cell_contains(&m, cell(&m, 6), p), b6);
        int in99 = !(b1 || b2 || b3 || b4 || b6);
        assert_int_equal(prox_cell_contains(&m, cell(&m, 99), p), in99);
        assert_int_equal(prox_cell_contains(&m, cell(&m, 100), p), 0);
    }
    /* keywords that do not shape the geometry (VOL, TMP) are read and left aside */
    assert_int_equal(m.nunchecked, 0);
    prox_cells_free(&m);
    /* unknown keywords are listed by kind with a count and their first line, not per cell */
    m = parse("unknown keywords\n1 0 -1 imp:n=1 foo=3 tmp2=1e-8\n2 0 1 imp:n=0 foo=4 bar\n3 like 2 but imp:n=1\n\n"
              "1 so 1\n\n");
    no_errors(&m);
    const prox_unchecked *u = unchecked(&m, "cell keyword FOO");
    assert_non_null(u);
    assert_int_equal(u->count, 3); /* cells 1, 2 and 3 (LIKE 2) */
    assert_int_equal(u->first_line, 2);
    assert_non_null(unchecked(&m, "cell keyword BAR"));
    assert_int_equal(m.nunchecked, 2);
    prox_cells_free(&m);
    assert_null(m.cells);
}

/* A universe filled with a transform: the window, in the universe's frame, holds y exactly when the
 * filling cell holds T(y). */
static void check_fill_window(const char *fill, prox_vec3 (*T)(prox_vec3))
{
    char deck[1024];
    snprintf(deck, sizeof deck,
             "fill\n"
             "1 0 -1 %s imp:n=1\n"
             "2 0 1 -9 imp:n=1\n"
             "3 0 9 imp:n=0\n"
             "10 0 -3 u=1 imp:n=1\n"
             "11 0 3 u=1 imp:n=1\n"
             "\n"
             "1 RCC 0 0 0  0 0 10  2\n"
             "3 SO 1\n"
             "9 SO 100\n"
             "\n"
             "tr2 5 5 5\n",
             fill);
    prox_cell_model m = parse(deck);
    no_errors(&m);
    assert_int_equal(m.nwindows, 2);
    assert_int_equal(m.windows[0].universe, 0);
    assert_int_equal(m.windows[0].nexpr, 0);
    assert_true(m.windows[0].cell == (size_t)-1);
    const prox_window *w = &m.windows[1];
    assert_int_equal(w->universe, 1);
    assert_int_equal(w->cell, cell(&m, 1));
    assert_int_equal(m.cells[cell(&m, 1)].fill, 1);
    assert_int_equal(m.cells[cell(&m, 10)].universe, 1);
    test_rng r = test_rng_seed(2);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        prox_vec3 y = prox_v3(test_range(&r, -12, 12), test_range(&r, -12, 12), test_range(&r, -12, 12));
        int e = prox_cell_contains(&m, cell(&m, 1), T(y));
        assert_int_equal(prox_region_contains(&m, w->expr, w->nexpr, y), e);
        hits += e;
    }
    assert_true(hits > 0);
    prox_cells_free(&m);
}

static prox_vec3 t_shift(prox_vec3 y) { return prox_v3(y.x + 5, y.y + 5, y.z + 5); }
static prox_vec3 t_rot(prox_vec3 y) { return prox_v3(1 - y.y, 2 + y.x, 3 + y.z); } /* o + R y, R: x->y, y->-x */

static void test_fill_windows(void **state)
{
    (void)state;
    check_fill_window("fill=1 (2)", t_shift);
    check_fill_window("fill=1 (5 5 5)", t_shift);
    check_fill_window("*fill=1 (1 2 3  90 0 90  180 90 90  90 90 0)", t_rot);
    check_fill_window("fill=1 (1 2 3  0 1 0  -1 0 0  0 0 1)", t_rot);
}

/* FILL and TRCL together: the universe follows the cell (placement = TRCL after the fill transform). */
static void test_fill_with_trcl(void **state)
{
    (void)state;
    prox_cell_model m = parse("fill and trcl\n"
                              "1 0 -1 fill=1 (2) trcl=(0 0 100) imp:n=1\n"
                              "2 0 1 imp:n=0\n"
                              "10 0 -3 u=1 imp:n=1\n"
                              "11 0 3 u=1 imp:n=1\n"
                              "\n"
                              "1 RCC 0 0 0  0 0 10  2\n"
                              "3 SO 1\n"
                              "\n"
                              "tr2 1 0 0\n");
    no_errors(&m);
    assert_int_equal(m.nwindows, 2);
    test_rng r = test_rng_seed(3);
    for (int i = 0; i < 3000; ++i) {
        prox_vec3 y = prox_v3(test_range(&r, -5, 5), test_range(&r, -5, 5), test_range(&r, -3, 13));
        prox_vec3 x = prox_v3(y.x + 1, y.y, y.z + 100);
        assert_int_equal(prox_region_contains(&m, m.windows[1].expr, m.windows[1].nexpr, y),
                         prox_cell_contains(&m, cell(&m, 1), x));
    }
    prox_cells_free(&m);
}

static const char *DECK_LATTICE = "lattice\n"
                                  "1 0 -1 fill=5 imp:n=1\n"
                                  "2 0 1 imp:n=0\n"
                                  "5 0 -2 u=5 lat=1 imp:n=1 fill=-1:1 -1:1 0:0 6 7 6 7 6 7 6 2r\n"
                                  "60 0 -4 u=6 imp:n=1\n"
                                  "61 0 4 u=6 imp:n=1\n"
                                  "70 0 -4 u=7 imp:n=1\n"
                                  "71 0 4 u=7 imp:n=1\n"
                                  "\n"
                                  "1 RPP -3 3 -3 3 -1 1\n"
                                  "2 RPP -1 1 -1 1 -1 1\n"
                                  "4 SO 0.5\n"
                                  "\n";

static void test_lattice_windows(void **state)
{
    (void)state;
    prox_cell_model m = parse(DECK_LATTICE);
    no_errors(&m);
    const prox_cell *lat = &m.cells[cell(&m, 5)];
    assert_int_equal(lat->lat, PROX_LAT_HEX);
    /* the lattice claims all space of its universe; its element (0,0,0) is the region as written */
    assert_int_equal(prox_cell_contains(&m, cell(&m, 5), prox_v3(7.5, -30, 2)), 1);
    assert_int_equal(prox_region_contains(&m, lat->elem_expr, lat->elem_nexpr, prox_v3(0.5, 0.5, 0.5)), 1);
    assert_int_equal(prox_region_contains(&m, lat->elem_expr, lat->elem_nexpr, prox_v3(1.5, 0.5, 0.5)), 0);
    /* a complement names the element, as written */
    prox_cell_model m2 = parse("complement of a lattice\n1 0 -1 #5 fill=5\n2 0 1\n5 0 -2 u=5 lat=1 fill=6\n"
                               "60 0 -4 u=6\n61 0 4 u=6\n\n1 RPP -3 3 -3 3 -1 1\n2 RPP -1 1 -1 1 -1 1\n4 SO 0.5\n\n");
    no_errors(&m2);
    assert_int_equal(prox_cell_contains(&m2, cell(&m2, 1), prox_v3(0.5, 0.5, 0.5)), 0);
    assert_int_equal(prox_cell_contains(&m2, cell(&m2, 1), prox_v3(2, 0.5, 0.5)), 1);
    assert_int_equal(m2.nwindows, 3);
    prox_cells_free(&m2);
    /* the real world, universe 5 in cell 1, and one element window for each of 6 and 7 */
    assert_int_equal(m.nwindows, 4);
    int seen6 = 0, seen7 = 0;
    for (size_t i = 1; i < m.nwindows; ++i) {
        const prox_window *w = &m.windows[i];
        if (w->universe == 5) assert_int_equal(w->cell, cell(&m, 1));
        else {
            assert_int_equal(w->cell, cell(&m, 5));
            seen6 += w->universe == 6, seen7 += w->universe == 7;
            /* the element region is the lattice cell's own region */
            test_rng r = test_rng_seed(4 + i);
            for (int k = 0; k < 500; ++k) {
                prox_vec3 y = prox_v3(test_range(&r, -2, 2), test_range(&r, -2, 2), test_range(&r, -2, 2));
                int e = fabs(y.x) < 1 && fabs(y.y) < 1 && fabs(y.z) < 1;
                assert_int_equal(prox_region_contains(&m, w->expr, w->nexpr, y), e);
            }
        }
    }
    assert_int_equal(seen6, 1);
    assert_int_equal(seen7, 1);
    prox_cells_free(&m);
    /* a fill array of the wrong size is an error on the cell's line */
    m = parse("bad lattice\n"
              "5 0 -2 u=5 lat=1 fill=-1:1 -1:1 0:0 6 7\n"
              "60 0 -4 u=6\n"
              "61 0 4 u=6\n"
              "70 0 -4 u=7\n"
              "71 0 4 u=7\n"
              "\n"
              "2 RPP -1 1 -1 1 -1 1\n"
              "4 SO 0.5\n"
              "\n");
    assert_true(has_error(&m, 2, "2 entries for 9 elements"));
    prox_cells_free(&m);
}

/* Importances and universes given in the data block, horizontally and vertically. */
static void test_data_block_parameters(void **state)
{
    (void)state;
    static const char *decks[] = {"horizontal\n1 0 -1\n2 0 1 -2\n3 0 2\n\n1 so 1\n2 so 2\n\nimp:n 1 1 0\n",
                                  "repeat\n1 0 -1\n2 0 1 -2\n3 0 2\n\n1 so 1\n2 so 2\n\nimp:n,p 1 r 0\n",
                                  "vertical\n1 0 -1\n2 0 1 -2\n3 0 2\n\n1 so 1\n2 so 2\n\n"
                                  "#   imp:n   imp:p\n1   1       1\n2   1       j\n3   0       0\nm1 1001 1\n",
                                  "vertical, cell numbers left out; a source table\n1 0 -1\n2 0 1 -2\n3 0 2\n\n"
                                  "1 so 1\n2 so 2\n\n#  imp:n\n   1\n   1\n   0\nsdef erg=d1\n# si1 sp1\n1 0.5\n2 0.5\n"};
    for (size_t d = 0; d < 4; ++d) {
        prox_cell_model m = parse(decks[d]);
        no_errors(&m);
        assert_int_equal(m.cells[cell(&m, 1)].outside, 0);
        assert_int_equal(m.cells[cell(&m, 2)].outside, 0);
        assert_int_equal(m.cells[cell(&m, 3)].outside, 1);
        assert_int_equal(m.nunchecked, 0);
        prox_cells_free(&m);
    }
    prox_cell_model m = parse("both\n1 0 -1 imp:n=1\n2 0 1 imp:n=0\n\n1 so 1\n\nimp:n 1 0\n");
    assert_true(has_error(&m, 7, "both on the cell card and in the data block"));
    prox_cells_free(&m);
    m = parse("universe by data\n1 0 -1 fill=1\n2 0 1\n3 0 -2\n4 0 2\n\n1 so 1\n2 so 0.5\n\nu 0 0 1 1\n");
    no_errors(&m);
    assert_int_equal(m.cells[cell(&m, 3)].universe, 1);
    assert_int_equal(m.nwindows, 2);
    prox_cells_free(&m);
}

static void test_errors_and_unchecked(void **state)
{
    (void)state;
    prox_cell_model m = parse("errors\n"
                              "1 0 -1 -7 imp:n=1\n"   /* 2: surface 7 missing */
                              "2 0 -5 imp:n=1\n"      /* 3: surface of an unknown kind */
                              "3 0 (-1 2 imp:n=1\n"   /* 4: missing ')' */
                              "4 0 #42\n"             /* 5: no cell 42 */
                              "5 like 77 but u=1\n"   /* 6: no cell 77 */
                              "6 0 -1.4\n"            /* 7: SO has no facets */
                              "7 0 -1 fill=3\n"       /* 8: universe 3 has no cells */
                              "8 0 -1 trcl=9\n"       /* 9: no TR9 */
                              "6 0 1\n"               /* 10: cell 6 again */
                              "\n"
                              "1 so 1\n"
                              "2 pz 0\n"
                              "5 XYZ 1 2\n"           /* 14 */
                              "6 PX\n"                /* 15: no entries */
                              "8 rpp 0 1 0 1 1 0\n"   /* 16: zmin > zmax */
                              "9 2 px 1\n"            /* 17: no TR2 */
                              "5 so 2\n"              /* 18: surface 5 again */
                              "\n");
    assert_true(has_error(&m, 2, "surface 7 is not defined"));
    assert_true(has_error(&m, 4, "missing ')'"));
    assert_true(has_error(&m, 5, "#42"));
    assert_true(has_error(&m, 6, "LIKE 77"));
    assert_true(has_error(&m, 7, "no facet 4"));
    assert_true(has_error(&m, 8, "universe 3"));
    assert_true(has_error(&m, 9, "TR9"));
    assert_true(has_error(&m, 10, "cell 6 is already defined on line 7"));
    assert_true(has_error(&m, 15, "6 PX: needs 1 entries, has 0"));
    assert_true(has_error(&m, 16, "8 RPP"));
    assert_true(has_error(&m, 17, "TR2"));
    assert_true(has_error(&m, 18, "surface 5 is already defined on line 14"));
    const prox_unchecked *u = unchecked(&m, "surface card XYZ");
    assert_non_null(u);
    assert_int_equal(u->count, 1);
    assert_int_equal(u->first_line, 14);
    /* the cell using it is kept, marked unchecked, and claims nothing */
    const prox_cell *c2 = &m.cells[cell(&m, 2)];
    assert_true(c2->unchecked);
    assert_true(c2->nexpr > 0);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 2), prox_v3(0, 0, 0)), 0);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 2), prox_v3(1e3, -7, 2)), 0);
    assert_true(m.cells[cell(&m, 1)].unchecked); /* its geometry has an error: it claims nothing either */
    assert_int_equal(prox_cell_contains(&m, cell(&m, 1), prox_v3(0, 0, 0)), 0);
    prox_cells_free(&m);
    /* bad arguments */
    assert_int_equal(prox_cells_parse(NULL, &m), PROX_EINVAL_ARG);
    assert_int_equal(prox_cells_parse("x", NULL), PROX_EINVAL_ARG);
    assert_int_equal(prox_cells_read_file(NULL, &m), PROX_EINVAL_ARG);
    prox_cells_free(NULL);
}

/* A void cell with no surfaces is all space; continuation lines and comments are read as in the
 * deck reader. */
static void test_card_format(void **state)
{
    (void)state;
    prox_cell_model m = parse("format\n"
                              "c a comment card\n"
                              "1 0 -1 2 $ inside the sphere,\n"
                              "     -3 imp:n=1 $ continued by five blanks\n"
                              "2 0 #1 &\n"
                              "   imp:n=1\n"
                              "3 0 imp:n=1\n"
                              "\n"
                              "1 so 5\n"
                              "2 pz 0\n"
                              "3 pz 2\n"
                              "\n");
    no_errors(&m);
    assert_int_equal(m.ncells, 3);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 1), prox_v3(0, 0, 1)), 1);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 1), prox_v3(0, 0, 3)), 0);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 2), prox_v3(0, 0, 3)), 1);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 3), prox_v3(1e6, 0, 0)), 1);
    prox_cells_free(&m);
}

/* Precedence: complement, then intersection, then union; juxtaposed groups intersect. */
static void test_precedence(void **state)
{
    (void)state;
    prox_cell_model m = parse("precedence\n"
                              "1 0 -1 -2:3\n"
                              "2 0 -1 (-2:3)\n"
                              "3 0 (-1)(-2:3)#(4)\n"
                              "4 0 -1:-2 -3\n"
                              "\n1 px 1\n2 py 1\n3 pz 1\n4 so 0.5\n\n");
    no_errors(&m);
    test_rng r = test_rng_seed(9);
    for (int i = 0; i < 3000; ++i) {
        prox_vec3 p = prox_v3(test_range(&r, -2, 3), test_range(&r, -2, 3), test_range(&r, -2, 3));
        int a = p.x < 1, b = p.y < 1, c = p.z < 1, s = p.x * p.x + p.y * p.y + p.z * p.z < 0.25;
        assert_int_equal(prox_cell_contains(&m, 0, p), (a && b) || !c);
        assert_int_equal(prox_cell_contains(&m, 1, p), a && (b || !c));
        assert_int_equal(prox_cell_contains(&m, 2, p), a && (b || !c) && s); /* #(4): not outside the sphere */
        assert_int_equal(prox_cell_contains(&m, 3, p), a || (b && c));
    }
    prox_cells_free(&m);
}

/* Cell parameters in the data block (U, FILL, TRCL, LAT), U=-n, and a hexagonal-prism lattice. */
static void test_more_parameters(void **state)
{
    (void)state;
    prox_cell_model m = parse("data-block placement\n"
                              "1 0 -1\n"
                              "2 0 1\n"
                              "3 0 -2\n"
                              "4 0 2\n"
                              "5 0 -3\n"
                              "\n1 so 10\n2 so 1\n3 rhp 0 0 -1  0 0 2  1 0 0\n\n"
                              "u 0 0 -7 7 0\n"
                              "fill 7 0 3j\n"
                              "trcl 0 0 5 0 0\n"
                              "lat 4j 2\n"
                              "tr5 0 0 3\n");
    no_errors(&m);
    assert_int_equal(m.cells[cell(&m, 3)].universe, 7);
    assert_int_equal(m.cells[cell(&m, 1)].fill, 7);
    assert_int_equal(m.cells[cell(&m, 5)].lat, PROX_LAT_HEXPRISM);
    /* cell 3 is moved up by TR5 */
    assert_int_equal(prox_cell_contains(&m, cell(&m, 3), prox_v3(0, 0, 3.5)), 1);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 3), prox_v3(0, 0, 0)), 0);
    /* cell 5 is a hexagonal-prism lattice with no fill: its element is the prism, it claims all space */
    const prox_cell *h = &m.cells[cell(&m, 5)];
    assert_int_equal(prox_cell_contains(&m, cell(&m, 5), prox_v3(50, 0, 0)), 1);
    assert_int_equal(prox_region_contains(&m, h->elem_expr, h->elem_nexpr, prox_v3(0.9, 0, 0.5)), 1);
    assert_int_equal(prox_region_contains(&m, h->elem_expr, h->elem_nexpr, prox_v3(0.9, 0.8, 0.5)), 0); /* beyond the 60-degree side */
    assert_int_equal(m.nwindows, 2);
    prox_cells_free(&m);
}

/* A deck read from a file that brings its surfaces in with READ. */
static void test_read_file(void **state)
{
    (void)state;
    prox_cell_model m = {0};
    assert_int_equal(prox_cells_read_file(PROX_VALIDATION_DIR "/decks/cells_main.i", &m), PROX_OK);
    no_errors(&m);
    assert_int_equal(m.ncells, 3);
    assert_true(m.nsurfs >= 8);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 1), prox_v3(0, 0, 5)), 1);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 2), prox_v3(0, 0, 5)), 0);
    assert_int_equal(prox_cell_contains(&m, cell(&m, 2), prox_v3(0, 0, 20)), 1);
    prox_cells_free(&m);
    /* an error in an included file: on the READ card's line, naming the file and its own line */
    assert_int_equal(prox_cells_read_file(PROX_VALIDATION_DIR "/decks/cells_bad_main.i", &m), PROX_OK);
    assert_true(has_error(&m, 6, "cells_bad_surfaces.i' line 2: surface 11 RCC: needs 7 entries, has 6"));
    assert_true(has_error(&m, 6, "cells_bad_surfaces.i' line 3: surface 12 C/Z"));
    assert_true(has_error(&m, 3, "cell 2: surface 13 is not defined"));
    prox_cells_free(&m);
    assert_int_equal(prox_cells_read_file(PROX_VALIDATION_DIR "/decks/no_such_deck.i", &m), PROX_OK);
    assert_true(m.nerrors == 1 && m.errors[0].line == 0);
    prox_cells_free(&m);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_trcl_and_like),        cmocka_unit_test(test_fill_windows),
        cmocka_unit_test(test_fill_with_trcl),       cmocka_unit_test(test_lattice_windows),
        cmocka_unit_test(test_data_block_parameters), cmocka_unit_test(test_errors_and_unchecked),
        cmocka_unit_test(test_card_format),          cmocka_unit_test(test_read_file),
        cmocka_unit_test(test_precedence),           cmocka_unit_test(test_more_parameters),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
