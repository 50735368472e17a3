/* offset_blocks.h — the offset blocks of a 3D body's pair passes (sph_body's ob_* and mb_*;
 * offset_blocks.c). */
#ifndef SPHRT_PAIRS_OFFSET_BLOCKS_H
#define SPHRT_PAIRS_OFFSET_BLOCKS_H

#include "core/defs.h"
#include "scene/body.h"

SPH_C_BEGIN

/* offset_blocks.c: the body's offset blocks (ob_* above), from its full lists (the set-up,
 * before the half lists), and the momentum pass's (mb_*), from its half lists and stripes;
 * nothing with sph_stencil_off, in 2D, or where its desc's offset_blocks leaves them out. */
void sph_offset_blocks_setup(sph_body *b);
void sph_momentum_blocks_setup(sph_body *b);

SPH_C_END

#endif
