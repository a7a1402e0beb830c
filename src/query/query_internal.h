/* Internal: entry points of query.c that hand back intermediate results to other parts of the
 * library (the scene's RELATION mode), so that a pair's dear solver runs once. */
#ifndef PROX_QUERY_QUERY_INTERNAL_H
#define PROX_QUERY_QUERY_INTERNAL_H

#include "prox/pairs.h"
#include "prox/query.h"

/* prox_shape_relation, also returning the signed distance it computed (normal and witness points
 * included) in *s when s is not NULL. */
prox_relation_result prox_shape_relation_with_signed(const prox_shape *a, const prox_shape *b, double tol,
                                                     prox_signed_result *s);

#endif
