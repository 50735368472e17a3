/* emit.h — the C emitter (model.c for the OpenMP target). */
#ifndef SPHC_EMIT_H
#define SPHC_EMIT_H

#include <stdio.h>

#include "check/model.h"

typedef struct {
    const Model *model;
    char **params;      /* names bound as C parameters */
    int nparams;
    const char *prefix; /* C spelling prefix of those names */
} EmitScope;

void emit_expr(FILE *out, const EmitScope *s, const Expr *e);
int expr_may_skip(const Expr *e);
int expr_uses_variables(const Model *m, const Expr *e);
/* static inline int fname(const sph_pt *p, double *out): 0 = skip, 1 = value in *out */
void emit_value_function(FILE *out, const Model *m, const char *fname, const Expr *e);

/* Write the whole generated program for the CPU target.  templates_dir holds
 * body_forces.c etc.  Returns 0 or -1 (reported). */
int emit_c_program(const Model *m, const char *templates_dir, FILE *out);
/* The same model for the CUDA target: model.cu, built by nvcc with runtime/sph_cuda.h.
 * Returns 0, or -1 after reporting a feature the target does not support yet. */
int emit_cuda_program(const Model *m, const char *templates_dir, FILE *out);

/* Print the per-body kernel plan (sphc --dump=plan). */
void plan_dump(const Model *m, FILE *out);

#endif
