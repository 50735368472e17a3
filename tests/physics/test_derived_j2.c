/* Laws with state given as their energy only (derived_j2.sph, 3D): the derived stress at the
 * returned state against the hand-written one of handwritten.sph and a closed form
 * (derived_j2_check.h). */
#define main generated_main
#include "derived_j2.c"
#undef main

#define DIM 3
#include "derived_j2_check.h"
