/* sph_cuda.h — what programs of the CUDA target (sphc --target cuda) use besides sphrt.h.
 * Header-only: it is compiled by nvcc with the generated model.cu, which links the same
 * host runtime (libsphrt) as the CPU target for set-up, the time loop and the outputs.
 *
 *  - SPH_FOR(i, n, { body }): the loop over particles of the generated passes, a device
 *    lambda run by one thread per particle (the CPU target writes the same body in an
 *    OpenMP loop); SPH_ONCE({ body }) the same on one thread.
 *  - SPH_FOR_MAX3(i, n, out, { ...; return sph_max3{x, y, z}; }): the same loop that also
 *    reduces out[k] = the maximum of the k-th value (x, y, z >= 0) per block, then once per
 *    block with an atomic: the |v|^2 and |a|^2 bounds of the time step (eq. 65-66) and the
 *    compression bound 1 / lambda_min^2.
 *  - SPH_FOR_SUM(i, n, out, { ...; return x; }): the same for *out += the sum of x.
 *  - The device view of a body: a copy of the host sph_body in managed memory, marked read
 *    mostly so that host and device each keep a copy of its page, whose arrays live in device
 *    memory; the generated code reads `b->u[...]` on either side and the device writes only
 *    arrays (its sums go to b->red).  The set-up (particles, pairs, kernel gradients,
 *    selections) stays on the host and is copied once; full pair lists (fb_*) replace the half
 *    lists, so that every thread sums the pairs of its own particle without atomics.
 *  - The device's clock (sph_clock): a batch of steps runs without the host, which chooses
 *    none of their time steps; the passes read t and dt from it (sph_time).
 *  - sph_cuda_reductions: the last step's sums back into the host body, the one wait of a
 *    batch; sph_cuda_monitor_sums: the stability monitor's sums (every 20 steps);
 *    sph_cuda_to_host: the state too, when the runtime reads it (outputs, or a monitor's
 *    closer look).
 *  - With SPH_CUDA_EMULATE the host compiler builds model.cu as C++ with the passes run
 *    serially on host memory: how the tests check the target's code without a GPU.
 *
 * The umbrella the generated model.cu includes: each part is a header of cuda/, of one job,
 * which includes cuda/target.h first (the device's tensor layout and time, set before the
 * headers shared with the CPU target); cuda/layout_switches.h gathers the benchmark-only
 * layout switches. */
#ifndef SPH_CUDA_H
#define SPH_CUDA_H

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>

#include "cuda/target.h"          /* SPH_TENSOR entry by entry, sph_time; the host emulation */
#include "sphrt.h"                /* what the CPU target uses too */
#include "cuda/layout_switches.h" /* benchmark-only layout switches */
#include "cuda/check.h"           /* SPH_CUDA_CHECK */
#include "cuda/slots.h"           /* a particle's pairs on the device: sph_slot */
#include "cuda/sums.h"            /* a body's sums on the device (SPH_RED_*) */
#include "cuda/device_clock.h"    /* the device's clock: sph_time */
#include "cuda/launch.h"          /* launches: waiting, the profile's events */
#include "cuda/loops.h"           /* SPH_FOR, SPH_FOR_MAX3, SPH_FOR_SUM, SPH_ONCE */
#include "cuda/memory.h"          /* device memory */
#include "cuda/halo.h"            /* the halo on many processes */
#include "cuda/full_lists.h"      /* the full pair lists, built on the host */
#include "cuda/view.h"            /* a body's device view: sph_cuda_body */
#include "cuda/components.h"      /* neighbours' u and v by component: SPH_VEC */
#include "cuda/transfer.h"        /* sums and state back to the host, checkpoints */
#include "cuda/advance.h"         /* a batch of steps on the device */

#endif
