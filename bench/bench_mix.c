/* prox_bench group "mix": every pair type, prox beside the peer libraries on the same pairs in the
 * same run, with the overlapping and the disjoint pairs also reported apart.
 *
 * Pairs (seeded, built before timing): two solids with every size (radius, height, edge, semi-axis)
 * uniform in [0.5, 10], centres uniform 0 to 14 apart in a uniformly random direction, each solid
 * under a uniformly random rotation. Families: the six pair types of the original four macrobodies
 * and a pair type for each added macrobody (kept only when the library validates the solids).
 *
 * Reference: prox's exact signed distance (prox_shape_signed_distance) of each pair; a peer's error is
 * |value - reference| / S with S = max(|cA - cB|, sizes). prox's own rows are checked against its
 * second, independent method (prox_shape_signed_distance_support: the support-function method), so
 * that their error column is the disagreement of two methods, not zero by construction. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench_mix.h"
#include "core/polytope.h"

#if defined(PROX_BENCH_HAVE_QUERY)

/* ---- solids ------------------------------------------------------------------------------------ */

static double size_u(bench_rng *r) { return bench_range(r, 0.5, 10.0); }

/* A random solid of kind k centred (near) c under the rotation R. */
static prox_shape mix_solid(bench_rng *r, prox_shape_kind k, prox_vec3 c, const bench_rot *R)
{
    prox_vec3 ex = bench_rot_apply(R, prox_v3(1, 0, 0)), ey = bench_rot_apply(R, prox_v3(0, 1, 0));
    prox_vec3 ez = bench_rot_apply(R, prox_v3(0, 0, 1));
    switch (k) {
    case PROX_SHAPE_RCC: {
        double rad = size_u(r), h = size_u(r);
        return prox_shape_from_rcc((prox_rcc){prox_v3_mad(c, -0.5 * h, ez), prox_v3_scale(ez, h), rad});
    }
    case PROX_SHAPE_BOX: {
        prox_vec3 e[3] = {prox_v3_scale(ex, size_u(r)), prox_v3_scale(ey, size_u(r)), prox_v3_scale(ez, size_u(r))};
        prox_vec3 corner = c;
        for (int i = 0; i < 3; ++i) corner = prox_v3_mad(corner, -0.5, e[i]);
        return prox_shape_from_box((prox_box){corner, {e[0], e[1], e[2]}});
    }
    case PROX_SHAPE_TRC: { /* the apex form (r2 = 0) when the library accepts it: the peers' Cone */
        double r1 = size_u(r), h = size_u(r);
        prox_trc t = {prox_v3_mad(c, -0.5 * h, ez), prox_v3_scale(ez, h), r1, 0.0};
        if (prox_trc_validate(&t) != PROX_OK) t.r2 = 0.25 * r1;
        return prox_shape_from_trc(t);
    }
    case PROX_SHAPE_REC: {
        double a1 = size_u(r), a2 = size_u(r), h = size_u(r);
        if (a2 > a1) { double t = a1; a1 = a2; a2 = t; }
        return prox_shape_from_rec((prox_rec){prox_v3_mad(c, -0.5 * h, ez), prox_v3_scale(ez, h),
                                              prox_v3_scale(ex, a1), prox_v3_scale(ey, a2)});
    }
    case PROX_SHAPE_ELL: return prox_shape_from_ell((prox_ell){c, prox_v3_scale(ez, 0.5 * size_u(r)), 0.5 * size_u(r)});
    case PROX_SHAPE_RHP: {
        double ap = 0.5 * size_u(r), h = size_u(r);
        prox_rhp x;
        if (prox_rhp_regular(prox_v3_mad(c, -0.5 * h, ez), prox_v3_scale(ez, h), prox_v3_scale(ex, ap), &x) != PROX_OK)
            return prox_shape_from_sph((prox_sph){c, ap});
        return prox_shape_from_rhp(x);
    }
    case PROX_SHAPE_WED: {
        double a = size_u(r), b = size_u(r), h = size_u(r), th = bench_range(r, 0.5, 2.6);
        prox_vec3 v1 = prox_v3_scale(ex, a), v2 = prox_v3_add(prox_v3_scale(ex, b * cos(th)), prox_v3_scale(ey, b * sin(th)));
        prox_vec3 v3 = prox_v3_scale(ez, h);
        prox_vec3 v = prox_v3_sub(c, prox_v3_scale(prox_v3_add(prox_v3_add(v1, v2), v3), 1.0 / 3.0));
        return prox_shape_from_wed((prox_wed){v, v1, v2, v3});
    }
    case PROX_SHAPE_ARB: { /* a truncated rectangular pyramid: corners 1-4 at the base, 5-8 at the top */
        double a = 0.5 * size_u(r), b = 0.5 * size_u(r), h = 0.5 * size_u(r), s = bench_range(r, 0.3, 1.0);
        prox_arb x;
        static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        for (int i = 0; i < 4; ++i) {
            x.corner[i] = prox_v3_add(c, prox_v3_add(prox_v3_add(prox_v3_scale(ex, sx[i] * a), prox_v3_scale(ey, sy[i] * b)),
                                                     prox_v3_scale(ez, -h)));
            x.corner[4 + i] = prox_v3_add(
                c, prox_v3_add(prox_v3_add(prox_v3_scale(ex, s * sx[i] * a), prox_v3_scale(ey, s * sy[i] * b)), prox_v3_scale(ez, h)));
        }
        static const int faces[6] = {1234, 5678, 1265, 2376, 3487, 4158};
        memcpy(x.face, faces, sizeof faces);
        return prox_shape_from_arb(x);
    }
    case PROX_SHAPE_SPH:
    default: return prox_shape_from_sph((prox_sph){c, 0.5 * size_u(r)});
    }
}

/* S = max(|cA - cB|, sizes) of a pair. */
static double mix_scale(const prox_shape *a, const prox_shape *b)
{
    return prox_shape_pair_scale(a, b);
}

/* ---- frames for the peers ---------------------------------------------------------------------- */

static void frame_from_axes(mix_frame *f, prox_vec3 x, prox_vec3 y, prox_vec3 z)
{
    prox_vec3 col[3] = {x, y, z};
    for (int j = 0; j < 3; ++j) {
        f->R[0][j] = col[j].x, f->R[1][j] = col[j].y, f->R[2][j] = col[j].z;
    }
}

/* Unit vectors completing the unit z to a right-handed frame. */
static void frame_from_z(mix_frame *f, prox_vec3 z)
{
    prox_vec3 a = fabs(z.x) < 0.6 ? prox_v3(1, 0, 0) : prox_v3(0, 1, 0);
    prox_vec3 x = prox_v3_mad(a, -prox_v3_dot(a, z), z);
    x = prox_v3_scale(x, 1.0 / prox_v3_norm(x));
    frame_from_axes(f, x, prox_v3_cross(z, x), z);
}

int bench_mix_frame(const prox_shape *s, mix_frame *f)
{
    memset(f, 0, sizeof *f);
    switch (s->kind) {
    case PROX_SHAPE_SPH:
        frame_from_axes(f, prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1));
        f->c = s->u.sph.center, f->size[0] = s->u.sph.radius;
        return 1;
    case PROX_SHAPE_RCC: {
        double h = prox_v3_norm(s->u.rcc.axis);
        frame_from_z(f, prox_v3_scale(s->u.rcc.axis, 1.0 / h));
        f->c = prox_v3_mad(s->u.rcc.base, 0.5, s->u.rcc.axis), f->size[0] = s->u.rcc.radius, f->size[1] = h;
        return 1;
    }
    case PROX_SHAPE_BOX:
    case PROX_SHAPE_RPP: {
        prox_box b = s->kind == PROX_SHAPE_BOX ? s->u.box : prox_rpp_to_box(&s->u.rpp);
        prox_vec3 u[3];
        f->c = b.corner;
        for (int i = 0; i < 3; ++i) {
            double l = prox_v3_norm(b.edge[i]);
            u[i] = prox_v3_scale(b.edge[i], 1.0 / l), f->size[i] = 0.5 * l;
            f->c = prox_v3_mad(f->c, 0.5, b.edge[i]);
        }
        if (prox_v3_dot(prox_v3_cross(u[0], u[1]), u[2]) < 0) u[2] = prox_v3_scale(u[2], -1.0); /* symmetric */
        frame_from_axes(f, u[0], u[1], u[2]);
        return 1;
    }
    case PROX_SHAPE_TRC: {
        if (s->u.trc.r2 != 0.0) return 0; /* a frustum: no canonical peer shape */
        double h = prox_v3_norm(s->u.trc.axis);
        frame_from_z(f, prox_v3_scale(s->u.trc.axis, 1.0 / h));
        f->c = prox_v3_mad(s->u.trc.base, 0.5, s->u.trc.axis), f->size[0] = s->u.trc.r1, f->size[1] = h;
        return 1;
    }
    case PROX_SHAPE_ELL: {
        double a = prox_v3_norm(s->u.ell.axis);
        frame_from_z(f, prox_v3_scale(s->u.ell.axis, 1.0 / a));
        f->c = s->u.ell.center, f->size[0] = s->u.ell.radius, f->size[1] = a;
        return 1;
    }
    case PROX_SHAPE_RHP:
    case PROX_SHAPE_WED:
    case PROX_SHAPE_ARB: {
        prox_polytope p;
        prox_vec3 c = prox_polytope_make(s, &p);
        frame_from_axes(f, prox_v3(1, 0, 0), prox_v3(0, 1, 0), prox_v3(0, 0, 1));
        f->c = c, f->nv = p.nv, f->nf = p.nf;
        for (int i = 0; i < p.nv; ++i) f->v[i] = prox_v3_add(c, p.v[i]);
        for (int k = 0; k < p.nf; ++k) {
            f->fnv[k] = p.fnv[k];
            for (int j = 0; j < p.fnv[k]; ++j) f->fv[k][j] = p.fv[k][j];
        }
        return 1;
    }
    default: return 0;
    }
}

/* ---- prox methods ------------------------------------------------------------------------------ */

static void *prox_prepare(const prox_shape *s) { return (void *)s; }

static void prox_run_distance(const void *cfg, const void *a, const void *b, bench_answer *out)
{
    (void)cfg;
    prox_distance_result r = prox_shape_distance(a, b);
    out->ok = r.status == PROX_OK, out->value = r.distance, out->intersect = r.intersect;
    out->p1 = r.p1, out->p2 = r.p2, out->has_points = !r.intersect;
}

static void prox_run_signed(const void *cfg, const void *a, const void *b, bench_answer *out)
{
    (void)cfg;
    prox_signed_result r = prox_shape_signed_distance(a, b);
    out->ok = r.status == PROX_OK, out->value = r.sd, out->intersect = r.sd <= 0;
    out->p1 = r.p1, out->p2 = r.p2, out->has_points = 1;
}

static void prox_run_verdict(const void *cfg, const void *a, const void *b, bench_answer *out)
{
    (void)cfg;
    prox_test_result r = prox_shape_test(a, b);
    out->ok = r.status == PROX_OK, out->intersect = r.intersect == 1, out->value = out->intersect;
}

/* Prepared solids (prox/solid.h): validated and built once before timing, as the peers build
 * theirs; the same answers as the shape queries. Kept for the process's life, like the peers'. */
static void *solid_prepare(const prox_shape *s) { return prox_solid_new(s, NULL); }

static void solid_run_distance(const void *cfg, const void *a, const void *b, bench_answer *out)
{
    (void)cfg;
    prox_distance_result r = prox_solid_distance(a, b);
    out->ok = r.status == PROX_OK, out->value = r.distance, out->intersect = r.intersect;
    out->p1 = r.p1, out->p2 = r.p2, out->has_points = !r.intersect;
}

static void solid_run_signed(const void *cfg, const void *a, const void *b, bench_answer *out)
{
    (void)cfg;
    prox_signed_result r = prox_solid_signed_distance(a, b);
    out->ok = r.status == PROX_OK, out->value = r.sd, out->intersect = r.sd <= 0;
    out->p1 = r.p1, out->p2 = r.p2, out->has_points = 1;
}

static void solid_run_verdict(const void *cfg, const void *a, const void *b, bench_answer *out)
{
    (void)cfg;
    prox_test_result r = prox_solid_test(a, b);
    out->ok = r.status == PROX_OK, out->intersect = r.intersect == 1, out->value = out->intersect;
}

static const mix_method k_prox[] = {
    {"prox/verdict", BENCH_VERDICT, prox_prepare, prox_run_verdict, NULL, NULL},
    {"prox/distance", BENCH_DIST, prox_prepare, prox_run_distance, NULL, NULL},
    {"prox/signed", BENCH_SIGNED, prox_prepare, prox_run_signed, NULL, NULL},
    {"prox-solid/verdict", BENCH_VERDICT, solid_prepare, solid_run_verdict, NULL, NULL},
    {"prox-solid/distance", BENCH_DIST, solid_prepare, solid_run_distance, NULL, NULL},
    {"prox-solid/signed", BENCH_SIGNED, solid_prepare, solid_run_signed, NULL, NULL},
};

/* ---- sets and cases ---------------------------------------------------------------------------- */

typedef struct mix_set {
    size_t n;
    prox_shape *a, *b;
    double *sd, *S; /* reference signed distance, scale */
    size_t *over, nover, *apart, napart;
} mix_set;

/* One case: a method on prepared solids of a subset, copied to contiguous arrays. */
typedef struct mix_case {
    const mix_method *m;
    void **pa, **pb;
} mix_case;

static double mix_one(const void *data, size_t i)
{
    const mix_case *c = data;
    bench_answer x;
    c->m->run(c->m->cfg, c->pa[i], c->pb[i], &x);
    return x.value;
}

/* Distance from x to a solid (0 inside): witness checks. */
static double off_solid(const prox_shape *s, prox_vec3 x)
{
    prox_sph p = {x, PROX_MIN_SIZE}; /* a point, as the smallest sphere the library takes */
    prox_distance_result r = prox_shape_distance(s, &(prox_shape){.kind = PROX_SHAPE_SPH, .u.sph = p});
    return r.status == PROX_OK ? r.distance : INFINITY;
}

static double quantile(double *v, size_t n, double q)
{
    return bench_quantile(v, n, q);
}

/* Accuracy of a method on the subset idx against the reference; prox rows against the support method. */
static bench_accuracy mix_accuracy(const mix_method *m, const mix_set *s, void **pa, void **pb, const size_t *idx, size_t n,
                                   int is_prox)
{
    bench_accuracy acc = {NAN, NAN, NAN, 0, 0, 0};
    double *err = bench_xmalloc((n ? n : 1) * sizeof *err);
    for (size_t k = 0; k < n; ++k) {
        size_t i = idx[k];
        bench_answer x;
        memset(&x, 0, sizeof x);
        m->run(m->cfg, pa[k], pb[k], &x);
        double sd = s->sd[i], S = s->S[i];
        if (is_prox && m->kind != BENCH_VERDICT) {
            prox_signed_result t = prox_shape_signed_distance_support(&s->a[i], &s->b[i]);
            if (t.status == PROX_OK) sd = t.sd;
        }
        if (!x.ok || !isfinite(x.value)) {
            ++acc.failures, err[k] = INFINITY;
            continue;
        }
        if (fabs(sd) > 1e-9 * S && x.intersect != (sd <= 0)) ++acc.mismatches;
        if (m->kind == BENCH_VERDICT) err[k] = 0;
        else if (m->kind == BENCH_DIST) err[k] = fabs(fmax(x.value, 0.0) - fmax(sd, 0.0)) / S;
        else err[k] = fabs(x.value - sd) / S;
        if (x.has_points && m->kind != BENCH_VERDICT) {
            double w = fabs(prox_v3_norm(prox_v3_sub(x.p2, x.p1)) - fabs(m->kind == BENCH_DIST ? fmax(x.value, 0.0) : x.value));
            if (x.value > 0) w = fmax(w, fmax(off_solid(&s->a[i], x.p1), off_solid(&s->b[i], x.p2)));
            acc.wit_max = fmax(acc.wit_max, w / S);
        }
    }
    if (m->kind != BENCH_VERDICT && n) {
        acc.err_median = quantile(err, n, 0.5), acc.err_p99 = quantile(err, n, 0.99), acc.err_max = err[n - 1];
    }
    if (m->kind == BENCH_VERDICT) acc.wit_max = NAN;
    free(err);
    return acc;
}

/* 1 when --filter can select one of the method's cases of the family (a free substring filter such as
 * "/agarwal" names none of them: the family's set-up, which runs every method for its accuracy, is
 * then skipped). */
static int mix_wanted(const bench_opts *o, const char *fam, const char *method)
{
    if (!o->filter) return 1;
    static const char *const subs[] = {"all", "overlap", "disjoint"};
    char name[96];
    for (int k = 0; k < 3; ++k) {
        snprintf(name, sizeof name, "mix/%s/%s/%s", fam, method, subs[k]);
        if (strstr(name, o->filter) || !strncmp(o->filter, name, strlen(o->filter))) return 1;
    }
    return 0;
}

static void mix_register(const bench_opts *o, const char *fam, const mix_method *m, const mix_set *s, int is_prox)
{
    if (m->skip && m->skip(s->a[0].kind, s->b[0].kind)) return;
    if (!mix_wanted(o, fam, m->name)) return;
    void **pa = bench_xmalloc(s->n * sizeof *pa), **pb = bench_xmalloc(s->n * sizeof *pb);
    for (size_t i = 0; i < s->n; ++i) {
        pa[i] = m->prepare(&s->a[i]), pb[i] = m->prepare(&s->b[i]);
        if (!pa[i] || !pb[i]) { /* the peer has no such shape */
            free(pa), free(pb);
            return;
        }
    }
    const struct {
        const char *name;
        const size_t *idx;
        size_t n;
    } subsets[] = {{"all", NULL, s->n}, {"overlap", s->over, s->nover}, {"disjoint", s->apart, s->napart}};
    for (int k = 0; k < 3; ++k) {
        size_t n = subsets[k].n;
        if (n == 0) continue;
        mix_case *c = bench_xmalloc(sizeof *c);
        c->m = m, c->pa = bench_xmalloc(n * sizeof *c->pa), c->pb = bench_xmalloc(n * sizeof *c->pb);
        size_t *idx = bench_xmalloc(n * sizeof *idx);
        for (size_t j = 0; j < n; ++j) {
            idx[j] = subsets[k].idx ? subsets[k].idx[j] : j;
            c->pa[j] = pa[idx[j]], c->pb[j] = pb[idx[j]];
        }
        char name[96];
        snprintf(name, sizeof name, "mix/%s/%s/%s", fam, m->name, subsets[k].name);
        bench_case *bc = bench_add(name, mix_one, c, NULL, n);
        bc->acc = mix_accuracy(m, s, c->pa, c->pb, idx, n, is_prox);
        bc->has_acc = 1;
        bench_note(bc, "pairs=%zu;overlapping=%.1f%%;reference=%s", n, 100.0 * (double)s->nover / (double)s->n,
                   is_prox ? "prox-support-method" : "prox-exact");
        free(idx);
    }
}

static int mix_build(const bench_opts *o, prox_shape_kind ka, prox_shape_kind kb, uint64_t seed, mix_set *s)
{
    size_t n = o->quick ? 2000 : 20000;
    bench_rng r = bench_rng_seed(seed);
    s->n = n;
    s->a = bench_xmalloc(n * sizeof *s->a), s->b = bench_xmalloc(n * sizeof *s->b);
    s->sd = bench_xmalloc(n * sizeof *s->sd), s->S = bench_xmalloc(n * sizeof *s->S);
    s->over = bench_xmalloc(n * sizeof *s->over), s->apart = bench_xmalloc(n * sizeof *s->apart);
    s->nover = s->napart = 0;
    for (size_t i = 0; i < n; ++i) {
        bench_rot Ra = bench_random_rot(&r), Rb = bench_random_rot(&r);
        prox_vec3 cb = prox_v3_scale(bench_unit(&r), bench_range(&r, 0.0, 14.0));
        s->a[i] = mix_solid(&r, ka, prox_v3(0, 0, 0), &Ra);
        s->b[i] = mix_solid(&r, kb, cb, &Rb);
        prox_signed_result t = prox_shape_signed_distance(&s->a[i], &s->b[i]);
        if (t.status != PROX_OK) return 0; /* the library does not answer this pair type yet */
        s->sd[i] = t.sd, s->S[i] = mix_scale(&s->a[i], &s->b[i]);
        if (t.sd <= 0) s->over[s->nover++] = i;
        else s->apart[s->napart++] = i;
    }
    return 1;
}

static void mix_family(const bench_opts *o, prox_shape_kind ka, prox_shape_kind kb, uint64_t seed)
{
    char fam[16], name[96];
    snprintf(fam, sizeof fam, "%s-%s", prox_shape_kind_name(ka), prox_shape_kind_name(kb));
    snprintf(name, sizeof name, "mix/%s/", fam);
    if (!bench_selected(o, name)) return;
    int wanted = 0;
    for (size_t k = 0; k < sizeof k_prox / sizeof k_prox[0]; ++k) wanted |= mix_wanted(o, fam, k_prox[k].name);
    int (*peers[])(const mix_method **) = {bench_mix_fcl_methods, bench_mix_coal_methods, bench_mix_bullet_methods,
                                           bench_mix_ccd_methods};
    for (size_t p = 0; p < sizeof peers / sizeof peers[0]; ++p) {
        const mix_method *list;
        int n = peers[p](&list);
        for (int k = 0; k < n; ++k) wanted |= mix_wanted(o, fam, list[k].name);
    }
    if (!wanted) return;
    mix_set *s = bench_xmalloc(sizeof *s);
    if (!mix_build(o, ka, kb, seed, s)) {
        fprintf(stderr, "prox_bench: mix/%s skipped: the library does not answer this pair type\n", fam);
        return;
    }
    for (size_t k = 0; k < sizeof k_prox / sizeof k_prox[0]; ++k) mix_register(o, fam, &k_prox[k], s, 1);
    for (size_t p = 0; p < sizeof peers / sizeof peers[0]; ++p) {
        const mix_method *list;
        int n = peers[p](&list);
        for (int k = 0; k < n; ++k) mix_register(o, fam, &list[k], s, 0);
    }
}

void bench_group_mix(const bench_opts *o)
{
    if (!bench_selected(o, "mix/")) return;
    static const struct {
        prox_shape_kind a, b;
    } fams[] = {{PROX_SHAPE_SPH, PROX_SHAPE_SPH}, {PROX_SHAPE_RCC, PROX_SHAPE_SPH}, {PROX_SHAPE_BOX, PROX_SHAPE_SPH},
                {PROX_SHAPE_BOX, PROX_SHAPE_BOX}, {PROX_SHAPE_BOX, PROX_SHAPE_RCC}, {PROX_SHAPE_RCC, PROX_SHAPE_RCC},
                {PROX_SHAPE_TRC, PROX_SHAPE_RCC}, {PROX_SHAPE_TRC, PROX_SHAPE_SPH}, {PROX_SHAPE_ELL, PROX_SHAPE_ELL},
                {PROX_SHAPE_ELL, PROX_SHAPE_BOX}, {PROX_SHAPE_REC, PROX_SHAPE_RCC}, {PROX_SHAPE_RHP, PROX_SHAPE_RHP},
                {PROX_SHAPE_WED, PROX_SHAPE_BOX}, {PROX_SHAPE_ARB, PROX_SHAPE_ARB}, {PROX_SHAPE_ARB, PROX_SHAPE_RCC}};
    for (size_t k = 0; k < sizeof fams / sizeof fams[0]; ++k) mix_family(o, fams[k].a, fams[k].b, 100 + k);
}

#ifndef PROX_BENCH_PEERS
int bench_mix_fcl_methods(const mix_method **out) { *out = NULL; return 0; }
int bench_mix_bullet_methods(const mix_method **out) { *out = NULL; return 0; }
int bench_mix_ccd_methods(const mix_method **out) { *out = NULL; return 0; }
#endif
#ifndef PROX_BENCH_COAL
int bench_mix_coal_methods(const mix_method **out) { *out = NULL; return 0; }
#endif

#else
void bench_group_mix(const bench_opts *o) { (void)o; }
#endif
