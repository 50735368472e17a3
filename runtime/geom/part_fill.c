/* part_fill.c — the particles one process of a run on many processes holds of a body: its
 * own part of the body's decomposition and its halo (docs/mpi.md), filled by this process
 * alone from the body's region and lattice, never the whole body. */
#include <stdlib.h>
#include <string.h>

#include "fill.h"
#include "partition.h"
#include "region.h"

/* The points of part `part`: its leaf's count (-1 when the leaf was not computed). */
static long leaf_count(const sph_rcb *T, int part)
{
    for (int k = 0; k < T->nnodes; k++) {
        const sph_rcb_node *nd = &T->node[k];
        if (nd->nparts == 1 && nd->first == part)
            return nd->done ? nd->count : -1;
    }
    return -1;
}

int sph_fill_part(const sph_region *r, int dim, double dx, double y_plane, double radius,
                  int range, int part, int nparts, sph_fill_check refuse, void *ctx,
                  sph_part_fill *out)
{
    memset(out, 0, sizeof *out);
    sph_lattice L;
    const int lat = sph_fill_lattice(r, dim, dx, y_plane, &L);
    if (lat < 0)
        return -1;
    if (lat == 0)
        return 0; /* no lattice: no particle (the caller reports an empty body) */
    sph_rcb T;
    if (sph_rcb_count(r, &L, nparts, part, sph_lattice_margin(&L, radius, range), &T) < 0)
        return -1;
    const long own = leaf_count(&T, part);
    if (own > 0 && refuse && refuse(own, ctx)) { /* (counted, nothing filled) */
        sph_rcb_free(&T);
        return SPH_FILL_REFUSED;
    }
    sph_rcb_local_set s;
    const int bad = sph_rcb_local(r, &L, &T, part, radius, range, &s);
    sph_rcb_free(&T);
    if (bad)
        return -1;
    const size_t n = (size_t)s.nown + (size_t)s.nhalo, D = (size_t)dim;
    out->X = malloc((n + 1) * D * sizeof *out->X);
    out->gid = malloc((n + 1) * sizeof *out->gid);
    out->halo_part = malloc(((size_t)s.nhalo + 1) * sizeof *out->halo_part);
    if (!out->X || !out->gid || !out->halo_part) {
        sph_rcb_local_free(&s);
        free(out->X), free(out->gid), free(out->halo_part);
        return -1;
    }
    /* own particles first, then the halo (each in id order, as sph_rcb_local gives them) */
    memcpy(out->X, s.own_X, (size_t)s.nown * D * sizeof *out->X);
    memcpy(out->X + (size_t)s.nown * D, s.halo_X, (size_t)s.nhalo * D * sizeof *out->X);
    memcpy(out->gid, s.own_id, (size_t)s.nown * sizeof *out->gid);
    memcpy(out->gid + s.nown, s.halo_id, (size_t)s.nhalo * sizeof *out->gid);
    memcpy(out->halo_part, s.halo_part, (size_t)s.nhalo * sizeof *out->halo_part);
    out->nown = s.nown;
    out->n = (int)n;
    sph_rcb_local_free(&s);
    return 0;
}
