/* The points a lattice's universe must fill (cells.h, prox_window: bexpr). A lattice cell L of
 * universe U repeats its element (0,0,0) by the lattice translations (MCNP manual, LAT: for LAT=1 the
 * element (1,0,0) lies beyond the first surface of the cell card, (-1,0,0) beyond the second, (0,1,0)
 * and (0,-1,0) beyond the third and fourth, (0,0,1) and (0,0,-1) beyond the fifth and sixth; for LAT=2
 * the hexagonal prism's (1,0,0), (-1,0,0), (0,1,0), (0,-1,0), (-1,1,0), (1,-1,0) beyond its first six
 * surfaces, (0,0,1) and (0,0,-1) beyond the seventh and eighth). Every element is element (0,0,0)
 * moved by its translation, and the universe u it holds is placed in it as in element (0,0,0). L
 * itself claims only what U's windows hold, so u must fill, in its own frame,
 *
 *   place^-1(E0) AND OR over elements k holding u, over U's windows W:  place^-1(W - s_k),
 *
 * with E0 the element (0,0,0) and s_k element k's translation. That set is bounded when U's windows
 * are, even where E0 is open (a lattice of infinite pins in a finite parent): it is built here as a
 * region, so that the check's interval proofs and its exact witness confirmations both use it.
 *
 * Each copy W - s_k matters only within D_k = box(E0) AND (box(W) - s_k); the copies of elements
 * whose D_k is empty are dropped, and within D_k every surface of the copy that the certified
 * classification (classify.c) proves one-signed on D_k is replaced by its constant: the copy becomes
 * (the faces of box(W) - s_k that cut box(E0)) AND (what is left). Copies of the interior elements of
 * a parent all reduce to one slab and are kept once; a union of the distinct copies remains, as a
 * balanced tree so that a box meets few of its branches. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cells/cells_internal.h"
#include "cells/check_internal.h"
#include "cells/window_bound.h"
#include "core/tol.h"

/* At most this many (element, parent window) copies are examined for one window, and this many terms
 * built for it; beyond either its region is not built (the window stays unbounded: undecided). */
#define MAX_COPIES 200000
#define MAX_TERMS 2000000

/* ---- model growth ---- */

typedef struct grower {
    prox_cell_model *m;
    size_t cap_s, cap_t;
    int nomem;
} grower;

static size_t add_surf(grower *g, const prox_surf *s)
{
    prox_cell_model *m = g->m;
    if (m->nsurfs == g->cap_s) {
        size_t c = g->cap_s ? 2 * g->cap_s : 64;
        void *p = realloc(m->surfs, c * sizeof *m->surfs);
        if (!p) return g->nomem = 1, 0;
        m->surfs = p, g->cap_s = c;
    }
    m->surfs[m->nsurfs] = *s;
    return m->nsurfs++;
}

static void add_term(grower *g, prox_op op, int sense, size_t surf)
{
    prox_cell_model *m = g->m;
    if (m->nterms == g->cap_t) {
        size_t c = g->cap_t ? 2 * g->cap_t : 64;
        void *p = realloc(m->terms, c * sizeof *m->terms);
        if (!p) {
            g->nomem = 1;
            return;
        }
        m->terms = p, g->cap_t = c;
    }
    m->terms[m->nterms++] = (prox_term){op, sense, surf};
}

/* ---- lattice translations ---- */

/* Plane leaf: unit outward normal u (away from the element's side) and a point p of the plane. */
static int plane_of(const prox_surf *s, int sense, double u[3], double p[3])
{
    if (s->kind != PROX_SURF_QUADRIC) return 0;
    for (int i = 0; i < 6; ++i)
        if (s->q[i] != 0.0) return 0;
    double g[3] = {s->q[6], s->q[7], s->q[8]}, n2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    if (!(n2 > 0.0) || !isfinite(n2)) return 0;
    const double o[3] = {s->o.x, s->o.y, s->o.z}, n = sqrt(n2);
    for (int i = 0; i < 3; ++i) {
        u[i] = -sense * g[i] / n; /* the element is on side `sense`: outward is the other way */
        p[i] = o[i] - s->q[9] * g[i] / n2;
    }
    return 1;
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static double det3(double A[3][3])
{
    return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
           A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

/* Solves the 3 x 3 system A x = b (rows of A) by Cramer's rule; 0 when singular. */
static int solve3(double A[3][3], const double b[3], double x[3])
{
    double det = det3(A);
    if (!(fabs(det) > 1e-12)) return 0;
    for (int c = 0; c < 3; ++c) {
        double M[3][3];
        memcpy(M, A, sizeof M);
        for (int r = 0; r < 3; ++r) M[r][c] = b[r];
        x[c] = det3(M) / det;
    }
    return 1;
}

/* The translations of lattice cell `ci` from the planes of its element (0,0,0), in the order MCNP
 * gives them (file comment); returns their number (2: the lattice is open along the third axis, 3),
 * 0 when the element is not such a set of plane pairs. */
static int lattice_basis(const prox_cell_model *m, size_t ci, double a[3][3])
{
    const prox_cell *c = &m->cells[ci];
    double u[8][3], p[8][3], w[4];
    int n = 0;
    for (size_t t = 0; t < c->elem_nexpr; ++t) {
        const prox_term *x = &m->terms[c->elem_expr + t];
        if (x->op == PROX_OP_AND) continue;
        if (x->op != PROX_OP_LEAF || n == 8 || !plane_of(&m->surfs[x->surf], x->sense, u[n], p[n])) return 0;
        ++n;
    }
    int hex = c->lat == PROX_LAT_HEXPRISM;
    if (hex ? n != 6 && n != 8 : n != 4 && n != 6) return 0;
    for (int k = 0; k < n / 2; ++k) { /* pair k: opposite planes; w = the element's width across them */
        double s[3] = {u[2 * k][0] + u[2 * k + 1][0], u[2 * k][1] + u[2 * k + 1][1], u[2 * k][2] + u[2 * k + 1][2]};
        double d[3] = {p[2 * k][0] - p[2 * k + 1][0], p[2 * k][1] - p[2 * k + 1][1], p[2 * k][2] - p[2 * k + 1][2]};
        if (!(sqrt(dot3(s, s)) <= PROX_TOL_LAT_PLANES)) return 0;
        w[k] = dot3(d, u[2 * k]);
        if (!(w[k] > 0.0) || !isfinite(w[k])) return 0;
    }
    double axis[3] = {u[0][1] * u[2][2] - u[0][2] * u[2][1], u[0][2] * u[2][0] - u[0][0] * u[2][2],
                      u[0][0] * u[2][1] - u[0][1] * u[2][0]};
    double an = sqrt(dot3(axis, axis));
    if (!(an > 0.1)) return 0;
    for (int i = 0; i < 3; ++i) axis[i] /= an;
    int third = hex ? 6 : 4, nb = n > third ? 3 : 2; /* the pair of the third axis, when present */
    double A[3][3];
    memcpy(A[0], u[0], sizeof A[0]);
    memcpy(A[1], u[2], sizeof A[1]);
    memcpy(A[2], nb == 3 ? u[third] : axis, sizeof A[2]);
    for (int k = 0; k < nb; ++k) { /* a_k . (normal of pair j) = width of k if j == k, else 0 */
        double b[3] = {0.0, 0.0, 0.0};
        b[k] = w[k == 2 ? third / 2 : k];
        if (hex && k < 2) { /* a hexagon's neighbour lies along the face normal */
            for (int i = 0; i < 3; ++i) a[k][i] = w[k] * u[2 * k][i];
            continue;
        }
        if (!solve3(A, b, a[k])) return 0;
    }
    if (hex) { /* the third pair: element (-1,1,0) lies beyond the fifth surface */
        double d[3] = {a[1][0] - a[0][0], a[1][1] - a[0][1], a[1][2] - a[0][2]};
        for (int i = 0; i < 3; ++i)
            if (!(fabs(d[i] - w[2] * u[4][i]) <= PROX_TOL_LAT_PLANES * w[2])) return 0;
    }
    return nb;
}

/* ---- boxes ---- */

/* ---- boxes of regions cut by tilted planes ---- */

/* Half-spaces the vertex enumeration takes at most (the rest are left out: the box stays a superset). */
#define LP_MAX 40

typedef struct halfspace {
    double n[3], c; /* n . x <= c, |n| = 1 */
} halfspace;

/* The box of the polyhedron AND h[0..nh) by its vertices: every triple of planes meeting in one point
 * that satisfies all the others (an exact linear programme for a bounded polyhedron; a cube of half
 * width big closes an open one, and a vertex on that cube marks its axis open). */
static prox_ccbox vertex_box(const halfspace *h, size_t nh, double big)
{
    prox_ccbox r = prox_ccbox_empty();
    for (size_t i = 0; i < nh; ++i)
        for (size_t j = i + 1; j < nh; ++j)
            for (size_t k = j + 1; k < nh; ++k) {
                double A[3][3], b[3] = {h[i].c, h[j].c, h[k].c}, x[3];
                memcpy(A[0], h[i].n, sizeof A[0]), memcpy(A[1], h[j].n, sizeof A[1]);
                memcpy(A[2], h[k].n, sizeof A[2]);
                if (!solve3(A, b, x)) continue;
                int ok = 1;
                double xm = fmax(fabs(x[0]), fmax(fabs(x[1]), fabs(x[2])));
                for (size_t q = 0; q < nh && ok; ++q)
                    ok = dot3(h[q].n, x) <= h[q].c + PROX_TOL_LAT_PLANES * (fabs(h[q].c) + 3.0 * xm + 1.0);
                if (!ok) continue;
                for (int a = 0; a < 3; ++a) r.lo[a] = fmin(r.lo[a], x[a]), r.hi[a] = fmax(r.hi[a], x[a]);
            }
    for (int a = 0; a < 3 && !prox_ccbox_is_empty(&r); ++a) {
        double pad = PROX_TOL_CELL_BOX * (fabs(r.lo[a]) + fabs(r.hi[a])) + PROX_TOL_LAT_PLANES;
        r.lo[a] = r.lo[a] <= -0.5 * big ? -INFINITY : r.lo[a] - pad;
        r.hi[a] = r.hi[a] >= 0.5 * big ? INFINITY : r.hi[a] + pad;
    }
    return r;
}

prox_ccbox cells_region_box(const prox_cell_model *m, size_t e, size_t n)
{
    if (!n) return prox_ccbox_all();
    prox_ccbox *box = malloc(n * sizeof *box);
    size_t *kid = malloc(2 * n * sizeof *kid), *stack = malloc(n * sizeof *stack);
    prox_ccbox r = prox_ccbox_all();
    size_t sp = 0;
    if (!box || !kid || !stack) goto done;
    for (size_t i = 0; i < n; ++i) { /* the side boxes over the tree, as the check's own */
        const prox_term *t = &m->terms[e + i];
        if (t->op == PROX_OP_LEAF) box[i] = prox_cc_side_box(&m->surfs[t->surf], t->sense);
        else if (t->op == PROX_OP_ALL) box[i] = prox_ccbox_all();
        else if (t->op == PROX_OP_NOT) {
            if (sp < 1) goto done;
            kid[2 * i] = stack[--sp];
            box[i] = prox_ccbox_all();
        } else {
            if (sp < 2) goto done;
            kid[2 * i + 1] = stack[--sp], kid[2 * i] = stack[--sp];
            box[i] = t->op == PROX_OP_AND ? prox_ccbox_and(&box[kid[2 * i]], &box[kid[2 * i + 1]])
                                          : prox_ccbox_or(&box[kid[2 * i]], &box[kid[2 * i + 1]]);
        }
        stack[sp++] = i;
    }
    if (sp != 1) goto done;
    r = box[n - 1];
    if (prox_ccbox_is_empty(&r) || prox_ccbox_bounded(&r)) goto done;
    /* The planes the region is the intersection of (its top-level AND), and the box's finite faces. */
    halfspace h[LP_MAX + 12];
    size_t nh = 0, top = 0;
    double scale = 1.0;
    stack[top++] = n - 1;
    while (top) {
        size_t i = stack[--top];
        const prox_term *t = &m->terms[e + i];
        if (t->op == PROX_OP_AND) {
            stack[top++] = kid[2 * i], stack[top++] = kid[2 * i + 1];
            continue;
        }
        double u[3], p[3];
        if (t->op != PROX_OP_LEAF || nh == LP_MAX || !plane_of(&m->surfs[t->surf], t->sense, u, p)) continue;
        halfspace *x = &h[nh++];
        memcpy(x->n, u, sizeof u);
        x->c = dot3(u, p);
        scale = fmax(scale, fabs(x->c));
    }
    for (int a = 0; a < 3; ++a) {
        if (isfinite(r.lo[a])) scale = fmax(scale, fabs(r.lo[a]));
        if (isfinite(r.hi[a])) scale = fmax(scale, fabs(r.hi[a]));
    }
    double big = 1e6 * scale;
    for (int a = 0; a < 3; ++a) {
        halfspace lo = {{0, 0, 0}, 0}, hi = {{0, 0, 0}, 0};
        lo.n[a] = -1.0, hi.n[a] = 1.0;
        lo.c = isfinite(r.lo[a]) ? -r.lo[a] : big;
        hi.c = isfinite(r.hi[a]) ? r.hi[a] : big;
        h[nh++] = lo, h[nh++] = hi;
    }
    prox_ccbox v = vertex_box(h, nh, big);
    r = prox_ccbox_and(&r, &v);
done:
    free(box);
    free(kid);
    free(stack);
    return r;
}

/* ---- copies of a parent window ---- */

/* A surface's geometry, for the identity of copies. */
typedef struct skey {
    int kind;
    double o[3], q[10], w[3], t[3];
} skey;

static skey key_of(const prox_surf *s)
{
    skey k;
    memset(&k, 0, sizeof k);
    k.kind = (int)s->kind;
    k.o[0] = s->o.x, k.o[1] = s->o.y, k.o[2] = s->o.z;
    memcpy(k.q, s->q, sizeof k.q);
    k.w[0] = s->w.x, k.w[1] = s->w.y, k.w[2] = s->w.z;
    k.t[0] = s->ta, k.t[1] = s->tb, k.t[2] = s->tc;
    return k;
}

/* One term of a copy being built: a leaf holds its surface (in the universe's frame). */
typedef struct cterm {
    prox_op op;
    int sense;
    prox_surf s;
} cterm;

/* The copies of one window. */
typedef struct copies {
    cterm *t;              /* all terms, copy after copy */
    size_t nt, capt;
    size_t *off, *len;     /* distinct copies */
    uint64_t *hash;
    size_t n, cap;
    int nomem;
} copies;

static int ct_push(copies *C, prox_op op, int sense, const prox_surf *s)
{
    if (C->nt == C->capt) {
        size_t c = C->capt ? 2 * C->capt : 256;
        void *p = realloc(C->t, c * sizeof *C->t);
        if (!p) return C->nomem = 1, 0;
        C->t = p, C->capt = c;
    }
    cterm *x = &C->t[C->nt++];
    memset(x, 0, sizeof *x);
    x->op = op, x->sense = sense;
    if (s) x->s = *s;
    return 1;
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t copy_hash(const cterm *t, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; ++i) {
        h = fnv(h, &t[i].op, sizeof t[i].op);
        h = fnv(h, &t[i].sense, sizeof t[i].sense);
        if (t[i].op == PROX_OP_LEAF) {
            skey k = key_of(&t[i].s);
            h = fnv(h, &k, sizeof k);
        }
    }
    return h;
}

static int same_copy(const cterm *a, const cterm *b, size_t n)
{
    for (size_t i = 0; i < n; ++i) {
        if (a[i].op != b[i].op || a[i].sense != b[i].sense) return 0;
        if (a[i].op == PROX_OP_LEAF) {
            skey x = key_of(&a[i].s), y = key_of(&b[i].s);
            if (memcmp(&x, &y, sizeof x)) return 0;
        }
    }
    return 1;
}

/* Keeps the copy [off, C->nt) unless an equal one is kept already. */
static void keep_copy(copies *C, size_t off)
{
    size_t n = C->nt - off;
    uint64_t h = copy_hash(C->t + off, n);
    for (size_t i = 0; i < C->n; ++i)
        if (C->hash[i] == h && C->len[i] == n && same_copy(C->t + C->off[i], C->t + off, n)) {
            C->nt = off;
            return;
        }
    if (C->n == C->cap) {
        size_t c = C->cap ? 2 * C->cap : 64;
        size_t *a = realloc(C->off, c * sizeof *a), *b = a ? realloc(C->len, c * sizeof *b) : NULL;
        if (a) C->off = a;
        if (b) C->len = b;
        uint64_t *hh = b ? realloc(C->hash, c * sizeof *hh) : NULL;
        if (!hh) {
            C->nomem = 1;
            return;
        }
        C->hash = hh, C->cap = c;
    }
    C->off[C->n] = off, C->len[C->n] = n, C->hash[C->n] = h;
    C->n++;
}

/* The surface moved by -s (its points x become x - s). A quadric that does not depend on a
 * coordinate (a PZ plane on x and y, a CZ cylinder on z) is not moved along it, exactly: so the copies
 * of an interior element, or of the elements along one edge of a parent, come out equal. */
static prox_surf moved(const prox_surf *s, const double sh[3])
{
    prox_surf r = *s;
    double o[3] = {s->o.x, s->o.y, s->o.z};
    const double *q = s->q;
    for (int c = 0; c < 3; ++c) {
        int uses = s->kind != PROX_SURF_QUADRIC || q[c] != 0.0 || q[6 + c] != 0.0 ||
                   (c != 2 && q[3] != 0.0) || (c != 0 && q[4] != 0.0) || (c != 1 && q[5] != 0.0);
        if (uses) o[c] -= sh[c];
    }
    r.o = prox_v3(o[0], o[1], o[2]);
    return r;
}

/* A box holding the copy terms [off, C->nt) (U's frame, before the placement). */
static prox_ccbox copy_box(const copies *C, size_t off, prox_ccbox *stack)
{
    size_t sp = 0;
    for (size_t i = off; i < C->nt; ++i) {
        const cterm *t = &C->t[i];
        if (t->op == PROX_OP_LEAF) stack[sp++] = prox_cc_side_box(&t->s, t->sense);
        else if (t->op == PROX_OP_NOT && sp) stack[sp - 1] = prox_ccbox_all();
        else if (sp >= 2) {
            --sp;
            stack[sp - 1] = t->op == PROX_OP_AND ? prox_ccbox_and(&stack[sp - 1], &stack[sp])
                                                 : prox_ccbox_or(&stack[sp - 1], &stack[sp]);
        }
    }
    return sp == 1 ? stack[0] : prox_ccbox_all();
}

/* Constant-folding stack entry: -1 false, +1 true, 0 the terms from `at` on. */
typedef struct item {
    int k;
    size_t at;
} item;

/* Appends the copy of region [e, e + n) (U's frame) moved by -sh and folded on D (U's frame, element
 * (0,0,0)): surfaces one-signed on D + sh become constants. Returns -1 (empty on D), +1 (all of D) or
 * 0 (terms appended). */
static int fold_copy(copies *C, const prox_cell_model *m, size_t e, size_t n, const double sh[3], const prox_ccbox *D,
                     int fold, item *st)
{
    size_t sp = 0;
    for (size_t i = e; i < e + n && !C->nomem; ++i) {
        const prox_term *t = &m->terms[i];
        if (t->op == PROX_OP_LEAF || t->op == PROX_OP_ALL) {
            int k = 1;
            if (t->op == PROX_OP_LEAF) {
                prox_surf s = moved(&m->surfs[t->surf], sh);
                int c = fold ? prox_cc_classify(&s, D) : 0;
                k = c == 0 ? 0 : (c == t->sense ? 1 : -1);
                if (!k) {
                    st[sp].at = C->nt;
                    ct_push(C, PROX_OP_LEAF, t->sense, &s);
                }
            }
            st[sp++].k = k;
            continue;
        }
        if (t->op == PROX_OP_NOT) {
            if (sp < 1) return -1;
            if (st[sp - 1].k) st[sp - 1].k = -st[sp - 1].k;
            else ct_push(C, PROX_OP_NOT, 0, NULL);
            continue;
        }
        if (sp < 2) return -1;
        item a = st[sp - 2], b = st[sp - 1];
        --sp;
        int absorb = t->op == PROX_OP_AND ? -1 : 1; /* false absorbs an AND, true an OR */
        if (a.k == absorb || b.k == absorb) {
            if (!a.k) C->nt = a.at;
            else if (!b.k) C->nt = b.at;
            st[sp - 1] = (item){absorb, 0};
        } else if (a.k) st[sp - 1] = b;  /* the neutral constant drops out */
        else if (b.k) st[sp - 1] = a;
        else ct_push(C, t->op, 0, NULL); /* both are terms, a's then b's: combine */
    }
    return sp == 1 ? st[0].k : -1;
}

/* ---- one window ---- */

typedef struct wstate {
    signed char *state;    /* per window: 0 not yet, 1 under way, 2 done */
    double (*basis)[3][3];
    int *nbasis;
    grower g;
    prox_ccbox *stack;
    item *items;
    size_t cap_stack;
} wstate;

static int ensure_stack(wstate *S, size_t n)
{
    if (n <= S->cap_stack) return 1;
    void *a = realloc(S->stack, n * sizeof *S->stack), *b = a ? realloc(S->items, n * sizeof *S->items) : NULL;
    if (a) S->stack = a;
    if (!b) return 0;
    S->items = b, S->cap_stack = n;
    return 1;
}

static void bound_window(wstate *S, size_t w);

/* The exact region of window p (U's frame): its bexpr when built, else its region. */
static void parent_region(wstate *S, size_t p, size_t *e, size_t *n)
{
    bound_window(S, p);
    const prox_window *x = &S->g.m->windows[p];
    if (x->bnexpr) *e = x->bexpr, *n = x->bnexpr;
    else *e = x->expr, *n = x->nexpr;
}

/* The elements of a FILL=u lattice that meet box B (U's frame): E0 + s_k meets B. */
static int enumerate(double a[3][3], int nb, const prox_ccbox *E0, const prox_ccbox *B, long lo[3], long hi[3])
{
    double A[3][3], axis[3];
    /* columns a_1, a_2, a_3 (or the open axis): the dual rows give an element's index of a point */
    axis[0] = a[0][1] * a[1][2] - a[0][2] * a[1][1], axis[1] = a[0][2] * a[1][0] - a[0][0] * a[1][2],
    axis[2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) A[r][c] = c < 2 || nb == 3 ? a[c][r] : axis[r];
    for (int k = 0; k < 3; ++k) {
        lo[k] = hi[k] = 0;
        if (k == 2 && nb == 2) break;
        double e[3] = {0.0, 0.0, 0.0}, d[3]; /* row k of A^-1: solve A^T d = e_k */
        double AT[3][3];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) AT[r][c] = A[c][r];
        e[k] = 1.0;
        if (!solve3(AT, e, d)) return 0;
        double l = 0.0, h = 0.0, dn = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
        for (int i = 0; i < 3; ++i) { /* range of d . (x - y), x in B, y in E0 (open along the axis) */
            if (fabs(d[i]) <= PROX_TOL_LAT_PLANES * dn) continue;
            double dl = B->lo[i] - E0->hi[i], dh = B->hi[i] - E0->lo[i];
            if (!isfinite(dl) || !isfinite(dh)) return 0;
            l += d[i] > 0 ? d[i] * dl : d[i] * dh;
            h += d[i] > 0 ? d[i] * dh : d[i] * dl;
        }
        if (!(h - l < 1e6) || !(fabs(l) < 1e9) || !(fabs(h) < 1e9)) return 0;
        lo[k] = (long)floor(l) - 1, hi[k] = (long)ceil(h) + 1;
    }
    return 1;
}

/* Whether the folded copy [off, C->nt) stays within box(W) - s wherever that box cuts box(E0): the
 * folding is exact on D = box(E0) AND (box(W) - s) only, and outside D the copy must be empty. Both
 * boxes come from the same surfaces, so they agree up to the rounding of the move (slack). */
static int within(const copies *C, size_t off, const prox_ccbox *B, const prox_ccbox *E0, const double sh[3],
                  prox_ccbox *stack)
{
    prox_ccbox cb = copy_box(C, off, stack);
    for (int i = 0; i < 3; ++i) {
        double lo = B->lo[i] - sh[i], hi = B->hi[i] - sh[i];
        double slack = PROX_TOL_LAT_PLANES * (fabs(lo) + fabs(hi) + fabs(sh[i]) + (hi - lo));
        if (lo > E0->lo[i] && !(cb.lo[i] >= lo - slack)) return 0;
        if (hi < E0->hi[i] && !(cb.hi[i] <= hi + slack)) return 0;
    }
    return 1;
}

/* The copies of window w for its elements and the parent windows (U's frame regions). */
static int build_copies(wstate *S, size_t w, copies *C, const prox_deck_tr *inv)
{
    prox_cell_model *m = S->g.m;
    prox_window *x = &m->windows[w];
    const prox_cell *L = &m->cells[x->cell];
    double (*a)[3] = S->basis[w];
    int nb = S->nbasis[w];
    if (!ensure_stack(S, L->elem_nexpr + 1)) return 0;
    prox_ccbox E0 = cells_region_box(m, L->elem_expr, L->elem_nexpr);
    size_t examined = 0;
    for (size_t p = 0; p < m->nwindows; ++p) {
        if (m->windows[p].universe != L->universe || p == w) continue;
        size_t pe, pn;
        parent_region(S, p, &pe, &pn);
        x = &m->windows[w];
        if (!pn || !ensure_stack(S, pn + 1)) return 0; /* all space, or no memory */
        prox_ccbox B = cells_region_box(m, pe, pn);
        if (prox_ccbox_is_empty(&B)) continue;
        if (!prox_ccbox_bounded(&B)) return 0;
        long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
        int listed = x->nelem > 0;
        if (!listed && !enumerate(a, nb, &E0, &B, lo, hi)) return 0;
        size_t ni = (size_t)(hi[0] - lo[0] + 1), nj = (size_t)(hi[1] - lo[1] + 1);
        size_t count = listed ? x->nelem : ni * nj * (size_t)(hi[2] - lo[2] + 1);
        for (size_t q = 0; q < count; ++q) {
            long ijk[3];
            if (listed) memcpy(ijk, x->elem[q], sizeof ijk);
            else {
                ijk[0] = lo[0] + (long)(q % ni), ijk[1] = lo[1] + (long)(q / ni % nj);
                ijk[2] = lo[2] + (long)(q / (ni * nj));
            }
            if (nb == 2 && ijk[2] != 0) return 0; /* an open lattice has one layer */
            if (++examined > MAX_COPIES) return 0;
            double sh[3];
            prox_ccbox D = E0;
            for (int i = 0; i < 3; ++i) {
                sh[i] = ijk[0] * a[0][i] + ijk[1] * a[1][i] + (nb == 3 ? ijk[2] * a[2][i] : 0.0);
                D.lo[i] = fmax(D.lo[i], B.lo[i] - sh[i]), D.hi[i] = fmin(D.hi[i], B.hi[i] - sh[i]);
            }
            if (prox_ccbox_is_empty(&D)) continue;
            size_t off = C->nt;
            int k = fold_copy(C, m, pe, pn, sh, &D, 1, S->items);
            if (k < 0) {
                C->nt = off;
                continue;
            }
            if (k > 0 || !within(C, off, &B, &E0, sh, S->stack)) { /* folding lost a bound: the copy as is */
                C->nt = off;
                if (fold_copy(C, m, pe, pn, sh, &D, 0, S->items) < 0) {
                    C->nt = off;
                    continue;
                }
            }
            for (size_t i = off; i < C->nt && inv; ++i)
                if (C->t[i].op == PROX_OP_LEAF) C->t[i].s = cells_surf_transform(&C->t[i].s, inv);
            if (C->nomem || C->nt > MAX_TERMS) return 0;
            keep_copy(C, off);
        }
        if (C->nomem) return 0;
    }
    return 1;
}

/* Emits the distinct copies [lo, hi) as a balanced union (shorter copies first: an interior slab
 * decides most boxes at the first branch). */
static void emit_union(wstate *S, const copies *C, const size_t *order, size_t lo, size_t hi, size_t *surf_of)
{
    if (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        emit_union(S, C, order, lo, mid, surf_of);
        emit_union(S, C, order, mid, hi, surf_of);
        add_term(&S->g, PROX_OP_OR, 0, 0);
        return;
    }
    size_t c = order[lo];
    for (size_t i = 0; i < C->len[c]; ++i) {
        size_t t = C->off[c] + i;
        add_term(&S->g, C->t[t].op, C->t[t].sense, C->t[t].op == PROX_OP_LEAF ? surf_of[t] : 0);
    }
}

typedef struct by_len {
    size_t len, index;
} by_len;

static int by_length(const void *pa, const void *pb)
{
    const by_len *a = pa, *b = pb;
    if (a->len != b->len) return a->len < b->len ? -1 : 1;
    return a->index < b->index ? -1 : a->index > b->index;
}

/* Appends the surfaces of the kept copies, one per distinct geometry among the copies. */
static size_t *push_surfaces(wstate *S, const copies *C)
{
    size_t *surf_of = malloc((C->nt ? C->nt : 1) * sizeof *surf_of);
    if (!surf_of) return NULL;
    for (size_t c = 0; c < C->n; ++c)
        for (size_t i = 0; i < C->len[c]; ++i) {
            size_t t = C->off[c] + i;
            if (C->t[t].op != PROX_OP_LEAF) continue;
            size_t found = SIZE_MAX;
            skey k = key_of(&C->t[t].s);
            for (size_t j = C->off[c]; j < t && found == SIZE_MAX; ++j) { /* the same copy's earlier leaves */
                skey y = key_of(&C->t[j].s);
                if (C->t[j].op == PROX_OP_LEAF && !memcmp(&k, &y, sizeof k)) found = surf_of[j];
            }
            surf_of[t] = found != SIZE_MAX ? found : add_surf(&S->g, &C->t[t].s);
        }
    return surf_of;
}

/* Builds window w's bexpr (after its parents'). */
static void bound_window(wstate *S, size_t w)
{
    prox_cell_model *m = S->g.m;
    if (S->state[w]) return; /* done, or under way (a cycle: left as it is) */
    S->state[w] = 1;
    prox_window *x = &m->windows[w];
    if (x->cell >= m->ncells || !m->cells[x->cell].lat || !S->nbasis[w] || m->cells[x->cell].universe == 0 ||
        !ensure_stack(S, m->cells[x->cell].elem_nexpr + 1)) {
        S->state[w] = 2;
        return;
    }
    const prox_cell *L = &m->cells[x->cell];
    prox_ccbox E0 = cells_region_box(m, L->elem_expr, L->elem_nexpr);
    if (prox_ccbox_bounded(&E0)) { /* a bounded element is checked whole, as its window says */
        S->state[w] = 2;
        return;
    }
    prox_deck_tr place = {0}, inv;
    int moved_frame = 0;
    for (int i = 0; i < 3; ++i) {
        place.o[i] = x->place_o[i];
        moved_frame |= x->place_o[i] != 0.0;
        for (int j = 0; j < 3; ++j)
            place.R[i][j] = x->place_R[i][j], moved_frame |= x->place_R[i][j] != (double)(i == j);
    }
    place.identity = !moved_frame;
    inv = cells_tr_inverse(&place);
    copies C = {0};
    int ok = build_copies(S, w, &C, moved_frame ? &inv : NULL);
    x = &m->windows[w];
    size_t *order = ok && C.n ? malloc(C.n * sizeof *order) : NULL;
    size_t *surf_of = order ? push_surfaces(S, &C) : NULL;
    if (ok && !C.n) { /* no element of this universe meets a parent window: nothing to fill */
        x->bexpr = m->nterms;
        add_term(&S->g, PROX_OP_ALL, 0, 0);
        add_term(&S->g, PROX_OP_NOT, 0, 0);
        x->bnexpr = S->g.nomem ? 0 : 2;
    } else if (ok && surf_of && !S->g.nomem) {
        by_len *bl = malloc(C.n * sizeof *bl);
        if (!bl) S->g.nomem = 1;
        for (size_t i = 0; i < C.n && bl; ++i) bl[i] = (by_len){C.len[i], i};
        if (bl) qsort(bl, C.n, sizeof *bl, by_length);
        for (size_t i = 0; i < C.n; ++i) order[i] = bl ? bl[i].index : i;
        free(bl);
        size_t start = m->nterms;
        for (size_t t = 0; t < x->nexpr; ++t) {
            const prox_term tt = m->terms[x->expr + t];
            add_term(&S->g, tt.op, tt.sense, tt.surf);
        }
        emit_union(S, &C, order, 0, C.n, surf_of);
        add_term(&S->g, PROX_OP_AND, 0, 0);
        if (!S->g.nomem) x->bexpr = start, x->bnexpr = m->nterms - start;
    } else if (ok) S->g.nomem = 1;
    free(order);
    free(surf_of);
    free(C.t);
    free(C.off);
    free(C.len);
    free(C.hash);
    S->state[w] = 2;
}

/* Lists every element of a FILL=u lattice window that meets a parent (window_bound's enumeration),
 * so that the check can map a witness back through each. */
static void list_all_elements(wstate *S, size_t w)
{
    prox_cell_model *m = S->g.m;
    prox_window *x = &m->windows[w];
    if (x->nelem || !x->bnexpr || !S->nbasis[w]) return;
    const prox_cell *L = &m->cells[x->cell];
    if (!ensure_stack(S, L->elem_nexpr + 1)) return;
    prox_ccbox E0 = cells_region_box(m, L->elem_expr, L->elem_nexpr), all = prox_ccbox_empty();
    for (size_t p = 0; p < m->nwindows; ++p) {
        if (m->windows[p].universe != L->universe || p == w) continue;
        size_t pe, pn;
        parent_region(S, p, &pe, &pn);
        if (!pn || !ensure_stack(S, pn + 1)) return;
        prox_ccbox B = cells_region_box(m, pe, pn);
        all = prox_ccbox_or(&all, &B);
    }
    long lo[3], hi[3];
    if (prox_ccbox_is_empty(&all) || !enumerate(S->basis[w], S->nbasis[w], &E0, &all, lo, hi)) return;
    size_t n = (size_t)(hi[0] - lo[0] + 1) * (size_t)(hi[1] - lo[1] + 1) * (size_t)(hi[2] - lo[2] + 1);
    if (n > MAX_COPIES) return;
    x->elem = malloc(n * sizeof *x->elem);
    if (!x->elem) return;
    for (long k = lo[2]; k <= hi[2]; ++k)
        for (long j = lo[1]; j <= hi[1]; ++j)
            for (long i = lo[0]; i <= hi[0]; ++i) {
                long *e = x->elem[x->nelem++];
                e[0] = i, e[1] = j, e[2] = k;
            }
}

prox_status cells_bound_windows(prox_cell_model *m)
{
    size_t n = m->nwindows;
    if (!n) return PROX_OK;
    wstate S = {.g = {.m = m, .cap_s = m->nsurfs, .cap_t = m->nterms}};
    S.state = calloc(n, 1);
    S.basis = calloc(n, sizeof *S.basis);
    S.nbasis = calloc(n, sizeof *S.nbasis);
    prox_status st = PROX_ENOMEM;
    if (S.state && S.basis && S.nbasis) {
        for (size_t w = 0; w < n; ++w) {
            prox_window *x = &m->windows[w];
            if (x->cell < m->ncells && m->cells[x->cell].lat) {
                S.nbasis[w] = lattice_basis(m, x->cell, S.basis[w]);
                x->nbasis = S.nbasis[w];
                for (int k = 0; k < x->nbasis; ++k)
                    x->basis[k] = prox_v3(S.basis[w][k][0], S.basis[w][k][1], S.basis[w][k][2]);
            }
        }
        for (size_t w = 0; w < n && !S.g.nomem; ++w) bound_window(&S, w);
        for (size_t w = 0; w < n && !S.g.nomem; ++w) list_all_elements(&S, w);
        st = S.g.nomem ? PROX_ENOMEM : PROX_OK;
    }
    free(S.state);
    free(S.basis);
    free(S.nbasis);
    free(S.stack);
    free(S.items);
    return st;
}
