/* prox_bench: one benchmark program with a table of named cases (after Box2D's
 * benchmark/): the selected groups build their seeded inputs first, then every case is timed.
 * For each case and each of R >= 5 repeats, after a warm-up pass: one batch pass gives the mean
 * ns/query (total / n), one pass timing every query on its own (clock overhead subtracted) gives the
 * median and p99 ns/query; the figure reported for each statistic is its median over the repeats.
 * Consecutive cases whose names agree up to their second '/' (a pair type of the mix group: prox
 * and the peers on the same pairs) form a block whose cases take their repeats in turn (run_block).
 * Usage: prox_bench [--quick] [--long] [--repeats R] [--filter SUBSTRING] [--csv FILE]
 *                   [--validation DIR] [--pairs N] [--list] [--agarwal-cases]
 * (--pairs: Agarwal-protocol pairs; --agarwal-cases: the case-definition study of
 * bench_agarwal_cases.c, no timing) */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, CLOCK_MONOTONIC */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>

#include "bench.h"
#ifdef PROX_BENCH_HAVE_SCENE
#include "bench_scene.h"
#endif

#ifndef PROX_BENCH_VALIDATION_DIR
#define PROX_BENCH_VALIDATION_DIR "tests/data"
#endif

/* The case table, filled by the groups' setups. */
static bench_case *g_cases;
static size_t g_ncases, g_capcases;

bench_case *bench_add(const char *name, bench_query_fn one, const void *data, const size_t *idx, size_t n)
{
    if (g_ncases == g_capcases) {
        g_capcases = g_capcases ? 2 * g_capcases : 64;
        bench_case *grown = realloc(g_cases, g_capcases * sizeof *g_cases);
        if (!grown) {
            fprintf(stderr, "prox_bench: out of memory\n");
            exit(2);
        }
        g_cases = grown;
    }
    bench_case *c = &g_cases[g_ncases++];
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "%s", name);
    c->one = one;
    c->data = data;
    c->idx = idx;
    c->n = n;
    return c;
}

void bench_note(bench_case *c, const char *fmt, ...)
{
    size_t used = strlen(c->note);
    if (used && used + 1 < sizeof c->note) c->note[used++] = ';', c->note[used] = '\0';
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->note + used, sizeof c->note - used, fmt, ap);
    va_end(ap);
}

/* Case-name prefixes of the groups: a filter starting with one sets up that group only. */
static const char *const g_groups[] = {"poly/", "prim/", "rcc/", "peer/", "stress/", "query/", "xcheck/", "scene", "mix/"};

int bench_selected(const bench_opts *o, const char *name)
{
    if (!o->filter) return 1;
    if (strstr(name, o->filter)) return 1;
    /* a group (or any prefix of a case name) is selected when the filter is more specific than it */
    if (!strncmp(o->filter, name, strlen(name))) return 1;
    /* a filter that names no group is a free substring: every group must be set up to find it */
    for (size_t k = 0; k < sizeof g_groups / sizeof g_groups[0]; ++k)
        if (!strncmp(o->filter, g_groups[k], strlen(g_groups[k]))) return 0;
    return 1;
}

/* Monotonic time in ns. */
static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

/* Median cost of an empty timed region, subtracted from per-query timings. */
static double clock_overhead(void)
{
    double t[2001];
    for (int k = 0; k < 2001; ++k) {
        double a = now_ns();
        t[k] = now_ns() - a;
    }
    return bench_quantile(t, 2001, 0.5);
}

static volatile double g_sink;

/* One batch pass: mean ns/query. */
static double time_batch(const bench_case *c)
{
    double s = 0.0, t0 = now_ns();
    for (size_t k = 0; k < c->n; ++k) s += c->one(c->data, c->idx ? c->idx[k] : k);
    double t1 = now_ns();
    g_sink = s;
    return (t1 - t0) / (double)c->n;
}

/* One pass timing each query alone: fills per[] (ns, overhead removed). */
static void time_each(const bench_case *c, double *per, double overhead)
{
    double s = 0.0;
    for (size_t k = 0; k < c->n; ++k) {
        size_t i = c->idx ? c->idx[k] : k;
        double t0 = now_ns();
        s += c->one(c->data, i);
        double dt = now_ns() - t0 - overhead;
        per[k] = dt > 0.0 ? dt : 0.0;
    }
    g_sink = s;
}

typedef struct case_stats {
    double mean, median, p99;
} case_stats;

/* The timings of one case over the repeats. */
typedef struct case_run {
    const bench_case *c;
    double *per, *means, *meds, *p99s;
} case_run;

/* One repeat of a case: a warm-up pass (the block's other cases ran since its last pass: caches,
 * branch predictors), then a batch pass and a per-query pass. */
static void run_repeat(case_run *u, int r, double overhead)
{
    (void)time_batch(u->c);
    u->means[r] = time_batch(u->c);
    time_each(u->c, u->per, overhead);
    u->meds[r] = bench_quantile(u->per, u->c->n, 0.5);
    u->p99s[r] = bench_quantile(u->per, u->c->n, 0.99);
}

/* Runs a block of m cases: R repeats in which every case of the block takes its turn, so that a
 * noisy spell of the machine falls on all of them alike rather than on whichever case it met; each
 * statistic is the median over the repeats. */
static void run_block(const bench_case *const *cs, int m, int repeats, double overhead, case_stats *st)
{
    case_run *u = bench_xmalloc((size_t)m * sizeof *u);
    for (int i = 0; i < m; ++i) {
        u[i].c = cs[i];
        u[i].per = bench_xmalloc((cs[i]->n ? cs[i]->n : 1) * sizeof *u[i].per);
        u[i].means = bench_xmalloc((size_t)repeats * sizeof *u[i].means);
        u[i].meds = bench_xmalloc((size_t)repeats * sizeof *u[i].meds);
        u[i].p99s = bench_xmalloc((size_t)repeats * sizeof *u[i].p99s);
    }
    for (int r = 0; r < repeats; ++r)
        for (int i = 0; i < m; ++i)
            if (cs[i]->n) run_repeat(&u[i], r, overhead);
    for (int i = 0; i < m; ++i) {
        st[i] = (case_stats){0, 0, 0};
        if (cs[i]->n) {
            st[i].mean = bench_quantile(u[i].means, (size_t)repeats, 0.5);
            st[i].median = bench_quantile(u[i].meds, (size_t)repeats, 0.5);
            st[i].p99 = bench_quantile(u[i].p99s, (size_t)repeats, 0.5);
        }
        free(u[i].per), free(u[i].means), free(u[i].meds), free(u[i].p99s);
    }
    free(u);
}

/* Length of the prefix of a case name up to its second '/' (its block: "mix/TRC-RCC/" holds prox,
 * its prepared solids and the peers on the same pairs); the whole name when it has fewer. */
static size_t block_key(const char *name)
{
    const char *p = strchr(name, '/');
    if (p) p = strchr(p + 1, '/');
    return p ? (size_t)(p - name) + 1 : strlen(name);
}

static void usage(void)
{
    fprintf(stderr,
            "usage: prox_bench [--quick] [--long] [--repeats R] [--filter SUBSTRING] [--csv FILE]\n"
            "                  [--validation DIR] [--pairs N] [--list] [--agarwal-cases]\n");
}

/* Prints a double or an empty CSV field when NaN. */
static void csv_num(FILE *f, double v)
{
    if (v == v) fprintf(f, ",%.4g", v);
    else fputs(",", f);
}

static void print_header(FILE *csv)
{
    printf("%-46s %9s %10s %10s %10s %9s %9s %9s %5s  %s\n", "case", "n", "mean_ns", "median_ns", "p99_ns",
           "err_max", "err_p99", "wit_max", "mism", "note");
    if (csv)
        fprintf(csv, "case,n,repeats,mean_ns,median_ns,p99_ns,err_max,err_p99,err_median,wit_max,mismatches,"
                     "failures,note\n");
}

static void print_row(FILE *csv, const bench_case *c, const case_stats *st, int repeats)
{
    printf("%-46s %9zu %10.1f %10.1f %10.1f", c->name, c->n, st->mean, st->median, st->p99);
    if (c->has_acc)
        printf(" %9.2g %9.2g %9.2g %5ld", c->acc.err_max, c->acc.err_p99, c->acc.wit_max, c->acc.mismatches);
    else
        printf(" %9s %9s %9s %5s", "", "", "", "");
    printf("  %s\n", c->note);
    fflush(stdout);
    if (!csv) return;
    fprintf(csv, "%s,%zu,%d,%.2f,%.2f,%.2f", c->name, c->n, repeats, st->mean, st->median, st->p99);
    if (c->has_acc) {
        csv_num(csv, c->acc.err_max), csv_num(csv, c->acc.err_p99), csv_num(csv, c->acc.err_median);
        csv_num(csv, c->acc.wit_max);
        fprintf(csv, ",%ld,%ld", c->acc.mismatches, c->acc.failures);
    } else {
        fputs(",,,,,,", csv);
    }
    fprintf(csv, ",\"%s\"\n", c->note);
    fflush(csv);
}

void bench_group_crosscheck(const bench_opts *o); /* bench/bench_crosscheck.c */
void bench_group_mix(const bench_opts *o);        /* bench/bench_mix.c */

/* Leaves main with status. FCL and Coal each bring their own Octomap library into the process, and
 * their static destructors free the same objects twice at exit ("double free or corruption"): with
 * Coal linked, the output is flushed and the process leaves without running them. */
static int finish(int status)
{
#ifdef PROX_BENCH_COAL
    fflush(stdout);
    fflush(stderr);
    _exit(status);
#endif
    return status;
}

int main(int argc, char **argv)
{
    bench_opts o = {0, 0, 7, NULL, PROX_BENCH_VALIDATION_DIR, 0};
    const char *csv_path = NULL;
    int list = 0, study = 0;
    for (int k = 1; k < argc; ++k) {
        if (!strcmp(argv[k], "--quick")) o.quick = 1;
        else if (!strcmp(argv[k], "--long")) o.long_stress = 1;
        else if (!strcmp(argv[k], "--list")) list = 1;
        else if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) {
            usage();
            return finish(0);
        }
        else if (!strcmp(argv[k], "--agarwal-cases")) study = 1;
        else if (!strcmp(argv[k], "--repeats") && k + 1 < argc) o.repeats = atoi(argv[++k]);
        else if (!strcmp(argv[k], "--filter") && k + 1 < argc) o.filter = argv[++k];
        else if (!strcmp(argv[k], "--csv") && k + 1 < argc) csv_path = argv[++k];
        else if (!strcmp(argv[k], "--pairs") && k + 1 < argc) o.pairs = atol(argv[++k]);
        else if (!strcmp(argv[k], "--validation") && k + 1 < argc) o.validation_dir = argv[++k];
        else {
            usage();
            return finish(2);
        }
    }
    if (o.repeats < 5) o.repeats = 5; /* the median of at least 5 repeats */
    gsl_set_error_handler_off();      /* the library must never rely on GSL's aborting handler */
    if (study) {
        bench_agarwal_case_study(&o); /* counts only, no timing */
        return finish(0);
    }

    /* Build every selected input before any timing. */
    bench_group_poly(&o);
    bench_group_prim(&o);
    bench_group_rcc(&o);
    bench_group_peers(&o);
    bench_group_stress(&o);
    bench_group_crosscheck(&o);
    bench_group_query(&o);
    bench_group_mix(&o);

    FILE *csv = NULL;
    if (csv_path && !(csv = fopen(csv_path, "w"))) {
        fprintf(stderr, "prox_bench: cannot write %s\n", csv_path);
        return finish(2);
    }
    double overhead = clock_overhead();
    printf("# prox_bench: %d repeats, clock overhead %.1f ns subtracted from per-query times%s\n", o.repeats,
           overhead, o.quick ? ", quick" : "");
    print_header(csv);
    /* the selected cases, timed in blocks of consecutive cases with the same block key */
    const bench_case **sel = bench_xmalloc((g_ncases ? g_ncases : 1) * sizeof *sel);
    case_stats *st = bench_xmalloc((g_ncases ? g_ncases : 1) * sizeof *st);
    size_t ns = 0;
    for (size_t k = 0; k < g_ncases; ++k)
        if (!o.filter || strstr(g_cases[k].name, o.filter)) sel[ns++] = &g_cases[k];
    for (size_t k = 0; k < ns;) {
        size_t e = k + 1, key = block_key(sel[k]->name);
        while (e < ns && block_key(sel[e]->name) == key && !strncmp(sel[e]->name, sel[k]->name, key)) ++e;
        if (list) {
            for (size_t i = k; i < e; ++i) printf("%s\n", sel[i]->name);
        } else {
            run_block(sel + k, (int)(e - k), o.repeats, overhead, st + k);
            for (size_t i = k; i < e; ++i) print_row(csv, sel[i], &st[i], o.repeats);
        }
        k = e;
    }
    free(sel), free(st);
#ifdef PROX_BENCH_HAVE_SCENE
    /* the scene module's bench (own rows): with no filter, or a filter naming it ("scene...") */
    if (!list && (!o.filter || !strncmp(o.filter, "scene", 5) || strstr("scene/", o.filter))) prox_bench_scene(csv);
#endif
    if (csv) fclose(csv);
    free(g_cases);
    return finish(0);
}
