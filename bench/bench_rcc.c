/* prox_bench group "rcc": cylinder-cylinder queries on Agarwal's protocol (Sec. 5 of Agarwal,
 * Srivatsan & Bandyopadhyay 2016; 10^6 pairs): the exact distance overall, near field
 * (|o| <= max(l1 + l2, r1 + r2)) and far field, per Agarwal case (1, 2.1, 2.2, 3, parallel) with the
 * case distribution beside the paper's Fig. 10, per closest primitive pair; the SAT verdict and the
 * signed distance on the same pairs; and every method's accuracy on the validation sets
 * (tests/data, quad-precision references) and on the bench's stress generator. */
#include <stdlib.h>
#include <string.h>

#include "bench_pairs.h"

/* Index subsets of a set: near / far field (Agarwal's split) and per class of a computed result. */
typedef struct subset {
    size_t *idx;
    size_t n;
} subset;

static subset subset_alloc(size_t cap)
{
    subset s = {bench_xmalloc(cap * sizeof(size_t)), 0};
    return s;
}

/* Near field of protocol A: |o| <= max(l1 + l2, r1 + r2), o the base of B. */
static int near_field(const prox_rcc *a, const prox_rcc *b)
{
    double lim = fmax(prox_v3_norm(a->axis) + prox_v3_norm(b->axis), a->radius + b->radius);
    return prox_v3_norm(b->base) <= lim;
}

/* Registers a method on Agarwal's protocol: all, near and far field. */
static void add_near_far(const bench_opts *o, const bench_method *m, const bench_pairs *P, subset *nf)
{
    char name[96];
    snprintf(name, sizeof name, "rcc/%s/agarwal", m->name);
    if (!bench_selected(o, name)) return;
    bench_add_method("rcc", m, P, NULL, P->n, "/all");
    bench_add_method("rcc", m, P, nf[0].idx, nf[0].n, "/near");
    bench_add_method("rcc", m, P, nf[1].idx, nf[1].n, "/far");
}

#ifdef PROX_BENCH_HAVE_RCC
static const struct {
    int code;
    const char *name;
} k_cases[] = {{PROX_CASE_1, "case1"},     {PROX_CASE_2_1, "case2.1"}, {PROX_CASE_2_2, "case2.2"},
               {PROX_CASE_3, "case3"},     {PROX_CASE_NONE, "case-none"}};
/* Names of prox_pair_kind, indexed by its value. */
enum { NPAIR = PROX_PAIR_OVERLAP + 1 };
static const char *const k_pairs[NPAIR] = {[PROX_PAIR_NONE] = "none", [PROX_PAIR_SS] = "SS", [PROX_PAIR_CS] = "CS",
                                           [PROX_PAIR_CD] = "CD",     [PROX_PAIR_CC] = "CC", [PROX_PAIR_OVERLAP] = "overlap"};

/* The distance query per Agarwal case and per closest primitive pair, with the case distribution
 * within near and far field written in the notes (compare the paper's Fig. 10). */
static void add_distance_classes(const bench_opts *o, const bench_pairs *P, const char *is_near)
{
    if (!bench_selected(o, "rcc/prox-distance/agarwal/")) return;
    size_t ncase = sizeof k_cases / sizeof k_cases[0];
    subset cs[5], ps[NPAIR], c1[3];
    size_t cnt[5][2] = {{0}}, nnear = 0;
    for (size_t k = 0; k < ncase; ++k) cs[k] = subset_alloc(P->n);
    for (size_t k = 0; k < NPAIR; ++k) ps[k] = subset_alloc(P->n);
    for (size_t k = 0; k < 3; ++k) c1[k] = subset_alloc(P->n);
    for (size_t i = 0; i < P->n; ++i) {
        prox_distance_result r = prox_rcc_distance(&P->a[i], &P->b[i]);
        nnear += (size_t)is_near[i];
        for (size_t k = 0; k < ncase; ++k)
            if ((int)r.agarwal == k_cases[k].code) cs[k].idx[cs[k].n++] = i, ++cnt[k][is_near[i] ? 0 : 1];
        if ((unsigned)r.pair < NPAIR) ps[r.pair].idx[ps[r.pair].n++] = i;
        if (r.agarwal == PROX_CASE_1) {
            subset *c = &c1[!r.intersect ? 0 : (r.a_in_b || r.b_in_a) ? 2 : 1];
            c->idx[c->n++] = i;
        }
    }
    char sfx[64];
    for (size_t k = 0; k < ncase; ++k) {
        snprintf(sfx, sizeof sfx, "/%s", k_cases[k].name);
        bench_case *c = bench_add_method("rcc", &bench_prox_distance_method, P, cs[k].idx, cs[k].n, sfx);
        bench_note(c, "share_all=%.2f%%;share_near=%.2f%%;share_far=%.2f%%", 100.0 * (double)cs[k].n / (double)P->n,
                   100.0 * (double)cnt[k][0] / (double)nnear, 100.0 * (double)cnt[k][1] / (double)(P->n - nnear));
    }
    /* Case 1 by class (disjoint, crossing, nested), each alone, then all three one class after the
     * other: against the case1 figure (the classes interleaved as drawn), the difference is the
     * cost of branches that the mixture makes unpredictable. */
    static const char *const c1_names[3] = {"/case1-disjoint", "/case1-crossing", "/case1-nested"};
    subset sorted = subset_alloc(P->n);
    for (size_t k = 0; k < 3; ++k) {
        bench_add_method("rcc", &bench_prox_distance_method, P, c1[k].idx, c1[k].n, c1_names[k]);
        for (size_t j = 0; j < c1[k].n; ++j) sorted.idx[sorted.n++] = c1[k].idx[j];
    }
    bench_add_method("rcc", &bench_prox_distance_method, P, sorted.idx, sorted.n, "/case1-by-class");
    for (size_t k = 0; k < NPAIR; ++k) {
        if (!ps[k].n) continue;
        snprintf(sfx, sizeof sfx, "/pair-%s", k_pairs[k]);
        bench_case *c = bench_add_method("rcc", &bench_prox_distance_method, P, ps[k].idx, ps[k].n, sfx);
        bench_note(c, "share=%.2f%%", 100.0 * (double)ps[k].n / (double)P->n);
    }
}
#endif

void bench_group_rcc(const bench_opts *o)
{
    if (!bench_selected(o, "rcc/")) return;
    const bench_pairs *P = bench_pairs_agarwal(o);
    subset nf[2] = {subset_alloc(P->n), subset_alloc(P->n)};
    char *is_near = bench_xmalloc(P->n);
    for (size_t i = 0; i < P->n; ++i) {
        is_near[i] = (char)near_field(&P->a[i], &P->b[i]);
        subset *s = &nf[is_near[i] ? 0 : 1];
        s->idx[s->n++] = i;
    }
    const bench_method *methods[16];
    int nm = 0;
    methods[nm++] = &bench_capsule_method;
    for (const bench_method *const *m = bench_prox_methods; *m; ++m) methods[nm++] = *m;
    for (int k = 0; k < nm; ++k) add_near_far(o, methods[k], P, nf);
    add_near_far(o, &bench_harness_method, P, nf); /* no reference sets: it computes nothing */
#ifdef PROX_BENCH_HAVE_RCC
    add_distance_classes(o, P, is_near);
#endif
    for (int k = 0; k < nm; ++k) bench_add_on_reference_sets(o, "rcc", methods[k]);
}
