/* Internal: validators that also hand back what they had to compute, for hot query paths. */
#ifndef PROX_CORE_VALIDATE_H
#define PROX_CORE_VALIDATE_H

#include "prox/shapes.h"

/* prox_rcc_validate, also returning the height |axis| in *h (0 when the cylinder is rejected). */
prox_status prox_rcc_validate_h(const prox_rcc *c, double *h);

#endif
