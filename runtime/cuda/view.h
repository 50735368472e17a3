/* view.h — the device view of a body (see sph_cuda.h): the host body's arrays copied to the
 * device, its full pair lists, its sums; what the device does not read left out. */
#ifndef SPHRT_CUDA_VIEW_H
#define SPHRT_CUDA_VIEW_H

#include <cstdlib>

#include "target.h"
#include "check.h"
#include "full_lists.h"
#include "halo.h"
#include "launch.h"
#include "memory.h"
#include "sums.h"
#include "core/profile.h"
#include "pairs/quadratic.h"
#include "scene/body.h"
#include "scene/body_desc.h"
#include "scene/pass_types.h"

/* The device view of host body h (see sph_cuda.h). */
static sph_body *sph_cuda_body(const sph_body *h)
{
    const size_t n = (size_t)h->n, d = (size_t)h->dim, nt = (size_t)h->ntab;
    sph_cuda_sync_mode(); /* decided before the first pass */
    sph_cuda_pick_device(h->par);
    sph_body *b;
    SPH_CUDA_CHECK(cudaMallocManaged(&b, sizeof *b));
    *b = *h;
    b->X = (double *)sph_dev_copy(h->X, n * d * sizeof(double));
    b->u = (double *)sph_dev_copy(h->u, n * d * sizeof(double));
    b->v = (double *)sph_dev_copy(h->v, n * d * sizeof(double));
    b->a = (double *)sph_dev_copy(h->a, n * d * sizeof(double));
    b->work = (double *)sph_dev_copy(h->work, n * d * sizeof(double));
    b->F = (double *)sph_dev_copy(h->F, n * 9 * sizeof(double));
    b->L = (double *)sph_dev_alloc(n * d * d * sizeof(double)); /* (own particles' only) */
    SPH_CUDA_CHECK(cudaMemcpy(b->L, h->L, (size_t)h->nown * d * d * sizeof(double),
                              cudaMemcpyHostToDevice));
    b->Q = (sph_real *)sph_dev_alloc(n * d * d * sizeof(sph_real)); /* each stress pass */
    b->Cv = (sph_real *)sph_dev_alloc(n * d * d * sizeof(sph_real)); /* writes them whole */
    b->Cs = (sph_real *)sph_dev_alloc(n * sizeof(sph_real));
    b->us = (double *)sph_dev_alloc(n * d * sizeof(double)); /* each pair pass */
    b->vs = (double *)sph_dev_alloc(n * d * sizeof(double)); /* writes the one it reads */
    b->lam2 = (double *)sph_dev_copy(h->lam2, n * sizeof(double)); /* NULL without crush */
    b->psi = (double *)sph_dev_copy(h->psi, n * sizeof(double));
    b->vq = (double *)sph_dev_copy(h->vq, n * sizeof(double)); /* NULL without viscous heat */
    b->fix = (uint8_t *)sph_dev_copy(h->fix, n);
    b->state = (double *)sph_dev_copy(h->state, n * (size_t)h->desc->nstate * sizeof(double));
    b->Fd = (double *)sph_dev_copy(h->Fd, n * 9 * sizeof(double)); /* a law that reads a rate */
    b->Ad = NULL; /* (the device's threads keep their particle's sum: body_cuda.cu) */
    b->s = (double *)sph_dev_copy(h->s, n * sizeof(double)); /* fracture (NULL without) */
    b->sd = (double *)sph_dev_copy(h->sd, n * sizeof(double));
    b->sdd = (double *)sph_dev_copy(h->sdd, n * sizeof(double));
    b->H = (double *)sph_dev_copy(h->H, n * sizeof(double));
    b->lap = (double *)sph_dev_copy(h->lap, n * sizeof(double));
    b->sd_n = (double *)sph_dev_copy(h->sd_n, n * sizeof(double));
    b->ltab = sph_dev_table(h->ltab, nt, 1); /* each with the zero entry of holes */
    b->wtab = sph_dev_table(h->wtab, nt, SPH_ROW(d));
    b->gtab = sph_dev_table(h->gtab, nt, 1);
    b->htab = sph_dev_table(h->htab, nt, 1);
    /* the quadratic gradient (NULL without): the pairs' monomials, each own particle's inverse
     * moment matrix and the stress's share the momentum pass reads; each thread keeps its
     * particle's fit sums (body_cuda.cu), so no Aq */
    b->qtab = sph_dev_table(h->qtab, nt, SPH_QR(d));
    b->Mq = (double *)sph_dev_copy(h->Mq, (size_t)h->nown * SPH_QM(d) * SPH_QM(d) * sizeof(double));
    b->Qq = h->Qq ? (sph_real *)sph_dev_alloc(n * SPH_QN(d) * SPH_ROW(d) * sizeof(sph_real)) : NULL;
    b->Aq = NULL;
    /* a clamp's images and the particles they mirror (NULL without: run/clamp.c) */
    b->image = (int *)sph_dev_copy(h->image, (size_t)h->nimages * sizeof(int));
    b->image_of = (int *)sph_dev_copy(h->image_of, (size_t)h->nimages * sizeof(int));
    sph_full f;
    SPH_TIMED("set-up: the device's full pair lists", sph_full_lists(h, &f));
    const size_t words = ((size_t)f.slots + 31) / 32;
    b->fb_count = (int *)sph_dev_copy(f.count, n * sizeof(int));
    b->fb = (int *)sph_dev_copy(f.nb, (size_t)f.slots * n * sizeof(int)); /* NULL with masks */
    b->fb_k = (int *)sph_dev_copy(f.k, (size_t)f.slots * n * sizeof(int));
    b->fb_mask = (unsigned *)sph_dev_copy(f.mask, words * n * sizeof(unsigned));
    b->fb_off = (int *)sph_dev_copy(f.off, (size_t)f.slots * sizeof(int));
    b->fb_slotk = (int *)sph_dev_copy(f.slotk, (size_t)f.slots * sizeof(int));
    free(f.count), free(f.nb), free(f.k), free(f.mask), free(f.off), free(f.slotk);
    double red[SPH_NRED];
    sph_host_sums(h, red);
    b->red = (double *)sph_dev_copy(red, sizeof red);
    const int nbcs = h->desc->nbcs;
    b->desc = NULL; /* host memory: the device view must not lead there (the host keeps h) */
    b->bc_list = NULL, b->bc_count = NULL;
    if (nbcs) { /* the particles of each `near` BC: a managed table of device lists */
        SPH_CUDA_CHECK(cudaMallocManaged(&b->bc_list, nbcs * sizeof(int *)));
        SPH_CUDA_CHECK(cudaMallocManaged(&b->bc_count, nbcs * sizeof(int)));
        for (int q = 0; q < nbcs; q++) {
            b->bc_count[q] = h->bc_count ? h->bc_count[q] : 0;
            b->bc_list[q] = h->bc_list && h->bc_list[q]
                                ? (int *)sph_dev_copy(h->bc_list[q], b->bc_count[q] * sizeof(int))
                                : NULL;
        }
    }
    /* host-only or not yet on the device: never read there */
    b->hb_start = b->hb = b->hb_k = b->stripe = NULL;
    b->stripe_sum = NULL;
    b->A = NULL; /* the device sums A per particle, in registers */
    b->nb_start = b->nb = b->nb_k = NULL;
    b->sigma = NULL, b->ms_list = NULL, b->ms_count = NULL;
    b->rare_hint = NULL; /* (the CPU's stress blocks) */
    b->st_o = b->st_k = b->st_run = NULL; /* the lattice stencil: the CPU's pair passes */
    b->rest = b->rest_start = b->rest_j = b->rest_k = NULL;
    b->ob_start = NULL, b->ob = NULL, b->ob_u = NULL, b->nob = 0; /* (the CPU's pair passes) */
    b->mb_start = b->mb_i0 = b->mb_stripe = NULL, b->mb = NULL, b->mb_soa = NULL, b->nmb = 0;
    /* Neither side writes these pages again: both keep a copy, and reads never fault. */
    sph_read_mostly(b, sizeof *b);
    if (nbcs) {
        sph_read_mostly(b->bc_list, nbcs * sizeof(int *));
        sph_read_mostly(b->bc_count, nbcs * sizeof(int));
    }
    SPH_CUDA_CHECK(cudaDeviceSynchronize());
    return b;
}

#endif
