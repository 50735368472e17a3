/* The artificial viscosity's G_ij is eq. 60's under homogeneous deformations (2D). */
#define main generated_main
#include "viscous2d.c"
#undef main

#define DIM 2
#define FORCES block_forces
#include "viscous_scale_check.h"
