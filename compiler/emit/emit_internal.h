/* emit_internal.h — the pieces of the generated program that the CPU emitter (emit_c.c) and
 * the CUDA emitter (emit_cuda.c) share: constants, functions and laws (SPH_FN), templates,
 * boundary-condition passes, the parts of a body's step and the scene description. */
#ifndef SPHC_EMIT_INTERNAL_H
#define SPHC_EMIT_INTERNAL_H

#include <stdio.h>

#include "check/model.h"
#include "lower/plan.h"

typedef struct {
    const Model *m;
    const BodyPlan *plans;
    const char *templates;
    FILE *out;
    int cuda;           /* the CUDA target (model.cu): device passes, SPH_FOR loops */
} Emitter;

void emit_header(Emitter *E);
/* s as a C string literal (quotes, backslashes and control characters escaped). */
void emit_c_string(FILE *out, const char *s);
/* "file.sph:LINE" of loc as a C string literal: where a model item is, for the runtime's
 * messages. */
void emit_where(FILE *out, SrcLoc loc);
void emit_consts_fns(Emitter *E);
void emit_material(Emitter *E, const BodyModel *b, const BodyPlan *p);
/* templates/FILE filled for body b (its features and numbers). */
void emit_template(Emitter *E, const char *file, const BodyModel *b, const BodyPlan *p);
void emit_bc_values(Emitter *E, const BodyModel *b);
/* The velocity or force boundary-condition pass of body b (loops as SPH_FOR for CUDA). */
void emit_bc_pass(Emitter *E, const BodyModel *b, BcKind kind);
/* Body b's BC value functions and the passes its plan needs. */
void emit_bc_passes(Emitter *E, const BodyModel *b, const BodyPlan *p);
/* Body i's part of the step up to its internal forces, and from its force BCs to the end. */
void emit_step_forces(Emitter *E, int i);
void emit_step_update(Emitter *E, int i);
/* Every body's passes of one step, body i named by the printf format `body` ("%d": i); with
 * contact, every body's forces, then the call `contact`, then every body's update. */
void emit_step_bodies(Emitter *E, const char *body, const char *contact);
/* The static scene description and main(). */
void emit_model_desc(Emitter *E);

#endif
