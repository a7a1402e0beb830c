/// @file vec3.h
/// Three-vectors of doubles passed by value, with inline arithmetic.
#ifndef PROX_VEC3_H
#define PROX_VEC3_H

#include <math.h>

/// pi to double precision (C17 has no M_PI).
#define PROX_PI 3.14159265358979323846264338327950288

/// A point or direction in space.
typedef struct prox_vec3 {
    double x, y, z;
} prox_vec3;

/// Builds a vector from its components.
static inline prox_vec3 prox_v3(double x, double y, double z)
{
    prox_vec3 v = {x, y, z};
    return v;
}
/// a + b
static inline prox_vec3 prox_v3_add(prox_vec3 a, prox_vec3 b) { return prox_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
/// a - b
static inline prox_vec3 prox_v3_sub(prox_vec3 a, prox_vec3 b) { return prox_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
/// s a
static inline prox_vec3 prox_v3_scale(prox_vec3 a, double s) { return prox_v3(s * a.x, s * a.y, s * a.z); }
/// a + s b
static inline prox_vec3 prox_v3_mad(prox_vec3 a, double s, prox_vec3 b)
{
    return prox_v3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}
/// -a
static inline prox_vec3 prox_v3_neg(prox_vec3 a) { return prox_v3(-a.x, -a.y, -a.z); }
/// a . b
static inline double prox_v3_dot(prox_vec3 a, prox_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// a x b
static inline prox_vec3 prox_v3_cross(prox_vec3 a, prox_vec3 b)
{
    return prox_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/// |a|^2
static inline double prox_v3_norm2(prox_vec3 a) { return prox_v3_dot(a, a); }
/// |a|, overflow- and underflow-safe: sqrt of the sum of squares, with a hypot fallback only when
/// that sum overflows or underflows and a is not zero (glibc's hypot costs ~20 ns, this path ~2 ns).
static inline double prox_v3_norm(prox_vec3 a)
{
    double s = a.x * a.x + a.y * a.y + a.z * a.z;
    if (s < 1e300 && s > 1e-300) return sqrt(s);
    if (a.x == 0.0 && a.y == 0.0 && a.z == 0.0) return 0.0; /* common (a direction along an axis) */
    return hypot(hypot(a.x, a.y), a.z);
}
/// sqrt(x^2 + y^2) without glibc hypot's cost, falling back to it on overflow or underflow.
static inline double prox_hypot2(double x, double y)
{
    double s = x * x + y * y;
    if (s < 1e300 && s > 1e-300) return sqrt(s);
    return hypot(x, y);
}
/// |a - b|
static inline double prox_v3_dist(prox_vec3 a, prox_vec3 b) { return prox_v3_norm(prox_v3_sub(a, b)); }
/// a / |a|; the zero vector is returned unchanged. A vector shorter than 2^-1000 is first scaled up by
/// 2^600 (exact), so that 1 / |a| cannot overflow for a subnormal length.
static inline prox_vec3 prox_v3_normalize(prox_vec3 a)
{
    double n = prox_v3_norm(a);
    if (n < 0x1p-1000 && n > 0.0) {
        a = prox_v3_scale(a, 0x1p600);
        n = prox_v3_norm(a);
    }
    return n > 0.0 ? prox_v3_scale(a, 1.0 / n) : a;
}
/// Largest absolute component.
static inline double prox_v3_maxabs(prox_vec3 a)
{
    double m = fabs(a.x);
    if (fabs(a.y) > m) m = fabs(a.y);
    if (fabs(a.z) > m) m = fabs(a.z);
    return m;
}
/// True when every component is finite.
static inline int prox_v3_isfinite(prox_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
/// Component of a orthogonal to the unit vector u: a - (a.u) u.
static inline prox_vec3 prox_v3_reject(prox_vec3 a, prox_vec3 u) { return prox_v3_mad(a, -prox_v3_dot(a, u), u); }
/// A unit vector orthogonal to the unit vector u (stable branch choice).
static inline prox_vec3 prox_v3_any_perp(prox_vec3 u)
{
    prox_vec3 t = fabs(u.x) < 0.57735 ? prox_v3(1, 0, 0) : (fabs(u.y) < 0.57735 ? prox_v3(0, 1, 0) : prox_v3(0, 0, 1));
    return prox_v3_normalize(prox_v3_reject(t, u));
}

#endif
