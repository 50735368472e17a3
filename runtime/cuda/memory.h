/* memory.h — device memory: allocated, copied from the host, tables with their zero entry,
 * and managed memory both sides only read. */
#ifndef SPHRT_CUDA_MEMORY_H
#define SPHRT_CUDA_MEMORY_H

#include <cstdlib>
#include <cstring>

#include "target.h"
#include "check.h"
#include "scene/pass_types.h"

/* `bytes` bytes of device memory (uninitialised). */
static inline void *sph_dev_alloc(size_t bytes)
{
    void *d;
    SPH_CUDA_CHECK(cudaMalloc(&d, bytes ? bytes : 1));
    return d;
}

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

/* A device copy of the table h of `entries` entries of `width` numbers, plus one entry of
 * zeros (NULL for NULL). */
static sph_real *sph_dev_table(const sph_real *h, size_t entries, size_t width)
{
    if (!h)
        return NULL;
    sph_real *t = (sph_real *)calloc((entries + 1) * width, sizeof(sph_real));
    memcpy(t, h, entries * width * sizeof(sph_real));
    sph_real *d = (sph_real *)sph_dev_copy(t, (entries + 1) * width * sizeof(sph_real));
    free(t);
    return d;
}

/* Managed memory that host and device only read from now on: each keeps its own copy. */
static void sph_read_mostly(const void *p, size_t bytes)
{
#ifndef SPH_CUDA_EMULATE
#if CUDART_VERSION >= 13000
    cudaMemLocation where = {};
    where.type = cudaMemLocationTypeDevice; /* (ignored for this advice) */
    SPH_CUDA_CHECK(cudaGetDevice(&where.id));
    SPH_CUDA_CHECK(cudaMemAdvise(p, bytes, cudaMemAdviseSetReadMostly, where));
#else
    int dev;
    SPH_CUDA_CHECK(cudaGetDevice(&dev));
    SPH_CUDA_CHECK(cudaMemAdvise(p, bytes, cudaMemAdviseSetReadMostly, dev));
#endif
#else
    (void)p, (void)bytes;
#endif
}

#endif
