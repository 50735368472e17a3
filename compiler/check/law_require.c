/* law_require.c — what a law's parameters must satisfy:
 *
 *   material viscoelastic(K, mu, g1, tau1) {
 *     require g1 >= 0 and g1 < 1, "a Prony weight g is in [0, 1)"
 *     ...
 *
 * A requirement is a scalar condition on the law's parameters, numbers and the model's
 * constants and functions; it adds nothing to the law's graph (ir/law.c passes it by).  It
 * is checked with the law (law_require_check) and evaluated with the model's constant
 * evaluator for each body that uses the law, with the body's parameter values
 * (law_require_body): where it is false or not a finite number, the body is refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "law_require.h"
#include "front/sph_print.h"
#include "lang/builtins.h"
#include "model/eval.h"
#include "util/diag.h"

/* One requirement of a law, as its condition is read: the statements before it at the
 * law's top level (their names hide the parameters, as in ir/law.c's lookup). */
typedef struct {
    const Model *m;
    const MaterialDef *law;
    int index;       /* the requirement's place among the law's top-level statements */
    const char *var; /* the law's deformation variable: F, or C or E of energy psi(C), psi(E) */
    int report;      /* 0: only say whether it is accepted (a body's check, after the law's) */
} Reads;

/* The variable the law is written with: C or E where its energy is psi(C) or psi(E), F
 * otherwise (an energy of anything else is reported by law_check). */
static const char *law_variable(const MaterialDef *law)
{
    for (int i = 0; i < law->body.n; i++) {
        const MatStmt *s = &law->body.items[i];
        if (s->kind == MS_ENERGY && s->of)
            return s->of;
    }
    return "F";
}

/* Whether name is one of the law's own values where the requirement stands: its variable,
 * or a let, state, stress or energy of the statements before it. */
static int law_local(const Reads *r, const char *name)
{
    if (!strcmp(name, r->var))
        return 1;
    for (int i = 0; i < r->index; i++) {
        const MatStmt *s = &r->law->body.items[i];
        int binds = s->kind == MS_LET || s->kind == MS_STATE || s->kind == MS_STRESS ||
                    s->kind == MS_ENERGY;
        if (binds && !strcmp(s->name, name))
            return 1;
    }
    return 0;
}

/* The parameter called name: its index, or -1. */
static int param_index(const MaterialDef *law, const char *name)
{
    for (int i = 0; i < law->nparams; i++)
        if (!strcmp(law->params[i], name))
            return i;
    return -1;
}

static int is_tensor_function(const char *f)
{
    static const char *const names[] = {"transpose", "tr", "det", "inv", "sym", "dev",
                                        "pos", "neg", "ddot"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(f, names[i]))
            return 1;
    return 0;
}

/* An error (with r->report) whose fmt names the law, then what: -1. */
static int refuse(const Reads *r, SrcLoc loc, const char *fmt, const char *what)
{
    if (r->report)
        diag_error(loc, fmt, r->law->name, what);
    return -1;
}

/* A name the condition reads, resolved as the law resolves it: its own values first, then
 * its parameters, the identity I, the model's constants. */
static int reads_name(const Reads *r, const Expr *e)
{
    static const char *const not_one =
        "a requirement of material '%s' reads only its parameters and constants; '%s' is not one";
    if (law_local(r, e->name))
        return refuse(r, e->loc, not_one, e->name);
    if (param_index(r->law, e->name) >= 0 || model_find_const(r->m, e->name))
        return 0;
    if (!strcmp(e->name, "I"))
        return refuse(r, e->loc, "a requirement of material '%s' is a scalar condition; '%s' is "
                                 "the identity tensor", e->name);
    return refuse(r, e->loc, not_one, e->name);
}

static int reads_expr(const Reads *r, const Expr *e);

/* A call: a function of the model or a built-in scalar function, of what may be read.  (A
 * function's body sees only its parameters and the constants: check_fn checked it.) */
static int reads_call(const Reads *r, const Expr *e)
{
    const FnDef *fn = model_find_fn(r->m, e->name);
    int bad = 0;
    for (int i = 0; i < e->nargs; i++)
        bad |= reads_expr(r, e->args[i]) != 0;
    if (bad) /* det(F): F is the error */
        return -1;
    if (!fn && is_tensor_function(e->name))
        return refuse(r, e->loc, "a requirement of material '%s' is a scalar condition; '%s' "
                                 "is a function of tensors", e->name);
    const int arity = fn ? fn->nparams : builtin_function_arity(e->name);
    if (arity < 0) {
        if (r->report)
            diag_error(e->loc, "unknown function '%s'", e->name);
        return -1;
    }
    if (e->nargs != arity) {
        if (r->report)
            diag_error(e->loc, "function '%s' takes %d argument%s, got %d", e->name, arity,
                       arity == 1 ? "" : "s", e->nargs);
        return -1;
    }
    return 0;
}

/* 0 where the condition reads only what a requirement may read and is a scalar; -1 (after
 * reporting, with r->report) otherwise. */
static int reads_expr(const Reads *r, const Expr *e)
{
    switch (e->kind) {
    case EX_NUM:
        return 0;
    case EX_NAME:
        return reads_name(r, e);
    case EX_CALL:
        return reads_call(r, e);
    case EX_UNARY:
        return reads_expr(r, e->args[0]);
    case EX_BINARY: {
        const int a = reads_expr(r, e->args[0]), b = reads_expr(r, e->args[1]);
        return a || b ? -1 : 0;
    }
    case EX_VEC:
        if (r->report)
            diag_error(e->loc, "a requirement of material '%s' is a scalar condition; got a "
                               "vector", r->law->name);
        return -1;
    case EX_SKIP:
        if (r->report)
            diag_error(e->loc, "'skip' cannot be used in a requirement of material '%s'",
                       r->law->name);
        return -1;
    }
    return -1;
}

/* Requirements inside blocks (an `if`, the `tension` block): each an error at itself. */
static int nested(const MaterialDef *law, const MatStmtList *l, const char *where)
{
    int bad = 0;
    for (int i = 0; i < l->n; i++) {
        const MatStmt *s = &l->items[i];
        if (s->kind == MS_REQUIRE) {
            diag_error(s->loc, "a requirement cannot be inside %s of material '%s' (it states "
                               "what the parameters must satisfy: write it at the law's top "
                               "level)", where, law->name);
            bad = 1;
        }
        bad |= nested(law, &s->body, where) != 0;
        bad |= nested(law, &s->orelse, where) != 0;
    }
    return bad ? -1 : 0;
}

int law_require_check(const Model *m, const MaterialDef *law)
{
    Reads r = {m, law, 0, law_variable(law), 1};
    int bad = 0;
    for (int i = 0; i < law->body.n; i++) {
        const MatStmt *s = &law->body.items[i];
        if (s->kind == MS_IF) {
            bad |= nested(law, &s->body, "an if block") != 0;
            bad |= nested(law, &s->orelse, "an if block") != 0;
        } else if (s->kind == MS_BLOCK) {
            bad |= nested(law, &s->body, !strcmp(s->name, "tension") ? "the tension block"
                                                                      : "a block") != 0;
        } else if (s->kind == MS_REQUIRE) {
            r.index = i;
            bad |= reads_expr(&r, s->value) != 0;
        }
    }
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ a body's values */

/* The shortest text of v that reads back as v ("1.2", not "1.2000000000000002"; a value just
 * below a bound is not shown as the bound). */
static void shortest(double v, char *buf, size_t size)
{
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(buf, size, "%.*g", digits, v);
        if (!isfinite(v) || strtod(buf, NULL) == v)
            return;
    }
}

/* The parameters and constants a condition reads, each once, in the order first read (not
 * inside the functions it calls), as "g1 = 1.2, tau1 = 0". */
typedef struct {
    const char *names[32];
    int n;
    char text[1024];
} ValuesRead;

static void values_read(const Reads *r, const double *args, const Expr *e, ValuesRead *out)
{
    for (int i = 0; e->kind != EX_NAME && i < e->nargs; i++)
        values_read(r, args, e->args[i], out);
    if (e->kind != EX_NAME || out->n == (int)(sizeof out->names / sizeof out->names[0]))
        return;
    for (int k = 0; k < out->n; k++)
        if (!strcmp(out->names[k], e->name))
            return; /* listed already */
    const int k = param_index(r->law, e->name);
    const ConstDef *c = k < 0 ? model_find_const(r->m, e->name) : NULL;
    if (k < 0 && !c)
        return;
    char num[40];
    shortest(k >= 0 ? args[k] : c->value, num, sizeof num);
    const size_t len = strlen(out->text);
    snprintf(out->text + len, sizeof out->text - len, "%s%s = %s", out->n ? ", " : "",
             e->name, num);
    out->names[out->n++] = e->name;
}

/* The condition as the model would write it, malloc'ed (NULL when out of memory). */
static char *condition_text(const Expr *e)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f)
        return NULL;
    sph_print_expr(e, f);
    fclose(f);
    return buf;
}

/* Requirement s (at top-level place i) of b's law with b's values: 0 where it holds, -1
 * after reporting at loc where it does not. */
static int require_one(const Model *m, const BodyModel *b, SrcLoc loc, const MatStmt *s, int i)
{
    const MaterialDef *law = b->law;
    const Reads r = {m, law, i, law_variable(law), 0};
    if (reads_expr(&r, s->value))
        return 0; /* refused with the law */
    const EvalEnv env = {(const char *const *)law->params, b->law_args, law->nparams, NULL, NULL};
    double v;
    if (eval_expr(m, s->value, &env, &v) != EVAL_OK)
        return 0; /* not a constant: cannot happen once the names are checked */
    if (v != 0 && isfinite(v))
        return 0;
    ValuesRead here = {{0}, 0, ""};
    values_read(&r, b->law_args, s->value, &here);
    char value[40], nonfinite[128] = "";
    shortest(v, value, sizeof value);
    if (!isfinite(v)) /* a condition that is no number cannot hold */
        snprintf(nonfinite, sizeof nonfinite, "%s the condition is %s, not a finite number",
                 here.n ? ", where" : ";", value);
    char *cond = condition_text(s->value);
    const char *msg = s->message ? s->message : "";
    diag_error(loc, "body '%s': material '%s' requires %s%s%s%s%s%s%s", b->name, law->name,
               cond ? cond : "its condition", *msg ? " (" : "", msg, *msg ? ")" : "",
               here.n ? "; here " : "", here.text, nonfinite);
    diag_note(s->loc, "material '%s' states the requirement here", law->name);
    free(cond);
    return -1;
}

int law_require_body(const Model *m, const BodyModel *b, SrcLoc loc)
{
    const MaterialDef *law = b->law;
    int bad = 0;
    for (int i = 0; i < law->body.n; i++)
        if (law->body.items[i].kind == MS_REQUIRE)
            bad |= require_one(m, b, loc, &law->body.items[i], i) != 0;
    return bad ? -1 : 0;
}
