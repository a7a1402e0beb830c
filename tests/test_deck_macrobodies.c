/* Tests of the deck reader's macrobodies beyond RCC/BOX/RPP/SPH (src/scene/deck.c): TRC, REC (12 and
 * 10 entries), ELL (foci and centre-axis forms), RHP and HEX (15 and 9 entries), WED, ARB; each
 * card's stored shape compared with the values the MCNP card defines, computed here; TRn / *TRn
 * placement (points moved, vectors turned) against a rotation written out in the test; wrong entry
 * counts and invalid bodies as errors with their lines; READ keywords ECHO / NOECHO / ENCODE; the
 * column limit; the TRn* spelling of *TRn. */
#include <string.h>

#include "test_util.h"
#include "prox/deck.h"

static prox_deck parse(const char *text)
{
    prox_deck d = {0};
    assert_int_equal(prox_deck_parse(text, &d), PROX_OK);
    return d;
}

static const prox_deck_body *body(const prox_deck *d, long j)
{
    for (size_t i = 0; i < d->nbodies; ++i)
        if (d->bodies[i].surface == j) return &d->bodies[i];
    for (size_t i = 0; i < d->nerrors; ++i) print_message("error line %d: %s\n", d->errors[i].line, d->errors[i].text);
    print_error("surface %ld not found\n", j);
    fail();
    return NULL;
}

static int has_note(const prox_deck_note *n, size_t count, int line, const char *needle)
{
    for (size_t i = 0; i < count; ++i)
        if (n[i].line == line && strstr(n[i].text, needle)) return 1;
    for (size_t i = 0; i < count; ++i) print_message("note line %d: %s\n", n[i].line, n[i].text);
    return 0;
}

static void assert_vec(prox_vec3 a, prox_vec3 e, double tol)
{
    assert_near(a.x, e.x, tol);
    assert_near(a.y, e.y, tol);
    assert_near(a.z, e.z, tol);
}

static const char *BODIES = "new bodies\n1 0 -1\n\n"
                            "1 TRC 1 2 3  0 0 5  2 0.5\n"
                            "2 REC 0 0 0  0 0 4  3 0 0  0 1.5 0\n"
                            "3 REC 0 0 0  0 0 4  3 0 0  1.5\n"
                            "4 ELL -2 0 0  2 0 0  3\n"
                            "5 ELL 1 1 0  0 0 4  -2\n"
                            "6 RHP 0 0 0  0 0 3  2 0 0\n"
                            "7 hex 0 0 0  0 0 3  2 0 0  0.5 1.5 0  -1.5 1.5 0\n"
                            "8 WED 0 0 0  3 0 0  0 2 0  0 0 4\n"
                            "9 ARB 0 0 0  4 0 0  0 4 0  0 0 4  0 0 0  0 0 0  0 0 0  0 0 0  1230 1240 1340 2340 0 0\n"
                            "\n";

static void test_every_new_body(void **state)
{
    (void)state;
    prox_deck d = parse(BODIES);
    for (size_t i = 0; i < d.nerrors; ++i) print_message("error line %d: %s\n", d.errors[i].line, d.errors[i].text);
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(d.nunsupported, 0);
    assert_int_equal(d.nbodies, 9);
    const prox_deck_body *b = body(&d, 1);
    assert_int_equal(b->shape.kind, PROX_SHAPE_TRC);
    assert_string_equal(b->card, "TRC");
    assert_int_equal(b->line, 4);
    assert_vec(b->shape.u.trc.base, prox_v3(1, 2, 3), 0);
    assert_near(b->shape.u.trc.r2, 0.5, 0);
    b = body(&d, 2);
    assert_int_equal(b->shape.kind, PROX_SHAPE_REC);
    assert_vec(b->shape.u.rec.a2, prox_v3(0, 1.5, 0), 0);
    /* 10 entries: a2 = r2 (h x a1) / |h x a1| = 1.5 (z x x) = (0, 1.5, 0) */
    b = body(&d, 3);
    assert_int_equal(b->shape.kind, PROX_SHAPE_REC);
    assert_vec(b->shape.u.rec.a2, prox_v3(0, 1.5, 0), 1e-15);
    /* foci (-+2,0,0), major radius 3: centre 0, semi-axis 3 along x, equatorial radius sqrt(9 - 4) */
    b = body(&d, 4);
    assert_int_equal(b->shape.kind, PROX_SHAPE_ELL);
    assert_vec(b->shape.u.ell.center, prox_v3(0, 0, 0), 1e-15);
    assert_near(fabs(b->shape.u.ell.axis.x), 3, 1e-14);
    assert_near(b->shape.u.ell.radius, sqrt(5.0), 1e-14);
    b = body(&d, 5);
    assert_vec(b->shape.u.ell.center, prox_v3(1, 1, 0), 0);
    assert_vec(b->shape.u.ell.axis, prox_v3(0, 0, 4), 0);
    assert_near(b->shape.u.ell.radius, 2, 0);
    /* 9 entries: the other two facet vectors are r turned by 60 and 120 degrees about h */
    b = body(&d, 6);
    assert_int_equal(b->shape.kind, PROX_SHAPE_RHP);
    assert_string_equal(b->card, "RHP");
    for (int k = 0; k < 3; ++k) {
        assert_near(prox_v3_norm(b->shape.u.rhp.r[k]), 2, 1e-14);
        assert_near(b->shape.u.rhp.r[k].z, 0, 1e-15);
        assert_near(prox_v3_dot(b->shape.u.rhp.r[k], b->shape.u.rhp.r[0]), 4 * cos(k * PROX_PI / 3), 1e-13);
    }
    b = body(&d, 7);
    assert_int_equal(b->shape.kind, PROX_SHAPE_RHP);
    assert_string_equal(b->card, "HEX");
    assert_vec(b->shape.u.rhp.r[2], prox_v3(-1.5, 1.5, 0), 0);
    b = body(&d, 8);
    assert_int_equal(b->shape.kind, PROX_SHAPE_WED);
    assert_vec(b->shape.u.wed.v3, prox_v3(0, 0, 4), 0);
    b = body(&d, 9);
    assert_int_equal(b->shape.kind, PROX_SHAPE_ARB);
    assert_vec(b->shape.u.arb.corner[3], prox_v3(0, 0, 4), 0);
    assert_int_equal(b->shape.u.arb.face[3], 2340);
    assert_int_equal(b->shape.u.arb.face[4], 0);
    prox_deck_free(&d);
}

/* Under TR1 (o = (1,-2,3), x' = y, y' = -x, z' = z) every point p of a card becomes o + R p and
 * every vector v becomes R v; *TR1 with the angles in degrees gives the same body. */
static prox_vec3 Rv(prox_vec3 v) { return prox_v3(-v.y, v.x, v.z); }
static prox_vec3 Rp(prox_vec3 p) { return prox_v3_add(prox_v3(1, -2, 3), Rv(p)); }

static void test_transformed_bodies(void **state)
{
    (void)state;
    const char *trs[] = {"tr1 1 -2 3  0 1 0  -1 0 0  0 0 1\n", "*tr1 1 -2 3  90 0 90  180 90 90  90 90 0\n"};
    for (int form = 0; form < 2; ++form) {
        char deck[2048];
        snprintf(deck, sizeof deck,
                 "moved\n1 0 -1\n\n"
                 "1 1 TRC 1 2 3  0 0 5  2 0.5\n"
                 "2 1 REC 0 0 0  0 0 4  3 0 0  1.5\n"
                 "4 1 ELL -2 0 0  2 0 0  3\n"
                 "6 1 RHP 0 0 0  0 0 3  2 0 0\n"
                 "8 1 WED 0 0 0  3 0 0  0 2 0  0 0 4\n"
                 "9 1 ARB 0 0 0  4 0 0  0 4 0  0 0 4  0 0 0  0 0 0  0 0 0  0 0 0  1230 1240 1340 2340 0 0\n"
                 "\n%s",
                 trs[form]);
        prox_deck d = parse(deck);
        assert_int_equal(d.nerrors, 0);
        const double t = 1e-14;
        const prox_deck_body *b = body(&d, 1);
        assert_int_equal(b->tr, 1);
        assert_vec(b->shape.u.trc.base, Rp(prox_v3(1, 2, 3)), t);
        assert_vec(b->shape.u.trc.axis, Rv(prox_v3(0, 0, 5)), t);
        b = body(&d, 2);
        assert_vec(b->shape.u.rec.base, Rp(prox_v3(0, 0, 0)), t);
        assert_vec(b->shape.u.rec.a1, Rv(prox_v3(3, 0, 0)), t);
        assert_vec(b->shape.u.rec.a2, Rv(prox_v3(0, 1.5, 0)), t);
        b = body(&d, 4);
        assert_vec(b->shape.u.ell.center, Rp(prox_v3(0, 0, 0)), t);
        assert_near(fabs(b->shape.u.ell.axis.y), 3, t); /* the major axis turned from x to y */
        b = body(&d, 6);
        assert_vec(b->shape.u.rhp.r[0], Rv(prox_v3(2, 0, 0)), t);
        b = body(&d, 8);
        assert_vec(b->shape.u.wed.vertex, Rp(prox_v3(0, 0, 0)), t);
        assert_vec(b->shape.u.wed.v1, Rv(prox_v3(3, 0, 0)), t);
        b = body(&d, 9);
        for (int k = 0; k < 4; ++k) {
            prox_vec3 c = k == 0 ? prox_v3(0, 0, 0) : k == 1 ? prox_v3(4, 0, 0) : k == 2 ? prox_v3(0, 4, 0) : prox_v3(0, 0, 4);
            assert_vec(b->shape.u.arb.corner[k], Rp(c), t);
        }
        assert_vec(b->shape.u.arb.corner[6], Rp(prox_v3(0, 0, 0)), t); /* unused corners are points too */
        prox_deck_free(&d);
    }
}

static void test_bad_bodies(void **state)
{
    (void)state;
    prox_deck d = parse("bad bodies\n1 0 -1\n\n"
                        "1 TRC 0 0 0  0 0 5  2 2\n"                       /* 4: equal radii */
                        "2 REC 0 0 0  0 0 4  3 0 0  0 1.5 1\n"            /* 5: a2 not across the axis */
                        "3 REC 0 0 0  0 0 4  3 0 0\n"                     /* 6: 9 entries */
                        "4 ELL -2 0 0  2 0 0  1\n"                        /* 7: major radius too short */
                        "5 RHP 0 0 0  0 0 3  2 0 0  1\n"                  /* 8: 10 entries */
                        "6 WED 0 0 0  3 0 0  6 0 0  0 0 4\n"              /* 9: parallel sides */
                        "7 ARB 0 0 0  4 0 0  0 4 0  0 0 4  0 0 0  0 0 0  0 0 0  0 0 0  1239 1240 1340 2340 0 0\n" /* 10 */
                        "8 ELL 0 0 0  0 0 1  0\n"                         /* 11: R = 0 */
                        "9 TRC 0 0 0  0 0 5  2 1\n"
                        "\n");
    assert_true(has_note(d.errors, d.nerrors, 4, "surface 1 TRC"));
    assert_true(has_note(d.errors, d.nerrors, 5, "surface 2 REC"));
    assert_true(has_note(d.errors, d.nerrors, 6, "needs 10 or 12 entries, has 9"));
    assert_true(has_note(d.errors, d.nerrors, 7, "surface 4 ELL"));
    assert_true(has_note(d.errors, d.nerrors, 8, "needs 9 or 15 entries, has 10"));
    assert_true(has_note(d.errors, d.nerrors, 9, "surface 6 WED"));
    assert_true(has_note(d.errors, d.nerrors, 10, "surface 7 ARB"));
    assert_true(has_note(d.errors, d.nerrors, 11, "surface 8 ELL"));
    assert_int_equal(d.nerrors, 8);
    assert_int_equal(d.nbodies, 1);
    prox_deck_free(&d);
}

static void test_read_keywords_and_columns(void **state)
{
    (void)state;
    /* READ with ECHO, NOECHO, ENCODE: no error (prox_deck_parse lists READ itself as unsupported) */
    prox_deck d = parse("read keywords\n1 0 -1\n\n1 SO 1\nread file=a.i echo\nread file=b.i noecho encode=b.e\n\n");
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(d.nunsupported, 2);
    prox_deck_free(&d);
    /* columns beyond 128 are not read: listed, never dropped silently; a $ comment may run on */
    char deck[1024], pad[200];
    memset(pad, ' ', sizeof pad);
    pad[120] = 0;
    snprintf(deck, sizeof deck, "columns\n1 0 -1\n\n1 SO 1%s     2\n2 SO 3 $%s long comment\n\n", pad, pad);
    d = parse(deck);
    assert_int_equal(d.nerrors, 0);
    assert_near(body(&d, 1)->shape.u.sph.radius, 1, 0); /* the 2 after column 128 is not an entry */
    assert_true(has_note(d.unsupported, d.nunsupported, 4, "text beyond column 128"));
    assert_int_equal(d.nunsupported, 1);
    prox_deck_free(&d);
    /* TRn* reads as *TRn (angles in degrees): the body lands where *TRn puts it */
    const char *rot = " 1 2 3  90 0 90  180 90 90  90 90 0\n";
    char a[256], b[256];
    snprintf(a, sizeof a, "tr star\n1 0 -1\n\n1 1 RCC 1 0 0  0 2 0  0.5\n\ntr1*%s", rot);
    snprintf(b, sizeof b, "tr star\n1 0 -1\n\n1 1 RCC 1 0 0  0 2 0  0.5\n\n*tr1%s", rot);
    d = parse(a);
    prox_deck e = parse(b);
    assert_int_equal(d.nerrors, 0);
    assert_int_equal(e.nerrors, 0);
    assert_int_equal(d.nbodies, 1);
    assert_int_equal(e.nbodies, 1);
    prox_rcc ra = d.bodies[0].shape.u.rcc, rb = e.bodies[0].shape.u.rcc;
    assert_near(ra.base.x, rb.base.x, 0);
    assert_near(ra.base.y, rb.base.y, 0);
    assert_near(ra.base.z, rb.base.z, 0);
    assert_near(ra.axis.x, rb.axis.x, 0);
    assert_near(ra.axis.y, rb.axis.y, 0);
    assert_near(ra.axis.z, rb.axis.z, 0);
    /* rotated by 90 degrees about z: the axis +y turns to -x */
    assert_near(ra.axis.x, -2, 1e-15);
    assert_near(ra.axis.y, 0, 1e-15);
    prox_deck_free(&e);
    prox_deck_free(&d);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_new_body),
        cmocka_unit_test(test_transformed_bodies),
        cmocka_unit_test(test_bad_bodies),
        cmocka_unit_test(test_read_keywords_and_columns),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
