/* The stress sphc derives from an energy-only law (derived2d.sph) against the
 * hand-written stress of the same energy (handwritten.sph), at random deformations (2 D). */
#define main generated_main
#include "derived2d.c"
#undef main

#define DIM 2
#include "derived_check.h"
