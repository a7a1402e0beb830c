/// @file cells.h
/// The cell model of an MCNP deck: every surface as a quadric or a torus, every cell as a Boolean
/// expression over surface senses, universes and the windows they fill. Read from a deck by
/// prox_cells_read_file; checked for overlaps and gaps by prox_cells_check (cellcheck.h).
///
/// Surfaces. Every MCNP surface card and every macrobody facet becomes a prox_surf: a quadric in
/// MCNP's GQ form (planes, spheres, cylinders, cones, SQ, GQ, the point-defined X/Y/Z, macrobody
/// facets) or an elliptic torus (TX/TY/TZ), placed in the frame of the universe whose cells use it
/// (TRn on the surface card, TRCL of the cell and FILL transforms already applied). The value f(x) is
/// negative on the surface's negative side. Each surface keeps a local origin o (f is written in
/// x - o) so that a surface far from the global origin keeps its relative precision.
///
/// Cells. A cell's region is a postfix (RPN) expression over surface senses with AND, OR and NOT:
/// intersections, unions (`:`), complements (`#n`, `#(...)`) and macrobodies (a macrobody's inside
/// is the AND of its facets' negative sides, every macrobody being convex) are all expanded by the
/// reader, so a region needs nothing else to be evaluated. LIKE n BUT is resolved by the reader.
#ifndef PROX_CELLS_H
#define PROX_CELLS_H

#include <stddef.h>

#include "deck.h"
#include "shapes.h"
#include "status.h"
#include "vec3.h"

/// Kind of a surface.
typedef enum prox_surf_kind {
    PROX_SURF_QUADRIC = 0, ///< f = q0 x^2 + q1 y^2 + q2 z^2 + q3 xy + q4 yz + q5 zx + q6 x + q7 y + q8 z + q9
    PROX_SURF_TORUS        ///< f = ((x.w)/B)^2 + ((|x - (x.w) w| - A)/C)^2 - 1 (x relative to o)
} prox_surf_kind;

/// One surface (or one macrobody facet) in the frame of the universe that uses it.
typedef struct prox_surf {
    prox_surf_kind kind;
    prox_vec3 o;   ///< local origin: f is evaluated at x - o
    double q[10];  ///< quadric coefficients, GQ order A B C D E F G H J K, in x - o
    prox_vec3 w;   ///< torus: unit axis
    double ta, tb, tc; ///< torus: A (major radius), B (semi-axis along w), C (semi-axis across)
    long number;   ///< surface number as written
    int facet;     ///< macrobody facet k of an `n.k` reference or of an expanded macrobody; 0 otherwise
    int line;      ///< line of the surface card
    char card[8];  ///< mnemonic, upper case ("PZ", "RCC", ...)
} prox_surf;

/// Operation of one term of a region expression (postfix: operands come first).
typedef enum prox_op {
    PROX_OP_LEAF = 0, ///< push: surface `surf` with sense `sense`
    PROX_OP_AND,      ///< pop two, push their intersection
    PROX_OP_OR,       ///< pop two, push their union
    PROX_OP_NOT,      ///< pop one, push its complement
    PROX_OP_ALL       ///< push: all space (the region of a cell card with no surfaces)
} prox_op;

/// One term of a region expression.
typedef struct prox_term {
    prox_op op;
    int sense;   ///< PROX_OP_LEAF: -1 the negative side (f < 0), +1 the positive side (f > 0)
    size_t surf; ///< PROX_OP_LEAF: index into prox_cell_model.surfs
} prox_term;

/// Lattice type of a cell (LAT keyword).
typedef enum prox_lat_kind { PROX_LAT_NONE = 0, PROX_LAT_HEX = 1, PROX_LAT_HEXPRISM = 2 } prox_lat_kind;

/// One cell, its region in the frame of its universe.
typedef struct prox_cell {
    long number;     ///< cell number
    int line;        ///< line of the cell card
    long material;   ///< 0 for void
    double density;  ///< as written (negative: g/cm^3), 0 for void
    long universe;   ///< U (0: the real world)
    int outside;     ///< 1 when every importance given is 0 (the outside world beyond the model)
    size_t expr;     ///< first term of the region in prox_cell_model.terms
    size_t nexpr;    ///< number of terms
    long fill;       ///< universe filled into the cell (0: none; lattices: see the model's windows)
    prox_lat_kind lat; ///< a lattice fills all space of its universe: its region (expr) is all space,
                       ///< and the region as written, element (0,0,0), is elem_expr / elem_nexpr
    int unchecked;   ///< 1 when the cell's region could not be built: it uses a surface prox cannot
                     ///< model (listed in unchecked) or its geometry has an error (listed in errors);
                     ///< its region is then empty (it claims no point)
    size_t elem_expr;  ///< lattice cells: element (0,0,0), the region as written (else equal to expr)
    size_t elem_nexpr;
} prox_cell;

/// A window: where a universe is used, as a region in that universe's own frame. Within each window
/// the universe's cells must claim every point exactly once. The real world (universe 0) has one
/// window: all space. A filled cell gives its region mapped into the filling universe's frame; a
/// lattice gives one element's region for each distinct universe its fill array names.
typedef struct prox_window {
    long universe;   ///< universe that must fill the window
    size_t cell;     ///< index of the filling (or lattice) cell; (size_t)-1 for the real world
    size_t expr;     ///< region, in the universe's frame (terms; nexpr = 0: all space)
    size_t nexpr;
    /* Lattice windows only (the filling cell has LAT); zero elsewhere. The universe fills the element
     * region only where the element lies in a window of the lattice cell's own universe: the points
     * it must fill are, in its frame, x with place(x) in element (0,0,0) and place(x) + shift of some
     * element listed below in such a window (MCNP manual, LAT and FILL: every element is element
     * (0,0,0) moved by its lattice translation). */
    size_t nelem;      ///< elements that hold this (universe, placement); 0: every element (FILL=u),
                       ///< then listed (those that meet the parents' boxes) when bexpr is built
    long (*elem)[3];   ///< their indices (i, j, k), nelem of them (owned by the model)
    int nbasis;        ///< lattice translations known: 2 (open along the third axis) or 3; 0: unknown
    prox_vec3 basis[3]; ///< translation of the elements (1,0,0), (0,1,0), (0,0,1) (lattice cell's frame)
    double place_o[3], place_R[3][3]; ///< universe frame -> lattice cell's universe frame:
                                      ///< x' = place_o + place_R x (R[i][j] as TRn's)
    size_t bexpr, bnexpr; ///< those points as a region in the universe's frame (window_bound.c):
                          ///< expr AND the union over the elements of the parent windows moved into
                          ///< the universe's frame; bnexpr 0: not built (a bounded element, planes
                          ///< that are not lattice pairs, an unbounded parent, too large)
} prox_window;

/// What the reader could not model, listed once per kind with its count and first line.
typedef struct prox_unchecked {
    char what[PROX_DECK_TEXT]; ///< e.g. "surface card WED" or "cell keyword TMP"
    size_t count;
    int first_line;
} prox_unchecked;

/// The cell model of a deck. Start from {0}; release with prox_cells_free.
typedef struct prox_cell_model {
    char title[PROX_DECK_TEXT];
    prox_surf *surfs;
    size_t nsurfs;
    prox_term *terms;
    size_t nterms;
    prox_cell *cells;
    size_t ncells;
    prox_window *windows;
    size_t nwindows;
    prox_deck_note *errors; ///< malformed cards (line and reason); a deck with errors is not checked
    size_t nerrors;
    prox_unchecked *unchecked;
    size_t nunchecked;
} prox_cell_model;

/// Reads the cells and surfaces of the deck at `path` (READ FILE= followed as prox_deck_read_file).
/// Returns PROX_OK when the file was read (see m->nerrors), PROX_EINVAL_ARG, PROX_ENOMEM.
PROX_API prox_status prox_cells_read_file(const char *path, prox_cell_model *m);
/// The same from text held in memory (READ cards listed as unchecked).
PROX_API prox_status prox_cells_parse(const char *text, prox_cell_model *m);
/// Frees everything the model holds and zeroes it.
PROX_API void prox_cells_free(prox_cell_model *m);

/// f(x) of a surface (x in the frame of the surface's universe).
PROX_API double prox_surf_eval(const prox_surf *s, prox_vec3 x);

/// Exact membership of x in a region: 1 inside, 0 outside, -1 when x lies on a surface that decides
/// it (f(x) == 0 for a surface whose sense matters there).
PROX_API int prox_region_contains(const prox_cell_model *m, size_t expr, size_t nexpr, prox_vec3 x);
/// Exact membership of x in cell `cell` (an index into m->cells), as prox_region_contains.
PROX_API int prox_cell_contains(const prox_cell_model *m, size_t cell, prox_vec3 x);

/// The facets of a valid macrobody as surfaces, numbered as MCNP numbers them for `n.k` (facet k
/// is out[k-1]); the body is the intersection of every facet's negative side. Returns the count
/// (at most 8), fills only number-independent fields (kind, o, q, w, ta..tc, facet, card).
PROX_API int prox_shape_facets(const prox_shape *s, prox_surf out[8]);

#endif
