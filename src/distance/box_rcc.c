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
 * Fast path (prox_box_rcc_distance; the complete method above stays as the fallback and as
 * prox_box_rcc_distance_enum): cheap common points first, then alternating projections between the
 * solids, each round solving the feature pair it lands on (a box edge against the solid cylinder by a
 * convex one-dimensional search, a box face against the cylinder's lowest point) and stopping at the
 * first pair certified by weak duality, gap(n) >= |p2 - p1| - PROX_TOL_CERT S (the certificate of the
 * cylinder pair, docs/design.md): on random pairs it settles all but a few in a thousand.
 * The signed distance (depth when they overlap) composes this with the support-function engine of
 * src/sat and lives in src/query/box_rcc_signed.c. */
#include "distance/box_internal.h"
#include "core/edge_root.h"
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

/* Cheap common points, each inside both solids up to rounding: the box centre in the cylinder, the
 * cylinder's centre in the box, the middle of the axis segment's part in the box. Six in ten of the
 * benchmark's overlapping pairs have one and need nothing more; the projections of br_fast find a
 * common point for most of the others. */
static int br_quick_common(const prox_bframe *B, const prox_cyl *c, prox_vec3 *x)
{
    if (prox_cyl_contains(c, B->m, 0.0)) {
        *x = B->m;
        return 1;
    }
    double l[3], s0, s1;
    prox_bframe_local(B, c->c, l);
    if (fabs(l[0]) <= B->h[0] && fabs(l[1]) <= B->h[1] && fabs(l[2]) <= B->h[2]) {
        *x = c->c;
        return 1;
    }
    if (prox_bframe_clip_segment(B, c->b, c->cap[1], 0.0, &s0, &s1)) {
        *x = prox_v3_mad(c->b, 0.5 * (s0 + s1) * c->h, c->w);
        return 1;
    }
    return 0;
}

/* Validates the pair and builds the frames relative to the box centre *o (the pair's coordinates
 * are then small numbers wherever it sits: the certificate below is computed to a few ulps of the
 * pair's scale). */
static prox_status box_rcc_frames(const prox_box *a, const prox_rcc *b, prox_bframe *B, prox_cyl *c, prox_vec3 *o)
{
    prox_status st = prox_valid2(prox_box_validate(a), prox_rcc_validate(b));
    if (st != PROX_OK) return st;
    *B = prox_bframe_make(a);
    *o = B->m;
    B->m = prox_v3(0, 0, 0);
    *c = prox_cyl_make(b, *o);
    return PROX_OK;
}

/* The verdict shared by the test and the distance (*x a common point when they meet; *n0 the best
 * cheap separating direction). A gap above 8 tol along a cheap direction decides "disjoint" without
 * the exact test: box_rcc_meet enlarges the solids by at most 2 tol per coordinate (2 sqrt(3) tol in
 * all), so it cannot find a common point there either. */
static void box_rcc_verdict(const prox_bframe *B, const prox_cyl *c, int *meet, prox_vec3 *x, prox_vec3 *n0)
{
    /* box_rcc_meet may report a contact up to 2 sqrt(3) tol away: a quarter of the query tolerance
     * keeps that within PROX_QUERY_REL_TOL x scale (pairs 3.3e-12 x scale apart were reported
     * touching with the full one), still far above the rounding of its tests. */
    double tol = 0.25 * PROX_QUERY_REL_TOL * pair_scale(B, c), gap;
    *n0 = br_separating_dir(B, c, &gap);
    *meet = gap > 8.0 * tol ? 0 : box_rcc_meet(B, c, tol, x);
}

PROX_API prox_test_result prox_box_rcc_test(const prox_box *a, const prox_rcc *b)
{
    prox_test_result r = {0};
    prox_bframe B;
    prox_cyl c;
    prox_vec3 o, x, n0;
    r.status = box_rcc_frames(a, b, &B, &c, &o);
    if (r.status != PROX_OK) return r;
    if (br_quick_common(&B, &c, &x)) r.intersect = 1;
    else box_rcc_verdict(&B, &c, &r.intersect, &x, &n0);
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
 * the best pair's direction, twice). Skipping such a candidate cannot change the minimum. Fills
 * r->distance, r->p1, r->p2 and r->certificate_gap in the frames' coordinates. */
static void br_enumerate(const prox_bframe *B, const prox_cyl *c, prox_vec3 n0, prox_distance_result *r)
{
    prox_vec3 x, y;
    double best = INFINITY;
    unsigned done = 0;
    prox_vec3 n = n0;
    for (int it = 0; it < 3; ++it) { /* seeds: support vertices, a first upper bound and direction */
        int i = 0;
        for (int k = 0; k < 3; ++k)
            if (prox_v3_dot(n, B->a[k]) > 0.0) i |= 1 << k;
        vertex_cyl(B, c, i, &done, &best, &r->p1, &r->p2);
        if (!(best > 0.0)) break;
        n = prox_v3_divs(prox_v3_sub(r->p2, r->p1), best);
    }
    br_dir D[2] = {br_dir_make(B, c, n0), br_dir_make(B, c, n)};
    for (int i = 0; i < 8; ++i)
        if (fmax(D[0].cmin - D[0].v[i], D[1].cmin - D[1].v[i]) < best)
            vertex_cyl(B, c, i, &done, &best, &r->p1, &r->p2);
    for (int top = 0; top < 2; ++top) {
        double rmin[2]; /* the rim's least projection: that of its disk */
        for (int d = 0; d < 2; ++d) rmin[d] = D[d].disk[top];
        for (int f = 0; f < 6; ++f) {
            int k = f / 2, sgn = (f & 1) ? 1 : -1;
            unsigned face = 0; /* the face's 4 vertices: bit k of the index = (sgn > 0) */
            for (int i = 0; i < 8; ++i)
                if ((i >> k & 1) == (sgn > 0)) face |= 1u << i;
            if (proj_lb(D, face, rmin) >= best) continue;
            double d = rim_face(c, top, B, k, sgn, &x, &y);
            if (d < best) best = d, r->p1 = y, r->p2 = x;
        }
    }
    edges_cyl(B, c, D, &best, &r->p1, &r->p2);
    r->distance = best > 0.0 ? best : 0.0; /* a vertex within rounding inside: touching */
    /* Both directions give lower bounds (weak duality); the pair's own direction is the sharp one
     * unless the points coincide (touching within rounding), where n0's is used. */
    double gap0 = -prox_cyl_support(c, prox_v3_neg(n0)) - prox_bframe_support(B, n0);
    r->certificate_gap = gap0;
    if (r->distance > 0.0) {
        n = prox_v3_divs(prox_v3_sub(r->p2, r->p1), prox_v3_dist(r->p2, r->p1));
        double g = -prox_cyl_support(c, prox_v3_neg(n)) - prox_bframe_support(B, n);
        if (g > gap0) r->certificate_gap = g;
    }
}

/* ---- the fast path: alternating projections, the feature pair they name, a certificate ---- */

/* Closest point of the solid cylinder to x with the feature it lies on: bit 0 the side (radius
 * clamped), bit 1 an end plane (axial coordinate clamped), so 3 is a rim and 0 the interior (x itself). */
static prox_vec3 br_cyl_closest(const prox_cyl *c, prox_vec3 x, int *feat)
{
    prox_vec3 d = prox_v3_sub(x, c->b);
    double t = prox_v3_dot(d, c->w);
    prox_vec3 radial = prox_v3_mad(d, -t, c->w);
    double rho = prox_v3_norm(radial);
    double tc = t < 0.0 ? 0.0 : (t > c->h ? c->h : t);
    *feat = (rho > c->r) | (tc != t) << 1;
    if (rho > c->r) radial = prox_v3_scale(radial, c->r / rho);
    return prox_v3_add(prox_v3_mad(c->b, tc, c->w), radial);
}

/* Closest point of the solid box to x with its local coordinates l; bit k of *mask set when l_k was
 * clamped to a face (three bits: a vertex, two: an edge, one: a face, none: x inside). */
static prox_vec3 br_box_closest(const prox_bframe *B, prox_vec3 x, double l[3], unsigned *mask)
{
    prox_bframe_local(B, x, l);
    *mask = 0;
    for (int k = 0; k < 3; ++k) {
        if (l[k] > B->h[k]) l[k] = B->h[k], *mask |= 1u << k;
        else if (l[k] < -B->h[k]) l[k] = -B->h[k], *mask |= 1u << k;
    }
    return prox_bframe_point(B, l);
}

/* G(t) = (x - P(x)).a_k at the point x of local coordinates le with le[k] = t (P the cylinder's
 * closest point), with x and y = P(x). */
typedef struct br_edge_ctx {
    const prox_bframe *B;
    const prox_cyl *c;
    int k;
    double le[3];
    prox_vec3 *x, *y;
} br_edge_ctx;

static double br_edge_g(void *ctx, double t)
{
    br_edge_ctx *q = ctx;
    q->le[q->k] = t;
    *q->x = prox_bframe_point(q->B, q->le);
    *q->y = prox_cyl_closest(q->c, *q->x);
    return prox_v3_dot(prox_v3_sub(*q->x, *q->y), q->B->a[q->k]);
}

/* The edge along a_k through the local point l (its other two coordinates at their bounds) against the
 * solid cylinder: x(t) = m + sum l_j a_j with l_k = t, the root of G in [-h_k, h_k] or an end
 * (core/edge_root.h), to a bracket a few ulps wide. t0 (the box point's coordinate) starts it.
 * Returns the distance of the pair (x on the edge, y on the cylinder). */
static double br_edge(const prox_bframe *B, const prox_cyl *c, int k, const double l[3], double t0, prox_vec3 *x,
                      prox_vec3 *y)
{
    br_edge_ctx q = {B, c, k, {l[0], l[1], l[2]}, x, y};
    double lo = -B->h[k], hi = B->h[k];
    double glo = br_edge_g(&q, lo);
    if (glo >= 0.0) return prox_v3_dist(*x, *y);
    double ghi = br_edge_g(&q, hi);
    if (ghi <= 0.0) return prox_v3_dist(*x, *y);
    double t = t0 > lo && t0 < hi ? t0 : 0.5 * (lo + hi);
    prox_edge_root(br_edge_g, &q, lo, hi, glo, ghi, t, 4.0 * DBL_EPSILON * B->h[k]);
    return prox_v3_dist(*x, *y);
}

/* The closest pair of the box feature the projections landed on (a face or an edge: the bits of mask
 * and the local point l) and the solid cylinder. An edge: br_edge. A face (outward normal n): the
 * cylinder's point lowest along n (a rim point, or the middle of a side segment or disk parallel to
 * the face) when it projects into the face (rim_face measures its height in box coordinates); else
 * the closest pair lies on the face's border on that side, and the one or two edges there are solved
 * (br_edge). A vertex needs nothing (its projection is exact). Returns the distance of the pair (x on
 * the box, y on the cylinder), INFINITY when there is nothing to solve. */
static double br_feature_pair(const prox_bframe *B, const prox_cyl *c, unsigned mask, const double l[3], prox_vec3 *x,
                              prox_vec3 *y)
{
    int nb = (mask & 1) + (mask >> 1 & 1) + (mask >> 2 & 1);
    if (nb == 2) { /* an edge along the free axis k */
        int k = (mask & 1) == 0 ? 0 : ((mask & 2) == 0 ? 1 : 2);
        return br_edge(B, c, k, l, l[k], x, y);
    }
    if (nb != 1) return INFINITY;
    int k = mask == 1 ? 0 : (mask == 2 ? 1 : 2), sgn = l[k] > 0.0 ? 1 : -1;
    prox_vec3 nf = prox_v3_scale(B->a[k], (double)sgn);
    double nw = prox_v3_dot(nf, c->w), d = rim_face(c, nw < 0.0, B, k, sgn, y, x);
    if (d < INFINITY) return d;
    /* the lowest point off the face: the border edges on its side, from the end it is on */
    prox_vec3 low = prox_cyl_support_point(c, prox_v3_neg(nf)), u, v;
    double ll[3];
    prox_bframe_local(B, low, ll);
    ll[k] = sgn * B->h[k];
    for (int j = 0; j < 3; ++j) {
        if (j == k || !(fabs(ll[j]) > B->h[j])) continue;
        double le[3] = {ll[0], ll[1], ll[2]};
        le[j] = ll[j] > 0.0 ? B->h[j] : -B->h[j];
        double e = br_edge(B, c, 3 - j - k, le, ll[3 - j - k], &u, &v);
        if (e < d) d = e, *x = u, *y = v;
    }
    return d;
}

/* gap(n) = -h_B(-n) - h_A(n) of the pair along the unit n, a lower bound of the distance. */
static double br_gap_dir(const prox_bframe *B, const prox_cyl *c, prox_vec3 n)
{
    return -prox_cyl_support(c, prox_v3_neg(n)) - prox_bframe_support(B, n);
}

/* Does the pair (x on the box, y on the cylinder, d = |y - x| > 0) certify itself: gap(n) >= d -
 * PROX_TOL_CERT S along n = (y - x) / d? *gap receives gap(n). */
static int br_certified(const prox_bframe *B, const prox_cyl *c, prox_vec3 x, prox_vec3 y, double d, double S,
                        double *gap)
{
    *gap = br_gap_dir(B, c, prox_v3_divs(prox_v3_sub(y, x), d));
    return *gap >= d - PROX_TOL_CERT * S;
}

/* br_fast's outcomes; BR_NEG_ROUNDS: rounds after which a negative gap(n) gives up. */
enum { BR_OPEN = 0, BR_DISJOINT = 1, BR_MEET = 2, BR_NEG_ROUNDS = 2 };

/* Alternating projections between the solids (von Neumann): from the cylinder point nearest the box
 * centre, the box point nearest it, the cylinder point nearest that, ... A projection that lands
 * inside the other solid is a common point (BR_MEET, *x). Each round also solves the feature pair the
 * box point lies on (br_feature_pair), whose pair, when nearer, is the next round's start: the plain
 * projections crawl where the surfaces are nearly parallel, the feature pair jumps to the contact.
 * Any pair (x, y) of points of the solids bounds the distance from above, gap(n) from below (weak
 * duality, the certificate of rcc_rcc.c): a pair with gap(n) >= |y - x| - PROX_TOL_CERT S is the
 * closest pair to a few ulps of S, and gap(n) > 8 tol proves the solids disjoint beyond the verdict's
 * tolerance (as box_rcc_verdict's cheap directions do): BR_DISJOINT with the pair and its gap.
 * Otherwise BR_OPEN, after a few rounds or as soon as gap(n) stays negative (then the pair most
 * likely overlaps, which the exact verdict decides sooner than the projections' slow approach to the
 * intersection): the verdict and the complete enumeration answer. */
static int br_fast(const prox_bframe *B, const prox_cyl *c, double S, prox_distance_result *r, prox_vec3 *x)
{
    double tol8 = 2.0 * PROX_QUERY_REL_TOL * S, l[3], gap;
    int feat;
    unsigned mask;
    prox_vec3 y = br_cyl_closest(c, B->m, &feat);
    for (int it = 0; it < 8; ++it) {
        prox_vec3 p = br_box_closest(B, y, l, &mask);
        if (mask == 0) { /* y lies in the box */
            *x = y;
            return BR_MEET;
        }
        prox_vec3 q = br_cyl_closest(c, p, &feat);
        if (feat == 0) {
            *x = p;
            return BR_MEET;
        }
        double d = prox_v3_dist(p, q);
        if (!(d > 0.0)) return BR_OPEN;
        if (br_certified(B, c, p, q, d, S, &gap)) {
            if (!(gap > tol8)) return BR_OPEN;
            r->distance = d, r->p1 = p, r->p2 = q, r->certificate_gap = gap;
            /* a face against a rim: rim_face measures the same pair's height in box coordinates, a
             * few ulps sharper than |q - p|; of two pairs of points of the solids the nearer wins */
            prox_vec3 u, v;
            double e = feat == 3 && (mask == 1 || mask == 2 || mask == 4)
                           ? br_feature_pair(B, c, mask, l, &u, &v) : INFINITY;
            if (e <= d) { /* its direction's bound too: the larger of two lower bounds holds */
                double g2 = br_gap_dir(B, c, prox_v3_divs(prox_v3_sub(v, u), e));
                r->distance = e, r->p1 = u, r->p2 = v, r->certificate_gap = g2 > gap ? g2 : gap;
            }
            return BR_DISJOINT;
        }
        if (it >= BR_NEG_ROUNDS && gap < 0.0) return BR_OPEN; /* likely overlapping: the exact verdict */
        prox_vec3 u, v;
        double e = br_feature_pair(B, c, mask, l, &u, &v);
        if (e < d) {
            if (!(e > 0.0)) return BR_OPEN;
            if (br_certified(B, c, u, v, e, S, &gap)) {
                if (!(gap > tol8)) return BR_OPEN;
                r->distance = e, r->p1 = u, r->p2 = v, r->certificate_gap = gap;
                return BR_DISJOINT;
            }
            q = v;
        }
        y = q;
    }
    return BR_OPEN;
}

/* The complete method without the fast path (cheap common points, projections): the verdict, then
 * every candidate. The fast path's cross-check (tests/test_box_rcc_fast.c). */
prox_distance_result prox_box_rcc_distance_enum(const prox_box *a, const prox_rcc *b);
prox_distance_result prox_box_rcc_distance_enum(const prox_box *a, const prox_rcc *b)
{
    prox_distance_result r = {0};
    prox_bframe B;
    prox_cyl c;
    prox_vec3 o, x, n0;
    r.status = box_rcc_frames(a, b, &B, &c, &o);
    if (r.status != PROX_OK) return r;
    box_rcc_verdict(&B, &c, &r.intersect, &x, &n0);
    if (r.intersect) r.p1 = r.p2 = x;
    else br_enumerate(&B, &c, n0, &r);
    r.p1 = prox_v3_add(r.p1, o);
    r.p2 = prox_v3_add(r.p2, o);
    return r;
}

/* 1 when x lies in both solids to tol: a checked common point (tol = PROX_TOL_TOUCH S, the touching
 * band, as the support-function engine checks its common points: a touching pair's solids may share
 * no point at all in floating point). */
static int br_in_both(const prox_bframe *B, const prox_cyl *c, prox_vec3 x, double tol)
{
    double l[3];
    prox_bframe_local(B, x, l);
    return fabs(l[0]) <= B->h[0] + tol && fabs(l[1]) <= B->h[1] + tol && fabs(l[2]) <= B->h[2] + tol &&
           prox_cyl_contains(c, x, tol);
}

/* The distance: a cheap common point (br_quick_common), else the fast path (br_fast: a common point
 * or a certified closest pair), else the verdict and the complete enumeration. Coordinates relative
 * to the box centre, moved back at the end. `certified` as result.h defines it: a disjoint answer
 * within PROX_TOL_CERT S of its lower bound, or a common point checked in both solids. */
PROX_API prox_distance_result prox_box_rcc_distance(const prox_box *a, const prox_rcc *b)
{
    prox_distance_result r = {0};
    prox_bframe B;
    prox_cyl c;
    prox_vec3 o, x, n0;
    r.status = box_rcc_frames(a, b, &B, &c, &o);
    if (r.status != PROX_OK) return r;
    double S = pair_scale(&B, &c);
    int v = br_quick_common(&B, &c, &x) ? BR_MEET : br_fast(&B, &c, S, &r, &x);
    if (v == BR_OPEN) {
        box_rcc_verdict(&B, &c, &r.intersect, &x, &n0);
        if (!r.intersect) {
            br_enumerate(&B, &c, n0, &r);
            r.certified = r.distance > 0.0 && r.certificate_gap >= r.distance - PROX_TOL_CERT * S;
        }
    } else {
        r.intersect = v == BR_MEET;
        r.certified = v == BR_DISJOINT;
    }
    if (r.intersect) {
        r.p1 = r.p2 = x;
        r.certified = br_in_both(&B, &c, x, PROX_TOL_TOUCH * S);
    }
    r.p1 = prox_v3_add(r.p1, o);
    r.p2 = prox_v3_add(r.p2, o);
    return r;
}
