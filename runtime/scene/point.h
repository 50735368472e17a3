/* point.h — the variables of user expressions (paper Table 1) at one particle (sph_pt),
 * which generated boundary conditions, fracture bounds and functions read. */
#ifndef SPHRT_SCENE_POINT_H
#define SPHRT_SCENE_POINT_H

#include "body.h"
#include "core/defs.h"

SPH_C_BEGIN

typedef struct sph_pt {
    double x0, y0, z0, x, y, z, ux, uy, uz, t, dt, dx;
} sph_pt;

SPH_HD static inline void sph_point(const sph_body *b, int i, int dim, double t, double dt, sph_pt *p)
{
    double X[3] = {0, b->y_plane, 0}, U[3] = {0, 0, 0};
    for (int k = 0; k < dim; k++) {
        X[sph_axis(dim, k)] = b->X[(size_t)i * dim + k];
        U[sph_axis(dim, k)] = b->u[(size_t)i * dim + k];
    }
    p->x0 = X[0], p->y0 = X[1], p->z0 = X[2];
    p->ux = U[0], p->uy = U[1], p->uz = U[2];
    p->x = X[0] + U[0], p->y = X[1] + U[1], p->z = X[2] + U[2];
    p->t = t, p->dt = dt, p->dx = b->dx;
}

SPH_C_END

#endif
