/* par_mpi.c — a generated program on many processes (sphc --mpi, docs/mpi.md): MPI started
 * and ended around the run, and the runtime's agreements (sph_par) made with MPI: sums in
 * process order, minima and maxima, a failure on any process, the halo exchanges of the
 * bodies (halo.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "halo.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "par/par.h"
#include "run/main.h"
#include "scene/body.h"
#include "scene/model.h"

#if defined(__has_include)
#if __has_include(<mpi-ext.h>)
#include <mpi-ext.h> /* Open MPI's extensions: MPIX_Query_cuda_support */
#endif
#endif

static MPI_Comm comm = MPI_COMM_NULL;
static double sent_bytes, waited;

static void out_of_memory(void)
{
    fprintf(stderr, "error: out of memory on process of a run on many processes\n");
    MPI_Abort(comm, SPH_EXIT_SETUP);
}

/* Sums in process order: every process adds the same values in the same order, so the bits
 * do not depend on MPI's reduction tree. */
static void par_sum(double *x, int n)
{
    int size;
    MPI_Comm_size(comm, &size);
    double *all = malloc(((size_t)n * (size_t)size + 1) * sizeof *all);
    if (!all)
        out_of_memory();
    MPI_Allgather(x, n, MPI_DOUBLE, all, n, MPI_DOUBLE, comm);
    for (int k = 0; k < n; k++) {
        double s = 0;
        for (int r = 0; r < size; r++)
            s += all[(size_t)r * n + k];
        x[k] = s;
    }
    free(all);
}

static void par_min(double *x, int n)
{
    MPI_Allreduce(MPI_IN_PLACE, x, n, MPI_DOUBLE, MPI_MIN, comm);
}

static void par_max(double *x, int n)
{
    MPI_Allreduce(MPI_IN_PLACE, x, n, MPI_DOUBLE, MPI_MAX, comm);
}

static void par_bcast(void *buf, int bytes, int root)
{
    MPI_Bcast(buf, bytes, MPI_BYTE, root, comm);
}

static void par_allgather(const void *mine, void *all, int bytes)
{
    MPI_Allgather(mine, bytes, MPI_BYTE, all, bytes, MPI_BYTE, comm);
}

/* Blocks of any length to process 0, one process after the other (so that process 0 holds
 * one at a time), in pieces of at most 1 GiB (MPI counts are ints). */
enum { TAG_GATHER = 11, CHUNK = 1 << 30 };

static void send_block(const void *data, size_t bytes)
{
    uint64_t n = bytes;
    MPI_Send(&n, 1, MPI_UINT64_T, 0, TAG_GATHER, comm);
    for (size_t at = 0; at < bytes; at += CHUNK) {
        const size_t k = bytes - at < CHUNK ? bytes - at : CHUNK;
        MPI_Send((const char *)data + at, (int)k, MPI_BYTE, 0, TAG_GATHER, comm);
    }
}

static void par_gather0(const void *data, size_t bytes,
                        void (*take)(void *ctx, int from, const void *data, size_t bytes),
                        void *ctx)
{
    int rank, size;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    if (rank != 0) {
        /* (a handshake first: process 0 takes the blocks in order, one in memory at once) */
        MPI_Recv(NULL, 0, MPI_BYTE, 0, TAG_GATHER, comm, MPI_STATUS_IGNORE);
        send_block(data, bytes);
        return;
    }
    take(ctx, 0, data, bytes);
    for (int q = 1; q < size; q++) {
        uint64_t n;
        MPI_Send(NULL, 0, MPI_BYTE, q, TAG_GATHER, comm);
        MPI_Recv(&n, 1, MPI_UINT64_T, q, TAG_GATHER, comm, MPI_STATUS_IGNORE);
        char *buf = malloc(n + 1);
        if (!buf)
            out_of_memory();
        for (size_t at = 0; at < n; at += CHUNK) {
            const size_t k = n - at < CHUNK ? n - at : CHUNK;
            MPI_Recv(buf + at, (int)k, MPI_BYTE, q, TAG_GATHER, comm, MPI_STATUS_IGNORE);
        }
        take(ctx, q, buf, n);
        free(buf);
    }
}

static void par_swap(const void *const *out, const size_t *bytes, void **in, size_t *got)
{
    int size;
    MPI_Comm_size(comm, &size);
    int *count = malloc(4 * ((size_t)size + 1) * sizeof *count);
    unsigned char *send = NULL;
    if (!count)
        out_of_memory();
    int *sdisp = count + size, *rcount = count + 2 * size, *rdisp = count + 3 * size;
    size_t total = 0;
    for (int q = 0; q < size; q++) {
        if (bytes[q] > (size_t)CHUNK || total > (size_t)CHUNK)
            out_of_memory(); /* (an int count; never near for contact's neighbours) */
        count[q] = (int)bytes[q], sdisp[q] = (int)total, total += bytes[q];
    }
    send = malloc(total + 1);
    if (!send)
        out_of_memory();
    for (int q = 0; q < size; q++)
        memcpy(send + sdisp[q], out[q], bytes[q]);
    MPI_Alltoall(count, 1, MPI_INT, rcount, 1, MPI_INT, comm);
    size_t rtotal = 0;
    for (int q = 0; q < size; q++)
        rdisp[q] = (int)rtotal, rtotal += (size_t)rcount[q], got[q] = (size_t)rcount[q];
    *in = malloc(rtotal + 1);
    if (!*in)
        out_of_memory();
    MPI_Alltoallv(send, count, sdisp, MPI_BYTE, *in, rcount, rdisp, MPI_BYTE, comm);
    free(send), free(count);
}

/* A failure anywhere: process 0 has reported its own; a failure of other processes alone is
 * reported by process 0 with the lowest one's first message. */
static int par_agree(int bad)
{
    int rank, size;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    int *flags = malloc(((size_t)size + 1) * sizeof *flags);
    if (!flags)
        out_of_memory();
    bad = bad != 0;
    MPI_Allgather(&bad, 1, MPI_INT, flags, 1, MPI_INT, comm);
    int first = -1;
    for (int r = 0; r < size && first < 0; r++)
        if (flags[r])
            first = r;
    free(flags);
    if (first <= 0)
        return first == 0;
    char msg[1024] = "";
    if (rank == first)
        snprintf(msg, sizeof msg, "%s", sph_message_kept());
    MPI_Bcast(msg, sizeof msg, MPI_CHAR, first, comm);
    if (rank == 0)
        sph_error("process %d: %s", first, msg[0] ? msg : "failed (no message)");
    return 1;
}

static int body_ready(sph_body *b)
{
    if (b->nown == b->n && !b->gid)
        return 0; /* (one process: no halo) */
    sph_halo *h = calloc(1, sizeof *h);
    if (!h || sph_halo_plan_ids(h, b->nown, b->gid, b->n - b->nown, b->gid + b->nown,
                                b->halo_part, comm)) {
        free(h);
        sph_error("body '%s': no plan for its halo exchange", b->desc->name);
        return -1;
    }
    b->halo = h;
    return 0;
}

static void body_free(sph_body *b)
{
    if (!b->halo)
        return;
    sph_halo_free(b->halo);
    free(b->halo);
    b->halo = NULL;
}

static void post(sph_body *b, const sph_field *f, int nf)
{
    sph_halo *h = b->halo;
    if (!h)
        return;
    if (sph_halo_post(h, f, nf))
        out_of_memory();
    sent_bytes += (double)h->bytes;
}

static void wait_halo(sph_body *b, const sph_field *f, int nf)
{
    if (!b->halo)
        return;
    const double t0 = MPI_Wtime();
    sph_halo_wait(b->halo, f, nf);
    waited += MPI_Wtime() - t0;
}

static void halo_lists(const sph_body *b, const int **send, int *nsend, const int **recv,
                       int *nrecv)
{
    const sph_halo *h = b->halo;
    *send = h ? h->send : NULL, *recv = h ? h->recv : NULL;
    *nsend = h ? h->send_start[h->npeers] : 0, *nrecv = h ? h->recv_start[h->npeers] : 0;
}

static void exchange_packed(sph_body *b, const void *out, void *in, size_t bytes)
{
    sph_halo *h = b->halo;
    if (!h)
        return;
    const double t0 = MPI_Wtime();
    if (sph_halo_exchange_packed(h, out, in, bytes))
        out_of_memory();
    sent_bytes += (double)h->send_start[h->npeers] * (double)bytes;
    waited += MPI_Wtime() - t0;
}

static double bytes_sent(void) { return sent_bytes; }
static double wait_seconds(void) { return waited; }

/* Whether the MPI library takes device memory in its calls (CUDA-aware): $SPH_MPI_DEVICE_BUFFERS
 * (0 or 1) where it is set, else Open MPI's answer at run time (its cuda extension: a build
 * whose headers say 0 may still load the support), else no.  Every process asks the same
 * library, and they agree all the same (the lowest answer), since a device target's halo
 * must go the same way on both ends. */
static int device_buffers(void)
{
    const char *e = getenv("SPH_MPI_DEVICE_BUFFERS");
    int yes = 0;
    if (e && *e)
        yes = strcmp(e, "0") != 0;
#if defined(OMPI_HAVE_MPI_EXT_CUDA) && OMPI_HAVE_MPI_EXT_CUDA
    else
        yes = MPIX_Query_cuda_support() == 1;
#endif
    int all = yes;
    MPI_Allreduce(&yes, &all, 1, MPI_INT, MPI_MIN, comm);
    return all;
}

int sph_mpi_main(const sph_model *m, int argc, char **argv)
{
    int provided;
    /* the threads of a process (OpenMP) never call MPI: funneled through the main thread */
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_dup(MPI_COMM_WORLD, &comm);
    sph_par par = {
        .sum = par_sum, .min = par_min, .max = par_max, .agree = par_agree, .bcast = par_bcast,
        .allgather = par_allgather, .gather0 = par_gather0, .swap = par_swap,
        .body_ready = body_ready, .body_free = body_free, .post = post, .wait = wait_halo,
        .halo_lists = halo_lists, .exchange_packed = exchange_packed,
        .bytes_sent = bytes_sent, .wait_seconds = wait_seconds,
    };
    MPI_Comm_rank(comm, &par.rank);
    MPI_Comm_size(comm, &par.size);
    par.device_buffers = device_buffers();
    if (par.rank != 0) {
        /* messages and progress come from process 0 (sph_par agree reports the others') */
        sph_message_keep(1);
        if (!freopen("/dev/null", "w", stdout))
            fprintf(stderr, "warning: process %d: its output is not silenced\n", par.rank);
    }
    const int rc = sph_main_par(m, argc, argv, &par);
    /* the exit status of process 0 is the run's (every process reaches the same end) */
    MPI_Comm_free(&comm);
    MPI_Finalize();
    return rc;
}
