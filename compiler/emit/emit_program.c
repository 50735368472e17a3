/* emit_program.c — the generated program, in the same order for every target:
 *
 *   header (includes) · constants and user functions · per body the pieces its target lists
 *   (material law, templates, boundary conditions, ...) · the scene's step and glue · the
 *   scene description and main()
 *
 * What differs between the targets comes from their tables (emit_target.c). */
#include <stdio.h>
#include <stdlib.h>

#include "emit.h"
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

/* Body i's pieces: all of them where it runs its own code, else its own boundary conditions
 * after a line that says whose code it runs; -1 after reporting. */
static int body_pieces(Emitter *E, int i)
{
    const BodyModel *b = &E->m->bodies[i];
    const int own = E->code[i] == i;
    if (!own)
        fprintf(E->out, "/* ==== body %s: the code of body %s (the same law, constants and passes) "
                        "==== */\n\n",
                b->name, emit_code_name(E, i));
    for (const BodyPiece *piece = E->target->body; piece->kind != PIECE_END; piece++)
        if ((own || !piece_is_code(piece->kind)) &&
            emit_body_piece(E, piece, b, &E->plans[i]))
            return -1;
    return 0;
}

int emit_program(const Plan *plan, Target t, int mpi, const char *templates_dir, FILE *out)
{
    Emitter E = {plan->model, plan, plan->bodies, templates_dir, out, emit_target(t), mpi, NULL};
    if (target_complete(E.target))
        return -1;
    int *code = malloc((size_t)(plan->nbodies > 0 ? plan->nbodies : 1) * sizeof *code);
    if (!code) {
        diag_fatal_noloc("out of memory");
        return -1;
    }
    if (emit_share_code(&E, code)) {
        free(code);
        return -1;
    }
    E.code = code;
    E.target->header(&E);
    emit_consts_fns(&E);
    int rc = 0;
    for (int i = 0; i < plan->nbodies && !rc; i++)
        rc = body_pieces(&E, i);
    if (!rc) {
        E.target->scene(&E);
        emit_model_desc(&E);
    }
    free(code);
    return rc;
}
