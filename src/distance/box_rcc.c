/* BOX-RCC: intersection verdict, exact distance and proximal points, signed distance.
 * Replaces the TRX report's Sec. 3.2 (LA-UR-13-26757, Eqs. (42)-(48): box edge lines against the
 * cylinder quadric, then against the end planes inside the circle), which misses a box inside the
 * cylinder, a cylinder inside the box, and a thin box (or slab) through the cylinder's side with no
 * box edge crossing the surface (the cylinder crosses two faces only).
 * Verdict: the intersection K of box and cylinder is compact convex; an extreme point of K lies on a box
 * edge (two box planes active), on a rim circle (no box plane active: an extreme point of the cylinder),
 * or on a face interior and the lateral surface. In the last case, if no edge meets the cylinder and no
 * rim meets the box, the face's section of the cylinder is a whole ellipse inside the face, and its
 * centre is on the axis: so  K != 0  <=>  an edge meets the cylinder, or a rim meets the box, or the
 * axis segment meets the box.
 * Distance (disjoint): a closest pair lies on (box vertex or edge, solid cylinder) or (rim circle, box
 * face interior); face-lateral and face-disk contacts are parallel and extend to one of those. Edge
 * against solid cylinder in closed form with the primitive solvers of Agarwal et al. (2016): the
 * lateral surface by P(L, S) (Sec. 3.1, prox_segment_cylsurf_inf, kept when its foot is between the end
 * planes), each end disk with its rim by P(D, L) (Sec. 3.2-3.3, prox_disk_segment), edges pruned by a
 * capsule lower bound. Rim against face: the circle's lowest point along the face normal.
 * The signed distance (depth when they overlap) composes this with the support-function engine of
 * src/sat and lives in src/query/box_rcc_signed.c. */
#include "distance/box_internal.h"
#include "core/tol.h"
#include "prox/primitives.h"

/* Does the rim circle meet the box enlarged by tol? Each constraint |g_k(th)| <= h_k + tol with
 * g_k = gamma + alpha cos th + beta sin th holds on arcs; a non-empty intersection of arcs contains
 * one of their end angles (or is the whole circle), so those angles and the midpoints between them
 * are the only candidates to test. */
static int rim_meets_box(const prox_cyl *c, int top, const prox_bframe *B, double tol, prox_vec3 *x)
{
    double cand[32];
    int nc = 0;
    cand[nc++] = 0.0;
    prox_fcircle rim = prox_cyl_rim(c, top);
    double g[3], al[3], be[3];
    for (int k = 0; k < 3; ++k) {
        g[k] = prox_v3_dot(prox_v3_sub(rim.c, B->m), B->a[k]);
        al[k] = rim.r * prox_v3_dot(rim.u, B->a[k]);
        be[k] = rim.r * prox_v3_dot(rim.v, B->a[k]);
        double R = prox_hypot2(al[k], be[k]), phi = atan2(be[k], al[k]);
        for (int sgn = -1; sgn <= 1 && R > 0.0; sgn += 2) {
            double rho = (sgn * (B->h[k] + tol) - g[k]) / R;
            if (fabs(rho) > 1.0) continue;
            double ac = acos(rho);
            cand[nc++] = phi + ac;
            cand[nc++] = phi - ac;
        }
    }
    int nb = nc; /* add midpoints between consecutive sorted boundary angles */
    for (int i = 0; i < nb; ++i) cand[i] = fmod(fmod(cand[i], 2 * PROX_PI) + 2 * PROX_PI, 2 * PROX_PI);
    for (int i = 1; i < nb; ++i)
        for (int j = i; j > 0 && cand[j] < cand[j - 1]; --j) { double t = cand[j]; cand[j] = cand[j - 1]; cand[j - 1] = t; }
    for (int i = 0; i < nb; ++i) cand[nc++] = i + 1 < nb ? 0.5 * (cand[i] + cand[i + 1]) : 0.5 * (cand[i] + cand[0] + 2 * PROX_PI);
    for (int i = 0; i < nc; ++i) {
        int ok = 1;
        for (int k = 0; k < 3 && ok; ++k)
            ok = fabs(g[k] + al[k] * cos(cand[i]) + be[k] * sin(cand[i])) <= B->h[k] + 2.0 * tol;
        if (ok) {
            *x = prox_fcircle_point(&rim, cand[i]);
            return 1;
        }
    }
    return 0;
}

static double pair_scale(const prox_bframe *B, const prox_cyl *c)
{
    double s = prox_v3_dist(B->m, c->c), v[3] = {prox_bframe_size(B), c->h, 2.0 * c->r};
    for (int i = 0; i < 3; ++i) s = v[i] > s ? v[i] : s;
    return s;
}

/* The verdict with a common point when they meet. */
static int box_rcc_meet(const prox_bframe *B, const prox_cyl *c, double tol, prox_vec3 *x)
{
    if (prox_bframe_edges_meet(B, prox_cyl_clip_segment, c, tol, x)) return 1;
    for (int top = 0; top < 2; ++top)
        if (rim_meets_box(c, top, B, tol, x)) return 1;
    double s0, s1;
    if (prox_bframe_clip_segment(B, c->b, c->cap[1], tol, &s0, &s1)) {
        *x = prox_v3_mad(c->b, 0.5 * (s0 + s1) * c->h, c->w);
        return 1;
    }
    return 0;
}

/* Projections on a unit direction n relative to the box centre m (small numbers: the rounding stays
 * ~1e-16 x pair scale wherever the pair sits): the 8 box vertices (prox_bframe_vertex numbering), their
 * maximum, and the least projection of the solid cylinder (of each end disk in disk[2]). For any x in a
 * set X of the box and y in a set Y of the cylinder, |y - x| >= n.(y - x) >= min_Y n.y - max_X n.x: the
 * lower bounds that prune the distance candidates below. */
typedef struct br_dir {
    prox_vec3 n;
    double v[8], vmax, cmin, disk[2];
} br_dir;

static br_dir br_dir_make(const prox_bframe *B, const prox_cyl *c, prox_vec3 n)
{
    br_dir D;
    D.n = n;
    double e[3];
    for (int k = 0; k < 3; ++k) e[k] = B->h[k] * prox_v3_dot(n, B->a[k]);
    D.vmax = fabs(e[0]) + fabs(e[1]) + fabs(e[2]);
    for (int i = 0; i < 8; ++i) D.v[i] = ((i & 1) ? e[0] : -e[0]) + ((i & 2) ? e[1] : -e[1]) + ((i & 4) ? e[2] : -e[2]);
    double nw = prox_v3_dot(n, c->w), perp = c->r * prox_v3_norm(prox_v3_mad(n, -nw, c->w));
    double b0 = prox_v3_dot(n, prox_v3_sub(c->b, B->m));
    D.disk[0] = b0 - perp;
    D.disk[1] = b0 + c->h * nw - perp;
    D.cmin = fmin(D.disk[0], D.disk[1]);
    return D;
}

/* Gap of the pair along D.n: a lower bound of the distance (negative when n does not separate). */
static double br_gap(const br_dir *D) { return D->cmin - D->vmax; }

/* A cheap separating direction: the best of the centre line, the cylinder axis and the box axes (each
 * oriented from the box towards the cylinder); *gap its gap (a lower bound of the distance). */
static prox_vec3 br_separating_dir(const prox_bframe *B, const prox_cyl *c, double *gap)
{
    prox_vec3 cc = prox_v3_sub(c->c, B->m);
    double ncc = prox_v3_norm(cc);
    prox_vec3 cand[5] = {ncc > 0.0 ? prox_v3_divs(cc, ncc) : c->w, c->w, B->a[0], B->a[1], B->a[2]};
    prox_vec3 best = cand[0];
    *gap = -INFINITY;
    for (int i = 0; i < 5; ++i) {
        prox_vec3 n = prox_v3_dot(cand[i], cc) >= 0.0 ? cand[i] : prox_v3_neg(cand[i]);
        br_dir D = br_dir_make(B, c, n);
        double g = br_gap(&D);
        if (g > *gap) *gap = g, best = n;
    }
    return best;
}

/* Validates the pair, builds the frames and decides the verdict shared by the test and the distance
 * (*x a common point when they meet; *n0 the best cheap separating direction). A gap above 8 tol along
 * a cheap direction decides "disjoint" without the exact test: box_rcc_meet enlarges the solids by at
 * most 2 tol per coordinate (2 sqrt(3) tol in all), so it cannot find a common point there either. */
static prox_status box_rcc_setup(const prox_box *a, const prox_rcc *b, prox_bframe *B, prox_cyl *c, int *meet,
                                 prox_vec3 *x, prox_vec3 *n0)
{
    prox_status st = prox_valid2(prox_box_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return st;
    *B = prox_bframe_make(a);
    *c = prox_cyl_make(b, prox_v3(0, 0, 0));
    /* box_rcc_meet may report a contact up to 2 sqrt(3) tol away: a quarter of the query tolerance
     * keeps that within PROX_QUERY_REL_TOL x scale (pairs 3.3e-12 x scale apart were reported
     * touching with the full one), still far above the rounding of its tests. */
    double tol = 0.25 * PROX_QUERY_REL_TOL * pair_scale(B, c), gap;
    *n0 = br_separating_dir(B, c, &gap);
    *meet = gap > 8.0 * tol ? 0 : box_rcc_meet(B, c, tol, x);
    return PROX_OK;
}

PROX_API prox_test_result prox_box_rcc_test(const prox_box *a, const prox_rcc *b)
{
    prox_test_result r = {0};
    prox_bframe B;
    prox_cyl c;
    prox_vec3 x, n0;
    r.status = box_rcc_setup(a, b, &B, &c, &r.intersect, &x, &n0);
    return r;
}

/* Edge (segment) against the lateral surface: the foot of the segment's closest approach to the axis
 * line (prox_segment_cylsurf_inf). It is a candidate only when its axial parameter lies in [0, h]: if the
 * closest cylinder point of a disjoint edge is interior to the lateral surface, the convex function
 * max(rho - r, 0) along the edge has a local, hence global, minimum there, which the solver returns
 * (for an edge parallel to the axis the representative may fall outside [0, h]; then the edge passes an
 * end plane at the same radius and the cap candidate attains the same distance). Conversely a foot in
 * [0, h] outside the surface is the edge's own minimum: dist(x, C) >= dist(x, infinite cylinder), with
 * equality at the foot. */
static double edge_lateral(const prox_cyl *c, const prox_segment *s, prox_vec3 *x, prox_vec3 *y)
{
    prox_cylsurf S = {c->b, c->w, c->h, c->r};
    prox_prim_result q = prox_segment_cylsurf_inf(s, &S);
    if (q.status != PROX_OK || !(q.s2[0] >= 0.0 && q.s2[0] <= c->h)) return INFINITY;
    *x = q.p1;
    *y = q.p2;
    return q.distance;
}

/* Distance of x to the segment s (for lower bounds). */
static double point_seg_dist(prox_vec3 x, const prox_segment *s)
{
    prox_vec3 d = prox_v3_sub(s->b, s->a);
    double dd = prox_v3_norm2(d), t = dd > 0.0 ? prox_v3_dot(prox_v3_sub(x, s->a), d) / dd : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return prox_v3_dist(x, prox_v3_mad(s->a, t, d));
}

/* Edge against the solid end disk `top` (its rim included) by prox_disk_segment (closed form: plane
 * crossing, endpoints against the disk, the rim by the quartic of prox_circle_segment), skipped when a
 * cheap lower bound (lb0 from the projections; height of the edge above the disk's plane; distance from
 * the disk's centre minus r) already reaches `best`. */
static double edge_cap(const prox_cyl *c, int top, const prox_segment *s, double lb0, double best, prox_vec3 *x,
                       prox_vec3 *y)
{
    prox_vec3 ctr = c->cap[top];
    double ha = prox_v3_dot(prox_v3_sub(s->a, ctr), c->w), hb = prox_v3_dot(prox_v3_sub(s->b, ctr), c->w);
    double lb = (ha > 0.0) == (hb > 0.0) && ha != 0.0 && hb != 0.0 ? fmin(fabs(ha), fabs(hb)) : 0.0;
    if (fmax(lb, lb0) >= best) return INFINITY;
    lb = fmax(lb, point_seg_dist(ctr, s) - c->r);
    if (lb >= best) return INFINITY;
    prox_disk D = {ctr, c->w, c->r};
    prox_prim_result q = prox_disk_segment(&D, s);
    if (q.status != PROX_OK) return INFINITY;
    *x = q.p2;
    *y = q.p1;
    return q.distance;
}

/* Vertex indices (prox_bframe_vertex numbering) of the ends of edge j (prox_bframe_edge numbering). */
static void edge_ends(int j, int *p, int *q)
{
    int k = j / 4, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    *p = ((j & 1) << k1) | (((j >> 1) & 1) << k2);
    *q = *p | (1 << k);
}

/* Lower bound of the distance from the box vertices in `mask` (max of their projections) to the part of
 * the cylinder with least projection `ymin[d]` along the two directions D[d]. */
static double proj_lb(const br_dir D[2], unsigned mask, const double ymin[2])
{
    double lb = -INFINITY;
    for (int d = 0; d < 2; ++d) {
        double hi = -INFINITY;
        for (int i = 0; i < 8; ++i)
            if (mask >> i & 1) hi = fmax(hi, D[d].v[i]);
        lb = fmax(lb, ymin[d] - hi);
    }
    return lb;
}

/* The 12 edges against the solid cylinder, nearest first by a lower bound: the projection bound along
 * the directions D (cheap; edges it already rules out get no more work), then the capsule bound
 * dist(edge, axis segment) - r (the cylinder lies in that capsule); stopping when the bound reaches the
 * best distance found; each remaining edge against the lateral surface and both end disks. */
static void edges_cyl(const prox_bframe *B, const prox_cyl *c, const br_dir D[2], double *best, prox_vec3 *p1,
                      prox_vec3 *p2)
{
    prox_segment e[12];
    double lb[12];
    unsigned ends[12];
    int order[12], m = 0;
    prox_vec3 top = c->cap[1], u, v;
    double cmin[2] = {D[0].cmin, D[1].cmin};
    for (int j = 0; j < 12; ++j) {
        int p, q;
        edge_ends(j, &p, &q);
        ends[j] = 1u << p | 1u << q;
        lb[j] = proj_lb(D, ends[j], cmin);
        if (lb[j] >= *best) continue;
        prox_bframe_edge(B, j, &e[j].a, &e[j].b);
        lb[j] = fmax(lb[j], prox_seg_seg(e[j].a, e[j].b, c->b, top, &u, &v) - c->r);
        int i = m++;
        for (; i > 0 && lb[order[i - 1]] > lb[j]; --i) order[i] = order[i - 1];
        order[i] = j;
    }
    for (int i = 0; i < m; ++i) {
        const prox_segment *s = &e[order[i]];
        if (lb[order[i]] >= *best) break;
        prox_vec3 x, y;
        double d = edge_lateral(c, s, &x, &y);
        if (d < INFINITY) { /* the foot is on the finite surface: it minimises dist(edge, C) itself */
            if (d < *best) *best = d, *p1 = x, *p2 = y;
            /* ... unless the edge is within 1e-3 rad of the axis: there the computed foot moves by
             * ~eps / angle^2 with the rounding of the edge, so a foot reported on the surface may
             * belong to an edge whose true closest approach lies beyond an end plane (the minimum is
             * then at a cap, up to angle x length lower: 2.6e-11 at 1e-9 rad in test_box_rcc). A
             * true foot on the surface needs no cap: the distance is flat around it to second order. */
            prox_vec3 ed = prox_v3_sub(s->b, s->a);
            if (prox_v3_norm2(prox_v3_cross(ed, c->w)) > PROX_TOL_WELL_COND2 * prox_v3_norm2(ed)) continue;
        }
        for (int t = 0; t < 2; ++t) {
            double dmin[2] = {D[0].disk[t], D[1].disk[t]};
            d = edge_cap(c, t, s, proj_lb(D, ends[order[i]], dmin), *best, &x, &y);
            if (d < *best) *best = d, *p1 = x, *p2 = y;
        }
    }
}

/* Rim circle against the interior of the box face with outward normal sgn a_k: the circle's lowest
 * point along the normal, when it projects into the face and lies above it. */
static double rim_face(const prox_cyl *c, int top, const prox_bframe *B, int k, int sgn, prox_vec3 *x, prox_vec3 *y)
{
    prox_vec3 nf = prox_v3_scale(B->a[k], (double)sgn);
    prox_vec3 ctr = c->cap[top];
    prox_vec3 rj = prox_v3_reject(nf, c->w);
    double rn = prox_v3_norm(rj);
    prox_vec3 dir;
    if (rn > PROX_TOL_PARALLEL) dir = prox_v3_neg(prox_v3_divs(rj, rn));
    else { /* circle parallel to the face: every rim point is as low; take the one nearest the centre */
        prox_vec3 t = prox_v3_reject(prox_v3_sub(B->m, ctr), c->w);
        double tn = prox_v3_norm(t);
        dir = tn > 0.0 ? prox_v3_divs(t, tn) : prox_v3_any_perp(c->w);
    }
    /* For a rim nearly parallel to the face, rj is a short difference whose rounding (~eps / rn
     * relative) tilts dir out of the rim's plane: r x that tilt put the "rim point" off the cylinder
     * by up to 1e-9 x scale (1e-9 rad tilts). One more rejection puts it back on the rim; its
     * in-plane direction error only moves it along a rim whose heights differ by r rn at most. */
    dir = prox_v3_normalize(prox_v3_reject(dir, c->w));
    *x = prox_v3_mad(ctr, c->r, dir);
    double l[3];
    prox_bframe_local(B, *x, l);
    for (int j = 0; j < 3; ++j)
        if (j != k && fabs(l[j]) > B->h[j]) return INFINITY;
    double height = sgn * l[k] - B->h[k];
    /* A point on the face up to the rounding of coordinates far from the origin (l is a difference of
     * coordinates ~|x|): a touching contact, distance 0, not a missing candidate (which left pairs
     * 1e6 from the origin 0.01-0.15 apart that touch). */
    double round_tol = PROX_TOL_NOISE * (prox_v3_maxabs(*x) + prox_v3_maxabs(B->m) + B->h[k]);
    if (!(height > -round_tol)) return INFINITY;
    if (height < 0.0) height = 0.0;
    l[k] = sgn * B->h[k];
    *y = prox_bframe_point(B, l);
    return height;
}

/* Vertex i of the box against the solid cylinder, once (bit i of *done). */
static void vertex_cyl(const prox_bframe *B, const prox_cyl *c, int i, unsigned *done, double *best, prox_vec3 *p1,
                       prox_vec3 *p2)
{
    if (*done >> i & 1) return;
    *done |= 1u << i;
    prox_vec3 n, y, v = prox_bframe_vertex(B, i);
    double d = prox_cyl_signed(c, v, &y, &n);
    if (d < *best) *best = d, *p1 = v, *p2 = y;
}

/* Candidates of a disjoint pair (box vertices, rim circles against face interiors, edges against the
 * solid cylinder), the minimum over all of them, with each candidate skipped when a lower bound from the
 * projections on two directions already reaches the best distance so far: the cheap separating direction
 * n0 and the direction of the best pair after the seeds (the box's support vertex along n0, then along
 * the best pair's direction, twice). Skipping such a candidate cannot change the minimum. */
PROX_API prox_distance_result prox_box_rcc_distance(const prox_box *a, const prox_rcc *b)
{
    prox_distance_result r = {0};
    prox_bframe B;
    prox_cyl c;
    prox_vec3 x, y, n0;
    r.status = box_rcc_setup(a, b, &B, &c, &r.intersect, &x, &n0);
    if (r.status != PROX_OK) return r;
    if (r.intersect) {
        r.p1 = r.p2 = x;
        return r;
    }
    double best = INFINITY;
    unsigned done = 0;
    prox_vec3 n = n0;
    for (int it = 0; it < 3; ++it) { /* seeds: support vertices, a first upper bound and direction */
        int i = 0;
        for (int k = 0; k < 3; ++k)
            if (prox_v3_dot(n, B.a[k]) > 0.0) i |= 1 << k;
        vertex_cyl(&B, &c, i, &done, &best, &r.p1, &r.p2);
        if (!(best > 0.0)) break;
        n = prox_v3_divs(prox_v3_sub(r.p2, r.p1), best);
    }
    br_dir D[2] = {br_dir_make(&B, &c, n0), br_dir_make(&B, &c, n)};
    for (int i = 0; i < 8; ++i)
        if (fmax(D[0].cmin - D[0].v[i], D[1].cmin - D[1].v[i]) < best) vertex_cyl(&B, &c, i, &done, &best, &r.p1, &r.p2);
    for (int top = 0; top < 2; ++top) {
        double rmin[2]; /* the rim's least projection: that of its disk */
        for (int d = 0; d < 2; ++d) rmin[d] = D[d].disk[top];
        for (int f = 0; f < 6; ++f) {
            int k = f / 2, sgn = (f & 1) ? 1 : -1;
            unsigned face = 0; /* the face's 4 vertices: bit k of the index = (sgn > 0) */
            for (int i = 0; i < 8; ++i)
                if ((i >> k & 1) == (sgn > 0)) face |= 1u << i;
            if (proj_lb(D, face, rmin) >= best) continue;
            double d = rim_face(&c, top, &B, k, sgn, &x, &y);
            if (d < best) best = d, r.p1 = y, r.p2 = x;
        }
    }
    edges_cyl(&B, &c, D, &best, &r.p1, &r.p2);
    r.distance = best > 0.0 ? best : 0.0; /* a vertex within rounding inside: touching */
    /* Both directions give lower bounds (weak duality); the pair's own direction is the sharp one
     * unless the points coincide (touching within rounding), where n0's is used. */
    double gap0 = -prox_cyl_support(&c, prox_v3_neg(n0)) - prox_bframe_support(&B, n0);
    r.certificate_gap = gap0;
    if (r.distance > 0.0) {
        n = prox_v3_divs(prox_v3_sub(r.p2, r.p1), prox_v3_dist(r.p2, r.p1));
        double g = -prox_cyl_support(&c, prox_v3_neg(n)) - prox_bframe_support(&B, n);
        if (g > gap0) r.certificate_gap = g;
    }
    return r;
}
