/// @file prox.h
/// Umbrella header of prox: exact proximity queries between MCNP macrobodies. It includes every
/// public header:
///  - vec3.h, status.h, version.h: vectors, status codes, the version;
///  - shapes.h: the macrobodies in MCNP's terms and their validators;
///  - result.h: one result type per question, shared by every pair and method;
///  - query.h: the generic queries for any pair of shapes (start here);
///  - solid.h: the same queries on solids prepared once (validated, their polytopes built);
///  - distance.h, sat.h: the cylinder pair's three methods, the verdict and the cross-check;
///  - support.h: support functions and the support-function signed distance of any pair;
///  - pairs.h: the advanced layer, each pair kind's specialised solver;
///  - primitives.h: point/segment/circle/disk/lateral-surface distance solvers (Agarwal's primitives);
///  - scene.h, deck.h: scenes with a broad phase, batch queries, the MCNP deck reader.
#ifndef PROX_PROX_H
#define PROX_PROX_H

#include "status.h"
#include "version.h"
#include "vec3.h"
#include "shapes.h"
#include "result.h"
#include "query.h"
#include "solid.h"
#include "distance.h"
#include "sat.h"
#include "support.h"
#include "pairs.h"
#include "primitives.h"
#include "scene.h"
#include "deck.h"
#include "cells.h"
#include "cellcheck.h"

#endif
