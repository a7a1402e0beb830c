/* prox check DECK: the geometry of an MCNP deck.
 *
 * By default (the deck has cells): the certified cell check (prox/cellcheck.h): overlapping cell
 * pairs, gaps, undecided slivers, and what the reader could not model, once per kind. Exit status 0
 * clean, 1 an overlap or a gap, 2 input errors (and, with --strict, unchecked cards).
 *
 * --bodies (implied by --clearance and --all, and for decks without cells): the body-level report:
 * the deck's bodies (prox/deck.h) that the cells use, in a scene (prox/scene.h), and the relation of
 * every pair that is not disjoint, or within the clearance, or (--all) of every pair. Exit status 0
 * no crossings, 1 crossings, 2 input errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "prox/cellcheck.h"
#include "prox/cells.h"
#include "prox/deck.h"
#include "prox/scene.h"

typedef prox_check_args check_opts;

static void check_usage(FILE *f)
{
    fprintf(f, "usage: prox check DECK [--resolution R] [--strict] [--threads N] [--json]\n"
               "       prox check DECK --bodies [--clearance D] [--all] [--json]\n"
               "  cells (default when the deck has cells): every point of every universe's windows must\n"
               "  lie in exactly one cell; lists overlapping cell pairs, gaps and undecided slivers larger\n"
               "  than R (default 1e-4 of the model's diagonal), and the cards it could not model\n"
               "  --strict     unchecked cards are an error (exit 2)\n"
               "  --bodies     crossing, touching and nested bodies that the cells use (and disjoint pairs\n"
               "               closer than D with --clearance, every pair with --all; both imply --bodies)\n"
               "  exit status: 0 clean, 1 overlaps or gaps (bodies: crossings) found, 2 input errors\n");
}

/* A positive number after option argv[*i]; 0 on success. */
static int number_arg(int argc, char **argv, int *i, double *v, int allow_zero)
{
    char *end = NULL;
    if (*i + 1 >= argc) return fprintf(stderr, "prox check: %s needs a value\n", argv[*i]), -1;
    const char *name = argv[*i];
    *v = strtod(argv[++*i], &end);
    if (!end || *end || end == argv[*i] || !(allow_zero ? *v >= 0.0 : *v > 0.0) || isinf(*v))
        return fprintf(stderr, "prox check: bad value '%s' for %s\n", argv[*i], name), -1;
    return 0;
}

/* Parses the options; returns 0 on success. */
static int parse_opts(int argc, char **argv, check_opts *o)
{
    for (int i = 1; i < argc; ++i) {
        double v = 0.0;
        if (!strcmp(argv[i], "--json")) o->json = 1;
        else if (!strcmp(argv[i], "--all")) o->all = 1;
        else if (!strcmp(argv[i], "--bodies")) o->bodies = 1;
        else if (!strcmp(argv[i], "--strict")) o->strict = 1;
        else if (!strcmp(argv[i], "--clearance")) {
            if (number_arg(argc, argv, &i, &o->clearance, 1)) return -1;
        } else if (!strcmp(argv[i], "--resolution")) {
            if (number_arg(argc, argv, &i, &o->resolution, 0)) return -1;
        } else if (!strcmp(argv[i], "--threads")) {
            if (number_arg(argc, argv, &i, &v, 0) || v != floor(v) || v > 64)
                return fprintf(stderr, "prox check: --threads takes 1 to 64\n"), -1;
            o->threads = (int)v;
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
    size_t *keep, nkeep; /* deck bodies checked: those the cells use (all of them without cells) */
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
    for (size_t k = 0; k < run->nkeep; ++k) {
        const prox_deck_body *b = &d->bodies[run->keep[k]];
        fprintf(f, "%s\n    {\"surface\": %ld, \"type\": \"%s\", \"line\": %d}", k ? "," : "", b->surface, b->card,
                b->line);
    }
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
            run->o->path, d->title, run->nkeep, run->rep.stats.naive_pairs, run->rep.stats.candidates,
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

/* Builds the scene of the checked bodies and asks for the pairs. 0 on success. */
static int run_check(check_run *run)
{
    const prox_deck *d = run->deck;
    prox_scene *s = prox_scene_create();
    run->body_of = malloc((d->nbodies ? d->nbodies : 1) * sizeof *run->body_of);
    if (!s || !run->body_of) {
        prox_scene_destroy(s);
        return -1;
    }
    for (size_t k = 0; k < run->nkeep; ++k) {
        size_t i = run->keep[k];
        run->body_of[prox_scene_count(s)] = i;
        if (prox_scene_add(s, &d->bodies[i].shape) != PROX_OK) { /* the reader validated it already */
            prox_scene_destroy(s);
            return -1;
        }
    }
    /* --threads N, else every processor: the broad phase and the ladder split across them */
    prox_scene_set_threads(s, run->o->threads > 0 ? run->o->threads : 0);
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

/* The bodies the cells use (surface numbers named by a cell's region); every body when the model
 * has no cells or errors. 0 on success. */
static int used_bodies(check_run *run, const prox_cell_model *cm)
{
    const prox_deck *d = run->deck;
    run->keep = malloc((d->nbodies ? d->nbodies : 1) * sizeof *run->keep);
    if (!run->keep) return -1;
    for (size_t i = 0; i < d->nbodies; ++i) {
        int used = !cm || !cm->ncells || cm->nerrors;
        for (size_t c = 0; c < (cm ? cm->ncells : 0) && !used; ++c) {
            const prox_cell *cell = &cm->cells[c];
            for (size_t t = cell->expr; t < cell->expr + cell->nexpr && !used; ++t)
                used = cm->terms[t].op == PROX_OP_LEAF && cm->terms[t].surf < cm->nsurfs &&
                       cm->surfs[cm->terms[t].surf].number == d->bodies[i].surface;
        }
        if (used) run->keep[run->nkeep++] = i;
    }
    return 0;
}

/* The errors of the cell cards the body reader does not see (an undefined surface, a bad region,
 * a bad fill): a deck that has them was not cell-checked, so they are listed after the body report
 * (on stderr after a JSON document), each line the deck reader already reported skipped. */
static void cell_errors(FILE *f, const prox_deck *d, const prox_cell_model *cm)
{
    size_t n = 0;
    for (size_t i = 0; cm && i < cm->nerrors; ++i) {
        int seen = 0;
        for (size_t j = 0; j < d->nerrors && !seen; ++j) seen = d->errors[j].line == cm->errors[i].line;
        if (seen) continue;
        fprintf(f, "%serror: line %d: %s\n", n++ ? "" : "\n", cm->errors[i].line, cm->errors[i].text);
    }
    if (cm && cm->nerrors)
        fprintf(f, "\nnot cell-checked: %zu error%s in the cards the cell model reads\n", cm->nerrors, cm->nerrors == 1 ? "" : "s");
}

/* The body-level report. */
static int bodies_report(const check_opts *o, const prox_cell_model *cm, FILE *out, prox_status *st)
{
    prox_deck deck = {0};
    *st = prox_deck_read_file(o->path, &deck);
    if (*st != PROX_OK) {
        prox_deck_free(&deck);
        return 2;
    }
    check_run run = {.o = o, .deck = &deck};
    int code = 2;
    if (used_bodies(&run, cm) || run_check(&run)) *st = run.rep.status != PROX_OK ? run.rep.status : PROX_ENOMEM;
    else {
        if (o->json) write_json(out, &run);
        else write_table(out, &run);
        cell_errors(o->json ? stderr : out, &deck, cm);
        code = (deck.nerrors || run.solver_errors) ? 2 : (run.ncrossing ? 1 : 0);
    }
    free(run.keep);
    free(run.body_of);
    prox_scene_report_free(&run.rep);
    prox_deck_free(&deck);
    return code;
}

/* ---- the cell report ---- */

static void json_num(FILE *f, double v)
{
    if (isfinite(v)) fprintf(f, "%.17g", v + 0.0);
    else fputs("null", f);
}

static void json_box(FILE *f, prox_vec3 lo, prox_vec3 hi)
{
    const double a[6] = {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z};
    fputs("[[", f);
    for (int i = 0; i < 6; ++i) {
        if (i == 3) fputs("], [", f);
        else if (i) fputs(", ", f);
        json_num(f, a[i]);
    }
    fputs("]]", f);
}

static size_t count_universes(const prox_cell_model *m)
{
    size_t n = 0;
    for (size_t i = 0; i < m->ncells; ++i) {
        int seen = 0;
        for (size_t j = 0; j < i && !seen; ++j) seen = m->cells[j].universe == m->cells[i].universe;
        n += !seen;
    }
    return n;
}

static void cells_json(FILE *f, const check_opts *o, const prox_cell_model *m, const prox_cells_report *r)
{
    fputs("{\n  \"deck\": ", f);
    json_string(f, o->path);
    fputs(",\n  \"title\": ", f);
    json_string(f, m->title);
    fprintf(f, ",\n  \"check\": \"cells\",\n  \"cells\": %zu,\n  \"universes\": %zu,\n  \"windows\": %zu,\n", m->ncells,
            count_universes(m), m->nwindows);
    fputs("  \"resolution\": ", f);
    json_num(f, r->resolution);
    fputs(",\n  \"model_box\": ", f);
    json_box(f, r->lo, r->hi);
    fputs(",\n  \"overlaps\": [", f);
    for (size_t i = 0; i < r->noverlaps; ++i) {
        const prox_cells_overlap *v = &r->overlaps[i];
        fprintf(f, "%s\n    {\"cells\": [%ld, %ld], \"universe\": %ld, \"point\": ", i ? "," : "", v->cells[0], v->cells[1],
                v->universe);
        json_vec(f, v->point);
        fputs(", \"volume_min\": ", f);
        json_num(f, v->volume_min);
        fputc('}', f);
    }
    fputs("\n  ],\n  \"gaps\": [", f);
    for (size_t i = 0; i < r->ngaps; ++i) {
        const prox_cells_gap *g = &r->gaps[i];
        fprintf(f, "%s\n    {\"universe\": %ld, \"window_cell\": %ld, \"point\": ", i ? "," : "", g->universe, g->window_cell);
        json_vec(f, g->point);
        fputs(", \"volume_min\": ", f);
        json_num(f, g->volume_min);
        fputc('}', f);
    }
    fputs("\n  ],\n  \"undecided\": [", f);
    for (size_t i = 0; i < r->nundecided; ++i) {
        const prox_cells_undecided *u = &r->undecided[i];
        fprintf(f, "%s\n    {\"universe\": %ld, \"cells\": [", i ? "," : "", u->universe);
        for (size_t k = 0; k < u->ncells; ++k) fprintf(f, "%s%ld", k ? ", " : "", u->cells[k]);
        fputs("], \"box\": ", f);
        json_box(f, u->lo, u->hi);
        fprintf(f, ", \"boxes\": %zu, \"volume_max\": ", u->nboxes);
        json_num(f, u->volume);
        fputs(", \"reason\": ", f);
        json_string(f, u->reason);
        fputc('}', f);
    }
    fputs("\n  ],\n  \"unchecked\": [", f);
    for (size_t i = 0; i < m->nunchecked; ++i) {
        fprintf(f, "%s\n    {\"what\": ", i ? "," : "");
        json_string(f, m->unchecked[i].what);
        fprintf(f, ", \"count\": %zu, \"line\": %d}", m->unchecked[i].count, m->unchecked[i].first_line);
    }
    fputs("\n  ],\n  \"errors\": [", f);
    json_notes(f, m->errors, m->nerrors, "message");
    fprintf(f, "\n  ],\n  \"stats\": {\"windows\": %zu, \"boxes\": %zu, \"clean\": %zu, \"leaves\": %zu}\n}\n",
            r->stats.windows, r->stats.boxes, r->stats.clean, r->stats.leaves);
}

static void cells_table(FILE *f, const check_opts *o, const prox_cell_model *m, const prox_cells_report *r)
{
    char p[64];
    fprintf(f, "deck: %s\ntitle: %s\ncells: %zu in %zu universe%s, %zu window%s\n", o->path, m->title, m->ncells,
            count_universes(m), count_universes(m) == 1 ? "" : "s", m->nwindows, m->nwindows == 1 ? "" : "s");
    if (!m->nerrors) {
        double dx = r->hi.x - r->lo.x, dy = r->hi.y - r->lo.y, dz = r->hi.z - r->lo.z;
        fprintf(f, "resolution: %.6g (%s; model box diagonal %.6g)\n", r->resolution,
                o->resolution > 0 ? "--resolution" : "default: 1e-4 of the diagonal", sqrt(dx * dx + dy * dy + dz * dz));
        fprintf(f, "checked: %zu window%s, %zu boxes, %zu proved clean, %zu probed at the resolution, %.3g s\n",
                r->stats.windows, r->stats.windows == 1 ? "" : "s", r->stats.boxes, r->stats.clean, r->stats.leaves,
                r->stats.seconds);
    }
    fputc('\n', f);
    if (r->noverlaps) {
        fprintf(f, "overlapping cells:\n%9s %17s %13s  %s\n", "universe", "cells", "volume >=", "a point in both");
        for (size_t i = 0; i < r->noverlaps; ++i) {
            const prox_cells_overlap *v = &r->overlaps[i];
            char cells[48];
            snprintf(cells, sizeof cells, "%ld and %ld", v->cells[0], v->cells[1]);
            fmt_vec(p, sizeof p, v->point);
            fprintf(f, "%9ld %17s %13.6g  %s\n", v->universe, cells, v->volume_min, p);
        }
    }
    if (r->ngaps) {
        fprintf(f, "gaps (points in no cell):\n%9s %12s %13s  %s\n", "universe", "window cell", "volume >=", "a point in no cell");
        for (size_t i = 0; i < r->ngaps; ++i) {
            const prox_cells_gap *g = &r->gaps[i];
            fmt_vec(p, sizeof p, g->point);
            fprintf(f, "%9ld %12ld %13.6g  %s\n", g->universe, g->window_cell, g->volume_min, p);
        }
    }
    for (size_t i = 0; i < r->nundecided; ++i) {
        const prox_cells_undecided *u = &r->undecided[i];
        char lo[64], hi[64];
        fmt_vec(lo, sizeof lo, u->lo);
        fmt_vec(hi, sizeof hi, u->hi);
        fprintf(f, "undecided: universe %ld, cells", u->universe);
        for (size_t k = 0; k < u->ncells; ++k) fprintf(f, " %ld", u->cells[k]);
        fprintf(f, ": %zu box%s, volume <= %.3g, in %s - %s: %s\n", u->nboxes, u->nboxes == 1 ? "" : "es", u->volume, lo,
                hi, u->reason);
    }
    for (size_t i = 0; i < m->nerrors; ++i) fprintf(f, "error: line %d: %s\n", m->errors[i].line, m->errors[i].text);
    for (size_t i = 0; i < m->nunchecked; ++i)
        fprintf(f, "unchecked: %s: %zu (first on line %d)\n", m->unchecked[i].what, m->unchecked[i].count,
                m->unchecked[i].first_line);
    if (m->nerrors) fprintf(f, "\nnot checked: %zu error%s in the deck\n", m->nerrors, m->nerrors == 1 ? "" : "s");
    else
        fprintf(f, "\n%zu overlapping cell pair%s, %zu gap%s, %zu undecided\n", r->noverlaps, r->noverlaps == 1 ? "" : "s",
                r->ngaps, r->ngaps == 1 ? "" : "s", r->nundecided);
}

int prox_check_run(const prox_check_args *o, FILE *out, prox_status *st)
{
    prox_cell_model m = {0};
    *st = prox_cells_read_file(o->path, &m);
    if (*st != PROX_OK) {
        prox_cells_free(&m);
        return 2;
    }
    if (!m.ncells && !m.nsurfs && !m.nerrors) { /* never a clean verdict on nothing */
        fprintf(out, "error: %s: no cell and no surface cards, nothing to check (a blank line right after "
                     "the title line ends the cell block)\n", o->path);
        prox_cells_free(&m);
        return 2;
    }
    /* A deck with malformed cards is not cell-checked: the body-level report lists the errors and
     * still checks the good bodies (exit 2). */
    int bodies = o->bodies || o->all || o->clearance > 0.0 || !m.ncells || m.nerrors;
    if (bodies) {
        int code = bodies_report(o, &m, out, st);
        if (m.nerrors && code < 2) code = 2; /* the cell cards' errors are input errors too */
        prox_cells_free(&m);
        return code;
    }
    prox_cells_report r = {0};
    if (!m.nerrors) {
        prox_cells_check_opts co = {.resolution = o->resolution, .threads = o->threads, .progress = o->progress};
        *st = prox_cells_check(&m, &co, &r);
        if (*st != PROX_OK) {
            prox_cells_free(&m);
            return 2;
        }
    }
    if (o->json) cells_json(out, o, &m, &r);
    else cells_table(out, o, &m, &r);
    int code = m.nerrors || (o->strict && m.nunchecked) ? 2 : (r.noverlaps || r.ngaps) ? 1 : 0;
    prox_cells_report_free(&r);
    prox_cells_free(&m);
    return code;
}

int prox_check_report(const char *path, double clearance, int all, int json, FILE *out, prox_status *st)
{
    prox_check_args a = {.path = path, .clearance = clearance, .all = all, .json = json};
    return prox_check_run(&a, out, st);
}

int prox_cli_check(int argc, char **argv)
{
    check_opts o = {.progress = 1};
    int pr = parse_opts(argc, argv, &o);
    if (pr) {
        check_usage(pr > 0 ? stdout : stderr);
        return pr > 0 ? 0 : 2;
    }
    prox_status st = PROX_OK;
    int code = prox_check_run(&o, stdout, &st);
    if (st != PROX_OK) fprintf(stderr, "prox check: %s\n", prox_status_str(st));
    return code;
}
