/* fill.h — particles on the lattice of a region: the whole body (fill.c), or the part one
 * process of a run on many processes holds (part_fill.c). */
#ifndef SPHRT_GEOM_FILL_H
#define SPHRT_GEOM_FILL_H

#include <stdint.h>

#include "region.h"
#include "core/defs.h"

SPH_C_BEGIN

/* Fill a region with particles on the lattice of spacing dx.  Lattice points are cell
 * centres: lo + (k + 1/2) dx along each axis, where lo is the region's bounding-box
 * minimum when the box spans whole cells along that axis, else the cells are centred on the
 * box; when r->has_corner, the cells have a corner at r->corner instead.  A point is kept
 * when it lies inside the region or within 1e-9 dx of it (on its surface).  In 2D only x
 * and z vary and every particle gets y = y_plane.  Returns the number of particles and sets
 * *X to a malloc'ed array of n*dim coordinates (x,z in 2D; x,y,z in 3D); 0 for an empty
 * region, -1 (with a message) when the lattice is too large or memory runs out. */
int sph_fill_region(const sph_region *r, int dim, double dx, double y_plane, double **X);

/* The same, with the particles counted first and refuse(n, ctx) asked before they are
 * allocated: a body too large for the run (set-up) is refused from its count, not after
 * filling gigabytes.  refuse returns nonzero to refuse (having said why), and the fill then
 * returns SPH_FILL_REFUSED with *X NULL; refuse NULL accepts every count.  On many processes
 * (sph_fill_part) the count asked about is the process's own particles, before its halo. */
typedef int (*sph_fill_check)(long n, void *ctx);
enum { SPH_FILL_REFUSED = -2 };
int sph_fill_region_checked(const sph_region *r, int dim, double dx, double y_plane,
                            sph_fill_check refuse, void *ctx, double **X);

/* part_fill.c: a process's particles of a body on many processes: its own (nown, first)
 * and its halo (n - nown after them, with the process each belongs to), positions X (dim
 * values each) and global ids.  0 (out->n = 0 when the region has no lattice), -1 when
 * the lattice is too large or memory runs out, SPH_FILL_REFUSED when refuse (as above; NULL:
 * none) refused the count of its own particles. */
typedef struct {
    int n, nown;
    double *X;
    int64_t *gid;
    int *halo_part;
} sph_part_fill;
int sph_fill_part(const sph_region *r, int dim, double dx, double y_plane, double radius,
                  int range, int part, int nparts, sph_fill_check refuse, void *ctx,
                  sph_part_fill *out);

SPH_C_END

#endif
