/// @file version.h
/// The version of prox: the header's (what the application was compiled against) and the library's
/// (what it runs with).
#ifndef PROX_VERSION_H
#define PROX_VERSION_H

#include "status.h"

#define PROX_VERSION_MAJOR 0
#define PROX_VERSION_MINOR 2
#define PROX_VERSION_PATCH 0
#define PROX_VERSION_STRING "0.2.0"

/// The library's version, "MAJOR.MINOR.PATCH".
PROX_API const char *prox_version(void);

#endif
