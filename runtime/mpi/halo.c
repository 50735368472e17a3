/* halo.c — the exchange plan of a part's halo and the exchange itself (halo.h). */
#include "halo.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { TAG_COUNT = 1, TAG_IDS = 2, TAG_VALUES = 3 };

/* The index of id in the ascending list ids[0..n), or -1. */
static int find_id(const int64_t *ids, int n, int64_t id)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        const int mid = lo + (hi - lo) / 2;
        if (ids[mid] == id)
            return mid;
        if (ids[mid] < id)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

/* The peers (the parts of the halo, ascending) and, per peer, the halo particles it
 * provides (in id order, as the halo is). */
static int plan_receives(sph_halo *h, const sph_rcb_local_set *s, int nparts)
{
    int *count = calloc((size_t)nparts, sizeof *count);
    if (!count)
        return -1;
    for (int i = 0; i < s->nhalo; i++)
        count[s->halo_part[i]]++;
    h->peer = malloc(((size_t)nparts + 1) * sizeof *h->peer);
    h->recv_start = malloc(((size_t)nparts + 1) * sizeof *h->recv_start);
    h->recv = malloc(((size_t)s->nhalo + 1) * sizeof *h->recv);
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
    for (int i = 0; at && i < s->nhalo; i++) {
        const int q = slot[s->halo_part[i]];
        h->recv[h->recv_start[q] + at[q]++] = i;
    }
    free(count), free(slot);
    if (!at)
        return -1;
    free(at);
    return 0;
}

/* What each peer needs of this part: the ids it asks for (counts first), as own indices. */
static int plan_sends(sph_halo *h, const sph_rcb_local_set *s)
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
        ids_out[i] = s->halo_id[h->recv[i]];
    for (int q = 0; q < np; q++) {
        MPI_Irecv(ids_in + h->send_start[q], asks[q], MPI_INT64_T, h->peer[q], TAG_IDS, h->comm,
                  &req[q]);
        MPI_Isend(ids_out + h->recv_start[q], want[q], MPI_INT64_T, h->peer[q], TAG_IDS,
                  h->comm, &req[np + q]);
    }
    MPI_Waitall(2 * np, req, MPI_STATUSES_IGNORE);
    int bad = 0;
    for (int i = 0; i < nsend; i++)
        if ((h->send[i] = find_id(s->own_id, s->nown, ids_in[i])) < 0)
            bad = 1;
    free(want), free(asks), free(req), free(ids_in), free(ids_out);
    return bad ? -2 : 0;
}

int sph_halo_plan(sph_halo *h, const sph_rcb_local_set *s, int kmax, MPI_Comm comm)
{
    memset(h, 0, sizeof *h);
    h->comm = comm;
    h->kmax = kmax;
    int nparts, rank;
    MPI_Comm_size(comm, &nparts);
    MPI_Comm_rank(comm, &rank);
    if (plan_receives(h, s, nparts) < 0)
        return fprintf(stderr, "error: part %d: out of memory for its halo plan\n", rank), -1;
    const int r = plan_sends(h, s);
    if (r < 0) {
        fprintf(stderr, "error: part %d: %s\n", rank,
                r == -1 ? "out of memory for its halo plan"
                        : "another part asks for a particle it does not own (the parts "
                          "disagree on the decomposition)");
        return -1;
    }
    const int np = h->npeers;
    h->sbuf = malloc(((size_t)h->send_start[np] * kmax + 1) * sizeof *h->sbuf);
    h->rbuf = malloc(((size_t)h->recv_start[np] * kmax + 1) * sizeof *h->rbuf);
    h->req = malloc((2 * (size_t)np + 1) * sizeof *h->req);
    if (!h->sbuf || !h->rbuf || !h->req)
        return fprintf(stderr, "error: part %d: out of memory for its halo\n", rank), -1;
    return 0;
}

void sph_halo_begin(sph_halo *h, const double *own, int k)
{
    const int np = h->npeers;
    for (int q = 0; q < np; q++) {
        const int a = h->recv_start[q], n = h->recv_start[q + 1] - a;
        MPI_Irecv(h->rbuf + (size_t)a * k, n * k, MPI_DOUBLE, h->peer[q], TAG_VALUES, h->comm,
                  &h->req[q]);
    }
    for (int q = 0; q < np; q++) {
        const int a = h->send_start[q], n = h->send_start[q + 1] - a;
        double *buf = h->sbuf + (size_t)a * k;
        for (int i = 0; i < n; i++)
            memcpy(buf + (size_t)i * k, own + (size_t)h->send[a + i] * k, (size_t)k * sizeof *own);
        MPI_Isend(buf, n * k, MPI_DOUBLE, h->peer[q], TAG_VALUES, h->comm, &h->req[np + q]);
    }
    h->bytes = (long)h->send_start[np] * k * (long)sizeof(double);
}

void sph_halo_end(sph_halo *h, double *halo, int k)
{
    const int np = h->npeers;
    MPI_Waitall(2 * np, h->req, MPI_STATUSES_IGNORE);
    for (int i = 0; i < h->recv_start[np]; i++)
        memcpy(halo + (size_t)h->recv[i] * k, h->rbuf + (size_t)i * k, (size_t)k * sizeof *halo);
}

void sph_halo_free(sph_halo *h)
{
    free(h->peer), free(h->send_start), free(h->send), free(h->recv_start), free(h->recv);
    free(h->sbuf), free(h->rbuf), free(h->req);
    memset(h, 0, sizeof *h);
}
