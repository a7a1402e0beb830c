// prox_bench group "mix" peer Coal 3 (FCL's maintained successor; PyPI wheel `coal`, which installs
// its headers and library under site-packages/cmeel.prefix). Built only with -DPROX_BENCH_COAL=ON.
// Every solid becomes Coal's own shape in its own frame (Sphere, Cylinder, Box, Cone, Ellipsoid, and
// Convex<Triangle> with each face fanned into triangles), built once before timing and placed by a
// rigid transform. coal::distance with nearest points and signed distance (GJK, EPA when overlapping),
// Coal's defaults otherwise.
#include "bench_mix.h"

#ifdef PROX_BENCH_COAL
#include <cmath>
#include <memory>
#include <vector>

#include <coal/collision_data.h>
#include <coal/distance.h>
#include <coal/shape/convex.h>
#include <coal/shape/geometric_shapes.h>

namespace {

struct CoalSolid {
    std::shared_ptr<coal::CollisionGeometry> geom;
    coal::Transform3s tf;
};

std::shared_ptr<coal::CollisionGeometry> coal_convex(const mix_frame &f)
{
    auto pts = std::make_shared<std::vector<coal::Vec3s>>();
    for (int i = 0; i < f.nv; ++i) pts->emplace_back(f.v[i].x - f.c.x, f.v[i].y - f.c.y, f.v[i].z - f.c.z);
    auto tris = std::make_shared<std::vector<coal::Triangle>>();
    for (int k = 0; k < f.nf; ++k)
        for (int j = 1; j + 1 < f.fnv[k]; ++j)
            tris->emplace_back(coal::Triangle::index_type(f.fv[k][0]), coal::Triangle::index_type(f.fv[k][j]),
                               coal::Triangle::index_type(f.fv[k][j + 1]));
    unsigned np = unsigned(pts->size()), nt = unsigned(tris->size());
    return std::make_shared<coal::Convex<coal::Triangle>>(pts, np, tris, nt);
}

void *coal_prepare(const prox_shape *s)
{
    mix_frame f;
    if (!bench_mix_frame(s, &f)) return nullptr;
    auto *x = new CoalSolid;
    coal::Matrix3s R;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R(i, j) = f.R[i][j];
    x->tf = coal::Transform3s(R, coal::Vec3s(f.c.x, f.c.y, f.c.z));
    switch (s->kind) {
    case PROX_SHAPE_SPH: x->geom = std::make_shared<coal::Sphere>(f.size[0]); break;
    case PROX_SHAPE_RCC: x->geom = std::make_shared<coal::Cylinder>(f.size[0], f.size[1]); break;
    case PROX_SHAPE_BOX:
    case PROX_SHAPE_RPP: x->geom = std::make_shared<coal::Box>(2 * f.size[0], 2 * f.size[1], 2 * f.size[2]); break;
    case PROX_SHAPE_TRC: x->geom = std::make_shared<coal::Cone>(f.size[0], f.size[1]); break;
    case PROX_SHAPE_ELL: x->geom = std::make_shared<coal::Ellipsoid>(f.size[0], f.size[0], f.size[1]); break;
    case PROX_SHAPE_RHP:
    case PROX_SHAPE_WED:
    case PROX_SHAPE_ARB: x->geom = coal_convex(f); break;
    default: delete x; return nullptr;
    }
    x->geom->computeLocalAABB();
    return x;
}

void coal_run(const void *cfg, const void *pa, const void *pb, bench_answer *out)
{
    (void)cfg;
    const CoalSolid *a = static_cast<const CoalSolid *>(pa), *b = static_cast<const CoalSolid *>(pb);
    coal::DistanceRequest req(true, true);
    coal::DistanceResult res;
    coal::distance(a->geom.get(), a->tf, b->geom.get(), b->tf, req, res);
    out->ok = std::isfinite(res.min_distance);
    out->value = res.min_distance;
    out->intersect = res.min_distance <= 0;
    out->p1 = prox_v3(res.nearest_points[0][0], res.nearest_points[0][1], res.nearest_points[0][2]);
    out->p2 = prox_v3(res.nearest_points[1][0], res.nearest_points[1][1], res.nearest_points[1][2]);
    out->has_points = 1;
}

const mix_method k_coal[] = {{"coal/signed", BENCH_SIGNED, coal_prepare, coal_run, nullptr, nullptr}};

} // namespace

extern "C" int bench_mix_coal_methods(const mix_method **out)
{
    *out = k_coal;
    return int(sizeof k_coal / sizeof k_coal[0]);
}
#endif
