/* Scenes, query modes and the batch API (include/prox/scene.h, docs/scene.md).
 * Broad phase: a bounding volume hierarchy over the axis-aligned boxes (src/scene/broad.c) hands on
 * every pair whose boxes come within the threshold on all three axes. Narrow phase: a ladder
 * of bounds, cheapest first: box gap and bounding-sphere gap (lower bounds on the distance), the
 * support-function gap along the line of centres, -h_B(-n) - h_A(n) <= dist(A, B) (a lower bound:
 * the slab of A and the slab of B along n are disjoint by that much), and |s_A(n) - s_B(-n)| >=
 * dist(A, B) (an upper bound: any two points of the solids), then the solvers of query.h. */
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/body.h"
#include "core/tol.h"
#include "prox/scene.h"
#include "prox/support.h"
#include "query/query_internal.h"
#include "scene/broad.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* Relative slack of the bound tests: a bound only rejects a pair when it clears the threshold by
 * more than rounding can explain. */
#define SCENE_SLACK PROX_TOL_BROAD
/* Candidates evaluated per parallel chunk (bounds the memory of a query). */
#define SCENE_CHUNK 65536
/* Candidates a worker of the ladder takes at once. */
#define SCENE_GRAIN 64

/* ---- bounding volumes ------------------------------------------------------------------------ */

/* Widens a box by a few ulps of its coordinates so that rounding cannot make it miss the shape. */
static prox_aabb aabb_widen(prox_aabb b)
{
    double m = fmax(prox_v3_maxabs(b.lo), prox_v3_maxabs(b.hi)) * 4e-16;
    b.lo = prox_v3_sub(b.lo, prox_v3(m, m, m));
    b.hi = prox_v3_add(b.hi, prox_v3(m, m, m));
    return b;
}

/* Box of a cylinder: the two rim disks; a disk of radius r with unit normal u reaches
 * r sqrt(1 - u_k^2) along axis k. */
static prox_aabb aabb_rcc(const prox_rcc *c)
{
    prox_vec3 u = prox_v3_normalize(c->axis), top = prox_v3_add(c->base, c->axis);
    prox_vec3 e = prox_v3(c->radius * sqrt(fmax(0.0, 1.0 - u.x * u.x)), c->radius * sqrt(fmax(0.0, 1.0 - u.y * u.y)),
                          c->radius * sqrt(fmax(0.0, 1.0 - u.z * u.z)));
    prox_aabb b = {prox_v3(fmin(c->base.x, top.x), fmin(c->base.y, top.y), fmin(c->base.z, top.z)),
                   prox_v3(fmax(c->base.x, top.x), fmax(c->base.y, top.y), fmax(c->base.z, top.z))};
    b.lo = prox_v3_sub(b.lo, e);
    b.hi = prox_v3_add(b.hi, e);
    return b;
}

/* Box of a general box: corner plus the negative / positive parts of the edges. */
static prox_aabb aabb_box(const prox_box *x)
{
    prox_aabb b = {x->corner, x->corner};
    for (int i = 0; i < 3; ++i) {
        prox_vec3 e = x->edge[i];
        b.lo = prox_v3_add(b.lo, prox_v3(fmin(e.x, 0), fmin(e.y, 0), fmin(e.z, 0)));
        b.hi = prox_v3_add(b.hi, prox_v3(fmax(e.x, 0), fmax(e.y, 0), fmax(e.z, 0)));
    }
    return b;
}

/* Distance from a body's reference point c to its farthest point (kinds after the first four). */
static double body_extent(const prox_body *b)
{
    switch (b->kind) {
    case PROX_BODY_POLY: {
        double r = 0.0;
        for (int i = 0; i < b->x.poly.nv; ++i) r = fmax(r, prox_v3_norm(b->x.poly.v[i]));
        return r;
    }
    case PROX_BODY_CONE: return fmax(hypot(b->x.cone.hh, b->x.cone.r1), hypot(b->x.cone.hh, b->x.cone.r2));
    case PROX_BODY_ECYL: return hypot(b->x.ecyl.hh, fmax(b->x.ecyl.a1, b->x.ecyl.a2));
    case PROX_BODY_ELL: return fmax(b->x.ell.a, b->x.ell.b);
    default: return b->size;
    }
}

/* Box of any kind from the generic body: h(+-e_k) = +-c_k + hc(+-e_k) along the three axes, enlarged
 * by PROX_TOL_BOUND (|c| + extent) for the rounding of c, of the geometry and of hc. */
static prox_aabb aabb_body(const prox_shape *s)
{
    prox_body b = prox_body_make(s);
    double up[3], down[3], reach = 0.0;
    for (int k = 0; k < 3; ++k) {
        prox_vec3 e = prox_v3(k == 0, k == 1, k == 2);
        up[k] = prox_body_hc(&b, e);
        down[k] = prox_body_hc(&b, prox_v3_neg(e));
        reach = fmax(reach, fmax(fabs(up[k]), fabs(down[k])));
    }
    double w = PROX_TOL_BOUND * (prox_v3_maxabs(b.c) + reach);
    prox_aabb box = {prox_v3(b.c.x - down[0] - w, b.c.y - down[1] - w, b.c.z - down[2] - w),
                     prox_v3(b.c.x + up[0] + w, b.c.y + up[1] + w, b.c.z + up[2] + w)};
    return box;
}

/* Sphere of any kind from the generic body: centre c, radius the farthest extent, enlarged like the box. */
static prox_sph sphere_body(const prox_shape *s)
{
    prox_body b = prox_body_make(s);
    double r = body_extent(&b);
    prox_sph out = {b.c, r + PROX_TOL_BOUND * (prox_v3_maxabs(b.c) + r)};
    return out;
}

PROX_API prox_aabb prox_shape_aabb(const prox_shape *s)
{
    prox_aabb b = {prox_v3(0, 0, 0), prox_v3(0, 0, 0)};
    switch (s->kind) {
    case PROX_SHAPE_RCC: b = aabb_rcc(&s->u.rcc); break;
    case PROX_SHAPE_BOX: b = aabb_box(&s->u.box); break;
    case PROX_SHAPE_RPP:
        b.lo = prox_v3(s->u.rpp.xmin, s->u.rpp.ymin, s->u.rpp.zmin);
        b.hi = prox_v3(s->u.rpp.xmax, s->u.rpp.ymax, s->u.rpp.zmax);
        return b; /* exact already */
    case PROX_SHAPE_SPH: {
        double r = s->u.sph.radius;
        b.lo = prox_v3_sub(s->u.sph.center, prox_v3(r, r, r));
        b.hi = prox_v3_add(s->u.sph.center, prox_v3(r, r, r));
        break;
    }
    default: return aabb_body(s);
    }
    return aabb_widen(b);
}

PROX_API prox_sph prox_shape_bounding_sphere(const prox_shape *s)
{
    prox_sph out = {prox_v3(0, 0, 0), 0};
    switch (s->kind) {
    case PROX_SHAPE_RCC:
        out.center = prox_v3_mad(s->u.rcc.base, 0.5, s->u.rcc.axis);
        out.radius = hypot(s->u.rcc.radius, 0.5 * prox_v3_norm(s->u.rcc.axis));
        break;
    case PROX_SHAPE_BOX: {
        prox_vec3 d = prox_v3_add(prox_v3_add(s->u.box.edge[0], s->u.box.edge[1]), s->u.box.edge[2]);
        out.center = prox_v3_mad(s->u.box.corner, 0.5, d);
        out.radius = 0.5 * prox_v3_norm(d); /* edges are orthogonal: the diagonal is the longest chord */
        break;
    }
    case PROX_SHAPE_RPP: {
        prox_vec3 lo = prox_v3(s->u.rpp.xmin, s->u.rpp.ymin, s->u.rpp.zmin);
        prox_vec3 hi = prox_v3(s->u.rpp.xmax, s->u.rpp.ymax, s->u.rpp.zmax);
        out.center = prox_v3_scale(prox_v3_add(lo, hi), 0.5);
        out.radius = 0.5 * prox_v3_dist(hi, lo);
        break;
    }
    case PROX_SHAPE_SPH: return s->u.sph;
    default: return sphere_body(s);
    }
    out.radius *= 1.0 + 4e-16; /* rounding must not shrink it */
    out.radius += 4e-16 * prox_v3_maxabs(out.center);
    return out;
}

/* Everything the ladder needs about one body, computed once. */
typedef struct bound {
    prox_aabb box;
    prox_sph sphere;
} bound;

static bound bound_make(const prox_shape *s)
{
    bound b = {prox_shape_aabb(s), prox_shape_bounding_sphere(s)};
    return b;
}

/* Euclidean gap between two boxes: a lower bound on the distance of what they hold. */
static double aabb_gap(const prox_aabb *a, const prox_aabb *b)
{
    double g[3] = {fmax(0.0, fmax(a->lo.x - b->hi.x, b->lo.x - a->hi.x)),
                   fmax(0.0, fmax(a->lo.y - b->hi.y, b->lo.y - a->hi.y)),
                   fmax(0.0, fmax(a->lo.z - b->hi.z, b->lo.z - a->hi.z))};
    return prox_v3_norm(prox_v3(g[0], g[1], g[2]));
}

/* ---- the ladder --------------------------------------------------------------------------------- */

/* Fills the result from an exact distance query. */
static void take_distance(prox_pair_result *r, const prox_distance_result *d, int points)
{
    r->status = d->status;
    r->distance = d->distance;
    r->intersect = d->intersect;
    if (points) r->p1 = d->p1, r->p2 = d->p2;
}

/* Fills the result from a signed distance query: depth and the move of b that makes them touch. */
static void take_signed(prox_pair_result *r, const prox_signed_result *s)
{
    r->status = s->status;
    r->signed_distance = s->sd;
    r->distance = fmax(s->sd, 0.0);
    r->intersect = s->sd <= 0.0;
    r->p1 = s->p1, r->p2 = s->p2;
    r->depth = fmax(-s->sd, 0.0);
    r->reposition = s->sd < 0.0 ? prox_v3_scale(s->normal, -s->sd) : prox_v3(0, 0, 0);
}

/* RELATION mode: the relation first, then the one further solver that its case needs. */
static void relation_stage(prox_pair_result *r, const prox_shape *a, const prox_shape *b)
{
    prox_signed_result s;
    prox_relation_result rel = prox_shape_relation_with_signed(a, b, -1.0, &s);
    r->status = rel.status;
    if (rel.status != PROX_OK) return;
    r->relation = rel.relation;
    r->signed_distance = rel.signed_distance;
    if (rel.relation == PROX_REL_CROSSING) { /* the relation's own signed distance: computed once */
        take_signed(r, &s);
        r->distance = 0.0;
        r->intersect = 1;
        return;
    }
    prox_distance_result d = prox_shape_distance(a, b);
    take_distance(r, &d, 1);
    if (rel.relation != PROX_REL_DISJOINT) { /* touching or nested: no depth, no move asked for */
        r->intersect = 1;
        r->distance = 0.0;
        if (rel.relation != PROX_REL_TOUCHING) r->clearance = rel.clearance;
    }
}

/* Bound rungs. Returns 1 when they decided the pair (r filled), 0 to go on. cut: the caller does not
 * care about pairs farther apart than this (INFINITY: cares about all). */
static int bound_rungs(prox_pair_result *r, const prox_shape *a, const prox_shape *b, const bound *ba,
                       const bound *bb, double cut, int early_yes)
{
    prox_vec3 ca = ba->sphere.center, cb = bb->sphere.center;
    double scale = fmax(fmax(prox_v3_maxabs(ca), prox_v3_maxabs(cb)), fmax(ba->sphere.radius, bb->sphere.radius));
    double slack = SCENE_SLACK * scale;
    double centres = prox_v3_dist(ca, cb);
    double lower = fmax(aabb_gap(&ba->box, &bb->box), centres - ba->sphere.radius - bb->sphere.radius);
    if (lower > cut + slack) {
        r->decided_by = PROX_DECIDED_BOUNDS;
        return 1;
    }
    if (early_yes && cut == INFINITY) { /* every pair is within an infinite threshold */
        r->decided_by = PROX_DECIDED_BOUNDS, r->closer = 1, r->intersect = -1;
        return 1;
    }
    if (!(centres > 0.0)) return 0; /* concentric: no line of centres */
    prox_vec3 n = prox_v3_scale(prox_v3_sub(cb, ca), 1.0 / centres);
    double gap = -prox_shape_support(b, prox_v3_neg(n)) - prox_shape_support(a, n);
    if (gap > cut + slack) {
        r->decided_by = PROX_DECIDED_SUPPORT;
        return 1;
    }
    if (early_yes && cut > 0.0) {
        double upper = prox_v3_dist(prox_shape_support_point(a, n), prox_shape_support_point(b, prox_v3_neg(n)));
        if (upper < cut - slack) {
            r->decided_by = PROX_DECIDED_SUPPORT, r->closer = 1, r->intersect = -1;
            return 1;
        }
    }
    return 0;
}

/* The whole ladder for a validated pair with precomputed bounds. */
static prox_pair_result ladder(const prox_shape *a, const prox_shape *b, const bound *ba, const bound *bb,
                               prox_query_mode mode, double cut)
{
    prox_pair_result r = {0};
    r.mode = mode;
    if (mode == PROX_MODE_VERDICT && !(cut > 0.0)) cut = 0.0;
    int cheap = mode <= PROX_MODE_CLOSER;
    if (bound_rungs(&r, a, b, ba, bb, cut, cheap)) return r;
    if (cheap && cut == 0.0) { /* a pure verdict: the separating-axis test decides */
        prox_test_result t = prox_shape_test(a, b);
        r.status = t.status, r.intersect = t.intersect, r.closer = t.intersect;
        r.decided_by = PROX_DECIDED_TEST;
        return r;
    }
    r.decided_by = PROX_DECIDED_EXACT;
    if (mode <= PROX_MODE_POINTS) {
        prox_distance_result d = prox_shape_distance(a, b);
        take_distance(&r, &d, mode == PROX_MODE_POINTS);
        r.closer = r.intersect || r.distance <= cut;
    } else if (mode == PROX_MODE_SIGNED) {
        prox_signed_result s = prox_shape_signed_distance(a, b);
        take_signed(&r, &s);
        r.closer = r.signed_distance <= cut;
    } else {
        relation_stage(&r, a, b);
        r.closer = r.intersect || r.distance <= cut;
    }
    if (r.status != PROX_OK) r.closer = 0;
    return r;
}

/* Checks a mode and threshold. */
static prox_status check_query(prox_query_mode mode, double d)
{
    if ((int)mode < (int)PROX_MODE_VERDICT || (int)mode > (int)PROX_MODE_RELATION) return PROX_EINVAL_ARG;
    if (isnan(d) || d < 0.0) return PROX_EINVAL_ARG;
    return PROX_OK;
}

PROX_API prox_pair_result prox_pair_query(const prox_shape *a, const prox_shape *b, prox_query_mode mode, double d)
{
    prox_pair_result r = {0};
    r.mode = mode;
    if (!a || !b) r.status = PROX_EINVAL_ARG;
    if (r.status == PROX_OK) r.status = check_query(mode, d);
    if (r.status == PROX_OK) r.status = prox_shape_validate(a);
    if (r.status == PROX_OK) r.status = prox_shape_validate(b);
    if (r.status != PROX_OK) return r;
    bound ba = bound_make(a), bb = bound_make(b);
    /* A single query in an exact mode wants its number: nothing is cut away. */
    double cut = mode <= PROX_MODE_CLOSER ? d : INFINITY;
    r = ladder(a, b, &ba, &bb, mode, cut);
    if (mode > PROX_MODE_CLOSER) r.closer = r.status == PROX_OK && (r.intersect == 1 || r.distance <= d);
    return r;
}

PROX_API int prox_batch_has_openmp(void)
{
#ifdef _OPENMP
    return 1;
#else
    return 0;
#endif
}

PROX_API prox_status prox_batch_query(const prox_shape *a, const prox_shape *b, size_t n, prox_query_mode mode,
                                      double d, int threads, prox_pair_result *out)
{
    if (n && (!a || !b || !out)) return PROX_EINVAL_ARG;
    ptrdiff_t m = (ptrdiff_t)n;
#ifdef _OPENMP
    int nt = threads > 0 ? threads : omp_get_max_threads();
#pragma omp parallel for schedule(static, 256) num_threads(nt) if (nt > 1 && m > 256)
    for (ptrdiff_t i = 0; i < m; ++i) out[i] = prox_pair_query(&a[i], &b[i], mode, d);
#else
    (void)threads;
    for (ptrdiff_t i = 0; i < m; ++i) out[i] = prox_pair_query(&a[i], &b[i], mode, d);
#endif
    return PROX_OK;
}

/* ---- scenes -------------------------------------------------------------------------------------- */

struct prox_scene {
    prox_shape *shapes;
    bound *bounds;
    size_t n, cap;
    int threads;
};

PROX_API prox_scene *prox_scene_create(void)
{
    prox_scene *s = calloc(1, sizeof *s);
    if (s) s->threads = 1;
    return s;
}

PROX_API void prox_scene_destroy(prox_scene *s)
{
    if (!s) return;
    free(s->shapes);
    free(s->bounds);
    free(s);
}

PROX_API prox_status prox_scene_add(prox_scene *s, const prox_shape *shape)
{
    if (!s || !shape) return PROX_EINVAL_ARG;
    prox_status st = prox_shape_validate(shape);
    if (st != PROX_OK) return st;
    if (s->n == s->cap) {
        size_t nc = s->cap ? 2 * s->cap : 64;
        prox_shape *ns = realloc(s->shapes, nc * sizeof *ns);
        if (!ns) return PROX_ENOMEM;
        s->shapes = ns;
        bound *nb = realloc(s->bounds, nc * sizeof *nb);
        if (!nb) return PROX_ENOMEM;
        s->bounds = nb;
        s->cap = nc;
    }
    s->shapes[s->n] = *shape;
    s->bounds[s->n] = bound_make(shape);
    s->n++;
    return PROX_OK;
}

PROX_API size_t prox_scene_count(const prox_scene *s) { return s ? s->n : 0; }

PROX_API const prox_shape *prox_scene_body(const prox_scene *s, size_t i)
{
    return s && i < s->n ? &s->shapes[i] : NULL;
}

PROX_API void prox_scene_set_threads(prox_scene *s, int threads)
{
    if (s) s->threads = threads;
}

PROX_API void prox_scene_report_free(prox_scene_report *r)
{
    if (!r) return;
    free(r->pairs);
    memset(r, 0, sizeof *r);
}

/* A candidate pair (indices a < b). */
typedef prox_broad_pair cand;

/* Growable list of candidates. */
static int push_cand(cand **v, size_t *n, size_t *cap, size_t a, size_t b)
{
    if (*n == *cap) {
        size_t nc = *cap ? 2 * *cap : 1024;
        cand *q = realloc(*v, nc * sizeof *q);
        if (!q) return -1;
        *v = q, *cap = nc;
    }
    (*v)[(*n)++] = a < b ? (cand){a, b} : (cand){b, a};
    return 0;
}

/* Sort key of the nearest pair's first bound. */
typedef struct near_key {
    double lo;
    size_t idx;
} near_key;

static int cmp_key(const void *x, const void *y)
{
    const near_key *a = x, *b = y;
    if (a->lo != b->lo) return a->lo < b->lo ? -1 : 1;
    return a->idx < b->idx ? -1 : (a->idx > b->idx);
}

/* Largest coordinate magnitude of the scene: scales the slack of the broad phase. */
static double scene_scale(const prox_scene *s)
{
    double m = 0;
    for (size_t i = 0; i < s->n; ++i)
        m = fmax(m, fmax(prox_v3_maxabs(s->bounds[i].box.lo), prox_v3_maxabs(s->bounds[i].box.hi)));
    return m;
}

/* Broad phase: every pair whose boxes are within `cut` (plus twice the ladder's slack at the scene's
 * scale) on all three axes, sorted by (a, b) (src/scene/broad.c). */
static int broad(const prox_scene *s, double cut, cand **out, size_t *nout)
{
    *out = NULL, *nout = 0;
    if (s->n < 2) return 0; /* (no bounds array to point into when the scene is empty) */
    double c = cut + 2 * SCENE_SLACK * scene_scale(s);
    return prox_broad_pairs(&s->bounds[0].box, sizeof *s->bounds, s->n, c, prox_par_threads(s->threads), out, nout);
}

/* Every pair of the scene as candidates (naive reference, or an infinite threshold). */
static int all_pairs(const prox_scene *s, cand **out, size_t *nout)
{
    size_t cap = 0;
    *out = NULL, *nout = 0;
    for (size_t i = 0; i < s->n; ++i)
        for (size_t j = i + 1; j < s->n; ++j)
            if (push_cand(out, nout, &cap, i, j)) return -1;
    return 0;
}

static int cmp_pair(const void *x, const void *y)
{
    const prox_scene_pair *a = x, *b = y;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    return a->b < b->b ? -1 : (a->b > b->b);
}

/* Tallies which rung decided a pair. */
static void count_rung(prox_scene_stats *st, prox_decided_by d)
{
    if (d == PROX_DECIDED_BOUNDS) st->bound_rejects++;
    else if (d == PROX_DECIDED_SUPPORT) st->support_decided++;
    else if (d == PROX_DECIDED_TEST) st->tests++;
    else if (d == PROX_DECIDED_EXACT) st->exact++;
}

/* One chunk of candidates through the ladder, shared by the worker threads. */
typedef struct ladder_job {
    const prox_scene *s;
    const cand *c;
    prox_pair_result *res;
    size_t m;
    prox_query_mode mode;
    double cut;
    atomic_size_t next;
} ladder_job;

static void ladder_worker(void *ctx, int worker)
{
    ladder_job *j = ctx;
    const prox_scene *s = j->s;
    (void)worker;
    for (;;) {
        size_t i0 = atomic_fetch_add(&j->next, SCENE_GRAIN);
        if (i0 >= j->m) return;
        size_t i1 = i0 + SCENE_GRAIN < j->m ? i0 + SCENE_GRAIN : j->m;
        for (size_t i = i0; i < i1; ++i) {
            const cand *c = &j->c[i];
            j->res[i] = ladder(&s->shapes[c->a], &s->shapes[c->b], &s->bounds[c->a], &s->bounds[c->b], j->mode, j->cut);
        }
    }
}

/* Runs the ladder over the candidates in chunks (on the scene's threads) and keeps the pairs within
 * the threshold or with a failed status. */
static prox_status evaluate(const prox_scene *s, const cand *c, size_t nc, prox_query_mode mode, double cut,
                            prox_scene_report *rep)
{
    size_t chunk = nc < SCENE_CHUNK ? nc : SCENE_CHUNK, cap = 0;
    prox_pair_result *res = chunk ? malloc(chunk * sizeof *res) : NULL;
    if (chunk && !res) return PROX_ENOMEM;
    int threads = prox_par_threads(s->threads);
    for (size_t start = 0; start < nc; start += chunk) {
        size_t m = nc - start < chunk ? nc - start : chunk;
        ladder_job job = {.s = s, .c = c + start, .res = res, .m = m, .mode = mode, .cut = cut};
        atomic_init(&job.next, 0);
        prox_par_run(m > SCENE_GRAIN ? threads : 1, ladder_worker, &job);
        for (size_t i = 0; i < m; ++i) {
            count_rung(&rep->stats, res[i].decided_by);
            if (!res[i].closer && res[i].status == PROX_OK) continue;
            if (rep->npairs == cap) {
                size_t ncap = cap ? 2 * cap : 256;
                prox_scene_pair *q = realloc(rep->pairs, ncap * sizeof *q);
                if (!q) {
                    free(res);
                    return PROX_ENOMEM;
                }
                rep->pairs = q, cap = ncap;
            }
            rep->pairs[rep->npairs++] = (prox_scene_pair){c[start + i].a, c[start + i].b, res[i]};
        }
    }
    free(res);
    /* the candidates come sorted by (a, b) already; the sort keeps the order a documented property */
    if (rep->npairs) qsort(rep->pairs, rep->npairs, sizeof *rep->pairs, cmp_pair);
    rep->stats.reported = rep->npairs;
    return PROX_OK;
}

/* Shared body of the scene queries: broad phase (or every pair), then the ladder. */
static prox_scene_report run_pairs(const prox_scene *s, double clearance, prox_query_mode mode, int naive)
{
    prox_scene_report rep = {0};
    if (!s) {
        rep.status = PROX_EINVAL_ARG;
        return rep;
    }
    rep.status = check_query(mode, clearance);
    if (rep.status != PROX_OK) return rep;
    rep.stats.bodies = s->n;
    rep.stats.naive_pairs = s->n < 2 ? 0 : s->n * (s->n - 1) / 2;
    cand *c = NULL;
    size_t nc = 0;
    int fail = (naive || clearance == INFINITY) ? all_pairs(s, &c, &nc) : broad(s, clearance, &c, &nc);
    rep.stats.candidates = nc;
    rep.status = fail ? PROX_ENOMEM : evaluate(s, c, nc, mode, clearance, &rep);
    free(c);
    return rep;
}

PROX_API prox_scene_report prox_scene_pairs(const prox_scene *s, double clearance, prox_query_mode mode)
{
    return run_pairs(s, clearance, mode, 0);
}

PROX_API prox_scene_report prox_scene_pairs_naive(const prox_scene *s, double clearance, prox_query_mode mode)
{
    return run_pairs(s, clearance, mode, 1);
}

PROX_API prox_scene_report prox_scene_intersecting(const prox_scene *s, prox_query_mode mode)
{
    return run_pairs(s, 0.0, mode, 0);
}

/* An upper bound on the smallest pair distance: the support-point bound of neighbours along x. */
static double nearest_upper_bound(const prox_scene *s)
{
    double best = INFINITY;
    near_key *key = malloc(s->n * sizeof *key);
    if (!key) return INFINITY;
    for (size_t i = 0; i < s->n; ++i) key[i] = (near_key){s->bounds[i].sphere.center.x, i};
    qsort(key, s->n, sizeof *key, cmp_key);
    for (size_t i = 0; i + 1 < s->n; ++i) {
        const prox_shape *a = &s->shapes[key[i].idx], *b = &s->shapes[key[i + 1].idx];
        prox_vec3 n = prox_v3_sub(s->bounds[key[i + 1].idx].sphere.center, s->bounds[key[i].idx].sphere.center);
        double up = prox_v3_dist(prox_shape_support_point(a, n), prox_shape_support_point(b, prox_v3_neg(n)));
        best = fmin(best, up);
    }
    free(key);
    return best;
}

PROX_API prox_scene_report prox_scene_nearest(const prox_scene *s)
{
    prox_scene_report rep = {0};
    if (!s) {
        rep.status = PROX_EINVAL_ARG;
        return rep;
    }
    rep.stats.bodies = s->n;
    rep.stats.naive_pairs = s->n < 2 ? 0 : s->n * (s->n - 1) / 2;
    if (s->n < 2) return rep;
    double best = nearest_upper_bound(s);
    cand *c = NULL;
    size_t nc = 0;
    if (broad(s, best, &c, &nc)) {
        rep.status = PROX_ENOMEM;
        return rep;
    }
    rep.stats.candidates = nc;
    prox_scene_pair found = {0, 0, {0}};
    int have = 0;
    for (size_t i = 0; i < nc; ++i) { /* serial, in (a, b) order: each exact distance tightens the cut */
        prox_pair_result r = ladder(&s->shapes[c[i].a], &s->shapes[c[i].b], &s->bounds[c[i].a], &s->bounds[c[i].b],
                                    PROX_MODE_POINTS, best);
        count_rung(&rep.stats, r.decided_by);
        if (r.status != PROX_OK) {
            rep.status = r.status;
            continue;
        }
        if (r.decided_by == PROX_DECIDED_EXACT && (!have || r.distance < found.r.distance)) {
            found = (prox_scene_pair){c[i].a, c[i].b, r};
            have = 1;
            best = fmin(best, r.distance);
        }
    }
    free(c);
    if (have) {
        rep.pairs = malloc(sizeof *rep.pairs);
        if (!rep.pairs) {
            rep.status = PROX_ENOMEM;
            return rep;
        }
        rep.pairs[0] = found;
        rep.npairs = rep.stats.reported = 1;
    }
    return rep;
}
