/* neighbours.h — neighbour lists in the reference configuration (neighbours.c). */
#ifndef SPHRT_PAIRS_NEIGHBOURS_H
#define SPHRT_PAIRS_NEIGHBOURS_H

#include "core/defs.h"

SPH_C_BEGIN

/* Cell-list search in the reference configuration: pairs (i, j), j != i, with
 * |X_i - X_j| <= radius (1 + 1e-9) and, when range > 0, |X_i^k - X_j^k| <= (range + 0.01) dx
 * for every component k (SoliDualSPHysics' nbsrange).  Pairs at exactly r == radius are
 * included (W = 0 there): with radius = 2h, h = sqrt(dim) dx, an interior lattice particle
 * has 24 neighbours in 2D and 178 in 3D.  Output in CSR form (both directions, symmetric),
 * each list sorted by j.  *start has n+1 entries. */
void sph_neighbours(const double *X, int n, int dim, double radius, int range, double dx,
                    int **start, int **nb);
/* The O(n^2) reference used by the tests. */
void sph_neighbours_brute(const double *X, int n, int dim, double radius, int range,
                          double dx, int **start, int **nb);

SPH_C_END

#endif
