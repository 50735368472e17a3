/* The artificial viscosity's G_ij is eq. 60's under homogeneous deformations (3D). */
#define main generated_main
#include "viscous3d.c"
#undef main

#define DIM 3
#define FORCES block_forces
#include "viscous_scale_check.h"
