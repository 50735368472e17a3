/* The S+ sphc derives from a tension block that gives psi+ only (derived_tension3d.sph)
 * against stdlib svk's written S+, and the degraded laws of both forms (3 D). */
#define main generated_main
#include "derived_tension3d.c"
#undef main

#define DIM 3
#include "derived_tension_check.h"
