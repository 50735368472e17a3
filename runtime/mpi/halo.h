/* halo.h — the exchange of a part's halo between processes (MPI), for runs on many processes
 * (docs/mpi.md).
 *
 * A part (runtime/partition.h, sph_rcb_local) holds its own particles and its halo, the
 * particles of other parts within the kernel support of its own, each list in id order.
 * Neighbours in the reference configuration never change, so the plan of what to send
 * where is made once: every process tells each part it takes halo particles from which ids
 * it needs (the neighbour relation is symmetric: the parts a process takes from are those
 * that take from it), and each maps the ids it is asked for to its own particles.  At every
 * step the values of the own particles (k doubles each) go to the parts that need them and
 * the halo's come in, with non-blocking messages: sph_halo_begin posts them, work on the
 * particles that need no halo can go on, sph_halo_end waits and puts the halo's in place. */
#ifndef SPH_MPI_HALO_H
#define SPH_MPI_HALO_H

#include <mpi.h>
#include <stdint.h>

#include "partition.h"

typedef struct {
    MPI_Comm comm;
    int npeers;              /* the parts this one exchanges with, */
    int *peer;               /* their ranks (= part numbers), ascending */
    int *send_start, *send;  /* own particles each peer needs: send[send_start[q] ..] */
    int *recv_start, *recv;  /* halo particles each peer provides: recv[recv_start[q] ..] */
    double *sbuf, *rbuf;     /* packed values, k per particle (sized for kmax) */
    int kmax;
    MPI_Request *req;        /* 2 npeers */
    long bytes;              /* sent by the last exchange */
} sph_halo;

/* The plan of part `rank` of comm (whose size is the number of parts) for the local set s,
 * for up to kmax values per particle.  Collective over the peers; 0, or -1 after an error
 * message (an id asked for that this part does not own: the parts disagree). */
int sph_halo_plan(sph_halo *h, const sph_rcb_local_set *s, int kmax, MPI_Comm comm);
/* Posts the exchange of k values per particle (k <= kmax): own[] holds s->nown * k values. */
void sph_halo_begin(sph_halo *h, const double *own, int k);
/* Waits for it and writes the halo's values into halo[] (s->nhalo * k values). */
void sph_halo_end(sph_halo *h, double *halo, int k);
void sph_halo_free(sph_halo *h);

#endif
