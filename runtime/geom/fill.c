/* fill.c — filling a region with particles on a cubic lattice.
 *
 * Lattice: cell centres lo + (k + 1/2) dx along every varying axis.  Along an axis where the
 * bounding box of the region's non-subtracted primitives (see region.c) spans a whole
 * number of cells, lo is its minimum, so the cells fill it exactly (a box holds its volume);
 * otherwise the cells are centred on it, with equal margins on both sides (round shapes
 * keep their volume best so).  A region with a lattice corner (has_corner) has its cells
 * aligned to r->corner instead: lo is corner + j dx (j integer) a cell below the minimum.
 * A lattice point is kept when the region contains it (inclusive), points within 1e-9 dx of
 * its surface included (a lattice node on a face counts as inside however the coordinates
 * round).  In 2D only x and z vary, y is y_plane, and the region is tested in its x-z
 * version (region.c: box y extent ignored,
 * sphere -> disc, cylinder -> rectangle, or disc when its axis is along y).
 *
 * Ordering (cache-friendly, deterministic): the lattice is cut into square/cubic tiles of
 * TILE points per axis (16 in 2D, 8 in 3D); tiles are visited with x fastest, then y, then
 * z, and inside a tile points are again ordered x fastest, then y, then z.  So particles that
 * are close in space are mostly close in memory, and a box narrower than one tile along x is
 * simply "x fastest".
 *
 * Both passes (count per tile, then write) run in parallel over tiles with OpenMP; between
 * them the caller may refuse the count (sph_fill_region_checked), before anything the size of
 * the particles is allocated.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fill.h"
#include "partition.h"
#include "region.h"
#include "core/defs.h"
#include "core/limits.h"
#include "core/message.h"

/* The lattice: box minimum, spacing, points and tiles per compact component. */
typedef struct {
    int dim, tile;
    double lo[3], dx, y_plane;
    long nk[3], nt[3], ntiles, tile_pts;
} lattice;

/* The most lattice points a body's bounding box may hold (particle indices are ints):
 * SPH_MAX_LATTICE_POINTS, core/limits.h. */

/* Sets up the lattice of region r; returns 0 when it is empty or invalid, -1 when it holds
 * more than SPH_MAX_LATTICE_POINTS points (about *total). */
static int lattice_init(lattice *L, const sph_region *r, int dim, double dx, double y_plane,
                        double *total)
{
    double lo[3], hi[3];
    *total = 1.0;
    if (dx <= 0.0 || (dim != 2 && dim != 3) || !sph_region_bbox_dim(r, dim, lo, hi))
        return 0;
    for (int c = 0; c < dim; c++) { /* before the counts below become longs */
        const double ext = (hi[sph_axis(dim, c)] - lo[sph_axis(dim, c)]) / dx;
        if (!(ext >= 0.0))
            return 0;
        *total *= fmax(ext, 1.0);
    }
    if (!(*total < SPH_MAX_LATTICE_POINTS))
        return -1;
    L->dim = dim;
    L->dx = dx;
    L->y_plane = y_plane;
    L->tile = dim == 2 ? 16 : 8;
    L->ntiles = 1;
    L->tile_pts = 1;
    for (int c = 0; c < 3; c++) {
        int ax = sph_axis(dim, c);
        double ext = c < dim ? (hi[ax] - lo[ax]) / dx : 0.0;
        L->lo[c] = c < dim ? lo[ax] : 0.0;
        L->nk[c] = 1;
        if (c >= dim)
            continue;
        if (r->has_corner) { /* one cell more on each side: contains() decides */
            double j = floor((lo[ax] - r->corner[ax]) / dx) - 1.0;
            if (!(fabs(j) < 1e12))
                return 0;
            L->lo[c] = r->corner[ax] + j * dx;
            L->nk[c] = (long)floor((hi[ax] - L->lo[c]) / dx) + 2;
        } else if (fabs(ext - nearbyint(ext)) <= 1e-9 * fmax(1.0, ext)) {
            L->nk[c] = (long)nearbyint(ext); /* whole cells: their faces on the bounding box */
        } else { /* cells centred on the bounding box, with equal margins on both sides */
            L->nk[c] = (long)ceil(ext);
            L->lo[c] = 0.5 * (lo[ax] + hi[ax]) - 0.5 * (double)L->nk[c] * dx;
        }
        if (L->nk[c] < 1)
            L->nk[c] = 1;
    }
    *total = 1.0;
    for (int c = 0; c < 3; c++) {
        L->nt[c] = c < dim ? (L->nk[c] + L->tile - 1) / L->tile : 1;
        L->ntiles *= L->nt[c];
        L->tile_pts *= c < dim ? L->tile : 1;
        *total *= (double)L->nk[c];
    }
    return *total < SPH_MAX_LATTICE_POINTS ? 1 : -1;
}

/* The lattice sph_fill_region uses (partition.h): the same lattice_init, its numbers copied
 * out.  1 for a lattice (which may still hold none of the region's points), 0 when the
 * region has no bounding box or dx is invalid, -1 when the lattice is too large. */
int sph_fill_lattice(const sph_region *r, int dim, double dx, double y_plane, sph_lattice *out)
{
    lattice L;
    double total;
    const int ok = lattice_init(&L, r, dim, dx, y_plane, &total);
    if (ok <= 0)
        return ok;
    out->dim = dim;
    out->dx = dx;
    out->y_plane = y_plane;
    for (int c = 0; c < 3; c++) {
        out->lo[c] = L.lo[c];
        out->nk[c] = L.nk[c];
    }
    return 1;
}

/* Lattice point number l of tile t: sets p (3D coordinates); 0 when outside the lattice. */
static int lattice_point(const lattice *L, long t, long l, double p[3])
{
    p[1] = L->y_plane;
    for (int c = 0; c < L->dim; c++) {
        long k = (t % L->nt[c]) * L->tile + l % L->tile;
        t /= L->nt[c];
        l /= L->tile;
        if (k >= L->nk[c])
            return 0;
        p[sph_axis(L->dim, c)] = L->lo[c] + ((double)k + 0.5) * L->dx;
    }
    return 1;
}

/* Visits tile t: counts its points in the region and, when X is given, writes them. */
static long tile_fill(const lattice *L, const sph_region *r, long t, double *X)
{
    long m = 0;
    double p[3];
    for (long l = 0; l < L->tile_pts; l++) {
        if (!lattice_point(L, t, l, p) ||
            !sph_region_contains_tol_dim(r, L->dim, p, 1e-9 * L->dx))
            continue;
        if (X)
            for (int c = 0; c < L->dim; c++)
                X[m * L->dim + c] = p[sph_axis(L->dim, c)];
        m++;
    }
    return m;
}

int sph_fill_region(const sph_region *r, int dim, double dx, double y_plane, double **X)
{
    return sph_fill_region_checked(r, dim, dx, y_plane, NULL, NULL, X);
}

int sph_fill_region_checked(const sph_region *r, int dim, double dx, double y_plane,
                            sph_fill_check refuse, void *ctx, double **X)
{
    lattice L;
    double total;
    *X = NULL;
    const int ok = lattice_init(&L, r, dim, dx, y_plane, &total);
    if (ok < 0) {
        sph_error("at spacing dx = %g the region's bounding box holds some "
                  "%.3g lattice points, more than %.0e: raise dp or lower refine",
                  dx, total, SPH_MAX_LATTICE_POINTS);
        return -1;
    }
    if (!ok)
        return 0;
    long *first = malloc((size_t)(L.ntiles + 1) * sizeof *first);
    if (!first) {
        sph_error("out of memory for %ld lattice tiles", L.ntiles);
        return -1;
    }
    first[0] = 0;
#pragma omp parallel for schedule(dynamic, 16)
    for (long t = 0; t < L.ntiles; t++)
        first[t + 1] = tile_fill(&L, r, t, NULL);
    for (long t = 0; t < L.ntiles; t++)
        first[t + 1] += first[t];
    long n = first[L.ntiles];
    if (n > 0 && refuse && refuse(n, ctx)) { /* (counted, nothing allocated: refused) */
        free(first);
        return SPH_FILL_REFUSED;
    }
    if (n > 0 && n <= 0x7fffffffL && (*X = malloc((size_t)n * dim * sizeof **X))) {
#pragma omp parallel for schedule(dynamic, 16)
        for (long t = 0; t < L.ntiles; t++)
            tile_fill(&L, r, t, *X + first[t] * dim);
    } else if (n > 0) {
        sph_error("cannot allocate %ld particles", n);
        n = -1;
    }
    free(first);
    return (int)n;
}
