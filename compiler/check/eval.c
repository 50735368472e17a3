/* eval.c — a reference interpreter for scalar expressions.
 *
 * The checker uses it to fold constants (`let`, settings, shape coordinates); tests use it
 * to compare the compiled C of an expression against the model's meaning. */
#include <math.h>
#include <string.h>

#include "eval.h"
#include "lang/builtins.h"

const ConstDef *model_find_const(const Model *m, const char *name)
{
    for (int i = 0; i < m->nconsts; i++)
        if (strcmp(m->consts[i].name, name) == 0)
            return &m->consts[i];
    return NULL;
}

const FnDef *model_find_fn(const Model *m, const char *name)
{
    for (int i = 0; i < m->nfns; i++)
        if (strcmp(m->fns[i].name, name) == 0)
            return &m->fns[i];
    return NULL;
}

static int eval_name(const Model *m, const Expr *e, const EvalEnv *env, double *out)
{
    for (const EvalEnv *s = env; s; s = s->parent)
        for (int i = 0; i < s->n; i++)
            if (strcmp(s->names[i], e->name) == 0) {
                *out = s->values[i];
                return EVAL_OK;
            }
    const ConstDef *c = model_find_const(m, e->name);
    if (c) {
        *out = c->value;
        return EVAL_OK;
    }
    for (const EvalEnv *s = env; s; s = s->parent)
        if (s->vars) {
            int k = builtin_variable(e->name);
            if (k >= 0) {
                *out = s->vars[k];
                return EVAL_OK;
            }
        }
    return EVAL_NOT_CONSTANT;
}

static double apply1(const char *f, double x)
{
    if (!strcmp(f, "sin")) return sin(x);
    if (!strcmp(f, "cos")) return cos(x);
    if (!strcmp(f, "tan")) return tan(x);
    if (!strcmp(f, "cot")) return 1.0 / tan(x);
    if (!strcmp(f, "sinh")) return sinh(x);
    if (!strcmp(f, "cosh")) return cosh(x);
    if (!strcmp(f, "tanh")) return tanh(x);
    if (!strcmp(f, "coth")) return 1.0 / tanh(x);
    if (!strcmp(f, "sqrt")) return sqrt(x);
    if (!strcmp(f, "log")) return log10(x);
    if (!strcmp(f, "ln")) return log(x);
    if (!strcmp(f, "exp")) return exp(x);
    if (!strcmp(f, "abs")) return fabs(x);
    return NAN;
}

static int eval_user_fn(const Model *m, const FnDef *fn, const double *args, const EvalEnv *env,
                        double *out)
{
    /* Function bodies see their parameters and the constants, not the caller's locals. */
    EvalEnv inner = {(const char *const *)fn->params, args, fn->nparams, NULL, NULL};
    for (const EvalEnv *s = env; s; s = s->parent)
        if (s->vars) {
            inner.vars = s->vars;
            break;
        }
    return eval_expr(m, fn->body, &inner, out);
}

static int eval_call(const Model *m, const Expr *e, const EvalEnv *env, double *out)
{
    if (strcmp(e->name, "if") == 0) {
        double c;
        int r = eval_expr(m, e->args[0], env, &c);
        if (r != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
        return eval_expr(m, e->args[c != 0.0 ? 1 : 2], env, out);
    }
    double a[8];
    if (e->nargs > 8)
        return EVAL_ERROR;
    for (int i = 0; i < e->nargs; i++) {
        int r = eval_expr(m, e->args[i], env, &a[i]);
        if (r != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
    }
    const FnDef *fn = model_find_fn(m, e->name);
    if (fn)
        return eval_user_fn(m, fn, a, env, out);
    if (!strcmp(e->name, "pow")) *out = pow(a[0], a[1]);
    else if (!strcmp(e->name, "min")) *out = fmin(a[0], a[1]);
    else if (!strcmp(e->name, "max")) *out = fmax(a[0], a[1]);
    else if (e->nargs == 1) *out = apply1(e->name, a[0]);
    else return EVAL_ERROR;
    return EVAL_OK;
}

static double apply_binary(OpKind op, double x, double y)
{
    switch (op) {
    case OP_ADD: return x + y;
    case OP_SUB: return x - y;
    case OP_MUL: return x * y;
    case OP_DIV: return x / y;
    case OP_POW: return pow(x, y);
    case OP_LT: return x < y;
    case OP_GT: return x > y;
    case OP_LE: return x <= y;
    case OP_GE: return x >= y;
    case OP_EQ: return x == y;
    case OP_NE: return x != y;
    case OP_AND: return (x != 0.0) && (y != 0.0);
    case OP_OR: return (x != 0.0) || (y != 0.0);
    default: return NAN;
    }
}

int eval_expr(const Model *m, const Expr *e, const EvalEnv *env, double *out)
{
    double x, y;
    int r;
    switch (e->kind) {
    case EX_NUM:
        *out = e->num;
        return EVAL_OK;
    case EX_NAME:
        return eval_name(m, e, env, out);
    case EX_SKIP:
        return EVAL_SKIP;
    case EX_VEC:
        return EVAL_ERROR;
    case EX_CALL:
        return eval_call(m, e, env, out);
    case EX_UNARY:
        if ((r = eval_expr(m, e->args[0], env, &x)) != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
        *out = e->op == OP_NEG ? -x : (double)(x == 0.0);
        return EVAL_OK;
    case EX_BINARY:
        if ((r = eval_expr(m, e->args[0], env, &x)) != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
        if ((r = eval_expr(m, e->args[1], env, &y)) != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
        *out = apply_binary(e->op, x, y);
        return EVAL_OK;
    }
    return EVAL_ERROR;
}
