/* loops.h — the loops over particles of the generated passes: SPH_FOR, one thread per
 * particle; SPH_FOR_MAX3 and SPH_FOR_SUM, the same with a reduction; SPH_ONCE, one thread
 * (emulated: serial loops on the host).  A step past the end of the clock's batch runs none
 * of them. */
#ifndef SPHRT_CUDA_LOOPS_H
#define SPHRT_CUDA_LOOPS_H

#include "target.h"
#include "device_clock.h"
#include "launch.h"
#include "run/time_step.h"

/* What an SPH_FOR_MAX3 body returns: three non-negative values to take the maxima of. */
struct sph_max3 {
    double x, y, z;
};

/* Threads per block of the passes (a multiple of 32, at most 1024). */
#ifndef SPH_CUDA_BLOCK
#define SPH_CUDA_BLOCK 256
#endif
static_assert(SPH_CUDA_BLOCK % 32 == 0 && SPH_CUDA_BLOCK >= 32 && SPH_CUDA_BLOCK <= 1024,
              "SPH_CUDA_BLOCK: the reductions take whole warps, and a block holds 1024 threads");
static inline int sph_blocks(int n) { return (n + SPH_CUDA_BLOCK - 1) / SPH_CUDA_BLOCK; }

#ifndef SPH_CUDA_EMULATE
template <class F> __global__ void sph_for_kernel(int n, F f)
{
    if (sph_clock.skip) /* a step past the batch's end (the clock) */
        return;
    for (int i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += blockDim.x * gridDim.x)
        f(i);
}

template <class F> static void sph_for(int n, const char *pass, F f)
{
    if (n <= 0)
        return;
    sph_launch(pass, [&] { sph_for_kernel<<<sph_blocks(n), SPH_CUDA_BLOCK>>>(n, f); });
}

/* *a = max(*a, v) for *a >= 0: positive doubles order like their bit patterns (v = -0, which
 * has the largest pattern, and 0 leave *a as it is). */
__device__ static inline void sph_atomic_max_pos(double *a, double v)
{
    if (v > 0)
        atomicMax((unsigned long long *)a, (unsigned long long)__double_as_longlong(v));
}

/* The maxima of a warp's values, in every lane. */
__device__ static inline sph_max3 sph_warp_max3(sph_max3 m)
{
    for (int o = 16; o > 0; o >>= 1) {
        m.x = fmax(m.x, __shfl_xor_sync(0xffffffffu, m.x, o));
        m.y = fmax(m.y, __shfl_xor_sync(0xffffffffu, m.y, o));
        m.z = fmax(m.z, __shfl_xor_sync(0xffffffffu, m.z, o));
    }
    return m;
}

/* Every thread runs the loop (so whole warps reach the shuffles), then warp and block
 * maxima, then one atomic per block. */
template <class F> __global__ void sph_for_max3_kernel(int n, double *out, F f)
{
    if (sph_clock.skip)
        return;
    sph_max3 m = {0, 0, 0};
    for (int i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += blockDim.x * gridDim.x) {
        const sph_max3 r = f(i); /* not a number: infinite (sph_max_bound, run/time_step.h) */
        m.x = sph_max_bound(m.x, r.x);
        m.y = sph_max_bound(m.y, r.y);
        m.z = sph_max_bound(m.z, r.z);
    }
    __shared__ sph_max3 warp[32];
    const int lane = threadIdx.x & 31, w = threadIdx.x >> 5;
    m = sph_warp_max3(m);
    if (lane == 0)
        warp[w] = m;
    __syncthreads();
    if (w)
        return;
    const sph_max3 zero = {0, 0, 0};
    m = sph_warp_max3(lane < (int)(blockDim.x >> 5) ? warp[lane] : zero);
    if (lane == 0) {
        sph_atomic_max_pos(&out[0], m.x);
        sph_atomic_max_pos(&out[1], m.y);
        sph_atomic_max_pos(&out[2], m.z);
    }
}

template <class F> static void sph_for_max3(int n, double *out, const char *pass, F f)
{
    if (n <= 0)
        return;
    sph_launch(pass, [&] { sph_for_max3_kernel<<<sph_blocks(n), SPH_CUDA_BLOCK>>>(n, out, f); });
}

/* The sum of a warp's values, in every lane. */
__device__ static inline double sph_warp_sum(double x)
{
    for (int o = 16; o > 0; o >>= 1)
        x += __shfl_xor_sync(0xffffffffu, x, o);
    return x;
}

/* As sph_for_max3_kernel, for a sum: warp, block, then one atomic add per block (an atomic
 * per thread on one address serialises a million threads). */
template <class F> __global__ void sph_for_sum_kernel(int n, double *out, F f)
{
    if (sph_clock.skip)
        return;
    double x = 0;
    for (int i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += blockDim.x * gridDim.x)
        x += f(i);
    __shared__ double warp[32];
    const int lane = threadIdx.x & 31, w = threadIdx.x >> 5;
    x = sph_warp_sum(x);
    if (lane == 0)
        warp[w] = x;
    __syncthreads();
    if (w)
        return;
    x = sph_warp_sum(lane < (int)(blockDim.x >> 5) ? warp[lane] : 0.0);
    if (lane == 0)
        atomicAdd(out, x);
}

template <class F> static void sph_for_sum(int n, double *out, const char *pass, F f)
{
    if (n <= 0)
        return;
    sph_launch(pass, [&] { sph_for_sum_kernel<<<sph_blocks(n), SPH_CUDA_BLOCK>>>(n, out, f); });
}
#else
template <class F> static void sph_for(int n, const char *pass, F f)
{
    sph_launch(pass, [&] {
        for (int i = 0; i < n && !sph_clock.skip; i++)
            f(i);
    });
}

static inline void sph_atomic_max_pos(double *a, double v) { *a = v > *a ? v : *a; }

template <class F> static void sph_for_sum(int n, double *out, const char *pass, F f)
{
    sph_launch(pass, [&] {
        for (int i = 0; i < n && !sph_clock.skip; i++)
            *out += f(i);
    });
}

template <class F> static void sph_for_max3(int n, double *out, const char *pass, F f)
{
    sph_launch(pass, [&] {
        for (int i = 0; i < n && !sph_clock.skip; i++) {
            const sph_max3 r = f(i);
            out[0] = sph_max_bound(out[0], r.x);
            out[1] = sph_max_bound(out[1], r.y);
            out[2] = sph_max_bound(out[2], r.z);
        }
    });
}
#endif

/* (__func__: the pass that launches, for sph_cuda_launched) */
#define SPH_FOR(i, n, ...) sph_for((n), __func__, [=] __device__(int i) __VA_ARGS__)
#define SPH_FOR_MAX3(i, n, out, ...) \
    sph_for_max3((n), (out), __func__, [=] __device__(int i) -> sph_max3 __VA_ARGS__)
#define SPH_FOR_SUM(i, n, out, ...) \
    sph_for_sum((n), (out), __func__, [=] __device__(int i) -> double __VA_ARGS__)
/* One thread: the body's scalars (reductions reset, sums advanced) in stream order. */
#define SPH_ONCE(...) sph_for(1, __func__, [=] __device__(int) __VA_ARGS__)

/* n doubles of device memory to zero, in stream order (a pass, so that a step past the
 * batch's end leaves the sums of the last one); a kernel of the pass that calls it. */
static void sph_cuda_zero_in(double *d, int n, const char *pass)
{
    sph_for(1, pass, [=] __device__(int) {
        for (int k = 0; k < n; k++)
            d[k] = 0;
    });
}
#define sph_cuda_zero(d, n) sph_cuda_zero_in((d), (n), __func__)

#endif
