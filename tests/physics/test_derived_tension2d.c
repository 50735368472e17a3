/* The S+ sphc derives from a tension block that gives psi+ only (derived_tension2d.sph)
 * against stdlib svk's written S+, and the degraded laws of both forms (2 D). */
#define main generated_main
#include "derived_tension2d.c"
#undef main

#define DIM 2
#include "derived_tension_check.h"
