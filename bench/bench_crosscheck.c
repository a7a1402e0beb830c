/* prox_bench group "xcheck": the cross-check of the two cylinder methods (prox_rcc_crosscheck).
 * Setup (untimed) runs prox_rcc_crosscheck on n pairs of Agarwal's protocol (A fixed r = 2, h = 5;
 * B radius (0, 20], height (0, 50], base uniform in the ball of radius 25, uniform axis; n = --pairs,
 * 10^6 by default, 2*10^4 with --quick) and on n/10 pairs of the stress generator (bench/stress_gen.h,
 * all families in turn), and prints every disagreement outside |sd| <= 1e-12 x scale as a 14-number
 * reproducer, with the totals. The timed cases are the cross-check on the first 2*10^4 pairs of each. */
#include <stdlib.h>

#include "bench.h"
#include "prox/sat.h"
#include "stress_gen.h"

void bench_group_crosscheck(const bench_opts *o);

typedef struct xc_data {
    prox_rcc *a, *b;
    size_t n;
} xc_data;

static double xc_one(const void *data, size_t i)
{
    const xc_data *d = data;
    prox_crosscheck_result r = prox_rcc_crosscheck(&d->a[i], &d->b[i]);
    return r.sd + r.agree;
}

/* Counts (and prints) the disagreements of a batch; returns their number. */
static long xc_sweep(const char *what, const xc_data *d, long *touching)
{
    long bad = 0;
    *touching = 0;
    for (size_t i = 0; i < d->n; ++i) {
        const prox_rcc *a = &d->a[i], *b = &d->b[i];
        prox_crosscheck_result r = prox_rcc_crosscheck(a, b);
        if (r.status == PROX_OK && r.agree) {
            if (!r.verdict_agree) (*touching)++; /* verdicts differ inside the touching band */
            continue;
        }
        bad++;
        printf("# xcheck DISAGREE %s %zu: status %d verdicts dist %d sat %d, distance %.17g sd %.17g diff %.3g "
               "tol %.3g margin %.3g\n#   %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
               "%.17g %.17g\n",
               what, i, (int)r.status, r.intersect_distance, r.intersect_sat, r.distance, r.sd, r.distance_diff, r.tol,
               r.margin, a->base.x, a->base.y, a->base.z, a->axis.x, a->axis.y, a->axis.z, a->radius, b->base.x,
               b->base.y, b->base.z, b->axis.x, b->axis.y, b->axis.z, b->radius);
    }
    return bad;
}

static xc_data *xc_alloc(size_t n)
{
    xc_data *d = bench_xmalloc(sizeof *d);
    d->a = bench_xmalloc(n * sizeof *d->a);
    d->b = bench_xmalloc(n * sizeof *d->b);
    d->n = n;
    return d;
}

void bench_group_crosscheck(const bench_opts *o)
{
    if (!bench_selected(o, "xcheck/")) return;
    size_t n = o->pairs > 0 ? (size_t)o->pairs : (o->quick ? 20000 : 1000000);
    xc_data *pa = xc_alloc(n);
    bench_rng g = bench_rng_seed(4401);
    for (size_t i = 0; i < n; ++i) {
        prox_rcc a = {{0, 0, 0}, {0, 0, 5}, 2}, b;
        b.radius = 20.0 * (1.0 - bench_uniform(&g));
        double h = 50.0 * (1.0 - bench_uniform(&g));
        do b.base = prox_v3(bench_range(&g, -25, 25), bench_range(&g, -25, 25), bench_range(&g, -25, 25));
        while (prox_v3_norm(b.base) > 25.0);
        b.axis = prox_v3_scale(bench_unit(&g), h);
        pa->a[i] = a;
        pa->b[i] = b;
    }
    size_t ns = n / 10 > 2600 ? n / 10 : 2600;
    xc_data *ps = xc_alloc(ns);
    sg_rng r = sg_seed(4402);
    for (size_t i = 0; i < ns; ++i) {
        sg_pair p = sg_make(&r, (int)(i % SG_NFAMILIES));
        ps->a[i] = p.a;
        ps->b[i] = p.b;
    }
    long ta, ts, ba = xc_sweep("protocol-A", pa, &ta), bs = xc_sweep("stress", ps, &ts);
    printf("# xcheck: protocol-A %zu pairs, %ld disagreements (%ld verdict splits inside |sd| <= tol); "
           "stress %zu pairs, %ld disagreements (%ld inside)\n",
           n, ba, ta, ns, bs, ts);
    size_t nt = n < 20000 ? n : 20000, nst = ns < 20000 ? ns : 20000;
    bench_case *c = bench_add("xcheck/protocol-A", xc_one, pa, NULL, nt);
    bench_note(c, "sweep_pairs=%zu;disagreements=%ld;touching_splits=%ld", n, ba, ta);
    c = bench_add("xcheck/stress", xc_one, ps, NULL, nst);
    bench_note(c, "sweep_pairs=%zu;disagreements=%ld;touching_splits=%ld", ns, bs, ts);
}
