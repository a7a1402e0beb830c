/* libccd 2.1 peer: GJK and MPR intersection tests with prox's cylinder support function
 * (prox_rcc_support_point, Eberly Sec. 3) and the cylinder centre as the MPR interior point. */
#include <ccd/ccd.h>

#include "peers/peers.h"

static void ccd_support(const void *obj, const ccd_vec3_t *dir, ccd_vec3_t *out)
{
    prox_vec3 p = prox_rcc_support_point((const prox_rcc *)obj, prox_v3(dir->v[0], dir->v[1], dir->v[2]));
    out->v[0] = p.x, out->v[1] = p.y, out->v[2] = p.z;
}

static void ccd_center(const void *obj, ccd_vec3_t *out)
{
    const prox_rcc *c = obj;
    prox_vec3 p = prox_v3_mad(c->base, 0.5, c->axis);
    out->v[0] = p.x, out->v[1] = p.y, out->v[2] = p.z;
}

/* A setting: algorithm (0 GJK, 1 MPR) and tolerance. */
typedef struct ccd_cfg {
    int mpr;
    double tol;
} ccd_cfg;

static void ccd_run(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    const ccd_cfg *c = cfg;
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd_support, ccd.support2 = ccd_support;
    ccd.center1 = ccd_center, ccd.center2 = ccd_center;
    ccd.max_iterations = 1000;
    ccd.mpr_tolerance = c->tol, ccd.epa_tolerance = c->tol;
    out->ok = 1;
    out->intersect = c->mpr ? ccdMPRIntersect(a, b, &ccd) : ccdGJKIntersect(a, b, &ccd);
    out->value = out->intersect;
    out->has_points = 0;
}

static const ccd_cfg k_cfg[] = {{0, 1e-4}, {1, 1e-4}, {1, 1e-8}, {1, 1e-12}};
static const bench_method k_methods[] = {
    {"ccd-gjk-intersect", BENCH_VERDICT, ccd_run, &k_cfg[0]},
    {"ccd-mpr-intersect/tol=1e-4", BENCH_VERDICT, ccd_run, &k_cfg[1]},
    {"ccd-mpr-intersect/tol=1e-8", BENCH_VERDICT, ccd_run, &k_cfg[2]},
    {"ccd-mpr-intersect/tol=1e-12", BENCH_VERDICT, ccd_run, &k_cfg[3]},
};

int bench_ccd_methods(const bench_method **out)
{
    *out = k_methods;
    return (int)(sizeof k_methods / sizeof k_methods[0]);
}
