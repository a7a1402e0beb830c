/* Internal: validators that also hand back what they had to compute, for hot query paths. */
#ifndef PROX_CORE_VALIDATE_H
#define PROX_CORE_VALIDATE_H

#include "prox/shapes.h"

/* prox_rcc_validate, also returning the squared height |axis|^2 in *h2 (0 when the cylinder is
 * rejected); sqrt(*h2) is |axis| as prox_v3_norm gives it. */
prox_status prox_rcc_validate_h2(const prox_rcc *c, double *h2);

#endif
