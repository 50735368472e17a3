/* halo.h — runs on many processes (sphc --mpi, docs/mpi.md): the device each process takes,
 * and the halo exchange of a device view's fields. */
#ifndef SPHRT_CUDA_HALO_H
#define SPHRT_CUDA_HALO_H

#include <cstdlib>

#include "target.h"
#include "check.h"
#include "loops.h"
#include "memory.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "par/par.h"
#include "scene/body.h"

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

enum { SPH_CUDA_HALO_FIELDS = 5 }; /* (the momentum pass's Q, cof F, Cs, F and Qq) */
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

#endif
