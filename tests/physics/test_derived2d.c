/* The stress sphc derives from an energy-only law (derived2d.sph) against the stdlib's
 * hand-written stress of the same energy, at random deformations (2 D). */
#define main generated_main
#include "derived2d.c"
#undef main

#define DIM 2
#include "derived_check.h"
