/* target.h — what the CUDA target sets before the runtime's shared headers
 * (scene/pass_types.h, scene/step_sums.h): a particle's tensors entry by entry, the time its
 * passes read the device clock's (device_clock.h), a body's step sums on the device
 * (sums.h); and the host emulation (emulate.h).  Every header of cuda/ includes it first. */
#ifndef SPHRT_CUDA_TARGET_H
#define SPHRT_CUDA_TARGET_H

#include "emulate.h"

/* Q and Cv entry by entry on the device (scene/pass_types.h): particle i's entry (r, c) at
 * (r*D + c)*n + i. */
#define SPH_TENSOR(i, r, c, D, n) ((size_t)((r) * (D) + (c)) * (size_t)(n) + (size_t)(i))
#define SPH_TIME_DEFINED /* sph_time: device_clock.h's, a value or the device clock's */
/* SPH_STEP_SUM, SPH_STEP_ONCE, SPH_STEP_SUM_OVER (templates/body_sums.c): sums.h's, a body's
 * step sums in its slots of b->red */
#define SPH_STEP_SUM_DEFINED

#endif
