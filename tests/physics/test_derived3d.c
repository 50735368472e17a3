/* The stress sphc derives from an energy-only law (derived3d.sph) against the
 * hand-written stress of the same energy (handwritten.sph), at random deformations (3 D). */
#define main generated_main
#include "derived3d.c"
#undef main

#define DIM 3
#include "derived_check.h"
