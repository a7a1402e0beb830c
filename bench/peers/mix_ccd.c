/* prox_bench group "mix" peer libccd 2.1: GJK and MPR intersection verdicts. libccd has no shapes
 * of its own: it runs on the caller's support function, here prox's exact one for every macrobody
 * (prox_shape_support_point) with the solid's reference point as MPR's interior point. */
#include <ccd/ccd.h>

#include "bench_mix.h"

static void *ccd_prepare(const prox_shape *s) { return (void *)s; }

static void ccd_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    prox_vec3 p = prox_shape_support_point(obj, prox_v3(dir->v[0], dir->v[1], dir->v[2]));
    out->v[0] = p.x, out->v[1] = p.y, out->v[2] = p.z;
}

static void ccd_center(const void *obj, ccd_vec3_t *out)
{
    prox_vec3 p = prox_shape_center(obj);
    out->v[0] = p.x, out->v[1] = p.y, out->v[2] = p.z;
}

static void ccd_run(const void *cfg, const void *a, const void *b, bench_answer *out)
{
    const int *mpr = cfg;
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd_support, ccd.support2 = ccd_support;
    ccd.center1 = ccd_center, ccd.center2 = ccd_center;
    ccd.max_iterations = 1000;
    ccd.mpr_tolerance = 1e-8;
    out->ok = 1;
    out->intersect = *mpr ? ccdMPRIntersect(a, b, &ccd) : ccdGJKIntersect(a, b, &ccd);
    out->value = out->intersect;
    out->has_points = 0;
}

static const int k_gjk = 0, k_mpr = 1;
static const mix_method k_methods[] = {
    {"ccd/gjk-verdict", BENCH_VERDICT, ccd_prepare, ccd_run, &k_gjk, NULL},
    {"ccd/mpr-verdict", BENCH_VERDICT, ccd_prepare, ccd_run, &k_mpr, NULL},
};

int bench_mix_ccd_methods(const mix_method **out)
{
    *out = k_methods;
    return (int)(sizeof k_methods / sizeof k_methods[0]);
}
