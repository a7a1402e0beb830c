/* The generic entry point: one set of queries for any pair of macrobodies (RCC, BOX, RPP, SPH),
 * dispatching to the specialised pair solvers; an RPP is answered as the BOX it describes, and a pair
 * whose solver is written the other way round is swapped and its answer mirrored (p1 <-> p2, normal
 * negated). The relation and the repositioning of the TRX report (LA-UR-13-26757, Sec. 4: "a
 * prescription to reposition an object that is determined to collide") are built on the signed
 * distance: moving B by (margin - sd) along the signed-distance normal leaves the supporting planes at
 * the witnesses exactly `margin` apart, so dist(A, B') = margin. */
#include "distance/box_internal.h"
#include "query/query_internal.h"
#include "prox/distance.h"
#include "prox/sat.h"
#include "prox/support.h"

#include <float.h>
#include <stddef.h>

/* Kind after RPP -> BOX, and the box itself. */
typedef struct norm_shape {
    prox_shape_kind kind; /* RCC, BOX or SPH */
    prox_box box;
    const prox_shape *s;
} norm_shape;

static prox_status normalise(const prox_shape *s, norm_shape *n)
{
    prox_status st = prox_shape_validate(s);
    if (st != PROX_OK) return st;
    n->s = s;
    n->kind = s->kind == PROX_SHAPE_RPP ? PROX_SHAPE_BOX : s->kind;
    if (s->kind == PROX_SHAPE_RPP) n->box = prox_rpp_to_box(&s->u.rpp);
    else if (s->kind == PROX_SHAPE_BOX) n->box = s->u.box;
    return PROX_OK;
}

static prox_status normalise2(const prox_shape *a, const prox_shape *b, norm_shape *na, norm_shape *nb)
{
    prox_status st = normalise(a, na);
    return st != PROX_OK ? st : normalise(b, nb);
}

/* Order of kinds for the canonical pair: BOX < RCC < SPH (the solvers take them in that order). */
static int rank(prox_shape_kind k) { return k == PROX_SHAPE_BOX ? 0 : (k == PROX_SHAPE_RCC ? 1 : 2); }

static prox_distance_result mirror_d(prox_distance_result r)
{
    prox_vec3 t = r.p1;
    r.p1 = r.p2;
    r.p2 = t;
    return r;
}

static prox_signed_result mirror_s(prox_signed_result r)
{
    prox_vec3 t = r.p1;
    r.p1 = r.p2;
    r.p2 = t;
    r.normal = prox_v3_neg(r.normal);
    return r;
}

/* RCC-RCC distance by the default method (prox_rcc_distance: prediction and certificate, the
 * closed-form method when that cannot certify). The cylinder-pair details (Agarwal's case, feature
 * pair) are left out, as for every other shape pair; the certificate and the method are kept. */
static prox_distance_result rcc_rcc_distance(const prox_rcc *a, const prox_rcc *b)
{
    prox_distance_result r = {0};
    prox_distance_result e = prox_rcc_distance(a, b);
    r.status = e.status;
    if (r.status != PROX_OK) return r;
    r.intersect = e.intersect;
    r.distance = e.distance;
    r.p1 = e.p1;
    r.p2 = e.p2;
    r.certificate_gap = e.intersect ? 0.0 : e.certificate_gap;
    r.certified = e.certified;
    r.method = e.method;
    return r;
}

/* Canonical-order distance (rank(a) <= rank(b)). */
static prox_distance_result dist_canon(const norm_shape *a, const norm_shape *b)
{
    const prox_shape *sa = a->s, *sb = b->s;
    switch (a->kind * 4 + b->kind) {
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_BOX: return prox_box_box_distance(&a->box, &b->box);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_RCC: return prox_box_rcc_distance(&a->box, &sb->u.rcc);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_SPH: return prox_box_sph_distance(&a->box, &sb->u.sph);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_RCC: return rcc_rcc_distance(&sa->u.rcc, &sb->u.rcc);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_SPH: return prox_rcc_sph_distance(&sa->u.rcc, &sb->u.sph);
    default: return prox_sph_sph_distance(&sa->u.sph, &sb->u.sph);
    }
}

static prox_signed_result signed_canon(const norm_shape *a, const norm_shape *b)
{
    const prox_shape *sa = a->s, *sb = b->s;
    switch (a->kind * 4 + b->kind) {
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_BOX: return prox_box_box_signed_distance(&a->box, &b->box);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_RCC: return prox_box_rcc_signed_distance(&a->box, &sb->u.rcc);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_SPH: return prox_box_sph_signed_distance(&a->box, &sb->u.sph);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_RCC: return prox_rcc_signed_distance(&sa->u.rcc, &sb->u.rcc);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_SPH: return prox_rcc_sph_signed_distance(&sa->u.rcc, &sb->u.sph);
    default: return prox_sph_sph_signed_distance(&sa->u.sph, &sb->u.sph);
    }
}

PROX_API double prox_shape_pair_scale(const prox_shape *a, const prox_shape *b)
{
    if (prox_shape_validate(a) != PROX_OK || prox_shape_validate(b) != PROX_OK) return 0.0;
    double s = prox_v3_dist(prox_shape_center(a), prox_shape_center(b));
    return fmax(s, fmax(prox_shape_size(a), prox_shape_size(b)));
}

PROX_API prox_distance_result prox_shape_distance(const prox_shape *a, const prox_shape *b)
{
    prox_distance_result r = {0};
    norm_shape na, nb;
    r.status = normalise2(a, b, &na, &nb);
    if (r.status != PROX_OK) return r;
    if (rank(na.kind) <= rank(nb.kind)) return dist_canon(&na, &nb);
    return mirror_d(dist_canon(&nb, &na));
}

PROX_API prox_signed_result prox_shape_signed_distance(const prox_shape *a, const prox_shape *b)
{
    prox_signed_result r = {0};
    norm_shape na, nb;
    r.status = normalise2(a, b, &na, &nb);
    if (r.status != PROX_OK) return r;
    if (rank(na.kind) <= rank(nb.kind)) return signed_canon(&na, &nb);
    return mirror_s(signed_canon(&nb, &na));
}

PROX_API prox_test_result prox_shape_test(const prox_shape *a, const prox_shape *b)
{
    prox_test_result r = {0};
    norm_shape na, nb;
    r.status = normalise2(a, b, &na, &nb);
    if (r.status != PROX_OK) return r;
    const norm_shape *x = &na, *y = &nb;
    if (rank(na.kind) > rank(nb.kind)) x = &nb, y = &na;
    if (x->kind == PROX_SHAPE_BOX && y->kind == PROX_SHAPE_BOX) return prox_box_box_test(&x->box, &y->box);
    if (x->kind == PROX_SHAPE_BOX && y->kind == PROX_SHAPE_RCC) return prox_box_rcc_test(&x->box, &y->s->u.rcc);
    if (x->kind == PROX_SHAPE_RCC && y->kind == PROX_SHAPE_RCC) { /* the certified SAT: ~6x cheaper */
        prox_test_result v = prox_rcc_sat(&x->s->u.rcc, &y->s->u.rcc);
        r.status = v.status;
        r.intersect = v.intersect;
        return r;
    }
    prox_distance_result d = dist_canon(x, y);
    r.status = d.status;
    r.intersect = d.intersect;
    return r;
}

PROX_API prox_contain_result prox_shape_contains(const prox_shape *a, const prox_shape *b)
{
    prox_contain_result r = {0};
    norm_shape na, nb;
    r.status = normalise2(a, b, &na, &nb);
    if (r.status != PROX_OK) return r;
    const prox_rcc *ra = &a->u.rcc, *rb = &b->u.rcc;
    const prox_sph *pa = &a->u.sph, *pb = &b->u.sph;
    switch (na.kind * 4 + nb.kind) {
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_BOX: return prox_box_in_box(&na.box, &nb.box);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_RCC: return prox_box_in_rcc(&na.box, rb);
    case PROX_SHAPE_BOX * 4 + PROX_SHAPE_SPH: return prox_box_in_sph(&na.box, pb);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_BOX: return prox_rcc_in_box(ra, &nb.box);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_RCC: return prox_rcc_in_rcc(ra, rb);
    case PROX_SHAPE_RCC * 4 + PROX_SHAPE_SPH: return prox_rcc_in_sph(ra, pb);
    case PROX_SHAPE_SPH * 4 + PROX_SHAPE_BOX: return prox_sph_in_box(pa, &nb.box);
    case PROX_SHAPE_SPH * 4 + PROX_SHAPE_RCC: return prox_sph_in_rcc(pa, rb);
    default: return prox_sph_in_sph(pa, pb);
    }
}

prox_relation_result prox_shape_relation_with_signed(const prox_shape *a, const prox_shape *b, double tol,
                                                     prox_signed_result *s_out)
{
    prox_relation_result r = {0};
    if (isnan(tol) || isinf(tol)) {
        r.status = PROX_EINVAL_ARG;
        return r;
    }
    prox_signed_result s = prox_shape_signed_distance(a, b);
    if (s_out) *s_out = s;
    r.status = s.status;
    if (r.status != PROX_OK) return r;
    r.tol = tol >= 0.0 ? tol : PROX_QUERY_REL_TOL * prox_shape_pair_scale(a, b);
    r.signed_distance = s.sd;
    if (s.sd > r.tol) {
        r.relation = PROX_REL_DISJOINT;
        return r;
    }
    /* Nested first: an inner solid touching the outer boundary from inside is nested (contact = 1), so
     * a pair is never both "touching" and nested; identical solids are A_IN_B. */
    prox_contain_result ab = prox_shape_contains(a, b), ba = prox_shape_contains(b, a);
    if (ab.clearance >= -r.tol) {
        r.relation = PROX_REL_A_IN_B;
        r.clearance = ab.clearance;
        r.contact = ab.clearance <= r.tol;
    } else if (ba.clearance >= -r.tol) {
        r.relation = PROX_REL_B_IN_A;
        r.clearance = ba.clearance;
        r.contact = ba.clearance <= r.tol;
    } else {
        r.relation = s.sd >= -r.tol ? PROX_REL_TOUCHING : PROX_REL_CROSSING;
        r.contact = 1;
    }
    return r;
}

PROX_API prox_relation_result prox_shape_relation(const prox_shape *a, const prox_shape *b, double tol)
{
    return prox_shape_relation_with_signed(a, b, tol, NULL);
}

static prox_shape translate(const prox_shape *s, prox_vec3 t);

PROX_API prox_reposition_result prox_shape_reposition(const prox_shape *a, const prox_shape *b, double margin)
{
    prox_reposition_result r = {0};
    if (!(margin >= 0.0) || isinf(margin)) {
        r.status = PROX_EINVAL_ARG;
        return r;
    }
    prox_signed_result s = prox_shape_signed_distance(a, b);
    r.status = s.status;
    if (r.status != PROX_OK) return r;
    r.signed_distance = s.sd;
    r.normal = s.normal;
    if (s.sd >= margin) return r;
    r.moved = 1;
    r.translation = prox_v3_scale(s.normal, margin - s.sd);
    /* One correction, measured: the move is only as good as its direction.  A near-touching pair's
     * normal comes from witness points a tiny gap apart (accurate to 1e-12 x scale each), and a
     * move much longer than that gap along a direction off by alpha misses the margin by about
     * length x alpha^2 / 2 (1.6e-11 x scale seen); the depth of an overlapping box-cylinder pair
     * comes from a multi-start search (docs/algorithms/sat.md 2 (f)).  After the move the pair is
     * about margin apart, where its witness direction is accurate, and moving B along it changes
     * the distance by exactly the step. */
    prox_shape b2 = translate(b, r.translation);
    prox_distance_result d = prox_shape_distance(a, &b2);
    double tol = 4.0 * DBL_EPSILON * prox_shape_pair_scale(a, &b2);
    if (d.status == PROX_OK && d.distance > 0.0 && fabs(d.distance - margin) > tol) {
        prox_vec3 n2 = prox_v3_scale(prox_v3_sub(d.p2, d.p1), 1.0 / d.distance);
        r.translation = prox_v3_mad(r.translation, margin - d.distance, n2);
        r.normal = prox_v3_normalize(r.translation);
    }
    return r;
}

/* s moved by t, by kind (no validation). */
static prox_shape translate(const prox_shape *s, prox_vec3 t)
{
    prox_shape o = *s;
    switch (s->kind) {
    case PROX_SHAPE_RCC: o.u.rcc.base = prox_v3_add(o.u.rcc.base, t); break;
    case PROX_SHAPE_BOX: o.u.box.corner = prox_v3_add(o.u.box.corner, t); break;
    case PROX_SHAPE_SPH: o.u.sph.center = prox_v3_add(o.u.sph.center, t); break;
    case PROX_SHAPE_RPP:
        o.u.rpp.xmin += t.x, o.u.rpp.xmax += t.x;
        o.u.rpp.ymin += t.y, o.u.rpp.ymax += t.y;
        o.u.rpp.zmin += t.z, o.u.rpp.zmax += t.z;
        break;
    }
    return o;
}

PROX_API prox_status prox_shape_translated(const prox_shape *s, prox_vec3 t, prox_shape *out)
{
    if (!s || !out) return PROX_EINVAL_ARG;
    if (!prox_v3_isfinite(t)) return PROX_EINVAL_NONFINITE;
    prox_shape o = translate(s, t);
    prox_status st = prox_shape_validate(&o);
    if (st == PROX_OK) *out = o;
    return st;
}
