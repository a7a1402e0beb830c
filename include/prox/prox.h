/// @file prox.h
/// Umbrella header of prox: exact proximity queries between MCNP macrobodies.
#ifndef PROX_PROX_H
#define PROX_PROX_H

#include "status.h"
#include "vec3.h"
#include "shapes.h"
#include "primitives.h"
#include "distance.h"

#endif
