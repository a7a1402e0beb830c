/* prox_bench pair sets and method accuracy.
 * Protocol A follows Agarwal, Srivatsan & Bandyopadhyay (2016) Sec. 5 as restated in
 * tests/data/README.md: A = (0 0 0, 0 0 5, r 2); B radius 20 U(0,1], height 50 U(0,1],
 * base uniform in the ball |o| <= 25 (rejection from the cube), uniformly random rotation of +z.
 * Accuracy: errors relative to S; distance methods against max(sd_ref, 0), signed ones against sd_ref;
 * a verdict mismatch is counted only when |sd_ref| > 1e-12 S (touching pairs are either verdict). */
#include <stdlib.h>
#include <string.h>

#include "bench_pairs.h"
#include "stress_gen.h"

/* Fills the scale column of a set. */
static void fill_scale(bench_pairs *P)
{
    P->scale = bench_xmalloc(P->n * sizeof *P->scale);
    for (size_t i = 0; i < P->n; ++i) P->scale[i] = sg_pair_scale(&P->a[i], &P->b[i]);
}

const bench_pairs *bench_pairs_agarwal(const bench_opts *o)
{
    static bench_pairs P; /* built once, lives until exit */
    if (P.n) return &P;
    P.name = "agarwal";
    P.n = o->pairs > 0 ? (size_t)o->pairs : (o->quick ? 20000 : 1000000);
    P.a = bench_xmalloc(P.n * sizeof *P.a);
    P.b = bench_xmalloc(P.n * sizeof *P.b);
    bench_rng r = bench_rng_seed(2016);
    for (size_t i = 0; i < P.n; ++i) {
        double rb = 20.0 * (1.0 - bench_uniform(&r)), hb = 50.0 * (1.0 - bench_uniform(&r));
        prox_vec3 o3;
        do {
            o3 = prox_v3(bench_range(&r, -25, 25), bench_range(&r, -25, 25), bench_range(&r, -25, 25));
        } while (prox_v3_norm(o3) > 25.0);
        bench_rot R = bench_random_rot(&r);
        P.a[i] = (prox_rcc){prox_v3(0, 0, 0), prox_v3(0, 0, 5), 2};
        P.b[i] = (prox_rcc){o3, bench_rot_apply(&R, prox_v3(0, 0, hb)), rb};
    }
    fill_scale(&P);
    return &P;
}

const bench_pairs *bench_pairs_valid(const bench_opts *o, const char *name)
{
    static bench_pairs sets[4];
    static int nsets;
    for (int k = 0; k < nsets; ++k)
        if (!strcmp(sets[k].name, name)) return sets[k].n ? &sets[k] : NULL;
    if (nsets == 4) return NULL;
    bench_pairs *P = &sets[nsets++];
    memset(P, 0, sizeof *P);
    P->name = name;
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.pairs", o->validation_dir, name);
    size_t n = bench_read_pairs(path, &P->a, &P->b);
    snprintf(path, sizeof path, "%s/%s.ref", o->validation_dir, name);
    size_t nr = bench_read_refs(path, &P->ref);
    if (n == 0 || nr != n) {
        fprintf(stderr, "prox_bench: skipping validation set %s (%zu pairs, %zu refs)\n", name, n, nr);
        P->n = 0;
        return NULL;
    }
    P->n = n;
    P->sd_ref = bench_xmalloc(n * sizeof *P->sd_ref);
    for (size_t i = 0; i < n; ++i) P->sd_ref[i] = P->ref[i].sd;
    fill_scale(P);
    return P;
}

const bench_pairs *bench_pairs_stressgen(const bench_opts *o)
{
    static bench_pairs P;
    if (P.n) return &P;
    P.name = "stressgen";
    P.n = o->long_stress ? 1300000 : (o->quick ? 2600 : 26000);
    P.a = bench_xmalloc(P.n * sizeof *P.a);
    P.b = bench_xmalloc(P.n * sizeof *P.b);
    P.sd_ref = bench_xmalloc(P.n * sizeof *P.sd_ref);
    P.family = bench_xmalloc(P.n * sizeof *P.family);
    sg_rng r = sg_seed(77);
    for (size_t i = 0; i < P.n; ++i) {
        sg_pair p = sg_make(&r, (int)(i % SG_NFAMILIES));
        P.a[i] = p.a, P.b[i] = p.b, P.sd_ref[i] = p.d_ref, P.family[i] = p.family;
    }
    fill_scale(&P);
    return &P;
}

/* A case's binding of a method to a set. */
typedef struct method_binding {
    const bench_method *m;
    const bench_pairs *P;
} method_binding;

static double q_method(const void *data, size_t i)
{
    const method_binding *b = data;
    bench_answer ans;
    b->m->run(b->m->cfg, &b->P->a[i], &b->P->b[i], &ans);
    return ans.value + ans.intersect;
}

/* Witness error of an answer: points in their solids and |p2 - p1| = |value|, relative to S. */
static double witness_error(const bench_method *m, const bench_pairs *P, size_t i, const bench_answer *x)
{
    if (!x->has_points) return 0.0;
    double e = fabs(prox_v3_dist(x->p1, x->p2) - fabs(x->value));
    long double da = sg_point_rcc(&P->a[i], x->p1), db = sg_point_rcc(&P->b[i], x->p2);
    if (m->kind == BENCH_DIST && x->value > 0) { /* disjoint: on the boundaries */
        e = fmax(e, (double)fabsl(da)), e = fmax(e, (double)fabsl(db));
    } else { /* in the solids */
        e = fmax(e, (double)fmaxl(da, 0)), e = fmax(e, (double)fmaxl(db, 0));
    }
    return e / P->scale[i];
}

bench_accuracy bench_method_accuracy(const bench_method *m, const bench_pairs *P, const size_t *idx, size_t n)
{
    bench_accuracy acc = {NAN, NAN, NAN, NAN, 0, 0};
    if (!P->sd_ref || n == 0) return acc;
    double *err = bench_xmalloc(n * sizeof *err);
    acc.wit_max = 0;
    for (size_t k = 0; k < n; ++k) {
        size_t i = idx ? idx[k] : k;
        bench_answer x;
        memset(&x, 0, sizeof x);
        m->run(m->cfg, &P->a[i], &P->b[i], &x);
        double S = P->scale[i], sd = P->sd_ref[i];
        if (!x.ok || !isfinite(x.value)) {
            ++acc.failures;
            err[k] = INFINITY;
            continue;
        }
        int ref_inter = sd <= 0;
        /* touching within 1e-12 S (or the input's own rounding, far from the origin) is either verdict */
        double tol = 1e-12 * S + 8.0 * sg_input_ulp(&P->a[i], &P->b[i]);
        if (fabs(sd) > tol && x.intersect != ref_inter) ++acc.mismatches;
        if (m->kind == BENCH_VERDICT) err[k] = 0;
        else if (m->kind == BENCH_DIST) err[k] = fabs(fmax(x.value, 0.0) - fmax(sd, 0.0)) / S;
        else err[k] = fabs(x.value - sd) / S;
        acc.wit_max = fmax(acc.wit_max, witness_error(m, P, i, &x));
    }
    if (m->kind != BENCH_VERDICT) {
        acc.err_median = bench_quantile(err, n, 0.5);
        acc.err_p99 = bench_quantile(err, n, 0.99);
        acc.err_max = err[n - 1];
    } else {
        acc.wit_max = NAN;
    }
    free(err);
    return acc;
}

/* A contiguous copy of the subset idx[0..n-1] of P (same name), made once per (P, idx) and kept
 * until exit: a subset is timed on its own array, so that its figure is the cost of its queries and
 * not the cache misses of reading a few pairs scattered over the whole set. */
static const bench_pairs *gathered(const bench_pairs *P, const size_t *idx, size_t n)
{
    static struct {
        const bench_pairs *P;
        const size_t *idx;
        bench_pairs *G;
    } cache[64];
    static int ncache;
    for (int k = 0; k < ncache; ++k)
        if (cache[k].P == P && cache[k].idx == idx) return cache[k].G;
    bench_pairs *G = bench_xmalloc(sizeof *G);
    memset(G, 0, sizeof *G);
    G->name = P->name;
    G->n = n;
    G->a = bench_xmalloc((n ? n : 1) * sizeof *G->a);
    G->b = bench_xmalloc((n ? n : 1) * sizeof *G->b);
    if (P->sd_ref) G->sd_ref = bench_xmalloc((n ? n : 1) * sizeof *G->sd_ref);
    if (P->ref) G->ref = bench_xmalloc((n ? n : 1) * sizeof *G->ref);
    if (P->scale) G->scale = bench_xmalloc((n ? n : 1) * sizeof *G->scale);
    if (P->family) G->family = bench_xmalloc((n ? n : 1) * sizeof *G->family);
    for (size_t i = 0; i < n; ++i) {
        size_t j = idx[i];
        G->a[i] = P->a[j], G->b[i] = P->b[j];
        if (G->sd_ref) G->sd_ref[i] = P->sd_ref[j];
        if (G->ref) G->ref[i] = P->ref[j];
        if (G->scale) G->scale[i] = P->scale[j];
        if (G->family) G->family[i] = P->family[j];
    }
    if (ncache < 64) cache[ncache].P = P, cache[ncache].idx = idx, cache[ncache++].G = G;
    return G;
}

bench_case *bench_add_method(const char *prefix, const bench_method *m, const bench_pairs *P, const size_t *idx,
                             size_t n, const char *suffix)
{
    if (idx) P = gathered(P, idx, n), idx = NULL;
    char name[96];
    snprintf(name, sizeof name, "%s/%s/%s%s", prefix, m->name, P->name, suffix ? suffix : "");
    method_binding *b = bench_xmalloc(sizeof *b); /* lives until exit */
    b->m = m, b->P = P;
    bench_case *c = bench_add(name, q_method, b, idx, n);
    if (P->sd_ref) {
        c->acc = bench_method_accuracy(m, P, idx, n);
        c->has_acc = 1;
    }
    return c;
}

void bench_add_on_reference_sets(const bench_opts *o, const char *prefix, const bench_method *m)
{
    char name[96];
    snprintf(name, sizeof name, "%s/%s/", prefix, m->name);
    if (!bench_selected(o, name)) return;
    const char *sets[] = {"agarwal_public", "stress_public"};
    for (int k = 0; k < 2; ++k) {
        const bench_pairs *V = bench_pairs_valid(o, sets[k]);
        if (V) bench_add_method(prefix, m, V, NULL, V->n, NULL);
    }
    const bench_pairs *G = bench_pairs_stressgen(o);
    bench_add_method(prefix, m, G, NULL, G->n, NULL);
}
