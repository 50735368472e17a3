/* scalar.h — the scalar expression graph (kernel IR for per-particle math).
 *
 * Material laws are evaluated symbolically into this graph: every tensor becomes nine
 * scalar nodes.  Nodes are hash-consed (common subexpressions are shared) and folded as they
 * are built (constants, x*0, x*1, x+0, known plane-strain zeros), so the emitted C holds
 * only the arithmetic a given body needs.  The graph is printed as C by lower/graph_print.c. */
#ifndef SPHC_SCALAR_H
#define SPHC_SCALAR_H

typedef enum {
    SN_CONST,  /* v */
    SN_INPUT,  /* name[(int)v], or name when v < 0: an input of the emitted function */
    SN_PARAM,  /* law parameter (int)v, symbolic (checking only) */
    SN_ADD, SN_SUB, SN_MUL, SN_DIV, SN_NEG, SN_POW, SN_MIN, SN_MAX,
    SN_LT, SN_LE, SN_GT, SN_GE, SN_EQ, SN_NE, SN_AND, SN_OR, SN_NOT,
    SN_CALL,   /* a built-in function of a: sqrt, log10, ... */
    SN_SELECT, /* a ? b : c */
    SN_EXT,    /* name(args..., out): a runtime routine with b outputs (sph_sym_pos3, ...) */
    SN_PART    /* output (int)v of the SN_EXT node a */
} SnOp;

/* The most operands of a runtime routine: a tensor and an adjoint (spectral.h). */
#define SG_MAX_ARGS 18

typedef struct {
    SnOp op;
    int a, b, c;        /* operands (node ids), -1 when unused */
    double v;           /* SN_CONST value, SN_INPUT / SN_PARAM / SN_PART index */
    const char *name;   /* SN_INPUT: its array; SN_EXT: the routine (static strings) */
    int fn;             /* SN_CALL: the built-in (BuiltinId, lang/builtins.h) */
    int args[SG_MAX_ARGS]; /* SN_EXT operands */
    int nargs;
    int line;           /* model line of the statement that created it */
    const char *file;
} SNode;

typedef struct {
    SNode *nodes;
    int n, cap;
    int *table;         /* hash table of node ids, -1 empty */
    int tcap;
    int line;           /* current statement, stamped on new nodes */
    const char *file;
} SGraph;

void sg_init(SGraph *g);
void sg_free(SGraph *g);

int sg_const(SGraph *g, double v);
int sg_input(SGraph *g, const char *name, int index); /* name[index]; name when index < 0 */
int sg_param(SGraph *g, int index);
int sg_binary(SGraph *g, SnOp op, int a, int b);
int sg_unary(SGraph *g, SnOp op, int a);         /* SN_NEG, SN_NOT */
int sg_call(SGraph *g, int fn, int a);           /* fn: a BF_CALL built-in, BI_sqrt, ... */
int sg_select(SGraph *g, int c, int a, int b);
/* A call of a runtime routine with nargs scalar inputs and nout outputs; its outputs are
 * sg_part(g, ext, k).  Emitted as `double tN[nout]; fn(a0, ..., tN);` (inputs passed as
 * one array when there are more than four).  sg_part folds a spectral routine of a
 * plane-strain tensor to its 2D closed form (spectral.h). */
int sg_ext(SGraph *g, const char *fn, const int *args, int nargs, int nout);
int sg_part(SGraph *g, int ext, int k);

int sg_is_const(const SGraph *g, int id, double *v);
/* The value of arithmetic node op for operand values x (and y): the folding arithmetic. */
double sg_apply(SnOp op, double x, double y);

/* The values of nodes 0 .. upto (into val[0 .. upto]): an input is input(name, index, ctx),
 * a law parameter params[index] (NaN without params), a runtime routine's outputs by the
 * routine itself (spectral.h; NaN for one the compiler does not know).  A reference
 * interpreter of the graph (scalar_eval.c). */
typedef double (*SgInput)(const char *name, int index, void *ctx);
void sg_eval(const SGraph *g, int upto, SgInput input, void *ctx, const double *params,
             double *val);

/* Marks in live[0 .. g->n - 1] (zeroed by the caller) the nodes that roots[0 .. nroots-1]
 * need (a root < 0 needs none): the nodes a printer of the graph writes. */
void sg_mark_live(const SGraph *g, const int *roots, int nroots, char *live);
/* An input node named `name` that root needs along a path that does not pass through the
 * nodes held[0 .. nheld-1], or -1 when it needs none so (a law's energy that reads the rate
 * of its update other than through its state's end values). */
int sg_input_reached(const SGraph *g, int root, const int *held, int nheld, const char *name);
/* The operations computing roots[0 .. nroots-1] takes: the nodes they reach, less constants,
 * inputs, parameters and a runtime routine's outputs (its call counts once). */
int sg_operations(const SGraph *g, const int *roots, int nroots);
/* The roots rebuilt (into out) with some inputs replaced: input(node) gives the node that
 * replaces an input, or -1 to keep it.  The rebuilt nodes are folded again (a constant
 * put for an input folds away what it zeroes); the old ones stay, dead. */
int sg_substitute(SGraph *g, const int *roots, int nroots, int (*input)(const SNode *, void *),
                  void *ctx, int *out);

/* The roots rebuilt (into out) with nodes from[k] replaced by nodes to[k] (k < n), folded
 * again: a constant put for a condition folds its selects to one side. */
void sg_replace(SGraph *g, const int *roots, int nroots, const int *from, const int *to, int n,
                int *out);

/* Reverse-mode derivatives of node y with respect to nodes x[0 .. n-1] (inputs, usually),
 * built into the graph (so folded and shared as any node) into dydx: the derivative of the
 * branch taken for select, min, max and abs, 0 for comparisons; through a spectral routine
 * (pos, SN_EXT) by its adjoint routine (spectral.h).  Returns 0, or -1 when y depends on a
 * node the rules do not cover (another runtime routine, an adjoint routine itself).
 * derivative.c. */
int sg_derivatives(SGraph *g, int y, const int *x, int n, int *dydx);
/* The same with nodes held[0 .. nheld-1] held fixed: taken as independent of x (a path from
 * y to x through a held node adds nothing), as if each were a fresh input put back after
 * the derivative.  A law's energy differentiated at its returned state: the state's end
 * values held. */
int sg_derivatives_held(SGraph *g, int y, const int *x, int n, const int *held, int nheld,
                        int *dydx);

/* The first constant the roots need that is not finite (a division by zero folded, ...),
 * or -1. */
int sg_first_nonfinite(const SGraph *g, const int *roots, int nroots);

#endif
