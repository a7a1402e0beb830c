/* Internal: the pieces of the cell check (include/prox/cellcheck.h) shared by its files:
 * classify.c (certified box-surface and box-pair classification), check_bounds.c (bounding boxes of
 * surface sides and the merging of coincident surfaces), check.c (evaluation, windows, tasks,
 * threads), check_tree.c (the subdivision of one task), check_merge.c (the report). */
#ifndef PROX_CELLS_CHECK_INTERNAL_H
#define PROX_CELLS_CHECK_INTERNAL_H

#include "prox/cellcheck.h"

/* An axis-aligned box [lo, hi]; lo > hi on an axis means empty, +-INFINITY an unbounded side. */
typedef struct prox_ccbox {
    double lo[3], hi[3];
} prox_ccbox;

/* Certified classification of the closed box b against surface s: -1 when f < 0 on every point of
 * b, +1 when f > 0 on every point, 0 when it cannot prove either (the surface may cross b). */
int prox_cc_classify(const prox_surf *s, const prox_ccbox *b);
/* The same through the general quadric Taylor form only (prox_cc_classify takes a shortcut for
 * planes that gives the same verdict; the tests compare the two). */
int prox_cc_classify_taylor(const prox_surf *s, const prox_ccbox *b);

/* Certified classification of the closed box b against the pair (u, v): with g = f_v - lambda f_u
 * (*lambda set by the call: the ratio that makes g constant for concentric spheres, coaxial cylinders
 * and parallel planes), -1 when g < 0 at every point of b, +1 when g > 0 at every point, 0 when it
 * cannot prove either (or u or v is a torus; *lambda is then 0). Strict: no rounding layer is given
 * away. g < 0 means no point of b has f_v >= 0 with lambda f_u <= 0; g > 0, none has f_v <= 0 with
 * lambda f_u >= 0: assignments of signs to u and v that the truth tables may drop (check_tree.c). */
int prox_cc_classify_pair(const prox_surf *u, const prox_surf *v, const prox_ccbox *b, double *lambda);

/* A box holding every point of the side `sense` (-1: f < 0, +1: f > 0) of s; unbounded axes are
 * +-INFINITY, an empty side gives an empty box. */
prox_ccbox prox_cc_side_box(const prox_surf *s, int sense);

/* Canonical surfaces: rep[i] is the index of the surface that stands for surface i (rep[i] <= i;
 * coincident surfaces share one), flip[i] is -1 when i's negative side is rep's positive side. */
prox_status prox_cc_merge_surfaces(const prox_surf *s, size_t n, size_t *rep, signed char *flip);

/* Box helpers. */
prox_ccbox prox_ccbox_all(void);
prox_ccbox prox_ccbox_empty(void);
int prox_ccbox_is_empty(const prox_ccbox *b);
int prox_ccbox_bounded(const prox_ccbox *b);
int prox_ccbox_meets(const prox_ccbox *a, const prox_ccbox *b);
prox_ccbox prox_ccbox_and(const prox_ccbox *a, const prox_ccbox *b);
prox_ccbox prox_ccbox_or(const prox_ccbox *a, const prox_ccbox *b);

/* ---- the subdivision (check.c, check_tree.c, check_merge.c) ---- */

#include <stdint.h>

/* Truth tables over the surfaces that cross a box: bit k of a mask is assignment k of signs to up to
 * six crossing surfaces (variable v negative in the assignments whose bit v of k is 1). t: the region
 * certainly holds every point of the box with that assignment; p: it may hold some. */
typedef struct prox_ccmask {
    uint64_t t, p;
} prox_ccmask;
#define PROX_CC_ALL (~(uint64_t)0)
#define PROX_CC_VARS 6

/* The model prepared for the check (read-only once built, shared by the threads). */
typedef struct prox_ccprep {
    const prox_cell_model *m;
    size_t *rep;          /* per surface: the surface standing for it */
    signed char *flip;    /* per surface: -1 when its sides are rep's swapped */
    size_t *kid0, *kid1;  /* per term: operands of AND / OR (kid0 also of NOT) */
    prox_ccbox *nbox;     /* per term: a box holding every point where the subexpression holds */
    prox_ccbox *cbox;     /* per cell: a box holding the cell */
    size_t *ucells;       /* cell indices sorted by universe */
    size_t maxucells;     /* most cells in one universe */
    double res;           /* resolution */
} prox_ccprep;

/* Per-thread evaluation state: per-surface classification of the current box. */
typedef struct prox_ccctx {
    const prox_ccprep *P;
    uint32_t stamp;
    uint32_t *seen;
    signed char *cls, *var;
    size_t vsurf[PROX_CC_VARS]; /* the surface of each variable */
    int nvar, overflow;
    prox_ccbox box;
} prox_ccctx;

prox_status prox_ccctx_init(prox_ccctx *c, const prox_ccprep *P);
void prox_ccctx_free(prox_ccctx *c);
/* Sets the box of the context (forgets the classifications of the previous box). */
void prox_ccctx_box(prox_ccctx *c, const prox_ccbox *b);
/* Truth tables of the region [expr, expr + nexpr) on the context's box (nexpr 0: all space). */
prox_ccmask prox_cc_eval(prox_ccctx *c, size_t expr, size_t nexpr);

/* One task: a box of one window, subdivided to the resolution. */
typedef struct prox_cctask {
    size_t win;           /* index into m->windows, or (size_t)-1 for the real world made up */
    long universe;
    size_t ucell0, nucell; /* the universe's cells: P->ucells[ucell0 .. ucell0 + nucell) */
    size_t wexpr, wnexpr; /* the window's region */
    long window_cell;     /* number of the filling cell, 0 for the real world */
    prox_ccbox box;
} prox_cctask;

/* Findings of one task. */
enum { PROX_CC_OVERLAP = 0, PROX_CC_GAP, PROX_CC_UNDECIDED };
typedef struct prox_ccrec {
    int kind;
    size_t task;
    size_t a, b;          /* overlap: cell indices a < b */
    prox_ccbox box;       /* overlap: the box of pt; gap, undecided: the hull of the boxes */
    prox_ccbox pbox;      /* gap: the largest proved box, or the box of pt */
    double vol;           /* overlap, gap: proved volume; undecided: total volume */
    double cube;          /* overlap, gap: volume of a proved cube around a probe point (may overlap boxes) */
    double best;          /* overlap: proved volume of the box that holds pt; gap: of pbox */
    size_t nboxes;        /* undecided: boxes merged */
    prox_vec3 pt;         /* overlap: confirmed point; gap: candidate point (has_pt) */
    int has_pt;
    size_t cells[PROX_CELLS_UNDECIDED_MAX], ncells; /* undecided */
    const char *reason;
} prox_ccrec;

typedef struct prox_ccout {
    prox_ccrec *recs;
    size_t n, cap;
    size_t boxes, clean, leaves;
    int failed;           /* out of memory */
} prox_ccout;

/* Subdivides one task's box (check_tree.c). */
void prox_cc_run_task(prox_ccctx *c, const prox_cctask *t, size_t task_index, prox_ccout *out);
/* Merges the tasks' findings into the report (check_merge.c). */
prox_status prox_cc_merge(const prox_ccprep *P, const prox_cctask *tasks, prox_ccout *outs, size_t ntasks,
                          prox_cells_report *r);
/* 1 when x lies in the window of task t (exact membership). */
int prox_cc_in_window(const prox_ccprep *P, const prox_cctask *t, prox_vec3 x);

#endif
