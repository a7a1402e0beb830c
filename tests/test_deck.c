/* Tests of the MCNP deck reader (src/scene/deck.c): block structure, comments, continuations,
 * shorthands, every supported surface card, TRn / *TRn placement (checked against an independent
 * rotation built in the test), that every bad or unsupported card is reported with its line, and
 * READ cards (files written to a fresh temp dir under /tmp: surface, cell and data blocks, nesting,
 * missing files, cycles; prox_deck_parse reports READ as unsupported). */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, rmdir */
#include <stdlib.h>
#include <string.h>

#include <unistd.h>
#include <sys/stat.h>

#include "test_util.h"
#include "prox/deck.h"

/* Parses text into a fresh deck; the parse itself must succeed. */
static prox_deck parse(const char *text)
{
    prox_deck d = {0};
    assert_int_equal(prox_deck_parse(text, &d), PROX_OK);
    return d;
}

/* The body with surface number j (fails when absent). */
static const prox_deck_body *body(const prox_deck *d, long j)
{
    for (size_t i = 0; i < d->nbodies; ++i)
        if (d->bodies[i].surface == j) return &d->bodies[i];
    print_error("surface %ld not found\n", j);
    fail();
    return NULL;
}

/* 1 when some error is on `line` and contains `needle`. */
static int has_error(const prox_deck *d, int line, const char *needle)
{
    for (size_t i = 0; i < d->nerrors; ++i)
        if (d->errors[i].line == line && strstr(d->errors[i].text, needle)) return 1;
    for (size_t i = 0; i < d->nerrors; ++i) print_message("error line %d: %s\n", d->errors[i].line, d->errors[i].text);
    return 0;
}

static void assert_vec(prox_vec3 a, prox_vec3 e, double tol)
{
    assert_near(a.x, e.x, tol);
    assert_near(a.y, e.y, tol);
    assert_near(a.z, e.z, tol);
}

static void test_deck_blocks_and_every_body(void **state)
{
    (void)state;
    prox_deck d = parse("Title card: all bodies\n"
                        "1 0 -1\n"
                        "2 0 1\n"
                        "\n"
                        "1 RCC 0 0 0  0 0 10  2\n"
                        "2 box 1 2 3  1 0 0  0 2 0  0 0 3\n"
                        "3 RpP -1 1 -2 2 -3 3\n"
                        "4 SPH 1 1 1 0.5\n"
                        "5 so 7\n"
                        "6 S 1 2 3 4\n"
                        "7 sx 5 1\n"
                        "8 SY -5 2\n"
                        "9 SZ 2.5E+01 1e-3\n"
                        "\n"
                        "mode n\n"
                        "nps 10\n");
    assert_string_equal(d.title, "Title card: all bodies");
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(d.nunsupported, 0);
    assert_int_equal(d.nbodies, 9);
    const prox_deck_body *b = body(&d, 1);
    assert_int_equal(b->shape.kind, PROX_SHAPE_RCC);
    assert_string_equal(b->card, "RCC");
    assert_int_equal(b->line, 5);
    assert_vec(b->shape.u.rcc.axis, prox_v3(0, 0, 10), 0);
    assert_near(b->shape.u.rcc.radius, 2, 0);
    b = body(&d, 2);
    assert_int_equal(b->shape.kind, PROX_SHAPE_BOX);
    assert_string_equal(b->card, "BOX");
    assert_vec(b->shape.u.box.corner, prox_v3(1, 2, 3), 0);
    assert_vec(b->shape.u.box.edge[2], prox_v3(0, 0, 3), 0);
    b = body(&d, 3);
    assert_int_equal(b->shape.kind, PROX_SHAPE_RPP);
    assert_near(b->shape.u.rpp.zmin, -3, 0);
    b = body(&d, 5);
    assert_int_equal(b->shape.kind, PROX_SHAPE_SPH);
    assert_vec(b->shape.u.sph.center, prox_v3(0, 0, 0), 0);
    assert_near(b->shape.u.sph.radius, 7, 0);
    assert_vec(body(&d, 6)->shape.u.sph.center, prox_v3(1, 2, 3), 0);
    assert_vec(body(&d, 7)->shape.u.sph.center, prox_v3(5, 0, 0), 0);
    assert_vec(body(&d, 8)->shape.u.sph.center, prox_v3(0, -5, 0), 0);
    assert_vec(body(&d, 9)->shape.u.sph.center, prox_v3(0, 0, 25), 0);
    assert_near(body(&d, 9)->shape.u.sph.radius, 1e-3, 0);
    assert_int_equal(body(&d, 9)->line, 13);
    prox_deck_free(&d);
    assert_null(d.bodies);
}

static void test_deck_comments_and_continuations(void **state)
{
    (void)state;
    prox_deck d = parse("message: inp=foo\n"
                        "   more message\n"
                        "\n"
                        "title\n"
                        "c a comment card\n"
                        "1 0 -1 $ cell comment\n"
                        "C\n"
                        "\n"
                        "c comment before\n"
                        "   C indented comment card\n"
                        "10 RCC 0 0 0 $ base\n"
                        "c comment inside a continued card\n"
                        "       0 0 5\n"
                        "     2\n"
                        "11 SPH 1 2 &\n"
                        "3 4\n"
                        "12 sph\t1 2 3 4\r\n"
                        "\n");
    assert_int_equal(d.nerrors, 0);
    assert_string_equal(d.title, "title");
    assert_int_equal(d.nbodies, 3);
    const prox_deck_body *b = body(&d, 10);
    assert_int_equal(b->line, 11);
    assert_vec(b->shape.u.rcc.axis, prox_v3(0, 0, 5), 0);
    assert_near(b->shape.u.rcc.radius, 2, 0);
    b = body(&d, 11);
    assert_int_equal(b->line, 15);
    assert_near(b->shape.u.sph.radius, 4, 0);
    assert_near(body(&d, 12)->shape.u.sph.radius, 4, 0);
    prox_deck_free(&d);
}

static void test_deck_shorthands(void **state)
{
    (void)state;
    prox_deck d = parse("t\n1 0 -1\n\n"
                        "1 RPP -1 1 2r -1 1\n"          /* -1 1 1 1 -1 1 : ymin=ymax -> invalid */
                        "2 RPP -1 2r 1 2 3\n"           /* -1 -1 -1 1 2 3: xmin = xmax invalid */
                        "3 RPP 0 2i 3 0 1 0 1\n"        /* 0 1 2 3 0 1 ... too many (8) */
                        "4 RCC 0 0 0 0 0 1 2m\n"        /* radius 2 x 1 */
                        "5 S 1 1i 3 0.5\n"              /* 1 2 3 0.5 */
                        "6 S 1 1ilog 100 2\n"           /* 1 10 100 2 */
                        "7 S 1 2 3 2j\n"                /* jump: error */
                        "8 S 3r 1 2 3\n"                /* no preceding entry */
                        "9 S 1 2 3 1.5-3\n"             /* Fortran exponent without its letter: 1.5e-3 */
                        "10 RPP 0 1 0 1 0 1d0\n"        /* D exponent */
                        "11 SO 2i 3\n"                  /* no preceding entry for 2i */
                        "12 SO 1 2i\n"                  /* nothing after 2i */
                        "\n");
    assert_true(has_error(&d, 4, "RPP needs min < max"));
    assert_true(has_error(&d, 5, "RPP needs min < max"));
    assert_true(has_error(&d, 6, "needs 6 entries, has 8"));
    assert_near(body(&d, 4)->shape.u.rcc.radius, 2, 0);
    assert_vec(body(&d, 5)->shape.u.sph.center, prox_v3(1, 2, 3), 0);
    assert_near(body(&d, 6)->shape.u.sph.center.y, 10, 1e-13);
    assert_true(has_error(&d, 10, "jump"));
    assert_true(has_error(&d, 11, "no preceding entry"));
    assert_near(body(&d, 9)->shape.u.sph.radius, 1.5e-3, 0);
    assert_near(body(&d, 10)->shape.u.rpp.zmax, 1, 0);
    assert_true(has_error(&d, 14, "no preceding entry"));
    assert_true(has_error(&d, 15, "no following entry"));
    assert_int_equal(d.nbodies, 5);
    assert_int_equal(d.nerrors, 7);
    prox_deck_free(&d);
}

static void test_deck_unsupported_listed(void **state)
{
    (void)state;
    prox_deck d = parse("t\n1 0 -1\n2 0 1 fill=3 (1 0 0)\n3 0 -2 trcl=(1 0 0)\n\n"
                        "1 PZ 3\n"
                        "2 CZ 4\n"
                        "*3 1 PX 3\n"
                        "4 RHP 0 0 0 0 0 1 0 1 0\n"
                        "5 SO 1\n"
                        "\n");
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(d.nbodies, 2); /* 4 RHP and 5 SO */
    assert_int_equal(d.nunsupported, 5);
    const char *want[] = {"cell 2 fill", "cell 3 trcl", "1 PZ", "2 CZ", "3 PX"};
    const int lines[] = {3, 4, 6, 7, 8};
    for (int i = 0; i < 5; ++i) {
        assert_int_equal(d.unsupported[i].line, lines[i]);
        assert_non_null(strstr(d.unsupported[i].text, want[i]));
    }
    prox_deck_free(&d);
}

static void test_deck_malformed(void **state)
{
    (void)state;
    prox_deck d = parse("t\n1 0 -1\n\n"
                        "1 RCC 0 0 0 0 0 1\n"          /* 6 entries */
                        "x SO 1\n"                      /* bad surface number */
                        "3 SO -1\n"                     /* negative radius */
                        "4 SPH 0 0 0 1 2\n"             /* too many */
                        "5 SO 1\n"
                        "5 SO 2\n"                      /* duplicate */
                        "6 4 SO 1\n"                    /* undefined TR4 */
                        "7 -2 SO 1\n"                   /* periodic */
                        "8 RCC 0 0 0 0 0 0 1\n"         /* zero axis */
                        "9 BOX 0 0 0 1 0 0 1 1 0 0 0 1\n" /* not orthogonal */
                        "10 SO 1 $ fine\n"
                        "11 SO abc\n"
                        "12 SO 1e999\n"
                        "13\n"
                        "\n");
    assert_true(has_error(&d, 4, "needs 7 entries, has 6"));
    assert_true(has_error(&d, 5, "not a positive integer"));
    assert_true(has_error(&d, 6, "radius"));
    assert_true(has_error(&d, 7, "needs 4 entries, has 5"));
    assert_true(has_error(&d, 9, "already defined on line 8"));
    assert_true(has_error(&d, 10, "TR4 is not defined"));
    assert_true(has_error(&d, 11, "periodic"));
    assert_true(has_error(&d, 12, "axis"));
    assert_true(has_error(&d, 13, "orthogonal"));
    assert_true(has_error(&d, 15, "'abc' is not a number"));
    assert_true(has_error(&d, 16, "'1e999' is not a number"));
    assert_true(has_error(&d, 17, "no mnemonic"));
    assert_int_equal(d.nerrors, 12);
    assert_int_equal(d.nbodies, 2);
    prox_deck_free(&d);
}

static void test_deck_structure_errors(void **state)
{
    (void)state;
    prox_deck d = parse("t\n1 0 -1\n");
    assert_int_equal(d.nerrors, 1);
    assert_int_equal(d.errors[0].line, 0);
    prox_deck_free(&d);
    d = parse("t\n1 0 -1\n\n     1 SO 1\n2 SO 1 &\n\n");
    assert_true(has_error(&d, 4, "no card to continue"));
    assert_true(has_error(&d, 6, "blank line"));
    prox_deck_free(&d);
    d = (prox_deck){0};
    assert_int_equal(prox_deck_read_file("/nonexistent/deck.i", &d), PROX_OK);
    assert_int_equal(d.nerrors, 1);
    assert_non_null(strstr(d.errors[0].text, "cannot read"));
    prox_deck_free(&d);
    assert_int_equal(prox_deck_parse(NULL, &d), PROX_EINVAL_ARG);
    assert_int_equal(prox_deck_parse("t", NULL), PROX_EINVAL_ARG);
}

/* The reference placement: r = O + sum_j x'_j * column_j, written out independently. */
static prox_vec3 ref_place(const double B[9], const double O[3], prox_vec3 r)
{
    double c[3] = {r.x, r.y, r.z}, out[3];
    for (int i = 0; i < 3; ++i) out[i] = O[i] + B[i] * c[0] + B[3 + i] * c[1] + B[6 + i] * c[2];
    return prox_v3(out[0], out[1], out[2]);
}

static void test_deck_transforms(void **state)
{
    (void)state;
    /* TR1: shift. TR2: 90 deg about z in degrees (x' = y, y' = -x). TR3: same in cosines with M=-1.
     * TR4: 6-entry pattern. */
    prox_deck d = parse("t\n1 0 -1\n\n"
                        "1 1 RCC 0 0 0 0 0 10 1\n"
                        "2 2 RCC 1 0 0 1 0 0 1\n"
                        "3 3 SPH 1 0 0 1\n"
                        "4 4 BOX 0 0 0 1 0 0 0 2 0 0 0 3\n"
                        "5 2 RPP 0 1 0 2 0 3\n"
                        "6 1 SO 2\n"
                        "\n"
                        "TR1 1 2 3\n"
                        "*tr2 0 0 0 90 0 90 180 90 90 90 90 0\n"
                        "tr3 5 0 0 0 1 0 -1 0 0 0 0 1 -1\n"
                        "TR4 0 0 0 0 1 0 -1 0 0\n");
    assert_int_equal(d.nerrors, 0);
    assert_vec(body(&d, 1)->shape.u.rcc.base, prox_v3(1, 2, 3), 0);
    assert_int_equal(body(&d, 1)->tr, 1);
    assert_vec(body(&d, 2)->shape.u.rcc.base, prox_v3(0, 1, 0), 0);
    assert_vec(body(&d, 2)->shape.u.rcc.axis, prox_v3(0, 1, 0), 0);
    /* M = -1: main origin at (5,0,0) of the auxiliary frame, so r = R (r' - O) = R (-4,0,0) = (0,-4,0). */
    assert_vec(body(&d, 3)->shape.u.sph.center, prox_v3(0, -4, 0), 0);
    assert_vec(body(&d, 4)->shape.u.box.edge[0], prox_v3(0, 1, 0), 0);
    assert_vec(body(&d, 4)->shape.u.box.edge[2], prox_v3(0, 0, 3), 0);
    const prox_deck_body *b = body(&d, 5); /* axis permutation keeps the RPP */
    assert_int_equal(b->shape.kind, PROX_SHAPE_RPP);
    assert_near(b->shape.u.rpp.xmin, -2, 0);
    assert_near(b->shape.u.rpp.xmax, 0, 0);
    assert_near(b->shape.u.rpp.ymin, 0, 0);
    assert_near(b->shape.u.rpp.ymax, 1, 0);
    assert_vec(body(&d, 6)->shape.u.sph.center, prox_v3(1, 2, 3), 0);
    prox_deck_free(&d);

    /* Random rotations written as cosines: placement matches the reference to 1e-13. */
    test_rng rng = test_rng_seed(606);
    for (int k = 0; k < 50; ++k) {
        test_rot R = test_random_rot(&rng);
        double B[9], O[3] = {test_range(&rng, -50, 50), test_range(&rng, -50, 50), test_range(&rng, -50, 50)};
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) B[3 * j + i] = R.m[i][j];
        char text[2048];
        snprintf(text, sizeof text,
                 "rot\n1 0 -1\n\n1 7 RCC 1 2 3 4 5 6 0.5\n2 7 RPP 0 1 0 2 0 3\n\n"
                 "tr7 %.17g %.17g %.17g\n     %.17g %.17g %.17g\n     %.17g %.17g %.17g\n     %.17g %.17g %.17g\n",
                 O[0], O[1], O[2], B[0], B[1], B[2], B[3], B[4], B[5], B[6], B[7], B[8]);
        d = parse(text);
        assert_int_equal(d.nerrors, 0);
        prox_rcc c = body(&d, 1)->shape.u.rcc;
        assert_vec(c.base, ref_place(B, O, prox_v3(1, 2, 3)), 1e-13 * 60);
        double zero[3] = {0, 0, 0};
        assert_vec(c.axis, ref_place(B, zero, prox_v3(4, 5, 6)), 1e-13 * 10);
        b = body(&d, 2);
        assert_int_equal(b->shape.kind, PROX_SHAPE_BOX);
        assert_vec(b->shape.u.box.corner, prox_v3(O[0], O[1], O[2]), 1e-13 * 60);
        assert_vec(b->shape.u.box.edge[1], ref_place(B, zero, prox_v3(0, 2, 0)), 1e-14);
        prox_deck_free(&d);
    }
}

static void test_deck_transform_errors(void **state)
{
    (void)state;
    prox_deck d = parse("t\n1 0 -1\n\n1 1 SO 1\n\n"
                        "tr1 0 0 0 1 0 0 0 1 0 0 0.5 1\n" /* not orthonormal */
                        "tr2 0 0 0 1 0\n"                 /* 5 entries */
                        "tr3 0 0 0 1 0 0 0 1 0 0 0 1 2\n" /* M = 2 */
                        "tr2 1 1 1\n"                     /* fine: the first tr2 failed */
                        "tr2 1 1 1\n"                     /* duplicate */
                        "trx 1 1 1\n"                     /* not a TR card: ignored like any data card */
                        "\n"
                        "ignored after the data block\n");
    assert_true(has_error(&d, 6, "not orthonormal"));
    assert_true(has_error(&d, 7, "5 entries"));
    assert_true(has_error(&d, 8, "M must be 1 or -1"));
    assert_true(has_error(&d, 10, "already defined on line 9"));
    assert_true(has_error(&d, 4, "TR1 is not defined"));
    assert_int_equal(d.nerrors, 5);
    prox_deck_free(&d);
}

/* ---- READ cards --------------------------------------------------------------------------------- */

/* A temp dir holding the files of one test (removed by tmp_done). */
typedef struct tmp_files {
    char dir[64];
    char names[16][64];
    int n;
} tmp_files;

static void tmp_start(tmp_files *t)
{
    memset(t, 0, sizeof *t);
    snprintf(t->dir, sizeof t->dir, "/tmp/prox_deck_XXXXXX");
    assert_non_null(mkdtemp(t->dir));
}

/* Writes `text` to dir/name (name may hold one subdirectory, created here) and returns the path. */
static const char *tmp_write(tmp_files *t, const char *name, const char *text)
{
    assert_true(t->n < 16);
    const char *slash = strchr(name, '/');
    if (slash) {
        char sub[256];
        snprintf(sub, sizeof sub, "%s/%.*s", t->dir, (int)(slash - name), name);
        mkdir(sub, 0700); /* may exist already */
    }
    static char path[256];
    snprintf(path, sizeof path, "%s/%s", t->dir, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fputs(text, f) >= 0, 1);
    assert_int_equal(fclose(f), 0);
    snprintf(t->names[t->n++], sizeof t->names[0], "%s", name);
    return path;
}

/* Removes every file written and the (sub)directories. */
static void tmp_done(tmp_files *t)
{
    char path[256];
    for (int i = t->n - 1; i >= 0; --i) {
        snprintf(path, sizeof path, "%s/%s", t->dir, t->names[i]);
        remove(path);
        char *slash = strchr(t->names[i], '/');
        if (slash) {
            snprintf(path, sizeof path, "%s/%.*s", t->dir, (int)(slash - t->names[i]), t->names[i]);
            rmdir(path); /* fails while the subdirectory still holds files */
        }
    }
    rmdir(t->dir);
}

/* Reads the main deck (written as dir/main.i) through prox_deck_read_file. */
static prox_deck read_deck(tmp_files *t, const char *text)
{
    const char *path = tmp_write(t, "main.i", text);
    prox_deck d = {0};
    assert_int_equal(prox_deck_read_file(path, &d), PROX_OK);
    return d;
}

/* 1 when some unsupported note is on `line` and contains `needle`. */
static int has_unsupported(const prox_deck *d, int line, const char *needle)
{
    for (size_t i = 0; i < d->nunsupported; ++i)
        if (d->unsupported[i].line == line && strstr(d->unsupported[i].text, needle)) return 1;
    for (size_t i = 0; i < d->nunsupported; ++i)
        print_message("unsupported line %d: %s\n", d->unsupported[i].line, d->unsupported[i].text);
    return 0;
}

static void test_deck_read_surface_block(void **state)
{
    (void)state;
    tmp_files t;
    tmp_start(&t);
    tmp_write(&t, "bodies.i",
              "2 RCC 0 0 0  0 0 5  1\n"
              "c a comment in the included file\n"
              "3 rpp 0 1 0 1 0 1 $ end comment\n"
              "5 RCC 1 2\n");
    prox_deck d = read_deck(&t, "read in the surface block\n"
                                "1 0 -1\n"
                                "\n"
                                "1 SO 1\n"
                                "Read NoEcho File=bodies.i $ two bodies and a bad card\n"
                                "4 SPH 9 0 0 1\n"
                                "\n"
                                "nps 1\n");
    assert_int_equal(d.nbodies, 4);
    assert_int_equal(body(&d, 1)->line, 4);
    const prox_deck_body *b = body(&d, 2);
    assert_int_equal(b->line, 5); /* the line of the READ card in the main deck */
    assert_int_equal(b->shape.kind, PROX_SHAPE_RCC);
    assert_vec(b->shape.u.rcc.axis, prox_v3(0, 0, 5), 0);
    b = body(&d, 3);
    assert_int_equal(b->line, 5);
    assert_int_equal(b->shape.kind, PROX_SHAPE_RPP);
    assert_near(b->shape.u.rpp.xmax, 1, 0);
    assert_int_equal(body(&d, 4)->line, 6);
    /* the bad card of the included file: READ line, and the file's own line in the text */
    assert_int_equal(d.nerrors, 1);
    assert_true(has_error(&d, 5, "bodies.i' line 4: surface 5 RCC: needs 7 entries, has 2"));
    assert_int_equal(d.nunsupported, 0);
    prox_deck_free(&d);
    tmp_done(&t);
}

static void test_deck_read_cell_block(void **state)
{
    (void)state;
    tmp_files t;
    tmp_start(&t);
    tmp_write(&t, "rest.i",
              "2 0 1 -2 fill=1\n"
              "\n"
              "1 SO 1\n"
              "1 SO 2\n");
    prox_deck d = read_deck(&t, "the cell block ends in the included file\n"
                                "1 0 -1\n"
                                "READ FILE=rest.i\n"
                                "3 SO 50\n"
                                "\n"
                                "nps 1\n");
    assert_int_equal(d.nbodies, 2);
    assert_int_equal(body(&d, 1)->line, 3);
    assert_int_equal(body(&d, 3)->line, 4); /* after the READ card: in the surface block */
    assert_near(body(&d, 3)->shape.u.sph.radius, 50, 0);
    assert_true(has_unsupported(&d, 3, "rest.i' line 1: cell 2 fill"));
    assert_int_equal(d.nerrors, 1); /* a duplicate within the file names the file's line */
    assert_true(has_error(&d, 3, "rest.i' line 4: surface 1 is already defined on '"));
    assert_true(has_error(&d, 3, "rest.i' line 3"));
    prox_deck_free(&d);
    tmp_done(&t);
}

static void test_deck_read_data_block(void **state)
{
    (void)state;
    tmp_files t;
    tmp_start(&t);
    tmp_write(&t, "tr.i", "tr1 10 20 30\n");
    prox_deck d = read_deck(&t, "the TR card comes from an included file\n"
                                "1 0 -1\n"
                                "\n"
                                "1 1 RCC 0 0 0  0 0 1  1\n"
                                "\n"
                                "mode p\n"
                                "read file=tr.i\n"
                                "nps 1\n");
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(d.nbodies, 1);
    const prox_deck_body *b = body(&d, 1);
    assert_int_equal(b->tr, 1);
    assert_vec(b->shape.u.rcc.base, prox_v3(10, 20, 30), 0);
    prox_deck_free(&d);
    tmp_done(&t);
}

static void test_deck_read_nested(void **state)
{
    (void)state;
    tmp_files t;
    tmp_start(&t);
    tmp_write(&t, "sub/a.i", "2 SO 2\nread file=b.i\n6 SO 6\n");  /* b.i: next to a.i, in sub/ */
    tmp_write(&t, "sub/b.i", "3 SO 3\n4 SO\n");
    prox_deck d = read_deck(&t, "nested READ\n"
                                "1 0 -1\n"
                                "\n"
                                "1 SO 1\n"
                                "READ FILE=sub/a.i\n"
                                "5 SO 5\n"
                                "\n");
    assert_int_equal(d.nbodies, 5);
    for (long j = 1; j <= 6; ++j) {
        if (j == 4) continue;
        assert_near(body(&d, j)->shape.u.sph.radius, (double)j, 0);
    }
    assert_int_equal(body(&d, 3)->line, 5);
    assert_int_equal(body(&d, 6)->line, 5);
    assert_int_equal(body(&d, 5)->line, 6);
    assert_int_equal(d.nerrors, 1);
    assert_true(has_error(&d, 5, "sub/b.i' line 2: surface 4 SO: needs 1 entries, has 0"));
    prox_deck_free(&d);
    tmp_done(&t);

    /* a chain main -> d1 -> ... -> d9: 8 levels are read, the 9th is an error naming the files */
    tmp_start(&t);
    char name[16], text[64];
    for (int k = 1; k <= 9; ++k) {
        snprintf(name, sizeof name, "d%d.i", k);
        snprintf(text, sizeof text, "%d SO %d\nread file=d%d.i\n", 10 + k, k, k + 1);
        tmp_write(&t, name, text);
    }
    d = read_deck(&t, "deep\n1 0 -1\n\nread file=d1.i\n\n");
    assert_int_equal(d.nbodies, 8);
    for (long j = 11; j <= 18; ++j) assert_int_equal(body(&d, j)->line, 4);
    assert_int_equal(d.nerrors, 1);
    assert_true(has_error(&d, 4, "d8.i' line 2: READ FILE=d9.i: nested deeper than 8 levels: main.i -> d1.i"));
    prox_deck_free(&d);
    tmp_done(&t);
}

static void test_deck_read_missing_file(void **state)
{
    (void)state;
    tmp_files t;
    tmp_start(&t);
    prox_deck d = read_deck(&t, "missing file\n"
                                "1 0 -1\n"
                                "\n"
                                "1 SO 1\n"
                                "READ FILE=nope.i\n"
                                "2 SO 2\n"
                                "read noecho\n"
                                "read file=\n"
                                "read file=x.i bogus\n"
                                "\n");
    assert_int_equal(d.nbodies, 2);
    assert_int_equal(body(&d, 2)->line, 6);
    assert_int_equal(d.nerrors, 4);
    assert_true(has_error(&d, 5, "READ FILE=nope.i: cannot read '"));
    assert_true(has_error(&d, 5, "nope.i'"));
    assert_true(has_error(&d, 7, "READ card without FILE=name"));
    assert_true(has_error(&d, 8, "FILE needs '=name'"));
    assert_true(has_error(&d, 9, "unknown keyword 'bogus'"));
    prox_deck_free(&d);
    tmp_done(&t);

    /* DECODE / ENCODE: reported, and the FILE= content is still read */
    tmp_start(&t);
    tmp_write(&t, "s.i", "2 SO 2\n");
    d = read_deck(&t, "decode\n1 0 -1\n\nREAD FILE=s.i DECODE=s.bin\n\n");
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(d.nbodies, 1);
    assert_int_equal(body(&d, 2)->line, 4);
    assert_true(has_unsupported(&d, 4, "READ DECODE=s.bin"));
    prox_deck_free(&d);
    tmp_done(&t);
}

static void test_deck_read_cycle(void **state)
{
    (void)state;
    tmp_files t;
    tmp_start(&t);
    tmp_write(&t, "a.i", "2 SO 2\nread file=b.i\n");
    tmp_write(&t, "b.i", "3 SO 3\nread file=a.i\n");
    prox_deck d = read_deck(&t, "cycle\n"
                                "1 0 -1\n"
                                "\n"
                                "1 SO 1\n"
                                "read file=a.i\n"
                                "read file=main.i\n" /* the deck itself */
                                "4 SO 4\n"
                                "\n");
    assert_int_equal(d.nbodies, 4); /* every body once */
    assert_int_equal(body(&d, 3)->line, 5);
    assert_int_equal(body(&d, 4)->line, 7);
    assert_int_equal(d.nerrors, 2);
    assert_true(has_error(&d, 5, "b.i' line 2: READ FILE=a.i: cycle main.i -> a.i -> b.i -> a.i"));
    assert_true(has_error(&d, 6, "READ FILE=main.i: cycle main.i -> main.i"));
    prox_deck_free(&d);
    tmp_done(&t);
}

static void test_deck_parse_read_unsupported(void **state)
{
    (void)state;
    prox_deck d = parse("READ FILE=title.i is the title\n"
                        "1 0 -1\n"
                        "read file=cells.i\n"
                        "\n"
                        "1 SO 1\n"
                        "READ FILE=/etc/passwd NOECHO $ never opened\n"
                        "  read\n"
                        "2 SO 2\n"
                        "\n"
                        "read file=data.i\n"
                        "\n");
    assert_string_equal(d.title, "READ FILE=title.i is the title");
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(d.nbodies, 2);
    assert_int_equal(d.nunsupported, 4);
    assert_true(has_unsupported(&d, 3, "read file=cells.i: included files are read by prox_deck_read_file"));
    assert_true(has_unsupported(&d, 6, "READ FILE=/etc/passwd NOECHO: included files are read by"));
    assert_true(has_unsupported(&d, 7, "read: included files"));
    assert_true(has_unsupported(&d, 10, "read file=data.i: included files"));
    prox_deck_free(&d);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_deck_blocks_and_every_body),
        cmocka_unit_test(test_deck_comments_and_continuations),
        cmocka_unit_test(test_deck_shorthands),
        cmocka_unit_test(test_deck_unsupported_listed),
        cmocka_unit_test(test_deck_malformed),
        cmocka_unit_test(test_deck_structure_errors),
        cmocka_unit_test(test_deck_transforms),
        cmocka_unit_test(test_deck_transform_errors),
        cmocka_unit_test(test_deck_read_surface_block),
        cmocka_unit_test(test_deck_read_cell_block),
        cmocka_unit_test(test_deck_read_data_block),
        cmocka_unit_test(test_deck_read_nested),
        cmocka_unit_test(test_deck_read_missing_file),
        cmocka_unit_test(test_deck_read_cycle),
        cmocka_unit_test(test_deck_parse_read_unsupported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
