/* eval.c — a reference interpreter for scalar expressions.
 *
 * The checker uses it to fold constants (`let`, settings, shape coordinates); tests use it
 * to compare the compiled C of an expression against the model's meaning. */
#include <stdlib.h>
#include <string.h>

#include "eval.h"
#include "lang/arith.h"
#include "lang/builtins.h"

const ConstDef *model_find_const(const Model *m, const char *name)
{
    const int k = name_index_get(&m->const_index, name);
    return k >= 0 && k < m->nconsts && !strcmp(m->consts[k].name, name) ? &m->consts[k] : NULL;
}

const FnDef *model_find_fn(const Model *m, const char *name)
{
    const int k = name_index_get(&m->fn_index, name);
    return k >= 0 && k < m->nfns && !strcmp(m->fns[k].name, name) ? &m->fns[k] : NULL;
}

void model_add_const(Model *m, ConstDef c)
{
    name_index_put(&m->const_index, c.name, m->nconsts);
    m->consts[m->nconsts++] = c;
}

void model_add_fn(Model *m, FnDef f)
{
    name_index_put(&m->fn_index, f.name, m->nfns);
    m->fns[m->nfns++] = f;
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
    int f = builtin_function(e->name);
    if (f == BI_if) { /* only the chosen branch: the other may skip or need a variable */
        double c;
        int r = eval_expr(m, e->args[0], env, &c);
        if (r != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
        return eval_expr(m, e->args[c != 0.0 ? 1 : 2], env, out);
    }
    double few[8], *a = e->nargs > 8 ? malloc((size_t)e->nargs * sizeof *a) : few;
    int r = EVAL_OK;
    for (int i = 0; i < e->nargs && r == EVAL_OK; i++)
        if ((r = eval_expr(m, e->args[i], env, &a[i])) == EVAL_SKIP)
            r = EVAL_ERROR;
    const FnDef *fn = model_find_fn(m, e->name);
    if (r == EVAL_OK && fn)
        r = eval_user_fn(m, fn, a, env, out);
    else if (r == EVAL_OK && (f < 0 || BUILTIN_FUNCTION[f].arity != e->nargs))
        r = EVAL_ERROR;
    else if (r == EVAL_OK)
        *out = builtin_value(f, a);
    if (a != few)
        free(a);
    return r;
}

/* The operators of the language in the folding arithmetic. */
static const ArithOp ARITH[] = {
    [OP_ADD] = AR_ADD, [OP_SUB] = AR_SUB, [OP_MUL] = AR_MUL, [OP_DIV] = AR_DIV,
    [OP_POW] = AR_POW, [OP_LT] = AR_LT,   [OP_GT] = AR_GT,   [OP_LE] = AR_LE,
    [OP_GE] = AR_GE,   [OP_EQ] = AR_EQ,   [OP_NE] = AR_NE,   [OP_AND] = AR_AND,
    [OP_OR] = AR_OR,   [OP_NEG] = AR_NEG, [OP_NOT] = AR_NOT,
};

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
        *out = arith_unary(ARITH[e->op], x);
        return EVAL_OK;
    case EX_BINARY:
        if ((r = eval_expr(m, e->args[0], env, &x)) != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
        if ((r = eval_expr(m, e->args[1], env, &y)) != EVAL_OK)
            return r == EVAL_SKIP ? EVAL_ERROR : r;
        *out = arith_binary(ARITH[e->op], x, y);
        return EVAL_OK;
    }
    return EVAL_ERROR;
}
