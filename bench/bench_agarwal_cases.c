/* prox_bench --agarwal-cases: which definition of Agarwal's first-level case reproduces the case
 * distribution of the paper's Fig. 10 (Agarwal, Srivatsan & Bandyopadhyay 2016, Sec. 5: 51.45 % of
 * near-field trials in Case 1, 34.12 % Case 1 with interference; 28.12 % Case 1 in the far field)?
 * No timing: for each sampling of the random trials and each case definition, the share of Case 1,
 * 2 and 3 in the near field (|o| <= max(l1 + l2, r1 + r2)) and in the far field, and the share of
 * Case 1 trials whose cylinders interfere (prox_rcc_distance). Definitions, from the feet s, t of the
 * common perpendicular of the axis lines (s along A from its base, t along B from its base):
 *   lines      s in [0, l1] and t in [0, l2] (prox's definition, Sec. 2 with p* in E_i);
 *   lines+int  as "lines", and every interfering pair counted as Case 1;
 *   surfaces   P(S1, S2) of the infinite lateral surfaces: when the axis lines are closer than r1 + r2
 *              the surfaces meet along a curve, and the pair is Case 1 when a point of that curve
 *              lies on both finite cylinders (sampled: 256 angles around A, a quadratic in s each);
 *              otherwise as "lines";
 *   [-1,1]     s in [-l1, l1], t in [-l2, l2] (a [-1, 1] range test on the normalised parameter whose
 *              origin is the base);
 *   unitlen    s in [0, 1], t in [0, 1] with s, t in length units (a normalisation slip the other way);
 *   doubled    s in [-l1/2, 3 l1/2], t likewise (a [-1, 1] test on a parameter centred at mid-axis
 *              with half-length units read as full length);
 *   A-foot     Case 1 when s in [0, l1] alone (the fixed cylinder's foot), B-foot when t in [0, l2]
 *              alone, either when one of them is (Case 1 or 2.1 of "lines").
 * Samplings: "ball" (protocol A: base of B uniform in the ball |o| <= 25), "radial" (|o| uniform in
 * (0, 25], direction uniform: the literal reading of "0 < |o| <= 5 l1"), "centre" (as "ball" but o
 * is the centre of B, the base at o - axis / 2). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

enum { NDEF = 9 };
static const char *const k_defs[NDEF] = {"lines", "lines+int", "surfaces", "[-1,1]", "unitlen", "doubled",
                                        "A-foot", "B-foot", "either"};

/* Feet of the common perpendicular of the axis lines (parallel: returns 0). */
static int line_feet(const prox_rcc *a, const prox_rcc *b, double *s, double *t)
{
    prox_vec3 u = a->axis, v = b->axis, w = prox_v3_sub(a->base, b->base);
    double A = prox_v3_dot(u, u), B = prox_v3_dot(u, v), C = prox_v3_dot(v, v);
    double D = prox_v3_dot(u, w), E = prox_v3_dot(v, w), den = A * C - B * B;
    if (den <= 1e-14 * A * C) return 0;
    double sn = (B * E - C * D) / den, tn = (A * E - B * D) / den; /* normalised (0..1 on the segments) */
    *s = sn * sqrt(A), *t = tn * sqrt(C);
    return 1;
}

/* Does the intersection curve of the infinite lateral surfaces have a point on both finite
 * cylinders? Points of A's surface a0 + s w + rA (cos th e1 + sin th e2) at distance rB from B's
 * axis line: a quadratic in s for each sampled angle th. */
static int surfaces_meet_on_both(const prox_rcc *a, const prox_rcc *b)
{
    double ha = prox_v3_norm(a->axis), hb = prox_v3_norm(b->axis);
    prox_vec3 w = prox_v3_scale(a->axis, 1.0 / ha), wb = prox_v3_scale(b->axis, 1.0 / hb);
    prox_vec3 e1 = prox_v3_any_perp(w), e2 = prox_v3_cross(w, e1);
    for (int k = 0; k < 256; ++k) {
        double th = 2.0 * PROX_PI * k / 256.0;
        prox_vec3 q0 = prox_v3_sub(prox_v3_add(a->base, prox_v3_add(prox_v3_scale(e1, a->radius * cos(th)),
                                                                    prox_v3_scale(e2, a->radius * sin(th)))),
                                   b->base);
        /* perpendicular part to wb of q0 + s w: p0 + s p1 */
        prox_vec3 p0 = prox_v3_mad(q0, -prox_v3_dot(q0, wb), wb), p1 = prox_v3_mad(w, -prox_v3_dot(w, wb), wb);
        double qa = prox_v3_dot(p1, p1), qb = 2.0 * prox_v3_dot(p0, p1), qc = prox_v3_dot(p0, p0) - b->radius * b->radius;
        double disc = qb * qb - 4.0 * qa * qc;
        if (qa <= 0.0 || disc < 0.0) continue;
        for (int sg = -1; sg <= 1; sg += 2) {
            double s = (-qb + sg * sqrt(disc)) / (2.0 * qa);
            double t = prox_v3_dot(prox_v3_mad(q0, s, w), wb);
            if (s >= 0.0 && s <= ha && t >= 0.0 && t <= hb) return 1;
        }
    }
    return 0;
}

/* Case (1, 2 or 3) of one pair under one definition. */
static int case_of(int def, const prox_rcc *a, const prox_rcc *b, int interfere)
{
    double s, t, ha = prox_v3_norm(a->axis), hb = prox_v3_norm(b->axis);
    if (!line_feet(a, b, &s, &t)) return 3;
    double lo_a = 0.0, hi_a = ha, lo_b = 0.0, hi_b = hb;
    if (def == 3) lo_a = -ha, lo_b = -hb;
    if (def == 4) hi_a = 1.0, hi_b = 1.0;
    if (def == 5) lo_a = -0.5 * ha, hi_a = 1.5 * ha, lo_b = -0.5 * hb, hi_b = 1.5 * hb;
    int on1 = s >= lo_a && s <= hi_a, on2 = t >= lo_b && t <= hi_b;
    if (def == 1 && interfere) return 1;
    if (def == 6) return on1 ? 1 : (on2 ? 2 : 3);
    if (def == 7) return on2 ? 1 : (on1 ? 2 : 3);
    if (def == 8) return on1 || on2 ? 1 : 3;
    if (def == 2) {
        prox_vec3 pa = prox_v3_mad(a->base, s / ha, a->axis), pb = prox_v3_mad(b->base, t / hb, b->axis);
        if (prox_v3_dist(pa, pb) < a->radius + b->radius) return surfaces_meet_on_both(a, b) ? 1 : (on1 || on2 ? 2 : 3);
    }
    return on1 && on2 ? 1 : (on1 || on2 ? 2 : 3);
}

/* One trial of a sampling; *o is the frame origin of B used for near / far. */
static void sample(bench_rng *r, int sampling, prox_rcc *a, prox_rcc *b, prox_vec3 *o)
{
    double rb = 20.0 * (1.0 - bench_uniform(r)), hb = 50.0 * (1.0 - bench_uniform(r));
    prox_vec3 p;
    if (sampling == 1) {
        p = prox_v3_scale(bench_unit(r), 25.0 * (1.0 - bench_uniform(r)));
    } else {
        do {
            p = prox_v3(bench_range(r, -25, 25), bench_range(r, -25, 25), bench_range(r, -25, 25));
        } while (prox_v3_norm(p) > 25.0);
    }
    bench_rot R = bench_random_rot(r);
    prox_vec3 ax = bench_rot_apply(&R, prox_v3(0, 0, hb));
    *a = (prox_rcc){prox_v3(0, 0, 0), prox_v3(0, 0, 5), 2};
    *b = (prox_rcc){sampling == 2 ? prox_v3_mad(p, -0.5, ax) : p, ax, rb};
    *o = p;
}

void bench_agarwal_case_study(const bench_opts *o)
{
    static const char *const samplings[3] = {"ball", "radial", "centre"};
    size_t n = o->pairs > 0 ? (size_t)o->pairs : (o->quick ? 20000 : 200000);
    printf("# Agarwal case definitions against Fig. 10 (paper: near Case 1 51.45 %%, of which interfering "
           "34.12 %% of all near trials; far Case 1 28.12 %%); %zu trials per sampling, seed 2016\n", n);
    printf("%-8s %-10s %8s | %8s %8s %8s %10s | %8s %8s %8s %10s\n", "sampling", "definition", "near%", "n:case1",
           "n:case2", "n:case3", "n:c1&int", "f:case1", "f:case2", "f:case3", "f:c1&int");
    for (int sm = 0; sm < 3; ++sm) {
        size_t cnt[NDEF][2][4] = {{{0}}}, c1int[NDEF][2] = {{0}}, nn[2] = {0, 0};
        bench_rng r = bench_rng_seed(2016);
        for (size_t i = 0; i < n; ++i) {
            prox_rcc a, b;
            prox_vec3 org;
            sample(&r, sm, &a, &b, &org);
            double lim = fmax(prox_v3_norm(a.axis) + prox_v3_norm(b.axis), a.radius + b.radius);
            int f = prox_v3_norm(org) <= lim ? 0 : 1;
            int interfere = prox_rcc_distance(&a, &b).intersect == 1;
            nn[f]++;
            for (int d = 0; d < NDEF; ++d) {
                int c = case_of(d, &a, &b, interfere);
                cnt[d][f][c]++;
                if (c == 1 && interfere) c1int[d][f]++;
            }
        }
        for (int d = 0; d < NDEF; ++d) {
            double pn = nn[0] ? 100.0 / (double)nn[0] : 0.0, pf = nn[1] ? 100.0 / (double)nn[1] : 0.0;
            printf("%-8s %-10s %8.2f | %8.2f %8.2f %8.2f %10.2f | %8.2f %8.2f %8.2f %10.2f\n", samplings[sm], k_defs[d],
                   100.0 * (double)nn[0] / (double)n, pn * (double)cnt[d][0][1], pn * (double)cnt[d][0][2],
                   pn * (double)cnt[d][0][3], pn * (double)c1int[d][0], pf * (double)cnt[d][1][1],
                   pf * (double)cnt[d][1][2], pf * (double)cnt[d][1][3], pf * (double)c1int[d][1]);
        }
    }
}
