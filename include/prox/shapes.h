/// @file shapes.h
/// Solid primitives in MCNP's own terms (macrobodies RCC, BOX, RPP, SPH) and their validators.
#ifndef PROX_SHAPES_H
#define PROX_SHAPES_H

#include "status.h"
#include "vec3.h"

/// Right circular cylinder: base centre, axis vector from base to top centre (|axis| = height), radius.
typedef struct prox_rcc {
    prox_vec3 base;
    prox_vec3 axis;
    double radius;
} prox_rcc;

/// General box: one corner and three mutually orthogonal edge vectors from it.
typedef struct prox_box {
    prox_vec3 corner;
    prox_vec3 edge[3];
} prox_box;

/// Axis-aligned rectangular parallelepiped: xmin xmax ymin ymax zmin zmax.
typedef struct prox_rpp {
    double xmin, xmax, ymin, ymax, zmin, zmax;
} prox_rpp;

/// Sphere: centre and radius.
typedef struct prox_sph {
    prox_vec3 center;
    double radius;
} prox_sph;

/// Kind tag of a generic shape.
typedef enum prox_shape_kind { PROX_SHAPE_RCC = 0, PROX_SHAPE_BOX, PROX_SHAPE_RPP, PROX_SHAPE_SPH } prox_shape_kind;

/// Any of the four macrobodies.
typedef struct prox_shape {
    prox_shape_kind kind;
    union {
        prox_rcc rcc;
        prox_box box;
        prox_rpp rpp;
        prox_sph sph;
    } u;
} prox_shape;

/// Supported range: |coordinate| <= PROX_MAX_COORD and every size (radius, height, edge length, RPP
/// extent) in [PROX_MIN_SIZE, PROX_MAX_COORD]. Within it no intermediate product of the solvers can
/// overflow or underflow; outside it the validators return PROX_EINVAL_RANGE.
#define PROX_MAX_COORD 1e100
#define PROX_MIN_SIZE 1e-100

/// Relative tolerance for box edge orthogonality: |e_i . e_j| <= tol |e_i| |e_j|.
#define PROX_BOX_ORTHO_TOL 1e-9

/// Checks a cylinder: finite data, radius > 0, axis length > 0.
PROX_API prox_status prox_rcc_validate(const prox_rcc *c);
/// Checks a box: finite data, non-zero and mutually orthogonal edges (relative tolerance).
PROX_API prox_status prox_box_validate(const prox_box *b);
/// Checks an RPP: finite bounds, min < max on each axis.
PROX_API prox_status prox_rpp_validate(const prox_rpp *r);
/// Checks a sphere: finite centre, radius > 0.
PROX_API prox_status prox_sph_validate(const prox_sph *s);
/// Checks a generic shape according to its kind.
PROX_API prox_status prox_shape_validate(const prox_shape *s);

/// The RPP as a BOX (corner at the minimum, edges along x, y, z).
PROX_API prox_box prox_rpp_to_box(const prox_rpp *r);

/// Generic shape constructors.
PROX_API prox_shape prox_shape_from_rcc(prox_rcc c);
PROX_API prox_shape prox_shape_from_box(prox_box b);
PROX_API prox_shape prox_shape_from_rpp(prox_rpp r);
PROX_API prox_shape prox_shape_from_sph(prox_sph s);

#endif
