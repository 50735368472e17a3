/* check_expr.c — checking scalar expressions: names, functions, arity, types, `skip`. */
#include <math.h>
#include <string.h>

#include "check_expr.h"
#include "util/diag.h"
#include "model/eval.h"
#include "lang/builtins.h"

static int in_scope(const ExprScope *s, const char *name)
{
    for (int i = 0; i < s->nparams; i++)
        if (strcmp(s->params[i], name) == 0)
            return 1;
    return 0;
}

static int check_name(const ExprScope *s, const Expr *e)
{
    if (in_scope(s, e->name) || model_find_const(s->model, e->name))
        return 0;
    if (builtin_variable(e->name) >= 0) {
        if (s->allow_vars)
            return 0;
        diag_error(e->loc, "'%s' is a particle variable and cannot be used here (%s)", e->name,
                   s->what);
        return -1;
    }
    diag_error(e->loc, "unknown name '%s'", e->name);
    return -1;
}

static int check_call(const ExprScope *s, const Expr *e, int tail)
{
    const FnDef *fn = model_find_fn(s->model, e->name);
    int arity = fn ? fn->nparams : builtin_function_arity(e->name);
    if (arity < 0) {
        diag_error(e->loc, "unknown function '%s'", e->name);
        return -1;
    }
    if (e->nargs != arity) {
        diag_error(e->loc, "function '%s' takes %d argument%s, got %d", e->name, arity,
                   arity == 1 ? "" : "s", e->nargs);
        return -1;
    }
    int bad = 0;
    int is_if = !fn && builtin_function(e->name) == BI_if;
    for (int i = 0; i < e->nargs; i++)
        bad |= check_scalar_expr(s, e->args[i], is_if && i > 0 ? tail : 0);
    return bad ? -1 : 0;
}

int check_scalar_expr(const ExprScope *s, const Expr *e, int tail)
{
    switch (e->kind) {
    case EX_NUM:
        return 0;
    case EX_NAME:
        return check_name(s, e);
    case EX_SKIP:
        if (tail && s->allow_skip)
            return 0;
        diag_error(e->loc, s->allow_skip ? "'skip' may only be a branch of 'if'"
                                         : "'skip' cannot be used here (%s)",
                   s->what);
        return -1;
    case EX_VEC:
        diag_error(e->loc, "expected a scalar, got a vector (%s)", s->what);
        return -1;
    case EX_CALL:
        return check_call(s, e, tail);
    case EX_UNARY:
        return check_scalar_expr(s, e->args[0], 0);
    case EX_BINARY: {
        int a = check_scalar_expr(s, e->args[0], 0);
        int b = check_scalar_expr(s, e->args[1], 0);
        return (a || b) ? -1 : 0;
    }
    }
    return -1;
}

/* A value that must be known at compile time (a setting, a coordinate). */
int check_const_expr(const Model *m, const Expr *e, const char *what, double *out)
{
    ExprScope s = {m, NULL, 0, 0, 0, what};
    if (check_scalar_expr(&s, e, 0))
        return -1;
    int r = eval_expr(m, e, NULL, out);
    if (r != EVAL_OK) {
        diag_error(e->loc, "%s must be a constant", what);
        return -1;
    }
    if (!isfinite(*out)) {
        diag_error(e->loc, "%s must be a finite number (got %g)", what, *out);
        return -1;
    }
    return 0;
}

int check_vec3(const Model *m, const Expr *e, const char *what, double out[3])
{
    if (e->kind != EX_VEC || e->nargs != 3) {
        diag_error(e->loc, "%s must be a vector [x, y, z]", what);
        return -1;
    }
    int bad = 0;
    for (int k = 0; k < 3; k++)
        bad |= check_const_expr(m, e->args[k], what, &out[k]);
    return bad ? -1 : 0;
}
