/* One task of the cell check: a box of one window, subdivided depth first (halving the longest
 * edge, or, in a box crossed by more surfaces than the truth tables hold, the edge across them:
 * layer_axis) until every part is decided or the resolution is reached. A child inherits the
 * surfaces its parent proved it lies on one side of (node), and the sign assignments that no point
 * of a box has are removed by side boxes and by pair classification (feasible).
 *
 * A box is decided when, for every assignment of signs to the surfaces crossing it (check.c), the
 * window's points are claimed by exactly one cell (clean); when two cells certainly hold all of it
 * (an overlap of the box's volume); or when no cell can hold any of it (a gap). A box with open
 * assignments is probed at its centre by exact membership, so that a finding is known early (with
 * the largest cube around the probe point proved to be in it). Boxes of the resolution still open
 * are probed at 27 points: a point in two cells is an overlap witness, a point in none a gap
 * witness, even below the resolution; what no witness explains is undecided. A box whose only open
 * questions are findings this task already holds is refined only while it is large next to the
 * finding, and within budgets (below): it can only add to a known finding's volume. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cells/check_internal.h"

static const char *const reason_many = "more than six surfaces cross a box of the resolution";
static const char *const reason_overlap = "surfaces meet within the resolution: a possible overlap thinner than it";
static const char *const reason_gap = "surfaces meet within the resolution: a possible gap thinner than it";
static const char *const reason_unconfirmed = "interval proof not confirmed by exact membership";

/* A box on the boundary of a finding already proved in the task is not refined once its longest edge
 * is below KNOWN_EDGE x the cube root of the finding's proved volume (nor below the resolution):
 * the volume then misses at most a band of that width, and the work stays bounded. */
#define KNOWN_EDGE 0.1

/* Boxes of the resolution one task probes before it stops refining boxes whose every open question
 * is already recorded (a sliver thinner than the resolution along a large surface would otherwise
 * cost its area over the resolution squared). */
#define LEAF_BUDGET 256

/* Boxes on the boundary of known findings one task refines before it stops (a long thin overlap
 * would otherwise cost its area over KNOWN_EDGE x its thickness squared); volume_min stays a proved
 * lower bound, only a looser one. */
#define KNOWN_BUDGET 16384

/* A box to process. Its surfaces classified on the parent box (negative or positive: not crossing)
 * are inherited: the parent's proof covers every point of the child, so they are not classified
 * again. An entry is (surface << 1) | (1 when positive), the surface being its canonical one. So is
 * the proof that the window holds the whole parent box (its region, possibly hundreds of terms, is
 * then not evaluated again). */
typedef struct node {
    prox_ccbox box;
    size_t off, n;   /* cells: pool[off .. off + n) */
    size_t soff, sn; /* inherited surfaces: spool[soff .. soff + sn) */
    int win_all;     /* the window holds every point of the box */
} node;

typedef struct level {
    node *v;
    size_t n, cap;
    size_t *pool;
    size_t np, capp;
    size_t *spool;
    size_t nsp, capsp;
} level;

typedef struct live {
    size_t cell;
    prox_ccmask k;
} live;

/* Everything one task works with. */
typedef struct task_state {
    prox_ccctx *c;
    const prox_ccprep *P;
    const prox_cctask *t;
    size_t index;
    prox_ccout *out;
    live *lv;
    size_t nl;
    size_t *pairs, npairs, cappairs; /* proved overlap pairs (a, b), a < b */
    double *pvol;                    /* their proved volumes in this task */
    int gap_known;
    double gap_vol;
    size_t nleaves;                  /* boxes of the resolution probed so far */
    size_t nknown;                   /* boxes refined although every open question was known */
    size_t *idx[3], nidx[3], capidx[3]; /* the task's records of each kind */
    size_t *known, nknown_s, capknown; /* surfaces decided on the current box (gather_decided) */
} task_state;

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) return 1;
    size_t c = *cap ? *cap : 64;
    while (c < need) c *= 2;
    void *q = realloc(*p, c * size);
    if (!q) return 0;
    *p = q;
    *cap = c;
    return 1;
}

static prox_ccrec *new_rec(task_state *s, int kind)
{
    prox_ccout *o = s->out;
    if (!grow((void **)&o->recs, &o->cap, o->n + 1, sizeof *o->recs) ||
        !grow((void **)&s->idx[kind], &s->capidx[kind], s->nidx[kind] + 1, sizeof *s->idx[kind])) {
        o->failed = 1;
        return NULL;
    }
    s->idx[kind][s->nidx[kind]++] = o->n;
    prox_ccrec *r = &o->recs[o->n++];
    memset(r, 0, sizeof *r);
    r->task = s->index;
    r->kind = kind;
    return r;
}

/* Index of a proved pair, or -1. */
static long pair_known(const task_state *s, size_t a, size_t b)
{
    if (a > b) {
        size_t x = a;
        a = b, b = x;
    }
    for (size_t i = 0; i < s->npairs; ++i)
        if (s->pairs[2 * i] == a && s->pairs[2 * i + 1] == b) return (long)i;
    return -1;
}

static double volume(const prox_ccbox *b)
{
    return (b->hi[0] - b->lo[0]) * (b->hi[1] - b->lo[1]) * (b->hi[2] - b->lo[2]);
}

/* Sample point k (0: the centre) of the 3 x 3 x 3 grid at 1/6, 1/2, 5/6 of the box. */
static prox_vec3 sample(const prox_ccbox *b, int k)
{
    static const double f[3] = {0.5, 1.0 / 6.0, 5.0 / 6.0};
    double x[3];
    int idx[3] = {k % 3, (k / 3) % 3, k / 9};
    for (int i = 0; i < 3; ++i) x[i] = b->lo[i] + f[idx[i]] * (b->hi[i] - b->lo[i]);
    return prox_v3(x[0], x[1], x[2]);
}

/* Adds (to the task's group of the pair) an overlap of volume vol with witness x in box b. */
/* Adds (to the task's group of the pair) an overlap: a proved box of volume vol (a subdivision box,
 * disjoint from the others; or, with cube set, a proved cube that may overlap them) with witness x. */
static void add_overlap_ex(task_state *s, size_t a, size_t b, const prox_ccbox *box, double vol, prox_vec3 x, int cube)
{
    if (a > b) {
        size_t t = a;
        a = b, b = t;
    }
    prox_ccout *o = s->out;
    long k = pair_known(s, a, b);
    if (k >= 0) s->pvol[k] += vol;
    for (size_t q = 0; q < s->nidx[PROX_CC_OVERLAP]; ++q) {
        prox_ccrec *r = &o->recs[s->idx[PROX_CC_OVERLAP][q]];
        if (r->a != a || r->b != b) continue;
        if (vol > r->best) r->box = *box, r->pt = x, r->best = vol;
        if (cube) r->cube = fmax(r->cube, vol);
        else r->vol += vol;
        return;
    }
    prox_ccrec *r = new_rec(s, PROX_CC_OVERLAP);
    if (!r) return;
    r->a = a, r->b = b, r->box = *box, r->best = vol, r->pt = x, r->has_pt = 1;
    if (cube) r->cube = vol;
    else r->vol = vol;
    size_t cap = s->cappairs;
    if (grow((void **)&s->pairs, &s->cappairs, 2 * (s->npairs + 1), sizeof *s->pairs) &&
        grow((void **)&s->pvol, &cap, 2 * (s->npairs + 1), sizeof *s->pvol)) {
        s->pairs[2 * s->npairs] = a;
        s->pairs[2 * s->npairs + 1] = b;
        s->pvol[s->npairs] = vol;
        s->npairs++;
    } else s->out->failed = 1;
}

static void add_overlap(task_state *s, size_t a, size_t b, const prox_ccbox *box, double vol, prox_vec3 x)
{
    add_overlap_ex(s, a, b, box, vol, x, 0);
}

static void add_undecided(task_state *s, const size_t *cells, size_t n, const prox_ccbox *b, const char *why)
{
    prox_ccout *o = s->out;
    for (size_t q = 0; q < s->nidx[PROX_CC_UNDECIDED]; ++q) {
        prox_ccrec *r = &o->recs[s->idx[PROX_CC_UNDECIDED][q]];
        if (r->reason != why || r->ncells != n || memcmp(r->cells, cells, n * sizeof *cells))
            continue;
        r->box = prox_ccbox_or(&r->box, b);
        r->vol += volume(b);
        r->nboxes++;
        return;
    }
    prox_ccrec *r = new_rec(s, PROX_CC_UNDECIDED);
    if (!r) return;
    r->box = *b, r->vol = volume(b), r->nboxes = 1, r->reason = why, r->ncells = n;
    memcpy(r->cells, cells, n * sizeof *cells);
}

/* Adds a gap box (proved volume vol; x a witness candidate or NULL) to the first of the task's gap
 * groups whose hull it touches, or to a new group. */
static void add_gap(task_state *s, const prox_ccbox *b, double vol, const prox_vec3 *x)
{
    s->gap_known = 1;
    s->gap_vol += vol;
    prox_ccout *o = s->out;
    prox_ccrec *r = NULL;
    for (size_t q = 0; q < s->nidx[PROX_CC_GAP] && !r; ++q)
        if (prox_ccbox_meets(&o->recs[s->idx[PROX_CC_GAP][q]].box, b)) r = &o->recs[s->idx[PROX_CC_GAP][q]];
    if (!r) {
        r = new_rec(s, PROX_CC_GAP);
        if (!r) return;
        r->box = *b, r->pbox = *b, r->vol = vol, r->best = vol, r->nboxes = 1;
        if (x) r->pt = *x, r->has_pt = 1;
        return;
    }
    r->box = prox_ccbox_or(&r->box, b);
    r->vol += vol;
    r->nboxes++;
    if (vol > r->best) r->pbox = *b, r->best = vol;
    if (x && !r->has_pt) r->pt = *x, r->has_pt = 1;
}

/* A box next to a known gap, not refined: it joins the hull of the gap group it touches (so that
 * the groups of neighbouring tasks meet), adding no proved volume. */
static void grow_gap_hull(task_state *s, const prox_ccbox *b)
{
    for (size_t q = 0; q < s->nidx[PROX_CC_GAP]; ++q) {
        prox_ccrec *r = &s->out->recs[s->idx[PROX_CC_GAP][q]];
        if (prox_ccbox_meets(&r->box, b)) {
            r->box = prox_ccbox_or(&r->box, b);
            return;
        }
    }
}

/* Sorted insertion of cell i into a set of at most PROX_CELLS_UNDECIDED_MAX. */
static void set_add(size_t *set, size_t *n, size_t i)
{
    size_t k = 0;
    while (k < *n && set[k] < i) ++k;
    if (k < *n && set[k] == i) return;
    if (*n == PROX_CELLS_UNDECIDED_MAX) return;
    memmove(set + k + 1, set + k, (*n - k) * sizeof *set);
    set[k] = i;
    ++*n;
}

/* Two or more cells certainly hold the whole box (and the window does): confirm and record. */
static void overlap_box(task_state *s, const prox_ccbox *b, const size_t *allc, size_t nall)
{
    const prox_cell_model *m = s->P->m;
    for (size_t i = 0; i < nall; ++i)
        for (size_t j = i + 1; j < nall; ++j) {
            int ok = 0;
            prox_vec3 x = sample(b, 0);
            for (int k = 0; k < 27 && !ok; ++k) {
                x = sample(b, k);
                ok = prox_cell_contains(m, allc[i], x) == 1 && prox_cell_contains(m, allc[j], x) == 1 &&
                     prox_cc_in_window(s->P, s->t, x) == 1;
            }
            if (ok) add_overlap(s, allc[i], allc[j], b, volume(b), x);
            else {
                size_t set[2] = {allc[i] < allc[j] ? allc[i] : allc[j], allc[i] < allc[j] ? allc[j] : allc[i]};
                add_undecided(s, set, 2, b, reason_unconfirmed);
            }
        }
}

/* Whether every cell of the bit's set lies in undecided record r's set. */
static int in_set(const prox_ccrec *r, const size_t *ids, size_t cnt)
{
    for (size_t i = 0; i < cnt; ++i) {
        int found = 0;
        for (size_t k = 0; k < r->ncells && !found; ++k) found = r->cells[k] == ids[i];
        if (!found) return 0;
    }
    return 1;
}

/* When every open assignment of the box is explained by findings this task already holds: the
 * smallest proved volume among them (0 when an undecided record explains one; *und is then that
 * record's index); -1 otherwise. Undecided records count only when use_undecided is set. */
static double covered(const task_state *s, uint64_t prob, int use_undecided, long *und, int *gapused)
{
    if (s->nl > 16) return -1.0;
    double v = INFINITY;
    *und = -1;
    *gapused = 0;
    for (int bit = 0; bit < 64; ++bit) {
        uint64_t mk = (uint64_t)1 << bit;
        if (!(prob & mk)) continue;
        size_t ids[16], cnt = 0;
        for (size_t k = 0; k < s->nl; ++k)
            if (s->lv[k].k.p & mk) ids[cnt++] = s->lv[k].cell;
        int ok = 1;
        double bv = INFINITY;
        if (cnt < 2) {
            ok = s->gap_known;
            bv = s->gap_vol;
            *gapused |= ok;
        } else
            for (size_t i = 0; i < cnt && ok; ++i)
                for (size_t j = i + 1; j < cnt && ok; ++j) {
                    long k = pair_known(s, ids[i], ids[j]);
                    ok = k >= 0;
                    if (ok) bv = fmin(bv, s->pvol[k]);
                }
        for (size_t q = 0; q < s->nidx[PROX_CC_UNDECIDED] && !ok && use_undecided; ++q)
            if (in_set(&s->out->recs[s->idx[PROX_CC_UNDECIDED][q]], ids, cnt)) {
                ok = 1, bv = 0.0;
                *und = (long)s->idx[PROX_CC_UNDECIDED][q];
            }
        if (!ok) return -1.0;
        v = fmin(v, bv);
    }
    return v;
}

/* Exact membership at the centre of a box with open questions: a point in two cells (in none)
 * makes the pair (a gap) known at once, so that a thin finding found at a coarse level does not have
 * its whole boundary refined before its first proved box. Returns 1 when it recorded something. */
/* The largest cube centred at x, half-width h halved up to 12 times, proved to lie in the window
 * and in both cells a and b (in no live cell when gap is set); 0 when none is. */
static double proved_cube(task_state *s, prox_vec3 x, double h, size_t a, size_t b, int gap, prox_ccbox *cube)
{
    const prox_cell_model *m = s->P->m;
    for (int it = 0; it < 12; ++it, h *= 0.5) {
        *cube = (prox_ccbox){{x.x - h, x.y - h, x.z - h}, {x.x + h, x.y + h, x.z + h}};
        prox_ccctx_box(s->c, cube);
        if (prox_cc_eval(s->c, s->t->wexpr, s->t->wnexpr).t != PROX_CC_ALL) continue;
        int ok = 1;
        if (gap)
            for (size_t q = 0; q < s->nl && ok; ++q) ok = !prox_cc_eval(s->c, m->cells[s->lv[q].cell].expr, m->cells[s->lv[q].cell].nexpr).p;
        else
            ok = prox_cc_eval(s->c, m->cells[a].expr, m->cells[a].nexpr).t == PROX_CC_ALL &&
                 prox_cc_eval(s->c, m->cells[b].expr, m->cells[b].nexpr).t == PROX_CC_ALL;
        if (ok) return volume(cube);
    }
    return 0.0;
}

/* The live cells that hold x (up to four, in inc) by exact membership; *amb set when x lies on a
 * surface that decides a cell. */
static size_t cells_at(const task_state *s, prox_vec3 x, size_t inc[4], int *amb)
{
    size_t ninc = 0;
    *amb = 0;
    for (size_t q = 0; q < s->nl; ++q) {
        int v = prox_cell_contains(s->P->m, s->lv[q].cell, x);
        if (v < 0) *amb = 1;
        else if (v == 1 && ninc < 4) inc[ninc++] = s->lv[q].cell;
    }
    return ninc;
}

/* Whether a point held by the cells inc would add a finding: a pair not yet proved (any pair when
 * all_pairs is set), or no cell at all while gaps are still sought. Only then does the point's
 * window membership matter; it is asked last, because a window's region (a lattice element bounded
 * by its parent) can be far longer than the cells'. */
static int would_record(const task_state *s, const size_t *inc, size_t ninc, int amb, int seek_gap, int all_pairs)
{
    if (ninc == 0) return !amb && seek_gap;
    for (size_t i = 0; i < ninc; ++i)
        for (size_t j = i + 1; j < ninc; ++j)
            if (all_pairs || pair_known(s, inc[i], inc[j]) < 0) return 1;
    return 0;
}

static int probe(task_state *s, const prox_ccbox *b)
{
    prox_vec3 x = sample(b, 0);
    size_t inc[4];
    int amb, rec = 0;
    size_t ninc = cells_at(s, x, inc, &amb);
    if (!would_record(s, inc, ninc, amb, !s->gap_known, 0)) return 0;
    if (s->t->wnexpr && prox_cc_in_window(s->P, s->t, x) != 1) return 0;
    double h = 0.5 * fmin(b->hi[0] - b->lo[0], fmin(b->hi[1] - b->lo[1], b->hi[2] - b->lo[2]));
    prox_ccbox cube;
    for (size_t i = 0; i < ninc; ++i)
        for (size_t j = i + 1; j < ninc; ++j)
            if (pair_known(s, inc[i], inc[j]) < 0) {
                double v = proved_cube(s, x, h, inc[i], inc[j], 0, &cube);
                add_overlap_ex(s, inc[i], inc[j], v > 0.0 ? &cube : b, v, x, 1);
                rec = 1;
            }
    if (ninc == 0 && !amb && !s->gap_known) {
        double v = proved_cube(s, x, h, 0, 0, 1, &cube);
        add_gap(s, v > 0.0 ? &cube : b, 0.0, &x);
        prox_ccrec *g = &s->out->recs[s->idx[PROX_CC_GAP][s->nidx[PROX_CC_GAP] - 1]];
        if (!s->out->failed && prox_ccbox_meets(&g->box, &cube)) g->cube = fmax(g->cube, v), s->gap_vol += v;
        rec = 1;
    }
    return rec;
}

/* A box of the resolution with open assignments: probe it by exact membership at 27 points. Every
 * witness found is recorded; what no witness explains is recorded as undecided. */
static void leaf(task_state *s, const prox_ccbox *b, uint64_t prob)
{
    s->out->leaves++;
    s->nleaves++;
    int gap_found = 0;
    for (int k = 0; k < 27; ++k) {
        prox_vec3 x = sample(b, k);
        size_t inc[4];
        int amb;
        size_t ninc = cells_at(s, x, inc, &amb);
        if (!would_record(s, inc, ninc, amb, !gap_found, k == 0)) continue;
        if (s->t->wnexpr && prox_cc_in_window(s->P, s->t, x) != 1) continue;
        for (size_t i = 0; i < ninc; ++i)
            for (size_t j = i + 1; j < ninc; ++j)
                if (pair_known(s, inc[i], inc[j]) < 0 || k == 0) add_overlap(s, inc[i], inc[j], b, 0.0, x);
        if (ninc == 0 && !amb && !gap_found) {
            add_gap(s, b, 0.0, &x);
            gap_found = 1;
        }
    }
    /* The assignments no witness explains. */
    size_t set[PROX_CELLS_UNDECIDED_MAX], n = 0;
    int over = 0, open = 0;
    for (int bit = 0; bit < 64; ++bit) {
        uint64_t mk = (uint64_t)1 << bit;
        if (!(prob & mk)) continue;
        size_t ids[16], cnt = 0;
        for (size_t q = 0; q < s->nl && cnt < 16; ++q)
            if (s->lv[q].k.p & mk) ids[cnt++] = s->lv[q].cell;
        int ok = cnt < 2 ? s->gap_known : 1;
        for (size_t i = 0; i < cnt && ok && cnt >= 2; ++i)
            for (size_t j = i + 1; j < cnt && ok; ++j) ok = pair_known(s, ids[i], ids[j]) >= 0;
        if (ok) continue;
        open = 1;
        for (size_t i = 0; i < cnt; ++i) set_add(set, &n, ids[i]);
        over |= cnt >= 2;
    }
    if (open) add_undecided(s, set, n, b, s->c->overflow ? reason_many : over ? reason_overlap : reason_gap);
}

static const uint64_t var_neg[PROX_CC_VARS] = {0xAAAAAAAAAAAAAAAAull, 0xCCCCCCCCCCCCCCCCull, 0xF0F0F0F0F0F0F0F0ull,
                                               0xFF00FF00FF00FF00ull, 0xFFFF0000FFFF0000ull, 0xFFFFFFFF00000000ull};

/* The assignments of signs to variables u and v that pair classification (classify.c) proves no
 * point of the box has: g = f_v - lambda f_u < 0 leaves no point with f_v >= 0 and the sign of f_u
 * opposite to lambda's; g > 0, none with f_v <= 0 and f_u of lambda's sign. This is what tells that
 * a point inside the inner of two concentric spheres (coaxial cylinders, parallel planes) is inside
 * the outer one, so that a thin shell is not refined along its whole area. */
static uint64_t pair_empty(prox_ccctx *c, int u, int v)
{
    const prox_surf *S = c->P->m->surfs;
    double lam;
    int k = prox_cc_classify_pair(&S[c->vsurf[u]], &S[c->vsurf[v]], &c->box, &lam);
    if (!k) return 0;
    const uint64_t u_as_lam = lam > 0.0 ? ~var_neg[u] : var_neg[u]; /* f_u of lambda's sign */
    return k < 0 ? ~var_neg[v] & ~u_as_lam : var_neg[v] & u_as_lam;
}

/* Assignments of signs to the crossing surfaces that no point of the box can have, removed pairwise.
 * First the pair classification of each pair (pair_empty). Then, while an assignment of prob is
 * left: on the part of the box where surface u has sign a (the box cut to a's side box), surface v
 * may be proved wholly negative or positive (classify.c); then (u = a, v = the other sign) is empty.
 * This is what tells that a pin's cylinder never reaches the planes of its lattice element. Every
 * removal is a proof, so stopping once nothing of prob is left changes nothing but the time. */
static uint64_t feasible(prox_ccctx *c, uint64_t prob)
{
    const prox_ccprep *P = c->P;
    uint64_t f = PROX_CC_ALL;
    for (int u = 0; u < c->nvar && (prob & f); ++u)
        for (int v = u + 1; v < c->nvar && (prob & f); ++v) f &= ~pair_empty(c, u, v);
    for (int u = 0; u < c->nvar && (prob & f); ++u)
        for (int a = -1; a <= 1 && (prob & f); a += 2) {
            prox_ccbox side = prox_cc_side_box(&P->m->surfs[c->vsurf[u]], a);
            prox_ccbox e = prox_ccbox_and(&side, &c->box);
            uint64_t mu = a < 0 ? var_neg[u] : ~var_neg[u];
            if (prox_ccbox_is_empty(&e)) {
                f &= ~mu;
                continue;
            }
            int same = 1;
            for (int i = 0; i < 3; ++i) same = same && e.lo[i] == c->box.lo[i] && e.hi[i] == c->box.hi[i];
            if (same) continue; /* the side box does not cut the box: nothing to learn */
            for (int v = 0; v < c->nvar; ++v) {
                if (v == u || !(prob & f & mu)) continue; /* nothing of (u = a) left to remove */
                int k = prox_cc_classify(&P->m->surfs[c->vsurf[v]], &e);
                if (k < 0) f &= ~(mu & ~var_neg[v]);
                else if (k > 0) f &= ~(mu & var_neg[v]);
            }
        }
    return f;
}

static int push(level *L, const prox_ccbox *b, const live *lv, size_t nl, const size_t *known, size_t nk, int win_all)
{
    if (!grow((void **)&L->v, &L->cap, L->n + 1, sizeof *L->v) ||
        !grow((void **)&L->pool, &L->capp, L->np + nl, sizeof *L->pool) ||
        !grow((void **)&L->spool, &L->capsp, L->nsp + nk, sizeof *L->spool))
        return 0;
    L->v[L->n++] = (node){*b, L->np, nl, L->nsp, nk, win_all};
    for (size_t k = 0; k < nl; ++k) L->pool[L->np++] = lv[k].cell;
    if (nk) memcpy(L->spool + L->nsp, known, nk * sizeof *known);
    L->nsp += nk;
    return 1;
}

/* Marks the parent's decided surfaces as classified on the context's (child) box. */
static void seed_decided(prox_ccctx *c, const size_t *known, size_t nk)
{
    for (size_t k = 0; k < nk; ++k) {
        size_t r = known[k] >> 1;
        c->seen[r] = c->stamp;
        c->cls[r] = (known[k] & 1) ? 1 : -1;
        c->var[r] = -1;
    }
}

/* Regions longer than this are not scanned for decided surfaces: the scan reads every term, while
 * their evaluation skips the subtrees whose boxes miss the box (a lattice element bounded by its
 * parent has hundreds of terms, most of them far away). */
#define GATHER_TERMS_MAX 64

/* Appends to s->known the surfaces of the region [e, e + n) classified negative or positive on the
 * context's box; var = -2 marks one already taken (var is read only for crossing surfaces). */
static int gather_region(task_state *s, size_t e, size_t n)
{
    prox_ccctx *c = s->c;
    const prox_ccprep *P = s->P;
    if (n > GATHER_TERMS_MAX) return 1;
    for (size_t i = e; i < e + n; ++i) {
        const prox_term *t = &P->m->terms[i];
        if (t->op != PROX_OP_LEAF) continue;
        size_t r = P->rep[t->surf];
        if (c->seen[r] != c->stamp || c->cls[r] == 0 || c->var[r] == -2) continue;
        if (!grow((void **)&s->known, &s->capknown, s->nknown_s + 1, sizeof *s->known)) return 0;
        s->known[s->nknown_s++] = (r << 1) | (c->cls[r] > 0);
        c->var[r] = -2;
    }
    return 1;
}

/* The surfaces of the window and of the live cells decided on the current box, for its halves. */
static int gather_decided(task_state *s)
{
    s->nknown_s = 0;
    if (!gather_region(s, s->t->wexpr, s->t->wnexpr)) return 0;
    const prox_cell *cells = s->P->m->cells;
    for (size_t q = 0; q < s->nl; ++q)
        if (!gather_region(s, cells[s->lv[q].cell].expr, cells[s->lv[q].cell].nexpr)) return 0;
    return 1;
}

/* A box crossed by more surfaces than the truth tables hold is split across the surfaces rather than
 * along its longest edge, while its edge on that axis is at least 1/LAYER_ASPECT of the longest: a
 * stack of thin layers (fuel plates, shells) is then cut into slabs along the layers, whose number
 * grows with the layers, not cubes, whose number grows with the layers' area over their pitch squared.
 * How a box is cut changes only the time: every box is still decided by the same proofs. */
#define LAYER_ASPECT 16.0

/* The axis along which the crossing surfaces' unit normals (at the box centre) point the most. */
static int layer_axis(const prox_ccctx *c, const prox_ccbox *b, int ax)
{
    double acc[3] = {0.0, 0.0, 0.0};
    for (int v = 0; v < c->nvar; ++v) {
        const prox_surf *S = &c->P->m->surfs[c->vsurf[v]];
        if (S->kind != PROX_SURF_QUADRIC) continue;
        const double *q = S->q;
        const double x = 0.5 * b->lo[0] + 0.5 * b->hi[0] - S->o.x, y = 0.5 * b->lo[1] + 0.5 * b->hi[1] - S->o.y,
                     z = 0.5 * b->lo[2] + 0.5 * b->hi[2] - S->o.z;
        const double g[3] = {2.0 * q[0] * x + q[3] * y + q[5] * z + q[6], 2.0 * q[1] * y + q[3] * x + q[4] * z + q[7],
                             2.0 * q[2] * z + q[4] * y + q[5] * x + q[8]};
        const double n = fabs(g[0]) + fabs(g[1]) + fabs(g[2]);
        if (n > 0.0 && isfinite(n))
            for (int i = 0; i < 3; ++i) acc[i] += fabs(g[i]) / n;
    }
    int best = ax;
    for (int i = 0; i < 3; ++i)
        if (acc[i] > acc[best] && LAYER_ASPECT * (b->hi[i] - b->lo[i]) >= b->hi[ax] - b->lo[ax]) best = i;
    return best;
}

/* Decides one box, or pushes its two halves onto `next`. */
static void process(task_state *s, const node *nd, const size_t *pool, const size_t *spool, level *next)
{
    const prox_ccprep *P = s->P;
    const prox_cell_model *m = P->m;
    const prox_ccbox *b = &nd->box;
    prox_ccctx_box(s->c, b);
    seed_decided(s->c, spool + nd->soff, nd->sn);
    const prox_ccmask all = {PROX_CC_ALL, PROX_CC_ALL};
    prox_ccmask W = nd->win_all ? all : prox_cc_eval(s->c, s->t->wexpr, s->t->wnexpr);
    if (!W.p) return;
    s->out->boxes++;
    uint64_t oneP = 0, twoP = 0, oneT = 0;
    size_t allc[PROX_CELLS_UNDECIDED_MAX], nall = 0;
    s->nl = 0;
    for (size_t q = 0; q < nd->n; ++q) {
        size_t i = pool[nd->off + q];
        if (!prox_ccbox_meets(&P->cbox[i], b)) continue;
        prox_ccmask k = prox_cc_eval(s->c, m->cells[i].expr, m->cells[i].nexpr);
        if (!k.p) continue;
        s->lv[s->nl++] = (live){i, k};
        twoP |= oneP & k.p;
        oneP |= k.p;
        oneT |= k.t;
        if (k.t == PROX_CC_ALL && nall < PROX_CELLS_UNDECIDED_MAX) allc[nall++] = i;
    }
    const uint32_t stamp = s->c->stamp; /* the classifications of b (a probe may move the context) */
    uint64_t prob = W.p & ~(oneT & ~twoP);
    if (prob && s->c->nvar >= 2) prob &= feasible(s->c, prob);
    if (!prob) {
        s->out->clean++;
        return;
    }
    if (W.t == PROX_CC_ALL && nall >= 2) {
        overlap_box(s, b, allc, nall);
        return;
    }
    if (W.t == PROX_CC_ALL && !oneP) {
        add_gap(s, b, volume(b), NULL);
        return;
    }
    int ax = 0;
    for (int i = 1; i < 3; ++i)
        if (b->hi[i] - b->lo[i] > b->hi[ax] - b->lo[ax]) ax = i;
    const int sx = s->c->overflow ? layer_axis(s->c, b, ax) : ax; /* before a probe moves the context */
    /* The boundary of a known finding is refined only until its boxes are small next to it; once the
     * task has probed LEAF_BUDGET boxes, not at all (undecided slivers then grow by whole boxes). */
    long und = -1;
    int spent = s->nleaves >= LEAF_BUDGET, gapused = 0;
    double known = covered(s, prob, spent, &und, &gapused);
    int overflow = s->c->overflow; /* the probe evaluates other boxes */
    if (known < 0.0 && probe(s, b)) known = covered(s, prob, spent, &und, &gapused);
    s->c->overflow = overflow;
    if (known >= 0.0 && !spent && s->nknown++ >= KNOWN_BUDGET) spent = 1;
    if (known >= 0.0 && (spent || b->hi[ax] - b->lo[ax] <= fmax(P->res, KNOWN_EDGE * cbrt(known)))) {
        if (und >= 0) {
            prox_ccrec *r = &s->out->recs[und];
            r->box = prox_ccbox_or(&r->box, b);
            r->vol += volume(b);
            r->nboxes++;
        }
        if (gapused) grow_gap_hull(s, b);
        return;
    }
    if (b->hi[ax] - b->lo[ax] <= P->res) {
        leaf(s, b, prob);
        return;
    }
    prox_ccbox l = *b, r = *b;
    l.hi[sx] = r.lo[sx] = 0.5 * b->lo[sx] + 0.5 * b->hi[sx];
    s->nknown_s = 0;
    if (s->c->stamp == stamp && !gather_decided(s)) s->nknown_s = 0;
    const int win_all = W.t == PROX_CC_ALL;
    if (!push(next, &l, s->lv, s->nl, s->known, s->nknown_s, win_all) ||
        !push(next, &r, s->lv, s->nl, s->known, s->nknown_s, win_all))
        s->out->failed = 1;
}

void prox_cc_run_task(prox_ccctx *c, const prox_cctask *t, size_t task_index, prox_ccout *out)
{
    const prox_ccprep *P = c->P;
    task_state s = {.c = c, .P = P, .t = t, .index = task_index, .out = out};
    level cur = {0}, next = {0};
    s.lv = malloc((t->nucell ? t->nucell : 1) * sizeof *s.lv);
    if (!s.lv) {
        out->failed = 1;
        return;
    }
    /* The root: the universe's cells whose boxes meet the task's box. */
    size_t nl = 0;
    for (size_t q = 0; q < t->nucell; ++q) {
        size_t i = P->ucells[t->ucell0 + q];
        if (prox_ccbox_meets(&P->cbox[i], &t->box)) s.lv[nl++] = (live){i, {0, 0}};
    }
    /* Depth first (a stack): a problem is met at the resolution early, so that the budgets above
     * stop the refinement of a hopeless sliver at coarse boxes. The pool is a stack too: the cells
     * of the nodes above the top are dead once it is popped. */
    if (!push(&cur, &t->box, s.lv, nl, NULL, 0, 0)) out->failed = 1;
    while (cur.n && !out->failed) {
        node nd = cur.v[--cur.n];
        cur.np = nd.off + nd.n;
        cur.nsp = nd.soff + nd.sn;
        process(&s, &nd, cur.pool, cur.spool, &cur);
    }
    free(cur.v);
    free(cur.pool);
    free(cur.spool);
    free(next.spool);
    free(s.known);
    free(next.v);
    free(next.pool);
    free(s.lv);
    free(s.pairs);
    for (int k = 0; k < 3; ++k) free(s.idx[k]);
    free(s.pvol);
}

int prox_cc_in_window(const prox_ccprep *P, const prox_cctask *t, prox_vec3 x)
{
    if (!t->wnexpr) return 1;
    return prox_region_contains(P->m, t->wexpr, t->wnexpr, x);
}
