/* emit_fracture.h — the generated code only bodies with phase-field fracture get
 * (emit_fracture.c). */
#ifndef SPHC_EMIT_FRACTURE_H
#define SPHC_EMIT_FRACTURE_H

#include <stdio.h>

#include "emit_internal.h"

/* The rest of the material function after its opening comment line (cuda: for the CUDA
 * target, emit_law.h). */
void emit_fracture_material(FILE *out, const BodyModel *b, const BodyPlan *p, int cuda);
/* B_phase_min and B_restrict(b, t, dt), when the body restricts its phase field. */
void emit_fracture_restrict(Emitter *E, const BodyModel *b);
/* B_notches and B_fracture for the body description. */
void emit_fracture_desc(FILE *out, const BodyModel *b);

#endif
