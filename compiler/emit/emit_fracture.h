/* emit_fracture.h — generated code for bodies with phase-field fracture (emit_fracture.c). */
#ifndef SPHC_EMIT_FRACTURE_H
#define SPHC_EMIT_FRACTURE_H

#include <stdio.h>

#include "check/model.h"
#include "lower/plan.h"

/* The rest of the material function after its opening comment line. */
void emit_fracture_material(FILE *out, const BodyModel *b, const BodyPlan *p);
/* B_phase_min and B_restrict(b, t, dt), when the body restricts its phase field. */
void emit_fracture_restrict(FILE *out, const Model *m, const BodyModel *b, int cuda);
/* B_notches and B_fracture for the body description. */
void emit_fracture_desc(FILE *out, const BodyModel *b);

#endif
