// prox_bench peers FCL 0.7 and Bullet 3.24 (Debian packages), for the run time against error
// comparison (docs/PERFORMANCE.md). Each cylinder is given to the peer in its own frame: centred,
// axis along z (FCL Cylinder(radius, length); Bullet btCylinderShapeZ with half extents (r, r, h/2)
// and margin 0), placed by a rigid transform taking z to the RCC axis. Bullet in Debian uses
// single-precision btScalar, so its answers carry float rounding.
#include <cmath>

#include <fcl/fcl.h>
#include <btBulletCollisionCommon.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "peers/peers.h"

namespace {

// Rotation taking +z to the unit vector w (Rodrigues about z x w; the antiparallel case flips x).
Eigen::Matrix3d rotation_z_to(const Eigen::Vector3d &w)
{
    Eigen::Vector3d z(0, 0, 1);
    return Eigen::Quaterniond::FromTwoVectors(z, w).toRotationMatrix();
}

struct Frame {
    Eigen::Matrix3d R;
    Eigen::Vector3d c;
    double h, r;
};

Frame frame_of(const prox_rcc *c)
{
    Eigen::Vector3d axis(c->axis.x, c->axis.y, c->axis.z);
    Frame f;
    f.h = axis.norm();
    f.R = rotation_z_to(axis / f.h);
    f.c = Eigen::Vector3d(c->base.x, c->base.y, c->base.z) + 0.5 * axis;
    f.r = c->radius;
    return f;
}

struct FclCfg {
    fcl::GJKSolverType solver;
    double tol;
};

void fcl_run(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    const FclCfg *c = static_cast<const FclCfg *>(cfg);
    Frame fa = frame_of(a), fb = frame_of(b);
    fcl::Cylinderd ca(fa.r, fa.h), cb(fb.r, fb.h);
    fcl::Transform3d ta = fcl::Transform3d::Identity(), tb = fcl::Transform3d::Identity();
    ta.linear() = fa.R, ta.translation() = fa.c;
    tb.linear() = fb.R, tb.translation() = fb.c;
    fcl::DistanceRequestd req(true, false, 0.0, 0.0, c->tol, c->solver);
    fcl::DistanceResultd res;
    fcl::distance(&ca, ta, &cb, tb, req, res);
    out->ok = std::isfinite(res.min_distance);
    out->value = res.min_distance > 0 ? res.min_distance : 0.0;
    out->intersect = res.min_distance <= 0;
    out->p1 = prox_v3(res.nearest_points[0][0], res.nearest_points[0][1], res.nearest_points[0][2]);
    out->p2 = prox_v3(res.nearest_points[1][0], res.nearest_points[1][1], res.nearest_points[1][2]);
    out->has_points = res.min_distance > 0;
}

const FclCfg k_fcl_cfg[] = {
    {fcl::GST_LIBCCD, 1e-2}, {fcl::GST_LIBCCD, 1e-4}, {fcl::GST_LIBCCD, 1e-6},
    {fcl::GST_LIBCCD, 1e-8}, {fcl::GST_LIBCCD, 1e-10}, {fcl::GST_LIBCCD, 1e-12},
    {fcl::GST_INDEP, 1e-2},  {fcl::GST_INDEP, 1e-4},  {fcl::GST_INDEP, 1e-6},
    {fcl::GST_INDEP, 1e-8},  {fcl::GST_INDEP, 1e-10}, {fcl::GST_INDEP, 1e-12},
};
const bench_method k_fcl[] = {
    {"fcl-gjk-libccd/tol=1e-2", BENCH_DIST, fcl_run, &k_fcl_cfg[0]},
    {"fcl-gjk-libccd/tol=1e-4", BENCH_DIST, fcl_run, &k_fcl_cfg[1]},
    {"fcl-gjk-libccd/tol=1e-6", BENCH_DIST, fcl_run, &k_fcl_cfg[2]},
    {"fcl-gjk-libccd/tol=1e-8", BENCH_DIST, fcl_run, &k_fcl_cfg[3]},
    {"fcl-gjk-libccd/tol=1e-10", BENCH_DIST, fcl_run, &k_fcl_cfg[4]},
    {"fcl-gjk-libccd/tol=1e-12", BENCH_DIST, fcl_run, &k_fcl_cfg[5]},
    {"fcl-gjk-indep/tol=1e-2", BENCH_DIST, fcl_run, &k_fcl_cfg[6]},
    {"fcl-gjk-indep/tol=1e-4", BENCH_DIST, fcl_run, &k_fcl_cfg[7]},
    {"fcl-gjk-indep/tol=1e-6", BENCH_DIST, fcl_run, &k_fcl_cfg[8]},
    {"fcl-gjk-indep/tol=1e-8", BENCH_DIST, fcl_run, &k_fcl_cfg[9]},
    {"fcl-gjk-indep/tol=1e-10", BENCH_DIST, fcl_run, &k_fcl_cfg[10]},
    {"fcl-gjk-indep/tol=1e-12", BENCH_DIST, fcl_run, &k_fcl_cfg[11]},
};

btTransform bt_transform(const Frame &f)
{
    btMatrix3x3 m(f.R(0, 0), f.R(0, 1), f.R(0, 2), f.R(1, 0), f.R(1, 1), f.R(1, 2), f.R(2, 0), f.R(2, 1), f.R(2, 2));
    return btTransform(m, btVector3(f.c[0], f.c[1], f.c[2]));
}

// GJK distance with zero margins; when the shapes overlap Bullet runs EPA and reports a negative
// distance (minus the penetration depth): a signed-distance method.
void bullet_run(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    Frame fa = frame_of(a), fb = frame_of(b);
    btCylinderShapeZ sa(btVector3(fa.r, fa.r, 0.5 * fa.h)), sb(btVector3(fb.r, fb.r, 0.5 * fb.h));
    sa.setMargin(0), sb.setMargin(0);
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector det(&sa, &sb, &simplex, &epa);
    btDiscreteCollisionDetectorInterface::ClosestPointInput in;
    in.m_transformA = bt_transform(fa);
    in.m_transformB = bt_transform(fb);
    btPointCollector res;
    det.getClosestPoints(in, res, nullptr);
    out->ok = res.m_hasResult && std::isfinite(res.m_distance);
    out->value = res.m_distance;
    out->intersect = res.m_distance <= 0;
    btVector3 pb = res.m_pointInWorld, pa = pb + res.m_normalOnBInWorld * res.m_distance;
    out->p1 = prox_v3(pa.x(), pa.y(), pa.z());
    out->p2 = prox_v3(pb.x(), pb.y(), pb.z());
    out->has_points = out->ok;
}

const bench_method k_bullet[] = {{"bullet-gjk-epa", BENCH_SIGNED, bullet_run, nullptr}};

} // namespace

extern "C" int bench_fcl_methods(const bench_method **out)
{
    *out = k_fcl;
    return int(sizeof k_fcl / sizeof k_fcl[0]);
}

extern "C" int bench_bullet_methods(const bench_method **out)
{
    *out = k_bullet;
    return int(sizeof k_bullet / sizeof k_bullet[0]);
}
