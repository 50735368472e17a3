/* eval.h — reference interpreter for checked scalar expressions. */
#ifndef SPHC_EVAL_H
#define SPHC_EVAL_H

#include "model.h"

enum { EVAL_OK = 0, EVAL_SKIP = 1, EVAL_NOT_CONSTANT = 2, EVAL_ERROR = 3 };

/* Names bound during evaluation: function parameters or material locals, and optionally
 * the built-in variables (vars[k] for BUILTIN_VARIABLES[k]). */
typedef struct EvalEnv {
    const char *const *names;
    const double *values;
    int n;
    const double *vars;         /* NULL: built-in variables are not available */
    const struct EvalEnv *parent;
} EvalEnv;

/* Evaluate e.  Returns EVAL_OK (value in *out), EVAL_SKIP (the expression chose `skip`),
 * EVAL_NOT_CONSTANT (it needs a variable that env does not provide) or EVAL_ERROR. */
int eval_expr(const Model *m, const Expr *e, const EvalEnv *env, double *out);

/* The `let` constant or `fn` of that name, or NULL (hashed: model_add_* keep the index). */
const ConstDef *model_find_const(const Model *m, const char *name);
const FnDef *model_find_fn(const Model *m, const char *name);
/* Append a constant or a function to the model (its array has room) and index its name. */
void model_add_const(Model *m, ConstDef c);
void model_add_fn(Model *m, FnDef f);

#endif
