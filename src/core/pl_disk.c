/* The minimum over a disk of a convex piecewise-linear function of two variables (pl_disk.h): the
 * cover of the support-function depth (src/sat/convex.c) bounds phi over a cap of directions by it. */
#include "core/pl_disk.h"
#include "core/minmax.h"

#include <string.h>

typedef prox_v2 v2;


/* max_j a_j + b_j . x (2D) over the nj planes. */
static double pl_max(const double *a, const v2 *b, int nj, v2 x)
{
    double m = -INFINITY;
    for (int j = 0; j < nj; ++j) m = prox_max2(m, a[j] + prox_v2_dot(b[j], x));
    return m;
}

/* Exact minimum over the disk |x| <= r of the convex piecewise-linear M(x) = max_j a_j + b_j . x: at a
 * vertex of the arrangement inside the disk, at a single plane's lowest point on the circle, or where
 * two planes cross on the circle. */
double prox_pl_disk_min(const double *a, const v2 *b, int nj, double r)
{
    double m = INFINITY;
    for (int j = 0; j < nj; ++j) {
        double bn = prox_v2_norm(b[j]);
        v2 x = {0, 0};
        if (bn > 0.0) x.x = -b[j].x * r / bn, x.y = -b[j].y * r / bn;
        m = prox_min2(m, pl_max(a, b, nj, x));
        for (int k = j + 1; k < nj; ++k) {
            v2 e = prox_v2_sub(b[j], b[k]);
            double ee = prox_v2_dot(e, e), al = a[j] - a[k];
            if (!(ee > 0.0)) continue;
            v2 x0 = {-al * e.x / ee, -al * e.y / ee};
            double h2 = r * r - prox_v2_dot(x0, x0);
            if (h2 >= 0.0) {
                double h = sqrt(h2 / ee);
                v2 xp = {x0.x - h * e.y, x0.y + h * e.x}, xm = {x0.x + h * e.y, x0.y - h * e.x};
                m = prox_min2(m, prox_min2(pl_max(a, b, nj, xp), pl_max(a, b, nj, xm)));
            }
            for (int l = k + 1; l < nj; ++l) {
                v2 f = prox_v2_sub(b[j], b[l]);
                double det = prox_v2_cross(e, f), rl = a[l] - a[j], rk = a[k] - a[j];
                if (!(fabs(det) > 0.0)) continue;
                v2 x3 = {(rk * f.y - rl * e.y) / det, (e.x * rl - f.x * rk) / det};
                if (prox_v2_dot(x3, x3) <= r * r) m = prox_min2(m, pl_max(a, b, nj, x3));
            }
        }
    }
    return m;
}

/* The part of the convex polygon p[0..n) (in place, n returned) where b.x <= e. */
static int clip_half(v2 *p, int n, v2 b, double e)
{
    v2 q[16];
    int m = 0;
    for (int i = 0; i < n; ++i) {
        v2 u = p[i], v = p[(i + 1) % n];
        double su = prox_v2_dot(b, u) - e, sv = prox_v2_dot(b, v) - e;
        if (su <= 0.0) q[m++] = u;
        if ((su < 0.0 && sv > 0.0) || (su > 0.0 && sv < 0.0)) {
            double t = su / (su - sv);
            q[m++] = (v2){u.x + t * (v.x - u.x), u.y + t * (v.y - u.y)};
        }
    }
    memcpy(p, q, (size_t)m * sizeof q[0]);
    return m;
}

/* 1 when M(x) = max_j a_j + b_j . x >= t at every x of the disk |x| <= r: the polygon where every
 * plane is at most t, clipped from the square around the disk, is empty or misses the disk (its
 * closest point to the centre lies farther than r). The test of a cell near the optimum, cheaper
 * than M's exact minimum (prox_pl_disk_min). */
int prox_pl_disk_above(const double *a, const v2 *b, int nj, double r, double t)
{
    v2 p[16] = {{-r, -r}, {r, -r}, {r, r}, {-r, r}};
    int n = 4;
    for (int j = 0; j < nj && n > 0; ++j) n = clip_half(p, n, b[j], t - a[j]);
    if (n == 0) return 1;
    double r2 = r * r;
    int inside = n >= 3; /* the centre inside the polygon (counter-clockwise, as the square) */
    for (int i = 0; i < n; ++i) {
        v2 u = p[i], v = p[(i + 1) % n], e = prox_v2_sub(v, u);
        double ee = prox_v2_dot(e, e), w = ee > 0.0 ? prox_max2(0.0, prox_min2(1.0, -prox_v2_dot(u, e) / ee)) : 0.0;
        v2 x = {u.x + w * e.x, u.y + w * e.y};
        if (prox_v2_dot(x, x) <= r2) return 0; /* a point of the polygon in the disk */
        if (prox_v2_cross(e, (v2){-u.x, -u.y}) < 0.0) inside = 0;
    }
    return !inside;
}
