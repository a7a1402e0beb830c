/* libFuzzer harness of pairs, two kinds of input chosen by the first byte.
 *
 * First byte < 0x80: the text the CLI reads in `prox pairs` (src/cli/pairs.c, cylinder pairs): the
 * bytes become stdin of prox_cli_pairs (through a temporary file), in the mode chosen by the first byte
 * modulo 3 (distance, --signed, --test) and with the method chosen by the first byte / 3 modulo 3
 * (--method fast, closed-form, support); run.sh passes -close_fd_mask=3 to silence its output.
 * Contract: no crash, no leak, exit status 0 or 1 (2 only for usage errors, never for data).
 *
 * First byte >= 0x80: a pair of any two of the ten macrobodies (byte 1: kind A in the low nibble, kind
 * B in the high one, modulo 10; bits 0-1 and 2-3 of byte 0: their fz_shape variants; raw doubles from
 * byte 2, B from double FZ_SHAPE_DOUBLES) and the properties of a pair answer (check_pair below). */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "cli/cli.h"
#include "fuzz_common.h"

/* A broken property prints the condition and its line (so a crash file explains itself), then traps. */
#define CHECK(c)                                                                    \
    do {                                                                            \
        if (!(c)) {                                                                 \
            fprintf(stderr, "fuzz_pairs.c:%d: contract broken: %s\n", __LINE__, #c); \
            __builtin_trap();                                                       \
        }                                                                           \
    } while (0)

/* Relative tolerances (x the pair scale S) of the pair properties. They are far looser than the
 * library's accuracy bar (1e-12 S for distances and points) so that only a wrong answer trips them:
 * PAIR_SYM_TOL for d(A, B) = d(B, A) and |p1 - p2| = d, PAIR_ON_TOL for a witness point lying in its
 * shape (measured as the distance of a point-sized sphere at it to the shape). */
#define PAIR_SYM_TOL 1e-9
#define PAIR_ON_TOL 1e-9

/* The rounding of a witness point's own coordinates: a pair 1e-57 across lying 5e-33 from the origin
 * (raw doubles make such pairs) has witnesses that cannot be placed closer than an ulp of 5e-33, and
 * the tolerances below add this to their share of S. */
static double coord_round(prox_vec3 p, prox_vec3 q)
{
    double m = fmax(fmax(fabs(p.x), fabs(p.y)), fmax(fabs(p.z), fmax(fmax(fabs(q.x), fabs(q.y)), fabs(q.z))));
    return 8.0 * DBL_EPSILON * m;
}

/* Distance from point q to shape s by the sphere queries (a sphere of radius r tiny against S; the
 * callers keep r at least PROX_MIN_SIZE, below which the sphere would be out of range: a pair 4e-93
 * across gets a witness sphere of 1e-100, 2.5e-8 of its scale). */
static double point_gap(const prox_shape *s, prox_vec3 q, double r)
{
    prox_shape ball = prox_shape_from_sph((prox_sph){q, r});
    prox_distance_result d = prox_shape_distance(s, &ball);
    return d.status == PROX_OK ? d.distance : NAN;
}

/* Properties of the answers for two valid shapes A and B: distance symmetric in A and B; |p1 - p2| is
 * the distance; p1 in A and p2 in B; the signed distance equals the distance when positive, and its
 * witnesses p2 - p1 = sd normal with a unit normal. */
static void check_pair(const prox_shape *a, const prox_shape *b)
{
    double S = prox_shape_pair_scale(a, b);
    if (!(S > 0.0) || !(S <= 1e90)) return; /* the witness spheres need room below the range */
    prox_distance_result ab = prox_shape_distance(a, b), ba = prox_shape_distance(b, a);
    CHECK(ab.status == PROX_OK && ba.status == PROX_OK);
    double tol = PAIR_SYM_TOL * S, ta = tol + coord_round(ab.p1, ab.p2);
    CHECK(fabs(ab.distance - ba.distance) <= tol + fmax(coord_round(ab.p1, ab.p2), coord_round(ba.p1, ba.p2)));
    CHECK(fabs(prox_v3_norm(prox_v3_sub(ab.p2, ab.p1)) - ab.distance) <= ta);
    double r = fmax(PAIR_ON_TOL * S + coord_round(ab.p1, ab.p2), PROX_MIN_SIZE);
    CHECK(point_gap(a, ab.p1, r) <= r);
    CHECK(point_gap(b, ab.p2, r) <= r);
    prox_signed_result g = prox_shape_signed_distance(a, b);
    CHECK(g.status == PROX_OK);
    double tg = tol + coord_round(g.p1, g.p2), rg = fmax(PAIR_ON_TOL * S + coord_round(g.p1, g.p2), PROX_MIN_SIZE);
    if (ab.distance > tol) CHECK(fabs(g.sd - ab.distance) <= fmax(ta, tg));
    CHECK(point_gap(a, g.p1, rg) <= rg);
    CHECK(point_gap(b, g.p2, rg) <= rg);
    CHECK(fabs(prox_v3_norm(g.normal) - 1.0) <= PAIR_SYM_TOL);
    CHECK(prox_v3_norm(prox_v3_sub(prox_v3_sub(g.p2, g.p1), prox_v3_scale(g.normal, g.sd))) <= tg);
    /* the proved enclosure holds the answer, and a certified one is within the depth bar */
    CHECK(g.sd_lower <= g.sd && g.sd <= g.sd_upper);
    if (g.certified) CHECK(g.sd_upper - g.sd_lower <= PAIR_SYM_TOL * S);
}

/* The binary branch: two shapes of the ten kinds, their pair properties when both are valid. */
static int fuzz_shape_pair(const uint8_t *data, size_t size)
{
    if (size < 2) return 0;
    const uint8_t *p = data + 2;
    size_t n = size - 2;
    prox_shape a = fz_shape((data[1] & 15) % 10, data[0] & 3, p, n, 0);
    prox_shape b = fz_shape((data[1] >> 4) % 10, (data[0] >> 2) & 3, p, n, FZ_SHAPE_DOUBLES);
    if (prox_shape_validate(&a) != PROX_OK || prox_shape_validate(&b) != PROX_OK) return 0;
    if (!(fz_max_abs(p, n, 2 * FZ_SHAPE_DOUBLES) <= 1e100)) return 0;
    check_pair(&a, &b);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[64];
    if (!path[0]) snprintf(path, sizeof path, "/tmp/prox_fuzz_pairs_%ld.txt", (long)getpid());
    if (size < 1) return 0;
    if (data[0] >= 0x80) return fuzz_shape_pair(data, size);
    FILE *f = fopen(path, "wb");
    if (!f) return 0;
    fwrite(data + 1, 1, size - 1, f);
    fclose(f);
    if (!freopen(path, "rb", stdin)) return 0;
    char a0[] = "pairs", a1[] = "--signed", a2[] = "--test", am[] = "--method";
    char m0[] = "fast", m1[] = "closed-form", m2[] = "support";
    char *methods[3] = {m0, m1, m2};
    char *argv[5] = {a0, am, methods[(data[0] / 3) % 3], data[0] % 3 == 1 ? a1 : a2, NULL};
    int argc = data[0] % 3 == 0 ? 3 : 4;
    int rc = prox_cli_pairs(argc, argv);
    if (rc != 0 && rc != 1) __builtin_trap();
    return 0;
}
