// prox_bench group "mix" peers FCL 0.7 and Bullet 3.24 (Debian packages): every solid becomes the
// peer's own shape in its own frame (FCL Sphere, Cylinder, Box, Cone, Ellipsoid, Convex; Bullet
// btSphereShape, btCylinderShapeZ, btBoxShape, btConeShapeZ, btConvexHullShape, all with zero
// margin where Bullet allows it), built once before timing and placed by a rigid transform, as a
// user of the peer does. FCL: distance with nearest points (GJK via libccd, tolerance 1e-6, the
// default) and signed distance (enable_signed_distance); Bullet: GJK with EPA when overlapping
// (single-precision btScalar in Debian's build).
#include <cmath>
#include <memory>
#include <vector>

#include <fcl/fcl.h>
#include <btBulletCollisionCommon.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "bench_mix.h"

namespace {

// ---- FCL ------------------------------------------------------------------------------------

struct FclSolid {
    std::shared_ptr<fcl::CollisionGeometryd> geom;
    fcl::Transform3d tf;
};

fcl::Transform3d fcl_pose(const mix_frame &f)
{
    fcl::Transform3d t = fcl::Transform3d::Identity();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) t.linear()(i, j) = f.R[i][j];
    t.translation() = Eigen::Vector3d(f.c.x, f.c.y, f.c.z);
    return t;
}

std::shared_ptr<fcl::CollisionGeometryd> fcl_convex(const mix_frame &f)
{
    auto verts = std::make_shared<std::vector<Eigen::Vector3d>>();
    for (int i = 0; i < f.nv; ++i) verts->emplace_back(f.v[i].x - f.c.x, f.v[i].y - f.c.y, f.v[i].z - f.c.z);
    auto faces = std::make_shared<std::vector<int>>();
    for (int k = 0; k < f.nf; ++k) {
        faces->push_back(f.fnv[k]);
        for (int j = 0; j < f.fnv[k]; ++j) faces->push_back(f.fv[k][j]);
    }
    return std::make_shared<fcl::Convexd>(verts, f.nf, faces);
}

void *fcl_prepare(const prox_shape *s)
{
    mix_frame f;
    if (!bench_mix_frame(s, &f)) return nullptr;
    auto *x = new FclSolid;
    x->tf = fcl_pose(f);
    switch (s->kind) {
    case PROX_SHAPE_SPH: x->geom = std::make_shared<fcl::Sphered>(f.size[0]); break;
    case PROX_SHAPE_RCC: x->geom = std::make_shared<fcl::Cylinderd>(f.size[0], f.size[1]); break;
    case PROX_SHAPE_BOX:
    case PROX_SHAPE_RPP: x->geom = std::make_shared<fcl::Boxd>(2 * f.size[0], 2 * f.size[1], 2 * f.size[2]); break;
    case PROX_SHAPE_TRC: x->geom = std::make_shared<fcl::Coned>(f.size[0], f.size[1]); break;
    case PROX_SHAPE_ELL: x->geom = std::make_shared<fcl::Ellipsoidd>(f.size[0], f.size[0], f.size[1]); break;
    case PROX_SHAPE_RHP:
    case PROX_SHAPE_WED:
    case PROX_SHAPE_ARB:
        x->geom = fcl_convex(f);
        x->tf = fcl::Transform3d::Identity();
        x->tf.translation() = Eigen::Vector3d(f.c.x, f.c.y, f.c.z);
        break;
    default: delete x; return nullptr;
    }
    return x;
}

struct FclCfg {
    bool signed_distance;
};

void fcl_run(const void *cfg, const void *pa, const void *pb, bench_answer *out)
{
    const FclCfg *c = static_cast<const FclCfg *>(cfg);
    const FclSolid *a = static_cast<const FclSolid *>(pa), *b = static_cast<const FclSolid *>(pb);
    fcl::DistanceRequestd req(true, c->signed_distance, 0.0, 0.0, 1e-6, fcl::GST_LIBCCD);
    fcl::DistanceResultd res;
    fcl::distance(a->geom.get(), a->tf, b->geom.get(), b->tf, req, res);
    out->ok = std::isfinite(res.min_distance);
    out->value = c->signed_distance ? res.min_distance : std::fmax(res.min_distance, 0.0);
    out->intersect = res.min_distance <= 0;
    out->p1 = prox_v3(res.nearest_points[0][0], res.nearest_points[0][1], res.nearest_points[0][2]);
    out->p2 = prox_v3(res.nearest_points[1][0], res.nearest_points[1][1], res.nearest_points[1][2]);
    out->has_points = res.min_distance > 0;
}

// FCL 0.7's signed distance of two spheres through libccd did not return in 120 s on these pairs.
int fcl_skip_signed(prox_shape_kind ka, prox_shape_kind kb) { return ka == PROX_SHAPE_SPH && kb == PROX_SHAPE_SPH; }

const FclCfg k_fcl_cfg[] = {{false}, {true}};
const mix_method k_fcl[] = {
    {"fcl/distance", BENCH_DIST, fcl_prepare, fcl_run, &k_fcl_cfg[0], nullptr},
    {"fcl/signed", BENCH_SIGNED, fcl_prepare, fcl_run, &k_fcl_cfg[1], fcl_skip_signed},
};

// ---- Bullet ---------------------------------------------------------------------------------

struct BtSolid {
    std::unique_ptr<btConvexShape> shape;
    btTransform tf;
};

void *bt_prepare(const prox_shape *s)
{
    mix_frame f;
    if (!bench_mix_frame(s, &f)) return nullptr;
    auto *x = new BtSolid;
    btMatrix3x3 m(f.R[0][0], f.R[0][1], f.R[0][2], f.R[1][0], f.R[1][1], f.R[1][2], f.R[2][0], f.R[2][1], f.R[2][2]);
    x->tf = btTransform(m, btVector3(f.c.x, f.c.y, f.c.z));
    switch (s->kind) {
    case PROX_SHAPE_SPH: x->shape.reset(new btSphereShape(f.size[0])); break; // the radius is its margin
    case PROX_SHAPE_RCC:
        x->shape.reset(new btCylinderShapeZ(btVector3(f.size[0], f.size[0], 0.5 * f.size[1])));
        x->shape->setMargin(0);
        break;
    case PROX_SHAPE_BOX:
    case PROX_SHAPE_RPP:
        x->shape.reset(new btBoxShape(btVector3(f.size[0], f.size[1], f.size[2])));
        x->shape->setMargin(0);
        break;
    case PROX_SHAPE_TRC:
        x->shape.reset(new btConeShapeZ(f.size[0], f.size[1]));
        x->shape->setMargin(0);
        break;
    case PROX_SHAPE_RHP:
    case PROX_SHAPE_WED:
    case PROX_SHAPE_ARB: {
        auto *h = new btConvexHullShape();
        for (int i = 0; i < f.nv; ++i) h->addPoint(btVector3(f.v[i].x - f.c.x, f.v[i].y - f.c.y, f.v[i].z - f.c.z), false);
        h->recalcLocalAabb();
        h->setMargin(0);
        x->shape.reset(h);
        x->tf = btTransform(btMatrix3x3::getIdentity(), btVector3(f.c.x, f.c.y, f.c.z));
        break;
    }
    default: delete x; return nullptr;
    }
    return x;
}

void bt_run(const void *cfg, const void *pa, const void *pb, bench_answer *out)
{
    (void)cfg;
    const BtSolid *a = static_cast<const BtSolid *>(pa), *b = static_cast<const BtSolid *>(pb);
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    btGjkPairDetector det(a->shape.get(), b->shape.get(), &simplex, &epa);
    btDiscreteCollisionDetectorInterface::ClosestPointInput in;
    in.m_transformA = a->tf;
    in.m_transformB = b->tf;
    btPointCollector res;
    det.getClosestPoints(in, res, nullptr);
    out->ok = res.m_hasResult && std::isfinite(res.m_distance);
    out->value = res.m_distance;
    out->intersect = res.m_distance <= 0;
    btVector3 q = res.m_pointInWorld, p = q + res.m_normalOnBInWorld * res.m_distance;
    out->p1 = prox_v3(p.x(), p.y(), p.z());
    out->p2 = prox_v3(q.x(), q.y(), q.z());
    out->has_points = out->ok;
}

const mix_method k_bt[] = {{"bullet/gjk-epa", BENCH_SIGNED, bt_prepare, bt_run, nullptr, nullptr}};

} // namespace

extern "C" int bench_mix_fcl_methods(const mix_method **out)
{
    *out = k_fcl;
    return int(sizeof k_fcl / sizeof k_fcl[0]);
}

extern "C" int bench_mix_bullet_methods(const mix_method **out)
{
    *out = k_bt;
    return int(sizeof k_bt / sizeof k_bt[0]);
}
