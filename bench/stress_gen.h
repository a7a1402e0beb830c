/* Near-degenerate cylinder pairs with a known exact distance, shared (header-only) by the stress test
 * tests/test_stress.c and the long stress run of prox_bench.
 *
 * Construction (the support-function slab argument): pick a unit normal n, a point pA of A's support
 * set in direction n and a point pB of B's support set in -n, and translate B so that pB = pA + gap n.
 * Then A lies in {x : n.x <= n.pA}, B in {x : n.x >= n.pA + gap}, so dist(A, B) >= gap, and
 * |pB - pA| = gap, so dist(A, B) = gap exactly (gap >= 0). The family fixes which features make the
 * contact by the choice of n and of the axes (parallel, perpendicular, tilted by a tiny angle).
 * The pair is then moved by a random rigid motion, scaled (family "scaled") or sent far from the
 * origin (family "far"), and A, B are swapped with probability 1/2. The placement rounds the input
 * once (~1e-16 of the largest coordinate), which bounds how exact the reference gap is. */
#ifndef PROX_BENCH_STRESS_GEN_H
#define PROX_BENCH_STRESS_GEN_H

#include <math.h>
#include <stdint.h>

#include "prox/prox.h"

/* The families: which features make the contact, and how the pair is placed. */
enum {
    SG_RIM_RIM = 0,   /* generic normal and axes: rim against rim */
    SG_LAT_LAT,       /* crossing lateral surfaces, n = WA x WB */
    SG_LAT_RIM,       /* lateral surface of A against a rim of B */
    SG_RIM_FACE,      /* a rim point of B on A's end disk */
    SG_FACE_FACE,     /* end disks, axes parallel / antiparallel within eps */
    SG_FACE_LAT,      /* A's end disk against B's lateral line, axes perpendicular within eps */
    SG_PARALLEL_SIDE, /* side by side, axes parallel within eps */
    SG_PERP_LAT,      /* crossing lateral surfaces, axes perpendicular within eps */
    SG_COAXIAL,       /* stacked nearly coaxial end circles: radial offset 1e-15..1e-3, tilt eps */
    SG_ASPECT,        /* r/h of each from 1e-6 to 1e6 */
    SG_SIZE_RATIO,    /* B 1e3..1e6 times larger or smaller than A */
    SG_SCALED,        /* a contact family, whole pair scaled by 10^U(-8, 8) */
    SG_FAR,           /* a contact family, translated 10^U(3, 8) from the origin */
    SG_NFAMILIES
};

static const char *const sg_family_names[SG_NFAMILIES] = {
    "rim-rim", "lat-lat", "lat-rim", "rim-face", "face-face", "face-lat", "parallel-side",
    "perp-lat", "coaxial", "aspect", "size-ratio", "scaled", "far"};

typedef struct sg_rng {
    uint64_t s[4];
} sg_rng;

static inline uint64_t sg_next(sg_rng *r)
{
    uint64_t *s = r->s, x = s[1] * 5, res = ((x << 7) | (x >> 57)) * 9, t = s[1] << 17;
    s[2] ^= s[0], s[3] ^= s[1], s[1] ^= s[2], s[0] ^= s[3], s[2] ^= t, s[3] = (s[3] << 45) | (s[3] >> 19);
    return res;
}
static inline sg_rng sg_seed(uint64_t seed)
{
    sg_rng r;
    for (int i = 0; i < 4; ++i) {
        uint64_t z = (seed += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        r.s[i] = z ^ (z >> 31);
    }
    return r;
}
static inline double sg_u(sg_rng *r) { return (double)(sg_next(r) >> 11) * 0x1.0p-53; }
static inline double sg_log(sg_rng *r, double lo, double hi) { return lo * exp(log(hi / lo) * sg_u(r)); }
static inline prox_vec3 sg_unit(sg_rng *r)
{
    for (;;) {
        prox_vec3 v = prox_v3(2 * sg_u(r) - 1, 2 * sg_u(r) - 1, 2 * sg_u(r) - 1);
        double n = prox_v3_norm(v);
        if (n > 1e-3 && n <= 1.0) return prox_v3_scale(v, 1.0 / n);
    }
}
/* A unit vector orthogonal to the unit u, uniformly around it. */
static inline prox_vec3 sg_perp(sg_rng *r, prox_vec3 u)
{
    prox_vec3 e1 = prox_v3_any_perp(u), e2 = prox_v3_cross(u, e1);
    double t = 2 * PROX_PI * sg_u(r);
    return prox_v3_add(prox_v3_scale(e1, cos(t)), prox_v3_scale(e2, sin(t)));
}
/* u turned by the angle eps towards a random perpendicular direction. */
static inline prox_vec3 sg_tilt(sg_rng *r, prox_vec3 u, double eps)
{
    return prox_v3_normalize(prox_v3_add(prox_v3_scale(u, cos(eps)), prox_v3_scale(sg_perp(r, u), sin(eps))));
}
/* Small angle: 0 in 15 % of draws, else log-uniform in [1e-15, 1e-3] rad. */
static inline double sg_eps(sg_rng *r) { return sg_u(r) < 0.15 ? 0.0 : sg_log(r, 1e-15, 1e-3); }
/* Gap for a size-1 pair: 0 in 10 % of draws, else log-uniform in [1e-12, 1e-3]. */
static inline double sg_gap(sg_rng *r) { return sg_u(r) < 0.10 ? 0.0 : sg_log(r, 1e-12, 1e-3); }

/* Rotates v by the rotation with quaternion (w, x, y, z) (unit). */
static inline prox_vec3 sg_qrot(const double q[4], prox_vec3 v)
{
    prox_vec3 u = prox_v3(q[1], q[2], q[3]);
    prox_vec3 t = prox_v3_scale(prox_v3_cross(u, v), 2.0);
    return prox_v3_add(prox_v3_add(v, prox_v3_scale(t, q[0])), prox_v3_cross(u, t));
}
static inline void sg_random_quat(sg_rng *r, double q[4])
{
    double u1 = sg_u(r), u2 = 2 * PROX_PI * sg_u(r), u3 = 2 * PROX_PI * sg_u(r);
    double a = sqrt(1 - u1), b = sqrt(u1);
    q[0] = a * sin(u2), q[1] = a * cos(u2), q[2] = b * sin(u3), q[3] = b * cos(u3);
}

/* A rigid motion (rotation q, then translation t) applied to a cylinder. */
static inline prox_rcc sg_move(prox_rcc c, const double q[4], prox_vec3 t)
{
    prox_rcc m = {prox_v3_add(sg_qrot(q, c.base), t), sg_qrot(q, c.axis), c.radius};
    return m;
}
static inline prox_rcc sg_scale(prox_rcc c, double s)
{
    prox_rcc m = {prox_v3_scale(c.base, s), prox_v3_scale(c.axis, s), c.radius * s};
    return m;
}

/* A cylinder with base centre at the origin, unit direction w, radius r, height h. */
static inline prox_rcc sg_cyl(prox_vec3 w, double r, double h)
{
    prox_rcc c = {prox_v3(0, 0, 0), prox_v3_scale(w, h), r};
    return c;
}

/* One generated pair with its exact distance. */
typedef struct sg_pair {
    prox_rcc a, b;
    double d_ref; /* exact distance of the construction */
    int family;
} sg_pair;

/* A point of the cylinder's support set in direction n (unit): the face centre when n is within
 * 1e-15 of the axis, else the rim point. The rejection of n from the axis is taken twice so that its
 * residual along the axis (rounding) cannot tilt the rim offset out of the face plane. */
static inline prox_vec3 sg_support_point(const prox_rcc *c, prox_vec3 n)
{
    prox_vec3 w = prox_v3_normalize(c->axis);
    double dw = prox_v3_dot(n, w);
    prox_vec3 p = dw >= 0.0 ? prox_v3_add(c->base, c->axis) : c->base;
    prox_vec3 dp = prox_v3_reject(prox_v3_reject(n, w), w);
    double len = prox_v3_norm(dp);
    return len > 1e-15 ? prox_v3_mad(p, c->radius / len, dp) : p;
}

/* Places B against A: support points in n and -n, gap along n; pA may be shifted within A's face
 * by `slide` (kept inside the support set by the caller). */
static inline void sg_place(prox_rcc *a, prox_rcc *b, prox_vec3 n, double gap, prox_vec3 slide)
{
    prox_vec3 pa = prox_v3_add(sg_support_point(a, n), slide);
    prox_vec3 pb = sg_support_point(b, prox_v3_neg(n));
    b->base = prox_v3_add(b->base, prox_v3_sub(prox_v3_mad(pa, gap, n), pb));
}

/* Sizes log-uniform in [0.2, 5]. */
static inline double sg_size(sg_rng *r) { return sg_log(r, 0.2, 5.0); }

/* Builds a contact-family pair of size ~1 (families SG_RIM_RIM..SG_SIZE_RATIO). */
static inline sg_pair sg_contact(sg_rng *r, int fam)
{
    sg_pair p;
    p.family = fam;
    prox_vec3 wa = sg_unit(r), wb = sg_unit(r), n = sg_unit(r), slide = prox_v3(0, 0, 0);
    double ra = sg_size(r), ha = sg_size(r), rb = sg_size(r), hb = sg_size(r), eps = sg_eps(r);
    double gap = sg_gap(r), sign = sg_u(r) < 0.5 ? 1.0 : -1.0;
    switch (fam) {
    case SG_LAT_LAT: n = prox_v3_normalize(prox_v3_cross(wa, wb)); break;
    case SG_LAT_RIM: n = sg_perp(r, wa); break;
    case SG_RIM_FACE: n = prox_v3_scale(wa, sign); break;
    case SG_FACE_FACE: n = prox_v3_scale(wa, sign), wb = sg_tilt(r, prox_v3_scale(wa, sg_u(r) < 0.5 ? 1 : -1), eps); break;
    case SG_FACE_LAT: n = prox_v3_scale(wa, sign), wb = sg_tilt(r, sg_perp(r, wa), eps); break;
    case SG_PARALLEL_SIDE: n = sg_perp(r, wa), wb = sg_tilt(r, prox_v3_scale(wa, sg_u(r) < 0.5 ? 1 : -1), eps); break;
    case SG_PERP_LAT:
        wb = sg_tilt(r, sg_perp(r, wa), eps);
        n = prox_v3_normalize(prox_v3_cross(wa, wb));
        break;
    case SG_COAXIAL:
        /* B stacked on A's top or bottom face, axis tilted by eps, its contact point offset radially
         * from A's face centre by 1e-15..1e-3 (relative): nearly coaxial end circles */
        n = prox_v3_scale(wa, sign), wb = sg_tilt(r, n, eps);
        slide = prox_v3_scale(sg_perp(r, wa), ra * sg_log(r, 1e-15, 1e-3));
        rb = ra * (1.0 - sg_log(r, 2e-3, 0.5)); /* rb < ra: B's lowest point stays on A's face */
        break;
    case SG_ASPECT:
        ha = ra / sg_log(r, 1e-6, 1e6), hb = rb / sg_log(r, 1e-6, 1e6);
        break;
    case SG_SIZE_RATIO: {
        double k = sg_log(r, 1e3, 1e6);
        if (sg_u(r) < 0.5) k = 1.0 / k;
        rb *= k, hb *= k;
        break;
    }
    default: break; /* SG_RIM_RIM: everything generic */
    }
    p.a = sg_cyl(wa, ra, ha);
    p.b = sg_cyl(wb, rb, hb);
    if (fam == SG_COAXIAL) {
        /* pA = A's face centre + offset + the radial offset of B's lowest point from B's face centre:
         * a point of A's face disk (rb < ra), which puts B's face centre on A's axis up to the offset */
        prox_vec3 centre = sign > 0 ? p.a.axis : prox_v3(0, 0, 0);
        prox_vec3 low = prox_v3_sub(sg_support_point(&p.b, prox_v3_neg(n)), p.b.base);
        slide = prox_v3_add(slide, prox_v3_sub(centre, sg_support_point(&p.a, n)));
        slide = prox_v3_add(slide, prox_v3_reject(low, n));
    }
    double scale = fmax(fmax(ra, ha), fmax(rb, hb));
    p.d_ref = gap * (fam == SG_SIZE_RATIO ? fmin(1.0, scale) : 1.0);
    sg_place(&p.a, &p.b, n, p.d_ref, slide);
    return p;
}

/* Builds one pair of family fam: the contact, a random rigid motion, scaling / far translation,
 * and a random swap. d_ref is exact for the construction (up to one rounding of the placement). */
static inline sg_pair sg_make(sg_rng *r, int fam)
{
    int base = fam;
    if (fam == SG_SCALED || fam == SG_FAR) base = (int)(sg_next(r) % (uint64_t)SG_COAXIAL);
    sg_pair p = sg_contact(r, base);
    p.family = fam;
    double q[4];
    sg_random_quat(r, q);
    prox_vec3 t = prox_v3(4 * sg_u(r) - 2, 4 * sg_u(r) - 2, 4 * sg_u(r) - 2);
    if (fam == SG_FAR) t = prox_v3_scale(sg_unit(r), sg_log(r, 1e3, 1e8));
    p.a = sg_move(p.a, q, t), p.b = sg_move(p.b, q, t);
    if (fam == SG_SCALED) {
        double s = pow(10.0, 16 * sg_u(r) - 8);
        p.a = sg_scale(p.a, s), p.b = sg_scale(p.b, s), p.d_ref *= s;
    }
    if (sg_u(r) < 0.5) {
        prox_rcc tmp = p.a;
        p.a = p.b, p.b = tmp;
    }
    return p;
}

/* Tolerance scale of a pair: S = max(|cA - cB|, hA, hB, rA, rB) (validation README). */
static inline double sg_pair_scale(const prox_rcc *a, const prox_rcc *b)
{
    prox_vec3 ca = prox_v3_mad(a->base, 0.5, a->axis), cb = prox_v3_mad(b->base, 0.5, b->axis);
    double s = prox_v3_dist(ca, cb);
    s = fmax(s, fmax(prox_v3_norm(a->axis), prox_v3_norm(b->axis)));
    return fmax(s, fmax(a->radius, b->radius));
}
/* Absolute rounding carried by the input doubles themselves: ~1e-16 of the largest coordinate. */
static inline double sg_input_ulp(const prox_rcc *a, const prox_rcc *b)
{
    double m = fmax(prox_v3_maxabs(a->base), prox_v3_maxabs(b->base));
    m = fmax(m, fmax(prox_v3_maxabs(prox_v3_add(a->base, a->axis)), prox_v3_maxabs(prox_v3_add(b->base, b->axis))));
    return 0x1p-52 * m;
}

/* Signed distance of the point x to the solid cylinder c in long double: > 0 outside, < 0 inside
 * (minus the depth below the nearest boundary). Independent of the library's solvers. */
static inline long double sg_point_rcc(const prox_rcc *c, prox_vec3 x)
{
    long double ax = c->axis.x, ay = c->axis.y, az = c->axis.z;
    long double h = sqrtl(ax * ax + ay * ay + az * az);
    ax /= h, ay /= h, az /= h;
    long double dx = (long double)x.x - c->base.x, dy = (long double)x.y - c->base.y,
                dz = (long double)x.z - c->base.z;
    long double t = dx * ax + dy * ay + dz * az;
    long double qx = dx - t * ax, qy = dy - t * ay, qz = dz - t * az;
    long double rho = sqrtl(qx * qx + qy * qy + qz * qz);
    long double out_r = rho - c->radius, out_t = fmaxl(-t, t - h);
    if (out_r <= 0 && out_t <= 0) return fmaxl(out_r, out_t);
    return sqrtl(fmaxl(out_r, 0) * fmaxl(out_r, 0) + fmaxl(out_t, 0) * fmaxl(out_t, 0));
}

#endif
