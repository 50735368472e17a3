/* check_expr.h — checking the expressions of a model (check_expr.c): names, arity, types,
 * `skip`; constants folded to numbers. */
#ifndef SPHC_CHECK_EXPR_H
#define SPHC_CHECK_EXPR_H

#include "model/model.h"

typedef struct {
    const Model *model;
    char **params;      /* function parameters in scope */
    int nparams;
    int allow_vars;     /* particle variables x0 ... dx allowed */
    int allow_skip;     /* `skip` allowed as a branch of if */
    const char *what;   /* context for messages, e.g. "a boundary condition" */
} ExprScope;

/* Check a scalar expression; tail = e is in tail position (skip allowed there).
 * Returns 0 or -1 after reporting. */
int check_scalar_expr(const ExprScope *s, const Expr *e, int tail);
int check_const_expr(const Model *m, const Expr *e, const char *what, double *out);
int check_vec3(const Model *m, const Expr *e, const char *what, double out[3]);

#endif
