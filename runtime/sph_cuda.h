/* sph_cuda.h — what programs of the CUDA target (sphc --target cuda) use besides sphrt.h.
 * Header-only: it is compiled by nvcc with the generated model.cu, which links the same
 * host runtime (libsphrt) as the CPU target for set-up, the time loop and the outputs.
 *
 *  - SPH_FOR(i, n, { body }): the loop over particles of the generated passes, a device
 *    lambda run by one thread per particle (the CPU target writes the same body in an
 *    OpenMP loop); SPH_ONCE({ body }) the same on one thread.
 *  - SPH_FOR_MAX3(i, n, out, { ...; return sph_max3{x, y, z}; }): the same loop that also
 *    reduces out[k] = the maximum of the k-th value (x, y, z >= 0) per block, then once per
 *    block with an atomic: the |v|^2 and |a|^2 bounds of the time step (eq. 65-66) and the
 *    compression bound 1 / lambda_min^2.
 *  - SPH_FOR_SUM(i, n, out, { ...; return x; }): the same for *out += the sum of x.
 *  - The device view of a body: a copy of the host sph_body in managed memory, marked read
 *    mostly so that host and device each keep a copy of its page, whose arrays live in device
 *    memory; the generated code reads `b->u[...]` on either side and the device writes only
 *    arrays (its sums go to b->red).  The set-up (particles, pairs, kernel gradients,
 *    selections) stays on the host and is copied once; full pair lists (fb_*) replace the half
 *    lists, so that every thread sums the pairs of its own particle without atomics.
 *  - The device's clock (sph_clock): a batch of steps runs without the host, which chooses
 *    none of their time steps; the passes read t and dt from it (sph_time).
 *  - sph_cuda_reductions: the last step's sums back into the host body, the one wait of a
 *    batch; sph_cuda_monitor_sums: the stability monitor's sums (every 20 steps);
 *    sph_cuda_to_host: the state too, when the runtime reads it (outputs, or a monitor's
 *    closer look).
 *  - With SPH_CUDA_EMULATE the host compiler builds model.cu as C++ with the passes run
 *    serially on host memory: how the tests check the target's code without a GPU. */
#ifndef SPH_CUDA_H
#define SPH_CUDA_H

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>

#ifdef SPH_CUDA_EMULATE
/* Host emulation, for checking the CUDA target's passes without a GPU: the generated model.cu
 * compiled as C++ by the host compiler, SPH_FOR a serial loop, device memory host memory. */
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
#endif

/* Q and Cv entry by entry on the device (sphrt.h): particle i's entry (r, c) at
 * (r*D + c)*n + i. */
#define SPH_TENSOR(i, r, c, D, n) ((size_t)((r) * (D) + (c)) * (size_t)(n) + (size_t)(i))
#define SPH_TIME_DEFINED /* sph_time: below, a value or the device clock's */
#include "sphrt.h"
#include "contact/contact_law.h"

/* The neighbour a hole (a slot of offset off that particle i lacks) reads, one of the nown own
 * particles: the particle at i + off, or the nearest one to it, so that the warp's load
 * stays as contiguous as at its other lanes (a lane that read i itself would add lines to
 * the load of every slot with a hole: near a surface, every slot pointing out of it).  A
 * hole's table entry is the zero entry ntab, so whatever finite values it reads add
 * nothing.  With SPH_CUDA_RECOMPUTE the pair's gradient comes from X_i - X_j instead, which
 * would not be zero there: i itself. */
SPH_FN int sph_hole(int i, int off, int nown)
{
#ifdef SPH_CUDA_RECOMPUTE
    (void)off, (void)nown;
    return i;
#else
    const int j = i + off;
    return j < 0 ? 0 : j >= nown ? nown - 1 : j;
#endif
}

/* Slot s of particle i's full list: its neighbour (returned) and table entry *k (~k for the
 * reversed pair; ntab, the zero entry, for a hole, sph_hole).  A body whose every pair lies
 * at i + its slot's offset keeps only masks (sph_full_lists): the same branch for every
 * thread of a launch. */
SPH_FN int sph_slot(const sph_body *b, int i, int s, int *k)
{
    if (b->fb_mask) {
        const int in = b->fb_mask[(size_t)(s >> 5) * (size_t)b->n + (size_t)i] >> (s & 31) & 1;
        *k = in ? b->fb_slotk[s] : b->ntab;
        return in ? i + b->fb_off[s] : sph_hole(i, b->fb_off[s], b->nown);
    }
    const size_t p = (size_t)s * (size_t)b->n + (size_t)i;
    *k = b->fb_k[p];
    return b->fb[p];
}

#define SPH_CUDA_CHECK(call)                                                                   \
    do {                                                                                       \
        cudaError_t err_ = (call);                                                             \
        if (err_ != cudaSuccess) {                                                             \
            sph_error("CUDA: %s failed: %s", #call, cudaGetErrorString(err_));                 \
            exit(SPH_EXIT_CUDA);                                                               \
        }                                                                                      \
    } while (0)

/* The device's sums of a body, b->red[SPH_RED_*]. */
enum {
    SPH_RED_VMAX2, SPH_RED_AMAX2, SPH_RED_CRUSH, /* maxima of |v|^2, |a|^2, 1 / lambda_min^2 */
    SPH_RED_VISC_RATE, SPH_RED_VISC_DISSIPATED,
    /* the monitor's pass (templates/body_cuda.cu): the maxima of a particle's failed check
     * (0 or 1) and of 1 - lambda_min^2 (and a spare maximum), and the body's energy */
    SPH_RED_BAD, SPH_RED_SQUEEZE, SPH_RED_SPARE, SPH_RED_ENERGY,
    SPH_NRED
};

/* ---- the device's clock ----------------------------------------------------------------
 * The time loop's state that the passes read (t and dt) when the device runs a batch of
 * steps by itself (sph_model.advance, sph_sim_advance): before each step it chooses the time
 * step from the last step's sums as sph_sim_stable_dt does (sph_cuda_clock_choose, with
 * sphrt.h's helpers), after it adds it to t (sph_cuda_clock_tick), so the host queues the
 * batch's steps without waiting between them.  Once the batch reaches its stop time, or its
 * time step collapses, `skip` makes every pass of the steps left return at once. */
enum { SPH_CLOCK_T, SPH_CLOCK_DT, SPH_CLOCK_T_HALF, SPH_CLOCK_T_NEXT };

struct sph_cuda_clock {
    double t, dt;              /* the step: from t, of dt */
    long step;
    int skip;                  /* 1: the passes return at once (until the batch ends) */
    double t_stop, eps;        /* the batch (sph_advance): no step from t >= t_stop - eps */
    double floor_dt;
    int collapsed;             /* the time step fell below its floor: it and the floor */
    double dt_bad, floor_bad;
    double dt_factor;          /* sph_sim.dt_factor */
    double cfl, dt_fixed, lambda_on; /* the scene's (sph_model) */
    int nbodies;
    sph_body *const *bodies;   /* the device views (managed) */
    const double *contact_sums; /* the contact's sums of the step (device, contact_law.h), */
    double contact_w2ref;      /* the laws' reference omega^2: the contact's bound (contact.c) */
};

__device__ static sph_cuda_clock sph_clock;

/* A time the passes read (sphrt.h): a value, or a field of the device's clock, read where
 * the passes use it, on the device. */
struct sph_time {
    double value;
    int field; /* SPH_CLOCK_*, or -1: value */
    SPH_HD sph_time(double v) : value(v), field(-1) {}
    static sph_time clock(int f)
    {
        sph_time c(0.0);
        c.field = f;
        return c;
    }
    __device__ operator double() const
    {
        switch (field) {
        case SPH_CLOCK_T: return sph_clock.t;
        case SPH_CLOCK_DT: return sph_clock.dt;
        case SPH_CLOCK_T_HALF: return sph_clock.t + 0.5 * sph_clock.dt;
        case SPH_CLOCK_T_NEXT: return sph_clock.t + sph_clock.dt;
        default: return value;
        }
    }
};

/* A body's smallest squared principal stretch from its sums (SPH_RED_CRUSH holds the largest
 * 1 / lambda^2; 0 before the first step of a body that does not track it). */
SPH_HD static inline double sph_red_lam2min(const double *red)
{
    return red[SPH_RED_CRUSH] > 0 ? 1.0 / red[SPH_RED_CRUSH] : 1.0;
}

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

/* Whether the host waits for every kernel and checks it (-1: not decided yet).  A batch of
 * steps is queued without waiting, and the host reads the bodies' views (managed memory) for
 * each launch while earlier kernels run, which needs a GPU with concurrent managed access
 * (Linux on Pascal and later).  Without it (some virtual machines, WSL) the host must wait
 * for each kernel before it reads; and with SPH_CUDA_SYNC=1 in the environment it does so
 * too, so that a kernel that fails is named by its pass. */
static int sph_cuda_sync_each = -1;

static int sph_cuda_sync_mode(void)
{
    if (sph_cuda_sync_each >= 0)
        return sph_cuda_sync_each;
    int concurrent = 1;
#ifndef SPH_CUDA_EMULATE
    int dev;
    SPH_CUDA_CHECK(cudaGetDevice(&dev));
    SPH_CUDA_CHECK(cudaDeviceGetAttribute(&concurrent, cudaDevAttrConcurrentManagedAccess, dev));
#endif
    const char *env = getenv("SPH_CUDA_SYNC");
    sph_cuda_sync_each = !concurrent || (env && *env && strcmp(env, "0") != 0);
    if (!concurrent)
        sph_note("this GPU has no concurrent managed access (the host may not read managed "
                 "memory while a kernel runs): the host waits for every pass, which is slower");
    return sph_cuda_sync_each;
}

/* ---- the profile (--profile): the passes' kernels timed on the device -----------------------
 * An event follows every launch, and the kernel's time is the time from the event before it:
 * the passes run one after the other in the default stream.  Where the host has waited (and
 * the device may have idled), and where the steps begin or end, the chain starts again with
 * an event just before the next launch.  The host reads the events where it waits anyway
 * (the end of a batch, the sums, the state; sph_cuda_profile_collect) and adds each kernel's
 * time to the pass that launched it (runtime/profile.c), in the phase of the run it was
 * launched in. */
#ifdef SPH_CUDA_EMULATE /* the host's clock at the event (the kernels have run by then) */
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

enum { SPH_PROFILE_EVENTS = 512 }; /* read back when full, or where the host waits */
static struct {
    cudaEvent_t ev[SPH_PROFILE_EVENTS];
    int slot[SPH_PROFILE_EVENTS]; /* the pass whose kernel ends at ev[k] (-1: a start) */
    int n, made;
    int phase; /* sph_profile_phase when the chain started */
} sph_prof;

static void sph_cuda_profile_record(int slot)
{
    if (!sph_prof.made) {
        for (int k = 0; k < SPH_PROFILE_EVENTS; k++)
            SPH_CUDA_CHECK(cudaEventCreate(&sph_prof.ev[k]));
        sph_prof.made = 1;
    }
    SPH_CUDA_CHECK(cudaEventRecord(sph_prof.ev[sph_prof.n]));
    sph_prof.slot[sph_prof.n++] = slot;
}

/* The kernels' times so far into the profile; the next launch starts a new chain. */
static void sph_cuda_profile_collect(void)
{
    if (!sph_profile_on || sph_prof.n == 0)
        return;
    SPH_CUDA_CHECK(cudaEventSynchronize(sph_prof.ev[sph_prof.n - 1]));
    for (int k = 1; k < sph_prof.n; k++) {
        float ms = 0;
        if (sph_prof.slot[k] < 0)
            continue;
        SPH_CUDA_CHECK(cudaEventElapsedTime(&ms, sph_prof.ev[k - 1], sph_prof.ev[k]));
        sph_profile_add(sph_prof.slot[k], 1e-3 * (double)ms);
    }
    sph_prof.n = 0;
}

/* Before a launch: the start of a chain, also where the steps begin or end (the host's
 * work between, an output say, is in neither). */
static void sph_cuda_launching(void)
{
    if (!sph_profile_on)
        return;
    if (sph_prof.n && sph_prof.phase != sph_profile_phase)
        sph_cuda_profile_collect();
    if (sph_prof.n == 0) {
        sph_prof.phase = sph_profile_phase;
        sph_cuda_profile_record(-1);
    }
}

/* After a launch (or an asynchronous call) of `pass`: its event when profiling; in the
 * waiting mode, wait for it and stop with its name if it failed. */
static void sph_cuda_launched(const char *pass)
{
    if (sph_profile_on) {
        sph_cuda_profile_record(sph_profile_slot(pass));
        if (sph_prof.n == SPH_PROFILE_EVENTS)
            sph_cuda_profile_collect();
    }
    if (sph_cuda_sync_each <= 0)
        return;
    cudaError_t err = cudaDeviceSynchronize();
    if (err == cudaSuccess)
        err = cudaGetLastError();
    if (err != cudaSuccess) {
        sph_error("CUDA: %s failed: %s", pass, cudaGetErrorString(err));
        exit(SPH_EXIT_CUDA);
    }
}

/* One launch of `pass`: run() launches its kernels (or, emulated, runs them), between the
 * profile's events and the waiting mode's check. */
template <class R> static void sph_launch(const char *pass, R run)
{
    sph_cuda_launching();
    run();
    sph_cuda_launched(pass);
}

/* A kernel on one thread: launched, or called on the host when emulated. */
#ifndef SPH_CUDA_EMULATE
#define SPH_ONE_THREAD(kernel) kernel<<<1, 1>>>()
#else
#define SPH_ONE_THREAD(kernel) kernel()
#endif

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
        const sph_max3 r = f(i); /* not a number: infinite (sph_max_bound, sphrt.h) */
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

/* ---- runs on many processes (sphc --mpi, docs/mpi.md) ----------------------------------
 * One process per GPU: the process's rank among those of its node (the MPI launcher's
 * variable) picks the device.  The halo's values are staged through the host: a kernel
 * packs the values of the own particles the plan sends into a device buffer, the host
 * copies it out, the processes exchange (sph_par), the host copies what came in back and a
 * kernel writes it into the halo particles. */
static void sph_cuda_pick_device(const sph_par *par)
{
    static int picked;
    if (picked || !par || par->size == 1)
        return;
    picked = 1;
    const char *names[] = {"OMPI_COMM_WORLD_LOCAL_RANK", "MPI_LOCALRANKID", "SLURM_LOCALID",
                           "PMI_LOCAL_RANK"};
    int count = 0;
    SPH_CUDA_CHECK(cudaGetDeviceCount(&count));
    for (const char *name : names)
        if (const char *v = getenv(name)) {
            if (count > 0)
                SPH_CUDA_CHECK(cudaSetDevice(atoi(v) % count));
            return;
        }
}

/* A field of a device view that the halo exchange carries: particle i's entry e at base + (i
 * pstride + e estride) elements of `size` bytes (a double: sph_real is double on many
 * processes, which `precision single` is not yet). */
struct sph_cuda_field {
    void *base;
    size_t size;
    int entries;
    size_t pstride, estride;
};

/* The plan's lists and buffers on the device, made at a body's first exchange. */
struct sph_cuda_halo_lists {
    int nsend, nrecv, width; /* width: the doubles of the buffers per particle */
    int *send, *recv;        /* device copies of the plan's lists */
    double *out, *in;        /* device buffers */
    double *host_out, *host_in; /* host buffers the halo is staged through (NULL where
                                 * the MPI library takes device memory, sph_par) */
};

static inline sph_cuda_halo_lists *sph_cuda_halo_prepare(sph_body *b, int width)
{
    sph_cuda_halo_lists *x = (sph_cuda_halo_lists *)b->halo_dev;
    if (x && x->width >= width)
        return x;
    const int *send, *recv;
    int nsend, nrecv;
    b->par->halo_lists(b, &send, &nsend, &recv, &nrecv);
    if (!x) {
        x = (sph_cuda_halo_lists *)calloc(1, sizeof *x);
        x->nsend = nsend, x->nrecv = nrecv;
        x->send = (int *)sph_dev_copy(send, (size_t)nsend * sizeof(int));
        x->recv = (int *)sph_dev_copy(recv, (size_t)nrecv * sizeof(int));
        b->halo_dev = x; /* (host memory: read on the host only) */
    }
    if (x->out) { /* (a wider exchange than the ones before) */
        SPH_CUDA_CHECK(cudaFree(x->out));
        SPH_CUDA_CHECK(cudaFree(x->in));
    }
    x->width = width;
    x->out = (double *)sph_dev_alloc(((size_t)nsend * width + 1) * sizeof(double));
    x->in = (double *)sph_dev_alloc(((size_t)nrecv * width + 1) * sizeof(double));
    if (b->par->device_buffers) /* the library takes the device's buffers: none on the host */
        return x;
    x->host_out = (double *)realloc(x->host_out, ((size_t)nsend * width + 1) * sizeof(double));
    x->host_in = (double *)realloc(x->host_in, ((size_t)nrecv * width + 1) * sizeof(double));
    if (!x->host_out || !x->host_in) {
        sph_error("out of memory for the halo of a body");
        exit(SPH_EXIT_SETUP);
    }
    return x;
}

enum { SPH_CUDA_HALO_FIELDS = 4 };
struct sph_cuda_fields {
    sph_cuda_field f[SPH_CUDA_HALO_FIELDS];
    int nf;
};

/* The halo's values of nf fields of device view b from their processes (a pass of the step;
 * nothing on one process). */
static inline void sph_cuda_halo(sph_body *b, const sph_cuda_field *f, int nf)
{
    if (!b->par || b->par->size == 1 || !b->halo)
        return;
    sph_cuda_fields fs;
    int width = 0;
    fs.nf = nf;
    for (int k = 0; k < nf && k < SPH_CUDA_HALO_FIELDS; k++) {
        fs.f[k] = f[k];
        width += f[k].entries;
        if (f[k].size != sizeof(double)) {
            sph_error("the halo of a device target carries doubles only");
            exit(SPH_EXIT_CUDA);
        }
    }
    sph_cuda_halo_lists *x = sph_cuda_halo_prepare(b, width);
    const int *send = x->send, *recv = x->recv, nown = b->nown;
    double *out = x->out, *in = x->in;
    sph_for(x->nsend, "halo: pack", [=] __device__(int q) {
        double *o = out + (size_t)q * width;
        const size_t i = (size_t)send[q];
        for (int k = 0; k < fs.nf; k++)
            for (int e = 0; e < fs.f[k].entries; e++)
                *o++ = ((const double *)fs.f[k].base)[i * fs.f[k].pstride + e * fs.f[k].estride];
    });
    const size_t bytes = (size_t)width * sizeof(double);
    if (b->par->device_buffers) { /* the library reads and writes the device's buffers */
        SPH_CUDA_CHECK(cudaDeviceSynchronize()); /* (the packing done first) */
        b->par->exchange_packed(b, out, in, bytes);
    } else {
        SPH_CUDA_CHECK(cudaMemcpy(x->host_out, out, (size_t)x->nsend * bytes,
                                  cudaMemcpyDeviceToHost));
        b->par->exchange_packed(b, x->host_out, x->host_in, bytes);
        SPH_CUDA_CHECK(cudaMemcpy(in, x->host_in, (size_t)x->nrecv * bytes,
                                  cudaMemcpyHostToDevice));
    }
    sph_for(x->nrecv, "halo: unpack", [=] __device__(int q) {
        const double *v = in + (size_t)q * width;
        const size_t i = (size_t)nown + (size_t)recv[q];
        for (int k = 0; k < fs.nf; k++)
            for (int e = 0; e < fs.f[k].entries; e++)
                ((double *)fs.f[k].base)[i * fs.f[k].pstride + e * fs.f[k].estride] = *v++;
    });
}

/* The slots of a lattice's keys (fixed slots, below): slot_of (nkey, zero on entry) holds
 * each key's slot on return, -1 for a key no pair uses; returns the number used.  The keys
 * go in the order of their mean offset j - i over the own particles' pairs, so that a warp's
 * next slot reads the neighbours of the last one shifted by a particle or a row, which the L1
 * cache still holds: on a lattice in slab order the offsets of one plane of the support lie
 * within a few rows, and the slots sweep the planes one by one instead of jumping between
 * j - i and i - j at every table entry (docs/cuda.md).  Keys only pairs with the halo use go
 * last.  Built with -DSPH_CUDA_SLOTS_BY_KEY, the slots follow the keys (bench/cuda's A/B).
 * off[key] is the key's offset and *uniform says whether every used key's own pairs have
 * the same one (a box in slab order: j = i + off for every pair). */
static int sph_slot_ranks(const sph_body *h, size_t nkey, int *slot_of, long *off, int *uniform)
{
    double *sum = (double *)calloc(nkey, sizeof(double));
    size_t *cnt = (size_t *)calloc(nkey, sizeof(size_t));
    long *hi = (long *)calloc(nkey, sizeof(long));
    for (size_t i = 0; i < (size_t)h->nown; i++)
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++) {
            const size_t key = 2 * (size_t)h->hb_k[p];
            const long d = (long)h->hb[p] - (long)i;
            if (!cnt[key])
                off[key] = hi[key] = d, off[key + 1] = hi[key + 1] = -d;
            off[key] = std::min(off[key], d), hi[key] = std::max(hi[key], d);
            off[key + 1] = std::min(off[key + 1], -d), hi[key + 1] = std::max(hi[key + 1], -d);
            sum[key] += (double)d, sum[key + 1] -= (double)d, cnt[key]++, cnt[key + 1]++;
        }
    for (size_t i = 0; h->xb_start && i < (size_t)h->nown; i++) /* pairs with the halo */
        for (int p = h->xb_start[i]; p < h->xb_start[i + 1]; p++)
            slot_of[2 * (size_t)h->xb_k[p]] = 1;
    int used = 0;
    size_t *order = (size_t *)malloc((nkey + 1) * sizeof(size_t));
    *uniform = 1;
    for (size_t key = 0; key < nkey; key++)
        if (cnt[key] || slot_of[key]) {
            order[used++] = key;
            *uniform = *uniform && cnt[key] && off[key] == hi[key];
        }
#ifndef SPH_CUDA_SLOTS_BY_KEY
    std::stable_sort(order, order + used, [&](size_t a, size_t b) {
        if (!cnt[a] || !cnt[b])
            return cnt[a] > cnt[b]; /* halo-only keys last */
        return sum[a] / (double)cnt[a] < sum[b] / (double)cnt[b];
    });
#endif
    for (size_t key = 0; key < nkey; key++)
        slot_of[key] = -1;
    for (int s = 0; s < used; s++)
        slot_of[order[s]] = s;
    free(sum), free(cnt), free(hi), free(order);
    return used;
}

/* A body's full pair lists as the device reads them (sphrt.h, fb_*; sph_slot). */
struct sph_full {
    int slots, *count, *nb, *k;    /* slot s of particle i: nb[s*n + i], k[s*n + i] */
    unsigned *mask;                /* or, every pair at i + its slot's offset: mask bits */
    int *off, *slotk;              /* and the slots' offsets and table entries */
};

/* The slot masks of a body whose every pair lies at j = i + f->off[its slot] (slot_of from
 * sph_slot_ranks): bit s & 31 of word (s >> 5)*n + i says whether particle i has slot s's
 * neighbour, and count[i] is its last slot + 1 (holes before it included). */
static void sph_slot_masks(const sph_body *h, size_t nkey, const int *slot_of, sph_full *f)
{
    const size_t n = (size_t)h->n, words = ((size_t)f->slots + 31) / 32;
    f->mask = (unsigned *)calloc(words * n + 1, sizeof(unsigned));
    f->slotk = (int *)malloc(((size_t)f->slots + 1) * sizeof(int));
    for (size_t key = 0; key < nkey; key++)
        if (slot_of[key] >= 0)
            f->slotk[slot_of[key]] = key & 1 ? ~(int)(key >> 1) : (int)(key >> 1);
    for (size_t i = 0; i < (size_t)h->nown; i++)
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++) {
            const int s = slot_of[2 * (size_t)h->hb_k[p]], r = slot_of[2 * (size_t)h->hb_k[p] + 1];
            f->mask[(size_t)(s >> 5) * n + i] |= 1u << (s & 31);
            f->mask[(size_t)(r >> 5) * n + (size_t)h->hb[p]] |= 1u << (r & 31);
        }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
        f->count[i] = 0;
        for (size_t w = words; w-- > 0;)
            if (f->mask[w * n + i]) {
                f->count[i] = (int)(w * 32) + 32 - __builtin_clz(f->mask[w * n + i]);
                break;
            }
    }
}

/* Each particle's count of full-list pairs into count (n), their largest into *maxc; returns
 * where each particle's pairs start in a packed array (n + 1 prefix sums).  (On many
 * processes the rows of own particles, each with its pairs with the halo too, h->xb: a halo
 * particle has no list.) */
static size_t *sph_pair_starts(const sph_body *h, int *count, int *maxc)
{
    const size_t n = (size_t)h->n;
    size_t *start = (size_t *)calloc(n + 1, sizeof(size_t));
    for (size_t i = 0; i < (size_t)h->nown; i++) {
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++)
            start[i + 1]++, start[h->hb[p] + 1]++;
        if (h->xb_start)
            start[i + 1] += (size_t)(h->xb_start[i + 1] - h->xb_start[i]);
    }
    *maxc = 0;
    for (size_t i = 0; i < n; i++) {
        count[i] = (int)start[i + 1];
        *maxc = count[i] > *maxc ? count[i] : *maxc;
        start[i + 1] += start[i];
    }
    return start;
}

/* Every pair from both sides, packed as key << 32 | j in each particle's range of start. */
static uint64_t *sph_packed_pairs(const sph_body *h, const size_t *start)
{
    const size_t n = (size_t)h->n;
    uint64_t *packed = (uint64_t *)malloc((start[n] + 1) * sizeof(uint64_t));
    size_t *fill = (size_t *)malloc((n + 1) * sizeof(size_t));
    memcpy(fill, start, n * sizeof(size_t));
    for (size_t i = 0; i < (size_t)h->nown; i++) {
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++) {
            const uint64_t j = (uint64_t)h->hb[p], key = 2 * (uint64_t)h->hb_k[p];
            packed[fill[i]++] = key << 32 | j;
            packed[fill[j]++] = (key + 1) << 32 | i;
        }
        for (int p = h->xb_start ? h->xb_start[i] : 0; h->xb_start && p < h->xb_start[i + 1]; p++)
            packed[fill[i]++] = (2 * (uint64_t)h->xb_k[p]) << 32 | (uint64_t)h->xb[p];
    }
    free(fill);
    return packed;
}

/* The lists nb and k of f from the packed pairs: with fixed slots (slot_of, and f->off the
 * slots' offsets) each pair in its key's slot, the rest holes; else packed from slot 0. */
static void sph_slot_lists(const sph_body *h, const size_t *start, uint64_t *packed,
                           const int *slot_of, sph_full *f)
{
    const size_t n = (size_t)h->n, slots = (size_t)f->slots;
    int *nb = f->nb = (int *)malloc((slots * n + 1) * sizeof(int));
    int *k = f->k = (int *)malloc((slots * n + 1) * sizeof(int));
#pragma omp parallel for schedule(static)
    for (size_t e = 0; e < slots * n; e++) { /* holes: sph_hole and the zero entry */
        const int i = (int)(e % n);
        nb[e] = slot_of ? sph_hole(i, f->off[e / n], h->nown) : i, k[e] = h->ntab;
    }
#pragma omp parallel for schedule(dynamic, 1024)
    for (size_t i = 0; i < n; i++) {
        std::sort(packed + start[i], packed + start[i + 1]);
        size_t last = 0; /* with fixed slots: the last slot used, holes before it included */
        for (size_t a = 0; a < start[i + 1] - start[i]; a++) {
            const uint64_t w = packed[start[i] + a], key = w >> 32;
            const size_t s = slot_of ? (size_t)slot_of[key] : a;
            nb[s * n + i] = (int)(w & 0xffffffffu);
            k[s * n + i] = key & 1 ? ~(int)(key >> 1) : (int)(key >> 1);
            last = s + 1 > last ? s + 1 : last;
        }
        if (slot_of)
            f->count[i] = (int)last;
    }
}

/* Full pair lists from the half lists (j > i): i gets (j, k), j gets (i, ~k), laid out slot
 * by slot (sphrt.h, fb_*).  A pair is packed as key << 32 | j, key = 2k or 2~k + 1 (every
 * offset its own key), and each particle's pairs are sorted by key.  When the body's pairs
 * use few distinct keys (a lattice: one table entry per offset) every key gets a fixed
 * slot, the same for every particle (sph_slot_ranks), and a particle's missing neighbours
 * are holes: a particle near i + the slot's offset (sph_hole) with the zero table entry
 * ntab, which adds nothing, so the passes need no branch.  A warp at one slot then reads one
 * offset in every thread, including threads whose particles lie near a surface.  Where
 * moreover every pair lies at i + its slot's offset (a box; not on many processes, whose
 * halo particles lie elsewhere) the lists are slot masks instead (sph_slot_masks): 4 bytes a
 * particle for 32 slots instead of 8 a pair, which the passes would otherwise stream from
 * memory at every step.  Built with -DSPH_CUDA_LISTS, lists always (bench/cuda's A/B).  Off
 * a lattice the pairs are packed from slot 0. */
static void sph_full_lists(const sph_body *h, sph_full *f)
{
    const size_t n = (size_t)h->n, nkey = 2 * (size_t)h->ntab + 2;
    int maxc, used = 0, uniform = 0;
    f->count = (int *)malloc((n + 1) * sizeof(int));
    f->nb = f->k = NULL, f->mask = NULL, f->off = f->slotk = NULL;
    size_t *start = sph_pair_starts(h, f->count, &maxc);
    /* few keys (one per offset: a lattice): fixed slots, if holes fill at most half of them */
    int *slot_of = nkey <= 4 * (size_t)maxc + 4 ? (int *)calloc(nkey, sizeof(int)) : NULL;
    long *off = slot_of ? (long *)calloc(nkey, sizeof(long)) : NULL;
    if (slot_of)
        used = sph_slot_ranks(h, nkey, slot_of, off, &uniform);
    if (slot_of && used > maxc + maxc / 2)
        free(slot_of), slot_of = NULL;
    f->slots = slot_of ? used : maxc;
    if (slot_of) { /* each slot's offset: the masks' neighbours, the lists' holes */
        f->off = (int *)calloc((size_t)used + 1, sizeof(int));
        for (size_t key = 0; key < nkey; key++)
            if (slot_of[key] >= 0)
                f->off[slot_of[key]] = (int)off[key];
    }
#ifdef SPH_CUDA_LISTS
    uniform = 0; /* lists for every body */
#endif
    if (slot_of && uniform && !h->xb_start)
        sph_slot_masks(h, nkey, slot_of, f);
    else {
        uint64_t *packed = sph_packed_pairs(h, start);
        sph_slot_lists(h, start, packed, slot_of, f);
        free(packed);
        free(f->off), f->off = NULL; /* (the device reads the lists) */
    }
    free(start), free(slot_of), free(off);
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

/* The device view of host body h (see the top of this file). */
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
    b->fix = (uint8_t *)sph_dev_copy(h->fix, n);
    b->state = (double *)sph_dev_copy(h->state, n * (size_t)h->desc->nstate * sizeof(double));
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

/* What a pair pass reads of its neighbours' u or v (D values a particle), by component:
 * s[r*n + i] = a[i*D + r] over all n particles (the halo's too, which has arrived), copied
 * by the pass that reads it, so that a warp's load of one component of 32 consecutive
 * neighbours touches 2 or 3 lines of 128 bytes instead of 6 or 7 (docs/cuda.md); returns
 * the array to read, through SPH_VEC(i, r, D, n).  Built with -DSPH_CUDA_AOS, no copy: a
 * itself, particle by particle (bench/cuda's A/B). */
#ifdef SPH_CUDA_AOS
#define SPH_VEC(i, r, D, n) ((void)(n), (size_t)(i) * (size_t)(D) + (size_t)(r))
#else
#define SPH_VEC(i, r, D, n) ((size_t)(r) * (size_t)(n) + (size_t)(i))
#endif
static const double *sph_cuda_components_in(const double *a, double *s, int n, int D,
                                             const char *pass)
{
#ifdef SPH_CUDA_AOS
    (void)s, (void)n, (void)D, (void)pass;
    return a;
#else
    sph_for(n, pass, [=] __device__(int i) {
        for (int r = 0; r < D; r++)
            s[(size_t)r * (size_t)n + (size_t)i] = a[(size_t)i * (size_t)D + (size_t)r];
    });
    return s;
#endif
}
#define sph_cuda_components(a, s, n, D) sph_cuda_components_in((a), (s), (n), (D), __func__)

/* The sums of device view d's last step into host body h (the time step of sph_sim_step,
 * the energies; after a batch, the clock's copy has waited already). */
static void sph_cuda_reductions(sph_body *h, const sph_body *d)
{
    double red[SPH_NRED];
    SPH_CUDA_CHECK(cudaMemcpy(red, d->red, sizeof red, cudaMemcpyDeviceToHost));
    sph_cuda_profile_collect(); /* (the host has waited) */
    h->vmax2 = red[SPH_RED_VMAX2], h->amax2 = red[SPH_RED_AMAX2];
    h->lam2min = sph_red_lam2min(red);
    h->visc_rate = red[SPH_RED_VISC_RATE], h->visc_dissipated = red[SPH_RED_VISC_DISSIPATED];
}

/* ---- the device's clock: a batch of steps (sph_model.advance) ----------------------------- */

/* The time step of the next step from the last step's sums, as sph_sim_stable_dt and
 * sph_sim_advance choose it on the host; or the end of the batch. */
__device__ static inline void sph_clock_choose_on(sph_cuda_clock *c)
{
    if (c->skip)
        return;
    if (!(c->t < c->t_stop - c->eps)) {
        c->skip = 1;
        return;
    }
    double dt = INFINITY, vmax2 = 0, amax2 = 0;
    c->dt_factor = 1.0;
    for (int i = 0; i < c->nbodies; i++) {
        const sph_body *b = c->bodies[i];
        const double *red = b->red;
        const double f = sph_stretch_factor(c->lambda_on, b->lam2 != NULL, sph_red_lam2min(red));
        c->dt_factor = fmin(c->dt_factor, f);
        dt = fmin(dt, sph_body_dt(f, b->h, b->c0, red[SPH_RED_VMAX2], red[SPH_RED_AMAX2]));
        vmax2 = fmax(vmax2, red[SPH_RED_VMAX2]), amax2 = fmax(amax2, red[SPH_RED_AMAX2]);
    }
    if (c->contact_sums) { /* the stiffest contact, where a pair is in contact or near it */
        const double *cs = c->contact_sums;
        const int near = sph_contact_near(cs[SPH_CSUM_CLOSE], cs[SPH_CSUM_LEVEL], vmax2, amax2,
                                          c->dt, sph_chosen_dt(c->dt_fixed, c->cfl, dt));
        dt = fmin(dt, sph_contact_bound(cs[SPH_CSUM_W2], c->contact_w2ref, near));
    }
    dt = sph_chosen_dt(c->dt_fixed, c->cfl, dt);
    const double floor_now = sph_dt_floor_now(c->floor_dt, c->dt_factor);
    if (!(dt >= floor_now)) {
        c->collapsed = 1, c->dt_bad = dt, c->floor_bad = floor_now, c->skip = 1;
        return;
    }
    c->dt = fmin(dt, c->t_stop - c->t);
}

__device__ static inline void sph_clock_tick_on(sph_cuda_clock *c)
{
    if (c->skip)
        return;
    c->t += c->dt;
    c->step++;
}

__global__ void sph_clock_choose_kernel() { sph_clock_choose_on(&sph_clock); }
__global__ void sph_clock_tick_kernel() { sph_clock_tick_on(&sph_clock); }
__global__ void sph_clock_resume_kernel() { sph_clock.skip = 0; }
static void sph_cuda_clock_choose()
{
    sph_launch("the clock's choice of the time step",
               [] { SPH_ONE_THREAD(sph_clock_choose_kernel); });
}
static void sph_cuda_clock_tick()
{
    sph_launch("the clock's tick", [] { SPH_ONE_THREAD(sph_clock_tick_kernel); });
}
static void sph_cuda_clock_resume()
{
    sph_launch("the clock's resumption", [] { SPH_ONE_THREAD(sph_clock_resume_kernel); });
}

/* The clock at the start of a batch: the host's time, the batch and the scene.  At the first
 * step the host's sums (sph_sim_init's initial speeds) go to the device, where the first time
 * step is chosen from them. */
static void sph_cuda_clock_start(const sph_sim *s, const sph_advance *a, sph_body *const *dev,
                                 const double *contact_sums, double contact_w2ref)
{
    if (s->step == 0)
        for (int i = 0; i < s->nbodies; i++)
            sph_host_sums_to_device(&s->bodies[i], dev[i]->red);
    static sph_body **views; /* the device views, where the device's clock reads them */
    if (!views) {
        SPH_CUDA_CHECK(cudaMallocManaged(&views, (size_t)s->nbodies * sizeof *views));
        for (int i = 0; i < s->nbodies; i++)
            views[i] = dev[i];
        sph_read_mostly(views, (size_t)s->nbodies * sizeof *views);
    }
    const sph_model *m = s->m;
    sph_cuda_clock c = {};
    c.t = s->t, c.dt = s->dt, c.step = s->step, c.dt_factor = s->dt_factor;
    c.t_stop = a->t_stop, c.eps = a->eps, c.floor_dt = a->floor_dt;
    c.cfl = m->cfl, c.dt_fixed = m->dt_fixed, c.lambda_on = m->dt_lambda_on;
    c.nbodies = s->nbodies, c.bodies = views;
    c.contact_sums = contact_sums, c.contact_w2ref = contact_w2ref;
    SPH_CUDA_CHECK(cudaMemcpyToSymbol(sph_clock, &c, sizeof c));
}

/* The end of a batch: the passes run again (skip cleared), and the host waits for the clock:
 * its time, step and time step, and whether the time step collapsed. */
static void sph_cuda_clock_finish(sph_sim *s, sph_advance *a)
{
    sph_cuda_clock_resume();
    SPH_CUDA_CHECK(cudaGetLastError());
    sph_cuda_clock c;
    SPH_CUDA_CHECK(cudaMemcpyFromSymbol(&c, sph_clock, sizeof c));
    sph_cuda_profile_collect(); /* (the host has waited) */
    s->t = c.t, s->dt = c.dt, s->step = c.step, s->dt_factor = c.dt_factor;
    a->collapsed = c.collapsed, a->dt_bad = c.dt_bad, a->floor_bad = c.floor_bad;
}

/* Whether the clock stopped the batch (one small copy: the host waits for the steps queued). */
static int sph_cuda_clock_stopped()
{
    sph_cuda_clock c;
    SPH_CUDA_CHECK(cudaMemcpyFromSymbol(&c, sph_clock, sizeof c));
    sph_cuda_profile_collect(); /* (the host has waited) */
    return c.skip;
}

/* Steps the host queues before it looks whether the clock stopped the batch. */
#ifndef SPH_CLOCK_CHUNK
#define SPH_CLOCK_CHUNK 20
#endif

/* A batch of steps (sph_model.advance): up to a->steps steps, each of the passes that
 * `step` queues (reading t and dt from the clock) between the clock's choice and tick.  The
 * host queues them SPH_CLOCK_CHUNK at a time and, where steps are left after a chunk, looks
 * whether the clock has stopped, so that a batch asked for many steps (up to its stop time)
 * queues only a chunk more than it takes.  contact_sums, contact_w2ref: the contact's bound
 * (NULL, 0 without contact). */
static void sph_cuda_advance(sph_sim *s, sph_advance *a, sph_body *const *dev,
                             const double *contact_sums, double contact_w2ref, void (*step)())
{
    sph_cuda_clock_start(s, a, dev, contact_sums, contact_w2ref);
    for (int done = 0; done < a->steps;) {
        const int chunk = a->steps - done < SPH_CLOCK_CHUNK ? a->steps - done : SPH_CLOCK_CHUNK;
        for (int k = 0; k < chunk; k++) {
            sph_cuda_clock_choose();
            step();
            sph_cuda_clock_tick();
        }
        done += chunk;
        if (done < a->steps && ((a->stop && *a->stop) || sph_cuda_clock_stopped()))
            break;
    }
    sph_cuda_clock_finish(s, a);
}

/* The stability monitor's sums of device view d, after its monitor pass: a few numbers
 * instead of the state (runtime/monitor.c). */
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
