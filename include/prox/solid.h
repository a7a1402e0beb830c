/// @file solid.h
/// Prepared solids: a macrobody validated once, with its polytope (BOX, RPP, RHP/HEX, WED, ARB) or its
/// support body (RCC, TRC, REC, ELL, SPH) built once, for programs that query the same solids many
/// times (a deck check's bodies, a planner's links against fixed obstacles). The queries answer
/// exactly as the generic prox_shape_* of query.h on the same shapes, bit for bit, through the same
/// solvers; they only skip the validation and the construction that the shape queries repeat on
/// every call. A solid is immutable once made and may be shared between threads.
#ifndef PROX_SOLID_H
#define PROX_SOLID_H

#include "result.h"
#include "shapes.h"

/// An opaque prepared solid.
typedef struct prox_solid prox_solid;

/// Validates s and prepares it. Returns NULL when s is NULL (status PROX_EINVAL_ARG), invalid (its
/// validator's status, as prox_shape_validate names it) or when memory runs out (PROX_ENOMEM);
/// *status (when not NULL) receives the status in every case.
PROX_API prox_solid *prox_solid_new(const prox_shape *s, prox_status *status);
/// Frees a solid (NULL is ignored).
PROX_API void prox_solid_free(prox_solid *s);
/// The shape the solid was made from.
PROX_API const prox_shape *prox_solid_shape(const prox_solid *s);

/// prox_shape_test on the solids' shapes (PROX_EINVAL_ARG for a NULL solid).
PROX_API prox_test_result prox_solid_test(const prox_solid *a, const prox_solid *b);
/// prox_shape_distance on the solids' shapes (PROX_EINVAL_ARG for a NULL solid).
PROX_API prox_distance_result prox_solid_distance(const prox_solid *a, const prox_solid *b);
/// prox_shape_signed_distance on the solids' shapes (PROX_EINVAL_ARG for a NULL solid).
PROX_API prox_signed_result prox_solid_signed_distance(const prox_solid *a, const prox_solid *b);

#endif
