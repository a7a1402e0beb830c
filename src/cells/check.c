/* The cell check (include/prox/cellcheck.h): prepares the model (coincident surfaces merged, region
 * trees, bounding boxes of every subexpression and cell), boxes each window, cuts the boxes into
 * tasks and runs them on worker threads (check_tree.c subdivides a task, check_merge.c merges the
 * findings into the report).
 *
 * Three-valued evaluation with truth tables. On a box each surface is proved negative, proved
 * positive or crossing (classify.c). A region is evaluated once for every assignment of signs to the
 * crossing surfaces (up to six: a 64-bit truth table), so that two cells that share a surface with
 * opposite senses never both claim an assignment: the shared boundary of adjacent cells is clean at
 * once, not refined to the resolution. Assignments that no point of the box realises are kept (the
 * tables are a superset), which can only leave a box undecided, never prove a false verdict. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cells/check_internal.h"
#include "cells/window_bound.h"
#include "core/tol.h"

static const uint64_t var_mask[PROX_CC_VARS] = {0xAAAAAAAAAAAAAAAAull, 0xCCCCCCCCCCCCCCCCull, 0xF0F0F0F0F0F0F0F0ull,
                                                0xFF00FF00FF00FF00ull, 0xFFFF0000FFFF0000ull, 0xFFFFFFFF00000000ull};

/* ---- evaluation ---- */

prox_status prox_ccctx_init(prox_ccctx *c, const prox_ccprep *P)
{
    size_t n = P->m->nsurfs ? P->m->nsurfs : 1;
    memset(c, 0, sizeof *c);
    c->P = P;
    c->seen = calloc(n, sizeof *c->seen);
    c->cls = calloc(n, 1);
    c->var = calloc(n, 1);
    if (!c->seen || !c->cls || !c->var) {
        prox_ccctx_free(c);
        return PROX_ENOMEM;
    }
    return PROX_OK;
}

void prox_ccctx_free(prox_ccctx *c)
{
    free(c->seen);
    free(c->cls);
    free(c->var);
    c->seen = NULL, c->cls = NULL, c->var = NULL;
}

void prox_ccctx_box(prox_ccctx *c, const prox_ccbox *b)
{
    c->box = *b;
    c->nvar = 0;
    c->overflow = 0;
    if (++c->stamp == 0) { /* wrapped: forget every mark */
        memset(c->seen, 0, (c->P->m->nsurfs ? c->P->m->nsurfs : 1) * sizeof *c->seen);
        c->stamp = 1;
    }
}

static prox_ccmask leaf(prox_ccctx *c, const prox_term *t)
{
    const prox_ccprep *P = c->P;
    size_t s = P->rep[t->surf];
    int sense = t->sense * P->flip[t->surf];
    if (c->seen[s] != c->stamp) {
        c->seen[s] = c->stamp;
        c->cls[s] = (signed char)prox_cc_classify(&P->m->surfs[s], &c->box);
        c->var[s] = -1;
    }
    if (c->cls[s] != 0) return c->cls[s] == sense ? (prox_ccmask){PROX_CC_ALL, PROX_CC_ALL} : (prox_ccmask){0, 0};
    if (c->var[s] < 0) {
        if (c->nvar >= PROX_CC_VARS) { /* too many crossing surfaces: unknown */
            c->overflow = 1;
            return (prox_ccmask){0, PROX_CC_ALL};
        }
        c->vsurf[c->nvar] = s;
        c->var[s] = (signed char)c->nvar++;
    }
    uint64_t k = var_mask[(int)c->var[s]];
    return sense < 0 ? (prox_ccmask){k, k} : (prox_ccmask){~k, ~k};
}

static prox_ccmask eval_term(prox_ccctx *c, size_t i)
{
    const prox_ccprep *P = c->P;
    if (!prox_ccbox_meets(&P->nbox[i], &c->box)) return (prox_ccmask){0, 0};
    const prox_term *t = &P->m->terms[i];
    prox_ccmask a, b;
    switch (t->op) {
    case PROX_OP_LEAF: return leaf(c, t);
    case PROX_OP_ALL: return (prox_ccmask){PROX_CC_ALL, PROX_CC_ALL};
    case PROX_OP_NOT:
        a = eval_term(c, P->kid0[i]);
        return (prox_ccmask){~a.p, ~a.t};
    case PROX_OP_AND:
        a = eval_term(c, P->kid0[i]);
        if (!a.p) return a;
        b = eval_term(c, P->kid1[i]);
        return (prox_ccmask){a.t & b.t, a.p & b.p};
    case PROX_OP_OR:
        a = eval_term(c, P->kid0[i]);
        if (a.t == PROX_CC_ALL) return a;
        b = eval_term(c, P->kid1[i]);
        return (prox_ccmask){a.t | b.t, a.p | b.p};
    }
    return (prox_ccmask){0, PROX_CC_ALL};
}

prox_ccmask prox_cc_eval(prox_ccctx *c, size_t expr, size_t nexpr)
{
    if (!nexpr) return (prox_ccmask){PROX_CC_ALL, PROX_CC_ALL};
    return eval_term(c, expr + nexpr - 1);
}

/* ---- preparation ---- */

/* Builds the tree and the boxes of the region [e, e + n); 0 when it is not a well-formed postfix
 * expression. stack has room for n entries. */
static int build_expr(prox_ccprep *P, size_t e, size_t n, size_t *stack)
{
    const prox_cell_model *m = P->m;
    if (e > m->nterms || n > m->nterms - e) return 0;
    size_t sp = 0;
    for (size_t i = e; i < e + n; ++i) {
        const prox_term *t = &m->terms[i];
        switch (t->op) {
        case PROX_OP_LEAF:
            if (t->surf >= m->nsurfs || (t->sense != 1 && t->sense != -1)) return 0;
            P->nbox[i] = prox_cc_side_box(&m->surfs[t->surf], t->sense);
            break;
        case PROX_OP_ALL: P->nbox[i] = prox_ccbox_all(); break;
        case PROX_OP_NOT:
            if (sp < 1) return 0;
            P->kid0[i] = stack[--sp];
            P->nbox[i] = prox_ccbox_all();
            break;
        case PROX_OP_AND:
        case PROX_OP_OR:
            if (sp < 2) return 0;
            P->kid1[i] = stack[--sp];
            P->kid0[i] = stack[--sp];
            P->nbox[i] = t->op == PROX_OP_AND ? prox_ccbox_and(&P->nbox[P->kid0[i]], &P->nbox[P->kid1[i]])
                                              : prox_ccbox_or(&P->nbox[P->kid0[i]], &P->nbox[P->kid1[i]]);
            break;
        default: return 0;
        }
        stack[sp++] = i;
    }
    return sp == 1 || n == 0;
}

static const prox_cell_model *sort_model; /* qsort has no context argument; set under sort_lock */
static pthread_mutex_t sort_lock = PTHREAD_MUTEX_INITIALIZER;

static int by_universe(const void *pa, const void *pb)
{
    const prox_cell *a = &sort_model->cells[*(const size_t *)pa], *b = &sort_model->cells[*(const size_t *)pb];
    if (a->universe != b->universe) return a->universe < b->universe ? -1 : 1;
    return *(const size_t *)pa < *(const size_t *)pb ? -1 : 1;
}

static void prep_free(prox_ccprep *P)
{
    free(P->rep);
    free(P->flip);
    free(P->kid0);
    free(P->kid1);
    free(P->nbox);
    free(P->cbox);
    free(P->ucells);
}

static prox_status prep_build(prox_ccprep *P, const prox_cell_model *m)
{
    memset(P, 0, sizeof *P);
    P->m = m;
    size_t ns = m->nsurfs ? m->nsurfs : 1, nt = m->nterms ? m->nterms : 1, nc = m->ncells ? m->ncells : 1;
    P->rep = malloc(ns * sizeof *P->rep);
    P->flip = malloc(ns);
    P->kid0 = calloc(nt, sizeof *P->kid0);
    P->kid1 = calloc(nt, sizeof *P->kid1);
    P->nbox = malloc(nt * sizeof *P->nbox);
    P->cbox = malloc(nc * sizeof *P->cbox);
    P->ucells = malloc(nc * sizeof *P->ucells);
    size_t *stack = malloc(nt * sizeof *stack);
    prox_status st = PROX_ENOMEM;
    if (!P->rep || !P->flip || !P->kid0 || !P->kid1 || !P->nbox || !P->cbox || !P->ucells || !stack) goto done;
    st = prox_cc_merge_surfaces(m->surfs, m->nsurfs, P->rep, P->flip);
    if (st != PROX_OK) goto done;
    st = PROX_EINVAL_ARG;
    for (size_t i = 0; i < m->ncells; ++i) {
        const prox_cell *c = &m->cells[i];
        if (!build_expr(P, c->expr, c->nexpr, stack)) goto done;
        P->cbox[i] = c->nexpr ? P->nbox[c->expr + c->nexpr - 1] : prox_ccbox_all();
        P->ucells[i] = i;
    }
    for (size_t i = 0; i < m->nwindows; ++i)
        if (!build_expr(P, m->windows[i].expr, m->windows[i].nexpr, stack) ||
            !build_expr(P, m->windows[i].bexpr, m->windows[i].bnexpr, stack))
            goto done;
    pthread_mutex_lock(&sort_lock);
    sort_model = m;
    qsort(P->ucells, m->ncells, sizeof *P->ucells, by_universe);
    pthread_mutex_unlock(&sort_lock);
    for (size_t i = 0, j; i < m->ncells; i = j) {
        for (j = i + 1; j < m->ncells && m->cells[P->ucells[j]].universe == m->cells[P->ucells[i]].universe;) ++j;
        if (j - i > P->maxucells) P->maxucells = j - i;
    }
    st = PROX_OK;
done:
    free(stack);
    return st;
}

/* Range of universe u in P->ucells. */
static void universe_cells(const prox_ccprep *P, long u, size_t *first, size_t *count)
{
    size_t lo = 0, hi = P->m->ncells;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (P->m->cells[P->ucells[mid]].universe < u) lo = mid + 1;
        else hi = mid;
    }
    size_t e = lo;
    while (e < P->m->ncells && P->m->cells[P->ucells[e]].universe == u) ++e;
    *first = lo;
    *count = e - lo;
}

/* Shrinks `hull` to the boxes of `b` (subdivided `depth` more times) where region (e, n) may hold. */
static void refine(prox_ccctx *c, size_t e, size_t n, const prox_ccbox *b, int depth, prox_ccbox *hull)
{
    int inside = !prox_ccbox_is_empty(hull);
    for (int i = 0; i < 3 && inside; ++i) inside = b->lo[i] >= hull->lo[i] && b->hi[i] <= hull->hi[i];
    if (inside) return;
    prox_ccctx_box(c, b);
    prox_ccmask k = prox_cc_eval(c, e, n);
    if (!k.p) return;
    if (k.t == PROX_CC_ALL || depth == 0) {
        *hull = prox_ccbox_or(hull, b);
        return;
    }
    int ax = 0;
    for (int i = 1; i < 3; ++i)
        if (b->hi[i] - b->lo[i] > b->hi[ax] - b->lo[ax]) ax = i;
    prox_ccbox l = *b, r = *b;
    l.hi[ax] = r.lo[ax] = 0.5 * b->lo[ax] + 0.5 * b->hi[ax];
    refine(c, e, n, &l, depth - 1, hull);
    refine(c, e, n, &r, depth - 1, hull);
}

/* Depth of the subdivision that bounds cells and windows the analytic boxes leave unbounded. */
#define REFINE_DEPTH 18

/* ---- windows and tasks ---- */

typedef struct winfo {
    long universe;
    size_t u0, nu;        /* the universe's cells */
    size_t expr, nexpr;
    long window_cell;
    size_t win;
    prox_ccbox dom;       /* empty: not checked */
    const char *why;      /* why not checked */
    int bounded;          /* a lattice element open along an axis, checked where its parent holds it */
} winfo;

/* A box holding the complement of the region of term i (De Morgan over the tree). */
static prox_ccbox complement_box(const prox_ccprep *P, size_t i)
{
    const prox_term *t = &P->m->terms[i];
    prox_ccbox a, b;
    switch (t->op) {
    case PROX_OP_LEAF: return prox_cc_side_box(&P->m->surfs[t->surf], -t->sense);
    case PROX_OP_NOT: return P->nbox[P->kid0[i]];
    case PROX_OP_AND:
        a = complement_box(P, P->kid0[i]), b = complement_box(P, P->kid1[i]);
        return prox_ccbox_or(&a, &b);
    case PROX_OP_OR:
        a = complement_box(P, P->kid0[i]), b = complement_box(P, P->kid1[i]);
        return prox_ccbox_and(&a, &b);
    default: return prox_ccbox_empty();
    }
}

/* Hull of the analytic boxes of the bounded cells of a universe; with skip_outside, outside cells
 * contribute the box of their complement instead (the model they surround) when it is bounded. */
static prox_ccbox bounded_hull(const prox_ccprep *P, size_t u0, size_t nu, int skip_outside)
{
    prox_ccbox h = prox_ccbox_empty();
    for (size_t k = 0; k < nu; ++k) {
        size_t i = P->ucells[u0 + k];
        const prox_cell *c = &P->m->cells[i];
        if (skip_outside && c->outside) {
            prox_ccbox cb = c->nexpr ? complement_box(P, c->expr + c->nexpr - 1) : prox_ccbox_empty();
            if (prox_ccbox_bounded(&cb) && !prox_ccbox_is_empty(&cb)) h = prox_ccbox_or(&h, &cb);
            continue;
        }
        prox_ccbox b = P->cbox[i];
        /* a cell cut by tilted planes (an RHP's, a WED's sides) is bounded by their vertices */
        if (!prox_ccbox_bounded(&b) && !prox_ccbox_is_empty(&b) && c->nexpr) {
            prox_ccbox t = cells_region_box(P->m, c->expr, c->nexpr);
            b = prox_ccbox_and(&b, &t);
        }
        if (prox_ccbox_bounded(&b) && !prox_ccbox_is_empty(&b)) h = prox_ccbox_or(&h, &b);
    }
    return h;
}

static double diag(const prox_ccbox *b)
{
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += (b->hi[i] - b->lo[i]) * (b->hi[i] - b->lo[i]);
    return sqrt(s);
}

/* The box each window is checked in. The real world: the hull of its bounded cells that are not
 * outside cells, widened by 1 % of its diagonal so that the outside cell's hold on the model's
 * boundary is checked too. A filled window: its region's box, bounded by the universe's cells and
 * shrunk by subdivision. */
static void window_domain(prox_ccctx *c, winfo *w)
{
    const prox_ccprep *P = c->P;
    w->why = NULL;
    if (!w->nexpr) {
        w->dom = bounded_hull(P, w->u0, w->nu, 1);
        if (prox_ccbox_is_empty(&w->dom)) {
            w->why = "no bounded cell: the real world cannot be boxed";
            return;
        }
        double pad = 0.01 * diag(&w->dom);
        for (int i = 0; i < 3; ++i) w->dom.lo[i] -= pad, w->dom.hi[i] += pad;
        return;
    }
    const prox_term *last = &P->m->terms[w->expr + w->nexpr - 1];
    if (w->bounded && w->nexpr == 2 && last->op == PROX_OP_NOT && P->m->terms[w->expr].op == PROX_OP_ALL) {
        w->dom = prox_ccbox_empty(); /* no element that holds the universe meets its parent: nothing to fill */
        return;
    }
    prox_ccbox b = P->nbox[w->expr + w->nexpr - 1];
    if (!prox_ccbox_is_empty(&b) && !prox_ccbox_bounded(&b)) { /* tilted planes may bound it */
        prox_ccbox t = cells_region_box(P->m, w->expr, w->nexpr);
        b = prox_ccbox_and(&b, &t);
    }
    if (!prox_ccbox_is_empty(&b) && !prox_ccbox_bounded(&b)) {
        prox_ccbox h = bounded_hull(P, w->u0, w->nu, 0);
        if (prox_ccbox_is_empty(&h)) {
            /* An element of a lattice of infinite pins: the window is open along the pins and so is
             * every cell; it is not checked, and says so (never a silent clean verdict). */
            w->dom = prox_ccbox_empty();
            w->why = "window not bounded: neither its region nor any cell of its universe is bounded";
            return;
        }
        b = prox_ccbox_and(&b, &h);
    }
    if (prox_ccbox_is_empty(&b) || !prox_ccbox_bounded(&b)) {
        w->dom = prox_ccbox_empty();
        w->why = prox_ccbox_is_empty(&b) ? NULL : "window not bounded";
        return;
    }
    prox_ccbox hull = prox_ccbox_empty();
    refine(c, w->expr, w->nexpr, &b, REFINE_DEPTH, &hull);
    w->dom = hull;
}

/* Cuts a domain into 2^depth boxes (halving the longest edge), appending tasks. */
static void cut(const winfo *w, const prox_ccbox *b, int depth, prox_cctask *tasks, size_t *n)
{
    if (depth == 0) {
        tasks[*n] = (prox_cctask){.win = w->win, .universe = w->universe, .ucell0 = w->u0, .nucell = w->nu,
                                  .wexpr = w->expr, .wnexpr = w->nexpr, .window_cell = w->window_cell, .box = *b};
        ++*n;
        return;
    }
    int ax = 0;
    for (int i = 1; i < 3; ++i)
        if (b->hi[i] - b->lo[i] > b->hi[ax] - b->lo[ax]) ax = i;
    prox_ccbox l = *b, r = *b;
    l.hi[ax] = r.lo[ax] = 0.5 * b->lo[ax] + 0.5 * b->hi[ax];
    cut(w, &l, depth - 1, tasks, n);
    cut(w, &r, depth - 1, tasks, n);
}

#define TASK_DEPTH 6

/* ---- threads ---- */

typedef struct pool {
    const prox_ccprep *P;
    const prox_cctask *tasks;
    prox_ccout *outs;
    size_t ntasks;
    atomic_size_t next, done;
    atomic_int failed;
} pool;

static void *worker(void *arg)
{
    pool *p = arg;
    prox_ccctx c;
    if (prox_ccctx_init(&c, p->P) != PROX_OK) {
        atomic_store(&p->failed, 1);
        return NULL;
    }
    for (size_t i; (i = atomic_fetch_add(&p->next, 1)) < p->ntasks;) {
        prox_cc_run_task(&c, &p->tasks[i], i, &p->outs[i]);
        atomic_fetch_add(&p->done, 1);
    }
    prox_ccctx_free(&c);
    return NULL;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Runs the tasks on `threads` threads; the calling thread prints the progress line. */
static prox_status run_pool(pool *p, int threads, int progress, double t0)
{
    enum { MAXT = 64 };
    pthread_t tid[MAXT];
    int nt = threads < 1 ? 2 : (threads > MAXT ? MAXT : threads), started = 0;
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, (size_t)64 << 20); /* deep region trees recurse */
    for (int i = 0; i < nt; ++i)
        if (pthread_create(&tid[started], &attr, worker, p) == 0) ++started;
    pthread_attr_destroy(&attr);
    if (!started) worker(p);
    int shown = 0, tty = progress && isatty(2);
    while (atomic_load(&p->done) < p->ntasks && started) {
        if (atomic_load(&p->failed) && atomic_load(&p->next) >= p->ntasks) break;
        nanosleep(&(struct timespec){0, 5000000L}, NULL);
        if (tty && now() - t0 > 1.0) {
            fprintf(stderr, "\rprox check: cells: %zu of %zu regions checked", atomic_load(&p->done), p->ntasks);
            shown = 1;
        }
    }
    for (int i = 0; i < started; ++i) pthread_join(tid[i], NULL);
    if (shown) fprintf(stderr, "\r%60s\r", "");
    if (atomic_load(&p->failed)) return PROX_ENOMEM;
    for (size_t i = 0; i < p->ntasks; ++i)
        if (p->outs[i].failed) return PROX_ENOMEM;
    return PROX_OK;
}

/* ---- entry point ---- */

/* A lattice window whose element is open along an axis is checked as its bexpr (cells.h): the element
 * where a window of the lattice's universe holds it. A bounded element is checked whole. */
static int uses_bound(const prox_ccprep *P, const prox_window *x)
{
    if (!x->bnexpr || !x->nexpr) return 0;
    const prox_ccbox *b = &P->nbox[x->expr + x->nexpr - 1];
    return !prox_ccbox_is_empty(b) && !prox_ccbox_bounded(b);
}

/* Windows of the model (a real-world window made up when the model lists none). */
static winfo *list_windows(const prox_ccprep *P, size_t *nw)
{
    const prox_cell_model *m = P->m;
    size_t n = m->nwindows ? m->nwindows : 1;
    winfo *w = calloc(n, sizeof *w);
    if (!w) return NULL;
    for (size_t i = 0; i < n; ++i) {
        if (m->nwindows) {
            const prox_window *x = &m->windows[i];
            w[i] = (winfo){.universe = x->universe, .expr = x->expr, .nexpr = x->nexpr, .win = i,
                           .window_cell = x->cell < m->ncells ? m->cells[x->cell].number : 0};
            if (uses_bound(P, x)) w[i].expr = x->bexpr, w[i].nexpr = x->bnexpr, w[i].bounded = 1;
        } else w[i] = (winfo){.universe = 0, .win = (size_t)-1};
        universe_cells(P, w[i].universe, &w[i].u0, &w[i].nu);
    }
    *nw = n;
    return w;
}

/* Bounds the cells the analytic boxes leave unbounded, within the hull of their universe's windows. */
static void bound_cells(prox_ccctx *c, prox_ccprep *P, const winfo *w, size_t nw)
{
    for (size_t k = 0; k < nw; ++k) {
        if (prox_ccbox_is_empty(&w[k].dom)) continue;
        int first = 1; /* each universe once: at its first window with a domain */
        for (size_t j = 0; j < k; ++j)
            if (w[j].universe == w[k].universe && !prox_ccbox_is_empty(&w[j].dom)) first = 0;
        if (!first) continue;
        prox_ccbox all = prox_ccbox_empty();
        for (size_t j = k; j < nw; ++j)
            if (w[j].universe == w[k].universe) all = prox_ccbox_or(&all, &w[j].dom);
        for (size_t q = 0; q < w[k].nu; ++q) {
            size_t i = P->ucells[w[k].u0 + q];
            if (prox_ccbox_bounded(&P->cbox[i])) continue;
            prox_ccbox b = prox_ccbox_and(&P->cbox[i], &all), hull = prox_ccbox_empty();
            if (!prox_ccbox_is_empty(&b)) refine(c, P->m->cells[i].expr, P->m->cells[i].nexpr, &b, REFINE_DEPTH, &hull);
            /* Keep the unbounded box outside the windows' hull: only `all` is ever checked. */
            P->cbox[i] = prox_ccbox_is_empty(&hull) ? prox_ccbox_empty() : hull;
        }
    }
}

/* 1 when windows a and b are the same region of the same universe: term by term the same operations
 * on the same canonical surfaces with the same senses (P->rep, P->flip). A universe filled into many
 * cells that its fills map onto one region (a fuel element repeated by TRCL or by a fill transform)
 * has one window per filling cell; checking the region once proves every copy. */
static int same_window(const prox_ccprep *P, const winfo *a, const winfo *b)
{
    if (a->universe != b->universe || a->nexpr != b->nexpr) return 0;
    for (size_t k = 0; k < a->nexpr; ++k) {
        const prox_term *x = &P->m->terms[a->expr + k], *y = &P->m->terms[b->expr + k];
        if (x->op != y->op) return 0;
        if (x->op == PROX_OP_LEAF &&
            (P->rep[x->surf] != P->rep[y->surf] || x->sense * P->flip[x->surf] != y->sense * P->flip[y->surf]))
            return 0;
    }
    return 1;
}

/* Marks each window equal to an earlier one (same_window) as not to be checked. */
static void skip_repeated_windows(const prox_ccprep *P, winfo *w, size_t nw, int *skip)
{
    for (size_t k = 0; k < nw; ++k)
        for (size_t j = 0; j < k && !skip[k]; ++j) skip[k] = !skip[j] && same_window(P, &w[j], &w[k]);
}

/* ---- witnesses of windows bounded by their parent ---- */

static const char *const reason_parent =
    "witness not confirmed in the parent window: no lattice element that holds the universe maps it into "
    "a window of the lattice cell's universe";

static int in_window_exact(const prox_cell_model *m, size_t wi, prox_vec3 x, int depth);

/* 1 when x (universe frame) lies in lattice window wi: in its element (0,0,0) and, mapped by the
 * placement and the translation of one of its elements, in a window of the lattice cell's universe
 * (exact membership at every step, independent of the window's bexpr). */
static int in_lattice_window(const prox_cell_model *m, size_t wi, prox_vec3 x, int depth)
{
    const prox_window *w = &m->windows[wi];
    if (prox_region_contains(m, w->expr, w->nexpr, x) != 1) return 0;
    const double xx[3] = {x.x, x.y, x.z};
    double y[3];
    for (int i = 0; i < 3; ++i)
        y[i] = w->place_o[i] + w->place_R[i][0] * xx[0] + w->place_R[i][1] * xx[1] + w->place_R[i][2] * xx[2];
    long U = m->cells[w->cell].universe;
    for (size_t k = 0; k < w->nelem; ++k) {
        prox_vec3 z = prox_v3(y[0], y[1], y[2]);
        for (int c = 0; c < w->nbasis; ++c) z = prox_v3_add(z, prox_v3_scale(w->basis[c], (double)w->elem[k][c]));
        for (size_t p = 0; p < m->nwindows; ++p)
            if (m->windows[p].universe == U && in_window_exact(m, p, z, depth + 1)) return 1;
    }
    return 0;
}

static int in_window_exact(const prox_cell_model *m, size_t wi, prox_vec3 x, int depth)
{
    const prox_window *w = &m->windows[wi];
    if (depth > 32) return 0;
    if (w->bnexpr && w->nbasis && w->cell < m->ncells && m->cells[w->cell].lat)
        return in_lattice_window(m, wi, x, depth);
    return !w->nexpr || prox_region_contains(m, w->expr, w->nexpr, x) == 1;
}

/* 1 when x lies in a window of universe u (window cell number `cell`, 0: any) as it was checked. */
static int witness_in_windows(const prox_ccprep *P, const winfo *w, size_t nw, long u, long cell, prox_vec3 x)
{
    for (size_t k = 0; k < nw; ++k) {
        if (w[k].universe != u || (cell && w[k].window_cell != cell) || w[k].win == (size_t)-1) continue;
        if (w[k].bounded ? in_lattice_window(P->m, w[k].win, x, 0)
                         : prox_region_contains(P->m, w[k].expr, w[k].nexpr, x) == 1)
            return 1;
    }
    return 0;
}

static int add_undecided(prox_cells_report *r, prox_cells_undecided u)
{
    prox_cells_undecided *v = realloc(r->undecided, (r->nundecided + 1) * sizeof *v);
    if (!v) return 0;
    r->undecided = v;
    r->undecided[r->nundecided++] = u;
    return 1;
}

/* A window bounded by its parent is checked as a region built from surfaces moved by the lattice
 * translations; every finding of its universe is confirmed once more by mapping the witness back
 * through an element's translation into the parent's own window. A witness that does not map back
 * becomes undecided (never a finding, never dropped). */
static prox_status confirm_bounded(const prox_ccprep *P, const winfo *w, size_t nw, prox_cells_report *r)
{
    size_t keep = 0;
    for (size_t i = 0; i < r->noverlaps; ++i) {
        prox_cells_overlap o = r->overlaps[i];
        int any = 0;
        for (size_t k = 0; k < nw && !any; ++k) any = w[k].bounded && w[k].universe == o.universe;
        if (!any || witness_in_windows(P, w, nw, o.universe, 0, o.point)) {
            r->overlaps[keep++] = o;
            continue;
        }
        prox_cells_undecided u = {.universe = o.universe, .cells = {o.cells[0], o.cells[1]}, .ncells = 2, .lo = o.point,
                                  .hi = o.point, .nboxes = 1, .volume = o.volume_min, .reason = reason_parent};
        if (!add_undecided(r, u)) return PROX_ENOMEM;
    }
    r->noverlaps = keep;
    keep = 0;
    for (size_t i = 0; i < r->ngaps; ++i) {
        prox_cells_gap g = r->gaps[i];
        int any = 0;
        for (size_t k = 0; k < nw && !any; ++k) any = w[k].bounded && w[k].universe == g.universe;
        if (!any || witness_in_windows(P, w, nw, g.universe, g.window_cell, g.point)) {
            r->gaps[keep++] = g;
            continue;
        }
        prox_cells_undecided u = {.universe = g.universe, .lo = g.point, .hi = g.point, .nboxes = 1,
                                  .volume = g.volume_min, .reason = reason_parent};
        if (!add_undecided(r, u)) return PROX_ENOMEM;
    }
    r->ngaps = keep;
    return PROX_OK;
}

static prox_status check_run(prox_ccprep *P, const prox_cells_check_opts *o, prox_cells_report *r, double t0)
{
    size_t nw = 0;
    winfo *w = list_windows(P, &nw);
    prox_ccctx c;
    if (!w) return PROX_ENOMEM;
    if (prox_ccctx_init(&c, P) != PROX_OK) {
        free(w);
        return PROX_ENOMEM;
    }
    int *skip = calloc(nw, sizeof *skip);
    if (!skip) {
        prox_ccctx_free(&c);
        free(w);
        return PROX_ENOMEM;
    }
    skip_repeated_windows(P, w, nw, skip);
    prox_ccbox model = prox_ccbox_empty();
    for (size_t k = 0; k < nw; ++k) {
        if (skip[k]) {
            w[k].dom = prox_ccbox_empty(), w[k].why = NULL;
            continue;
        }
        window_domain(&c, &w[k]);
        if (w[k].universe == 0 && !prox_ccbox_is_empty(&w[k].dom)) model = prox_ccbox_or(&model, &w[k].dom);
    }
    if (prox_ccbox_is_empty(&model))
        for (size_t k = 0; k < nw; ++k) model = prox_ccbox_or(&model, &w[k].dom);
    bound_cells(&c, P, w, nw);
    prox_ccctx_free(&c);
    if (!prox_ccbox_is_empty(&model)) {
        r->lo = prox_v3(model.lo[0], model.lo[1], model.lo[2]);
        r->hi = prox_v3(model.hi[0], model.hi[1], model.hi[2]);
    }
    P->res = o && o->resolution > 0.0 ? o->resolution
                                      : PROX_CELLS_DEFAULT_RESOLUTION * (prox_ccbox_is_empty(&model) ? 1.0 : diag(&model));
    r->resolution = P->res;
    size_t ntasks = 0;
    for (size_t k = 0; k < nw; ++k) ntasks += prox_ccbox_is_empty(&w[k].dom) ? 0 : (size_t)1 << TASK_DEPTH;
    prox_cctask *tasks = malloc((ntasks ? ntasks : 1) * sizeof *tasks);
    prox_ccout *outs = calloc(ntasks ? ntasks : 1, sizeof *outs);
    prox_status st = PROX_ENOMEM;
    if (tasks && outs) {
        size_t n = 0;
        for (size_t k = 0; k < nw; ++k)
            if (!prox_ccbox_is_empty(&w[k].dom)) cut(&w[k], &w[k].dom, TASK_DEPTH, tasks, &n), r->stats.windows++;
        pool p = {.P = P, .tasks = tasks, .outs = outs, .ntasks = ntasks};
        st = run_pool(&p, o ? o->threads : 0, o ? o->progress : 0, t0);
        if (st == PROX_OK) st = prox_cc_merge(P, tasks, outs, ntasks, r);
        if (st == PROX_OK) st = confirm_bounded(P, w, nw, r);
    }
    /* Windows that could not be boxed are undecided as a whole. */
    for (size_t k = 0; k < nw && st == PROX_OK; ++k) {
        if (!w[k].why) continue;
        int told = 0; /* one entry per universe and reason */
        for (size_t j = 0; j < k && !told; ++j) told = w[j].why == w[k].why && w[j].universe == w[k].universe;
        if (told) continue;
        prox_cells_undecided *u = realloc(r->undecided, (r->nundecided + 1) * sizeof *u);
        if (!u) {
            st = PROX_ENOMEM;
            break;
        }
        r->undecided = u;
        u[r->nundecided++] = (prox_cells_undecided){.universe = w[k].universe, .lo = prox_v3(-INFINITY, -INFINITY, -INFINITY),
                                                    .hi = prox_v3(INFINITY, INFINITY, INFINITY), .volume = INFINITY,
                                                    .reason = w[k].why};
    }
    for (size_t i = 0; i < ntasks && outs; ++i) free(outs[i].recs);
    free(skip);
    free(outs);
    free(tasks);
    free(w);
    return st;
}

prox_status prox_cells_check(const prox_cell_model *m, const prox_cells_check_opts *o, prox_cells_report *r)
{
    if (!r) return PROX_EINVAL_ARG;
    memset(r, 0, sizeof *r);
    if (!m || m->nerrors || (m->nsurfs && !m->surfs) || (m->nterms && !m->terms) || (m->ncells && !m->cells) ||
        (m->nwindows && !m->windows))
        return r->status = PROX_EINVAL_ARG;
    double t0 = now();
    prox_ccprep P;
    prox_status st = prep_build(&P, m);
    if (st == PROX_OK) st = check_run(&P, o, r, t0);
    prep_free(&P);
    r->stats.seconds = now() - t0;
    if (st != PROX_OK) {
        prox_cells_report_free(r);
        r->status = st;
        return st;
    }
    r->status = PROX_OK;
    return PROX_OK;
}

void prox_cells_report_free(prox_cells_report *r)
{
    if (!r) return;
    free(r->overlaps);
    free(r->gaps);
    free(r->undecided);
    memset(r, 0, sizeof *r);
}
