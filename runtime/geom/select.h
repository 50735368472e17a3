/* select.h — choosing particles by geometry in the reference configuration. */
#ifndef SPHRT_SELECT_H
#define SPHRT_SELECT_H

#include "region.h"

/* Particles (of X, n×dim) whose distance to region r is <= dx (the BC's `near`).
 * Returns the count; *idx is malloc'ed (may be NULL when the count is 0). */
int sph_select_near(const double *X, int n, int dim, double y_plane, double dx,
                    const sph_region *r, int **idx);

/* Particles cut by a measurement plane (quad p[4]): distance to the quad's plane <= dx/2
 * (plus 1e-9 dx) and projection inside the quad grown by dx/2.  In 2D the quad is
 * projected onto the x–z plane (y ignored): it becomes a segment, and particles within
 * dx/2 of the segment are kept. */
int sph_select_plane(const double *X, int n, int dim, double dx, const double p[4][3],
                     int **idx);

#endif
