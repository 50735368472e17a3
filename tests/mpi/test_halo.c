/* The halo exchange of runs on many processes (runtime/mpi/halo.h), run on 1 to 4 processes:
 * each process fills its part of a body (runtime/geom/partition.h: by counting, not the whole
 * body) and its halo, makes the exchange plan, and exchanges values computed from the
 * particles' positions, held as a body holds them (own particles first, then the halo: the
 * fields of sph_halo_post/wait).  Checked on every process:
 *  - every halo value arrives, equal to the value its owner computed (bit for bit: the same
 *    function of the same position, which every process computes alike from the lattice);
 *  - the parts hold every particle of the body once (their counts add up to the body's);
 *  - what the parts send adds up to what they receive, and the plan serves a second
 *    exchange of another width. */
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

#include "geom/partition.h"
#include "geom/region.h"
#include "mpi/halo.h"
#include "par/par.h"

static double value(const double *x, int dim, int c)
{
    return sin(1e3 * x[0] + c) + (c + 1) * cos(2e3 * x[dim - 1]) + (dim == 3 ? 1e3 * x[1] : 0);
}

/* One body on this process's part: the number of failed checks. */
static int body(const char *name, const sph_region *r, int dim, double dx, int rank, int size)
{
    sph_lattice L;
    if (sph_fill_lattice(r, dim, dx, 0.0, &L) != 1)
        return 1;
    const double radius = 2.0 * sqrt((double)dim) * dx; /* coefh 1: 2h, h = sqrt(dim) dx */
    sph_rcb T;
    sph_rcb_local_set s;
    if (sph_rcb_count(r, &L, size, rank, sph_lattice_margin(&L, radius, 0), &T) < 0 ||
        sph_rcb_local(r, &L, &T, rank, radius, 0, &s) < 0)
        return 1;
    sph_halo h;
    int bad = sph_halo_plan_ids(&h, s.nown, s.own_id, s.nhalo, s.halo_id, s.halo_part,
                                MPI_COMM_WORLD) != 0;
    long mismatched = 0;
    for (int k = 3; k >= 1 && !bad; k -= 2) { /* 3 values per particle, then 1 */
        double *val = malloc(((size_t)(s.nown + s.nhalo) * k + 1) * sizeof *val);
        double *halo = val + (size_t)s.nown * k;
        for (int i = 0; i < s.nown; i++)
            for (int c = 0; c < k; c++)
                val[(size_t)i * k + c] = value(s.own_X + (size_t)i * dim, dim, c);
        for (int i = 0; i < s.nhalo * k; i++)
            halo[i] = NAN;
        const sph_field f = SPH_FIELD(val, k);
        if ((bad = sph_halo_post(&h, &f, 1) != 0))
            break; /* (the value array leaks with the failure: the test fails anyway) */
        sph_halo_wait(&h, &f, 1);
        for (int i = 0; i < s.nhalo; i++)
            for (int c = 0; c < k; c++)
                mismatched += halo[(size_t)i * k + c] != value(s.halo_X + (size_t)i * dim, dim, c);
        free(val);
    }
    long sent = bad ? 0 : h.send_start[h.npeers], got = bad ? 0 : h.recv_start[h.npeers];
    long counts[3] = {s.nown, sent, got}, totals[3];
    MPI_Allreduce(counts, totals, 3, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    const long lo[3] = {0, 0, 0}, hi[3] = {L.nk[0] - 1, L.nk[1] - 1, L.nk[2] - 1};
    const long whole = sph_lattice_count(r, &L, lo, hi);
    int fails = bad + (mismatched != 0) + (totals[0] != whole) + (totals[1] != totals[2]);
    int worst;
    MPI_Allreduce(&fails, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (rank == 0 || fails)
        printf("%-4s %s on %d processes, part %d: %d own, %d halo from %d parts, %ld values "
               "wrong; all parts: %ld particles of %ld, %ld sent, %ld received\n",
               fails ? "FAIL" : "ok", name, size, rank, s.nown, s.nhalo, bad ? 0 : h.npeers,
               mismatched, totals[0], whole, totals[1], totals[2]);
    if (!bad)
        sph_halo_free(&h);
    sph_rcb_local_free(&s);
    sph_rcb_free(&T);
    return worst != 0;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    /* a 2D plate with a hole off its centre, and a 3D block minus a corner */
    const sph_shape plate[2] = {
        {SPH_BOX, {0, 0, 0}, {40e-3, 0, 20e-3}, 0, 0, NULL, NULL, 0},
        {SPH_BOX, {12e-3, -1, 5e-3}, {19e-3, 1, 12e-3}, 0, 1, NULL, NULL, 0},
    };
    const sph_shape block[2] = {
        {SPH_BOX, {0, 0, 0}, {12e-3, 9e-3, 8e-3}, 0, 0, NULL, NULL, 0},
        {SPH_BOX, {6e-3, 5e-3, -1}, {13e-3, 10e-3, 1}, 0, 1, NULL, NULL, 0},
    };
    const sph_region r2 = {.prims = plate, .n = 2}, r3 = {.prims = block, .n = 2};
    int failed = body("2D plate with a hole", &r2, 2, 0.5e-3, rank, size);
    failed += body("3D block less a corner", &r3, 3, 1e-3, rank, size);
    MPI_Finalize();
    return failed != 0;
}
