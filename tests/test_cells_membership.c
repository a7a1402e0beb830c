/* Tests of the cell model's surfaces and membership (src/cells/surfaces.c, facets.c, membership.c):
 * every surface card of MCNP's Table 3-4 read from a one-cell deck and compared, at random points,
 * with its textbook equation written out here; every macrobody's inside compared with an
 * independent containment test (foci distances for the ellipsoid, barycentric coordinates for the
 * wedge and a tetrahedron, projections for the others); facets n.k; TRn / *TRn on the surface card
 * against the untransformed model at mapped points; three-valued answers on a deciding surface. */
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "prox/cells.h"

/* Parses a deck made of the cell card "1 0 <geom>", the surface card `surf` and optional data. */
static prox_cell_model model(const char *geom, const char *surf, const char *data)
{
    char deck[2048];
    snprintf(deck, sizeof deck, "membership test\n1 0 %s\n\n%s\n\n%s\n", geom, surf, data ? data : "");
    prox_cell_model m = {0};
    assert_int_equal(prox_cells_parse(deck, &m), PROX_OK);
    for (size_t i = 0; i < m.nerrors; ++i) print_message("error line %d: %s\n", m.errors[i].line, m.errors[i].text);
    assert_int_equal(m.nerrors, 0);
    assert_int_equal(m.ncells, 1);
    assert_false(m.cells[0].unchecked);
    return m;
}

/* The textbook value g(x) of a surface: negative on its negative side. */
typedef double (*textbook_fn)(prox_vec3 p);

typedef struct surf_case {
    const char *card;
    textbook_fn g;
} surf_case;

static double sq(double x) { return x * x; }
static double g_p(prox_vec3 p) { return p.x + 2 * p.y + 3 * p.z - 4; }
static double g_p3(prox_vec3 p) { return p.x + p.y + p.z - 1; }     /* origin on the negative side */
static double g_p3o(prox_vec3 p) { return p.z - p.x; }              /* through the origin, (0,0,inf) positive */
static double g_px(prox_vec3 p) { return p.x - 2; }
static double g_py(prox_vec3 p) { return p.y + 1; }
static double g_pz(prox_vec3 p) { return p.z - 0.5; }
static double g_so(prox_vec3 p) { return sq(p.x) + sq(p.y) + sq(p.z) - 9; }
static double g_s(prox_vec3 p) { return sq(p.x - 1) + sq(p.y - 2) + sq(p.z - 3) - 4; }
static double g_sx(prox_vec3 p) { return sq(p.x - 1) + sq(p.y) + sq(p.z) - 4; }
static double g_sy(prox_vec3 p) { return sq(p.x) + sq(p.y + 1) + sq(p.z) - 4; }
static double g_sz(prox_vec3 p) { return sq(p.x) + sq(p.y) + sq(p.z - 2) - 4; }
static double g_cx_(prox_vec3 p) { return sq(p.y - 1) + sq(p.z - 2) - 9; }
static double g_cy_(prox_vec3 p) { return sq(p.x - 1) + sq(p.z - 2) - 9; }
static double g_cz_(prox_vec3 p) { return sq(p.x - 1) + sq(p.y - 2) - 9; }
static double g_cx(prox_vec3 p) { return sq(p.y) + sq(p.z) - 4; }
static double g_cy(prox_vec3 p) { return sq(p.x) + sq(p.z) - 4; }
static double g_cz(prox_vec3 p) { return sq(p.x) + sq(p.y) - 4; }
static double g_kx_(prox_vec3 p) { return sq(p.y - 2) + sq(p.z - 3) - 0.25 * sq(p.x - 1); }
static double g_ky_(prox_vec3 p) { return sq(p.x - 1) + sq(p.z - 3) - 0.25 * sq(p.y - 2); }
static double g_kz_(prox_vec3 p) { return sq(p.x - 1) + sq(p.y - 2) - 0.25 * sq(p.z - 3); }
static double g_kx(prox_vec3 p) { return sq(p.y) + sq(p.z) - 0.5 * sq(p.x - 1); }
static double g_ky(prox_vec3 p) { return sq(p.x) + sq(p.z) - 0.5 * sq(p.y - 1); }
static double g_kz(prox_vec3 p) { return sq(p.x) + sq(p.y) - 0.5 * sq(p.z - 1); }
/* one-sheet cones: inside the double cone and on the named side of the apex */
static double g_kz_up(prox_vec3 p) { return (g_kz_(p) < 0 && p.z > 3) ? -1 : 1; }
static double g_kx_down(prox_vec3 p) { return (g_kx(p) < 0 && p.x < 1) ? -1 : 1; }
static double g_sq(prox_vec3 p)
{
    return 1 * sq(p.x - 1) + 2 * sq(p.y - 2) + 3 * sq(p.z - 3) + 2 * 0.5 * (p.x - 1) - 2 * 0.5 * (p.y - 2) +
           2 * 1 * (p.z - 3) - 4;
}
static double g_gq(prox_vec3 p)
{
    return 1 * sq(p.x) + 2 * sq(p.y) - 1 * sq(p.z) + 0.5 * p.x * p.y + 0.3 * p.y * p.z + 0.1 * p.z * p.x + p.x -
           p.y + 2 * p.z - 5;
}
static double g_tx(prox_vec3 p) { return sq((p.x - 1) / 1.0) + sq((sqrt(sq(p.y - 2) + sq(p.z - 3)) - 4) / 0.5) - 1; }
static double g_ty(prox_vec3 p) { return sq((p.y - 2) / 1.5) + sq((sqrt(sq(p.x - 1) + sq(p.z - 3)) - 3) / 1.0) - 1; }
static double g_tz(prox_vec3 p) { return sq((p.z - 3) / 0.5) + sq((sqrt(sq(p.x - 1) + sq(p.y - 2)) - 2) / 0.8) - 1; }
static double g_x1(prox_vec3 p) { return p.x - 1; }
static double g_xcyl(prox_vec3 p) { return sq(p.y) + sq(p.z) - 4; }
/* cone through (x, r) = (1, 2) and (3, 4): r = x + 1, the nappe x > -1 */
static double g_xcone(prox_vec3 p) { return (sq(p.y) + sq(p.z) < sq(p.x + 1) && p.x > -1) ? -1 : 1; }
/* three pairs (0,1), (1,2), (2,1): r^2 = -3 x^2 + 6 x + 1 */
static double g_x3(prox_vec3 p) { return sq(p.y) + sq(p.z) - (-3 * sq(p.x) + 6 * p.x + 1); }
static double g_y3(prox_vec3 p) { return sq(p.x) + sq(p.z) - (-3 * sq(p.y) + 6 * p.y + 1); }
static double g_z2(prox_vec3 p) { return p.z - 2; }

static const surf_case SURFACES[] = {
    {"1 P 1 2 3 4", g_p},
    {"1 P 1 0 0  0 1 0  0 0 1", g_p3},
    {"1 P 1 0 0  0 0 1  0 1 0", g_p3},
    {"1 P 0 0 0  0 1 0  1 0 1", g_p3o},
    {"1 P 0 0 0  1 0 1  0 1 0", g_p3o},
    {"1 PX 2", g_px},
    {"1 py -1", g_py},
    {"1 Pz 0.5", g_pz},
    {"1 SO 3", g_so},
    {"1 S 1 2 3 2", g_s},
    {"1 SX 1 2", g_sx},
    {"1 SY -1 2", g_sy},
    {"1 SZ 2 2", g_sz},
    {"1 C/X 1 2 3", g_cx_},
    {"1 C/Y 1 2 3", g_cy_},
    {"1 c/z 1 2 3", g_cz_},
    {"1 CX 2", g_cx},
    {"1 CY 2", g_cy},
    {"1 CZ 2", g_cz},
    {"1 K/X 1 2 3 0.25", g_kx_},
    {"1 K/Y 1 2 3 0.25", g_ky_},
    {"1 K/Z 1 2 3 0.25", g_kz_},
    {"1 K/Z 1 2 3 0.25 1", g_kz_up},
    {"1 KX 1 0.5", g_kx},
    {"1 KY 1 0.5", g_ky},
    {"1 KZ 1 0.5", g_kz},
    {"1 KX 1 0.5 -1", g_kx_down},
    {"1 SQ 1 2 3 0.5 -0.5 1 -4 1 2 3", g_sq},
    {"1 GQ 1 2 -1 0.5 0.3 0.1 1 -1 2 -5", g_gq},
    {"1 TX 1 2 3 4 1 0.5", g_tx},
    {"1 TY 1 2 3 3 1.5 1", g_ty},
    {"1 TZ 1 2 3 2 0.5 0.8", g_tz},
    {"1 X 1 2", g_x1},
    {"1 X 1 2 3 2", g_xcyl},
    {"1 X 1 2 3 4", g_xcone},
    {"1 X 0 1 1 2 2 1", g_x3},
    {"1 Y 0 1 1 2 2 1", g_y3},
    {"1 Z 2 5 2 7", g_z2},
};

/* Membership of the cell "-1" agrees with g < 0 at random points (points within 1e-9 of the
 * surface are skipped: their sign is the rounding's). */
static void check_cell(const prox_cell_model *m, size_t cell, textbook_fn g, double lo, double hi, uint64_t seed,
                       const char *what)
{
    test_rng r = test_rng_seed(seed);
    int inside = 0, outside = 0;
    for (int i = 0; i < 4000; ++i) {
        prox_vec3 p = prox_v3(test_range(&r, lo, hi), test_range(&r, lo, hi), test_range(&r, lo, hi));
        double e = g(p);
        if (fabs(e) < 1e-9) continue;
        int got = prox_cell_contains(m, cell, p);
        if (got != (e < 0)) {
            print_error("%s: at (%g %g %g) textbook %g, cell says %d\n", what, p.x, p.y, p.z, e, got);
            fail();
        }
        inside += e < 0, outside += e > 0;
    }
    if (!inside || !outside) {
        print_error("%s: the sample did not see both sides (%d in, %d out)\n", what, inside, outside);
        fail();
    }
}

static void test_every_surface_card(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof SURFACES / sizeof SURFACES[0]; ++i) {
        prox_cell_model m = model("-1", SURFACES[i].card, NULL);
        check_cell(&m, 0, SURFACES[i].g, -6, 6, 100 + i, SURFACES[i].card);
        /* and the complement "1" */
        prox_cells_free(&m);
        m = model("1", SURFACES[i].card, NULL);
        test_rng r = test_rng_seed(7 + i);
        for (int k = 0; k < 500; ++k) {
            prox_vec3 p = prox_v3(test_range(&r, -6, 6), test_range(&r, -6, 6), test_range(&r, -6, 6));
            double e = SURFACES[i].g(p);
            if (fabs(e) < 1e-9) continue;
            assert_int_equal(prox_cell_contains(&m, 0, p), e > 0);
        }
        prox_cells_free(&m);
    }
}

/* prox_surf_eval of a single-part surface has the textbook's sign and vanishes where it does. */
static void test_surf_eval_sign(void **state)
{
    (void)state;
    prox_cell_model m = model("-1", "1 SQ 1 2 3 0.5 -0.5 1 -4 1 2 3", NULL);
    assert_int_equal(m.nsurfs, 1);
    test_rng r = test_rng_seed(3);
    for (int i = 0; i < 1000; ++i) {
        prox_vec3 p = prox_v3(test_range(&r, -5, 5), test_range(&r, -5, 5), test_range(&r, -5, 5));
        /* SQ is written exactly as its textbook form: the values agree, not only the signs */
        assert_near(prox_surf_eval(&m.surfs[0], p), g_sq(p), 1e-12 * (1 + fabs(g_sq(p))));
    }
    prox_cells_free(&m);
}

/* ---- macrobodies against independent containment ---------------------------------------------- */

static double in_rpp(prox_vec3 p) { return (p.x > -1 && p.x < 2 && p.y > -2 && p.y < 1 && p.z > 0 && p.z < 3) ? -1 : 1; }
/* BOX corner (1,1,1), edges (2,2,0), (-1,1,0), (0,0,3): coordinates along each edge in (0, 1) */
static double in_box(prox_vec3 p)
{
    prox_vec3 d = prox_v3(p.x - 1, p.y - 1, p.z - 1);
    double a = (2 * d.x + 2 * d.y) / 8, b = (-d.x + d.y) / 2, c = d.z / 3;
    return (a > 0 && a < 1 && b > 0 && b < 1 && c > 0 && c < 1) ? -1 : 1;
}
static double in_sph(prox_vec3 p) { return sq(p.x - 1) + sq(p.y) + sq(p.z + 1) < 9 ? -1 : 1; }
static double in_rcc(prox_vec3 p) { return (sq(p.x) + sq(p.z) < 4 && p.y > -1 && p.y < 3) ? -1 : 1; }
/* TRC base (0,0,-2), axis (0,0,5), r1 = 3, r2 = 1: radius 3 - 2 t at height fraction t */
static double in_trc(prox_vec3 p)
{
    double t = (p.z + 2) / 5;
    return (t > 0 && t < 1 && sqrt(sq(p.x) + sq(p.y)) < 3 - 2 * t) ? -1 : 1;
}
/* REC base (0,0,-1), axis (0,0,4), a1 = (3,0,0), a2 = (0,1.5,0) */
static double in_rec(prox_vec3 p) { return (sq(p.x / 3) + sq(p.y / 1.5) < 1 && p.z > -1 && p.z < 3) ? -1 : 1; }
/* ELL with foci (-2,0,0), (2,0,0), major radius 3: the sum of focal distances below 6 */
static double in_ell_foci(prox_vec3 p)
{
    double d1 = sqrt(sq(p.x + 2) + sq(p.y) + sq(p.z)), d2 = sqrt(sq(p.x - 2) + sq(p.y) + sq(p.z));
    return d1 + d2 < 6 ? -1 : 1;
}
/* ELL centre (1,1,0), major semi-axis (0,0,4), minor radius 2 */
static double in_ell_axis(prox_vec3 p) { return sq(p.z / 4) + (sq(p.x - 1) + sq(p.y - 1)) / 4 < 1 ? -1 : 1; }
/* RHP base (0,0,0), height (0,0,3), r = (2,0,0): a regular hexagon of apothem 2 */
static double in_rhp(prox_vec3 p)
{
    if (!(p.z > 0 && p.z < 3)) return 1;
    for (int k = 0; k < 3; ++k) {
        double a = k * PROX_PI / 3;
        if (fabs(p.x * cos(a) + p.y * sin(a)) >= 2) return 1;
    }
    return -1;
}
/* RHP, 15 entries: r = (2,0,0), s = (0.5,1.5,0), t = (-1.5,1.5,0) (an irregular convex hexagon) */
static double in_rhp15(prox_vec3 p)
{
    if (!(p.z > 0 && p.z < 3)) return 1;
    const prox_vec3 v[3] = {{2, 0, 0}, {0.5, 1.5, 0}, {-1.5, 1.5, 0}};
    for (int k = 0; k < 3; ++k)
        if (fabs(prox_v3_dot(p, v[k])) >= prox_v3_norm2(v[k])) return 1;
    return -1;
}
/* WED vertex (0,0,0), v1 (3,0,0), v2 (0,2,0), v3 (0,0,4): barycentric a = x/3, b = y/2 */
static double in_wed(prox_vec3 p)
{
    double a = p.x / 3, b = p.y / 2, c = p.z / 4;
    return (a > 0 && b > 0 && a + b < 1 && c > 0 && c < 1) ? -1 : 1;
}
/* ARB tetrahedron (0,0,0), (4,0,0), (0,4,0), (0,0,4) */
static double in_tet(prox_vec3 p) { return (p.x > 0 && p.y > 0 && p.z > 0 && p.x + p.y + p.z < 4) ? -1 : 1; }
/* ARB: the cube [0,2]^3 from eight corners */
static double in_cube(prox_vec3 p) { return (p.x > 0 && p.x < 2 && p.y > 0 && p.y < 2 && p.z > 0 && p.z < 2) ? -1 : 1; }

static const surf_case BODIES[] = {
    {"1 RPP -1 2 -2 1 0 3", in_rpp},
    {"1 BOX 1 1 1  2 2 0  -1 1 0  0 0 3", in_box},
    {"1 SPH 1 0 -1 3", in_sph},
    {"1 RCC 0 -1 0  0 4 0  2", in_rcc},
    {"1 TRC 0 0 -2  0 0 5  3 1", in_trc},
    {"1 REC 0 0 -1  0 0 4  3 0 0  0 1.5 0", in_rec},
    {"1 REC 0 0 -1  0 0 4  3 0 0  1.5", in_rec},
    {"1 ELL -2 0 0  2 0 0  3", in_ell_foci},
    {"1 ELL 1 1 0  0 0 4  -2", in_ell_axis},
    {"1 RHP 0 0 0  0 0 3  2 0 0", in_rhp},
    {"1 HEX 0 0 0  0 0 3  2 0 0", in_rhp},
    {"1 RHP 0 0 0  0 0 3  2 0 0  0.5 1.5 0  -1.5 1.5 0", in_rhp15},
    {"1 WED 0 0 0  3 0 0  0 2 0  0 0 4", in_wed},
    {"1 ARB 0 0 0  4 0 0  0 4 0  0 0 4  0 0 0  0 0 0  0 0 0  0 0 0  1230 1240 1340 2340 0 0", in_tet},
    {"1 ARB 0 0 0  2 0 0  2 2 0  0 2 0  0 0 2  2 0 2  2 2 2  0 2 2  1234 5678 1265 2376 3487 1584", in_cube},
};

static void test_macrobodies(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof BODIES / sizeof BODIES[0]; ++i) {
        prox_cell_model m = model("-1", BODIES[i].card, NULL);
        check_cell(&m, 0, BODIES[i].g, -5, 5, 300 + i, BODIES[i].card);
        prox_cells_free(&m);
    }
}

/* n.k facets: the negative side of each named facet, against its plane or surface. */
static double f_rpp1(prox_vec3 p) { return p.x - 2; }
static double f_rpp4(prox_vec3 p) { return -2 - p.y; }
static double f_rcc1(prox_vec3 p) { return sq(p.x) + sq(p.z) - 4; }
static double f_rcc2(prox_vec3 p) { return p.y - 3; }
static double f_rcc3(prox_vec3 p) { return -1 - p.y; }
static double f_rhp1(prox_vec3 p) { return p.x - 2; }
static double f_rhp2(prox_vec3 p) { return -2 - p.x; }
static double f_rhp7(prox_vec3 p) { return p.z - 3; }
static double f_rhp8(prox_vec3 p) { return -p.z; }
static double f_wed1(prox_vec3 p) { return p.x / 3 + p.y / 2 - 1; }
static double f_wed2(prox_vec3 p) { return -p.x; }  /* face of v2 and v3 */
static double f_wed3(prox_vec3 p) { return -p.y; }  /* face of v1 and v3 */
static double f_wed4(prox_vec3 p) { return p.z - 4; }
static double f_wed5(prox_vec3 p) { return -p.z; }
static double f_tet4(prox_vec3 p) { return p.x + p.y + p.z - 4; }
static double f_tet1(prox_vec3 p) { return -p.z; }

static void test_facets(void **state)
{
    (void)state;
    static const struct {
        const char *geom, *card;
        textbook_fn g;
    } F[] = {
        {"-1.1", "1 RPP -1 2 -2 1 0 3", f_rpp1},
        {"-1.4", "1 RPP -1 2 -2 1 0 3", f_rpp4},
        {"-1.1", "1 RCC 0 -1 0  0 4 0  2", f_rcc1},
        {"-1.2", "1 RCC 0 -1 0  0 4 0  2", f_rcc2},
        {"-1.3", "1 RCC 0 -1 0  0 4 0  2", f_rcc3},
        {"-1.1", "1 RHP 0 0 0  0 0 3  2 0 0", f_rhp1},
        {"-1.2", "1 RHP 0 0 0  0 0 3  2 0 0", f_rhp2},
        {"-1.7", "1 RHP 0 0 0  0 0 3  2 0 0", f_rhp7},
        {"-1.8", "1 RHP 0 0 0  0 0 3  2 0 0", f_rhp8},
        {"-1.1", "1 WED 0 0 0  3 0 0  0 2 0  0 0 4", f_wed1},
        {"-1.2", "1 WED 0 0 0  3 0 0  0 2 0  0 0 4", f_wed2},
        {"-1.3", "1 WED 0 0 0  3 0 0  0 2 0  0 0 4", f_wed3},
        {"-1.4", "1 WED 0 0 0  3 0 0  0 2 0  0 0 4", f_wed4},
        {"-1.5", "1 WED 0 0 0  3 0 0  0 2 0  0 0 4", f_wed5},
        {"-1.4", "1 ARB 0 0 0  4 0 0  0 4 0  0 0 4  0 0 0  0 0 0  0 0 0  0 0 0  1230 1240 1340 2340 0 0", f_tet4},
        {"-1.1", "1 ARB 0 0 0  4 0 0  0 4 0  0 0 4  0 0 0  0 0 0  0 0 0  0 0 0  1230 1240 1340 2340 0 0", f_tet1},
    };
    for (size_t i = 0; i < sizeof F / sizeof F[0]; ++i) {
        prox_cell_model m = model(F[i].geom, F[i].card, NULL);
        char what[96];
        snprintf(what, sizeof what, "%s of %s", F[i].geom, F[i].card);
        check_cell(&m, 0, F[i].g, -5, 5, 500 + i, what);
        prox_cells_free(&m);
    }
}

/* prox_shape_facets on shapes built directly: the body is the AND of the facets' negative sides. */
static void test_shape_facets_api(void **state)
{
    (void)state;
    prox_surf f[8];
    prox_shape s = prox_shape_from_rcc((prox_rcc){prox_v3(0, -1, 0), prox_v3(0, 4, 0), 2});
    assert_int_equal(prox_shape_facets(&s, f), 3);
    for (int k = 0; k < 3; ++k) assert_int_equal(f[k].facet, k + 1);
    assert_string_equal(f[0].card, "RCC");
    test_rng r = test_rng_seed(11);
    for (int i = 0; i < 2000; ++i) {
        prox_vec3 p = prox_v3(test_range(&r, -4, 4), test_range(&r, -4, 4), test_range(&r, -4, 4));
        int in = 1;
        for (int k = 0; k < 3; ++k) in &= prox_surf_eval(&f[k], p) < 0;
        if (fabs(in_rcc(p)) > 0) assert_int_equal(in, in_rcc(p) < 0);
    }
    prox_shape bad = {.kind = PROX_SHAPE_KIND_COUNT_};
    assert_int_equal(prox_shape_facets(&bad, f), 0);
    assert_int_equal(prox_shape_facets(NULL, f), 0);
}

/* ---- TRn on the surface card ------------------------------------------------------------------ */

/* A body under TR1 holds x exactly when the untransformed body holds x' = R^T (x - o). */
static void test_surface_transforms(void **state)
{
    (void)state;
    /* TR1: o = (1, -2, 0.5), axes x' = (cos 30, sin 30, 0), y' = (-sin 30, cos 30, 0), z' = z */
    const char *tr[] = {"tr1 1 -2 0.5  30 60 90  120 30 90  90 90 0", /* with * : degrees */
                        "tr1 1 -2 0.5  0.8660254037844387 0.5 0  -0.5 0.8660254037844387 0  0 0 1"};
    const char *star[] = {"*", ""};
    const double c = cos(PROX_PI / 6), s = sin(PROX_PI / 6);
    const char *cards[] = {"RPP -1 2 -2 1 0 3", "BOX 1 1 1  2 2 0  -1 1 0  0 0 3", "RCC 0 -1 0  0 4 0  2",
                           "TRC 0 0 -2  0 0 5  3 1", "REC 0 0 -1  0 0 4  3 0 0  1.5", "ELL -2 0 0  2 0 0  3",
                           "RHP 0 0 0  0 0 3  2 0 0", "WED 0 0 0  3 0 0  0 2 0  0 0 4",
                           "ARB 0 0 0  4 0 0  0 4 0  0 0 4  0 0 0  0 0 0  0 0 0  0 0 0  1230 1240 1340 2340 0 0",
                           "C/Z 1 2 1.5", "K/Y 1 2 3 0.25 1", "TZ 1 2 3 2 0.5 0.8", "P 1 2 3 4", "GQ 1 2 -1 0.5 0.3 0.1 1 -1 2 -5"};
    for (int form = 0; form < 2; ++form)
        for (size_t i = 0; i < sizeof cards / sizeof cards[0]; ++i) {
            char moved[200], plain[200], data[200];
            snprintf(moved, sizeof moved, "1 1 %s", cards[i]);
            snprintf(plain, sizeof plain, "1 %s", cards[i]);
            snprintf(data, sizeof data, "%s%s", star[form], tr[form]);
            prox_cell_model a = model("-1", moved, data), b = model("-1", plain, NULL);
            test_rng r = test_rng_seed(900 + i);
            for (int k = 0; k < 1500; ++k) {
                prox_vec3 x = prox_v3(test_range(&r, -6, 6), test_range(&r, -6, 6), test_range(&r, -6, 6));
                prox_vec3 d = prox_v3(x.x - 1, x.y + 2, x.z - 0.5);
                prox_vec3 xl = prox_v3(c * d.x + s * d.y, -s * d.x + c * d.y, d.z); /* R^T d */
                int ia = prox_cell_contains(&a, 0, x), ib = prox_cell_contains(&b, 0, xl);
                if (ia != ib) {
                    /* allowed only within rounding of a surface: check by nudging */
                    double e = 0;
                    for (size_t q = 0; q < b.nsurfs; ++q) {
                        double v = fabs(prox_surf_eval(&b.surfs[q], xl));
                        e = q ? fmin(e, v) : v;
                    }
                    if (!(e < 1e-9)) {
                        print_error("%s (%s): %d vs %d at (%g %g %g)\n", cards[i], star[form], ia, ib, x.x, x.y, x.z);
                        fail();
                    }
                }
            }
            prox_cells_free(&a);
            prox_cells_free(&b);
        }
}

/* ---- three-valued answers --------------------------------------------------------------------- */

static void test_on_surface(void **state)
{
    (void)state;
    prox_cell_model m = model("-1 2", "1 SO 5\n2 PZ 0", NULL);
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(0, 0, 1)), 1);
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(1, 2, 0)), -1);  /* on the plane, inside the sphere */
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(7, 0, 0)), 0);   /* on the plane, but outside the sphere */
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(0, 0, 5)), -1);  /* on the sphere, above the plane */
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(0, 0, -5)), 0);  /* on the sphere, below the plane */
    prox_cells_free(&m);
    m = model("-1 : 2", "1 SO 5\n2 PZ 0", NULL);
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(7, 0, 0)), -1); /* the plane decides */
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(1, 0, 0)), 1);  /* inside the sphere decides */
    prox_cells_free(&m);
    m = model("#(-1 2)", "1 SO 5\n2 PZ 0", NULL);
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(1, 2, 0)), -1);
    assert_int_equal(prox_cell_contains(&m, 0, prox_v3(7, 0, 0)), 1);
    prox_cells_free(&m);
    /* bad arguments */
    assert_int_equal(prox_cell_contains(NULL, 0, prox_v3(0, 0, 0)), 0);
    assert_true(isnan(prox_surf_eval(NULL, prox_v3(0, 0, 0))));
}

/* Far from the origin: every surface is written about a point of its own, so the sign is right
 * within 1e-8 of a unit-sized surface placed 1e6 away (x - o is then exact to ~1e-10). */
static void test_far_from_origin(void **state)
{
    (void)state;
    static const char *cards[] = {"1 S 1e6 -1e6 2e6 1", "1 RCC 1e6 -1e6 2e6  0 0 1  1", "1 1 SO 1",
                                  "1 1 RPP -1 1 -1 1 -1 1", "1 1 TZ 0 0 0 2 1 1"};
    const prox_vec3 c = prox_v3(1e6, -1e6, 2e6);
    for (size_t k = 0; k < sizeof cards / sizeof cards[0]; ++k) {
        prox_cell_model m = model("-1", cards[k], "tr1 1e6 -1e6 2e6  0.6 0.8 0  -0.8 0.6 0  0 0 1");
        test_rng r = test_rng_seed(40 + k);
        for (int i = 0; i < 500; ++i) {
            /* a point just inside or outside the surface along a random ray from the body's centre */
            prox_vec3 d = test_unit(&r), q;
            double t;
            if (k == 0 || k == 2) t = 1, q = d;
            else if (k == 1) d.z = 0, d = prox_v3_normalize(d), t = 1, q = prox_v3(d.x, d.y, 0.5), d = q; /* cylinder wall */
            else if (k == 3) t = 1 / prox_v3_maxabs(d), q = d;  /* the cube [-1,1]^3 in its own frame */
            else d = prox_v3(d.x, d.y, 0), d = prox_v3_normalize(d), t = 3, q = d; /* torus outer equator */
            double eps = 1e-8;
            int inside = i % 2;
            prox_vec3 loc = k == 1 ? prox_v3(q.x * (inside ? 1 - eps : 1 + eps), q.y * (inside ? 1 - eps : 1 + eps), q.z)
                                   : prox_v3_scale(q, t * (inside ? 1 - eps : 1 + eps));
            prox_vec3 x;
            if (k == 0 || k == 1) x = prox_v3_add(c, loc);
            else x = prox_v3_add(c, prox_v3(0.6 * loc.x - 0.8 * loc.y, 0.8 * loc.x + 0.6 * loc.y, loc.z));
            assert_int_equal(prox_cell_contains(&m, 0, x), inside);
        }
        prox_cells_free(&m);
    }
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_surface_card), cmocka_unit_test(test_surf_eval_sign),
        cmocka_unit_test(test_macrobodies),        cmocka_unit_test(test_facets),
        cmocka_unit_test(test_shape_facets_api),   cmocka_unit_test(test_surface_transforms),
        cmocka_unit_test(test_on_surface),        cmocka_unit_test(test_far_from_origin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
