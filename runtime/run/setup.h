/* setup.h — building a body (setup.c): particles, neighbours, gradients, selections and
 * arrays. */
#ifndef SPHRT_RUN_SETUP_H
#define SPHRT_RUN_SETUP_H

#include "core/defs.h"
#include "par/par.h"
#include "scene/body.h"
#include "scene/model.h"

SPH_C_BEGIN

/* Particles, neighbours, gradients, selections and arrays of one body, on the
 * processes par (collective); t_end, the run's end time, for the warnings of boundary
 * conditions that would never act. */
int sph_body_setup(sph_body *b, const sph_body_desc *d, const sph_model *m, double t_end,
                   const sph_par *par);
void sph_body_free(sph_body *b);

/* The program's --whole-law: the CPU's stress pass takes no law's fast path (setup.c;
 * templates/body_forces.c, RARE). */
extern int sph_fast_law_off;

SPH_C_END

#endif
