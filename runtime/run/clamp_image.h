/* clamp_image.h — what a clamp by mirror images does to its image k (run/clamp.c), written
 * once for the CPU's loops over the images (clamp.c) and the device's threads, one an image
 * (templates/body_cuda.cu).  Q's entries by SPH_TENSOR as the target that includes this lays
 * them out (scene/pass_types.h, cuda/target.h). */
#ifndef SPHRT_RUN_CLAMP_IMAGE_H
#define SPHRT_RUN_CLAMP_IMAGE_H

#include "core/defs.h"
#include "pairs/quadratic.h"
#include "scene/body.h"
#include "scene/pass_types.h"

SPH_C_BEGIN

/* Before the pair passes: the image's displacement and velocity, minus its particle's (the
 * odd extension of the field across the plane). */
SPH_HD static inline void sph_clamp_image_move(sph_body *b, int k)
{
    const int D = b->dim;
    const size_t g = (size_t)b->image[k] * D, q = (size_t)b->image_of[k] * D;
    for (int c = 0; c < D; c++) {
        b->u[g + c] = -b->u[q + c];
        b->v[g + c] = -b->v[q + c];
    }
}

/* After the stress pass: the image carries no stress and no strain energy. */
SPH_HD static inline void sph_clamp_image_quiet(sph_body *b, int k)
{
    const int D = b->dim, g = b->image[k];
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++)
            b->Q[SPH_TENSOR(g, r, c, D, b->n)] = 0;
    if (b->Qq) /* (the quadratic gradient's share of the stress) */
        for (int m = 0; m < SPH_QN(D) * SPH_ROW(D); m++)
            b->Qq[(size_t)g * SPH_QN(D) * SPH_ROW(D) + m] = 0;
    b->psi[g] = 0;
}

/* After the momentum pass: the image's force (its acceleration less g, which may be NULL)
 * acts on its particle with the opposite sign (the image's displacement is minus the
 * particle's), and the image's acceleration is zero.  A particle has one image at most. */
SPH_HD static inline void sph_clamp_image_reaction(sph_body *b, int k, const double *g)
{
    const int D = b->dim;
    const size_t im = (size_t)b->image[k] * D, q = (size_t)b->image_of[k] * D;
    for (int c = 0; c < D; c++) {
        b->a[q + c] -= b->a[im + c] - (g ? g[c] : 0.0);
        b->a[im + c] = 0;
    }
}

SPH_C_END

#endif
