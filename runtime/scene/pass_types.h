/* pass_types.h — the types the generated passes work in: the precision of their working
 * arrays (sph_real), the layout of a particle's tensors in them (SPH_ROW, SPH_TENSOR), short
 * vectors of the CPU's pair passes, and the time they read (sph_time). */
#ifndef SPHRT_SCENE_PASS_TYPES_H
#define SPHRT_SCENE_PASS_TYPES_H

#include <stddef.h>

/* Entry (r, c) of particle i's D x D tensor Q or Cv (the pair passes' working arrays, which
 * only generated code reads), of n particles.  The CPU target stores a particle's tensor
 * column by column, each column padded with zeros to SPH_ROW(D) entries, so that its pair
 * loops handle a column as one short vector (templates/body_forces.c); the CUDA target
 * stores it entry by entry, a structure of arrays (cuda/target.h defines SPH_TENSOR first), so
 * that a warp's threads read consecutive words.  A per-particle tensor takes
 * SPH_TENSOR_SIZE(D) entries on the CPU, D * D on the device; the offset table of kernel
 * gradients wtab holds SPH_ROW(D) entries per offset on both. */
#define SPH_ROW(D) ((D) == 3 ? 4 : (D))
#define SPH_TENSOR_SIZE(D) ((D) * SPH_ROW(D))
#ifndef SPH_TENSOR
#define SPH_TENSOR(i, r, c, D, n) (((size_t)(i) * (D) + (size_t)(c)) * SPH_ROW(D) + (size_t)(r))
#endif
/* A short vector of R sph_real (GCC's and Clang's vector extensions), in which the CPU pair
 * passes hold a row of A, a column of Q or Cv, or a table entry: whole-vector arithmetic,
 * a scalar operand standing for R copies of itself.  Aligned like sph_real and aliasing it,
 * so it loads from any place in those arrays. */
#define SPH_VECTOR(name, R)                                                                    \
    typedef sph_real name                                                                      \
        __attribute__((vector_size((R) * sizeof(sph_real)), aligned(sizeof(sph_real)), may_alias))

/* Two doubles, aligned like one, aliasing double: the x and y components of a particle's
 * velocity or acceleration (runs of D doubles) in one vector load or store (the CPU's pair
 * passes). */
#ifndef __CUDACC__
typedef double sph_double2
    __attribute__((vector_size(2 * sizeof(double)), aligned(sizeof(double)), may_alias));
#endif

/* A time the passes read, t or dt: a double on the CPU; in the CUDA target (cuda/target.h
 * defines it first) a reference to the device's clock, which the device advances itself. */
#ifndef SPH_TIME_DEFINED
typedef double sph_time;
#endif

/* Precision of the pair passes' working arrays: the offset tables, A, Q and Cv.  double,
 * or float in the runtime built with SPH_SINGLE (libsphrt_single), which programs of models
 * with `precision single` link (their generated code defines SPH_SINGLE).  Positions,
 * displacements, velocities, accelerations, F, the material law and the time integration
 * are double in both. */
#ifdef SPH_SINGLE
typedef float sph_real;
#else
typedef double sph_real;
#endif

#endif
