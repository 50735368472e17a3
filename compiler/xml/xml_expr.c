/* xml_expr.c — the expression language of SoliDualSPHysics attribute values.
 *
 * A recursive-descent parser producing the same Expr nodes as parser.y, with the
 * precedence of the paper's Table 3 (loosest first): or, and, comparisons, + -, * /,
 * unary - and not, ^ (right associative, tighter than unary minus).  if(c, a, b) is a
 * call; skip and Skip are the keyword.  Names may start with GenCase's '#' marker
 * ("#Lyf + 0.5e-3"), which is dropped.  libxml2 has already undone the XML escapes, and
 * newlines inside attribute values arrive as blanks. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "model/eval.h"
#include "xml_internal.h"
#include "lang/builtins.h"

typedef enum { T_END, T_NUM, T_NAME, T_OP } TokKind;

typedef struct {
    const char *text, *what;
    SrcLoc loc;
    const char *p;       /* next character */
    TokKind kind;        /* current token */
    const char *start;   /* its first character */
    char op[3];
    double num;
    char name[XML_MAX_NAME + 1];
    int nesting;         /* parse_unary calls under way: every nested operand is one */
    int failed;
} Parser;

static void fail(Parser *ps, const char *msg)
{
    if (ps->failed)
        return;
    ps->failed = 1;
    int at = (int)(ps->start - ps->text) + 1;
    if (!*ps->start)
        diag_error(ps->loc, "%s: %s at the end of '%s'", ps->what, msg, ps->text);
    else
        diag_error(ps->loc, "%s: %s at character %d ('%.24s') of '%s'", ps->what, msg, at,
                   ps->start, ps->text);
}

static int lex_number(Parser *ps)
{
    const char *s = ps->p;
    while (isdigit((unsigned char)*s))
        s++;
    if (*s == '.')
        for (s++; isdigit((unsigned char)*s); s++)
            ;
    if ((*s == 'e' || *s == 'E') &&
        (isdigit((unsigned char)s[1]) ||
         ((s[1] == '+' || s[1] == '-') && isdigit((unsigned char)s[2])))) {
        s += 2;
        while (isdigit((unsigned char)*s))
            s++;
    }
    if (isalpha((unsigned char)*s) || *s == '_') {
        fail(ps, "invalid number");
        return -1;
    }
    /* a plain decimal ends at s, so strtod reads exactly it */
    errno = 0;
    ps->num = strtod(ps->p, NULL);
    if (errno == ERANGE) {
        fail(ps, fabs(ps->num) > 1.0 ? "number out of range"
                                     : "number too small (write 0 for zero)");
        return -1;
    }
    ps->kind = T_NUM;
    ps->p = s;
    return 0;
}

static int lex_name(Parser *ps)
{
    const char *s = ps->p + (*ps->p == '#');
    size_t len = 0;
    if (!isalpha((unsigned char)*s) && *s != '_') {
        fail(ps, "expected a name after '#'");
        return -1;
    }
    while (isalnum((unsigned char)s[len]) || s[len] == '_')
        len++;
    if (len >= sizeof ps->name) {
        fail(ps, "name too long");
        return -1;
    }
    memcpy(ps->name, s, len);
    ps->name[len] = 0;
    ps->kind = T_NAME;
    ps->p = s + len;
    return 0;
}

/* Reads the next token; -1 (after reporting) on a bad character. */
static int next(Parser *ps)
{
    static const char *const two[] = {"<=", ">=", "==", "!="};
    while (isspace((unsigned char)*ps->p))
        ps->p++;
    ps->start = ps->p;
    char c = *ps->p;
    if (!c) {
        ps->kind = T_END;
        return 0;
    }
    if (isdigit((unsigned char)c) || (c == '.' && isdigit((unsigned char)ps->p[1])))
        return lex_number(ps);
    if (isalpha((unsigned char)c) || c == '_' || c == '#')
        return lex_name(ps);
    for (int i = 0; i < 4; i++)
        if (!strncmp(ps->p, two[i], 2)) {
            memcpy(ps->op, two[i], 3);
            ps->p += 2;
            ps->kind = T_OP;
            return 0;
        }
    if (strchr("+-*/^<>(),", c)) {
        ps->op[0] = c;
        ps->op[1] = 0;
        ps->p++;
        ps->kind = T_OP;
        return 0;
    }
    ps->kind = T_OP;
    ps->op[0] = 0;
    fail(ps, "unexpected character");
    return -1;
}

static int is_op(const Parser *ps, const char *op)
{
    return ps->kind == T_OP && strcmp(ps->op, op) == 0;
}

static int is_word(const Parser *ps, const char *w)
{
    return ps->kind == T_NAME && strcmp(ps->name, w) == 0;
}

static int expect_op(Parser *ps, const char *op)
{
    if (!is_op(ps, op)) {
        char msg[32];
        snprintf(msg, sizeof msg, "expected '%s'", op);
        fail(ps, msg);
        return -1;
    }
    return next(ps);
}

static Expr *parse_or(Parser *ps);

/* name(args) after the name; the '(' is the current token. */
static Expr *parse_call(Parser *ps, const char *name)
{
    Expr **args = NULL;
    int nargs = 0;
    if (next(ps))
        return NULL;
    if (!is_op(ps, ")"))
        for (;;) {
            Expr *a = parse_or(ps);
            if (!a)
                return NULL;
            ast_push_expr(&args, &nargs, a);
            if (!is_op(ps, ","))
                break;
            if (next(ps))
                return NULL;
        }
    if (expect_op(ps, ")"))
        return NULL;
    return ast_call(ps->loc, name, args, nargs);
}

static Expr *parse_primary(Parser *ps)
{
    if (ps->kind == T_NUM) {
        Expr *e = ast_num(ps->loc, ps->num);
        return next(ps) ? NULL : e;
    }
    if (is_op(ps, "(")) {
        if (next(ps))
            return NULL;
        Expr *e = parse_or(ps);
        return e && !expect_op(ps, ")") ? e : NULL;
    }
    if (ps->kind == T_NAME) {
        if (is_word(ps, "skip") || is_word(ps, "Skip"))
            return next(ps) ? NULL : ast_skip(ps->loc);
        if (is_word(ps, "and") || is_word(ps, "or") || is_word(ps, "not")) {
            fail(ps, "expected an operand");
            return NULL;
        }
        char name[sizeof ps->name];
        memcpy(name, ps->name, sizeof name);
        if (next(ps))
            return NULL;
        return is_op(ps, "(") ? parse_call(ps, name) : ast_name(ps->loc, name);
    }
    fail(ps, "expected an operand");
    return NULL;
}

static Expr *parse_unary(Parser *ps);

static Expr *parse_pow(Parser *ps)
{
    Expr *a = parse_primary(ps);
    if (!a || !is_op(ps, "^"))
        return a;
    if (next(ps))
        return NULL;
    Expr *b = parse_unary(ps);
    return b ? ast_binary(ps->loc, OP_POW, a, b) : NULL;
}

static Expr *parse_unary_op(Parser *ps);

/* Each level of nesting (parentheses, arguments, unary operators, the right of '^') goes
 * through here: the parser recurses once per level, and the later stages once per level
 * of the tree. */
static Expr *parse_unary(Parser *ps)
{
    if (ps->nesting >= AST_MAX_DEPTH) {
        fail(ps, "expression nested too deeply");
        return NULL;
    }
    ps->nesting++;
    Expr *e = parse_unary_op(ps);
    ps->nesting--;
    if (e && e->depth > AST_MAX_DEPTH) {
        fail(ps, "expression nested too deeply");
        return NULL;
    }
    return e;
}

static Expr *parse_unary_op(Parser *ps)
{
    OpKind op;
    if (is_op(ps, "-"))
        op = OP_NEG;
    else if (is_word(ps, "not"))
        op = OP_NOT;
    else if (is_op(ps, "+"))
        return next(ps) ? NULL : parse_unary(ps);
    else
        return parse_pow(ps);
    if (next(ps))
        return NULL;
    Expr *a = parse_unary(ps);
    return a ? ast_unary(ps->loc, op, a) : NULL;
}

/* One left-associative level: operands from sub, operators from ops/kinds. */
static Expr *parse_level(Parser *ps, Expr *(*sub)(Parser *), const char *const *ops,
                         const OpKind *kinds, int nops)
{
    Expr *a = sub(ps);
    while (a) {
        int k = -1;
        for (int i = 0; i < nops && k < 0; i++)
            if (is_op(ps, ops[i]) || is_word(ps, ops[i]))
                k = i;
        if (k < 0)
            return a;
        if (next(ps))
            return NULL;
        Expr *b = sub(ps);
        a = b ? ast_binary(ps->loc, kinds[k], a, b) : NULL;
        if (a && a->depth > AST_MAX_DEPTH) {
            fail(ps, "expression nested too deeply");
            return NULL;
        }
    }
    return NULL;
}

static Expr *parse_mul(Parser *ps)
{
    static const char *const ops[] = {"*", "/"};
    static const OpKind kinds[] = {OP_MUL, OP_DIV};
    return parse_level(ps, parse_unary, ops, kinds, 2);
}

static Expr *parse_add(Parser *ps)
{
    static const char *const ops[] = {"+", "-"};
    static const OpKind kinds[] = {OP_ADD, OP_SUB};
    return parse_level(ps, parse_mul, ops, kinds, 2);
}

static Expr *parse_cmp(Parser *ps)
{
    static const char *const ops[] = {"<=", ">=", "==", "!=", "<", ">"};
    static const OpKind kinds[] = {OP_LE, OP_GE, OP_EQ, OP_NE, OP_LT, OP_GT};
    return parse_level(ps, parse_add, ops, kinds, 6);
}

static Expr *parse_and(Parser *ps)
{
    static const char *const ops[] = {"and"};
    static const OpKind kinds[] = {OP_AND};
    return parse_level(ps, parse_cmp, ops, kinds, 1);
}

static Expr *parse_or(Parser *ps)
{
    static const char *const ops[] = {"or"};
    static const OpKind kinds[] = {OP_OR};
    return parse_level(ps, parse_and, ops, kinds, 1);
}

Expr *xml_parse_expr(const char *text, SrcLoc loc, const char *what)
{
    Parser ps = {0};
    ps.text = text;
    ps.what = what;
    ps.loc = loc;
    ps.p = text;
    if (next(&ps))
        return NULL;
    if (ps.kind == T_END) {
        fail(&ps, "expected an expression");
        return NULL;
    }
    Expr *e = parse_or(&ps);
    if (e && ps.kind != T_END) {
        fail(&ps, is_op(&ps, ")") ? "unmatched ')'" : "expected an operator");
        return NULL;
    }
    return ps.failed ? NULL : e;
}

/* ------------------------------------------------------------------ evaluation */

static int index_of(const char *name, char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(names[i], name) == 0)
            return i;
    return -1;
}

/* Names and functions are known, skip does not appear; reports the first problem. */
static int check_const(const Expr *e, char *const *names, int n, const char *what)
{
    switch (e->kind) {
    case EX_NAME:
        if (index_of(e->name, names, n) >= 0)
            return 0;
        if (builtin_variable(e->name) >= 0)
            diag_error(e->loc, "%s: '%s' is a particle variable; a constant is needed here",
                       what, e->name);
        else
            diag_error(e->loc, "%s: unknown variable '%s'", what, e->name);
        return -1;
    case EX_SKIP:
        diag_error(e->loc, "%s: 'skip' cannot be used here; a constant is needed", what);
        return -1;
    case EX_CALL: {
        int arity = builtin_function_arity(e->name);
        if (arity < 0) {
            diag_error(e->loc, "%s: unknown function '%s'", what, e->name);
            return -1;
        }
        if (arity != e->nargs) {
            diag_error(e->loc, "%s: function '%s' takes %d argument%s, got %d", what, e->name,
                       arity, arity == 1 ? "" : "s", e->nargs);
            return -1;
        }
        break;
    }
    default:
        break;
    }
    for (int i = 0; i < e->nargs; i++)
        if (check_const(e->args[i], names, n, what))
            return -1;
    return 0;
}

int xml_eval(const Expr *e, char *const *names, const double *values, int n, const char *what,
             double *out)
{
    static const Model none;
    if (check_const(e, names, n, what))
        return -1;
    EvalEnv env = {(const char *const *)names, values, n, NULL, NULL};
    if (eval_expr(&none, e, &env, out) != EVAL_OK) {
        diag_error(e->loc, "%s: cannot evaluate the value", what);
        return -1;
    }
    return 0;
}

void xml_rename(Expr *e, const char *from, const char *to)
{
    if (e->kind == EX_NAME && strcmp(e->name, from) == 0)
        e->name = ast_strdup(to);
    for (int i = 0; i < e->nargs; i++)
        xml_rename(e->args[i], from, to);
}
