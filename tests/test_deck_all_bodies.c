/* A deck that uses every macrobody (RCC, BOX, RPP, SPH / SO / S, TRC, REC of 12 and 10 entries, ELL
 * in the foci and the axis (R < 0) forms, RHP of 9 and HEX of 15 entries, WED, ARB), several under
 * TRn cards (cosines, *TRn in degrees, TRn* read as *TRn, M = -1, a 9-entry TR with z' = x' x y'),
 * read by prox_deck_parse and run through a scene in RELATION mode; every body and every pair is
 * checked against geometry written here from the card definitions (tests/test_deck_all_bodies_ref.h:
 * own TR placement, support functions, membership), never against a prox solver:
 *  - each parsed body equals the shape built here from its card and TR, to 1e-14 of its size;
 *  - the relation of each pair equals the one found here: a designed touching pair (with its contact
 *    plane), a separating direction among sampled ones (disjoint), all sampled support points of one
 *    body inside the other (nested), or a common point plus points of each outside the other
 *    (crossing); an undecided pair fails the test;
 *  - disjoint: p1 in A and p2 in B within 1e-12 S, |p2 - p1| = d, and the dual bound
 *    -(h_A(n) + h_B(-n)) >= d - 1e-12 S along n = (p2 - p1)/d; closed forms where they exist
 *    (sphere-sphere, sphere-RPP, RPP-RPP);
 *  - touching: |sd| <= 1e-12 S, the contact plane supports both bodies;
 *  - crossing: phi(n) = h_A(n) + h_B(-n) along the reported repositioning equals the depth within
 *    1e-9 S, and the depth is at most phi along every sampled direction (depth = min phi);
 *  - nested: the clearance equals the closed form where there is one (outer polytope: min over
 *    facets of b_f - h_inner(n_f); inner sphere: distance from its centre to the outer boundary
 *    minus its radius; outer sphere or RCC and inner polytope), within 1e-12 S.
 * S is the larger |coordinate| either body reaches. DECKCHECK_VERBOSE=1 in the environment lists
 * every pair with its relation, signed distance and clearance. */
#include <string.h>

#include "test_util.h"
#include "test_deck_all_bodies_ref.h"
#include "prox/deck.h"
#include "prox/scene.h"

/* One card a line; a line of five leading blanks continues the card above. */
static const char *DECK =
    "every macrobody\n"
    "1 0 -1\n"
    "2 0 1\n"
    "\n"
    "1 RPP -10 10 -10 10 -10 10\n"
    "2 1 ELL 0 0 0  3 0 0  -1.5\n"
    "3 1 SPH 0.5 0.2 0  0.6\n"
    "4 2 BOX -2 -1.5 -1  4 0 0  0 3 0  0 0 2\n"
    "5 2 WED -1 -1 -0.5  2 0 0  0 1.5 0  0 0 1\n"
    "6 RPP 2 5 2 5 -9 -6\n"
    "7 RPP 5 8 2 5 -9 -6\n"
    "8 RCC -5 5 -6  0 0 4  1.5\n"
    "9 3 TRC 0 0 -1.5  0 0 3  1.2 0.4\n"
    "10 5 REC 0 0 0  0 0 3  1.5 0 0  0 0.8 0\n"
    "11 REC 5 -5 2  0 0 3  0 1.2 0  0.6\n"
    "12 4 RHP 0 0 0  0 0 2  0.8 0 0\n"
    "13 4 HEX 1.6 0 0  0 0 2  0.8 0 0  0.4 0.6928203230275509 0  -0.4 0.6928203230275509 0\n"
    "14 ARB -1 -6 9  1 -6 9  1 -4 9  -1 -4 9  -0.5 -5.5 11  0.5 -5.5 11  0.5 -4.5 11  -0.5 -4.5 11\n"
    "      1234 5678 1265 2376 3487 4158\n"
    "15 ELL 0 6 6  3 6 6  2.5\n"
    "16 SO 0.5\n"
    "17 S 0 0 -12 1.5\n"
    "18 SPH 0 0 1.5 1\n"
    "19 RPP -7 -3 3 7 -8 -6\n"
    "20 SO 40\n"
    "21 SPH 5 -5 5  0.8\n"
    "22 3 RPP -0.5 0.5 -0.5 0.5 -0.5 0.5\n"
    "\n"
    "tr1 -5 -5 5  0.6666666666666666 0.6666666666666666 -0.3333333333333333\n"
    "     -0.3333333333333333 0.6666666666666666 0.6666666666666666\n"
    "     0.6666666666666666 -0.3333333333333333 0.6666666666666666\n"
    "*tr2 5 5 5  30 60 90  120 30 90  90 90 0\n"
    "tr3 2.7142857142857144 7.571428571428571 1.1428571428571428\n"
    "     0.2857142857142857 0.42857142857142855 0.8571428571428571\n"
    "     0.42857142857142855 -0.8571428571428571 0.2857142857142857\n"
    "     0.8571428571428571 0.2857142857142857 -0.42857142857142855  -1\n"
    "tr4* -6 -5 -6  0 90 90  90 45 45  90 135 45\n"
    "tr5 5 -5 -3  0.2857142857142857 0.42857142857142855 0.8571428571428571\n"
    "     0.42857142857142855 -0.8571428571428571 0.2857142857142857\n";

/* Pairs placed in contact from outside, by surface number, with the contact normal from the first
 * towards the second in the TR's auxiliary frame of `tr` (0: main frame): two RPPs sharing the face
 * x = 5; the RHP and the HEX sharing the side facet x' = 0.8; SO and SPH meeting at (0, 0, 0.5); the
 * RCC's base disk on the RPP's top face z = -6. */
static const struct { long s1, s2, tr; double n[3]; } TOUCHING[] = {
    {6, 7, 0, {1, 0, 0}}, {12, 13, 4, {1, 0, 0}}, {16, 18, 0, {0, 0, 1}}, {8, 19, 0, {0, 0, -1}},
};

#define NDIR 800

typedef struct ctx {
    ref_deck rd;
    prox_deck deck;
    prox_shape expect[REF_MAX_CARDS];
    ref_body g[REF_MAX_CARDS];
    prox_vec3 dir[NDIR + 6];
    int ndir;
    int count[5];   /* pairs seen per relation */
    int closed[2];  /* disjoint pairs with a closed-form distance, nested pairs with a closed-form clearance */
} ctx;

static const ref_card *tr_card(const ref_deck *rd, long n)
{
    for (int i = 0; i < rd->ntr; ++i)
        if (rd->tr[i].number == n) return &rd->tr[i];
    print_error("TR%ld not in the deck\n", n);
    fail();
    return NULL;
}

/* ---- step 1: each parsed body against the shape built from its card ---- */

static void near_v(prox_vec3 a, prox_vec3 e, double tol, long surf, const char *what)
{
    double d = prox_v3_maxabs(prox_v3_sub(a, e));
    if (!(d <= tol)) {
        print_error("surface %ld %s: (%.17g %.17g %.17g) expected (%.17g %.17g %.17g), |diff| %.3g > %.3g\n", surf,
                    what, a.x, a.y, a.z, e.x, e.y, e.z, d, tol);
        fail();
    }
}

static void near_s(double a, double e, double tol, long surf, const char *what)
{
    if (!(fabs(a - e) <= tol)) {
        print_error("surface %ld %s: %.17g expected %.17g\n", surf, what, a, e);
        fail();
    }
}

/* The ELL axis may point either way (the same solid). */
static void near_axis(prox_vec3 a, prox_vec3 e, double tol, long surf)
{
    if (prox_v3_dot(a, e) < 0) a = prox_v3_neg(a);
    near_v(a, e, tol, surf, "ELL axis");
}

static void compare_shape(const prox_shape *a, const prox_shape *e, double tol, long s)
{
    assert_int_equal(a->kind, e->kind);
    switch (e->kind) {
    case PROX_SHAPE_RPP:
        near_s(a->u.rpp.xmin, e->u.rpp.xmin, tol, s, "xmin"), near_s(a->u.rpp.xmax, e->u.rpp.xmax, tol, s, "xmax");
        near_s(a->u.rpp.ymin, e->u.rpp.ymin, tol, s, "ymin"), near_s(a->u.rpp.ymax, e->u.rpp.ymax, tol, s, "ymax");
        near_s(a->u.rpp.zmin, e->u.rpp.zmin, tol, s, "zmin"), near_s(a->u.rpp.zmax, e->u.rpp.zmax, tol, s, "zmax");
        break;
    case PROX_SHAPE_BOX:
        near_v(a->u.box.corner, e->u.box.corner, tol, s, "corner");
        for (int k = 0; k < 3; ++k) near_v(a->u.box.edge[k], e->u.box.edge[k], tol, s, "edge");
        break;
    case PROX_SHAPE_SPH:
        near_v(a->u.sph.center, e->u.sph.center, tol, s, "centre");
        near_s(a->u.sph.radius, e->u.sph.radius, tol, s, "radius");
        break;
    case PROX_SHAPE_RCC:
        near_v(a->u.rcc.base, e->u.rcc.base, tol, s, "base"), near_v(a->u.rcc.axis, e->u.rcc.axis, tol, s, "axis");
        near_s(a->u.rcc.radius, e->u.rcc.radius, tol, s, "radius");
        break;
    case PROX_SHAPE_TRC:
        near_v(a->u.trc.base, e->u.trc.base, tol, s, "base"), near_v(a->u.trc.axis, e->u.trc.axis, tol, s, "axis");
        near_s(a->u.trc.r1, e->u.trc.r1, tol, s, "r1"), near_s(a->u.trc.r2, e->u.trc.r2, tol, s, "r2");
        break;
    case PROX_SHAPE_REC:
        near_v(a->u.rec.base, e->u.rec.base, tol, s, "base"), near_v(a->u.rec.axis, e->u.rec.axis, tol, s, "axis");
        near_v(a->u.rec.a1, e->u.rec.a1, tol, s, "a1"), near_v(a->u.rec.a2, e->u.rec.a2, tol, s, "a2");
        break;
    case PROX_SHAPE_ELL:
        near_v(a->u.ell.center, e->u.ell.center, tol, s, "centre"), near_axis(a->u.ell.axis, e->u.ell.axis, tol, s);
        near_s(a->u.ell.radius, e->u.ell.radius, tol, s, "radius");
        break;
    case PROX_SHAPE_RHP:
        near_v(a->u.rhp.base, e->u.rhp.base, tol, s, "base"), near_v(a->u.rhp.axis, e->u.rhp.axis, tol, s, "axis");
        for (int k = 0; k < 3; ++k) near_v(a->u.rhp.r[k], e->u.rhp.r[k], tol, s, "facet vector");
        break;
    case PROX_SHAPE_WED:
        near_v(a->u.wed.vertex, e->u.wed.vertex, tol, s, "vertex"), near_v(a->u.wed.v1, e->u.wed.v1, tol, s, "v1");
        near_v(a->u.wed.v2, e->u.wed.v2, tol, s, "v2"), near_v(a->u.wed.v3, e->u.wed.v3, tol, s, "v3");
        break;
    case PROX_SHAPE_ARB:
        for (int k = 0; k < 8; ++k) near_v(a->u.arb.corner[k], e->u.arb.corner[k], tol, s, "corner");
        for (int k = 0; k < 6; ++k) assert_int_equal(a->u.arb.face[k], e->u.arb.face[k]);
        break;
    default: fail();
    }
}

/* Size of a body for the relative tolerances: the largest |coordinate| it reaches (>= 1). */
static double body_scale(const ref_body *g)
{
    double s = 1;
    for (int k = 0; k < 3; ++k) {
        prox_vec3 e = prox_v3(k == 0, k == 1, k == 2);
        s = fmax(s, fmax(ref_h(g, e, NULL), ref_h(g, prox_v3_neg(e), NULL)));
    }
    return s;
}

static void build(ctx *c, const char *text)
{
    ref_read_deck(text, &c->rd);
    assert_int_equal(prox_deck_parse(text, &c->deck), PROX_OK);
    for (size_t i = 0; i < c->deck.nerrors; ++i) print_message("error line %d: %s\n", c->deck.errors[i].line, c->deck.errors[i].text);
    assert_int_equal(c->deck.nerrors, 0);
    assert_int_equal(c->deck.nunsupported, 0);
    assert_int_equal((int)c->deck.nbodies, c->rd.nsurf);
    for (int i = 0; i < c->rd.nsurf; ++i) {
        const ref_card *card = &c->rd.surf[i];
        const prox_deck_body *b = &c->deck.bodies[i];
        assert_int_equal(b->surface, card->number);
        assert_int_equal(b->tr, card->tr);
        assert_true(ref_local_shape(card, &c->expect[i]));
        if (card->tr) {
            ref_tr t = ref_tr_of(tr_card(&c->rd, card->tr));
            ref_move(&c->expect[i], &t);
        }
        c->g[i] = ref_body_of(&c->expect[i]);
        compare_shape(&b->shape, &c->expect[i], 1e-14 * body_scale(&c->g[i]), card->number);
    }
    /* Directions: a Fibonacci lattice on the sphere and the coordinate axes. */
    c->ndir = 0;
    for (int k = 0; k < NDIR; ++k) {
        double z = 1 - (2 * k + 1.0) / NDIR, r = sqrt(1 - z * z), ph = k * REF_PI * (3 - sqrt(5.0));
        c->dir[c->ndir++] = prox_v3(r * cos(ph), r * sin(ph), z);
    }
    for (int k = 0; k < 6; ++k) {
        double s = k < 3 ? 1 : -1;
        c->dir[c->ndir++] = prox_v3(s * (k % 3 == 0), s * (k % 3 == 1), s * (k % 3 == 2));
    }
}

/* The closed-form support functions agree with the support points (the two evaluations of h). */
static void check_support_forms(const ctx *c)
{
    for (int i = 0; i < c->rd.nsurf; ++i) {
        const ref_body *g = &c->g[i];
        double S = body_scale(g);
        for (int k = 0; k < c->ndir; ++k) {
            prox_vec3 p;
            double h = ref_h(g, c->dir[k], &p);
            assert_near(ref_h_formula(g, c->dir[k]), h, 1e-13 * S);
            assert_true(ref_f(g, p) <= 1e-12 * S); /* a support point lies on the body */
        }
    }
}

/* ---- step 2: each pair against the geometry written here ---- */

static int touching_normal(const ctx *c, long s1, long s2, prox_vec3 *n)
{
    for (size_t k = 0; k < sizeof TOUCHING / sizeof TOUCHING[0]; ++k)
        if (TOUCHING[k].s1 == s1 && TOUCHING[k].s2 == s2) {
            *n = prox_v3(TOUCHING[k].n[0], TOUCHING[k].n[1], TOUCHING[k].n[2]);
            if (TOUCHING[k].tr) {
                ref_tr t = ref_tr_of(tr_card(&c->rd, TOUCHING[k].tr));
                *n = ref_tr_vec(&t, *n);
            }
            return 1;
        }
    return 0;
}

/* phi(n) = h_A(n) + h_B(-n): the overlap of the two bodies' shadows along n (< 0: a gap). */
static double phi(const ref_body *a, const ref_body *b, prox_vec3 n)
{
    return ref_h(a, n, NULL) + ref_h(b, prox_v3_neg(n), NULL);
}

/* What the sampled support points say: are all of A's in B, is one of A's outside B, is a point of
 * A (support point or centre) strictly inside B. */
typedef struct sampled {
    int a_in_b, a_out_b, common;
} sampled;

static sampled sample(const ctx *c, const ref_body *a, const ref_body *b, double tol)
{
    sampled s = {1, 0, ref_f(b, a->c) < -tol};
    for (int k = 0; k < c->ndir; ++k) {
        prox_vec3 p;
        ref_h(a, c->dir[k], &p);
        double f = ref_f(b, p);
        if (f > tol) s.a_in_b = 0, s.a_out_b = 1;
        if (f < -tol) s.common = 1;
    }
    return s;
}

static prox_relation expected_relation(const ctx *c, size_t i, size_t j, double S)
{
    const ref_body *a = &c->g[i], *b = &c->g[j];
    const double tol = 1e-12 * S;
    prox_vec3 n;
    if (touching_normal(c, c->rd.surf[i].number, c->rd.surf[j].number, &n)) {
        assert_near(phi(a, b, n), 0, tol); /* the contact plane supports both bodies from either side */
        return PROX_REL_TOUCHING;
    }
    double gap = -INFINITY;
    for (int k = 0; k < c->ndir; ++k) gap = fmax(gap, -phi(a, b, c->dir[k]));
    if (gap > 1e-9 * S) return PROX_REL_DISJOINT;
    sampled ab = sample(c, a, b, tol), ba = sample(c, b, a, tol);
    if (ab.a_in_b) return PROX_REL_A_IN_B;
    if (ba.a_in_b) return PROX_REL_B_IN_A;
    if ((ab.common || ba.common) && ab.a_out_b && ba.a_out_b) return PROX_REL_CROSSING;
    print_error("surfaces %ld and %ld: the sampled geometry decides nothing (gap %.3g)\n", c->rd.surf[i].number,
                c->rd.surf[j].number, gap);
    fail();
    return PROX_REL_DISJOINT;
}

/* Closed-form distances of disjoint pairs: sphere-sphere, sphere-RPP, RPP-RPP. NAN when none applies. */
static double closed_distance(const prox_shape *a, const prox_shape *b)
{
    if (a->kind == PROX_SHAPE_RPP && b->kind == PROX_SHAPE_RPP) { /* the per-axis gaps */
        const prox_rpp *p = &a->u.rpp, *q = &b->u.rpp;
        double gx = fmax(0, fmax(q->xmin - p->xmax, p->xmin - q->xmax));
        double gy = fmax(0, fmax(q->ymin - p->ymax, p->ymin - q->ymax));
        double gz = fmax(0, fmax(q->zmin - p->zmax, p->zmin - q->zmax));
        return sqrt(gx * gx + gy * gy + gz * gz);
    }
    if (a->kind != PROX_SHAPE_SPH && b->kind == PROX_SHAPE_SPH) return closed_distance(b, a);
    if (a->kind != PROX_SHAPE_SPH) return NAN;
    prox_vec3 c = a->u.sph.center;
    if (b->kind == PROX_SHAPE_SPH) return prox_v3_dist(c, b->u.sph.center) - a->u.sph.radius - b->u.sph.radius;
    if (b->kind != PROX_SHAPE_RPP) return NAN;
    const prox_rpp *r = &b->u.rpp;
    prox_vec3 q = prox_v3(fmin(fmax(c.x, r->xmin), r->xmax), fmin(fmax(c.y, r->ymin), r->ymax),
                          fmin(fmax(c.z, r->zmin), r->zmax));
    return prox_v3_dist(c, q) - a->u.sph.radius;
}

/* Clearance of inner inside outer where it has a closed form; NAN otherwise. Outer polytope: the
 * distance of an interior point to the boundary is the least facet-plane distance, so the clearance
 * is min over facets of b_f - h_inner(n_f). Inner sphere: distance of its centre to the boundary
 * minus its radius. Outer sphere, inner polytope: radius minus the farthest corner's distance; outer
 * RCC, inner polytope: the least over the corners of the distances to the side and to the caps. */
static double closed_clearance(const ref_body *in, const ref_body *out)
{
    if (out->poly) {
        double m = INFINITY;
        for (int k = 0; k < out->nplane; ++k) m = fmin(m, out->pb[k] - ref_h(in, out->pn[k], NULL));
        return m;
    }
    if (in->kind == PROX_SHAPE_SPH) {
        double inside = -ref_f(out, in->c); /* exact for SPH and ELL */
        if (out->kind == PROX_SHAPE_SPH || out->kind == PROX_SHAPE_ELL) return inside - in->r;
        if (out->kind == PROX_SHAPE_RCC) return -fmax(prox_v3_norm(prox_v3_reject(prox_v3_sub(in->c, out->c), out->w)) - out->r,
                                                      fabs(prox_v3_dot(prox_v3_sub(in->c, out->c), out->w)) - out->hh) - in->r;
        return NAN;
    }
    if (out->kind == PROX_SHAPE_RCC && in->poly) { /* min(r - rho, hh - |t|) over the corners */
        double m = INFINITY;
        for (int k = 0; k < in->ncorner; ++k) {
            prox_vec3 d = prox_v3_sub(in->corner[k], out->c);
            m = fmin(m, fmin(out->r - prox_v3_norm(prox_v3_reject(d, out->w)), out->hh - fabs(prox_v3_dot(d, out->w))));
        }
        return m;
    }
    if (out->kind == PROX_SHAPE_SPH && in->poly) {
        double m = 0;
        for (int k = 0; k < in->ncorner; ++k) m = fmax(m, prox_v3_dist(in->corner[k], out->c));
        return out->r - m;
    }
    return NAN;
}

static void check_disjoint(ctx *c, size_t i, size_t j, const prox_pair_result *r, double S)
{
    const ref_body *a = &c->g[i], *b = &c->g[j];
    const double tol = 1e-12 * S;
    double d = r->distance;
    assert_true(d > 0);
    assert_near(r->signed_distance, d, tol);
    assert_true(ref_f(a, r->p1) <= tol);
    assert_true(ref_f(b, r->p2) <= tol);
    prox_vec3 v = prox_v3_sub(r->p2, r->p1);
    double len = prox_v3_norm(v);
    assert_near(len, d, tol);
    double lower = -phi(a, b, prox_v3_scale(v, 1.0 / len)); /* the dual bound along the witness line */
    if (!(lower >= d - tol)) {
        print_error("surfaces %ld-%ld: dual bound %.17g < distance %.17g\n", c->rd.surf[i].number, c->rd.surf[j].number,
                    lower, d);
        fail();
    }
    double cf = closed_distance(&c->expect[i], &c->expect[j]);
    if (isnan(cf)) return;
    assert_near(d, cf, tol);
    c->closed[0]++;
}

static void check_touching(const ctx *c, size_t i, size_t j, const prox_pair_result *r, double S)
{
    const double tol = 1e-12 * S;
    assert_near(r->signed_distance, 0, tol);
    assert_true(ref_f(&c->g[i], r->p1) <= tol);
    assert_true(ref_f(&c->g[j], r->p2) <= tol);
    assert_near(prox_v3_dist(r->p1, r->p2), 0, tol);
}

static void check_crossing(const ctx *c, size_t i, size_t j, const prox_pair_result *r, double S)
{
    const ref_body *a = &c->g[i], *b = &c->g[j];
    double depth = r->depth, len = prox_v3_norm(r->reposition);
    assert_true(depth > 0);
    assert_near(r->signed_distance, -depth, 1e-12 * S);
    assert_near(len, depth, 1e-12 * S);
    double along = phi(a, b, prox_v3_scale(r->reposition, 1.0 / len)); /* moving B by depth n separates */
    if (!(fabs(along - depth) <= 1e-9 * S)) {
        print_error("surfaces %ld-%ld: phi(n) %.17g, depth %.17g\n", c->rd.surf[i].number, c->rd.surf[j].number, along, depth);
        fail();
    }
    for (int k = 0; k < c->ndir; ++k) /* depth = min over n of phi(n) */
        assert_true(depth <= phi(a, b, c->dir[k]) + 1e-9 * S);
}

static void check_nested(ctx *c, size_t in, size_t out, const prox_pair_result *r, double S)
{
    double cl = closed_clearance(&c->g[in], &c->g[out]);
    assert_true(r->clearance >= -1e-12 * S);
    if (isnan(cl)) return;
    c->closed[1]++;
    if (!(fabs(r->clearance - cl) <= 1e-12 * S)) {
        print_error("surface %ld in %ld: clearance %.17g, closed form %.17g\n", c->rd.surf[in].number,
                    c->rd.surf[out].number, r->clearance, cl);
        fail();
    }
}

static const char *REL_NAME[] = {"disjoint", "touching", "crossing", "A in B", "B in A"};

static void check_pairs(ctx *c, prox_relation (*expect)(const ctx *, size_t, size_t, double))
{
    prox_scene *s = prox_scene_create();
    assert_non_null(s);
    for (size_t i = 0; i < c->deck.nbodies; ++i) assert_int_equal(prox_scene_add(s, &c->deck.bodies[i].shape), PROX_OK);
    prox_scene_report rep = prox_scene_pairs(s, INFINITY, PROX_MODE_RELATION);
    assert_int_equal(rep.status, PROX_OK);
    size_t n = c->deck.nbodies;
    assert_int_equal(rep.npairs, n * (n - 1) / 2);
    memset(c->count, 0, sizeof c->count);
    memset(c->closed, 0, sizeof c->closed);
    for (size_t k = 0; k < rep.npairs; ++k) {
        const prox_scene_pair *p = &rep.pairs[k];
        const prox_pair_result *r = &p->r;
        double S = fmax(body_scale(&c->g[p->a]), body_scale(&c->g[p->b]));
        assert_int_equal(r->status, PROX_OK);
        prox_relation e = expect(c, p->a, p->b, S);
        if (r->relation != e) {
            print_error("surfaces %ld-%ld: prox says %s, the geometry here %s (sd %.17g)\n", c->rd.surf[p->a].number,
                        c->rd.surf[p->b].number, REL_NAME[r->relation], REL_NAME[e], r->signed_distance);
            fail();
        }
        c->count[e]++;
        if (getenv("DECKCHECK_VERBOSE"))
            print_message("%ld-%ld %s sd %.17g clearance %.17g\n", c->rd.surf[p->a].number, c->rd.surf[p->b].number,
                          REL_NAME[e], r->signed_distance, r->clearance);
        switch (e) {
        case PROX_REL_DISJOINT: check_disjoint(c, p->a, p->b, r, S); break;
        case PROX_REL_TOUCHING: check_touching(c, p->a, p->b, r, S); break;
        case PROX_REL_CROSSING: check_crossing(c, p->a, p->b, r, S); break;
        case PROX_REL_A_IN_B: check_nested(c, p->a, p->b, r, S); break;
        case PROX_REL_B_IN_A: check_nested(c, p->b, p->a, r, S); break;
        }
    }
    prox_scene_report_free(&rep);
    prox_scene_destroy(s);
}

static void test_bodies_and_pairs(void **state)
{
    (void)state;
    static ctx c;
    build(&c, DECK);
    check_support_forms(&c);
    check_pairs(&c, expected_relation);
    print_message("pairs: %d disjoint, %d touching, %d crossing, %d A in B, %d B in A\n", c.count[0], c.count[1],
                  c.count[2], c.count[3], c.count[4]);
    print_message("closed forms: %d distances, %d clearances\n", c.closed[0], c.closed[1]);
    /* the deck holds every relation, and the designed ones */
    for (int k = 0; k < 5; ++k) assert_true(c.count[k] > 0);
    assert_int_equal(c.count[PROX_REL_TOUCHING], (int)(sizeof TOUCHING / sizeof TOUCHING[0]));
    prox_deck_free(&c.deck);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bodies_and_pairs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
