/* prox check DECK [--clearance D] [--json] [--all]: reads an MCNP deck (prox/deck.h), puts its bodies
 * in a scene (prox/scene.h) and reports the relation of every pair that is not disjoint, or within the
 * clearance, or (--all) of every pair. Exit status: 0 no crossings, 1 crossings, 2 input errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "prox/deck.h"
#include "prox/scene.h"

/* Command-line options. */
typedef struct check_opts {
    const char *path;
    double clearance;
    int json, all;
} check_opts;

static void check_usage(FILE *f)
{
    fprintf(f, "usage: prox check DECK [--clearance D] [--json] [--all]\n"
               "  reports crossing, touching and nested bodies of an MCNP deck (and disjoint pairs\n"
               "  closer than D with --clearance, every pair with --all)\n"
               "  exit status: 0 no crossings, 1 crossings found, 2 input errors\n");
}

/* Parses the options; returns 0 on success. */
static int parse_opts(int argc, char **argv, check_opts *o)
{
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--json")) o->json = 1;
        else if (!strcmp(argv[i], "--all")) o->all = 1;
        else if (!strcmp(argv[i], "--clearance")) {
            char *end = NULL;
            if (i + 1 >= argc) return fprintf(stderr, "prox check: --clearance needs a value\n"), -1;
            o->clearance = strtod(argv[++i], &end);
            if (!end || *end || end == argv[i] || !(o->clearance >= 0.0) || isinf(o->clearance))
                return fprintf(stderr, "prox check: bad clearance '%s'\n", argv[i]), -1;
        } else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return 1;
        else if (argv[i][0] == '-' && argv[i][1]) return fprintf(stderr, "prox check: unknown option '%s'\n", argv[i]), -1;
        else if (o->path) return fprintf(stderr, "prox check: more than one deck given\n"), -1;
        else o->path = argv[i];
    }
    if (!o->path) return fprintf(stderr, "prox check: no deck given\n"), -1;
    return 0;
}

/* The word of a relation used in the table and in JSON. */
static const char *relation_word(prox_relation r)
{
    switch (r) {
    case PROX_REL_DISJOINT: return "disjoint";
    case PROX_REL_TOUCHING: return "touching";
    case PROX_REL_CROSSING: return "crossing";
    case PROX_REL_A_IN_B:
    case PROX_REL_B_IN_A: return "nested";
    }
    return "unknown";
}

/* Writes s as a JSON string. */
static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; ++s) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') fprintf(f, "\\%c", c);
        else if (c < 0x20) fprintf(f, "\\u%04x", c);
        else fputc(c, f);
    }
    fputc('"', f);
}

/* -0 prints as 0: adding +0.0 maps -0.0 to +0.0 and leaves every other value unchanged. */
static prox_vec3 no_neg_zero(prox_vec3 v) { return prox_v3(v.x + 0.0, v.y + 0.0, v.z + 0.0); }

static void json_vec(FILE *f, prox_vec3 v)
{
    v = no_neg_zero(v);
    fprintf(f, "[%.17g, %.17g, %.17g]", v.x, v.y, v.z);
}

/* Notes of a list as JSON objects {"line": n, "<key>": text}. */
static void json_notes(FILE *f, const prox_deck_note *n, size_t count, const char *key)
{
    for (size_t i = 0; i < count; ++i) {
        fprintf(f, "%s\n    {\"line\": %d, \"%s\": ", i ? "," : "", n[i].line, key);
        json_string(f, n[i].text);
        fputc('}', f);
    }
}

/* Everything the report writers need. */
typedef struct check_run {
    const check_opts *o;
    const prox_deck *deck;
    prox_scene_report rep;
    size_t *body_of;   /* scene index -> deck body index */
    size_t ncrossing;
    int solver_errors; /* pairs whose query failed */
} check_run;

static void write_json_pair(FILE *f, const check_run *run, const prox_scene_pair *p)
{
    const prox_deck_body *a = &run->deck->bodies[run->body_of[p->a]], *b = &run->deck->bodies[run->body_of[p->b]];
    const prox_pair_result *r = &p->r;
    fprintf(f, "\n    {\"a\": %ld, \"b\": %ld, ", a->surface, b->surface);
    if (r->status != PROX_OK) {
        fprintf(f, "\"error\": ");
        json_string(f, prox_status_str(r->status));
        fputc('}', f);
        return;
    }
    fprintf(f, "\"relation\": \"%s\", \"distance\": %.17g, \"points\": [", relation_word(r->relation),
            r->relation == PROX_REL_DISJOINT ? r->distance : 0.0);
    json_vec(f, r->p1);
    fputs(", ", f);
    json_vec(f, r->p2);
    fputc(']', f);
    if (r->relation == PROX_REL_A_IN_B || r->relation == PROX_REL_B_IN_A)
        fprintf(f, ", \"inner\": %ld, \"clearance\": %.17g", r->relation == PROX_REL_A_IN_B ? a->surface : b->surface,
                r->clearance);
    if (r->relation == PROX_REL_CROSSING) {
        fprintf(f, ", \"depth\": %.17g, \"reposition\": ", r->depth);
        json_vec(f, r->reposition);
    }
    fputc('}', f);
}

static void write_json(FILE *f, const check_run *run)
{
    const prox_deck *d = run->deck;
    fputs("{\n  \"deck\": ", f);
    json_string(f, run->o->path);
    fputs(",\n  \"title\": ", f);
    json_string(f, d->title);
    fputs(",\n  \"bodies\": [", f);
    for (size_t i = 0; i < d->nbodies; ++i)
        fprintf(f, "%s\n    {\"surface\": %ld, \"type\": \"%s\", \"line\": %d}", i ? "," : "", d->bodies[i].surface,
                d->bodies[i].card, d->bodies[i].line);
    fputs("\n  ],\n  \"pairs\": [", f);
    for (size_t i = 0; i < run->rep.npairs; ++i) {
        if (i) fputc(',', f);
        write_json_pair(f, run, &run->rep.pairs[i]);
    }
    fputs("\n  ],\n  \"errors\": [", f);
    json_notes(f, d->errors, d->nerrors, "message");
    fputs("\n  ],\n  \"unsupported\": [", f);
    json_notes(f, d->unsupported, d->nunsupported, "card");
    const prox_scene_stats *s = &run->rep.stats;
    fprintf(f, "\n  ],\n  \"stats\": {\"pairs\": %zu, \"candidates\": %zu, \"exact\": %zu, \"crossing\": %zu}\n}\n",
            s->naive_pairs, s->candidates, s->exact, run->ncrossing);
}

/* "(x, y, z)" with a fixed number of significant digits, for the table. */
static void fmt_vec(char *buf, size_t n, prox_vec3 v)
{
    v = no_neg_zero(v);
    snprintf(buf, n, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
}

static void write_table(FILE *f, const check_run *run)
{
    const prox_deck *d = run->deck;
    fprintf(f, "deck: %s\ntitle: %s\nbodies: %zu, pairs: %zu (%zu near enough to test, %zu exact queries)\n\n",
            run->o->path, d->title, d->nbodies, run->rep.stats.naive_pairs, run->rep.stats.candidates,
            run->rep.stats.exact);
    if (run->rep.npairs) {
        fprintf(f, "%8s %8s  %-9s %13s %13s  %-34s %-34s %s\n", "a", "b", "relation", "distance", "depth",
                "point on a", "point on b", "reposition of b / inner body");
        for (size_t i = 0; i < run->rep.npairs; ++i) {
            const prox_scene_pair *p = &run->rep.pairs[i];
            const prox_pair_result *r = &p->r;
            long sa = d->bodies[run->body_of[p->a]].surface, sb = d->bodies[run->body_of[p->b]].surface;
            if (r->status != PROX_OK) {
                fprintf(f, "%8ld %8ld  error: %s\n", sa, sb, prox_status_str(r->status));
                continue;
            }
            char p1[64], p2[64], extra[64] = "";
            fmt_vec(p1, sizeof p1, r->p1);
            fmt_vec(p2, sizeof p2, r->p2);
            if (r->relation == PROX_REL_CROSSING) fmt_vec(extra, sizeof extra, r->reposition);
            if (r->relation == PROX_REL_A_IN_B || r->relation == PROX_REL_B_IN_A)
                snprintf(extra, sizeof extra, "inner %ld, clearance %.6g", r->relation == PROX_REL_A_IN_B ? sa : sb,
                         r->clearance);
            fprintf(f, "%8ld %8ld  %-9s %13.6g %13.6g  %-34s %-34s %s\n", sa, sb, relation_word(r->relation),
                    r->relation == PROX_REL_DISJOINT ? r->distance : 0.0, r->depth, p1, p2, extra);
        }
    } else fprintf(f, "no pairs to report\n");
    for (size_t i = 0; i < d->nerrors; ++i) fprintf(f, "error: line %d: %s\n", d->errors[i].line, d->errors[i].text);
    for (size_t i = 0; i < d->nunsupported; ++i)
        fprintf(f, "unsupported: line %d: %s\n", d->unsupported[i].line, d->unsupported[i].text);
    fprintf(f, "\n%zu crossing pair%s\n", run->ncrossing, run->ncrossing == 1 ? "" : "s");
}

/* Builds the scene of the deck's bodies and asks for the pairs. 0 on success. */
static int run_check(check_run *run)
{
    const prox_deck *d = run->deck;
    prox_scene *s = prox_scene_create();
    run->body_of = malloc((d->nbodies ? d->nbodies : 1) * sizeof *run->body_of);
    if (!s || !run->body_of) {
        prox_scene_destroy(s);
        return -1;
    }
    for (size_t i = 0; i < d->nbodies; ++i) {
        run->body_of[prox_scene_count(s)] = i;
        if (prox_scene_add(s, &d->bodies[i].shape) != PROX_OK) { /* the reader validated it already */
            prox_scene_destroy(s);
            return -1;
        }
    }
    run->rep = prox_scene_pairs(s, run->o->all ? INFINITY : run->o->clearance, PROX_MODE_RELATION);
    prox_scene_destroy(s);
    if (run->rep.status != PROX_OK) return -1;
    for (size_t i = 0; i < run->rep.npairs; ++i) {
        const prox_pair_result *r = &run->rep.pairs[i].r;
        if (r->status != PROX_OK) run->solver_errors++;
        else if (r->relation == PROX_REL_CROSSING) run->ncrossing++;
    }
    return 0;
}

int prox_check_report(const char *path, double clearance, int all, int json, FILE *out, prox_status *st)
{
    check_opts o = {.path = path, .clearance = clearance, .all = all, .json = json};
    prox_deck deck = {0};
    *st = prox_deck_read_file(o.path, &deck);
    if (*st != PROX_OK) {
        prox_deck_free(&deck);
        return 2;
    }
    check_run run = {.o = &o, .deck = &deck};
    int code = 2;
    if (run_check(&run)) *st = run.rep.status != PROX_OK ? run.rep.status : PROX_ENOMEM;
    else {
        if (o.json) write_json(out, &run);
        else write_table(out, &run);
        code = (deck.nerrors || run.solver_errors) ? 2 : (run.ncrossing ? 1 : 0);
    }
    free(run.body_of);
    prox_scene_report_free(&run.rep);
    prox_deck_free(&deck);
    return code;
}

int prox_cli_check(int argc, char **argv)
{
    check_opts o = {0};
    int pr = parse_opts(argc, argv, &o);
    if (pr) {
        check_usage(pr > 0 ? stdout : stderr);
        return pr > 0 ? 0 : 2;
    }
    prox_status st = PROX_OK;
    int code = prox_check_report(o.path, o.clearance, o.all, o.json, stdout, &st);
    if (st != PROX_OK) fprintf(stderr, "prox check: %s\n", prox_status_str(st));
    return code;
}
