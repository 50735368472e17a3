/* partition_report.c — `--partition N`: how each body of the model would be decomposed for a
 * run on N processes (partition.h, docs/mpi.md), without running it: particles per part and
 * their balance, the halo (particles of other parts within the kernel support) per part and
 * as a fraction of the own particles, and the time the decomposition took.  The body is
 * filled whole here (a report is made on one machine); the tree is the one each process of
 * a run computes alone by counting lattice points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "partition_report.h"
#include "core/clock.h"
#include "core/message.h"
#include "geom/fill.h"
#include "geom/partition.h"
#include "scene/body_desc.h"
#include "scene/model.h"

/* One body's report; 0, or -1 after a message. */
static int body_report(const sph_model *m, const sph_body_desc *d, int nparts)
{
    const double dx = m->dp / d->refine, radius = 2.0 * m->coefh * sqrt((double)m->dim) * dx;
    sph_lattice L;
    if (sph_fill_lattice(&d->region, m->dim, dx, d->y_plane, &L) != 1) {
        sph_error("--partition: body '%s' has no lattice to decompose", d->name);
        return -1;
    }
    const double t0 = sph_wall_time();
    sph_rcb T;
    if (sph_rcb_count(&d->region, &L, nparts, -1, 0, &T) < 0) {
        sph_error("--partition: body '%s': out of memory for %d parts", d->name, nparts);
        return -1;
    }
    const double t_tree = sph_wall_time() - t0;
    double *X = NULL;
    const int n = sph_fill_region(&d->region, m->dim, dx, d->y_plane, &X);
    int *part = malloc(((size_t)n + 1) * sizeof *part);
    long *halo = calloc((size_t)nparts, sizeof *halo), *own = calloc((size_t)nparts, sizeof *own);
    int bad = !part || !halo || !own;
    for (int i = 0; !bad && i < n; i++) {
        long k[3];
        sph_lattice_coords(&L, X + (size_t)i * m->dim, k);
        part[i] = sph_rcb_owner(&T, &L, k);
        own[part[i]]++;
    }
    if (!bad)
        bad = sph_rcb_halo_sizes(&L, X, n, part, nparts, radius, d->nbsrange, halo) < 0;
    if (bad) {
        sph_error("--partition: body '%s': out of memory", d->name);
    } else {
        long omin = n, omax = 0, hmax = 0, hsum = 0, empty = 0;
        for (int p = 0; p < nparts; p++) {
            omin = own[p] < omin ? own[p] : omin;
            omax = own[p] > omax ? own[p] : omax;
            hmax = halo[p] > hmax ? halo[p] : hmax;
            hsum += halo[p];
            empty += own[p] == 0;
        }
        const double mean = (double)n / nparts;
        printf("%s: body %s: %d particles in %d parts: %ld to %ld a part (mean %.1f, balance "
               "%.2f %%), halo %.1f a part (most %ld), halo / own %.1f %%; tree in %.3f s\n",
               m->name, d->name, n, nparts, omin, omax, mean, 100 * (omax - mean) / mean,
               (double)hsum / nparts, hmax, n ? 100.0 * (double)hsum / n : 0.0, t_tree);
        if (empty)
            printf("%s: body %s: %ld of the %d parts hold no particle (more parts than the "
                   "body has particles to share)\n", m->name, d->name, empty, nparts);
    }
    free(X), free(part), free(halo), free(own);
    sph_rcb_free(&T);
    return bad ? -1 : 0;
}

int sph_partition_report(const sph_model *m, int nparts)
{
    for (int i = 0; i < m->nbodies; i++)
        if (body_report(m, &m->bodies[i], nparts))
            return -1;
    return 0;
}
