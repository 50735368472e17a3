/* emit_expr.c — user expressions (paper Tables 1-3) as C.
 *
 * Constants become `k_NAME`, user functions `f_NAME(...)`, particle variables fields of
 * the sph_pt argument `p`.  An expression that may `skip` becomes a function returning 0
 * for "do nothing" and 1 with the value in *out; its `if`s become C if/else. */
#include <string.h>

#include "emit_expr.h"
#include "model/eval.h"
#include "lang/builtins.h"

static void name(FILE *out, const EmitScope *s, const char *n)
{
    for (int i = 0; i < s->nparams; i++)
        if (!strcmp(s->params[i], n)) {
            fprintf(out, "%s%s", s->prefix, n);
            return;
        }
    if (model_find_const(s->model, n)) {
        fprintf(out, "k_%s", n);
        return;
    }
    fprintf(out, "p->%s", n); /* a particle variable (checked) */
}

static void args(FILE *out, const EmitScope *s, const Expr *e)
{
    for (int i = 0; i < e->nargs; i++) {
        if (i)
            fputs(", ", out);
        emit_expr(out, s, e->args[i]);
    }
}

/* A user function f_NAME(...), or a built-in by its form (lang/builtins.h). */
static void call(FILE *out, const EmitScope *s, const Expr *e)
{
    if (model_find_fn(s->model, e->name)) {
        fprintf(out, "f_%s(", e->name);
        args(out, s, e);
        fputs(")", out);
        return;
    }
    const Builtin *b = &BUILTIN_FUNCTION[builtin_function(e->name)]; /* checked */
    switch (b->form) {
    case BF_IF:
        fputs("(", out);
        emit_expr(out, s, e->args[0]);
        fputs(" ? ", out);
        emit_expr(out, s, e->args[1]);
        fputs(" : ", out);
        emit_expr(out, s, e->args[2]);
        fputs(")", out);
        return;
    case BF_RECIP:
        fprintf(out, "(1.0 / %s(", b->c);
        emit_expr(out, s, e->args[0]);
        fputs("))", out);
        return;
    default:
        fprintf(out, "%s(", b->c);
        args(out, s, e);
        fputs(")", out);
        return;
    }
}

/* A number as a C double literal: %.17g writes whole numbers without a point (2, 1e+16 is
 * 10000000000000000), which C would read as integers, so that 1/2 became the integer
 * division 0 and 1/0 undefined behaviour instead of infinity. */
static void number(FILE *out, double v)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.17g", v);
    int whole = strspn(buf, "-0123456789") == strlen(buf);
    fprintf(out, v < 0 ? "(%s%s)" : "%s%s", buf, whole ? ".0" : "");
}

static const char *c_operator(OpKind op)
{
    switch (op) {
    case OP_AND: return "&&";
    case OP_OR: return "||";
    default: return op_spelling(op);
    }
}

void emit_expr(FILE *out, const EmitScope *s, const Expr *e)
{
    switch (e->kind) {
    case EX_NUM:
        number(out, e->num);
        return;
    case EX_NAME:
        name(out, s, e->name);
        return;
    case EX_CALL:
        call(out, s, e);
        return;
    case EX_UNARY:
        fputs(e->op == OP_NEG ? "(-" : "(!", out);
        emit_expr(out, s, e->args[0]);
        fputs(")", out);
        return;
    case EX_BINARY:
        if (e->op == OP_POW) {
            fputs("pow(", out);
            emit_expr(out, s, e->args[0]);
            fputs(", ", out);
            emit_expr(out, s, e->args[1]);
            fputs(")", out);
            return;
        }
        fputs("(", out);
        emit_expr(out, s, e->args[0]);
        fprintf(out, " %s ", c_operator(e->op));
        emit_expr(out, s, e->args[1]);
        fputs(")", out);
        return;
    case EX_VEC:
    case EX_SKIP:
        fputs("0 /* unreachable */", out);
        return;
    }
}

int expr_uses_variables(const Model *m, const Expr *e)
{
    if (e->kind == EX_NAME)
        return !model_find_const(m, e->name) && builtin_variable(e->name) >= 0;
    for (int i = 0; i < e->nargs; i++)
        if (expr_uses_variables(m, e->args[i]))
            return 1;
    return 0;
}

static int is_if(const Expr *e)
{
    return e->kind == EX_CALL && builtin_function(e->name) == BI_if && e->nargs == 3;
}

int expr_may_skip(const Expr *e)
{
    if (e->kind == EX_SKIP)
        return 1;
    return is_if(e) && (expr_may_skip(e->args[1]) || expr_may_skip(e->args[2]));
}

static void indent_by(FILE *out, int depth)
{
    for (int i = 0; i < depth; i++)
        fputs("    ", out);
}

/* The body of a value function: if/else down to the skips, an assignment elsewhere. */
static void statements(FILE *out, const EmitScope *s, const Expr *e, int depth)
{
    if (e->kind == EX_SKIP) {
        indent_by(out, depth);
        fputs("return 0; /* skip */\n", out);
        return;
    }
    if (!expr_may_skip(e)) {
        indent_by(out, depth);
        fputs("*out = ", out);
        emit_expr(out, s, e);
        fputs(";\n", out);
        indent_by(out, depth);
        fputs("return 1;\n", out);
        return;
    }
    indent_by(out, depth);
    fputs("if (", out);
    emit_expr(out, s, e->args[0]);
    fputs(") {\n", out);
    statements(out, s, e->args[1], depth + 1);
    indent_by(out, depth);
    fputs("}\n", out);
    statements(out, s, e->args[2], depth);
}

void emit_value_function(FILE *out, const Model *m, const char *fname, const Expr *e)
{
    EmitScope s = {m, NULL, 0, ""};
    fprintf(out, "SPH_FN int %s(const sph_pt *p, double *out)\n{\n", fname);
    if (!expr_uses_variables(m, e))
        fputs("    (void)p;\n", out);
    statements(out, &s, e, 1);
    fputs("}\n", out);
}
