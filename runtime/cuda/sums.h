/* sums.h — what the device sums of a body at every step (b->red[SPH_RED_*]): the time
 * step's maxima, the viscosity's energy, the monitor's checks. */
#ifndef SPHRT_CUDA_SUMS_H
#define SPHRT_CUDA_SUMS_H

#include "target.h"
#include "check.h"
#include "core/defs.h"
#include "scene/body.h"

/* The device's sums of a body, b->red[SPH_RED_*]. */
enum {
    SPH_RED_VMAX2, SPH_RED_AMAX2, SPH_RED_CRUSH, /* maxima of |v|^2, |a|^2, 1 / lambda_min^2 */
    SPH_RED_VISC_RATE, SPH_RED_VISC_DISSIPATED,
    /* the monitor's pass (templates/body_cuda.cu): the maxima of a particle's failed check
     * (0 or 1) and of 1 - lambda_min^2 (and a spare maximum), and the body's energy */
    SPH_RED_BAD, SPH_RED_SQUEEZE, SPH_RED_SPARE, SPH_RED_ENERGY,
    SPH_NRED
};

/* A body's smallest squared principal stretch from its sums (SPH_RED_CRUSH holds the largest
 * 1 / lambda^2; 0 before the first step of a body that does not track it). */
SPH_HD static inline double sph_red_lam2min(const double *red)
{
    return red[SPH_RED_CRUSH] > 0 ? 1.0 / red[SPH_RED_CRUSH] : 1.0;
}

/* The sums of host body h's last step as the device keeps them (b->red[SPH_RED_VMAX2 ..
 * SPH_RED_VISC_DISSIPATED]; the rest, the monitor's, 0): the next time step comes from them. */
static void sph_host_sums(const sph_body *h, double red[SPH_NRED])
{
    for (int k = 0; k < SPH_NRED; k++)
        red[k] = 0;
    red[SPH_RED_VMAX2] = h->vmax2, red[SPH_RED_AMAX2] = h->amax2;
    red[SPH_RED_CRUSH] = 1.0 / h->lam2min;
    red[SPH_RED_VISC_RATE] = h->visc_rate, red[SPH_RED_VISC_DISSIPATED] = h->visc_dissipated;
}

/* The same onto the device view's sums (the monitor's left as they are). */
static void sph_host_sums_to_device(const sph_body *h, double *dev_red)
{
    double red[SPH_NRED];
    sph_host_sums(h, red);
    SPH_CUDA_CHECK(cudaMemcpy(dev_red, red, (SPH_RED_VISC_DISSIPATED + 1) * sizeof(double),
                              cudaMemcpyHostToDevice));
}

#endif
