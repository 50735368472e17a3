/* launch.h — a pass's launch on the device: whether the host waits for every kernel and
 * checks it, and the profile's events around the kernels (--profile). */
#ifndef SPHRT_CUDA_LAUNCH_H
#define SPHRT_CUDA_LAUNCH_H

#include <cstdlib>
#include <cstring>

#include "target.h"
#include "check.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "core/profile.h"

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
 * time to the pass that launched it (core/profile.c), in the phase of the run it was
 * launched in. */
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

#endif
