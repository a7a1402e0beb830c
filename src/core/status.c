/* Status codes and their messages. */
#include "prox/status.h"
#include "prox/version.h"

PROX_API const char *prox_status_str(prox_status s)
{
    switch (s) {
    case PROX_OK: return "ok";
    case PROX_EINVAL_NONFINITE: return "invalid input: a coordinate, vector or size is NaN or infinite";
    case PROX_EINVAL_RADIUS: return "invalid input: radius must be positive";
    case PROX_EINVAL_AXIS: return "invalid input: cylinder axis (height vector) has zero length";
    case PROX_EINVAL_BOX_EDGE: return "invalid input: a box edge vector has zero length";
    case PROX_EINVAL_BOX_ORTHO: return "invalid input: box edge vectors are not mutually orthogonal";
    case PROX_EINVAL_RPP_BOUNDS: return "invalid input: RPP needs min < max on every axis";
    case PROX_EINVAL_ARG: return "invalid argument: null pointer or value out of range";
    case PROX_EINVAL_RANGE:
        return "invalid input: a coordinate or size is outside the supported range "
               "(|coordinate| <= 1e100, sizes 1e-100..1e100)";
    case PROX_EINVAL_SHAPE_KIND: return "invalid input: unknown shape kind";
    case PROX_ENUMERIC: return "numerical failure: an internal solver did not converge";
    case PROX_ENOMEM: return "out of memory";
    case PROX_EUNSUPPORTED: return "query not supported for this pair of shapes";
    case PROX_EINVAL_TRC: return "invalid input: TRC radii must be >= 0, not both 0 and not equal";
    case PROX_EINVAL_REC_ORTHO: return "invalid input: REC axis and semi-axis vectors are not mutually orthogonal";
    case PROX_EINVAL_ELL: return "invalid input: ELL major radius must exceed half the distance between the foci";
    case PROX_EINVAL_RHP:
        return "invalid input: RHP facet vectors must be perpendicular to the height and bound a convex hexagon";
    case PROX_EINVAL_WED: return "invalid input: WED triangle sides parallel or height not perpendicular to them";
    case PROX_EINVAL_ARB_FACE: return "invalid input: ARB face names a missing, repeated or unused corner";
    case PROX_EINVAL_ARB_PLANAR: return "invalid input: ARB face corners are not coplanar";
    case PROX_EINVAL_ARB_CONVEX: return "invalid input: ARB faces do not bound a convex closed body";
    case PROX_STATUS_COUNT_: break;
    }
    return "unknown status code";
}

PROX_API const char *prox_version(void) { return PROX_VERSION_STRING; }
