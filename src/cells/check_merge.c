/* Merges the findings of the cell check's tasks into the report: one overlap per universe and cell
 * pair (volumes summed, the witness of the largest proved box), one gap per connected region of gap
 * boxes (boxes that touch, closed), one undecided entry per universe, set of cells and reason (none
 * for a pair already proved to overlap). Every gap's witness is confirmed here by exact membership
 * against every cell of its universe (overlap witnesses were confirmed when found). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cells/check_internal.h"

typedef struct ref {
    const prox_ccrec *r;
    long universe;
    long na, nb;   /* overlap: the cells' numbers */
    size_t root;   /* gap: the component */
} ref;

static int by_pair(const void *pa, const void *pb)
{
    const ref *a = pa, *b = pb;
    if (a->universe != b->universe) return a->universe < b->universe ? -1 : 1;
    if (a->r->a != b->r->a) return a->na < b->na ? -1 : a->na > b->na ? 1 : (a->r->a < b->r->a ? -1 : 1);
    if (a->r->b != b->r->b) return a->nb < b->nb ? -1 : a->nb > b->nb ? 1 : (a->r->b < b->r->b ? -1 : 1);
    return a->r->task < b->r->task ? -1 : a->r->task > b->r->task;
}

static int by_cells(const void *pa, const void *pb)
{
    const ref *a = pa, *b = pb;
    if (a->universe != b->universe) return a->universe < b->universe ? -1 : 1;
    if (a->r->ncells != b->r->ncells) return a->r->ncells < b->r->ncells ? -1 : 1;
    for (size_t i = 0; i < a->r->ncells; ++i)
        if (a->r->cells[i] != b->r->cells[i]) return a->r->cells[i] < b->r->cells[i] ? -1 : 1;
    int c = strcmp(a->r->reason, b->r->reason);
    if (c) return c;
    return a->r->task < b->r->task ? -1 : a->r->task > b->r->task;
}

static int by_lox(const void *pa, const void *pb)
{
    const ref *a = pa, *b = pb;
    if (a->universe != b->universe) return a->universe < b->universe ? -1 : 1;
    if (a->r->box.lo[0] != b->r->box.lo[0]) return a->r->box.lo[0] < b->r->box.lo[0] ? -1 : 1;
    return a->r->task < b->r->task ? -1 : a->r->task > b->r->task;
}

static size_t find(size_t *up, size_t i)
{
    while (up[i] != i) i = up[i] = up[up[i]];
    return i;
}

static prox_status merge_overlaps(const prox_ccprep *P, ref *v, size_t n, prox_cells_report *r)
{
    qsort(v, n, sizeof *v, by_pair);
    r->overlaps = calloc(n ? n : 1, sizeof *r->overlaps);
    if (!r->overlaps) return PROX_ENOMEM;
    for (size_t i = 0, j; i < n; i = j) {
        const prox_ccrec *best = v[i].r;
        double vol = 0.0;
        for (j = i; j < n && v[j].universe == v[i].universe && v[j].r->a == v[i].r->a && v[j].r->b == v[i].r->b; ++j) {
            vol += fmax(v[j].r->vol, v[j].r->cube); /* one record per task: tasks are disjoint */
            if (v[j].r->best > best->best) best = v[j].r;
        }
        long na = P->m->cells[best->a].number, nb = P->m->cells[best->b].number;
        prox_cells_overlap *o = &r->overlaps[r->noverlaps++];
        *o = (prox_cells_overlap){.universe = v[i].universe, .point = best->pt, .volume_min = vol};
        int swap = na > nb;
        o->cells[0] = swap ? nb : na, o->cells[1] = swap ? na : nb;
        o->index[0] = swap ? best->b : best->a, o->index[1] = swap ? best->a : best->b;
    }
    return PROX_OK;
}

/* A point of box b (pt first when given) in task t's window and in no cell of its universe. */
static int confirm_gap(const prox_ccprep *P, const prox_cctask *t, const prox_ccrec *g, prox_vec3 *out)
{
    static const double f[3] = {0.5, 1.0 / 6.0, 5.0 / 6.0};
    for (int k = -1; k < 27; ++k) {
        prox_vec3 x;
        if (k < 0) {
            if (!g->has_pt) continue;
            x = g->pt;
        } else {
            double c[3];
            int idx[3] = {k % 3, (k / 3) % 3, k / 9};
            for (int i = 0; i < 3; ++i) c[i] = g->pbox.lo[i] + f[idx[i]] * (g->pbox.hi[i] - g->pbox.lo[i]);
            x = prox_v3(c[0], c[1], c[2]);
        }
        if (prox_cc_in_window(P, t, x) != 1) continue;
        const double xx[3] = {x.x, x.y, x.z};
        int free_pt = 1;
        for (size_t q = 0; q < t->nucell && free_pt; ++q) {
            size_t i = P->ucells[t->ucell0 + q];
            const prox_ccbox *cb = &P->cbox[i];
            int in = 1;
            for (int a = 0; a < 3; ++a) in = in && xx[a] >= cb->lo[a] && xx[a] <= cb->hi[a];
            if (in && prox_cell_contains(P->m, i, x) != 0) free_pt = 0;
        }
        if (free_pt) {
            *out = x;
            return 1;
        }
    }
    return 0;
}

static int touch(const prox_ccbox *a, const prox_ccbox *b) { return prox_ccbox_meets(a, b); }

static int by_root_vol(const void *pa, const void *pb)
{
    const ref *a = pa, *b = pb;
    if (a->root != b->root) return a->root < b->root ? -1 : 1;
    double va = a->r->best, vb = b->r->best;
    if (va != vb) return va > vb ? -1 : 1;
    return a->r->task < b->r->task ? -1 : a->r->task > b->r->task;
}

static prox_status push_undecided(prox_cells_report *r, const prox_cells_undecided *u)
{
    prox_cells_undecided *p = realloc(r->undecided, (r->nundecided + 1) * sizeof *p);
    if (!p) return PROX_ENOMEM;
    r->undecided = p;
    p[r->nundecided++] = *u;
    return PROX_OK;
}

static prox_status merge_gaps(const prox_ccprep *P, const prox_cctask *tasks, ref *v, size_t n, prox_cells_report *r)
{
    qsort(v, n, sizeof *v, by_lox);
    size_t *up = malloc((n ? n : 1) * sizeof *up);
    if (!up) return PROX_ENOMEM;
    for (size_t i = 0; i < n; ++i) up[i] = i;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n && v[j].universe == v[i].universe && v[j].r->box.lo[0] <= v[i].r->box.hi[0]; ++j)
            if (touch(&v[i].r->box, &v[j].r->box)) up[find(up, i)] = find(up, j);
    for (size_t i = 0; i < n; ++i) v[i].root = find(up, i);
    free(up);
    /* Each component: its references in order of volume, largest first. */
    qsort(v, n, sizeof *v, by_root_vol);
    r->gaps = calloc(n ? n : 1, sizeof *r->gaps);
    if (!r->gaps) return PROX_ENOMEM;
    for (size_t i = 0, j; i < n; i = j) {
        double vol = 0.0, cube = 0.0;
        prox_ccbox hull = prox_ccbox_empty();
        size_t nb = 0;
        for (j = i; j < n && v[j].root == v[i].root; ++j)
            vol += v[j].r->vol, cube = fmax(cube, v[j].r->cube), nb += v[j].r->nboxes, hull = prox_ccbox_or(&hull, &v[j].r->box);
        vol = fmax(vol, cube); /* the boxes are disjoint; a cube may overlap them */
        prox_vec3 x;
        int ok = 0;
        size_t k = i;
        for (; k < j && k < i + 64 && !ok; ++k) ok = confirm_gap(P, &tasks[v[k].r->task], v[k].r, &x);
        if (ok) {
            r->gaps[r->ngaps++] = (prox_cells_gap){.universe = v[i].universe, .window_cell = tasks[v[k - 1].r->task].window_cell,
                                                   .point = x, .volume_min = vol};
            continue;
        }
        prox_cells_undecided u = {.universe = v[i].universe, .lo = prox_v3(hull.lo[0], hull.lo[1], hull.lo[2]),
                                  .hi = prox_v3(hull.hi[0], hull.hi[1], hull.hi[2]), .nboxes = nb, .volume = vol,
                                  .reason = "gap not confirmed by exact membership"};
        if (push_undecided(r, &u) != PROX_OK) return PROX_ENOMEM;
    }
    return PROX_OK;
}

/* 1 when the report already names cells a and b of universe u as overlapping. */
static int known_pair(const prox_cells_report *r, long u, long a, long b)
{
    for (size_t i = 0; i < r->noverlaps; ++i) {
        const prox_cells_overlap *o = &r->overlaps[i];
        if (o->universe == u && ((o->cells[0] == a && o->cells[1] == b) || (o->cells[0] == b && o->cells[1] == a)))
            return 1;
    }
    return 0;
}

/* Undecided entries after the overlaps are merged: an entry for exactly a pair of cells already
 * proved to overlap is left out (the thin rim of a found overlap, where its boundary surfaces meet,
 * would only repeat it). */
static prox_status merge_undecided(const prox_ccprep *P, ref *v, size_t n, prox_cells_report *r)
{
    qsort(v, n, sizeof *v, by_cells);
    for (size_t i = 0, j; i < n; i = j) {
        prox_cells_undecided u = {.universe = v[i].universe, .ncells = v[i].r->ncells, .reason = v[i].r->reason};
        for (size_t k = 0; k < u.ncells; ++k) u.cells[k] = P->m->cells[v[i].r->cells[k]].number;
        prox_ccbox hull = prox_ccbox_empty();
        for (j = i; j < n && by_cells(&v[i], &v[j]) <= 0 && v[j].universe == v[i].universe &&
                    v[j].r->ncells == v[i].r->ncells && !memcmp(v[j].r->cells, v[i].r->cells, u.ncells * sizeof(size_t)) &&
                    !strcmp(v[j].r->reason, v[i].r->reason);
             ++j) {
            hull = prox_ccbox_or(&hull, &v[j].r->box);
            u.nboxes += v[j].r->nboxes;
            u.volume += v[j].r->vol;
        }
        u.lo = prox_v3(hull.lo[0], hull.lo[1], hull.lo[2]);
        u.hi = prox_v3(hull.hi[0], hull.hi[1], hull.hi[2]);
        if (u.ncells == 2 && known_pair(r, u.universe, u.cells[0], u.cells[1])) continue;
        if (push_undecided(r, &u) != PROX_OK) return PROX_ENOMEM;
    }
    return PROX_OK;
}

prox_status prox_cc_merge(const prox_ccprep *P, const prox_cctask *tasks, prox_ccout *outs, size_t ntasks,
                          prox_cells_report *r)
{
    size_t counts[3] = {0};
    for (size_t t = 0; t < ntasks; ++t) {
        r->stats.boxes += outs[t].boxes;
        r->stats.clean += outs[t].clean;
        r->stats.leaves += outs[t].leaves;
        for (size_t i = 0; i < outs[t].n; ++i) counts[outs[t].recs[i].kind]++;
    }
    ref *v[3];
    for (int k = 0; k < 3; ++k) v[k] = malloc((counts[k] ? counts[k] : 1) * sizeof(ref));
    prox_status st = PROX_ENOMEM;
    if (v[0] && v[1] && v[2]) {
        size_t n[3] = {0};
        for (size_t t = 0; t < ntasks; ++t)
            for (size_t i = 0; i < outs[t].n; ++i) {
                const prox_ccrec *x = &outs[t].recs[i];
                long na = x->kind == PROX_CC_OVERLAP ? P->m->cells[x->a].number : 0;
                long nb = x->kind == PROX_CC_OVERLAP ? P->m->cells[x->b].number : 0;
                v[x->kind][n[x->kind]++] = (ref){x, tasks[t].universe, na, nb, 0};
            }
        st = merge_overlaps(P, v[0], n[0], r);
        if (st == PROX_OK) st = merge_undecided(P, v[2], n[2], r);
        if (st == PROX_OK) st = merge_gaps(P, tasks, v[1], n[1], r);
    }
    for (int k = 0; k < 3; ++k) free(v[k]);
    return st;
}
