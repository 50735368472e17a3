/* scalar.c — building and folding the scalar expression graph, and its passes over the
 * nodes some roots need. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scalar.h"
#include "spectral.h"
#include "lang/arith.h"
#include "lang/builtins.h"

void sg_init(SGraph *g)
{
    memset(g, 0, sizeof *g);
    g->tcap = 1024;
    g->table = malloc((size_t)g->tcap * sizeof(int));
    memset(g->table, -1, (size_t)g->tcap * sizeof(int));
}

void sg_free(SGraph *g)
{
    free(g->nodes);
    free(g->table);
    memset(g, 0, sizeof *g);
}

/* ------------------------------------------------------------------ hash-consing */

static unsigned hash_node(const SNode *s)
{
    unsigned h = (unsigned)s->op * 2654435761u;
    h ^= (unsigned)(s->a + 7) * 40503u + (unsigned)(s->b + 11) * 97u + (unsigned)(s->c + 13);
    unsigned long long bits;
    memcpy(&bits, &s->v, sizeof bits);
    h ^= (unsigned)(bits ^ (bits >> 32));
    h = h * 31u + (unsigned)s->fn;
    if (s->name)
        for (const char *p = s->name; *p; p++)
            h = h * 31u + (unsigned char)*p;
    for (int k = 0; k < s->nargs; k++)
        h = h * 131u + (unsigned)(s->args[k] + 17);
    return h;
}

static int same_node(const SNode *x, const SNode *y)
{
    if (x->op != y->op || x->a != y->a || x->b != y->b || x->c != y->c || x->fn != y->fn)
        return 0;
    if (memcmp(&x->v, &y->v, sizeof x->v) != 0)
        return 0;
    if (x->nargs != y->nargs || memcmp(x->args, y->args, (size_t)x->nargs * sizeof(int)))
        return 0;
    return (!x->name && !y->name) || (x->name && y->name && !strcmp(x->name, y->name));
}

static void grow_table(SGraph *g)
{
    free(g->table);
    g->tcap *= 2;
    g->table = malloc((size_t)g->tcap * sizeof(int));
    memset(g->table, -1, (size_t)g->tcap * sizeof(int));
    for (int id = 0; id < g->n; id++) {
        unsigned h = hash_node(&g->nodes[id]) & (unsigned)(g->tcap - 1);
        while (g->table[h] >= 0)
            h = (h + 1) & (unsigned)(g->tcap - 1);
        g->table[h] = id;
    }
}

static int intern(SGraph *g, SNode s)
{
    s.line = g->line;
    s.file = g->file;
    unsigned h = hash_node(&s) & (unsigned)(g->tcap - 1);
    while (g->table[h] >= 0) {
        if (same_node(&g->nodes[g->table[h]], &s))
            return g->table[h];
        h = (h + 1) & (unsigned)(g->tcap - 1);
    }
    if (g->n == g->cap) {
        g->cap = g->cap ? 2 * g->cap : 256;
        g->nodes = realloc(g->nodes, (size_t)g->cap * sizeof *g->nodes);
    }
    g->nodes[g->n] = s;
    g->table[h] = g->n;
    if (2 * (g->n + 1) > g->tcap) {
        g->n++;
        grow_table(g);
        return g->n - 1;
    }
    return g->n++;
}

static SNode node(SnOp op, int a, int b, int c)
{
    SNode s = {.op = op, .a = a, .b = b, .c = c};
    return s;
}

int sg_const(SGraph *g, double v)
{
    if (v == 0.0)
        v = 0.0; /* one zero: -0.0 folds to +0.0 */
    SNode s = node(SN_CONST, -1, -1, -1);
    s.v = v;
    return intern(g, s);
}

int sg_input(SGraph *g, const char *name, int index)
{
    SNode s = node(SN_INPUT, -1, -1, -1);
    s.name = name;
    s.v = index < 0 ? -1 : index;
    return intern(g, s);
}

int sg_param(SGraph *g, int index)
{
    SNode s = node(SN_PARAM, -1, -1, -1);
    s.v = index;
    return intern(g, s);
}

int sg_is_const(const SGraph *g, int id, double *v)
{
    if (g->nodes[id].op != SN_CONST)
        return 0;
    if (v)
        *v = g->nodes[id].v;
    return 1;
}

/* ------------------------------------------------------------------ folding */

/* The graph's operators in the folding arithmetic (the interpreter's, check/eval.c). */
static const ArithOp ARITH[] = {
    [SN_ADD] = AR_ADD, [SN_SUB] = AR_SUB, [SN_MUL] = AR_MUL, [SN_DIV] = AR_DIV,
    [SN_NEG] = AR_NEG, [SN_POW] = AR_POW, [SN_MIN] = AR_MIN, [SN_MAX] = AR_MAX,
    [SN_LT] = AR_LT,   [SN_LE] = AR_LE,   [SN_GT] = AR_GT,   [SN_GE] = AR_GE,
    [SN_EQ] = AR_EQ,   [SN_NE] = AR_NE,   [SN_AND] = AR_AND, [SN_OR] = AR_OR,
    [SN_NOT] = AR_NOT,
};

double sg_apply(SnOp op, double x, double y)
{
    return op == SN_NEG || op == SN_NOT ? arith_unary(ARITH[op], x) : arith_binary(ARITH[op], x, y);
}

static int commutative(SnOp op)
{
    return op == SN_ADD || op == SN_MUL || op == SN_MIN || op == SN_MAX || op == SN_EQ ||
           op == SN_NE || op == SN_AND || op == SN_OR;
}

/* Whether v is a power of two, 2^e with a normal result: multiplying by it is exact (the
 * exponent moves, the significand stays), unless the product leaves the normal range. */
static int power_of_two(double v)
{
    int e;
    return isnormal(v) && fabs(frexp(v, &e)) == 0.5;
}

/* k * (c * z) as (k c) * z where that is the same number to the last bit: one of k, c a
 * power of two and k c a normal number (the derivative's chains of factors, 0.5 * (2 * x),
 * fold away).  Returns a node id or -1. */
static int fold_factors(SGraph *g, double k, int m)
{
    const SNode *n = &g->nodes[m];
    double c;
    if (n->op != SN_MUL)
        return -1;
    int z = n->b;
    if (!sg_is_const(g, n->a, &c)) {
        if (!sg_is_const(g, n->b, &c))
            return -1;
        z = n->a;
    }
    const double kc = k * c;
    if (!(power_of_two(k) || power_of_two(c)) || !(isnormal(kc) || kc == 0.0))
        return -1;
    return sg_binary(g, SN_MUL, sg_const(g, kc), z);
}

/* Algebraic identities with one constant operand; returns a node id or -1. */
static int fold_identity(SGraph *g, SnOp op, int a, int b)
{
    double x = 0, y = 0;
    int ca = sg_is_const(g, a, &x), cb = sg_is_const(g, b, &y);
    switch (op) {
    case SN_ADD:
        if (ca && x == 0.0) return b;
        if (cb && y == 0.0) return a;
        if (a == b) return sg_binary(g, SN_MUL, sg_const(g, 2.0), a); /* (exact) */
        break;
    case SN_SUB:
        if (cb && y == 0.0) return a;
        if (ca && x == 0.0) return sg_unary(g, SN_NEG, b);
        if (a == b) return sg_const(g, 0.0);
        break;
    case SN_MUL:
        if ((ca && x == 0.0) || (cb && y == 0.0)) return sg_const(g, 0.0);
        if (ca && x == 1.0) return b;
        if (cb && y == 1.0) return a;
        if (ca && x == -1.0) return sg_unary(g, SN_NEG, b);
        if (cb && y == -1.0) return sg_unary(g, SN_NEG, a);
        if (ca) return fold_factors(g, x, b);
        if (cb) return fold_factors(g, y, a);
        break;
    case SN_DIV:
        if (cb && y == 1.0) return a;
        if (ca && x == 0.0) return sg_const(g, 0.0);
        if (cb && y != 0.0) return sg_binary(g, SN_MUL, a, sg_const(g, 1.0 / y));
        break;
    case SN_POW:
        if (cb && y == 1.0) return a;
        if (cb && y == 0.0) return sg_const(g, 1.0);
        if (cb && y == 2.0) return sg_binary(g, SN_MUL, a, a);
        if (cb && y == 0.5) return sg_call(g, BI_sqrt, a);
        break;
    default:
        break;
    }
    return -1;
}

int sg_binary(SGraph *g, SnOp op, int a, int b)
{
    double x, y;
    if (sg_is_const(g, a, &x) && sg_is_const(g, b, &y))
        return sg_const(g, arith_binary(ARITH[op], x, y));
    int f = fold_identity(g, op, a, b);
    if (f >= 0)
        return f;
    if (commutative(op) && a > b) {
        int t = a;
        a = b;
        b = t;
    }
    if ((op == SN_MIN || op == SN_MAX) && a == b)
        return a;
    return intern(g, node(op, a, b, -1));
}

int sg_unary(SGraph *g, SnOp op, int a)
{
    double x;
    if (sg_is_const(g, a, &x))
        return sg_const(g, arith_unary(ARITH[op], x));
    if (op == SN_NEG && g->nodes[a].op == SN_NEG)
        return g->nodes[a].a;
    return intern(g, node(op, a, -1, -1));
}

/* A constant argument folds by the interpreter's value of the built-in, unless that is
 * NaN (sqrt of a negative constant stays a call in the generated code). */
int sg_call(SGraph *g, int fn, int a)
{
    double x;
    if (sg_is_const(g, a, &x)) {
        double r = builtin_value(fn, &x);
        if (!isnan(r))
            return sg_const(g, r);
    }
    SNode s = node(SN_CALL, a, -1, -1);
    s.fn = fn;
    return intern(g, s);
}

int sg_select(SGraph *g, int c, int a, int b)
{
    double x;
    if (sg_is_const(g, c, &x))
        return x != 0.0 ? a : b;
    if (a == b)
        return a;
    return intern(g, node(SN_SELECT, c, a, b));
}

int sg_ext(SGraph *g, const char *fn, const int *args, int nargs, int nout)
{
    SNode s = node(SN_EXT, -1, nout, -1);
    s.name = fn;
    s.nargs = nargs;
    memcpy(s.args, args, (size_t)nargs * sizeof(int));
    return intern(g, s);
}

/* Whether node id is the constant 0. */
static int is_zero(const SGraph *g, int id)
{
    double v;
    return sg_is_const(g, id, &v) && v == 0.0;
}

/* Whether the 3x3 tensor args[0 .. 8] has the plane-strain structure: no y coupling, and (yy)
 * 0 unless any_yy. */
static int plane(const SGraph *g, const int *args, int any_yy)
{
    return is_zero(g, args[1]) && is_zero(g, args[3]) && is_zero(g, args[5]) &&
           is_zero(g, args[7]) && (any_yy || is_zero(g, args[4]));
}

/* Output k of routine ext folded where its arguments allow: the 3D positive part (and its
 * adjoint) of a plane-strain tensor (no y coupling, yy zero) is the 2D closed form's, with
 * zeros in the y row and column.  Returns the node, or -1 (sg_part keeps the part). */
static int fold_spectral_part(SGraph *g, int ext, int k)
{
    const SNode s = g->nodes[ext]; /* a copy: g grows */
    const int pos = s.nargs == 9 && !strcmp(s.name, SPECTRAL_POS3);
    const int adj = s.nargs == 18 && !strcmp(s.name, SPECTRAL_POS3_ADJOINT);
    if (!(pos || adj) || !plane(g, s.args, 0) || (adj && !plane(g, s.args + 9, 1)))
        return -1;
    /* y is an eigenvector of eigenvalue 0: pos_yy = 0, and the adjoint's y row and column
     * are 0 (Gamma(0, 0) = f'(0) = 0, eq. 13-16 differentiated) */
    if (k != 0 && k != 2 && k != 6 && k != 8)
        return sg_const(g, 0.0);
    const int out = k == 0 ? 0 : k == 8 ? 2 : 1;
    if (pos) {
        const int args[3] = {s.args[0], s.args[2], s.args[8]};
        return sg_part(g, sg_ext(g, SPECTRAL_POS2, args, 3, 3), out);
    }
    /* the adjoint of pos2's xz output is that of pos3's (x, z) and (z, x) outputs together;
     * its xz adjoint stands for both entries: half each */
    const int b_xz = sg_binary(g, SN_ADD, s.args[9 + 2], s.args[9 + 6]);
    const int args[6] = {s.args[0], s.args[2], s.args[8], s.args[9], b_xz, s.args[9 + 8]};
    const int part = sg_part(g, sg_ext(g, SPECTRAL_POS2_ADJOINT, args, 6, 3), out);
    return out == 1 ? sg_binary(g, SN_MUL, sg_const(g, 0.5), part) : part;
}

int sg_part(SGraph *g, int ext, int k)
{
    const int folded = fold_spectral_part(g, ext, k); /* pos of a plane-strain tensor */
    if (folded >= 0)
        return folded;
    SNode s = node(SN_PART, ext, -1, -1);
    s.v = k;
    return intern(g, s);
}

/* ------------------------------------------------------------------ passes */

/* A node's operands were made before it (smaller ids), so one sweep from the last node down
 * marks them all, without recursion however deep the graph. */
void sg_mark_live(const SGraph *g, const int *roots, int nroots, char *live)
{
    for (int k = 0; k < nroots; k++)
        if (roots[k] >= 0)
            live[roots[k]] = 1;
    for (int id = g->n - 1; id >= 0; id--) {
        const SNode *s = &g->nodes[id];
        if (!live[id])
            continue;
        if (s->op == SN_EXT) {
            for (int k = 0; k < s->nargs; k++)
                live[s->args[k]] = 1;
            continue;
        }
        const int ops[3] = {s->a, s->b, s->c};
        for (int k = 0; k < 3; k++)
            if (ops[k] >= 0)
                live[ops[k]] = 1;
    }
}

int sg_input_reached(const SGraph *g, int root, const int *held, int nheld, const char *name)
{
    char *live = calloc((size_t)g->n + 1, 1), *stop = calloc((size_t)g->n + 1, 1);
    for (int k = 0; k < nheld; k++)
        if (held[k] >= 0)
            stop[held[k]] = 1;
    int found = -1;
    if (root >= 0)
        live[root] = 1;
    for (int id = root; id >= 0 && found < 0; id--) {
        const SNode *s = &g->nodes[id];
        if (!live[id] || stop[id])
            continue;
        if (s->op == SN_INPUT && !strcmp(s->name, name))
            found = id;
        for (int k = 0; s->op == SN_EXT && k < s->nargs; k++)
            live[s->args[k]] = 1;
        const int ops[3] = {s->a, s->b, s->c};
        for (int k = 0; s->op != SN_EXT && k < 3; k++)
            if (ops[k] >= 0)
                live[ops[k]] = 1;
    }
    free(live), free(stop);
    return found;
}

int sg_operations(const SGraph *g, const int *roots, int nroots)
{
    char *live = calloc((size_t)g->n + 1, 1);
    sg_mark_live(g, roots, nroots, live);
    int ops = 0;
    for (int id = 0; id < g->n; id++)
        ops += live[id] && g->nodes[id].op > SN_PARAM && g->nodes[id].op != SN_PART;
    free(live);
    return ops;
}

/* The roots rebuilt into out: replace(id, node, ctx) gives a node that replaces node id, or
 * -1 to rebuild it from its rebuilt operands (sg_substitute, sg_replace). */
static void rebuild(SGraph *g, const int *roots, int nroots,
                    int (*replace)(int, const SNode *, void *), void *ctx, int *out)
{
    const int n = g->n;
    char *live = calloc((size_t)n + 1, 1);
    int *map = malloc((size_t)(n + 1) * sizeof *map);
    sg_mark_live(g, roots, nroots, live);
    const int line = g->line;
    const char *file = g->file;
    for (int id = 0; id < n; id++) {
        if (!live[id])
            continue;
        const SNode s = g->nodes[id]; /* a copy: the graph grows */
        const int a = s.a >= 0 && s.op != SN_EXT ? map[s.a] : s.a, b = s.b >= 0 && s.op != SN_EXT ? map[s.b] : s.b;
        g->line = s.line, g->file = s.file; /* the rebuilt node keeps its model line */
        int r = replace(id, &s, ctx);
        if (r >= 0) {
            map[id] = r;
            continue;
        }
        r = id;
        switch (s.op) {
        case SN_INPUT:
        case SN_CONST:
        case SN_PARAM: break;
        case SN_NEG:
        case SN_NOT: r = sg_unary(g, s.op, a); break;
        case SN_CALL: r = sg_call(g, s.fn, a); break;
        case SN_SELECT: r = sg_select(g, a, b, map[s.c]); break;
        case SN_EXT: {
            int args[SG_MAX_ARGS];
            for (int k = 0; k < s.nargs; k++)
                args[k] = map[s.args[k]];
            r = sg_ext(g, s.name, args, s.nargs, s.b);
            break;
        }
        case SN_PART: r = sg_part(g, a, (int)s.v); break;
        default: r = sg_binary(g, s.op, a, b); break;
        }
        map[id] = r;
    }
    for (int k = 0; k < nroots; k++)
        out[k] = roots[k] >= 0 ? map[roots[k]] : roots[k];
    g->line = line, g->file = file;
    free(map);
    free(live);
}

typedef struct {
    int (*input)(const SNode *, void *);
    void *ctx;
} InputCtx;

static int replace_input(int id, const SNode *s, void *ctx)
{
    const InputCtx *c = ctx;
    (void)id;
    return s->op == SN_INPUT ? c->input(s, c->ctx) : -1;
}

int sg_substitute(SGraph *g, const int *roots, int nroots, int (*input)(const SNode *, void *),
                  void *ctx, int *out)
{
    InputCtx c = {input, ctx};
    rebuild(g, roots, nroots, replace_input, &c, out);
    return 0;
}

typedef struct {
    const int *from, *to;
    int n;
} ReplaceCtx;

static int replace_listed(int id, const SNode *s, void *ctx)
{
    const ReplaceCtx *c = ctx;
    (void)s;
    for (int k = 0; k < c->n; k++)
        if (c->from[k] == id)
            return c->to[k];
    return -1;
}

void sg_replace(SGraph *g, const int *roots, int nroots, const int *from, const int *to, int n,
                int *out)
{
    ReplaceCtx c = {from, to, n};
    rebuild(g, roots, nroots, replace_listed, &c, out);
}

int sg_first_nonfinite(const SGraph *g, const int *roots, int nroots)
{
    char *live = calloc((size_t)g->n + 1, 1);
    sg_mark_live(g, roots, nroots, live);
    int found = -1;
    for (int id = 0; id < g->n && found < 0; id++)
        if (live[id] && g->nodes[id].op == SN_CONST && !isfinite(g->nodes[id].v))
            found = id;
    free(live);
    return found;
}
