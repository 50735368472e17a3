/* par.c — the processes of a run on one process (sph_par_one): every agreement is this
 * process's own, and there is no halo.  The many-process version is mpi/par_mpi.c. */
#include <stdlib.h>
#include <string.h>

#include "par.h"

static void one_values(double *x, int n) { (void)x, (void)n; }
static int one_agree(int bad) { return bad; }
static void one_bcast(void *buf, int bytes, int root) { (void)buf, (void)bytes, (void)root; }
static int one_body_ready(sph_body *b) { return (void)b, 0; }
static void one_body_free(sph_body *b) { (void)b; }
static void one_fields(sph_body *b, const sph_field *f, int nf) { (void)b, (void)f, (void)nf; }
static double one_zero(void) { return 0.0; }
static void one_halo_lists(const sph_body *b, const int **send, int *nsend, const int **recv,
                           int *nrecv)
{
    (void)b;
    *send = *recv = NULL;
    *nsend = *nrecv = 0;
}
static void one_exchange_packed(sph_body *b, const void *out, void *in, size_t bytes)
{
    (void)b, (void)out, (void)in, (void)bytes;
}
static void one_allgather(const void *mine, void *all, int bytes)
{
    memcpy(all, mine, (size_t)bytes);
}
static void one_swap(const void *const *out, const size_t *bytes, void **in, size_t *got)
{
    *in = malloc(bytes[0] + 1);
    if (*in)
        memcpy(*in, out[0], bytes[0]);
    got[0] = *in ? bytes[0] : 0;
}
static void one_gather0(const void *data, size_t bytes,
                        void (*take)(void *ctx, int from, const void *data, size_t bytes),
                        void *ctx)
{
    take(ctx, 0, data, bytes);
}

const sph_par sph_par_one = {
    .rank = 0, .size = 1,
    .sum = one_values, .min = one_values, .max = one_values,
    .agree = one_agree, .bcast = one_bcast, .allgather = one_allgather, .gather0 = one_gather0,
    .swap = one_swap,
    .body_ready = one_body_ready, .body_free = one_body_free,
    .post = one_fields, .wait = one_fields,
    .halo_lists = one_halo_lists, .exchange_packed = one_exchange_packed,
    .bytes_sent = one_zero, .wait_seconds = one_zero,
};
