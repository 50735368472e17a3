/* Laws with state given as their energy only (derived_j2_2d.sph, plane strain): the derived
 * stress at the returned state against the hand-written one of handwritten.sph and a
 * closed form (derived_j2_check.h). */
#define main generated_main
#include "derived_j2_2d.c"
#undef main

#define DIM 2
#include "derived_j2_check.h"
