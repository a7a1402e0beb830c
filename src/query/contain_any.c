/* Containment of any macrobody A in any macrobody B: the clearance
 *   c(A, B) = min over A of the distance to B's boundary = -max over A of sd_B,
 * sd_B the signed distance to B (convex and 1-Lipschitz because B is convex), so that A lies in B iff
 * c >= 0, and c is exact whenever A is inside. When A sticks out, c < 0 and -c is at most how far:
 * exactly that on paths 1, 3, 4 and 6, the face-plane or slab and lateral excess (which can be less
 * near an edge) on paths 2 and 5. Because sd_B is convex, its maximum over A is attained at an
 * extreme point of A (corners, rims, a sphere's or ellipsoid's surface); and for any convex set,
 * sd_B(x) = max over unit n of n.x - h_B(n), so max over A of sd_B = max over n of h_A(n) - h_B(n).
 * Cheapest exact path first (docs/algorithms/dispatch.md):
 *  1. A a sphere: c = -sd_B(centre) - r (the ball about the centre of radius -sd_B fits exactly).
 *  2. B a polytope {n_f . x <= d_f}: the support function of A gives every face exactly,
 *     c = min_f (d_f - h_A(n_f)) (inside a convex polytope the distance to the boundary is the least
 *     distance to a face plane).
 *  3. A a polytope: its corners, c = -max_i sd_B(v_i).
 *  4. B a sphere: c = R - (the farthest point of A from the centre): rims of RCC and TRC in closed
 *     form, elliptical rims of REC and the meridian ellipse of ELL by the secular equation of the
 *     farthest point of an ellipse (Eberly, "Distance from a point to an ellipse", the same Lagrange
 *     condition with the multiplier beyond the largest semi-axis squared).
 *  5. B an RCC, TRC or REC: B is the intersection of its slab and of its infinite lateral solid L,
 *     and for x in B, sd_B(x) = max(slab, sd_L(x)) (a ball lies in an intersection iff it lies in
 *     each). The slab is exact by h_A(+-w). L's outward normals are a one-parameter family (the angle
 *     phi about B's axis), so max over A of sd_L = max over phi of G(phi) = h_A(n(phi)) - h_L(n(phi)):
 *     for an RCC the distance from the axis, whose maximum over A is in closed form
 *     (rcc_lateral_clearance); for TRC and REC a branch-and-bound with a second-order bound
 *     (lateral_smooth, a_pieces).
 *  6. B an ELL: max over unit n of h_A(n) - h_B(n), a branch-and-bound over the sphere of normals
 *     with the same second-order bound (ell_clearance).
 * The searches certify the clearance to PROX_TOL_CONTAIN_BB x scale (1e-12). */
#include "core/body.h"
#include "core/tol.h"
#include "query/query_internal.h"

static int kind_poly(prox_shape_kind k)
{
    return k == PROX_SHAPE_BOX || k == PROX_SHAPE_RPP || k == PROX_SHAPE_RHP || k == PROX_SHAPE_WED ||
           k == PROX_SHAPE_ARB;
}

/* 2. B a polytope: min over its faces of d_f - h_A(n_f), relative to B's reference point. */
static double faces_clearance(const prox_body *A, const prox_body *B)
{
    prox_vec3 dc = prox_v3_sub(A->c, B->c);
    double c = INFINITY;
    if (B->kind == PROX_BODY_BOX) {
        for (int k = 0; k < 6; ++k) {
            prox_vec3 n = k < 3 ? B->box.a[k] : prox_v3_neg(B->box.a[k - 3]);
            c = fmin(c, B->box.h[k % 3] - (prox_v3_dot(n, dc) + prox_body_hc(A, n)));
        }
        return c;
    }
    for (int f = 0; f < B->x.poly.nf; ++f) {
        prox_vec3 n = B->x.poly.n[f];
        c = fmin(c, B->x.poly.d[f] - (prox_v3_dot(n, dc) + prox_body_hc(A, n)));
    }
    return c;
}

/* 3. A a polytope: -max over its corners of sd_B. */
static double corners_clearance(const prox_body *A, const prox_body *B)
{
    double c = INFINITY;
    prox_vec3 q;
    int nv = A->kind == PROX_BODY_BOX ? 8 : A->x.poly.nv;
    for (int i = 0; i < nv; ++i) {
        prox_vec3 v = A->kind == PROX_BODY_BOX ? prox_bframe_vertex(&A->box, i) : A->x.poly.v[i];
        c = fmin(c, -prox_body_boundary(B, prox_v3_add(A->c, v), &q));
    }
    return c;
}

/* Largest distance from (y0, y1) to the ellipse (x0/e0)^2 + (x1/e1)^2 = 1. With e0 >= e1 the
 * farthest point is x_i = e_i^2 y_i / (e_i^2 - lambda), lambda = e0^2 + s, s > 0 the root of the
 * decreasing convex F(s) = (e0 y0 / s)^2 + (e1 y1 / (s + delta))^2 - 1, delta = e0^2 - e1^2, in
 * (0, e0 |y|] (F <= 0 there); y0 = 0 with F(0) <= 0 is the degenerate case lambda = e0^2. */
static double ellipse_farthest(double e0, double e1, double y0, double y1)
{
    if (e0 < e1) {
        double t = e0;
        e0 = e1, e1 = t, t = y0, y0 = y1, y1 = t;
    }
    double ny = hypot(y0, y1);
    if (e0 == e1 || !(ny > 0.0)) return ny + e0;
    double delta = (e0 - e1) * (e0 + e1), x0, x1;
    if (y0 == 0.0 && e1 * fabs(y1) <= delta) {
        x1 = -e1 * e1 * y1 / delta;
        x0 = e0 * sqrt(fmax(0.0, 1.0 - (x1 / e1) * (x1 / e1)));
        return hypot(x0 - y0, x1 - y1);
    }
    /* Newton on the convex decreasing F, safeguarded by the bracket [lo, hi] (a bisection step, in
     * the geometric mean while lo = 0, whenever Newton leaves it) */
    double lo = 0.0, hi = e0 * ny, s = hi, A = e0 * y0, B = e1 * y1;
    for (int it = 0; it < 200; ++it) {
        double p = A / s, q = B / (s + delta), F = p * p + q * q - 1.0;
        if (F > 0.0) lo = s;
        else hi = s;
        double dF = -2.0 * (p * p / s + q * q / (s + delta)), next = s - F / dF;
        if (!(next > lo && next < hi)) next = lo > 0.0 ? 0.5 * (lo + hi) : 1e-3 * hi;
        if (fabs(next - s) <= 1e-16 * s || hi - lo <= 1e-16 * hi) {
            s = next;
            break;
        }
        s = next;
    }
    x0 = -e0 * e0 * y0 / s;
    x1 = -e1 * e1 * y1 / (s + delta);
    return hypot(x0 - y0, x1 - y1);
}

/* 4. B a sphere (centre o, radius R) and A curved: R - the farthest point of A from o. */
static double in_sphere_clearance(const prox_body *A, prox_vec3 o, double R)
{
    prox_vec3 d = prox_v3_sub(o, A->c);
    double far = 0.0;
    if (A->kind == PROX_BODY_ELL) { /* the meridian ellipse through o */
        double t = prox_v3_dot(d, A->x.ell.w), rho = prox_v3_norm(prox_v3_reject(d, A->x.ell.w));
        return R - ellipse_farthest(A->x.ell.a, A->x.ell.b, t, rho);
    }
    prox_vec3 w = A->kind == PROX_BODY_CYL ? A->cyl.w : (A->kind == PROX_BODY_CONE ? A->x.cone.w : A->x.ecyl.w);
    double hh = A->kind == PROX_BODY_CYL ? A->cyl.hh : (A->kind == PROX_BODY_CONE ? A->x.cone.hh : A->x.ecyl.hh);
    for (int end = 0; end < 2; ++end) { /* the rims at -hh (base) and +hh (top) */
        prox_vec3 e = prox_v3_mad(d, end ? -hh : hh, w);
        double ax = prox_v3_dot(e, w);
        if (A->kind == PROX_BODY_ECYL) {
            double p = ellipse_farthest(A->x.ecyl.a1, A->x.ecyl.a2, prox_v3_dot(e, A->x.ecyl.u1),
                                        prox_v3_dot(e, A->x.ecyl.u2));
            far = fmax(far, hypot(ax, p));
            continue;
        }
        double r = A->kind == PROX_BODY_CYL ? A->cyl.r : (end ? A->x.cone.r2 : A->x.cone.r1);
        far = fmax(far, hypot(ax, prox_v3_norm(prox_v3_reject(e, w)) + r));
    }
    return R - far;
}

/* ---- second-order bounds of a curved A's support function ----
 * A lies in the ball of radius R tangent at its support point p(n0) (inner normal -n0), so
 * h_A(n) <= n.p(n0) + R (1 - n.n0) for every unit n. An ELL has one such ball, R its largest radius of
 * curvature max(a, b)^2 / min(a, b) (Blaschke's rolling theorem). RCC, TRC and REC are the hulls of
 * their rims, h_A = max over the rims of h_rim, and a plane ellipse of semi-axes a1 >= a2 (a circle:
 * a1 = a2 = r) lies in the ball tangent at its support point of radius (a1^2 / a2) / |P n0|, P the
 * projection onto its plane: the 2D disk of radius a1^2 / a2 tangent at that point holds it, and
 * leaning the ball out of the plane by the angle of n0 scales the radius by 1 / |P n0|. A zero rim
 * radius (a TRC's apex) is a point, R = 0; n0 along the rims' normal gives R = infinity (the cell is
 * cut further). Returns the number of pieces (1 or 2): support points relative to A's centre in p[],
 * radii in R[]. */
static int a_pieces(const prox_body *A, prox_vec3 n, prox_vec3 *p, double *R)
{
    if (A->kind == PROX_BODY_ELL) {
        double a = A->x.ell.a, b = A->x.ell.b;
        p[0] = prox_body_pc(A, n);
        R[0] = fmax(a, b) * (fmax(a, b) / fmin(a, b));
        return 1;
    }
    int cyl = A->kind == PROX_BODY_CYL, ecyl = A->kind == PROX_BODY_ECYL;
    prox_vec3 w = cyl ? A->cyl.w : (ecyl ? A->x.ecyl.w : A->x.cone.w);
    double hh = cyl ? A->cyl.hh : (ecyl ? A->x.ecyl.hh : A->x.cone.hh);
    prox_vec3 pn = prox_v3_reject(n, w);
    pn = prox_v3_reject(pn, w);
    double lp = prox_v3_norm(pn);
    for (int end = 0; end < 2; ++end) {
        prox_vec3 cj = prox_v3_scale(w, end ? hh : -hh), x = prox_v3(0, 0, 0);
        double rmax, rmin;
        if (ecyl) {
            const prox_ecyl *k = &A->x.ecyl;
            double d1 = k->a1 * prox_v3_dot(n, k->u1), d2 = k->a2 * prox_v3_dot(n, k->u2), h = hypot(d1, d2);
            if (h > 0.0) x = prox_v3_mad(prox_v3_scale(k->u1, k->a1 * d1 / h), k->a2 * d2 / h, k->u2);
            rmax = fmax(k->a1, k->a2), rmin = fmin(k->a1, k->a2);
        } else {
            rmax = rmin = cyl ? A->cyl.r : (end ? A->x.cone.r2 : A->x.cone.r1);
            if (lp > 0.0) x = prox_v3_scale(pn, rmax / lp);
        }
        p[end] = prox_v3_add(cj, x);
        R[end] = rmax == 0.0 ? 0.0 : (lp > 0.0 ? rmax * (rmax / rmin) / lp : INFINITY);
    }
    return 2;
}

/* ---- 5. lateral part of an RCC, TRC or REC B: G(phi) = h_A(n(phi)) - h_L(n(phi)) ---- */
typedef struct lat_ctx {
    const prox_body *A;
    prox_vec3 dc;     /* A's reference point relative to B's centre */
    prox_vec3 e1, e2; /* orthonormal, across B's axis (REC: its major and minor directions) */
    prox_vec3 w;      /* B's unit axis */
    double k, s;      /* TRC: slope of the radius along w and sqrt(1 + k^2); 0 and 1 otherwise */
    double r;         /* RCC radius, TRC middle radius */
    double a1, a2;    /* REC semi-axes (0 otherwise) */
} lat_ctx;

static double lateral_smooth(const lat_ctx *c, double eps);

static double lateral_clearance(const prox_body *A, const prox_body *B, double eps)
{
    lat_ctx c = {A, prox_v3_sub(A->c, B->c), {0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0.0, 1.0, 0.0, 0.0, 0.0};
    if (B->kind == PROX_BODY_ECYL) {
        c.w = B->x.ecyl.w, c.e1 = B->x.ecyl.u1, c.e2 = B->x.ecyl.u2;
        c.a1 = B->x.ecyl.a1, c.a2 = B->x.ecyl.a2;
    } else {
        c.w = B->kind == PROX_BODY_CYL ? B->cyl.w : B->x.cone.w;
        c.e1 = prox_v3_any_perp(c.w);
        c.e2 = prox_v3_cross(c.w, c.e1);
        if (B->kind == PROX_BODY_CYL) c.r = B->cyl.r;
        else {
            c.k = (B->x.cone.r2 - B->x.cone.r1) / (2.0 * B->x.cone.hh);
            c.s = sqrt(1.0 + c.k * c.k);
            c.r = 0.5 * (B->x.cone.r1 + B->x.cone.r2);
        }
    }
    return -lateral_smooth(&c, eps);
}

/* The lateral family, bounded to second order as in ell_clearance: with
 * n0 = n(phi0), g = dc + p_A(n0) - p_L(n0) (p_L(n0) the point of L's supporting plane at n0 used by
 * lat_normal, so G(n0) = g.n0), G(n) <= n.g + R_A (1 - n.n0). The family n(phi) is a circle of radius
 * at most 1 on the sphere, so with D = phi - phi0, (n - n0).g <= (g.n'(phi0)) D + |g| D^2 / 2 and
 * 1 - n.n0 = |n - n0|^2 / 2 <= D^2 / 2:
 * G(n) <= G(n0) + |g.n'(phi0)| |D| + (|g| + R_A) D^2 / 2, quadratic at the maximum along the family
 * (where g.n' = dG/dphi vanishes). */
typedef struct lat_cell {
    double t, hw, v, bound;
} lat_cell;

/* The normal n(phi) of L and its support point relative to B's centre (*pl, with n.pl = h_L - n.cB). */
static prox_vec3 lat_normal(const lat_ctx *c, double phi, prox_vec3 *pl)
{
    double cp = cos(phi), sp = sin(phi);
    prox_vec3 u = prox_v3_mad(prox_v3_scale(c->e1, cp), sp, c->e2);
    if (c->a1 > 0.0) { /* REC: the cross-section's point of outward normal u */
        double h = hypot(c->a1 * cp, c->a2 * sp);
        *pl = prox_v3_mad(prox_v3_scale(c->e1, c->a1 * c->a1 * cp / h), c->a2 * c->a2 * sp / h, c->e2);
        return u;
    }
    *pl = prox_v3_scale(u, c->r); /* the generator's point at the centre's height */
    return c->k != 0.0 ? prox_v3_scale(prox_v3_mad(u, -c->k, c->w), 1.0 / c->s) : u;
}

static void lat_eval(const lat_ctx *c, lat_cell *x)
{
    prox_vec3 pl, n = lat_normal(c, x->t, &pl), p[2];
    double R[2];
    /* n'(phi): the turned u, scaled by 1 / s for the cone */
    prox_vec3 dn = prox_v3_scale(prox_v3_mad(prox_v3_scale(c->e1, -sin(x->t)), cos(x->t), c->e2), 1.0 / c->s);
    int m = a_pieces(c->A, n, p, R);
    x->v = x->bound = -INFINITY;
    for (int j = 0; j < m; ++j) {
        prox_vec3 g = prox_v3_sub(prox_v3_add(c->dc, p[j]), pl);
        double v = prox_v3_dot(n, g);
        x->v = fmax(x->v, v);
        x->bound = fmax(x->bound, v + fabs(prox_v3_dot(g, dn)) * x->hw + (prox_v3_norm(g) + R[j]) * 0.5 * x->hw * x->hw);
    }
}

/* max over phi of G for a curved A: the grid's local maxima polished first (a strong first value),
 * then the depth-first search with the second-order bound. */
static double lateral_smooth(const lat_ctx *c, double eps)
{
    enum { CAP = 512, M = 64 };
    lat_cell st[CAP];
    int n = 0;
    double best = -INFINITY;
    for (int i = 0; i < M; ++i) {
        lat_cell x = {(i + 0.5) * 2.0 * PROX_PI / M, PROX_PI / M, 0, 0};
        lat_eval(c, &x);
        best = fmax(best, x.v);
        st[n++] = x;
    }
    for (int i = 0; i < M; ++i) { /* local maxima of the grid, polished by halving steps */
        if (st[i].v < st[(i + 1) % M].v || st[i].v < st[(i + M - 1) % M].v) continue;
        lat_cell y = st[i];
        double h = st[i].hw;
        for (int it = 0; it < 400 && h > 1e-15; ++it) {
            lat_cell l = {y.t - h, 0, 0, 0}, r = {y.t + h, 0, 0, 0};
            lat_eval(c, &l);
            lat_eval(c, &r);
            if (l.v > y.v || r.v > y.v) y = l.v > r.v ? l : r;
            else h *= 0.5;
        }
        best = fmax(best, y.v);
    }
    long evals = n;
    while (n > 0) {
        lat_cell x = st[--n];
        if (x.bound <= best + eps) continue;
        if (n + 3 > CAP || evals > 200000) { /* out of budget: the open cells' bound stands */
            double up = x.bound;
            for (int i = 0; i < n; ++i) up = fmax(up, st[i].bound);
            return fmax(best, up - eps);
        }
        lat_cell ch[3];
        for (int m = 0; m < 3; ++m) {
            ch[m].hw = x.hw / 3.0;
            ch[m].t = x.t + (m - 1) * 2.0 * ch[m].hw;
            lat_eval(c, &ch[m]);
            best = fmax(best, ch[m].v);
        }
        evals += 3;
        for (int m = 0; m < 3; ++m) st[n++] = ch[m];
    }
    return best;
}

/* ---- 5'. B an RCC: the lateral part in closed form ----
 * The distance of a point from B's axis is its distance in B's cross-section plane, so the farthest
 * point of A from the axis is the farthest point from the axis of A's shadow along w: the hull of the
 * shadows of A's rims (ellipses), or the shadow of an ELL (an ellipse). Each shadow ellipse is put in
 * its principal axes (the 2 x 2 eigenproblem of its conjugate semi-axes) and its farthest point from
 * the axis found by ellipse_farthest. */

/* Largest distance from the origin of the plane ellipse c + al cos t + be sin t (2D vectors). */
static double shadow_farthest(const double c[2], const double al[2], const double be[2])
{
    double m00 = al[0] * al[0] + be[0] * be[0], m01 = al[0] * al[1] + be[0] * be[1], m11 = al[1] * al[1] + be[1] * be[1];
    double tr = 0.5 * (m00 + m11), df = 0.5 * (m00 - m11), rad = hypot(df, m01);
    double l1 = tr + rad, l2 = fmax(0.0, tr - rad);
    /* unit eigenvector of l1: (m01, l1 - m00) or (l1 - m11, m01), the better conditioned */
    double v0 = m01, v1 = l1 - m00;
    if (fabs(l1 - m11) + fabs(m01) > fabs(v0) + fabs(v1)) v0 = l1 - m11, v1 = m01;
    double vn = hypot(v0, v1);
    if (!(vn > 0.0)) v0 = 1.0, v1 = 0.0, vn = 1.0;
    v0 /= vn, v1 /= vn;
    /* the origin seen from the ellipse's centre, in its principal frame */
    double y0 = -(c[0] * v0 + c[1] * v1), y1 = -(-c[0] * v1 + c[1] * v0);
    return ellipse_farthest(sqrt(l1), sqrt(l2), y0, y1);
}

/* r - the farthest point of a curved A (RCC, TRC, REC, ELL) from the axis of the cylinder B. */
static double rcc_lateral_clearance(const prox_body *A, const prox_body *B)
{
    prox_vec3 w = B->cyl.w, e1 = prox_v3_any_perp(w), e2 = prox_v3_cross(w, e1), dc = prox_v3_sub(A->c, B->c);
    double far = 0.0;
    if (A->kind == PROX_BODY_ELL) {
        prox_vec3 wa = A->x.ell.w;
        double pw[2] = {prox_v3_dot(wa, e1), prox_v3_dot(wa, e2)}, pn = hypot(pw[0], pw[1]);
        double a = A->x.ell.a, b = A->x.ell.b, major = sqrt(b * b + (a - b) * (a + b) * pn * pn);
        double u[2] = {pn > 0.0 ? pw[0] / pn : 1.0, pn > 0.0 ? pw[1] / pn : 0.0};
        double c[2] = {prox_v3_dot(dc, e1), prox_v3_dot(dc, e2)};
        double al[2] = {major * u[0], major * u[1]}, be[2] = {-b * u[1], b * u[0]};
        return B->cyl.r - shadow_farthest(c, al, be);
    }
    prox_vec3 wa, u1, u2;
    double hh, ra[2], rb[2];
    if (A->kind == PROX_BODY_ECYL) {
        wa = A->x.ecyl.w, u1 = A->x.ecyl.u1, u2 = A->x.ecyl.u2, hh = A->x.ecyl.hh;
        ra[0] = ra[1] = A->x.ecyl.a1, rb[0] = rb[1] = A->x.ecyl.a2;
    } else { /* RCC, TRC: circular rims */
        int cyl = A->kind == PROX_BODY_CYL;
        wa = cyl ? A->cyl.w : A->x.cone.w, hh = cyl ? A->cyl.hh : A->x.cone.hh;
        u1 = prox_v3_any_perp(wa), u2 = prox_v3_cross(wa, u1);
        ra[0] = rb[0] = cyl ? A->cyl.r : A->x.cone.r1, ra[1] = rb[1] = cyl ? A->cyl.r : A->x.cone.r2;
    }
    for (int end = 0; end < 2; ++end) {
        prox_vec3 cj = prox_v3_mad(dc, end ? hh : -hh, wa);
        double c[2] = {prox_v3_dot(cj, e1), prox_v3_dot(cj, e2)};
        double al[2] = {ra[end] * prox_v3_dot(u1, e1), ra[end] * prox_v3_dot(u1, e2)};
        double be[2] = {rb[end] * prox_v3_dot(u2, e1), rb[end] * prox_v3_dot(u2, e2)};
        far = fmax(far, shadow_farthest(c, al, be));
    }
    return B->cyl.r - far;
}

/* The slab of B (half height hh about its centre along w): min of the two cap clearances. */
static double slab_clearance(const prox_body *A, const prox_body *B)
{
    prox_vec3 w = B->kind == PROX_BODY_CYL ? B->cyl.w : (B->kind == PROX_BODY_CONE ? B->x.cone.w : B->x.ecyl.w);
    double hh = B->kind == PROX_BODY_CYL ? B->cyl.hh : (B->kind == PROX_BODY_CONE ? B->x.cone.hh : B->x.ecyl.hh);
    double t = prox_v3_dot(prox_v3_sub(A->c, B->c), w);
    return fmin(hh - (t + prox_body_hc(A, w)), hh - (-t + prox_body_hc(A, prox_v3_neg(w))));
}

/* A curved A in an ELL B by the normals: max over unit n of G(n) = h_A(n) - h_B(n), relative to B's
 * centre, by branch-and-bound over cells of the sphere of normals (angles theta from B's axis and phi
 * about it) with a second-order bound. With g = p_A(n0) - p_B(n0) (the support points at the cell's
 * centre n0, so G(n0) = g.n0; for RCC, TRC and REC per rim) and delta >= |n - n0| over the cell:
 *  - h_A(n) <= n.p_A(n0) + R_A (1 - n.n0), R_A the radius of a_pieces;
 *  - h_B(n) >= n.p_B(n0) (p_B(n0) is a point of B);
 * hence G(n) <= G(n0) + |g_t| delta + (R_A - G(n0)) delta^2 / 2, g_t the part of g across n0
 * (1 - n.n0 = |n - n0|^2 / 2). The bound is quadratic at a smooth maximum, where g_t vanishes, so the
 * cells left open stay few down to PROX_TOL_CONTAIN_BB x scale. */
typedef struct ee_cell {
    double t[2], hw[2], v, bound;
} ee_cell;

typedef struct ee_ctx {
    const prox_body *A, *B;
    prox_vec3 dc, e1, e2, e3;
} ee_ctx;

/* G at the cell's centre and the cell's bound, over the pieces of A's support (a_pieces). */
static void ee_eval(const ee_ctx *c, ee_cell *x)
{
    double st = sin(x->t[0]), R[2];
    prox_vec3 n = prox_v3_mad(prox_v3_mad(prox_v3_scale(c->e3, cos(x->t[0])), st * cos(x->t[1]), c->e1),
                              st * sin(x->t[1]), c->e2), p[2];
    prox_vec3 pb = prox_body_pc(c->B, n);
    double delta = x->hw[0] + x->hw[1] * fmin(1.0, fabs(st) + x->hw[0]);
    int m = a_pieces(c->A, n, p, R);
    x->v = x->bound = -INFINITY;
    for (int j = 0; j < m; ++j) {
        prox_vec3 g = prox_v3_sub(prox_v3_add(c->dc, p[j]), pb);
        double v = prox_v3_dot(n, g), gt = prox_v3_norm(prox_v3_reject(g, n));
        x->v = fmax(x->v, v);
        x->bound = fmax(x->bound, v + gt * delta + fmax(0.0, R[j] - v) * 0.5 * delta * delta);
    }
}

/* The point of the sphere at angles t. */
static prox_vec3 ee_dir(const ee_ctx *c, const double *t)
{
    double st = sin(t[0]);
    return prox_v3_mad(prox_v3_mad(prox_v3_scale(c->e3, cos(t[0])), st * cos(t[1]), c->e1), st * sin(t[1]), c->e2);
}

/* G and its gradient on the sphere, g_t (dG = g . dn, g of the piece attaining G), at the unit n. */
static double ee_value(const ee_ctx *c, prox_vec3 n, prox_vec3 *gt)
{
    prox_vec3 p[2], pb = prox_body_pc(c->B, n);
    double R[2], best = -INFINITY;
    int m = a_pieces(c->A, n, p, R);
    for (int j = 0; j < m; ++j) {
        prox_vec3 g = prox_v3_sub(prox_v3_add(c->dc, p[j]), pb);
        double v = prox_v3_dot(n, g);
        if (v > best) best = v, *gt = prox_v3_reject(g, n);
    }
    return best;
}

/* Gradient ascent on the sphere from n (steps along g_t, grown on success, halved on failure): a
 * strong first value for the search, whose pruning is only as good as its best value. */
static double ee_ascend(const ee_ctx *c, prox_vec3 n)
{
    prox_vec3 gt;
    double v = ee_value(c, n, &gt), step = 0.1;
    for (int it = 0; it < 300 && step > 1e-15; ++it) {
        double len = prox_v3_norm(gt);
        if (!(len > 0.0)) break;
        prox_vec3 m = prox_v3_normalize(prox_v3_mad(n, step / len, gt)), gm;
        double w = ee_value(c, m, &gm);
        if (w > v) n = m, v = w, gt = gm, step *= 1.5;
        else step *= 0.5;
    }
    return v;
}

static double ell_clearance(const prox_body *A, const prox_body *B, double eps)
{
    ee_ctx c = {A, B, prox_v3_sub(A->c, B->c), {0, 0, 0}, {0, 0, 0}, B->x.ell.w};
    c.e1 = prox_v3_any_perp(c.e3);
    c.e2 = prox_v3_cross(c.e3, c.e1);
    enum { CAP = 1024, M0 = 8, M1 = 16 }; /* 128 starting cells plus two per level */
    ee_cell st[CAP];
    int n = 0;
    double best = -INFINITY;
    for (int i = 0; i < M0; ++i)
        for (int j = 0; j < M1; ++j) {
            ee_cell x = {{(i + 0.5) * PROX_PI / M0, (j + 0.5) * 2.0 * PROX_PI / M1}, {0.5 * PROX_PI / M0, PROX_PI / M1}, 0, 0};
            ee_eval(&c, &x);
            best = fmax(best, x.v);
            st[n++] = x;
        }
    /* every starting cell that may hold the maximum ascended first: the search then starts from the
     * best local maximum, and prunes every other basin at once */
    for (int i = 0; i < n; ++i)
        if (st[i].bound > best + eps) best = fmax(best, ee_ascend(&c, ee_dir(&c, st[i].t)));
    long evals = n;
    while (n > 0) {
        ee_cell x = st[--n];
        if (x.bound <= best + eps) continue;
        if (n + 3 > CAP || evals > 400000) { /* out of budget: the open cells' bound stands */
            double up = x.bound;
            for (int i = 0; i < n; ++i) up = fmax(up, st[i].bound);
            return -fmax(best, up - eps);
        }
        /* cut in three along the longer side (phi's length is sin(theta) x its width) */
        int k = x.hw[1] * fabs(sin(x.t[0])) > x.hw[0] ? 1 : 0;
        ee_cell ch[3] = {x, x, x};
        for (int m = 0; m < 3; ++m) {
            ch[m].hw[k] = x.hw[k] / 3.0;
            ch[m].t[k] = x.t[k] + (m - 1) * 2.0 * ch[m].hw[k];
            ee_eval(&c, &ch[m]);
            best = fmax(best, ch[m].v);
        }
        evals += 3;
        for (int m = 0; m < 3; ++m) st[n++] = ch[m];
    }
    return -best;
}

double prox_query_clearance(const prox_shape *a, const prox_shape *b, int *certified)
{
    *certified = 1;
    if (a->kind == PROX_SHAPE_SPH) return -prox_query_point_signed(b, a->u.sph.center) - a->u.sph.radius;
    prox_body A = prox_body_make(a), B = prox_body_make(b);
    if (kind_poly(b->kind)) return faces_clearance(&A, &B);
    if (kind_poly(a->kind)) return corners_clearance(&A, &B);
    if (B.kind == PROX_BODY_SPH) return in_sphere_clearance(&A, B.c, B.r);
    double S = fmax(prox_v3_dist(A.c, B.c), fmax(A.size, B.size));
    *certified = 0;
    if (B.kind == PROX_BODY_ELL) return ell_clearance(&A, &B, PROX_TOL_CONTAIN_BB * S);
    if (B.kind == PROX_BODY_CYL) {
        *certified = 1;
        return fmin(slab_clearance(&A, &B), rcc_lateral_clearance(&A, &B));
    }
    return fmin(slab_clearance(&A, &B), lateral_clearance(&A, &B, PROX_TOL_CONTAIN_BB * S));
}
