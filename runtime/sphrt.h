/* sphrt.h — the contract between generated model code and the sphc runtime (libsphrt).
 *
 * Generated code (model.c) fills an sph_model with the scene description and the
 * scene-specific passes (forces, boundary conditions, integrator), then calls sph_main().
 * The runtime builds particles, neighbour lists and kernel gradients, runs the time loop,
 * controls dt, monitors stability and writes the output.
 *
 * The one header generated code includes: the parts of the runtime it uses, each a header of
 * one job in the runtime's folders (docs/architecture.md), which the runtime's own files
 * include one by one.
 *
 * Conventions
 *  - Vectors of a body are stored compactly with `dim` components: in 2D (plane strain in
 *    the x–z plane) component 0 is x and component 1 is z; y is the constant out-of-plane
 *    coordinate `body->y_plane`.  sph_axis(dim, k) gives the 3D axis of component k.
 *  - Tensors of a body are stored per particle, row-major, dim×dim (`T[i*dim*dim + r*dim + c]`),
 *    except F, which is stored 3×3 (`F[i*9 + r*3 + c]`) so that 2D plane-strain values
 *    (F_yy = 1) and 3D values share one layout for output, and the pair passes' working
 *    tensors A, Q and Cv, whose rows or columns are padded for short vectors (SPH_TENSOR).
 *  - Pairs are stored per particle (CSR, both directions): nb_start[i] .. nb_start[i+1]-1,
 *    neighbour nb[p].  Everything that depends only on the reference offset X_i - X_j is
 *    looked up through nb_k[p] in small tables: wtab[k*SPH_ROW(dim) + c] = V_j dW/dX_i^c (the
 *    uncorrected kernel gradient times the neighbour volume; the corrected gradient is
 *    L_i · that) and gtab[k] (eq. 60, see run/setup.c).  On a particle lattice there are a few
 *    dozen distinct offsets, so a pair costs 8 bytes; otherwise the tables have one entry
 *    per pair.
 */
#ifndef SPHRT_H
#define SPHRT_H

#include <math.h>
#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "core/defs.h"        /* SPH_HD, SPH_FN, SPH_FLAT, SPH_IVDEP; sph_axis, sph_max */
#include "core/exit_codes.h"  /* the program's exit codes */
#include "core/kernel.h"      /* the kernels, a pair's V_j grad W */
#include "core/tensor3.h"     /* per-particle 3×3 helpers */
#include "core/message.h"     /* sph_error, sph_warning, sph_note */
#include "core/clock.h"       /* the wall clock */
#include "core/profile.h"     /* SPH_PASS, SPH_TIMED (--profile) */
#include "geom/region.h"      /* shapes and regions */
#include "geom/fill.h"        /* a region's particles */
#include "par/par.h"          /* the processes of a run, the halo's fields */
#include "scene/body_desc.h"  /* a body's description */
#include "scene/model.h"      /* the scene description: sph_model */
#include "scene/pass_types.h" /* sph_real, SPH_TENSOR, sph_time */
#include "scene/body.h"       /* a body's particles: sph_body */
#include "scene/state_arrays.h" /* a body's state from step to step */
#include "scene/sim.h"        /* a simulation: sph_sim */
#include "scene/point.h"      /* the variables of user expressions: sph_pt */
#include "pairs/neighbours.h" /* neighbour lists */
#include "pairs/gradients.h"  /* corrected kernel gradients */
#include "pairs/stencil.h"    /* the lattice stencil */
#include "pairs/offset_blocks.h" /* 3D offset blocks */
#include "pairs/quadratic.h"  /* the gradient exact for quadratic fields */
#include "contact/contact.h"  /* contact between bodies */
#include "run/main.h"         /* sph_main */
#include "run/setup.h"        /* a body's set-up, --whole-law */
#include "run/sim.h"          /* the simulation without the program */
#include "run/measure.h"      /* energies, measurements */
#include "run/clamp.h"        /* a clamp by mirror images */
#include "run/clamp_image.h"  /* what it does to one image, on either target */
#include "run/table.h"        /* reference solutions' tables */
#include "run/time_step.h"    /* the time step, eq. 64-66 */

#endif
