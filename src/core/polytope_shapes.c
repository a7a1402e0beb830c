/* Validators of the polytope macrobodies RHP/HEX, WED and ARB, and the 9-entry RHP card form.
 * Card definitions: MCNP manual, macrobody surface cards (docs/algorithms/polytopes.md). */
#include <math.h>

#include "core/polytope.h"
#include "core/tol.h"
#include "prox/shapes.h"

static int coord_ok(double x) { return fabs(x) <= PROX_MAX_COORD; }
static int coord3_ok(prox_vec3 v) { return coord_ok(v.x) & coord_ok(v.y) & coord_ok(v.z); }
static int size_ok(double s) { return (s >= PROX_MIN_SIZE) & (s <= PROX_MAX_COORD); }

/* Finite (else NONFINITE) and within the coordinate range (else RANGE). */
static prox_status vec_ok(prox_vec3 v)
{
    if (!prox_v3_isfinite(v)) return PROX_EINVAL_NONFINITE;
    return coord3_ok(v) ? PROX_OK : PROX_EINVAL_RANGE;
}

/* |cos| of the angle between two non-zero vectors, on unit vectors so that nothing overflows. */
static double abs_cos(prox_vec3 a, prox_vec3 b)
{
    return fabs(prox_v3_dot(prox_v3_normalize(a), prox_v3_normalize(b)));
}

/* A non-zero vector inside the size range: 0 when fine, else the status. */
static prox_status size_vec(prox_vec3 v, prox_status zero)
{
    double l = prox_v3_norm(v);
    if (!(l > 0.0)) return zero;
    return size_ok(l) ? PROX_OK : PROX_EINVAL_RANGE;
}

/* The six side lines of the cross-section bound a convex hexagon with six sides of positive length:
 * consecutive normals (by angle) turn by less than pi, and each corner lies strictly inside the
 * four other side lines (by PROX_TOL_POLY_DEGEN x the hexagon's size). */
static int hexagon_ok(const prox_rhp_section *hx)
{
    const double(*nl)[2] = hx->nl, *dl = hx->dl, (*x)[2] = hx->x;
    double scale = fmax(dl[0], fmax(dl[2], dl[4]));
    for (int k = 0; k < 6; ++k) {
        if (!(hx->det[k] > PROX_TOL_POLY_DEGEN)) return 0;
        if (!isfinite(x[k][0]) || !isfinite(x[k][1])) return 0;
    }
    for (int k = 0; k < 6; ++k)
        for (int m = 0; m < 6; ++m) {
            if (m == k || m == (k + 1) % 6) continue;
            double s = nl[m][0] * x[k][0] + nl[m][1] * x[k][1] - dl[m];
            if (!(s < -PROX_TOL_POLY_DEGEN * scale)) return 0;
        }
    return 1;
}

/* Within the supported aspect ratio (shapes.h): the width across every face (the spread of the
 * corners along its normal) at least 1/PROX_MAX_ASPECT of the diameter; a flat plate or a needle
 * has a face across which it is thinner. */
static prox_status aspect_ok(const prox_polytope *p)
{
    for (int f = 0; f < p->nf; ++f) {
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < p->nv; ++i) { /* finite values: comparisons, not fmin/fmax calls */
            double t = prox_v3_dot(p->n[f], p->v[i]);
            lo = t < lo ? t : lo;
            hi = t > hi ? t : hi;
        }
        if (!((hi - lo) * PROX_MAX_ASPECT >= p->size)) return PROX_EINVAL_RANGE;
    }
    return PROX_OK;
}

/* rhp_card_ok's OK at the cost of a few products: every coordinate inside the range (which also
 * fails NaN and infinities), the squared lengths of the height and of r, s, t well inside the size
 * range, and each |cos(r_i, h)| <= PROX_BOX_ORTHO_TOL squared, with 2 % to spare for the rounding
 * of the squares (as box_plainly_valid). A card it does not accept goes to rhp_card_ok, which
 * names the fault or accepts it exactly as before. */
static int rhp_plainly_valid(const prox_rhp *h)
{
    int ok = coord3_ok(h->base) & coord3_ok(h->axis);
    double aa = prox_v3_norm2(h->axis);
    ok &= (aa >= 1e-140) & (aa <= 1e140);
    for (int i = 0; i < 3; ++i) {
        double rr = prox_v3_norm2(h->r[i]), c = prox_v3_dot(h->r[i], h->axis);
        ok &= coord3_ok(h->r[i]) & (rr >= 1e-140) & (rr <= 1e140);
        ok &= c * c <= 0.98 * PROX_BOX_ORTHO_TOL * PROX_BOX_ORTHO_TOL * rr * aa;
    }
    return ok;
}

/* aspect_ok's OK for the prism of an RHP (m = 6) or a WED (m = 3) from one corner pair per face:
 * a corner of the face and one across it. Across side k of the hexagon that is the first corner of
 * side k + 3 (the parallel side: the sides are sorted by angle, so +r and -r lie three apart); across
 * side k of the triangle the third corner, k + 2; across the top the first corner of the base and
 * back. Their spread t_a - t_b, with the same products aspect_ok forms, is at most its hi - lo
 * (rounding is monotone), so passing here passes there; failing sends the prism to aspect_ok. */
static int prism_aspect_plainly_ok(const prox_polytope *p, int m)
{
    int ok = 1;
    for (int f = 0; f < m + 2; ++f) {
        int b = f < m ? (m == 6 ? p->fv[(f + 3) % 6][0] : (f + 2) % 3) : p->fv[2 * m + 1 - f][0];
        double ta = prox_v3_dot(p->n[f], p->v[p->fv[f][0]]), tb = prox_v3_dot(p->n[f], p->v[b]);
        ok &= (ta - tb) * PROX_MAX_ASPECT >= p->size;
    }
    return ok;
}

/* The checks of each card that need no polytope; prox_polytope_checked builds it once after them
 * (an RHP's hexagon test runs there, on the section the builder uses). */
static prox_status rhp_card_ok(const prox_rhp *h)
{
    prox_status s;
    if ((s = vec_ok(h->base)) || (s = vec_ok(h->axis))) return s;
    for (int i = 0; i < 3; ++i)
        if ((s = vec_ok(h->r[i]))) return s;
    if ((s = size_vec(h->axis, PROX_EINVAL_AXIS))) return s;
    for (int i = 0; i < 3; ++i) {
        if ((s = size_vec(h->r[i], PROX_EINVAL_RHP))) return s;
        if (abs_cos(h->r[i], h->axis) > PROX_BOX_ORTHO_TOL) return PROX_EINVAL_RHP;
    }
    return PROX_OK;
}

PROX_API prox_status prox_rhp_validate(const prox_rhp *h)
{
    if (!h) return PROX_EINVAL_ARG;
    prox_shape sh = prox_shape_from_rhp(*h);
    prox_polytope p;
    prox_vec3 c;
    return prox_polytope_checked(&sh, &p, &c);
}

PROX_API prox_status prox_rhp_regular(prox_vec3 base, prox_vec3 axis, prox_vec3 r, prox_rhp *out)
{
    if (!out) return PROX_EINVAL_ARG;
    prox_rhp h = {.base = base, .axis = axis, .r = {r, r, r}};
    if (prox_v3_isfinite(axis) && prox_v3_isfinite(r) && prox_v3_norm(axis) > 0.0) {
        /* s and t: r turned by 60 and 120 degrees about the height (right-handed). */
        prox_vec3 w = prox_v3_normalize(axis);
        prox_vec3 wr = prox_v3_cross(w, r);
        const double c = 0.5, sn = 0.86602540378443864676; /* cos 60, sin 60 */
        h.r[1] = prox_v3_add(prox_v3_scale(r, c), prox_v3_scale(wr, sn));
        h.r[2] = prox_v3_add(prox_v3_scale(r, -c), prox_v3_scale(wr, sn));
    }
    prox_status s = prox_rhp_validate(&h);
    *out = s == PROX_OK ? h : (prox_rhp){0};
    return s;
}

static prox_status wed_card_ok(const prox_wed *w)
{
    prox_status s;
    if ((s = vec_ok(w->vertex)) || (s = vec_ok(w->v1)) || (s = vec_ok(w->v2)) || (s = vec_ok(w->v3))) return s;
    if ((s = size_vec(w->v1, PROX_EINVAL_WED)) || (s = size_vec(w->v2, PROX_EINVAL_WED)) ||
        (s = size_vec(w->v3, PROX_EINVAL_WED)))
        return s;
    if (abs_cos(w->v3, w->v1) > PROX_BOX_ORTHO_TOL || abs_cos(w->v3, w->v2) > PROX_BOX_ORTHO_TOL)
        return PROX_EINVAL_WED;
    prox_vec3 c = prox_v3_cross(prox_v3_normalize(w->v1), prox_v3_normalize(w->v2));
    return prox_v3_norm(c) > PROX_TOL_POLY_DEGEN ? PROX_OK : PROX_EINVAL_WED;
}

/* wed_card_ok's OK at the cost of a few products: coordinates in range, squared lengths well inside
 * the size range, |cos(v3, v1)|, |cos(v3, v2)| <= PROX_BOX_ORTHO_TOL squared with 2 % to spare, and
 * |v1 x v2|^2 above (1.02 PROX_TOL_POLY_DEGEN)^2 |v1|^2 |v2|^2 (the sine of v1, v2 clear of the
 * tolerance by far more than its rounding). Anything else goes to wed_card_ok. */
static int wed_plainly_valid(const prox_wed *w)
{
    const double lo = 1e-140, hi = 1e140, ct = 0.98 * PROX_BOX_ORTHO_TOL * PROX_BOX_ORTHO_TOL;
    const double st = 1.0404 * PROX_TOL_POLY_DEGEN * PROX_TOL_POLY_DEGEN;
    double a = prox_v3_norm2(w->v1), b = prox_v3_norm2(w->v2), h = prox_v3_norm2(w->v3);
    double c1 = prox_v3_dot(w->v3, w->v1), c2 = prox_v3_dot(w->v3, w->v2);
    int ok = coord3_ok(w->vertex) & coord3_ok(w->v1) & coord3_ok(w->v2) & coord3_ok(w->v3);
    ok &= (a >= lo) & (a <= hi) & (b >= lo) & (b <= hi) & (h >= lo) & (h <= hi);
    ok &= (c1 * c1 <= ct * h * a) & (c2 * c2 <= ct * h * b);
    return ok && prox_v3_norm2(prox_v3_cross(w->v1, w->v2)) > st * a * b;
}

PROX_API prox_status prox_wed_validate(const prox_wed *w)
{
    if (!w) return PROX_EINVAL_ARG;
    prox_shape sh = prox_shape_from_wed(*w);
    prox_polytope p;
    prox_vec3 c;
    return prox_polytope_checked(&sh, &p, &c);
}

/* ---- ARB ---- */

/* Face entries: 0 (unused) or four digits, the first three naming corners 1-8 and the fourth a
 * corner or 0, all distinct; at least four faces. */
static prox_status arb_faces_ok(const prox_arb *a)
{
    int nf = 0;
    for (int f = 0; f < 6; ++f) {
        int x = a->face[f];
        if (x == 0) continue;
        if (x < 1000 || x > 9999) return PROX_EINVAL_ARB_FACE;
        int dig[4] = {x / 1000, x / 100 % 10, x / 10 % 10, x % 10}; /* x has four digits here */
        for (int i = 0; i < 4; ++i) {
            if (dig[i] > 8 || (i < 3 && dig[i] == 0)) return PROX_EINVAL_ARB_FACE;
            for (int j = 0; j < i; ++j)
                if (dig[i] != 0 && dig[i] == dig[j]) return PROX_EINVAL_ARB_FACE;
        }
        nf++;
    }
    return nf >= 4 ? PROX_OK : PROX_EINVAL_ARB_CONVEX;
}

/* A four-corner loop crosses itself (its corners are not named in order round the face): one pair
 * of opposite sides cross (the builder's test, core/polytope.c). */
static int loop_crossed(const prox_polytope *p, int f)
{
    if (p->fnv[f] != 4) return 0;
    prox_vec3 x[4], n = p->n[f];
    for (int i = 0; i < 4; ++i) x[i] = p->v[p->fv[f][i]];
    return prox_sides_cross(x[0], x[1], x[2], x[3], n) || prox_sides_cross(x[1], x[2], x[3], x[0], n);
}

/* Corners of each face turn the same way about its normal (a convex loop). */
static int loop_ok(const prox_polytope *p, int f)
{
    int m = p->fnv[f];
    for (int i = 0; i < m; ++i) {
        int j = i + 1 < m ? i + 1 : 0, k = j + 1 < m ? j + 1 : 0;
        prox_vec3 a = p->v[p->fv[f][i]], b = p->v[p->fv[f][j]], c = p->v[p->fv[f][k]];
        prox_vec3 t = prox_v3_cross(prox_v3_sub(b, a), prox_v3_sub(c, b));
        if (!(prox_v3_dot(t, p->n[f]) > 0.0)) return 0;
    }
    return 1;
}

/* Shape of the built polytope: distinct corners, non-degenerate planar faces in order, a closed
 * surface (every edge shared by two faces, V - E + F = 2), and every corner behind every face plane
 * with some corner strictly behind each (a convex solid). */
static prox_status arb_solid_ok(const prox_polytope *p)
{
    double S = p->size, tol = PROX_TOL_POLY_DEGEN * S;
    if (!(S > 0.0)) return PROX_EINVAL_ARB_CONVEX;
    for (int i = 0; i < p->nv; ++i)
        for (int j = i + 1; j < p->nv; ++j)
            if (!(prox_v3_dist(p->v[i], p->v[j]) > tol)) return PROX_EINVAL_ARB_FACE;
    for (int f = 0; f < p->nf; ++f) {
        /* the builder puts a four-corner loop in order round its face (prox_arb_face_loop); one
         * still crossing there is a face its corners do not make (or has a zero normal); one in
         * order that turns both ways (or with three corners in a line) is a dent */
        if (!(prox_v3_norm(p->n[f]) > 0.5) || loop_crossed(p, f)) return PROX_EINVAL_ARB_FACE;
        if (!loop_ok(p, f)) return PROX_EINVAL_ARB_CONVEX;
        for (int i = 0; i < p->fnv[f]; ++i)
            if (fabs(prox_v3_dot(p->n[f], p->v[p->fv[f][i]]) - p->d[f]) > PROX_TOL_ARB_PLANAR * S)
                return PROX_EINVAL_ARB_PLANAR;
    }
    if (p->ne < 0 || p->nv - p->ne + p->nf != 2) return PROX_EINVAL_ARB_CONVEX;
    for (int f = 0; f < p->nf; ++f) {
        double deepest = 0.0;
        for (int i = 0; i < p->nv; ++i) {
            double s = prox_v3_dot(p->n[f], p->v[i]) - p->d[f];
            if (s > PROX_TOL_ARB_PLANAR * S) return PROX_EINVAL_ARB_CONVEX;
            deepest = fmin(deepest, s);
        }
        if (!(deepest < -tol)) return PROX_EINVAL_ARB_CONVEX;
    }
    return PROX_OK;
}

/* arb_solid_ok's, size_ok's and aspect_ok's OK in one pass. Every corner's product n_f . v_i is
 * formed once per face, with the same expressions as those checks (planarity, every corner behind
 * the plane, one strictly behind, the width across the face), so those verdicts are theirs. Two
 * tests are replaced by stricter ones: the corners' least squared distance m2 (from the build)
 * above 1.01 tol^2, both far from under- and overflow, so that |v_i - v_j| > tol follows; and every
 * turn of every face loop above 1e-9 S^2 about its normal, far beyond the rounding of those turns:
 * then the loop is convex (loop_ok) and no pair of its opposite sides can cross (loop_crossed's
 * orientations are these turns). Each face plane must also stand 1e-6 S clear of the centroid (the reference point), far
 * beyond rounding: the builder's quick choice of each loop's direction (by its first three corners)
 * is then the one its Newell normal makes, so the polytope is prox_polytope_make's. Any failure
 * sends the card to a rebuild and the ordered checks, which name the fault. */
static int arb_plainly_ok(const prox_polytope *p, double m2)
{
    double S = p->size, tol = PROX_TOL_POLY_DEGEN * S, ptol = PROX_TOL_ARB_PLANAR * S;
    if (!(S > 0.0) || !size_ok(S) || p->ne < 0 || p->nv - p->ne + p->nf != 2) return 0;
    double tt = tol * tol, turn = 1e-9 * S * S;
    if (!(tt > 1e-290) || !(m2 > 1.01 * tt)) return 0;
    for (int f = 0; f < p->nf; ++f) {
        prox_vec3 n = p->n[f];
        int m = p->fnv[f];
        /* |n| > 0.5 as norm2 > 0.3: a Newell normal is a unit vector or zero */
        if (!(prox_v3_norm2(n) > 0.3) || !(p->d[f] > 1e-6 * S)) return 0;
        unsigned on = 0;
        prox_vec3 e[PROX_POLY_MAXFV];
        for (int i = 0; i < m; ++i) {
            e[i] = prox_v3_sub(p->v[p->fv[f][i + 1 < m ? i + 1 : 0]], p->v[p->fv[f][i]]);
            on |= 1u << p->fv[f][i];
        }
        int ok = 1; /* every test of the face, then one branch */
        for (int i = 0; i < m; ++i)
            ok &= prox_v3_dot(prox_v3_cross(e[i], e[i + 1 < m ? i + 1 : 0]), n) > turn;
        /* extremes instead of a test per corner (the values are finite: exact, order-free) */
        double lo = INFINITY, hi = -INFINITY, deepest = 0.0, front = -INFINITY, off = 0.0;
        for (int i = 0; i < p->nv; ++i) {
            double t = prox_v3_dot(n, p->v[i]), s = t - p->d[f], a = ((on >> i) & 1u) ? fabs(s) : 0.0;
            deepest = s < deepest ? s : deepest;
            front = s > front ? s : front;
            off = a > off ? a : off;
            lo = t < lo ? t : lo;
            hi = t > hi ? t : hi;
        }
        ok &= (front <= ptol) & (off <= ptol);
        if (!ok || !(deepest < -tol) || !((hi - lo) * PROX_MAX_ASPECT >= S)) return 0;
    }
    return 1;
}

static prox_status arb_card_ok(const prox_arb *a)
{
    prox_status s;
    for (int i = 0; i < 8; ++i)
        if (!prox_v3_isfinite(a->corner[i])) return PROX_EINVAL_NONFINITE;
    for (int i = 0; i < 8; ++i)
        if ((s = vec_ok(a->corner[i]))) return s;
    return arb_faces_ok(a);
}

PROX_API prox_status prox_arb_validate(const prox_arb *a)
{
    if (!a) return PROX_EINVAL_ARG;
    prox_shape sh = prox_shape_from_arb(*a);
    prox_polytope p;
    prox_vec3 c;
    return prox_polytope_checked(&sh, &p, &c);
}

/* The fast path: the "plainly valid" tests above, each of which passes only where the ordered checks
 * pass, so that their OK stands for the checks' OK; the polytope is the one the checks build. */
int prox_polytope_fast(const prox_shape *s, prox_polytope *p, prox_vec3 *c)
{
    if (s->kind == PROX_SHAPE_RHP) {
        const prox_rhp *h = &s->u.rhp;
        if (!rhp_plainly_valid(h)) return 0;
        prox_rhp_section hx;
        prox_rhp_hexagon(h, &hx);
        if (!hexagon_ok(&hx)) return 0;
        *c = prox_polytope_rhp(h, &hx, p);
        return prism_aspect_plainly_ok(p, 6);
    }
    if (s->kind == PROX_SHAPE_WED) {
        if (!wed_plainly_valid(&s->u.wed)) return 0;
        *c = prox_polytope_make(s, p);
        return prism_aspect_plainly_ok(p, 3);
    }
    if (s->kind == PROX_SHAPE_ARB) {
        double least;
        if (arb_card_ok(&s->u.arb) != PROX_OK) return 0;
        *c = prox_polytope_arb(&s->u.arb, p, &least, 1);
        return arb_plainly_ok(p, least);
    }
    return 0;
}

/* The ordered checks of every kind, each fault named, and the polytope built once for them. */
prox_status prox_polytope_checked_full(const prox_shape *s, prox_polytope *p, prox_vec3 *c)
{
    prox_status st;
    switch (s->kind) {
    case PROX_SHAPE_RHP: st = rhp_card_ok(&s->u.rhp); break;
    case PROX_SHAPE_WED: st = wed_card_ok(&s->u.wed); break;
    case PROX_SHAPE_ARB: st = arb_card_ok(&s->u.arb); break;
    case PROX_SHAPE_BOX: st = prox_box_validate(&s->u.box); break;
    case PROX_SHAPE_RPP: st = prox_rpp_validate(&s->u.rpp); break;
    default: return PROX_EINVAL_SHAPE_KIND;
    }
    if (st != PROX_OK) return st;
    if (s->kind == PROX_SHAPE_RHP) { /* the hexagon computed once for its test and the build */
        prox_rhp_section hx;
        prox_rhp_hexagon(&s->u.rhp, &hx);
        if (!hexagon_ok(&hx)) return PROX_EINVAL_RHP;
        *c = prox_polytope_rhp(&s->u.rhp, &hx, p);
        return aspect_ok(p);
    }
    *c = prox_polytope_make(s, p);
    if (s->kind == PROX_SHAPE_BOX || s->kind == PROX_SHAPE_RPP) return PROX_OK;
    if (s->kind == PROX_SHAPE_ARB) {
        if ((st = arb_solid_ok(p))) return st;
        if (!size_ok(p->size)) return PROX_EINVAL_RANGE;
    }
    return aspect_ok(p);
}

prox_status prox_polytope_checked(const prox_shape *s, prox_polytope *p, prox_vec3 *c)
{
    return prox_polytope_fast(s, p, c) ? PROX_OK : prox_polytope_checked_full(s, p, c);
}
