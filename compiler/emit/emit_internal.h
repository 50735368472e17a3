/* emit_internal.h — the pieces of the emitter: constants, functions and laws (SPH_FN), a
 * body's templates, its boundary-condition passes, the step and the scene description,
 * shared by both targets, and the table of what differs between the targets.  The pieces
 * these call have headers of their own: emit_fracture.h, emit_law.h, emit_quote.h. */
#ifndef SPHC_EMIT_INTERNAL_H
#define SPHC_EMIT_INTERNAL_H

#include <stdio.h>

#include "model/model.h"
#include "emit.h"
#include "emit_expr.h"
#include "lower/plan.h"

typedef struct Emitter Emitter;

/* What a body's code is made of, in the order of the generated file. */
typedef enum {
    PIECE_LAW,      /* its material law (emit_functions.c) */
    PIECE_GRAVITY,  /* its gravity as a table the passes read */
    PIECE_TEMPLATE, /* a file of templates/ filled for it */
    PIECE_LANES,    /* a file of templates/ filled for it once per element type its loops
                     * use (the pair terms: emit_body.c) */
    PIECE_BCS,      /* its boundary-condition values and passes */
    PIECE_RESTRICT, /* the lower bound of its phase field */
    PIECE_END
} PieceKind;

typedef struct {
    PieceKind kind;
    const char *file; /* PIECE_TEMPLATE, PIECE_LANES */
} BodyPiece;

/* Whether a piece is the body's code (its law and passes), which another body whose code
 * is the same text runs too (emit_share.c), rather than its own: its boundary conditions
 * and the bound of its phase field, whose values differ between bodies. */
static inline int piece_is_code(PieceKind kind)
{
    return kind != PIECE_BCS && kind != PIECE_RESTRICT;
}

/* What differs between the targets; every member must be set (emit_program checks). */
typedef struct {
    const char *name;   /* as in --target */
    const char *suffix; /* of the generated file */
    /* The file's opening comment and includes. */
    void (*header)(Emitter *E);
    /* A parallel loop over particles `i` < `n` (one thread each on the device), opened and
     * closed at the indent given. */
    void (*loop_open)(FILE *out, const char *indent, const char *i, const char *n);
    void (*loop_close)(FILE *out, const char *indent);
    /* A pass in the step of the body `b` whose code is body `body`'s: `body_pass(args);`,
     * timed for --profile. */
    void (*pass)(FILE *out, const char *body, const char *pass, const char *args);
    /* Whether a boundary condition's time window is evaluated inside its loop (where the
     * device reads t and dt) rather than once before it. */
    int windows_in_loops;
    /* Whether a law's dt reaches a body's forces as their argument `law_dt` (a time the
     * device's clock may give) rather than in b->law_dt, which the step sets. */
    int law_dt_argument;
    /* The pieces of each body's code. */
    const BodyPiece *body;
    /* Whether a body whose code is another's text runs that body's functions (emit_share.c);
     * its passes are then timed under its own name (SPH_BODY_PASS). */
    int share_code;
    /* The scene's step and whatever glue the runtime calls (model_step, ...). */
    void (*scene)(Emitter *E);
    /* Before the scene description, and the members of sph_model it adds. */
    const char *desc_prologue;
    const char *desc_members;
} EmitTarget;

struct Emitter {
    const Model *m;
    const Plan *plan;
    const BodyPlan *plans; /* plan->bodies */
    const char *templates;
    FILE *out;
    const EmitTarget *target;
    int mpi; /* sphc --mpi: the program runs on many processes (sph_mpi_main) */
    /* For each body, the body whose code it runs: itself, or an earlier body whose code
     * pieces are the same text (emit_share.c); NULL: each its own. */
    const int *code;
};

/* The name of the body whose code body i runs (its passes, law and pair terms are that
 * body's functions); its boundary conditions are its own, under its own name. */
static inline const char *emit_code_name(const Emitter *E, int i)
{
    return E->m->bodies[E->code ? E->code[i] : i].name;
}

/* The targets' tables (emit_target.c) and the targets' scenes. */
const EmitTarget *emit_target(Target t);
void emit_scene_cpu(Emitter *E);  /* emit_step.c */
void emit_scene_cuda(Emitter *E); /* emit_cuda.c */

/* ---- a body's code and the bodies that share it */
/* One piece of body b's code, as the target lists them (emit_piece.c); -1 after
 * reporting. */
int emit_body_piece(Emitter *E, const BodyPiece *piece, const BodyModel *b, const BodyPlan *p);
/* code[i] for every body (Emitter.code), from the text of their code pieces
 * (emit_share.c); -1 after reporting an error of a template. */
int emit_share_code(Emitter *E, int *code);

/* ---- constants, user functions and material laws (emit_functions.c) */
void emit_consts_fns(Emitter *E);
void emit_material(Emitter *E, const BodyModel *b, const BodyPlan *p);

/* ---- a body's templates (emit_body.c) */
/* templates/FILE filled for body b (its features and numbers); -1 after reporting. */
int emit_template(Emitter *E, const char *file, const BodyModel *b, const BodyPlan *p);
/* templates/FILE filled once for each element type body b's pair loops use; -1 after
 * reporting. */
int emit_template_lanes(Emitter *E, const char *file, const BodyModel *b, const BodyPlan *p);
void emit_gravity(Emitter *E, const BodyModel *b, const BodyPlan *p);

/* ---- boundary conditions (emit_bcs.c) */
/* Body b's BC value functions and the passes its plan needs. */
void emit_bc_passes(Emitter *E, const BodyModel *b, const BodyPlan *p);

/* ---- the step (emit_step.c) */
/* Every body's passes of one step, body i named by the printf format `body` ("%d": i); with
 * contact, every body's forces, then the call `contact`, then every body's update. */
void emit_step_bodies(Emitter *E, const char *body, const char *contact);
/* model_stress_output: every body's Cauchy stress for output (`from`: where it is read). */
void emit_stress_output(Emitter *E, const char *from);

/* ---- the scene description and main() (emit_desc.c) */
void emit_model_desc(Emitter *E);

#endif
