/* stencil.h — the lattice stencil of a body's pair passes (sph_body's st_*; stencil.c). */
#ifndef SPHRT_PAIRS_STENCIL_H
#define SPHRT_PAIRS_STENCIL_H

#include "core/defs.h"
#include "scene/body.h"

SPH_C_BEGIN

/* stencil.c: the body's lattice stencil and its runs (st_* above), from its half lists;
 * nothing with sph_stencil_off (the program's --no-stencil). */
extern int sph_stencil_off;
void sph_stencil_setup(sph_body *b);

SPH_C_END

#endif
