/* components.h — what a pair pass reads of its neighbours' u or v, copied component by
 * component (read through SPH_VEC, layout_switches.h). */
#ifndef SPHRT_CUDA_COMPONENTS_H
#define SPHRT_CUDA_COMPONENTS_H

#include "target.h"
#include "layout_switches.h"
#include "loops.h"

/* What a pair pass reads of its neighbours' u or v (D values a particle), by component:
 * s[r*n + i] = a[i*D + r] over all n particles (the halo's too, which has arrived), copied
 * by the pass that reads it, so that a warp's load of one component of 32 consecutive
 * neighbours touches 2 or 3 lines of 128 bytes instead of 6 or 7 (docs/cuda.md); returns
 * the array to read, through SPH_VEC(i, r, D, n).  With SPH_CUDA_AOS (layout_switches.h),
 * no copy: a itself, particle by particle. */
static const double *sph_cuda_components_in(const double *a, double *s, int n, int D,
                                             const char *pass)
{
    if constexpr (SPH_LAYOUT_AOS) {
        return a;
    } else {
        sph_for(n, pass, [=] __device__(int i) {
            for (int r = 0; r < D; r++)
                s[(size_t)r * (size_t)n + (size_t)i] = a[(size_t)i * (size_t)D + (size_t)r];
        });
        return s;
    }
}
#define sph_cuda_components(a, s, n, D) sph_cuda_components_in((a), (s), (n), (D), __func__)

#endif
