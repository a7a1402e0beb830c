/* Internal (cells): the regions of lattice windows bounded by their parents (window_bound.c). */
#ifndef PROX_CELLS_WINDOW_BOUND_H
#define PROX_CELLS_WINDOW_BOUND_H

#include "cells/check_internal.h"
#include "prox/cells.h"

/* For every lattice window whose element is open along an axis: the lattice's translations (basis),
 * its elements (a FILL=u lattice: those that meet the parents) and the region of the points its
 * universe must fill (bexpr), when they can be built. Appends surfaces and terms to the model. */
prox_status cells_bound_windows(prox_cell_model *m);

/* A box holding region [e, e + n): the side boxes of its surfaces combined over the tree, tightened
 * by the half-spaces of the planes it is the intersection of (tilted planes too: a linear programme
 * solved by its vertices). Unbounded axes are +-INFINITY. */
prox_ccbox cells_region_box(const prox_cell_model *m, size_t e, size_t n);

#endif
