/// @file status.h
/// Status codes: every public query reports one; invalid input is never answered with a number.
#ifndef PROX_STATUS_H
#define PROX_STATUS_H

#if defined(PROX_STATIC) || !defined(__GNUC__)
#define PROX_API
#else
#define PROX_API __attribute__((visibility("default")))
#endif

/// What went wrong, if anything.
typedef enum prox_status {
    PROX_OK = 0,              ///< success
    PROX_EINVAL_NONFINITE,    ///< a coordinate, vector or size is NaN or infinite
    PROX_EINVAL_RADIUS,       ///< radius is zero or negative
    PROX_EINVAL_AXIS,         ///< cylinder axis (height vector) has zero length
    PROX_EINVAL_BOX_EDGE,     ///< a box edge vector has zero length
    PROX_EINVAL_BOX_ORTHO,    ///< box edge vectors are not mutually orthogonal
    PROX_EINVAL_RPP_BOUNDS,   ///< RPP has min >= max on some axis
    PROX_EINVAL_ARG,          ///< a null pointer or an out-of-range argument
    PROX_EINVAL_RANGE,        ///< a coordinate or size outside the supported range (see shapes.h)
    PROX_EINVAL_SHAPE_KIND,   ///< unknown shape kind in a generic shape
    PROX_ENUMERIC,            ///< an internal numerical method failed (e.g. GSL's QR did not converge)
    PROX_ENOMEM,              ///< allocation failed
    PROX_EUNSUPPORTED,        ///< the query is not implemented for this pair of shapes
    PROX_EINVAL_TRC,          ///< TRC radii negative, both zero or equal
    PROX_EINVAL_REC_ORTHO,    ///< REC axis and semi-axis vectors not mutually orthogonal
    PROX_EINVAL_ELL,          ///< ELL foci form: major radius not longer than half the focal distance
    PROX_EINVAL_RHP,          ///< RHP facet vectors not perpendicular to the height or not a convex hexagon
    PROX_EINVAL_WED,          ///< WED vectors degenerate (parallel sides, height not perpendicular)
    PROX_EINVAL_ARB_FACE,     ///< ARB face number names a missing, repeated or unused corner
    PROX_EINVAL_ARB_PLANAR,   ///< ARB face corners not coplanar
    PROX_EINVAL_ARB_CONVEX,   ///< ARB faces do not bound a convex closed body
    PROX_STATUS_COUNT_
} prox_status;

/// A human-readable, static description of a status code.
PROX_API const char *prox_status_str(prox_status s);

#endif
