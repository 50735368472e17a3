/* halo.c — the exchange plan of a part's halo and the exchange itself (halo.h). */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "halo.h"
#include "geom/partition.h"
#include "par/par.h"

enum { TAG_COUNT = 1, TAG_IDS = 2, TAG_VALUES = 3 };

/* The peers (the parts of the halo, ascending) and, per peer, the halo particles it
 * provides (in id order, as the halo is). */
static int plan_receives(sph_halo *h, const int *halo_part, int nparts)
{
    int *count = calloc((size_t)nparts, sizeof *count);
    if (!count)
        return -1;
    for (int i = 0; i < h->nhalo; i++)
        count[halo_part[i]]++;
    h->peer = malloc(((size_t)nparts + 1) * sizeof *h->peer);
    h->recv_start = malloc(((size_t)nparts + 1) * sizeof *h->recv_start);
    h->recv = malloc(((size_t)h->nhalo + 1) * sizeof *h->recv);
    int *slot = malloc(((size_t)nparts + 1) * sizeof *slot);
    if (!h->peer || !h->recv_start || !h->recv || !slot) {
        free(count), free(slot);
        return -1;
    }
    h->npeers = 0;
    h->recv_start[0] = 0;
    for (int p = 0; p < nparts; p++)
        if (count[p]) {
            slot[p] = h->npeers;
            h->peer[h->npeers] = p;
            h->recv_start[h->npeers + 1] = h->recv_start[h->npeers] + count[p];
            h->npeers++;
        }
    int *at = calloc((size_t)h->npeers + 1, sizeof *at);
    for (int i = 0; at && i < h->nhalo; i++) {
        const int q = slot[halo_part[i]];
        h->recv[h->recv_start[q] + at[q]++] = i;
    }
    free(count), free(slot);
    if (!at)
        return -1;
    free(at);
    return 0;
}

/* What each peer needs of this part: the ids it asks for (counts first), as own indices. */
static int plan_sends(sph_halo *h, const int64_t *own_id, const int64_t *halo_id)
{
    const int np = h->npeers;
    int *want = malloc(((size_t)np + 1) * sizeof *want);
    int *asks = malloc(((size_t)np + 1) * sizeof *asks);
    MPI_Request *req = malloc((2 * (size_t)np + 1) * sizeof *req);
    if (!want || !asks || !req)
        return free(want), free(asks), free(req), -1;
    for (int q = 0; q < np; q++) {
        want[q] = h->recv_start[q + 1] - h->recv_start[q];
        MPI_Irecv(&asks[q], 1, MPI_INT, h->peer[q], TAG_COUNT, h->comm, &req[q]);
        MPI_Isend(&want[q], 1, MPI_INT, h->peer[q], TAG_COUNT, h->comm, &req[np + q]);
    }
    MPI_Waitall(2 * np, req, MPI_STATUSES_IGNORE);
    h->send_start = malloc(((size_t)np + 1) * sizeof *h->send_start);
    if (!h->send_start)
        return free(want), free(asks), free(req), -1;
    h->send_start[0] = 0;
    for (int q = 0; q < np; q++)
        h->send_start[q + 1] = h->send_start[q] + asks[q];
    const int nsend = h->send_start[np];
    int64_t *ids_in = malloc(((size_t)nsend + 1) * sizeof *ids_in);
    int64_t *ids_out = malloc(((size_t)h->recv_start[np] + 1) * sizeof *ids_out);
    h->send = malloc(((size_t)nsend + 1) * sizeof *h->send);
    if (!ids_in || !ids_out || !h->send)
        return free(want), free(asks), free(req), free(ids_in), free(ids_out), -1;
    for (int i = 0; i < h->recv_start[np]; i++)
        ids_out[i] = halo_id[h->recv[i]];
    for (int q = 0; q < np; q++) {
        MPI_Irecv(ids_in + h->send_start[q], asks[q], MPI_INT64_T, h->peer[q], TAG_IDS, h->comm,
                  &req[q]);
        MPI_Isend(ids_out + h->recv_start[q], want[q], MPI_INT64_T, h->peer[q], TAG_IDS,
                  h->comm, &req[np + q]);
    }
    MPI_Waitall(2 * np, req, MPI_STATUSES_IGNORE);
    sph_id_index *sorted = sph_id_sort(own_id, h->nown);
    int bad = !sorted;
    for (int i = 0; !bad && i < nsend; i++)
        if ((h->send[i] = sph_id_find(sorted, h->nown, ids_in[i])) < 0)
            bad = 2;
    free(want), free(asks), free(req), free(ids_in), free(ids_out), free(sorted);
    return -bad;
}

/* Buffers for `bytes` per particle: 0, or -1 when memory runs out. */
static int reserve(sph_halo *h, size_t bytes)
{
    if (bytes <= h->cap)
        return 0;
    const int np = h->npeers;
    unsigned char *sb = realloc(h->sbuf, (size_t)h->send_start[np] * bytes + 1);
    if (sb)
        h->sbuf = sb;
    unsigned char *rb = realloc(h->rbuf, (size_t)h->recv_start[np] * bytes + 1);
    if (rb)
        h->rbuf = rb;
    if (!sb || !rb)
        return -1;
    h->cap = bytes;
    return 0;
}

int sph_halo_plan_ids(sph_halo *h, int nown, const int64_t *own_id, int nhalo,
                      const int64_t *halo_id, const int *halo_part, MPI_Comm comm)
{
    memset(h, 0, sizeof *h);
    h->comm = comm;
    h->nown = nown, h->nhalo = nhalo;
    int nparts, rank;
    MPI_Comm_size(comm, &nparts);
    MPI_Comm_rank(comm, &rank);
    if (plan_receives(h, halo_part, nparts) < 0)
        return fprintf(stderr, "error: part %d: out of memory for its halo plan\n", rank), -1;
    const int r = plan_sends(h, own_id, halo_id);
    if (r < 0) {
        fprintf(stderr, "error: part %d: %s\n", rank,
                r == -1 ? "out of memory for its halo plan"
                        : "another part asks for a particle it does not own (the parts "
                          "disagree on the decomposition)");
        return -1;
    }
    h->req = malloc((2 * (size_t)h->npeers + 1) * sizeof *h->req);
    if (!h->req)
        return fprintf(stderr, "error: part %d: out of memory for its halo\n", rank), -1;
    return 0;
}

/* Receives posted, then each peer's values packed and sent; `bytes` per particle. */
static void post_messages(sph_halo *h, size_t bytes)
{
    const int np = h->npeers;
    for (int q = 0; q < np; q++) {
        const int a = h->recv_start[q], n = h->recv_start[q + 1] - a;
        MPI_Irecv(h->rbuf + (size_t)a * bytes, (int)((size_t)n * bytes), MPI_BYTE, h->peer[q],
                  TAG_VALUES, h->comm, &h->req[q]);
    }
}

static void send_messages(sph_halo *h, size_t bytes)
{
    const int np = h->npeers;
    for (int q = 0; q < np; q++) {
        const int a = h->send_start[q], n = h->send_start[q + 1] - a;
        MPI_Isend(h->sbuf + (size_t)a * bytes, (int)((size_t)n * bytes), MPI_BYTE, h->peer[q],
                  TAG_VALUES, h->comm, &h->req[np + q]);
    }
    h->bytes = (long)((size_t)h->send_start[np] * bytes);
}

static size_t field_bytes(const sph_field *f, int nf)
{
    size_t bytes = 0;
    for (int k = 0; k < nf; k++)
        bytes += f[k].size;
    return bytes;
}

int sph_halo_post(sph_halo *h, const sph_field *f, int nf)
{
    const size_t bytes = field_bytes(f, nf);
    if (reserve(h, bytes))
        return -1;
    post_messages(h, bytes);
    const int nsend = h->send_start[h->npeers];
    for (int i = 0; i < nsend; i++) {
        unsigned char *to = h->sbuf + (size_t)i * bytes;
        for (int k = 0; k < nf; k++) {
            memcpy(to, (const unsigned char *)f[k].base + (size_t)h->send[i] * f[k].size,
                   f[k].size);
            to += f[k].size;
        }
    }
    send_messages(h, bytes);
    return 0;
}

void sph_halo_wait(sph_halo *h, const sph_field *f, int nf)
{
    const size_t bytes = field_bytes(f, nf);
    MPI_Waitall(2 * h->npeers, h->req, MPI_STATUSES_IGNORE);
    const int nrecv = h->recv_start[h->npeers];
    for (int i = 0; i < nrecv; i++) {
        const unsigned char *from = h->rbuf + (size_t)i * bytes;
        const size_t at = (size_t)h->nown + (size_t)h->recv[i];
        for (int k = 0; k < nf; k++) {
            memcpy((unsigned char *)f[k].base + at * f[k].size, from, f[k].size);
            from += f[k].size;
        }
    }
}

int sph_halo_exchange_packed(sph_halo *h, const void *out, void *in, size_t bytes)
{
    if (reserve(h, bytes))
        return -1;
    post_messages(h, bytes);
    memcpy(h->sbuf, out, (size_t)h->send_start[h->npeers] * bytes);
    send_messages(h, bytes);
    MPI_Waitall(2 * h->npeers, h->req, MPI_STATUSES_IGNORE);
    memcpy(in, h->rbuf, (size_t)h->recv_start[h->npeers] * bytes);
    return 0;
}

void sph_halo_free(sph_halo *h)
{
    free(h->peer), free(h->send_start), free(h->send), free(h->recv_start), free(h->recv);
    free(h->sbuf), free(h->rbuf), free(h->req);
    memset(h, 0, sizeof *h);
}
