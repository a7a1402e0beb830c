/* Internal (cells): the pieces of the cell model reader. A surface card becomes a cells_sdef: one
 * or more prox_surf parts whose senses, ANDed, give the card's negative side (one part for an
 * ordinary surface; the facets of a macrobody; a quadric and a plane for a one-sheet cone). */
#ifndef PROX_CELLS_INTERNAL_H
#define PROX_CELLS_INTERNAL_H

#include <stddef.h>

#include "prox/cells.h"
#include "scene/deck_internal.h"

#define CELLS_MAXPARTS 8

typedef struct cells_sdef {
    int nparts;
    prox_surf part[CELLS_MAXPARTS];
    int in[CELLS_MAXPARTS]; /* the card's negative side is AND_k (side in[k] of part k) */
    int body;               /* a macrobody: `n.k` names part k-1 */
} cells_sdef;

/* Surface card with mnemonic mn (upper case) and entries v[0..nv), placed by t (NULL: none).
 * Returns 0 on success, 1 when mn is not a surface prox models (out untouched), -1 when the card is
 * malformed (reason in err). The parts' number/line fields are left to the caller. */
int cells_surface_card(const char *mn, const double *v, size_t nv, const prox_deck_tr *t, cells_sdef *out,
                       char *err, size_t errsz);

/* A quadric from its symmetric matrix A, linear part b and constant c, all in x - o. */
void cells_quadric(prox_surf *s, prox_vec3 o, double A[3][3], prox_vec3 b, double c);
/* The plane n.(x - o) = 0 (n need not be unit: it is normalised). */
void cells_plane(prox_surf *s, prox_vec3 o, prox_vec3 n);
/* The surface moved by t (r = o + R r'). */
prox_surf cells_surf_transform(const prox_surf *s, const prox_deck_tr *t);
/* Inverse and composition (a after b) of maps r = o + R r'. */
prox_deck_tr cells_tr_inverse(const prox_deck_tr *t);
prox_deck_tr cells_tr_compose(const prox_deck_tr *a, const prox_deck_tr *b);

#endif
