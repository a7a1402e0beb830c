/* Internal (distance module): the entry points of the cylinder-pair distance methods, one function per
 * prox_method, which prox_rcc_distance_ex dispatches to. Each validates its own input and is exact on
 * its own; they share only the geometric core (src/core/), so comparing two of them is an independent
 * check (docs/design.md, "Three cylinder methods"). */
#ifndef PROX_DISTANCE_RCC_METHODS_H
#define PROX_DISTANCE_RCC_METHODS_H

#include "prox/result.h"
#include "prox/shapes.h"

/* PROX_METHOD_CLOSED_FORM (src/distance/rcc_closed_form.c, docs/algorithms/closed_form.md): Agarwal et
 * al.'s complete primitive decomposition. Every stationary pair of every feature pair is enumerated
 * (S-S, the four rim / lateral-surface pairs, the eight rim / disk pairs, the four rim pairs, the
 * degree-8 polynomial rooted by GSL's companion-matrix QR), the minimum is certified by the
 * support-function gap, and overlapping pairs get a common point checked in both solids.
 * Status: the validators' on invalid input, PROX_ENUMERIC when a polynomial could not be rooted. */
prox_distance_result prox_rcc_closed_form(const prox_rcc *a, const prox_rcc *b);

#endif
