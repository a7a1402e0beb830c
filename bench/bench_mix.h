/* prox_bench group "mix": every pair type of macrobodies, prox and the peer libraries on the same
 * pairs in the same run. A mix method prepares each solid once (a peer builds its own shape object and
 * pose, as its users do), then answers pairs of prepared solids. */
#ifndef PROX_BENCH_MIX_H
#define PROX_BENCH_MIX_H

#ifdef __cplusplus
extern "C" {
#endif

#include "bench_pairs.h"

typedef struct mix_method {
    const char *name; /* e.g. "fcl/signed", "coal/signed" */
    bench_kind kind;  /* BENCH_DIST, BENCH_SIGNED or BENCH_VERDICT */
    /* The method's own object for a solid; NULL when the method has no such shape. */
    void *(*prepare)(const prox_shape *s);
    /* One answer for two prepared solids. */
    void (*run)(const void *cfg, const void *a, const void *b, bench_answer *out);
    const void *cfg;
    /* Pair kinds the method is not run on (a known hang or failure of the peer), or NULL. */
    int (*skip)(prox_shape_kind ka, prox_shape_kind kb);
} mix_method;

/* Registers the group's cases (bench.c). */
void bench_group_mix(const bench_opts *o);

/* Peers, each returning its methods (0 when not built): FCL 0.7 distance and signed distance, Bullet
 * 3 GJK/EPA, libccd 2.1 GJK/MPR penetration with prox's support functions, Coal 3 (FCL's
 * successor; built with -DPROX_BENCH_COAL=ON). */
int bench_mix_fcl_methods(const mix_method **out);
int bench_mix_bullet_methods(const mix_method **out);
int bench_mix_ccd_methods(const mix_method **out);
int bench_mix_coal_methods(const mix_method **out);

/* A solid's frame for peers that place a canonical shape: rotation R (columns: the shape's local x,
 * y, z in world coordinates), centre c, and the canonical sizes: SPH r; RCC r, height; BOX/RPP half
 * extents; TRC base radius, height (apex form r2 = 0 only); ELL equatorial radius, polar semi-axis.
 * Polytopes (RHP, WED, ARB) give their corners (world coordinates) and face loops instead. Returns 0
 * for kinds a canonical peer shape cannot represent. */
typedef struct mix_frame {
    double R[3][3];
    prox_vec3 c;
    double size[3];
    int nv, nf;
    prox_vec3 v[12];
    int fnv[8];
    int fv[8][6];
} mix_frame;
int bench_mix_frame(const prox_shape *s, mix_frame *f);

#ifdef __cplusplus
}
#endif

#endif
