/* prox pairs: cylinder pairs on stdin, one result line per pair on stdout.
 * Input format: tests/data/README.md ("Pair line"): 14 numbers, cylinder A as base centre,
 * axis vector, radius, then B; '#' comment lines and blank lines are skipped (they produce no output).
 * A malformed line (wrong count, not a number, invalid cylinder) is reported on stderr with its line
 * number and reason; the other lines are still processed and the exit status is 1. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/cli.h"
#include "prox/prox.h"

typedef enum pairs_mode { MODE_DISTANCE, MODE_SIGNED, MODE_TEST } pairs_mode;

typedef struct pair_list {
    prox_rcc *a, *b;
    size_t n, cap;
} pair_list;

static int list_push(pair_list *l, prox_rcc a, prox_rcc b)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 1024;
        prox_rcc *na = realloc(l->a, cap * sizeof *na);
        if (!na) return 0;
        l->a = na;
        prox_rcc *nb = realloc(l->b, cap * sizeof *nb);
        if (!nb) return 0;
        l->b = nb;
        l->cap = cap;
    }
    l->a[l->n] = a;
    l->b[l->n] = b;
    l->n++;
    return 1;
}

/* 1 for a line that holds no data: blank or a '#' comment. */
static int is_skippable(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') ++s;
    return *s == '\0' || *s == '#';
}

/* Parses exactly 14 finite-syntax numbers; on failure writes the reason to `why`. */
static int parse_numbers(const char *s, double v[14], char *why, size_t whylen)
{
    int k = 0;
    const char *p = s;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n' || *p == ',') ++p;
        if (*p == '\0') break;
        char *end;
        errno = 0;
        double x = strtod(p, &end);
        if (end == p) {
            const char *e = p;
            while (*e && *e != ' ' && *e != '\t' && *e != '\r' && *e != '\n') ++e;
            snprintf(why, whylen, "field %d is not a number: '%.*s'", k + 1, (int)(e - p > 40 ? 40 : e - p), p);
            return 0;
        }
        if (k < 14) v[k] = x;
        ++k;
        p = end;
        if (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n' && *p != ',') {
            snprintf(why, whylen, "field %d has trailing characters: '%.20s'", k, p);
            return 0;
        }
    }
    if (k != 14) {
        snprintf(why, whylen, "expected 14 numbers (two cylinders: base, axis, radius), found %d", k);
        return 0;
    }
    return 1;
}

static prox_rcc rcc_from(const double *v)
{
    prox_rcc c = {prox_v3(v[0], v[1], v[2]), prox_v3(v[3], v[4], v[5]), v[6]};
    return c;
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e9 * (double)ts.tv_sec + (double)ts.tv_nsec;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Signed distance by the chosen method: the support method's own (support.h) or the library's
 * composition (sat.h: the exact distance when disjoint, the support-function depth when overlapping). */
static prox_signed_result signed_by(const prox_rcc *a, const prox_rcc *b, prox_method m)
{
    if (m != PROX_METHOD_SUPPORT) return prox_rcc_signed_distance(a, b);
    prox_shape sa = prox_shape_from_rcc(*a), sb = prox_shape_from_rcc(*b);
    return prox_shape_signed_distance_support(&sa, &sb);
}

/* Intersection verdict by the chosen method: the separating axes for the support method, the
 * distance query's verdict otherwise. */
static prox_test_result test_by(const prox_rcc *a, const prox_rcc *b, prox_method m)
{
    if (m == PROX_METHOD_SUPPORT) return prox_rcc_sat(a, b);
    prox_distance_result d = prox_rcc_distance_ex(a, b, m);
    prox_test_result t = {0};
    t.status = d.status;
    t.intersect = d.status == PROX_OK && d.intersect;
    return t;
}

/* Median over repeats of the in-memory query loop, in ns per pair (parsing and printing excluded). */
static double time_queries(const pair_list *l, pairs_mode mode, prox_method m)
{
    enum { REPEATS = 7 };
    double t[REPEATS];
    volatile double sink = 0.0;
    for (int r = 0; r < REPEATS; ++r) {
        double t0 = now_ns();
        for (size_t i = 0; i < l->n; ++i) {
            if (mode == MODE_DISTANCE) sink += prox_rcc_distance_ex(&l->a[i], &l->b[i], m).distance;
            else if (mode == MODE_SIGNED) sink += signed_by(&l->a[i], &l->b[i], m).sd;
            else sink += test_by(&l->a[i], &l->b[i], m).intersect;
        }
        t[r] = (now_ns() - t0) / (double)(l->n ? l->n : 1);
    }
    (void)sink;
    qsort(t, REPEATS, sizeof t[0], cmp_double);
    return t[REPEATS / 2];
}

/* Runs one query and prints its line; returns 0 on a library error (reported with the line). */
static int answer(const prox_rcc *a, const prox_rcc *b, pairs_mode mode, prox_method m, long lineno)
{
    if (mode == MODE_DISTANCE) {
        prox_distance_result r = prox_rcc_distance_ex(a, b, m);
        if (r.status != PROX_OK) goto fail_status;
        printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", r.distance, r.p1.x, r.p1.y, r.p1.z, r.p2.x,
               r.p2.y, r.p2.z);
        return 1;
    fail_status:
        fprintf(stderr, "prox pairs: line %ld: %s\n", lineno, prox_status_str(r.status));
        return 0;
    }
    if (mode == MODE_SIGNED) {
        prox_signed_result r = signed_by(a, b, m);
        if (r.status != PROX_OK) {
            fprintf(stderr, "prox pairs: line %ld: %s\n", lineno, prox_status_str(r.status));
            return 0;
        }
        printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", r.sd, r.p1.x, r.p1.y, r.p1.z, r.p2.x, r.p2.y,
               r.p2.z);
        return 1;
    }
    prox_test_result r = test_by(a, b, m);
    if (r.status != PROX_OK) {
        fprintf(stderr, "prox pairs: line %ld: %s\n", lineno, prox_status_str(r.status));
        return 0;
    }
    printf("%d\n", r.intersect ? 1 : 0);
    return 1;
}

static void pairs_usage(FILE *f)
{
    fprintf(f, "usage: prox pairs [--signed | --test] [--method fast|closed-form|support] [--time] < pairs.txt\n"
               "  each input line: bAx bAy bAz aAx aAy aAz rA bBx bBy bBz aBx aBy aBz rB\n"
               "  default   writes 'd p1x p1y p1z p2x p2y p2z' (distance, proximal points)\n"
               "  --signed  writes 'sd p1x p1y p1z p2x p2y p2z' (negative sd = -penetration depth)\n"
               "  --test    writes 1 (intersect) or 0 (separated)\n"
               "  --method  the cylinder method: fast (default: prediction + certificate), closed-form\n"
               "            (Agarwal's complete primitive decomposition, degree-8 roots by GSL) or support\n"
               "            (separating axes and support-function optimisation); all three are exact\n"
               "  --time    also prints 'time_ns_per_pair X' on stderr (median of 7 repeats)\n");
}

/* Validates one cylinder, naming it in the message. */
static int check_cyl(const prox_rcc *c, const char *name, long lineno)
{
    prox_status st = prox_rcc_validate(c);
    if (st == PROX_OK) return 1;
    fprintf(stderr, "prox pairs: line %ld: cylinder %s: %s\n", lineno, name, prox_status_str(st));
    return 0;
}

int prox_cli_pairs(int argc, char **argv)
{
    pairs_mode mode = MODE_DISTANCE;
    prox_method method = PROX_METHOD_FAST;
    int timing = 0;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--time") == 0) timing = 1;
        else if (strcmp(argv[i], "--method") == 0 || strncmp(argv[i], "--method=", 9) == 0) {
            const char *name = argv[i][8] == '=' ? argv[i] + 9 : (i + 1 < argc ? argv[++i] : NULL);
            if (!name || !prox_method_parse(name, &method)) {
                fprintf(stderr, "prox pairs: --method needs fast, closed-form or support (got '%s')\n",
                        name ? name : "");
                pairs_usage(stderr);
                return 2;
            }
        }
        else if (strcmp(argv[i], "--signed") == 0) mode = MODE_SIGNED;
        else if (strcmp(argv[i], "--test") == 0) mode = MODE_TEST;
        else if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            pairs_usage(stdout);
            return 0;
        } else {
            fprintf(stderr, "prox pairs: unknown option '%s'\n", argv[i]);
            pairs_usage(stderr);
            return 2;
        }
    }
    pair_list list = {0};
    char *line = NULL;
    size_t cap = 0;
    long lineno = 0;
    int errors = 0;
    while (getline(&line, &cap, stdin) != -1) {
        ++lineno;
        if (is_skippable(line)) continue;
        double v[14];
        char why[160];
        if (!parse_numbers(line, v, why, sizeof why)) {
            fprintf(stderr, "prox pairs: line %ld: %s\n", lineno, why);
            ++errors;
            continue;
        }
        prox_rcc a = rcc_from(v), b = rcc_from(v + 7);
        if (!check_cyl(&a, "A", lineno) || !check_cyl(&b, "B", lineno)) {
            ++errors;
            continue;
        }
        if (!answer(&a, &b, mode, method, lineno)) {
            ++errors;
            continue;
        }
        if (timing && !list_push(&list, a, b)) {
            fprintf(stderr, "prox pairs: out of memory\n");
            free(line);
            return 2;
        }
    }
    free(line);
    if (timing) fprintf(stderr, "time_ns_per_pair %.1f\n", time_queries(&list, mode, method));
    free(list.a);
    free(list.b);
    if (errors) fprintf(stderr, "prox pairs: %d line(s) with errors\n", errors);
    return errors ? 1 : 0;
}
