/* sph_cuda.h — what programs of the CUDA target (sphc --target cuda) use besides sphrt.h.
 * Header-only: it is compiled by nvcc with the generated model.cu, which links the same
 * host runtime (libsphrt) as the CPU target for set-up, the time loop and the outputs.
 *
 *  - SPH_FOR(i, n, { body }): the loop over particles of the generated passes, a device
 *    lambda run by one thread per particle (the CPU target writes the same body in an
 *    OpenMP loop); SPH_ONCE({ body }) the same on one thread.
 *  - The device view of a body: a copy of the host sph_body in managed memory whose arrays
 *    live on the device, so the generated code reads `b->u[...]` on either side.  The set-up
 *    (particles, pairs, kernel gradients, selections) stays on the host and is copied once;
 *    full pair lists (fb_*) replace the half lists, so that every thread sums the pairs of its
 *    own particle without atomics.
 *  - sph_cuda_to_host: the state back into the host body, when the runtime reads it.
 *  - With SPH_CUDA_EMULATE the host compiler builds model.cu as C++ with the passes run
 *    serially on host memory: how the tests check the target's code without a GPU. */
#ifndef SPH_CUDA_H
#define SPH_CUDA_H

#include <cstdio>
#include <cstdlib>
#include <cstring>

#ifdef SPH_CUDA_EMULATE
/* Host emulation, for checking the CUDA target's passes without a GPU: the generated model.cu
 * compiled as C++ by the host compiler, SPH_FOR a serial loop, device memory host memory. */
#define __global__
#define __device__
#define __host__
typedef int cudaError_t;
enum { cudaSuccess = 0, cudaMemcpyHostToDevice = 1, cudaMemcpyDeviceToHost = 2 };
static inline const char *cudaGetErrorString(cudaError_t) { return "no error"; }
static inline cudaError_t cudaMalloc(void *p, size_t n)
{
    *(void **)p = malloc(n ? n : 1);
    return cudaSuccess;
}
#define cudaMallocManaged cudaMalloc
static inline cudaError_t cudaMemcpy(void *d, const void *s, size_t n, int)
{
    memcpy(d, s, n);
    return cudaSuccess;
}
static inline cudaError_t cudaDeviceSynchronize() { return cudaSuccess; }
static inline cudaError_t cudaGetLastError() { return cudaSuccess; }
static inline void atomicAdd(double *a, double v) { *a += v; }
#endif

#include "sphrt.h"

#define SPH_CUDA_CHECK(call)                                                                   \
    do {                                                                                       \
        cudaError_t err_ = (call);                                                             \
        if (err_ != cudaSuccess) {                                                             \
            fprintf(stderr, "sph cuda: %s failed: %s\n", #call, cudaGetErrorString(err_));   \
            exit(5);                                                                           \
        }                                                                                      \
    } while (0)

#ifndef SPH_CUDA_EMULATE
template <class F> __global__ void sph_for_kernel(int n, F f)
{
    for (int i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += blockDim.x * gridDim.x)
        f(i);
}

template <class F> static void sph_for(int n, F f)
{
    if (n > 0)
        sph_for_kernel<<<(n + 255) / 256, 256>>>(n, f);
}

/* *a = max(*a, v) for v >= 0: non-negative doubles order like their bit patterns. */
__device__ static inline void sph_atomic_max_pos(double *a, double v)
{
    atomicMax((unsigned long long *)a, (unsigned long long)__double_as_longlong(v));
}
#else
template <class F> static void sph_for(int n, F f)
{
    for (int i = 0; i < n; i++)
        f(i);
}

static inline void sph_atomic_max_pos(double *a, double v) { *a = v > *a ? v : *a; }
#endif

#define SPH_FOR(i, n, ...) sph_for((n), [=] __device__(int i) __VA_ARGS__)
/* One thread: the body's scalars (reductions reset, sums advanced) in stream order. */
#define SPH_ONCE(...) sph_for(1, [=] __device__(int) __VA_ARGS__)

/* A device copy of `bytes` bytes at h (NULL for NULL). */
static void *sph_dev_copy(const void *h, size_t bytes)
{
    if (!h || !bytes)
        return NULL;
    void *d;
    SPH_CUDA_CHECK(cudaMalloc(&d, bytes));
    SPH_CUDA_CHECK(cudaMemcpy(d, h, bytes, cudaMemcpyHostToDevice));
    return d;
}

/* Full pair lists from the half lists (j > i): i gets (j, k), j gets (i, ~k). */
static void sph_full_lists(const sph_body *h, int **start, int **nb, int **k)
{
    const int n = h->n;
    *start = (int *)calloc((size_t)n + 1, sizeof(int));
    for (int i = 0; i < n; i++)
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++)
            (*start)[i + 1]++, (*start)[h->hb[p] + 1]++;
    for (int i = 0; i < n; i++)
        (*start)[i + 1] += (*start)[i];
    *nb = (int *)malloc(((size_t)(*start)[n] + 1) * sizeof(int));
    *k = (int *)malloc(((size_t)(*start)[n] + 1) * sizeof(int));
    int *fill = (int *)malloc(((size_t)n + 1) * sizeof(int));
    memcpy(fill, *start, (size_t)n * sizeof(int));
    for (int i = 0; i < n; i++)
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++) {
            const int j = h->hb[p];
            (*nb)[fill[i]] = j, (*k)[fill[i]++] = h->hb_k[p];
            (*nb)[fill[j]] = i, (*k)[fill[j]++] = ~h->hb_k[p];
        }
    free(fill);
}

/* The device view of host body h (see the top of this file). */
static sph_body *sph_cuda_body(const sph_body *h)
{
    const size_t n = (size_t)h->n, d = (size_t)h->dim, nt = (size_t)h->ntab;
    sph_body *b;
    SPH_CUDA_CHECK(cudaMallocManaged(&b, sizeof *b));
    *b = *h;
    b->X = (double *)sph_dev_copy(h->X, n * d * sizeof(double));
    b->u = (double *)sph_dev_copy(h->u, n * d * sizeof(double));
    b->v = (double *)sph_dev_copy(h->v, n * d * sizeof(double));
    b->a = (double *)sph_dev_copy(h->a, n * d * sizeof(double));
    b->work = (double *)sph_dev_copy(h->work, n * d * sizeof(double));
    b->F = (double *)sph_dev_copy(h->F, n * 9 * sizeof(double));
    b->L = (double *)sph_dev_copy(h->L, n * d * d * sizeof(double));
    b->Q = (sph_real *)sph_dev_copy(h->Q, n * d * d * sizeof(sph_real));
    b->Cv = (sph_real *)sph_dev_copy(h->Cv, n * d * d * sizeof(sph_real));
    b->psi = (double *)sph_dev_copy(h->psi, n * sizeof(double));
    b->fix = (uint8_t *)sph_dev_copy(h->fix, n);
    b->state = (double *)sph_dev_copy(h->state, n * (size_t)h->desc->nstate * sizeof(double));
    b->s = (double *)sph_dev_copy(h->s, n * sizeof(double)); /* fracture (NULL without) */
    b->sd = (double *)sph_dev_copy(h->sd, n * sizeof(double));
    b->sdd = (double *)sph_dev_copy(h->sdd, n * sizeof(double));
    b->H = (double *)sph_dev_copy(h->H, n * sizeof(double));
    b->lap = (double *)sph_dev_copy(h->lap, n * sizeof(double));
    b->sd_n = (double *)sph_dev_copy(h->sd_n, n * sizeof(double));
    b->ltab = (sph_real *)sph_dev_copy(h->ltab, nt * sizeof(sph_real));
    b->wtab = (sph_real *)sph_dev_copy(h->wtab, nt * d * sizeof(sph_real));
    b->gtab = (sph_real *)sph_dev_copy(h->gtab, nt * sizeof(sph_real));
    b->htab = (sph_real *)sph_dev_copy(h->htab, nt * sizeof(sph_real));
    int *start, *nb, *k;
    sph_full_lists(h, &start, &nb, &k);
    b->fb_start = (int *)sph_dev_copy(start, (n + 1) * sizeof(int));
    b->fb = (int *)sph_dev_copy(nb, (size_t)start[n] * sizeof(int));
    b->fb_k = (int *)sph_dev_copy(k, (size_t)start[n] * sizeof(int));
    free(start), free(nb), free(k);
    const int nbcs = h->desc->nbcs;
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
    b->A = NULL; /* the device sums A per particle, in registers */
    b->nb_start = b->nb = b->nb_k = NULL;
    b->sigma = NULL, b->ms_list = NULL, b->ms_count = NULL;
    SPH_CUDA_CHECK(cudaDeviceSynchronize());
    return b;
}

/* The state of device view d back into host body h: what outputs, energies, measurements
 * and the stability monitor read. */
static void sph_cuda_to_host(sph_body *h, const sph_body *d)
{
    const size_t n = (size_t)h->n, dim = (size_t)h->dim;
    SPH_CUDA_CHECK(cudaDeviceSynchronize());
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
    /* (vmax2 and amax2 come back with every step; the host's initial ones stand until then) */
    h->visc_rate = d->visc_rate, h->visc_dissipated = d->visc_dissipated;
}

#endif
