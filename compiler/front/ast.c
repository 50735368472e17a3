/* ast.c — construction of syntax-tree nodes and the growable lists.
 *
 * Nodes are allocated and never freed: the compiler is short-lived.  The push
 * helpers grow their arrays by one element per call, so they work on any array
 * of exactly n elements obtained from malloc/realloc (or NULL with n == 0). */
#include <stdlib.h>
#include <string.h>

#include "ast.h"
#include "util/diag.h"

void *ast_alloc(size_t size)
{
    void *p = calloc(1, size ? size : 1);
    if (!p) {
        diag_fatal_noloc("out of memory");
        exit(1);
    }
    return p;
}

static void *ast_grow(void *arr, size_t n, size_t elem)
{
    void *p = realloc(arr, (n + 1) * elem);
    if (!p) {
        diag_fatal_noloc("out of memory");
        exit(1);
    }
    return p;
}

void *ast_room(void *arr, size_t count, size_t elem)
{
    if (arr && count > 0 && (count & (count - 1)) != 0)
        return arr; /* room left from the last doubling */
    void *p = realloc(arr, (count ? 2 * count : 1) * elem);
    if (!p) {
        diag_fatal_noloc("out of memory");
        exit(1);
    }
    return p;
}

char *ast_strdup(const char *s)
{
    if (!s)
        return NULL;
    size_t len = strlen(s) + 1;
    char *d = ast_alloc(len);
    memcpy(d, s, len);
    return d;
}

/* ---------------------------------------------------------------- expressions */

static Expr *ast_expr(ExprKind kind, SrcLoc loc)
{
    Expr *e = ast_alloc(sizeof *e);
    e->kind = kind;
    e->loc = loc;
    e->depth = 1;
    return e;
}

/* Sets e->depth from its arguments; returns e. */
static Expr *ast_deepen(Expr *e)
{
    for (int i = 0; i < e->nargs; i++)
        if (e->args[i] && e->args[i]->depth >= e->depth)
            e->depth = e->args[i]->depth + 1;
    return e;
}

Expr *ast_num(SrcLoc loc, double v)
{
    Expr *e = ast_expr(EX_NUM, loc);
    e->num = v;
    return e;
}

Expr *ast_name(SrcLoc loc, const char *name)
{
    Expr *e = ast_expr(EX_NAME, loc);
    e->name = ast_strdup(name);
    return e;
}

Expr *ast_unary(SrcLoc loc, OpKind op, Expr *a)
{
    Expr *e = ast_expr(EX_UNARY, loc);
    e->op = op;
    ast_push_expr(&e->args, &e->nargs, a);
    return ast_deepen(e);
}

Expr *ast_binary(SrcLoc loc, OpKind op, Expr *a, Expr *b)
{
    Expr *e = ast_expr(EX_BINARY, loc);
    e->op = op;
    ast_push_expr(&e->args, &e->nargs, a);
    ast_push_expr(&e->args, &e->nargs, b);
    return ast_deepen(e);
}

/* Takes ownership of args (an array of nargs elements, or NULL). */
Expr *ast_call(SrcLoc loc, const char *name, Expr **args, int nargs)
{
    Expr *e = ast_expr(EX_CALL, loc);
    e->name = ast_strdup(name);
    e->args = args;
    e->nargs = nargs;
    return ast_deepen(e);
}

/* Takes ownership of args. */
Expr *ast_vec(SrcLoc loc, Expr **args, int nargs)
{
    Expr *e = ast_expr(EX_VEC, loc);
    e->args = args;
    e->nargs = nargs;
    return ast_deepen(e);
}

Expr *ast_skip(SrcLoc loc)
{
    return ast_expr(EX_SKIP, loc);
}

/* ---------------------------------------------------------------- lists */

void ast_push_expr(Expr ***arr, int *n, Expr *e)
{
    *arr = ast_grow(*arr, (size_t)*n, sizeof **arr);
    (*arr)[(*n)++] = e;
}

void ast_push_setting(SettingList *l, Setting s)
{
    l->items = ast_grow(l->items, (size_t)l->n, sizeof *l->items);
    l->items[l->n++] = s;
}

const Setting *ast_find_setting(const SettingList *l, const char *key)
{
    for (int i = 0; i < l->n; i++)
        if (!strcmp(l->items[i].key, key))
            return &l->items[i];
    return NULL;
}

void ast_push_matstmt(MatStmtList *l, MatStmt s)
{
    l->items = ast_grow(l->items, (size_t)l->n, sizeof *l->items);
    l->items[l->n++] = s;
}

void ast_push_bodyitem(BodyDecl *b, BodyItem it)
{
    b->items = ast_grow(b->items, (size_t)b->n, sizeof *b->items);
    b->items[b->n++] = it;
}

void ast_push_item(Program *p, Item it)
{
    p->items = ast_grow(p->items, (size_t)p->n, sizeof *p->items);
    p->items[p->n++] = it;
}

/* locs may be NULL when no locations are kept (fn parameters). */
void ast_push_name(char ***arr, SrcLoc **locs, int *n, const char *name, SrcLoc loc)
{
    *arr = ast_grow(*arr, (size_t)*n, sizeof **arr);
    (*arr)[*n] = ast_strdup(name);
    if (locs) {
        *locs = ast_grow(*locs, (size_t)*n, sizeof **locs);
        (*locs)[*n] = loc;
    }
    (*n)++;
}

/* ---------------------------------------------------------------- other nodes */

Setting ast_setting(SrcLoc loc, const char *key, Expr *value)
{
    Setting s = { 0 };
    s.key = ast_strdup(key);
    s.loc = loc;
    if (value)
        ast_push_expr(&s.values, &s.nvalues, value);
    return s;
}

Setting ast_setting_text(SrcLoc loc, const char *key, const char *text)
{
    Setting s = ast_setting(loc, key, NULL);
    s.text = ast_strdup(text);
    return s;
}

ShapeExpr *ast_shape_prim(NamedCall call)
{
    ShapeExpr *s = ast_alloc(sizeof *s);
    s->op = 0;
    s->loc = call.loc;
    s->prim = call;
    s->depth = 1;
    return s;
}

ShapeExpr *ast_shape_op(SrcLoc loc, char op, ShapeExpr *lhs, ShapeExpr *rhs)
{
    ShapeExpr *s = ast_alloc(sizeof *s);
    s->op = op;
    s->loc = loc;
    s->lhs = lhs;
    s->rhs = rhs;
    int dl = lhs ? lhs->depth : 0, dr = rhs ? rhs->depth : 0;
    s->depth = 1 + (dl > dr ? dl : dr);
    return s;
}

MatStmt ast_matstmt(MatStmtKind kind, SrcLoc loc, const char *name, Expr *value)
{
    MatStmt m = { 0 };
    m.kind = kind;
    m.loc = loc;
    m.name = ast_strdup(name);
    m.value = value;
    m.depth = 1;
    return m;
}

int ast_axis_bit(const char *name)
{
    if (strcmp(name, "x") == 0)
        return 1;
    if (strcmp(name, "y") == 0)
        return 2;
    if (strcmp(name, "z") == 0)
        return 4;
    return 0;
}

const char *op_spelling(OpKind op)
{
    switch (op) {
    case OP_ADD: return "+";
    case OP_SUB: return "-";
    case OP_MUL: return "*";
    case OP_DIV: return "/";
    case OP_POW: return "^";
    case OP_LT:  return "<";
    case OP_GT:  return ">";
    case OP_LE:  return "<=";
    case OP_GE:  return ">=";
    case OP_EQ:  return "==";
    case OP_NE:  return "!=";
    case OP_AND: return "and";
    case OP_OR:  return "or";
    case OP_NEG: return "-";
    case OP_NOT: return "not";
    }
    return "?";
}
