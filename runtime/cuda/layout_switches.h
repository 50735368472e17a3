/* layout_switches.h — the CUDA target's benchmark-only layout switches.  Each, defined when a
 * program is built (-DNAME), replaces one choice of the device's memory layout by the one it
 * was measured against (bench/cuda's A/Bs, docs/cuda.md); programs sphc builds define none,
 * and the tests build them too (tests/compiler/codegen, DEFINE), so that they keep compiling
 * and giving the same results.  The rest of cuda/ reads them only through the constants below
 * (in `if constexpr`), so that its normal path has no #ifdef:
 *
 *   SPH_CUDA_AOS           the neighbours' u and v read particle by particle, from the state
 *                          itself, instead of from a copy by component (SPH_VEC below;
 *                          sph_cuda_components, components.h): SPH_LAYOUT_AOS.
 *   SPH_CUDA_LISTS         pair lists for every body, never the slot masks of a box
 *                          (sph_full_lists, full_lists.h): SPH_LAYOUT_LISTS.
 *   SPH_CUDA_SLOTS_BY_KEY  a lattice's fixed slots in the order of the offset table's keys
 *                          instead of their mean offset (sph_slot_ranks, full_lists.h):
 *                          SPH_LAYOUT_SLOTS_BY_KEY.
 *   SPH_CUDA_RECOMPUTE     a pair's kernel gradient from X_i - X_j instead of the offset
 *                          tables (templates/body_cuda.cu, which tests the macro itself); a
 *                          hole then reads particle i itself (sph_hole, slots.h):
 *                          SPH_LAYOUT_RECOMPUTE. */
#ifndef SPHRT_CUDA_LAYOUT_SWITCHES_H
#define SPHRT_CUDA_LAYOUT_SWITCHES_H

#include <cstddef>

#ifdef SPH_CUDA_AOS
#define SPH_LAYOUT_AOS 1
#else
#define SPH_LAYOUT_AOS 0
#endif

#ifdef SPH_CUDA_LISTS
#define SPH_LAYOUT_LISTS 1
#else
#define SPH_LAYOUT_LISTS 0
#endif

#ifdef SPH_CUDA_SLOTS_BY_KEY
#define SPH_LAYOUT_SLOTS_BY_KEY 1
#else
#define SPH_LAYOUT_SLOTS_BY_KEY 0
#endif

#ifdef SPH_CUDA_RECOMPUTE
#define SPH_LAYOUT_RECOMPUTE 1
#else
#define SPH_LAYOUT_RECOMPUTE 0
#endif

/* Component r of particle i's vector of D values, in the array a pair pass reads of its
 * neighbours' u or v (n particles; components.h): by component, or with SPH_CUDA_AOS
 * particle by particle. */
#ifdef SPH_CUDA_AOS
#define SPH_VEC(i, r, D, n) ((void)(n), (size_t)(i) * (size_t)(D) + (size_t)(r))
#else
#define SPH_VEC(i, r, D, n) ((size_t)(r) * (size_t)(n) + (size_t)(i))
#endif

#endif
