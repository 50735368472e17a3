/* transfer.h — what the host reads back from the device views: a step's sums, the stability
 * monitor's sums, the state for outputs; and the state both ways for checkpoints. */
#ifndef SPHRT_CUDA_TRANSFER_H
#define SPHRT_CUDA_TRANSFER_H

#include "target.h"
#include "check.h"
#include "launch.h"
#include "sums.h"
#include "scene/body.h"
#include "scene/body_desc.h"
#include "scene/model.h"
#include "scene/state_arrays.h"
#include "scene/step_sums.h"

/* The step sums of device view d's last step into host body h (the time step of
 * sph_sim_step, the energies; after a batch, the clock's copy has waited already). */
static void sph_cuda_reductions(sph_body *h, const sph_body *d)
{
    double red[SPH_NRED];
    SPH_CUDA_CHECK(cudaMemcpy(red, d->red, sizeof red, cudaMemcpyDeviceToHost));
    sph_cuda_profile_collect(); /* (the host has waited) */
    double x[SPH_STEP_NSUMS];
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        x[k] = sph_red_to_host(k, red[k]);
    sph_step_sums_set(h, x);
}

/* The stability monitor's sums of device view d, after its monitor pass: a few numbers
 * instead of the state (run/monitor.c). */
static void sph_cuda_monitor_sums(const sph_body *d, sph_monitor_sums *out)
{
    double red[SPH_NRED];
    SPH_CUDA_CHECK(cudaMemcpy(red, d->red, sizeof red, cudaMemcpyDeviceToHost));
    sph_cuda_profile_collect(); /* (the host has waited) */
    out->bad = red[SPH_RED_BAD] > 0;
    out->energy = red[SPH_RED_ENERGY];
    out->stretch2 = 1.0 - red[SPH_RED_SQUEEZE];
}

/* The state of device view d back into host body h: what outputs, energies, measurements
 * and the stability monitor read. */
static void sph_cuda_to_host(sph_body *h, const sph_body *d)
{
    const size_t n = (size_t)h->n, dim = (size_t)h->dim;
    SPH_CUDA_CHECK(cudaDeviceSynchronize());
    sph_cuda_profile_collect(); /* (the host has waited) */
    SPH_CUDA_CHECK(cudaMemcpy(h->u, d->u, n * dim * sizeof(double), cudaMemcpyDeviceToHost));
    SPH_CUDA_CHECK(cudaMemcpy(h->v, d->v, n * dim * sizeof(double), cudaMemcpyDeviceToHost));
    SPH_CUDA_CHECK(cudaMemcpy(h->a, d->a, n * dim * sizeof(double), cudaMemcpyDeviceToHost));
    SPH_CUDA_CHECK(cudaMemcpy(h->F, d->F, n * 9 * sizeof(double), cudaMemcpyDeviceToHost));
    SPH_CUDA_CHECK(cudaMemcpy(h->psi, d->psi, n * sizeof(double), cudaMemcpyDeviceToHost));
    SPH_CUDA_CHECK(cudaMemcpy(h->fix, d->fix, n, cudaMemcpyDeviceToHost));
    if (h->s) { /* fracture: the phase field and its history for outputs and energies */
        SPH_CUDA_CHECK(cudaMemcpy(h->s, d->s, n * sizeof(double), cudaMemcpyDeviceToHost));
        SPH_CUDA_CHECK(cudaMemcpy(h->H, d->H, n * sizeof(double), cudaMemcpyDeviceToHost));
    }
    if (h->state) /* plasticity: the VTU files and the plastic work read it */
        SPH_CUDA_CHECK(cudaMemcpy(h->state, d->state, n * (size_t)h->desc->nstate * sizeof(double),
                                  cudaMemcpyDeviceToHost));
    if (h->Fd) /* the rate of F, for the output's stress of a law that reads it */
        SPH_CUDA_CHECK(cudaMemcpy(h->Fd, d->Fd, n * 9 * sizeof(double), cudaMemcpyDeviceToHost));
    /* (the sums come back with every step, sph_cuda_reductions; before the first, the
     * host's initial ones are the device's) */
}

/* Every state array of host body h and device view d (sph_body_state_arrays), to the host
 * for a checkpoint or to the device for a run resumed from one; to the device also the sums
 * the next time step comes from (where a body's compression bounds it, 1 / (1 / x) may differ
 * from x in its last bit: the resumed run may then take a time step a last bit apart). */
static void sph_cuda_state_copy(sph_body *h, const sph_body *d, int to_device)
{
    sph_state_array ha[SPH_STATE_ARRAYS], da[SPH_STATE_ARRAYS];
    const int n = sph_body_state_arrays(h, h->desc->nstate, ha);
    sph_body_state_arrays(const_cast<sph_body *>(d), h->desc->nstate, da); /* (the same list) */
    SPH_CUDA_CHECK(cudaDeviceSynchronize());
    sph_cuda_profile_collect(); /* (the host has waited) */
    for (int k = 0; k < n; k++)
        SPH_CUDA_CHECK(to_device ? cudaMemcpy(da[k].data, ha[k].data, ha[k].bytes,
                                              cudaMemcpyHostToDevice)
                                 : cudaMemcpy(ha[k].data, da[k].data, ha[k].bytes,
                                              cudaMemcpyDeviceToHost));
    if (to_device)
        sph_host_sums_to_device(h, d->red);
}

#endif
