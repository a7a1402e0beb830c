/* Internal: the support-function engine shared by the SAT verdict, the signed distance of any two
 * macrobodies and the cross-check. Every macrobody is centrally symmetric, so a shape is kept as
 * its centre c plus a centred support function hc(d) = h(d) - d.c with hc(-d) = hc(d). For a pair,
 * phi(D) = h_A(D) + h_B(-D) = hcA(D) + hcB(D) - D.Delta, Delta = cB - cA, and sd = -min_{|D|=1} phi. */
#ifndef PROX_SAT_SUP_ENGINE_H
#define PROX_SAT_SUP_ENGINE_H

#include <stddef.h>

#include "prox/sat.h"
#include "prox/shapes.h"

enum { SUP_CYL = 0, SUP_BOX = 1, SUP_SPH = 2 };

/* A macrobody in centred form. */
typedef struct sup_body {
    int kind;
    prox_vec3 c;          /* centre */
    prox_vec3 w;          /* cylinder: unit axis */
    double r, hh;         /* cylinder: radius, half height; sphere: r = radius */
    prox_vec3 e[3];       /* box: unit edges */
    double ext[3];        /* box: half extents */
    double size;          /* largest dimension (tolerance scale) */
} sup_body;

/* Centred form of a valid shape. */
sup_body sup_body_make(const prox_shape *s);
/* Centred support function hc(d) (d need not be unit). */
double sup_hc(const sup_body *b, prox_vec3 d);
/* Centred support point: a point x of (body - c) with d.x = hc(d); sign(0) picks the face centre. */
prox_vec3 sup_pc(const sup_body *b, prox_vec3 d);

/* Witness points for the minimising unit direction n and signed distance sd: p1 in the support set
 * of a in n, p2 in that of b in -n, with p2 - p1 as close to sd n as the sets allow. */
void sup_witnesses(const sup_body *a, const sup_body *b, prox_vec3 n, double sd, prox_vec3 *p1, prox_vec3 *p2);

/* Penetration depth of two overlapping cylinders (both SUP_CYL) by enumerating the stationary
 * directions of each stratum (docs/algorithms/sat.md, "fast depth"); 1 and *res filled when every
 * stratum was either solved exactly or excluded by a lower bound, 0 when the caller must fall back
 * to the global search. *res always holds the best direction found (a valid upper bound). */
int sup_rcc_depth_enum(const sup_body *a, const sup_body *b, prox_signed_result *res);

/* Signed distance of two bodies (see the file comment); status is always PROX_OK. hint (may be
 * NULL): a direction to try first, e.g. a separating direction from the SAT. */
prox_signed_result sup_signed_distance(const sup_body *a, const sup_body *b, const prox_vec3 *hint);

/* Signed distance of two cylinders by the support-function method alone (both signs), started from
 * the SAT's separating direction: the independent method of prox_rcc_crosscheck. */
prox_signed_result sup_rcc_signed_support(const prox_rcc *a, const prox_rcc *b);

#endif
