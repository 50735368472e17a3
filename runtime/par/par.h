/* par.h — the processes of a run: one (sph_par_one, par.c), or many under MPI (mpi/,
 * libsphrt_mpi, sph_mpi_main), and the values of a body's particles their halo exchanges
 * carry. */
#ifndef SPHRT_PAR_PAR_H
#define SPHRT_PAR_PAR_H

#include <stddef.h>

#include "core/defs.h"

SPH_C_BEGIN

/* Values of a body's particles that a pass reads from neighbours: bytes per particle at
 * base (particle i at base + i size), for the halo exchange of runs on many processes. */
typedef struct {
    void *base;
    size_t size;
} sph_field;
#define SPH_FIELD(array, per_particle) ((sph_field){(array), (per_particle) * sizeof *(array)})

typedef struct sph_body sph_body;

/* The processes of a run: one (sph_par_one), or many under MPI (libsphrt_mpi, sph_mpi_main).
 * The runtime calls these at the points where processes must agree; on one process they
 * do nothing.  Sums add the processes' values in process order, so that every process gets
 * the same bits whatever the library's reduction order. */
typedef struct sph_par {
    int rank, size;
    void (*sum)(double *x, int n);          /* in place, elementwise over the processes */
    void (*min)(double *x, int n);
    void (*max)(double *x, int n);
    /* Collective: 1 when `bad` on any process; then the first message (sph_error) of the
     * lowest failing process is printed by process 0, unless process 0 failed too. */
    int (*agree)(int bad);
    void (*bcast)(void *buf, int bytes, int root);
    /* Every process's `bytes` at mine into all (size blocks, in process order). */
    void (*allgather)(const void *mine, void *all, int bytes);
    /* Collective: process 0 gets every process's block (any length) in process order, and
     * calls take(ctx, process, data, bytes) with each; the others only send. */
    void (*gather0)(const void *data, size_t bytes,
                    void (*take)(void *ctx, int from, const void *data, size_t bytes),
                    void *ctx);
    /* Every process sends out[q] (bytes[q] bytes) to process q and gets what each sent it:
     * *in (malloc'd; free it) holds the blocks in process order, got[q] bytes from q. */
    void (*swap)(const void *const *out, const size_t *bytes, void **in, size_t *got);
    /* Collective, once after every body's set-up: the plan of body b's halo exchange;
     * 0, or -1 after a message. */
    int (*body_ready)(sph_body *b);
    void (*body_free)(sph_body *b);
    /* The halo's values of nf fields of body b from their processes: post starts the
     * exchange, wait ends it (the same fields); passes that need no halo value run between. */
    void (*post)(sph_body *b, const sph_field *f, int nf);
    void (*wait)(sph_body *b, const sph_field *f, int nf);
    /* For device targets, which pack and unpack the values themselves: body b's halo plan,
     * the own particles whose values go out (in this order) and, for each value that comes
     * in, the halo particle it is of (0 .. n - nown - 1); 0 of each on one process.  Then the
     * exchange itself of packed values, `bytes` per particle, blocking. */
    void (*halo_lists)(const sph_body *b, const int **send, int *nsend, const int **recv,
                       int *nrecv);
    void (*exchange_packed)(sph_body *b, const void *out, void *in, size_t bytes);
    /* 1: exchange_packed takes device memory (an MPI library that reads and writes a
     * device's memory itself, CUDA-aware), so a device target's halo goes from device buffer
     * to device buffer; 0: through host buffers. */
    int device_buffers;
    /* The bytes this process has sent in all exchanges so far, and the seconds it waited
     * for them (in wait). */
    double (*bytes_sent)(void);
    double (*wait_seconds)(void);
} sph_par;

/* The run on one process. */
extern const sph_par sph_par_one;

SPH_C_END

#endif
