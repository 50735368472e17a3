/* emit_expr.h — user expressions (paper Tables 1-3) as C (emit_expr.c). */
#ifndef SPHC_EMIT_EXPR_H
#define SPHC_EMIT_EXPR_H

#include <stdio.h>

#include "model/model.h"

typedef struct {
    const Model *model;
    char **params;      /* names bound as C parameters */
    int nparams;
    const char *prefix; /* C spelling prefix of those names */
} EmitScope;

void emit_expr(FILE *out, const EmitScope *s, const Expr *e);
int expr_may_skip(const Expr *e);
int expr_uses_variables(const Model *m, const Expr *e);
/* SPH_FN int fname(const sph_pt *p, double *out): 0 = skip, 1 = value in *out */
void emit_value_function(FILE *out, const Model *m, const char *fname, const Expr *e);

#endif
