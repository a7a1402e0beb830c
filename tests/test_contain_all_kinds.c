/* Containment (prox_shape_contains) and the relation's nesting (prox_shape_relation) on every ordered
 * pair of the ten macrobodies, against the test's own long-double brute force (test_kinds_brute.h):
 * the clearance of A in B is min over unit n of h_B(n) - h_A(n) (the distance from a point of A to
 * B's boundary is the least distance to B's supporting planes), minimised over sampled directions and
 * refined. Nested pairs must report that clearance (never more than any direction allows, and the
 * minimum to 1e-9 S); pairs clearly in or out must be judged so; the relation must name the nesting
 * from either side with the same clearance. */
#include "test_kinds_brute.h"
#include "query/query_internal.h" /* prox_query_clearance: the general paths, for the cross-check */

#define NK PROX_SHAPE_KIND_COUNT_


static void set_ctx(const prox_shape *a, const prox_shape *b, int t)
{
    snprintf(ctx, sizeof ctx, "%s in %s trial %d", prox_shape_kind_name(a->kind), prox_shape_kind_name(b->kind), t);
}

/* Brute clearance of A in B. */
static ld brute_clearance(const prox_shape *a, const prox_shape *b)
{
    tk_body A = tk_make(a), B = tk_make(b);
    return tk_minimise(tk_hdiff, &A, &B, 1200, NULL);
}

/* A pair likely nested: B of kind kb (size about 2) at the origin, A of kind ka (size about 0.3 .. 0.6)
 * a little off B's centre. */
static void nested_pair(test_rng *g, int ka, int kb, prox_shape *a, prox_shape *b)
{
    *b = tk_random_shape(g, (prox_shape_kind)kb, prox_v3(0, 0, 0), 2.0);
    prox_vec3 c = prox_v3_scale(test_unit(g), test_range(g, 0.0, 0.4));
    *a = tk_random_shape(g, (prox_shape_kind)ka, c, test_range(g, 0.3, 0.6));
}

/* Nested pairs: the clearance is the brute minimum (one-sided to 1e-12 S: no direction shows less
 * room than reported; the minimum found to 1e-9 S). */
static void test_nested_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(21);
    int nested = 0;
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < 3; ++t) {
                prox_shape a, b;
                nested_pair(&g, ka, kb, &a, &b);
                set_ctx(&a, &b, t);
                double S = prox_shape_pair_scale(&a, &b);
                prox_contain_result c = prox_shape_contains(&a, &b);
                check(c.status == PROX_OK);
                ld brute = brute_clearance(&a, &b);
                if (brute > 0) {
                    ++nested;
                    check(c.inside);
                    check(c.clearance <= brute + 1e-12 * S);
                    check_near(c.clearance, (double)brute, 1e-9 * S);
                }
                prox_contain_result o = prox_shape_contains(&b, &a); /* the big one in the small one */
                check(o.status == PROX_OK && !o.inside);
            }
    check(nested > 200);
}

/* Random pairs of every size ratio: in or out as the brute force says, outside a band of 1e-9 S. When
 * A sticks out, the brute minimum is minus how far (the largest distance of a point of A from B) and
 * the clearance reported is negative and not below it (the face planes of a polytope B, or the slab
 * and lateral surface of a cylinder or cone, may measure less than the Euclidean distance). */
static void test_decision_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(22);
    int in = 0, out = 0;
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb)
            for (int t = 0; t < 3; ++t) {
                prox_shape b = tk_random_shape(&g, (prox_shape_kind)kb, prox_v3(0, 0, 0), 2.0);
                prox_vec3 c = prox_v3_scale(test_unit(&g), test_range(&g, 0.0, 1.2));
                prox_shape a = tk_random_shape(&g, (prox_shape_kind)ka, c, test_range(&g, 0.3, 1.2));
                set_ctx(&a, &b, t);
                double S = prox_shape_pair_scale(&a, &b);
                prox_contain_result r = prox_shape_contains(&a, &b);
                check(r.status == PROX_OK);
                ld brute = brute_clearance(&a, &b);
                if (brute > 1e-9 * S) {
                    check(r.inside);
                    check(r.clearance <= brute + 1e-12 * S);
                    check_near(r.clearance, (double)brute, 1e-9 * S);
                    ++in;
                }
                if (brute < -1e-9 * S) { /* out: negative, and no more than how far A sticks out */
                    check(!r.inside && r.clearance < 0.0);
                    check(r.clearance >= brute - 1e-9 * S);
                    ++out;
                }
            }
    check(in > 50 && out > 50);
}

/* A pair translated so that A touches B's boundary from inside: the clearance found from the brute
 * direction is about 0, and moving A further out by 1e-6 S makes it stick out. */
static void test_flush_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(23);
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb) {
            prox_shape a, b, a2, a3;
            nested_pair(&g, ka, kb, &a, &b);
            set_ctx(&a, &b, 0);
            tk_body A = tk_make(&a), B = tk_make(&b);
            lv3 n;
            ld c0 = tk_minimise(tk_hdiff, &A, &B, 1200, &n);
            if (!(c0 > 0)) continue;
            double S = prox_shape_pair_scale(&a, &b);
            /* moving A by c0 along n takes its support plane onto B's: flush (to the brute's accuracy) */
            prox_vec3 nn = prox_v3((double)n.x, (double)n.y, (double)n.z);
            assert_int_equal(prox_shape_translated(&a, prox_v3_scale(nn, (double)c0), &a2), PROX_OK);
            assert_int_equal(prox_shape_translated(&a, prox_v3_scale(nn, (double)c0 + 1e-6 * S), &a3), PROX_OK);
            prox_contain_result r2 = prox_shape_contains(&a2, &b), r3 = prox_shape_contains(&a3, &b);
            check(fabs(r2.clearance) <= 1e-9 * S);
            check(!r3.inside && r3.clearance <= -0.9e-6 * S);
            prox_relation_result rel = prox_shape_relation(&a2, &b, 1e-9 * S);
            check(rel.status == PROX_OK && rel.relation == PROX_REL_A_IN_B && rel.contact);
        }
}

/* The relation names the nesting from either side, with the clearance of the containment query. */
static void test_relation_nesting_every_pair(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(24);
    for (int ka = 0; ka < NK; ++ka)
        for (int kb = 0; kb < NK; ++kb) {
            prox_shape a, b;
            nested_pair(&g, ka, kb, &a, &b);
            set_ctx(&a, &b, 0);
            prox_contain_result c = prox_shape_contains(&a, &b);
            prox_relation_result r = prox_shape_relation(&a, &b, -1.0), s = prox_shape_relation(&b, &a, -1.0);
            check(r.status == PROX_OK && s.status == PROX_OK);
            if (c.clearance > 1e-9 * prox_shape_pair_scale(&a, &b)) {
                check(r.relation == PROX_REL_A_IN_B && s.relation == PROX_REL_B_IN_A);
                check(r.clearance == c.clearance && s.clearance == c.clearance);
                check(!r.contact && r.signed_distance < 0.0);
            }
        }
}

/* The general paths of containment (faces of a polytope B, corners of a polytope A, a sphere's
 * centre, the farthest point from a sphere's centre, a cylinder's slab and axis) against the
 * specialised solvers of the old pairs (RCC, BOX, RPP, SPH), which the public query uses for them:
 * the same clearance for nested pairs, the same verdict for the others. */
static void test_general_paths_match_specialised(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(25);
    int nested = 0;
    for (int ka = 0; ka <= PROX_SHAPE_SPH; ++ka)
        for (int kb = 0; kb <= PROX_SHAPE_SPH; ++kb)
            for (int t = 0; t < 20; ++t) {
                prox_shape a, b;
                nested_pair(&g, ka, kb, &a, &b);
                set_ctx(&a, &b, t);
                double S = prox_shape_pair_scale(&a, &b);
                int certified;
                prox_contain_result c = prox_shape_contains(&a, &b);
                double gen = prox_query_clearance(&a, &b, &certified);
                check(certified);
                check((gen >= 0.0) == (c.clearance >= 0.0) || fabs(c.clearance) <= 1e-12 * S);
                if (c.clearance > 0.0) {
                    ++nested;
                    check_near(gen, c.clearance, 1e-12 * S);
                }
            }
    check(nested > 100);
}

int main(void)
{
    test_init();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nested_every_pair),
        cmocka_unit_test(test_decision_every_pair),
        cmocka_unit_test(test_flush_every_pair),
        cmocka_unit_test(test_relation_nesting_every_pair),
        cmocka_unit_test(test_general_paths_match_specialised),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
