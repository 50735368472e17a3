/* clamp.h — a body clamped on a plane by the mirror images of its particles (clamp.c). */
#ifndef SPHRT_RUN_CLAMP_H
#define SPHRT_RUN_CLAMP_H

#include "core/defs.h"
#include "scene/body.h"

SPH_C_BEGIN

/* The body's images (desc->clamp): every particle behind the plane is paired with the
 * particle at its mirror image in front (b->image, b->image_of, b->nimages).  -1 with an
 * error naming the first particle without one (the plane must lie on the faces of the
 * lattice's cells), 0 otherwise. */
int sph_clamp_setup(sph_body *b);
/* Before the pair passes: each image's displacement and velocity, minus its particle's. */
void sph_clamp_images(sph_body *b);
/* After the stress pass: the images carry no stress and no strain energy. */
void sph_clamp_quiet(sph_body *b);
/* After the momentum pass: each image's force (its acceleration less g, which may be NULL)
 * moved to its particle with the opposite sign, the image's acceleration zero. */
void sph_clamp_reactions(sph_body *b, const double *g);

SPH_C_END

#endif
