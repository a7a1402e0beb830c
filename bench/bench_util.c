/* prox_bench utilities: seeded RNG (xoshiro256** seeded by splitmix64, as the validation sets'
 * generator documents in tests/data/README.md), Shoemake's uniform random rotation,
 * validation-file readers and order statistics. Setup code only: never timed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

void *bench_xmalloc(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) {
        fprintf(stderr, "prox_bench: out of memory (%zu bytes)\n", bytes);
        exit(2);
    }
    return p;
}

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

uint64_t bench_rng_next(bench_rng *r)
{
    uint64_t *s = r->s, res = rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return res;
}

bench_rng bench_rng_seed(uint64_t seed)
{
    bench_rng r;
    for (int i = 0; i < 4; ++i) { /* splitmix64 */
        uint64_t z = (seed += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        r.s[i] = z ^ (z >> 31);
    }
    return r;
}

double bench_uniform(bench_rng *r) { return (double)(bench_rng_next(r) >> 11) * 0x1.0p-53; }
double bench_range(bench_rng *r, double lo, double hi) { return lo + (hi - lo) * bench_uniform(r); }
double bench_logrange(bench_rng *r, double lo, double hi) { return lo * exp(log(hi / lo) * bench_uniform(r)); }

prox_vec3 bench_unit(bench_rng *r)
{
    for (;;) {
        prox_vec3 v = prox_v3(bench_range(r, -1, 1), bench_range(r, -1, 1), bench_range(r, -1, 1));
        double n = prox_v3_norm(v);
        if (n > 1e-3 && n <= 1.0) return prox_v3_scale(v, 1.0 / n);
    }
}

bench_rot bench_random_rot(bench_rng *r)
{
    double u1 = bench_uniform(r), u2 = 2 * PROX_PI * bench_uniform(r), u3 = 2 * PROX_PI * bench_uniform(r);
    double a = sqrt(1 - u1), b = sqrt(u1);
    double w = a * sin(u2), x = a * cos(u2), y = b * sin(u3), z = b * cos(u3);
    bench_rot R = {{{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                    {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                    {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}}};
    return R;
}

prox_vec3 bench_rot_apply(const bench_rot *R, prox_vec3 v)
{
    return prox_v3(R->m[0][0] * v.x + R->m[0][1] * v.y + R->m[0][2] * v.z,
                   R->m[1][0] * v.x + R->m[1][1] * v.y + R->m[1][2] * v.z,
                   R->m[2][0] * v.x + R->m[2][1] * v.y + R->m[2][2] * v.z);
}

/* Reads up to `want` doubles from one non-comment line; returns how many were read. */
static int read_line_numbers(const char *line, double *v, int want)
{
    int k = 0;
    const char *p = line;
    while (k < want) {
        char *end;
        double x = strtod(p, &end);
        if (end == p) break;
        v[k++] = x;
        p = end;
    }
    return k;
}

size_t bench_read_pairs(const char *path, prox_rcc **a, prox_rcc **b)
{
    FILE *f = fopen(path, "r");
    *a = *b = NULL;
    if (!f) return 0;
    size_t n = 0, cap = 0;
    char line[1024];
    while (fgets(line, sizeof line, f)) {
        double v[14];
        if (line[0] == '#' || read_line_numbers(line, v, 14) != 14) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 1024;
            prox_rcc *na = realloc(*a, cap * sizeof **a), *nb = realloc(*b, cap * sizeof **b);
            if (!na || !nb) exit(2);
            *a = na, *b = nb;
        }
        (*a)[n] = (prox_rcc){prox_v3(v[0], v[1], v[2]), prox_v3(v[3], v[4], v[5]), v[6]};
        (*b)[n] = (prox_rcc){prox_v3(v[7], v[8], v[9]), prox_v3(v[10], v[11], v[12]), v[13]};
        ++n;
    }
    fclose(f);
    return n;
}

size_t bench_read_refs(const char *path, bench_ref **out)
{
    FILE *f = fopen(path, "r");
    *out = NULL;
    if (!f) return 0;
    size_t n = 0, cap = 0;
    char line[1024];
    while (fgets(line, sizeof line, f)) {
        double v[7];
        if (line[0] == '#' || read_line_numbers(line, v, 7) != 7) continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 1024;
            bench_ref *g = realloc(*out, cap * sizeof **out);
            if (!g) exit(2);
            *out = g;
        }
        (*out)[n++] = (bench_ref){v[0], prox_v3(v[1], v[2], v[3]), prox_v3(v[4], v[5], v[6])};
    }
    fclose(f);
    return n;
}

static int cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

double bench_quantile(double *v, size_t n, double q)
{
    if (n == 0) return NAN;
    qsort(v, n, sizeof *v, cmp_double);
    size_t k = (size_t)(q * (double)(n - 1) + 0.5);
    return v[k < n ? k : n - 1];
}
