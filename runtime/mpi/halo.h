/* halo.h — the exchange of a part's halo between processes (MPI), for runs on many processes
 * (docs/mpi.md).
 *
 * A part (geom/partition.h, sph_rcb_local) holds its own particles and its halo, the
 * particles of other parts within the kernel support of its own.  Neighbours in the
 * reference configuration never change, so the plan of what to send where is made once:
 * every process tells each part it takes halo particles from which ids it needs (the
 * neighbour relation is symmetric: the parts a process takes from are those that take from
 * it), and each maps the ids it is asked for to its own particles.  At every step the values
 * of the own particles go to the parts that need them and the halo's come in, with
 * non-blocking messages: a post starts the exchange, work on the particles that need no halo
 * can go on, a wait ends it and puts the halo's values in place.
 *
 * The values are fields of arrays that hold the own particles first and the halo after them
 * (a body's: sph_field of par/par.h), or packed by the caller (a device target's). */
#ifndef SPH_MPI_HALO_H
#define SPH_MPI_HALO_H

#include <mpi.h>
#include <stdint.h>

#include "par/par.h"

typedef struct {
    MPI_Comm comm;
    int nown, nhalo;
    int npeers;              /* the parts this one exchanges with, */
    int *peer;               /* their ranks (= part numbers), ascending */
    int *send_start, *send;  /* own particles each peer needs: send[send_start[q] ..] */
    int *recv_start, *recv;  /* halo particles each peer provides: recv[recv_start[q] ..],
                                as indices into the halo (0 .. nhalo - 1) */
    unsigned char *sbuf, *rbuf; /* packed values */
    size_t cap;              /* bytes per particle the buffers hold */
    MPI_Request *req;        /* 2 npeers */
    long bytes;              /* sent by the last exchange */
} sph_halo;

/* The plan of process `rank` of comm (whose size is the number of parts) for nown own
 * particles of ids own_id (any order) and nhalo halo particles of ids halo_id, held by the
 * parts halo_part.  Collective over the peers; 0, or -1 after an error message (an id asked
 * for that this part does not own: the parts disagree; or memory ran out). */
int sph_halo_plan_ids(sph_halo *h, int nown, const int64_t *own_id, int nhalo,
                      const int64_t *halo_id, const int *halo_part, MPI_Comm comm);

/* Posts the exchange of nf fields; own particle i at f->base + i size, halo particle k at
 * f->base + (nown + k) size.  0, or -1 when memory for the buffers runs out. */
int sph_halo_post(sph_halo *h, const sph_field *f, int nf);
/* Waits for it and writes the halo's values of the same fields. */
void sph_halo_wait(sph_halo *h, const sph_field *f, int nf);

/* The exchange of values packed by the caller, `bytes` per particle: out[] in the order of
 * the send list (send[0 .. send_start[npeers]]), in[] gets one per halo value in the order of
 * the receive list (recv[...]).  Blocking; 0, or -1 when memory runs out. */
int sph_halo_exchange_packed(sph_halo *h, const void *out, void *in, size_t bytes);

void sph_halo_free(sph_halo *h);

#endif
