/* Shared helpers for the cmocka tests: assert_near (Debian's cmocka has no float asserts),
 * a seeded RNG (xoshiro256**), random rotations and shapes, and the GSL handler switch. */
#ifndef PROX_TEST_UTIL_H
#define PROX_TEST_UTIL_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <cmocka.h>
#include <gsl/gsl_errno.h>

#include "prox/prox.h"
#include "prox/support.h" /* prox_shape_size */

/* Fails with expected, actual and tolerance printed. */
#define assert_near(actual, expected, tol)                                                         \
    do {                                                                                           \
        double a_ = (actual), e_ = (expected), t_ = (tol);                                         \
        if (!(fabs(a_ - e_) <= t_)) {                                                              \
            print_error("assert_near failed: actual %.17g expected %.17g |diff| %.3g > tol %.3g\n", \
                        a_, e_, fabs(a_ - e_), t_);                                                \
            fail();                                                                                \
        }                                                                                          \
    } while (0)

/* s translated by t through prox_shape_translated, which must accept it. */
static inline prox_shape test_translate(const prox_shape *s, prox_vec3 t)
{
    prox_shape o = *s;
    prox_status st = prox_shape_translated(s, t, &o);
    if (st != PROX_OK) {
        print_error("prox_shape_translated: %s\n", prox_status_str(st));
        fail();
    }
    return o;
}

typedef struct test_rng {
    uint64_t s[4];
} test_rng;

static inline uint64_t test_rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
static inline uint64_t test_rng_next(test_rng *r)
{
    uint64_t *s = r->s, res = test_rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
    s[2] ^= s[0]; s[3] ^= s[1]; s[1] ^= s[2]; s[0] ^= s[3]; s[2] ^= t; s[3] = test_rotl(s[3], 45);
    return res;
}
static inline test_rng test_rng_seed(uint64_t seed)
{
    test_rng r;
    for (int i = 0; i < 4; ++i) { /* splitmix64 */
        uint64_t z = (seed += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        r.s[i] = z ^ (z >> 31);
    }
    return r;
}
/* Uniform in [0, 1). */
static inline double test_uniform(test_rng *r) { return (double)(test_rng_next(r) >> 11) * 0x1.0p-53; }
/* Uniform in [lo, hi). */
static inline double test_range(test_rng *r, double lo, double hi) { return lo + (hi - lo) * test_uniform(r); }
/* Uniform unit vector. */
static inline prox_vec3 test_unit(test_rng *r)
{
    for (;;) {
        prox_vec3 v = prox_v3(test_range(r, -1, 1), test_range(r, -1, 1), test_range(r, -1, 1));
        double n = prox_v3_norm(v);
        if (n > 1e-3 && n <= 1.0) return prox_v3_scale(v, 1.0 / n);
    }
}
/* A uniformly random rotation as a 3x3 matrix (Shoemake quaternion). */
typedef struct test_rot {
    double m[3][3];
} test_rot;
static inline test_rot test_random_rot(test_rng *r)
{
    double u1 = test_uniform(r), u2 = 2 * PROX_PI * test_uniform(r), u3 = 2 * PROX_PI * test_uniform(r);
    double a = sqrt(1 - u1), b = sqrt(u1);
    double w = a * sin(u2), x = a * cos(u2), y = b * sin(u3), z = b * cos(u3);
    test_rot R = {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                   {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                   {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
    return R;
}
static inline prox_vec3 test_rot_apply(const test_rot *R, prox_vec3 v)
{
    return prox_v3(R->m[0][0] * v.x + R->m[0][1] * v.y + R->m[0][2] * v.z,
                   R->m[1][0] * v.x + R->m[1][1] * v.y + R->m[1][2] * v.z,
                   R->m[2][0] * v.x + R->m[2][1] * v.y + R->m[2][2] * v.z);
}

/* A random macrobody of kind 0 (RCC), 1 (BOX) or 2 (SPH) at c, every size log-uniform over
 * 1e-3 .. 1e3 and a random orientation: the extreme-aspect sweeps. */
static inline prox_shape test_extreme_shape(test_rng *g, int kind, prox_vec3 c)
{
    if (kind == 0) {
        prox_vec3 axis = prox_v3_scale(test_unit(g), pow(10.0, test_range(g, -3, 3)));
        prox_rcc x = {c, axis, pow(10.0, test_range(g, -3, 3))};
        return prox_shape_from_rcc(x);
    }
    if (kind == 1) {
        test_rot R = test_random_rot(g);
        prox_box b;
        b.corner = c;
        for (int k = 0; k < 3; ++k)
            b.edge[k] = prox_v3_scale(test_rot_apply(&R, prox_v3(k == 0, k == 1, k == 2)),
                                      pow(10.0, test_range(g, -3, 3)));
        return prox_shape_from_box(b);
    }
    prox_sph s = {c, pow(10.0, test_range(g, -3, 3))};
    return prox_shape_from_sph(s);
}

/* An extreme pair: *a of kind ka at the origin, *b of kind kb centred 10^-2 .. 10 times a's size
 * away in a random direction (close enough that both disjoint and overlapping pairs occur). */
static inline void test_extreme_pair(test_rng *g, int ka, int kb, prox_shape *a, prox_shape *b)
{
    *a = test_extreme_shape(g, ka, prox_v3(0, 0, 0));
    double sz = prox_shape_size(a);
    prox_vec3 cb = prox_v3_scale(test_unit(g), pow(10.0, test_range(g, -2, 1)) * sz);
    *b = test_extreme_shape(g, kb, cb);
}

/* A size log-uniform over 0.2 .. 10. */
static inline double test_lsize(test_rng *g) { return exp(test_range(g, log(0.2), log(10.0))); }

/* A random solid of any of the ten kinds centred near c, sizes test_lsize, random orientation (RPP
 * axis-aligned; TRC a full cone one time in five; ARB a frustum of a rectangular pyramid). */
static inline prox_shape test_any_shape(test_rng *g, int kind, prox_vec3 c)
{
    double s[4];
    for (int k = 0; k < 4; ++k) s[k] = test_lsize(g);
    test_rot R = test_random_rot(g);
    prox_vec3 e0 = test_rot_apply(&R, prox_v3(1, 0, 0)), e1 = test_rot_apply(&R, prox_v3(0, 1, 0)), e2 = test_rot_apply(&R, prox_v3(0, 0, 1));
    prox_vec3 base = prox_v3_mad(c, -0.5 * s[0], e2);
    switch (kind) {
    case PROX_SHAPE_RCC: return prox_shape_from_rcc((prox_rcc){base, prox_v3_scale(e2, s[0]), 0.5 * s[1]});
    case PROX_SHAPE_BOX: {
        prox_box b = {c, {prox_v3_scale(e0, s[0]), prox_v3_scale(e1, s[1]), prox_v3_scale(e2, s[2])}};
        for (int k = 0; k < 3; ++k) b.corner = prox_v3_mad(b.corner, -0.5, b.edge[k]);
        return prox_shape_from_box(b);
    }
    case PROX_SHAPE_RPP:
        return prox_shape_from_rpp((prox_rpp){c.x - 0.5 * s[0], c.x + 0.5 * s[0], c.y - 0.5 * s[1], c.y + 0.5 * s[1], c.z - 0.5 * s[2],
                                              c.z + 0.5 * s[2]});
    case PROX_SHAPE_SPH: return prox_shape_from_sph((prox_sph){c, 0.5 * s[0]});
    case PROX_SHAPE_TRC: {
        prox_trc t = {base, prox_v3_scale(e2, s[0]), 0.5 * s[1], test_uniform(g) < 0.2 ? 0.0 : 0.5 * s[2]};
        if (t.r1 == t.r2) t.r2 *= 0.5;
        return prox_shape_from_trc(t);
    }
    case PROX_SHAPE_REC:
        return prox_shape_from_rec((prox_rec){base, prox_v3_scale(e2, s[0]), prox_v3_scale(e0, 0.5 * fmax(s[1], s[2])),
                                              prox_v3_scale(e1, 0.5 * fmin(s[1], s[2]))});
    case PROX_SHAPE_ELL: return prox_shape_from_ell((prox_ell){c, prox_v3_scale(e2, 0.5 * s[0]), 0.5 * s[1]});
    case PROX_SHAPE_RHP: {
        prox_rhp h;
        assert_int_equal(prox_rhp_regular(base, prox_v3_scale(e2, s[0]), prox_v3_scale(e0, 0.5 * s[1]), &h), PROX_OK);
        return prox_shape_from_rhp(h);
    }
    case PROX_SHAPE_WED: {
        double a = test_range(g, 0.3, 2.8);
        prox_wed w = {prox_v3_mad(base, -0.3 * s[1], e0), prox_v3_scale(e0, s[1]),
                      prox_v3_scale(prox_v3_add(prox_v3_scale(e0, cos(a)), prox_v3_scale(e1, sin(a))), s[2]), prox_v3_scale(e2, s[0])};
        return prox_shape_from_wed(w);
    }
    default: { /* ARB: a frustum, the top rectangle the bottom one scaled by f */
        prox_arb x = {{{0}}, {1234, 5678, 1265, 2376, 3487, 4158}};
        double f = test_range(g, 0.2, 1.5);
        static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        for (int i = 0; i < 4; ++i) {
            prox_vec3 q = prox_v3_add(prox_v3_scale(e0, 0.5 * s[1] * sx[i]), prox_v3_scale(e1, 0.5 * s[2] * sy[i]));
            x.corner[i] = prox_v3_add(base, q);
            x.corner[i + 4] = prox_v3_add(prox_v3_mad(base, s[0], e2), prox_v3_scale(q, f));
        }
        return prox_shape_from_arb(x);
    }
    }
}

/* Call first in every test main: the library must never rely on GSL's aborting handler. */
static inline void test_init(void) { gsl_set_error_handler_off(); }

#endif
