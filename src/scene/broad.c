/* Broad phase of scene queries (src/scene/broad.h): every pair of boxes that come within c of each
 * other, found with a bounding volume hierarchy, so that the work grows with the pairs near enough to
 * test and not with the bodies a slab along one axis happens to hold.
 *
 * Each box is enlarged to E = [lo, hi + c]: two boxes come within c on an axis (lo_j <= hi_i + c and
 * lo_i <= hi_j + c) exactly when their enlarged intervals overlap, with the same rounding as the test
 * itself. The hierarchy is built top-down over the enlarged boxes: a node's items are split at the
 * median of their box centres along the axis where the centres spread most (an object-median split,
 * Ericson, Real-Time Collision Detection, Sec. 6.2.1-6.2.2), down to leaves of at most BROAD_LEAF
 * items. A median split by count keeps the tree balanced (depth log2(n / BROAD_LEAF)) whatever the
 * sizes, positions or duplicates of the bodies; a huge body only widens the nodes above its leaf.
 *
 * The top levels are split serially and the subtrees below them built by the worker threads; every
 * subtree owns a fixed range of node slots, so the tree is the same whatever the thread count.
 *
 * Query: item p (in leaf order) descends into every node whose box overlaps E_p and that holds an
 * item after p, and tests those items; each pair is thus found once, from its first item in leaf
 * order. The items are queried in leaf order, so consecutive queries walk the same nodes (they stay
 * in cache), in chunks taken from an atomic counter by the worker threads, each into its own list.
 * The lists are merged by a counting sort on the first index and a sort of each bucket on the
 * second: the output is sorted by (a, b), independent of the thread count and of the schedule.
 *
 * Memory: 56 bytes per item, n - 1 node slots of 72 bytes, 8 bytes per body for the counting sort,
 * and 16 bytes per pair twice (the workers' lists and the sorted output). */
#define _POSIX_C_SOURCE 200809L /* sysconf, pthreads */
#include "scene/broad.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#define BROAD_LEAF 4     /* items per leaf: a leaf test costs about what one more level of nodes does */
#define BROAD_CHUNK 512  /* query positions a worker takes at once */
#define BROAD_STACK 192  /* traversal stack: the depth is at most log2(n) + 1 < 66 */

/* The node slots (see split) assume that every leaf holds at least 2 items. */
_Static_assert(BROAD_LEAF >= 3, "a split of BROAD_LEAF + 1 items must leave at least 2 on each side");

/* ---- threads ------------------------------------------------------------------------------------ */

int prox_par_threads(int requested)
{
    long t = requested;
    if (t <= 0) {
#ifdef _OPENMP
        t = omp_get_max_threads();
#else
        t = sysconf(_SC_NPROCESSORS_ONLN);
#endif
    }
    if (t < 1) t = 1;
    return t > PROX_PAR_MAX_THREADS ? PROX_PAR_MAX_THREADS : (int)t;
}

typedef struct par_arg {
    prox_par_fn fn;
    void *ctx;
    int worker;
} par_arg;

static void *par_entry(void *p)
{
    par_arg *a = p;
    a->fn(a->ctx, a->worker);
    return NULL;
}

void prox_par_run(int threads, prox_par_fn fn, void *ctx)
{
    if (threads < 1) threads = 1;
    if (threads > PROX_PAR_MAX_THREADS) threads = PROX_PAR_MAX_THREADS;
    pthread_t tid[PROX_PAR_MAX_THREADS];
    par_arg arg[PROX_PAR_MAX_THREADS];
    int started[PROX_PAR_MAX_THREADS] = {0};
    for (int w = 1; w < threads; ++w) {
        arg[w] = (par_arg){fn, ctx, w};
        started[w] = pthread_create(&tid[w], NULL, par_entry, &arg[w]) == 0;
    }
    fn(ctx, 0);
    for (int w = 1; w < threads; ++w) {
        if (started[w]) pthread_join(tid[w], NULL);
        else fn(ctx, w); /* no thread for it: the caller does its share (usually nothing is left) */
    }
}

/* ---- the hierarchy ------------------------------------------------------------------------------ */

/* An enlarged box [lo, hi + c] and the index of its body. */
typedef struct item {
    double lo[3], hi[3];
    size_t idx;
} item;

/* A node: the union of its items' boxes, the items [start, end) in leaf order, and its right child
 * (0 for a leaf; the left child is the next node). */
typedef struct node {
    double lo[3], hi[3];
    size_t start, end, right;
} node;

typedef struct tree {
    item *it;
    node *nd; /* n - 1 slots suffice (see split) */
    size_t n;
} tree;

/* Minimum and maximum without libm's NaN handling (no NaN reaches the broad phase: shapes are
 * validated, and an infinite c only makes boxes unbounded). */
static inline double dmin(double a, double b) { return b < a ? b : a; }
static inline double dmax(double a, double b) { return b > a ? b : a; }

/* Twice the centre of an item along axis k: the key of the median split. */
static double centre2(const item *x, int k) { return x->lo[k] + x->hi[k]; }

/* The axis along which the centres of items [0, m) spread most. */
static int split_axis(const item *a, size_t m)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < m; ++i)
        for (int k = 0; k < 3; ++k) {
            double v = centre2(&a[i], k);
            lo[k] = dmin(lo[k], v), hi[k] = dmax(hi[k], v);
        }
    int ax = 0;
    for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > hi[ax] - lo[ax]) ax = k;
    return ax;
}

static void swap_item(item *x, item *y)
{
    item t = *x;
    *x = *y, *y = t;
}

/* The middle one of three values. */
static double median3(double a, double b, double c)
{
    if (a > b) {
        double t = a;
        a = b, b = t;
    }
    return c < a ? a : (c > b ? b : c);
}

/* Quickselect (Hoare's partition, median-of-three pivot): afterwards no item before position k has
 * a larger key along axis ax than item k, and none after it a smaller one. Equal keys are split
 * evenly, so a pile of duplicates still halves. */
static void select_nth(item *a, size_t m, size_t k, int ax)
{
    ptrdiff_t lo = 0, hi = (ptrdiff_t)m - 1, kk = (ptrdiff_t)k;
    while (hi > lo) {
        double p = median3(centre2(&a[lo], ax), centre2(&a[lo + (hi - lo) / 2], ax), centre2(&a[hi], ax));
        ptrdiff_t i = lo, j = hi;
        while (i <= j) {
            while (centre2(&a[i], ax) < p) ++i;
            while (centre2(&a[j], ax) > p) --j;
            if (i <= j) swap_item(&a[i++], &a[j--]);
        }
        /* now keys of [lo, j] <= p <= keys of [i, hi], and every key strictly between is p */
        if (kk <= j) hi = j;
        else if (kk >= i) lo = i;
        else return;
    }
}

/* The box of node d from its items (leaf) or its children. */
static void node_box_items(node *d, const item *it)
{
    for (int k = 0; k < 3; ++k) d->lo[k] = INFINITY, d->hi[k] = -INFINITY;
    for (size_t i = d->start; i < d->end; ++i)
        for (int k = 0; k < 3; ++k) d->lo[k] = dmin(d->lo[k], it[i].lo[k]), d->hi[k] = dmax(d->hi[k], it[i].hi[k]);
}

static void node_box_children(node *d, const node *l, const node *r)
{
    for (int k = 0; k < 3; ++k) d->lo[k] = dmin(l->lo[k], r->lo[k]), d->hi[k] = dmax(l->hi[k], r->hi[k]);
}

/* Node slots: the subtree of m >= 2 items has at most m - 1 nodes (each leaf holds at least 2 items:
 * only m > BROAD_LEAF >= 4 is split, into halves of at least 2). The subtree at slot `me` with
 * m items gives its left child (m / 2 items) slot me + 1 and its right child slot me + m / 2, so
 * every subtree owns a fixed range of slots and subtrees can be built in parallel. */

/* Splits the items of node me (when it has more than BROAD_LEAF) and returns the number of items
 * of its left child, or 0 for a leaf (whose box is then set). */
static size_t split(tree *t, size_t me, size_t start, size_t end)
{
    node *d = &t->nd[me];
    d->start = start, d->end = end, d->right = 0;
    size_t m = end - start;
    if (m <= BROAD_LEAF) {
        node_box_items(d, t->it);
        return 0;
    }
    size_t half = m / 2;
    select_nth(t->it + start, m, half, split_axis(t->it + start, m));
    d->right = me + half;
    return half;
}

/* Builds the subtree of items [start, end) at slot me. Recursion depth log2(n / BROAD_LEAF): the
 * median split halves the count at every level. */
static void build(tree *t, size_t me, size_t start, size_t end)
{
    size_t half = split(t, me, start, end);
    if (!half) return;
    build(t, me + 1, start, start + half);
    build(t, me + half, start + half, end);
    node_box_children(&t->nd[me], &t->nd[me + 1], &t->nd[me + half]);
}

/* The subtrees below the top levels, built by the workers in parallel. */
typedef struct build_task {
    size_t me, start, end;
} build_task;

typedef struct build_job {
    tree *t;
    build_task task[64];
    int ntask;
    atomic_int next;
} build_job;

/* Splits the top `levels` levels serially and queues the subtrees below them. */
static void build_top(build_job *j, size_t me, size_t start, size_t end, int levels)
{
    if (levels == 0) {
        j->task[j->ntask++] = (build_task){me, start, end};
        return;
    }
    size_t half = split(j->t, me, start, end);
    if (!half) return;
    build_top(j, me + 1, start, start + half, levels - 1);
    build_top(j, me + half, start + half, end, levels - 1);
}

/* Boxes of the top levels, once the subtrees below them are built. */
static void finish_top(tree *t, size_t me, int levels)
{
    node *d = &t->nd[me];
    if (levels == 0 || !d->right) return;
    finish_top(t, me + 1, levels - 1);
    finish_top(t, d->right, levels - 1);
    node_box_children(d, &t->nd[me + 1], &t->nd[d->right]);
}

static void build_worker(void *ctx, int w)
{
    build_job *j = ctx;
    (void)w;
    for (int k; (k = atomic_fetch_add(&j->next, 1)) < j->ntask;) build(j->t, j->task[k].me, j->task[k].start, j->task[k].end);
}

/* The whole tree: the top levels serially, then 2^levels subtrees on the worker threads (levels
 * from the thread count, at most 6: the task list holds 64). */
static void build_tree(tree *t, int threads)
{
    int levels = 0;
    while ((1 << levels) < threads && levels < 6) ++levels;
    if (levels && threads > 1) ++levels; /* twice as many subtrees as threads: they differ in cost */
    if (levels > 6) levels = 6;
    build_job j = {.t = t};
    atomic_init(&j.next, 0);
    build_top(&j, 0, 0, t->n, levels);
    prox_par_run(j.ntask > 1 ? threads : 1, build_worker, &j);
    finish_top(t, 0, levels);
}

/* 1 when the closed boxes overlap on all three axes. */
static int overlap(const double *alo, const double *ahi, const double *blo, const double *bhi)
{
    return alo[0] <= bhi[0] && blo[0] <= ahi[0] && alo[1] <= bhi[1] && blo[1] <= ahi[1] && alo[2] <= bhi[2] &&
           blo[2] <= ahi[2];
}

/* ---- queries ------------------------------------------------------------------------------------ */

/* A worker's list of pairs. */
typedef struct plist {
    prox_broad_pair *v;
    size_t n, cap;
} plist;

static int plist_push(plist *l, size_t a, size_t b)
{
    if (l->n == l->cap) {
        size_t nc = l->cap ? 2 * l->cap : 4096;
        prox_broad_pair *q = realloc(l->v, nc * sizeof *q);
        if (!q) return -1;
        l->v = q, l->cap = nc;
    }
    l->v[l->n++] = a < b ? (prox_broad_pair){a, b} : (prox_broad_pair){b, a};
    return 0;
}

/* The pairs of item p with the items after it in leaf order. */
static int query(const tree *t, size_t p, plist *out)
{
    const item *q = &t->it[p];
    size_t stack[BROAD_STACK];
    int sp = 0;
    stack[sp++] = 0;
    while (sp) {
        const node *d = &t->nd[stack[--sp]];
        if (d->end <= p + 1 || !overlap(d->lo, d->hi, q->lo, q->hi)) continue;
        if (d->right) {
            stack[sp++] = d->right;
            stack[sp++] = (size_t)(d - t->nd) + 1; /* the left child first */
            continue;
        }
        for (size_t k = d->start > p + 1 ? d->start : p + 1; k < d->end; ++k)
            if (overlap(t->it[k].lo, t->it[k].hi, q->lo, q->hi) && plist_push(out, q->idx, t->it[k].idx)) return -1;
    }
    return 0;
}

typedef struct query_job {
    const tree *t;
    atomic_size_t next;
    atomic_int fail;
    plist *lists; /* one per worker */
} query_job;

static void query_worker(void *ctx, int w)
{
    query_job *j = ctx;
    for (;;) {
        size_t start = atomic_fetch_add(&j->next, BROAD_CHUNK);
        if (start >= j->t->n || atomic_load(&j->fail)) return;
        size_t end = start + BROAD_CHUNK < j->t->n ? start + BROAD_CHUNK : j->t->n;
        for (size_t p = start; p < end; ++p)
            if (query(j->t, p, &j->lists[w])) {
                atomic_store(&j->fail, 1);
                return;
            }
    }
}

/* ---- the sorted output -------------------------------------------------------------------------- */

static int cmp_second(const void *x, const void *y)
{
    size_t a = ((const prox_broad_pair *)x)->b, b = ((const prox_broad_pair *)y)->b;
    return (a > b) - (a < b);
}

/* Merges the workers' lists into one array sorted by (a, b): a counting sort on a (bodies n), then
 * each bucket by b. Returns NULL when out of memory or when there is nothing to merge. */
static prox_broad_pair *merge_sorted(plist *lists, int nl, size_t n, size_t total)
{
    if (!total) return NULL;
    prox_broad_pair *out = malloc(total * sizeof *out);
    size_t *pos = calloc(n + 1, sizeof *pos);
    if (!out || !pos) {
        free(out), free(pos);
        return NULL;
    }
    for (int w = 0; w < nl; ++w)
        for (size_t i = 0; i < lists[w].n; ++i) pos[lists[w].v[i].a + 1]++;
    for (size_t a = 0; a < n; ++a) pos[a + 1] += pos[a];
    for (int w = 0; w < nl; ++w) {
        for (size_t i = 0; i < lists[w].n; ++i) out[pos[lists[w].v[i].a]++] = lists[w].v[i];
        free(lists[w].v), lists[w].v = NULL;
    }
    /* pos[a] is now the end of bucket a, which starts where bucket a - 1 ends */
    for (size_t a = 0, begin = 0; a < n; begin = pos[a++])
        if (pos[a] - begin > 1) qsort(out + begin, pos[a] - begin, sizeof *out, cmp_second);
    free(pos);
    return out;
}

/* Copies the enlarged boxes into leaf items. */
static item *make_items(const prox_aabb *box0, size_t stride, size_t n, double c)
{
    item *it = malloc(n * sizeof *it);
    if (!it) return NULL;
    for (size_t i = 0; i < n; ++i) {
        const prox_aabb *b = (const prox_aabb *)((const char *)box0 + i * stride);
        it[i] = (item){{b->lo.x, b->lo.y, b->lo.z}, {b->hi.x + c, b->hi.y + c, b->hi.z + c}, i};
    }
    return it;
}

int prox_broad_pairs(const prox_aabb *box0, size_t stride, size_t n, double c, int threads, prox_broad_pair **out,
                     size_t *nout)
{
    *out = NULL, *nout = 0;
    if (n < 2) return 0;
    if (threads < 1) threads = 1;
    if (threads > PROX_PAR_MAX_THREADS) threads = PROX_PAR_MAX_THREADS;
    tree t = {make_items(box0, stride, n, c), malloc((n - 1) * sizeof(node)), n};
    plist *lists = calloc((size_t)threads, sizeof *lists);
    int fail = !t.it || !t.nd || !lists;
    if (!fail) {
        build_tree(&t, threads);
        query_job job = {.t = &t, .lists = lists};
        atomic_init(&job.next, 0);
        atomic_init(&job.fail, 0);
        prox_par_run(n > BROAD_CHUNK ? threads : 1, query_worker, &job);
        fail = atomic_load(&job.fail);
    }
    free(t.it), free(t.nd);
    size_t total = 0;
    for (int w = 0; lists && w < threads; ++w) total += lists[w].n;
    if (!fail && total) {
        *out = merge_sorted(lists, threads, n, total);
        fail = !*out;
    }
    for (int w = 0; lists && w < threads; ++w) free(lists[w].v);
    free(lists);
    if (fail) return -1;
    *nout = total;
    return 0;
}
