/* defs.h — what every part of the runtime and generated code share before anything else: the
 * markers of functions that run on the device too (SPH_HD, SPH_FN), are inlined into the
 * CPU's stress pass (SPH_FLAT) or never inlined (SPH_PIECE), loops without dependences
 * (SPH_IVDEP), C linkage for the CUDA target's C++ (SPH_C_BEGIN, SPH_C_END), the vector
 * math library's forms, and the smallest helpers: a compact vector's axis, the model
 * language's max and min. */
#ifndef SPHRT_CORE_DEFS_H
#define SPHRT_CORE_DEFS_H

#include <math.h>

/* The runtime's functions keep C linkage where the CUDA target (C++) includes them. */
#ifdef __cplusplus
#define SPH_C_BEGIN extern "C" {
#define SPH_C_END }
#else
#define SPH_C_BEGIN
#define SPH_C_END
#endif

/* Per-particle functions run on the host and, in the CUDA target, on the device: SPH_FN marks
 * the generated ones (material laws, boundary-condition values, user functions), SPH_HD the
 * runtime's helpers. */
#ifdef __CUDACC__
#define SPH_HD __host__ __device__
#else
#define SPH_HD
#endif
#define SPH_FN SPH_HD static inline
/* SPH_FLAT marks the generated functions of a particle's stress (the material law, its
 * caller): the CPU's stress pass inlines them into its loop over a block of particles,
 * whatever their size, so that the loop can be vectorised (templates/body_forces.c). */
#ifdef __CUDACC__
#define SPH_FLAT SPH_FN
#else
#define SPH_FLAT static inline __attribute__((always_inline))
#endif
/* SPH_PIECE marks the pieces of a large material law (more operations than sphc prints as one
 * function): each compiled once, called from the law's function, never inlined into it, and
 * by GCC at -O1, which takes half the time of -O3 on such straight-line code. */
#ifdef __CUDACC__
#define SPH_PIECE SPH_HD static __noinline__
#elif defined(__clang__) || !defined(__GNUC__)
#define SPH_PIECE static __attribute__((noinline))
#else
#define SPH_PIECE static __attribute__((noinline, optimize("O1")))
#endif
/* SPH_IVDEP, before a loop: no iteration depends on another (GCC's ivdep, Clang's
 * assume_safety), so the compiler need not prove that the arrays it touches never overlap. */
#if defined(__clang__)
#define SPH_IVDEP _Pragma("clang loop vectorize(assume_safety)")
/* (Clang says where such a loop stays scalar anyway: a law with a branch, 3D strides) */
#pragma clang diagnostic ignored "-Wpass-failed"
#elif defined(__GNUC__)
#define SPH_IVDEP _Pragma("GCC ivdep")
#else
#define SPH_IVDEP
#endif
/* glibc's vector math library (libmvec, which -lm links where it is used) has 2-, 4- and
 * 8-wide forms of these on x86-64; declared so, they let GCC vectorise the stress pass's
 * loop over a law that calls them (glibc's own headers declare them only under
 * -ffast-math).  Within 4 ulp, where the scalar ones are within 1. */
#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__) && defined(__x86_64__) &&  \
    defined(__GLIBC__) && !defined(__FAST_MATH__)
SPH_C_BEGIN
__attribute__((__simd__("notinbranch"))) double exp(double);
__attribute__((__simd__("notinbranch"))) double log(double);
__attribute__((__simd__("notinbranch"))) double pow(double, double);
__attribute__((__simd__("notinbranch"))) double sin(double);
__attribute__((__simd__("notinbranch"))) double cos(double);
SPH_C_END
#endif

SPH_C_BEGIN

/* Component k (0..dim-1) of a compact vector -> 3D axis (0 = x, 1 = y, 2 = z). */
SPH_HD static inline int sph_axis(int dim, int k) { return dim == 2 ? 2 * k : k; }

/* max and min of the model language (material laws, expressions): the larger or smaller of a
 * and b, and not a number where either is, so that a state gone wrong stays visible to the
 * stability checks.  Comparisons the compiler makes branch-free: C's fmax and fmin return the
 * other operand of a NaN, and on x86-64 they are library calls, which cost a fracture law's
 * stress pass a tenth of its time. */
SPH_HD static inline double sph_max(double a, double b) { return a > b || a != a ? a : b; }
SPH_HD static inline double sph_min(double a, double b) { return a < b || a != a ? a : b; }

SPH_C_END

#endif
