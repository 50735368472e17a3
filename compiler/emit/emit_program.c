/* emit_program.c — the generated program, in the same order for every target:
 *
 *   header (includes) · constants and user functions · per body the pieces its target lists
 *   (material law, templates, boundary conditions, ...) · the scene's step and glue · the
 *   scene description and main()
 *
 * What differs between the targets comes from their tables (emit_target.c). */
#include <stdio.h>

#include "emit.h"
#include "emit_fracture.h"
#include "emit_internal.h"
#include "util/diag.h"

/* A table with a member unset is the emitter's own bug: say so rather than write a program
 * without that part. */
static int target_complete(const EmitTarget *t)
{
    const char *missing = !t->name ? "name" : !t->suffix ? "suffix" : !t->header ? "header"
                        : !t->loop_open ? "loop_open" : !t->loop_close ? "loop_close"
                        : !t->pass ? "pass" : !t->body ? "body" : !t->scene ? "scene"
                        : !t->desc_prologue ? "desc_prologue" : !t->desc_members ? "desc_members"
                        : NULL;
    if (missing)
        diag_fatal_noloc("internal error: the target table '%s' has no '%s'",
                         t->name ? t->name : "?", missing);
    return missing ? -1 : 0;
}

/* One piece of body b's code; -1 after reporting. */
static int body_piece(Emitter *E, const BodyPiece *piece, const BodyModel *b, const BodyPlan *p)
{
    switch (piece->kind) {
    case PIECE_LAW: emit_material(E, b, p); return 0;
    case PIECE_GRAVITY: emit_gravity(E, b, p); return 0;
    case PIECE_TEMPLATE: return emit_template(E, piece->file, b, p);
    case PIECE_LANES: return emit_template_lanes(E, piece->file, b, p);
    case PIECE_BCS: emit_bc_passes(E, b, p); return 0;
    case PIECE_RESTRICT: emit_fracture_restrict(E, b); return 0;
    case PIECE_END: return 0;
    }
    return 0;
}

int emit_program(const Plan *plan, Target t, int mpi, const char *templates_dir, FILE *out)
{
    Emitter E = {plan->model, plan, plan->bodies, templates_dir, out, emit_target(t), mpi};
    if (target_complete(E.target))
        return -1;
    E.target->header(&E);
    emit_consts_fns(&E);
    for (int i = 0; i < plan->nbodies; i++)
        for (const BodyPiece *piece = E.target->body; piece->kind != PIECE_END; piece++)
            if (body_piece(&E, piece, &plan->model->bodies[i], &plan->bodies[i]))
                return -1;
    E.target->scene(&E);
    emit_model_desc(&E);
    return 0;
}
