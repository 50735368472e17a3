/* derivative.c — symbolic derivatives in the scalar graph, by reverse accumulation.
 *
 * The adjoint of node y is 1; going down the nodes (an operand is always older than its
 * node, so descending ids are a reverse topological order), each node with an adjoint adds
 * its share to its operands' by the chain rule.  The adjoints are graph nodes, built with
 * the same folding and hash-consing as the law itself: x * 0 vanishes, a factor shared by
 * several entries is computed once.  A runtime routine (SN_EXT, pos of eq. 13-16) has
 * several outputs, its parts (SN_PART, newer than it): their adjoints are gathered when the
 * descent reaches the routine, and its rule gives its arguments' at once: the parts of its
 * adjoint routine (spectral.h), one more SN_EXT node. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lang/builtins.h"
#include "scalar.h"
#include "spectral.h"

static int add(SGraph *g, int a, int b) { return sg_binary(g, SN_ADD, a, b); }
static int mul(SGraph *g, int a, int b) { return sg_binary(g, SN_MUL, a, b); }
static int divide(SGraph *g, int a, int b) { return sg_binary(g, SN_DIV, a, b); }
static int num(SGraph *g, double v) { return sg_const(g, v); }

/* adj[k] += term */
static void accumulate(SGraph *g, int *adj, int k, int term)
{
    adj[k] = adj[k] < 0 ? term : add(g, adj[k], term);
}

/* d f(x) / dx of built-in f at x, whose value is node fx, by the rule in f's row of
 * BUILTIN_FUNCTIONS (lang/builtins.h), written with these builders; -1 for a function
 * without a rule. */
static int call_rule(SGraph *g, int fn, int x, int fx)
{
#define call(f, arg) sg_call(g, BI_##f, arg)
#define neg(v) sg_unary(g, SN_NEG, v)
#define add(p, q) add(g, p, q)
#define sub(p, q) sg_binary(g, SN_SUB, p, q)
#define mul(p, q) mul(g, p, q)
#define divide(p, q) divide(g, p, q)
#define num(v) num(g, v)
#define select(c, p, q) sg_select(g, c, p, q)
#define lt(p, q) sg_binary(g, SN_LT, p, q)
#define NONE -1
    switch (fn) {
#define X(name, arity, form, c, value, derivative) case BI_##name: return derivative;
        BUILTIN_FUNCTIONS(X)
#undef X
    }
    return -1;
#undef call
#undef neg
#undef add
#undef sub
#undef mul
#undef divide
#undef num
#undef select
#undef lt
#undef NONE
}

/* The shares of node s (value: node id) with adjoint d, added to its operands'. */
static int propagate(SGraph *g, SNode s, int id, int d, int *adj)
{
    const int zero = num(g, 0);
    switch (s.op) {
    case SN_ADD:
        accumulate(g, adj, s.a, d), accumulate(g, adj, s.b, d);
        return 0;
    case SN_SUB:
        accumulate(g, adj, s.a, d), accumulate(g, adj, s.b, sg_unary(g, SN_NEG, d));
        return 0;
    case SN_MUL:
        accumulate(g, adj, s.a, mul(g, d, s.b)), accumulate(g, adj, s.b, mul(g, d, s.a));
        return 0;
    case SN_DIV: /* d(a/b) = da / b - (a/b) db / b */
        accumulate(g, adj, s.a, divide(g, d, s.b));
        accumulate(g, adj, s.b, sg_unary(g, SN_NEG, divide(g, mul(g, d, id), s.b)));
        return 0;
    case SN_NEG:
        accumulate(g, adj, s.a, sg_unary(g, SN_NEG, d));
        return 0;
    case SN_POW: { /* d(a^b) = b a^(b-1) da + a^b ln(a) db */
        double e;
        const int bm1 = sg_binary(g, SN_SUB, s.b, num(g, 1));
        accumulate(g, adj, s.a, mul(g, d, mul(g, s.b, sg_binary(g, SN_POW, s.a, bm1))));
        if (!sg_is_const(g, s.b, &e))
            accumulate(g, adj, s.b, mul(g, d, mul(g, id, sg_call(g, BI_ln, s.a))));
        return 0;
    }
    case SN_MIN:
    case SN_MAX: { /* the branch taken: a where a <= b (min), a >= b (max) */
        const int takes_a = sg_binary(g, s.op == SN_MIN ? SN_LE : SN_GE, s.a, s.b);
        accumulate(g, adj, s.a, sg_select(g, takes_a, d, zero));
        accumulate(g, adj, s.b, sg_select(g, takes_a, zero, d));
        return 0;
    }
    case SN_SELECT:
        accumulate(g, adj, s.b, sg_select(g, s.a, d, zero));
        accumulate(g, adj, s.c, sg_select(g, s.a, zero, d));
        return 0;
    case SN_CALL: {
        const int r = call_rule(g, s.fn, s.a, id);
        if (r < 0)
            return -1;
        accumulate(g, adj, s.a, mul(g, d, r));
        return 0;
    }
    case SN_PART: /* gathered by its routine (routine_adjoint) */
        return 0;
    default: /* constants, inputs, parameters; comparisons and logic are flat */
        return 0;
    }
}

/* The rule of runtime routine ext: given the adjoints of its outputs (bar[k], a node, or -1
 * where output k has none), the adjoints of its arguments (into arg_bar[k]) as the parts of
 * its adjoint routine (spectral.h).  Returns 0, or -1 for a routine without one. */
static int ext_rule(SGraph *g, int ext, const int *bar, int *arg_bar)
{
    const SNode s = g->nodes[ext]; /* a copy: g grows */
    const char *adjoint = spectral_adjoint_of(s.name, s.nargs);
    if (!adjoint || s.nargs + s.b > SG_MAX_ARGS)
        return -1;
    int args[SG_MAX_ARGS], any = 0;
    memcpy(args, s.args, (size_t)s.nargs * sizeof(int));
    for (int q = 0; q < s.b; q++) {
        double v;
        args[s.nargs + q] = bar[q] >= 0 ? bar[q] : sg_const(g, 0.0);
        any |= !sg_is_const(g, args[s.nargs + q], &v) || v != 0.0;
    }
    if (!any) { /* no adjoint reaches the routine */
        for (int q = 0; q < s.nargs; q++)
            arg_bar[q] = sg_const(g, 0.0);
        return 0;
    }
    const int adj = sg_ext(g, adjoint, args, s.nargs + s.b, s.nargs);
    for (int q = 0; q < s.nargs; q++)
        arg_bar[q] = sg_part(g, adj, q);
    return 0;
}

/* The adjoint of runtime routine ext (its parts' adjoints, adj[] of the SN_PART nodes of ext
 * between ext and y that are not held) passed to its arguments.  Returns 0, or -1 for a
 * routine without a rule. */
static int routine_adjoint(SGraph *g, int ext, int y, const char *stop, int *adj)
{
    int bar[SG_MAX_ARGS], arg_bar[SG_MAX_ARGS], any = 0;
    const int nout = g->nodes[ext].b;
    for (int k = 0; k < nout && k < SG_MAX_ARGS; k++)
        bar[k] = -1;
    for (int id = ext + 1; id <= y; id++) {
        const SNode *p = &g->nodes[id];
        if (p->op == SN_PART && p->a == ext && adj[id] >= 0 && !stop[id])
            bar[(int)p->v] = adj[id], any = 1;
    }
    if (!any)
        return 0;
    if (ext_rule(g, ext, bar, arg_bar))
        return -1;
    const SNode s = g->nodes[ext]; /* a copy: g grew */
    for (int k = 0; k < s.nargs; k++)
        accumulate(g, adj, s.args[k], arg_bar[k]);
    return 0;
}

int sg_derivatives_held(SGraph *g, int y, const int *x, int n, const int *held, int nheld,
                        int *dydx)
{
    int *adj = malloc((size_t)(y + 1) * sizeof *adj);
    char *stop = calloc((size_t)y + 1, 1);
    for (int k = 0; k <= y; k++)
        adj[k] = -1;
    for (int k = 0; k < nheld; k++)
        if (held[k] >= 0 && held[k] <= y)
            stop[held[k]] = 1;
    adj[y] = num(g, 1);
    int bad = 0;
    for (int id = y; id >= 0 && !bad; id--) { /* a held node keeps its adjoint to itself */
        if (stop[id])
            continue;
        if (g->nodes[id].op == SN_EXT)
            bad = routine_adjoint(g, id, y, stop, adj) != 0;
        else if (adj[id] >= 0)
            bad = propagate(g, g->nodes[id], id, adj[id], adj) != 0; /* a copy: g grows */
    }
    for (int k = 0; k < n; k++)
        dydx[k] = x[k] <= y && adj[x[k]] >= 0 ? adj[x[k]] : num(g, 0);
    free(stop);
    free(adj);
    return bad ? -1 : 0;
}

int sg_derivatives(SGraph *g, int y, const int *x, int n, int *dydx)
{
    return sg_derivatives_held(g, y, x, n, NULL, 0, dydx);
}
