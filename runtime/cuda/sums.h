/* sums.h — what the device sums of a body at every step (b->red[SPH_RED_*]): its step sums
 * (scene/step_sums.h: the time step's bounds, the viscosity's energy, ...) and the monitor's
 * checks. */
#ifndef SPHRT_CUDA_SUMS_H
#define SPHRT_CUDA_SUMS_H

#include "target.h"
#include "check.h"
#include "core/defs.h"
#include "scene/body.h"
#include "scene/step_sums.h"

/* The device's sums of a body, b->red[SPH_RED_*]: the step sums first, each at its row's index
 * (scene/step_sums.h: SPH_RED_<SLOT> = SPH_STEP_SUM_<member>), then the monitor's. */
enum {
#define SPH_RED_SLOT(member, SLOT, ...) SPH_RED_##SLOT = SPH_STEP_SUM_##member,
    SPH_STEP_SUMS(SPH_RED_SLOT)
#undef SPH_RED_SLOT
    /* the monitor's pass (templates/body_cuda.cu): the maxima of a particle's failed check
     * (0 or 1) and of 1 - lambda_min^2 (and a spare maximum), and the body's energy */
    SPH_RED_BAD = SPH_STEP_NSUMS, SPH_RED_SQUEEZE, SPH_RED_SPARE, SPH_RED_ENERGY,
    SPH_NRED
};
/* (the update's SPH_FOR_MAX3 writes its three maxima in a row: templates/body_cuda.cu) */
static_assert(SPH_RED_AMAX2 == SPH_RED_VMAX2 + 1 && SPH_RED_CRUSH == SPH_RED_VMAX2 + 2,
              "the update pass reduces max |v|^2, |a|^2 and 1 / lambda_min^2 into three slots");

/* Step sum k as the device holds it, from the host's value x (a minimum as its reciprocal,
 * scene/step_sums.h), and back. */
SPH_HD static inline double sph_red_of_host(int k, double x)
{
    return sph_step_sum_reduce(k) == SPH_REDUCE_MIN ? 1.0 / x : x;
}
SPH_HD static inline double sph_red_to_host(int k, double r)
{
    if (sph_step_sum_reduce(k) != SPH_REDUCE_MIN)
        return r;
    return r > 0 ? 1.0 / r : sph_step_sum_initial(k);
}

/* A body's smallest squared principal stretch from its sums (SPH_RED_CRUSH holds the largest
 * 1 / lambda^2; 0 before the first step of a body that does not track it: 1). */
SPH_HD static inline double sph_red_lam2min(const double *red)
{
    return sph_red_to_host(SPH_STEP_SUM_lam2min, red[SPH_RED_CRUSH]);
}

/* The step sums of host body h's last step as the device keeps them (the monitor's slots 0):
 * the next time step comes from them. */
static void sph_host_sums(const sph_body *h, double red[SPH_NRED])
{
    double x[SPH_STEP_NSUMS];
    sph_step_sums_get(h, x);
    for (int k = 0; k < SPH_NRED; k++)
        red[k] = k < SPH_STEP_NSUMS ? sph_red_of_host(k, x[k]) : 0;
}

/* The same onto the device view's sums (the monitor's left as they are). */
static void sph_host_sums_to_device(const sph_body *h, double *dev_red)
{
    double red[SPH_NRED];
    sph_host_sums(h, red);
    SPH_CUDA_CHECK(cudaMemcpy(dev_red, red, SPH_STEP_NSUMS * sizeof(double),
                              cudaMemcpyHostToDevice));
}

/* The words of templates/body_sums.c on the device (scene/step_sums.h has the CPU's): a step
 * sum is its slot of b->red, statements once are one thread's, and a sum over the particles
 * is a pass of SPH_FOR_SUM into the slot (one atomic add per block). */
#define SPH_STEP_SUM(b, member) ((b)->red[SPH_STEP_SUM_##member])
#define SPH_STEP_ONCE(...) SPH_ONCE(__VA_ARGS__)
#define SPH_STEP_SUM_OVER(b, member, i, ...)                                                  \
    do {                                                                                      \
        sph_cuda_zero((b)->red + SPH_STEP_SUM_##member, 1);                                   \
        SPH_FOR_SUM(i, (b)->nown, (b)->red + SPH_STEP_SUM_##member,                           \
                    { return (double)(__VA_ARGS__); });                                       \
    } while (0)

#endif
