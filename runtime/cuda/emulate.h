/* emulate.h — the CUDA runtime's calls on the host, for SPH_CUDA_EMULATE: the generated
 * model.cu compiled as C++ by the host compiler, SPH_FOR a serial loop, device memory host
 * memory, events the host's clock.  How the tests check the CUDA target's code without a
 * GPU; nothing without SPH_CUDA_EMULATE. */
#ifndef SPHRT_CUDA_EMULATE_H
#define SPHRT_CUDA_EMULATE_H

#include <cstdlib>
#include <cstring>

#include "core/clock.h"

#ifdef SPH_CUDA_EMULATE
#define __global__
#define __device__
#define __host__
typedef int cudaError_t;
enum { cudaSuccess = 0, cudaMemcpyHostToDevice = 1, cudaMemcpyDeviceToHost = 2,
       cudaMemcpyDeviceToDevice = 3 };
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
static inline cudaError_t cudaMemset(void *d, int v, size_t n)
{
    memset(d, v, n);
    return cudaSuccess;
}
static inline cudaError_t cudaDeviceSynchronize() { return cudaSuccess; }
template <class T> static inline cudaError_t cudaMemcpyToSymbol(T &sym, const void *s, size_t n)
{
    memcpy(&sym, s, n);
    return cudaSuccess;
}
template <class T> static inline cudaError_t cudaMemcpyFromSymbol(void *d, const T &sym, size_t n)
{
    memcpy(d, &sym, n);
    return cudaSuccess;
}
static inline cudaError_t cudaGetLastError() { return cudaSuccess; }
static inline cudaError_t cudaGetDeviceCount(int *n)
{
    *n = 1;
    return cudaSuccess;
}
static inline cudaError_t cudaSetDevice(int) { return cudaSuccess; }
static inline cudaError_t cudaFree(void *p)
{
    free(p);
    return cudaSuccess;
}
static inline void atomicAdd(double *a, double v) { *a += v; }

/* Events: the host's clock at the event (the kernels have run by then). */
typedef double *cudaEvent_t;
static inline cudaError_t cudaEventCreate(cudaEvent_t *e)
{
    *e = (double *)calloc(1, sizeof(double));
    return cudaSuccess;
}
static inline cudaError_t cudaEventRecord(cudaEvent_t e)
{
    *e = sph_wall_time();
    return cudaSuccess;
}
static inline cudaError_t cudaEventSynchronize(cudaEvent_t) { return cudaSuccess; }
static inline cudaError_t cudaEventElapsedTime(float *ms, cudaEvent_t a, cudaEvent_t b)
{
    *ms = (float)(1e3 * (*b - *a));
    return cudaSuccess;
}
#endif

#endif
