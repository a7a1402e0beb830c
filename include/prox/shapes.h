/// @file shapes.h
/// Solid primitives in MCNP's own terms (the ten macrobodies RCC, BOX, RPP, SPH, TRC, REC, ELL,
/// RHP/HEX, WED, ARB) and their validators. docs/algorithms/macrobodies.md gives the MCNP card
/// entries each one is read from and the facet numbering of `n.k` references.
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

/// Truncated right circular cone (TRC): base centre, axis vector from base to top (|axis| = height),
/// base radius r1 and top radius r2 (both >= 0, not equal, not both 0: r1 == r2 is an RCC).
typedef struct prox_trc {
    prox_vec3 base;
    prox_vec3 axis;
    double r1, r2;
} prox_trc;

/// Right elliptical cylinder (REC): base centre, axis vector (base to top), and the two semi-axis
/// vectors of the elliptical cross-section, a1 (major) and a2 (minor); axis, a1 and a2 are mutually
/// orthogonal. The 10-entry card form (a minor radius instead of a2) is prox_rec_from_radius.
typedef struct prox_rec {
    prox_vec3 base;
    prox_vec3 axis;
    prox_vec3 a1, a2;
} prox_rec;

/// Ellipsoid of revolution (ELL, MCNP's only ellipsoid): centre, semi-axis vector along the axis of
/// revolution (|axis| = that semi-axis, either longer or shorter than the other two) and the
/// equatorial radius. The card forms (foci and major radius; centre, axis and minor radius) are
/// prox_ell_from_foci and prox_ell_from_axis.
typedef struct prox_ell {
    prox_vec3 center;
    prox_vec3 axis;
    double radius;
} prox_ell;

/// Right hexagonal prism (RHP, alias HEX): base centre, height vector, and three vectors r[0..2] from
/// the axis to the middle of the first, second and third side facets (the 15-entry form; each
/// perpendicular to the height). The 9-entry form (r[1], r[2] = r[0] turned by 60 and 120 degrees
/// about the height) is prox_rhp_regular.
typedef struct prox_rhp {
    prox_vec3 base;
    prox_vec3 axis;
    prox_vec3 r[3];
} prox_rhp;

/// Wedge (WED): a right triangular prism: vertex, the two triangle side vectors v1 and v2 from it,
/// and the height vector v3 (perpendicular to v1 and v2).
typedef struct prox_wed {
    prox_vec3 vertex;
    prox_vec3 v1, v2, v3;
} prox_wed;

/// Arbitrary polyhedron (ARB): eight corners (unused ones are zero) and six faces, each a number of
/// four digits naming its corners 1-8, in any order (as MCNP reads them; three corners and a 0 for a
/// triangle; 0 for an unused face). The body must be convex with planar faces.
typedef struct prox_arb {
    prox_vec3 corner[8];
    int face[6];
} prox_arb;

/// Kind tag of a generic shape (new kinds are appended: the values are stable).
typedef enum prox_shape_kind {
    PROX_SHAPE_RCC = 0,
    PROX_SHAPE_BOX,
    PROX_SHAPE_RPP,
    PROX_SHAPE_SPH,
    PROX_SHAPE_TRC,
    PROX_SHAPE_REC,
    PROX_SHAPE_ELL,
    PROX_SHAPE_RHP,
    PROX_SHAPE_WED,
    PROX_SHAPE_ARB,
    PROX_SHAPE_KIND_COUNT_
} prox_shape_kind;

/// Any of the ten macrobodies.
typedef struct prox_shape {
    prox_shape_kind kind;
    union {
        prox_rcc rcc;
        prox_box box;
        prox_rpp rpp;
        prox_sph sph;
        prox_trc trc;
        prox_rec rec;
        prox_ell ell;
        prox_rhp rhp;
        prox_wed wed;
        prox_arb arb;
    } u;
} prox_shape;

/// The MCNP mnemonic of a kind ("RCC", ..., "RHP"; "?" for an unknown kind).
PROX_API const char *prox_shape_kind_name(prox_shape_kind k);

/// Supported range: |coordinate| <= PROX_MAX_COORD and every size (radius, height, edge length, RPP
/// extent) in [PROX_MIN_SIZE, PROX_MAX_COORD]. Within it no intermediate product of the solvers can
/// overflow or underflow; outside it the validators return PROX_EINVAL_RANGE.
#define PROX_MAX_COORD 1e100
#define PROX_MIN_SIZE 1e-100

/// The added macrobodies (TRC, REC, ELL, RHP/HEX, WED, ARB) also keep every dimension within a factor
/// PROX_MAX_ASPECT of their largest (a TRC's height and larger radius; a REC's height and semi-axes; an
/// ELL's two semi-axes; a polytope's width across each face and its diameter): a plate or a needle
/// thinner than that gives PROX_EINVAL_RANGE. Within it the solvers keep their stated accuracy.
#define PROX_MAX_ASPECT 1e12

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
/// Checks a TRC: finite data, height > 0, radii >= 0, not both 0 and not equal (PROX_EINVAL_TRC).
PROX_API prox_status prox_trc_validate(const prox_trc *t);
/// Checks a REC: finite data, non-zero axis and semi-axes, mutually orthogonal (PROX_EINVAL_REC_ORTHO).
PROX_API prox_status prox_rec_validate(const prox_rec *r);
/// Checks an ELL: finite data, non-zero axis, radius > 0.
PROX_API prox_status prox_ell_validate(const prox_ell *e);
/// Checks an RHP: finite data, non-zero height, each r[i] non-zero and perpendicular to the height,
/// and the six side planes bound a convex hexagon (PROX_EINVAL_RHP).
PROX_API prox_status prox_rhp_validate(const prox_rhp *h);
/// Checks a WED: finite data, non-zero vectors, v3 perpendicular to v1 and v2, v1 and v2 not
/// parallel (PROX_EINVAL_WED).
PROX_API prox_status prox_wed_validate(const prox_wed *w);
/// Checks an ARB: finite data, face numbers naming existing distinct corners (PROX_EINVAL_ARB_FACE),
/// planar faces (PROX_EINVAL_ARB_PLANAR), a convex closed body (PROX_EINVAL_ARB_CONVEX).
PROX_API prox_status prox_arb_validate(const prox_arb *a);
/// Checks a generic shape according to its kind.
PROX_API prox_status prox_shape_validate(const prox_shape *s);

/// The RPP as a BOX (corner at the minimum, edges along x, y, z).
PROX_API prox_box prox_rpp_to_box(const prox_rpp *r);

/// Generic shape constructors.
PROX_API prox_shape prox_shape_from_rcc(prox_rcc c);
PROX_API prox_shape prox_shape_from_box(prox_box b);
PROX_API prox_shape prox_shape_from_rpp(prox_rpp r);
PROX_API prox_shape prox_shape_from_sph(prox_sph s);
PROX_API prox_shape prox_shape_from_trc(prox_trc t);
PROX_API prox_shape prox_shape_from_rec(prox_rec r);
PROX_API prox_shape prox_shape_from_ell(prox_ell e);
PROX_API prox_shape prox_shape_from_rhp(prox_rhp h);
PROX_API prox_shape prox_shape_from_wed(prox_wed w);
PROX_API prox_shape prox_shape_from_arb(prox_arb a);

/// Card forms that MCNP allows beside the stored one (each returns PROX_OK or the validator's error):
/// REC with a minor radius r2 (10 entries): a2 = r2 (axis x a1) / |axis x a1|.
PROX_API prox_status prox_rec_from_radius(prox_vec3 base, prox_vec3 axis, prox_vec3 a1, double r2, prox_rec *out);
/// ELL with foci f1, f2 and major radius rm > 0 (prolate: requires rm > |f2 - f1| / 2).
PROX_API prox_status prox_ell_from_foci(prox_vec3 f1, prox_vec3 f2, double rm, prox_ell *out);
/// ELL with centre, major semi-axis vector and minor radius (the card's R < 0 form, |R| passed).
PROX_API prox_status prox_ell_from_axis(prox_vec3 center, prox_vec3 major, double rminor, prox_ell *out);
/// RHP of 9 entries: a regular hexagon, r[1] and r[2] are r turned by 60 and 120 degrees about axis.
PROX_API prox_status prox_rhp_regular(prox_vec3 base, prox_vec3 axis, prox_vec3 r, prox_rhp *out);

#endif
