/// @file cellcheck.h
/// The certified cell-level check of a deck's geometry: within each universe's windows (cells.h),
/// every point must lie in exactly one cell. prox_cells_check finds every overlap (a point in two
/// cells) and every gap (a point in no cell) larger than a resolution, and proves the rest clean down
/// to it; what it cannot decide at the resolution it lists as undecided. See docs/scene.md, "Cell
/// check".
///
/// The certificate: a box is clean when interval arithmetic with a rounding allowance proves that
/// every point of the box in the window lies in exactly one cell; an overlap (gap) box is proved to
/// lie wholly in two cells (in none). Every reported witness point is confirmed by exact membership
/// (prox_cell_contains). Any overlap or gap region that contains an axis-aligned cube of edge
/// 2 x resolution is reported (as a proved box or a confirmed witness point); thinner ones are
/// reported when a sample point confirms them, else listed as undecided.
#ifndef PROX_CELLCHECK_H
#define PROX_CELLCHECK_H

#include <stddef.h>

#include "cells.h"
#include "status.h"
#include "vec3.h"

/// Default resolution as a fraction of the diagonal of the model box: the box of the real world's
/// bounded cells and of the region its outside cells surround, widened by 1 % (prox_cells_report lo, hi).
#define PROX_CELLS_DEFAULT_RESOLUTION 1e-4

/// Most cells named by one undecided entry.
#define PROX_CELLS_UNDECIDED_MAX 8

/// Options of prox_cells_check. Zero-initialised options give the defaults.
typedef struct prox_cells_check_opts {
    double resolution; ///< edge of the finest box (model length units); <= 0: default fraction of the model diagonal
    int threads;       ///< worker threads; <= 0: 2
    int progress;      ///< nonzero: a progress line on stderr after 1 s when stderr is a terminal
} prox_cells_check_opts;

/// Two cells of a universe that share a region.
typedef struct prox_cells_overlap {
    long universe;
    long cells[2];      ///< cell numbers, cells[0] < cells[1]
    size_t index[2];    ///< the same cells as indices into prox_cell_model.cells
    prox_vec3 point;    ///< a point in both cells (universe frame), confirmed by exact membership
    double volume_min;  ///< proved lower bound on the shared volume (0: only the witness point is proved)
} prox_cells_overlap;

/// A region of a window that no cell of the universe claims.
typedef struct prox_cells_gap {
    long universe;
    long window_cell;   ///< number of the cell whose fill makes the window (0: the real world)
    prox_vec3 point;    ///< a point in no cell (universe frame), confirmed by exact membership
    double volume_min;  ///< proved lower bound on the gap's volume (0: only the witness point)
} prox_cells_gap;

/// Boxes of the resolution that the check could neither prove clean nor confirm as a finding.
typedef struct prox_cells_undecided {
    long universe;
    long cells[PROX_CELLS_UNDECIDED_MAX]; ///< cells involved (numbers), ncells of them
    size_t ncells;
    prox_vec3 lo, hi;   ///< the hull of the boxes (universe frame)
    size_t nboxes;
    double volume;      ///< total volume of the boxes (an upper bound on what they hide)
    const char *reason; ///< static text
} prox_cells_undecided;

/// Counters of one check.
typedef struct prox_cells_check_stats {
    size_t windows;      ///< windows checked
    size_t boxes;        ///< boxes evaluated
    size_t clean;        ///< boxes proved clean
    size_t leaves;       ///< boxes at the resolution that needed sample points
    double seconds;      ///< wall time
} prox_cells_check_stats;

/// Answer of prox_cells_check; free with prox_cells_report_free.
typedef struct prox_cells_report {
    prox_status status;
    double resolution;           ///< the resolution used
    prox_vec3 lo, hi;            ///< the model box: the part of the real world that is checked
    prox_cells_overlap *overlaps; ///< one per universe and cell pair, sorted
    size_t noverlaps;
    prox_cells_gap *gaps;        ///< one per connected gap region, sorted
    size_t ngaps;
    prox_cells_undecided *undecided; ///< one per universe and set of cells
    size_t nundecided;
    prox_cells_check_stats stats;
} prox_cells_report;

/// Checks every window of the model. Returns (and sets r->status) PROX_OK when the check ran,
/// PROX_EINVAL_ARG for null arguments, a model with errors or a malformed region, PROX_ENOMEM.
PROX_API prox_status prox_cells_check(const prox_cell_model *m, const prox_cells_check_opts *o, prox_cells_report *r);
/// Frees the lists of a report and zeroes it.
PROX_API void prox_cells_report_free(prox_cells_report *r);

#endif
