/* particle_order.h — the order of a body's particles in memory (particle_order.c). */
#ifndef SPHRT_RUN_PARTICLE_ORDER_H
#define SPHRT_RUN_PARTICLE_ORDER_H

#include "core/defs.h"
#include "scene/body.h"

SPH_C_BEGIN

/* Sorts the body's own particles (X and gid; a halo stays after them) in slabs, lines and
 * points along three axes: see particle_order.c for which axis is the fastest. */
void sph_order_particles(sph_body *b);

SPH_C_END

#endif
