/* prox_bench group "prim": every primitive pair of include/prox/primitives.h (Agarwal et al. 2016,
 * Sec. 3: points, segments L, circles C, disks D, cylindrical surfaces S) on seeded random inputs
 * spread over a cube of side 20 with sizes in [0.1, 5]. Timing only: accuracy is the tests' job. */
#include <stdlib.h>

#include "bench.h"


/* One random primitive of each kind per query slot. */
typedef struct prim_in {
    prox_vec3 p;
    prox_segment s;
    prox_circle c;
    prox_cylsurf y;
} prim_in;

typedef struct prim_set {
    size_t n;
    prim_in *a, *b;
} prim_set;

static prim_in random_prim(bench_rng *r)
{
    prim_in x;
    prox_vec3 o = prox_v3(bench_range(r, -10, 10), bench_range(r, -10, 10), bench_range(r, -10, 10));
    x.p = o;
    x.s.a = o;
    x.s.b = prox_v3_mad(o, bench_range(r, 0.1, 10), bench_unit(r));
    x.c.center = o;
    x.c.normal = bench_unit(r);
    x.c.radius = bench_range(r, 0.1, 5);
    x.y.base = o;
    x.y.dir = bench_unit(r);
    x.y.height = bench_range(r, 0.1, 10);
    x.y.radius = bench_range(r, 0.1, 5);
    return x;
}

#define PRIM_QUERY(fname, call)                                \
    static double fname(const void *data, size_t i)            \
    {                                                          \
        const prim_set *S = data;                              \
        const prim_in *A = &S->a[i], *B = &S->b[i];            \
        (void)A, (void)B;                                      \
        prox_prim_result res = call;                           \
        return res.distance;                                   \
    }

#ifdef PROX_BENCH_HAVE_POINT_SEGMENT
PRIM_QUERY(q_point_segment, prox_point_segment(A->p, &B->s))
#endif
#ifdef PROX_BENCH_HAVE_POINT_CIRCLE
PRIM_QUERY(q_point_circle, prox_point_circle(A->p, &B->c))
#endif
#ifdef PROX_BENCH_HAVE_POINT_DISK
PRIM_QUERY(q_point_disk, prox_point_disk(A->p, &B->c))
#endif
#ifdef PROX_BENCH_HAVE_POINT_CYLSURF
PRIM_QUERY(q_point_cylsurf, prox_point_cylsurf(A->p, &B->y))
#endif
#ifdef PROX_BENCH_HAVE_SEGMENT_SEGMENT
PRIM_QUERY(q_segment_segment, prox_segment_segment(&A->s, &B->s))
#endif
#ifdef PROX_BENCH_HAVE_SEGMENT_CYLSURF_INF
PRIM_QUERY(q_segment_cylsurf_inf, prox_segment_cylsurf_inf(&A->s, &B->y))
#endif
#ifdef PROX_BENCH_HAVE_CYLSURF_CYLSURF_INF
PRIM_QUERY(q_cylsurf_cylsurf_inf, prox_cylsurf_cylsurf_inf(&A->y, &B->y))
#endif
#ifdef PROX_BENCH_HAVE_DISK_SEGMENT
PRIM_QUERY(q_disk_segment, prox_disk_segment(&A->c, &B->s))
#endif
#ifdef PROX_BENCH_HAVE_CIRCLE_SEGMENT
PRIM_QUERY(q_circle_segment, prox_circle_segment(&A->c, &B->s))
#endif
#ifdef PROX_BENCH_HAVE_DISK_CIRCLE
PRIM_QUERY(q_disk_circle, prox_disk_circle(&A->c, &B->c))
#endif
#ifdef PROX_BENCH_HAVE_CIRCLE_CIRCLE
PRIM_QUERY(q_circle_circle, prox_circle_circle(&A->c, &B->c))
#endif

void bench_group_prim(const bench_opts *o)
{
    static const struct {
        const char *name;
        bench_query_fn fn;
    } table[] = {
#ifdef PROX_BENCH_HAVE_POINT_SEGMENT
        {"prim/point_segment", q_point_segment},
#endif
#ifdef PROX_BENCH_HAVE_POINT_CIRCLE
        {"prim/point_circle", q_point_circle},
#endif
#ifdef PROX_BENCH_HAVE_POINT_DISK
        {"prim/point_disk", q_point_disk},
#endif
#ifdef PROX_BENCH_HAVE_POINT_CYLSURF
        {"prim/point_cylsurf", q_point_cylsurf},
#endif
#ifdef PROX_BENCH_HAVE_SEGMENT_SEGMENT
        {"prim/segment_segment", q_segment_segment},
#endif
#ifdef PROX_BENCH_HAVE_SEGMENT_CYLSURF_INF
        {"prim/segment_cylsurf_inf", q_segment_cylsurf_inf},
#endif
#ifdef PROX_BENCH_HAVE_CYLSURF_CYLSURF_INF
        {"prim/cylsurf_cylsurf_inf", q_cylsurf_cylsurf_inf},
#endif
#ifdef PROX_BENCH_HAVE_DISK_SEGMENT
        {"prim/disk_segment", q_disk_segment},
#endif
#ifdef PROX_BENCH_HAVE_CIRCLE_SEGMENT
        {"prim/circle_segment", q_circle_segment},
#endif
#ifdef PROX_BENCH_HAVE_DISK_CIRCLE
        {"prim/disk_circle", q_disk_circle},
#endif
#ifdef PROX_BENCH_HAVE_CIRCLE_CIRCLE
        {"prim/circle_circle", q_circle_circle},
#endif
        {NULL, NULL},
    };
    if (!bench_selected(o, "prim/")) return;
    prim_set *S = bench_xmalloc(sizeof *S); /* lives until exit */
    S->n = o->quick ? 5000 : 200000;
    S->a = bench_xmalloc(S->n * sizeof *S->a);
    S->b = bench_xmalloc(S->n * sizeof *S->b);
    bench_rng r = bench_rng_seed(7);
    for (size_t i = 0; i < S->n; ++i) S->a[i] = random_prim(&r), S->b[i] = random_prim(&r);
    for (size_t k = 0; table[k].name; ++k)
        if (bench_selected(o, table[k].name)) bench_add(table[k].name, table[k].fn, S, NULL, S->n);
}
