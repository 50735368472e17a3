/* graph_print.c — a law's scalar graph printed as C statements: the body of a generated
 * material function (emit/emit_law.c) and, with the outputs named as the dump names them,
 * the law in --dump=plan (plan_dump.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graph_print.h"
#include "lang/builtins.h"
#include "util/source.h"

static int is_leaf(const SNode *s)
{
    return s->op == SN_CONST || s->op == SN_INPUT || s->op == SN_PARAM;
}

/* A law printed in pieces (graph_print_pieces): the nodes of each piece in order, and the values
 * a piece reads from another (an earlier piece's, an input, one the function returns) kept in
 * the array v the pieces share, each at a place in v free from its first to its last use. */
typedef struct {
    int n;          /* pieces */
    int *piece;     /* per node: its piece, -1 for an input or a constant */
    int *slot;      /* per node: its place in v, -1 where no other piece reads it */
    int nslots;
    int cur;        /* the piece printed; n: the function after its pieces */
    int *ids, nids; /* the nodes the outputs need, by piece */
} Pieces;

/* Whether a reference to node id reads v: a value another piece computed, or in a piece, an
 * input the function copied in (after the pieces, an input is read where it is: its place in
 * v may hold another value by then). */
static int in_v(const SGraph *g, const Pieces *P, int id)
{
    if (!P || P->slot[id] < 0 || P->piece[id] == P->cur)
        return 0;
    return !is_leaf(&g->nodes[id]) || (P->cur >= 0 && P->cur < P->n);
}

static void print_ref(const SGraph *g, const Pieces *P, int id, FILE *out)
{
    const SNode *s = &g->nodes[id];
    if (in_v(g, P, id)) {
        fprintf(out, "v[%d]", P->slot[id]);
    } else if (s->op == SN_CONST) {
        if (s->v < 0)
            fprintf(out, "(%.17g)", s->v);
        else
            fprintf(out, "%.17g", s->v);
    } else if (s->op == SN_INPUT) {
        if (s->v < 0)
            fputs(s->name, out);
        else
            fprintf(out, "%s[%d]", s->name, (int)s->v);
    } else if (s->op == SN_PARAM) {
        fprintf(out, "p%d", (int)s->v);
    } else if (s->op == SN_PART) {
        fprintf(out, "t%d[%d]", s->a, (int)s->v);
    } else {
        fprintf(out, "t%d", id);
    }
}

/* A function's argument: constants written as doubles (2.0, not 2), so that C++ (the CUDA
 * target) picks the double overload of fmax, pow, ... on the device too. */
static void arg_ref(const SGraph *g, const Pieces *P, int id, FILE *out)
{
    const SNode *s = &g->nodes[id];
    if (s->op != SN_CONST || s->v != floor(s->v) || fabs(s->v) >= 1e15) {
        print_ref(g, P, id, out);
        return;
    }
    if (s->v < 0)
        fprintf(out, "(%.17g.0)", s->v);
    else
        fprintf(out, "%.17g.0", s->v);
}

static const char *infix(SnOp op)
{
    static const char *const ops[] = {
        [SN_ADD] = "+", [SN_SUB] = "-", [SN_MUL] = "*", [SN_DIV] = "/", [SN_LT] = "<",
        [SN_LE] = "<=", [SN_GT] = ">", [SN_GE] = ">=", [SN_EQ] = "==", [SN_NE] = "!=",
        [SN_AND] = "&&", [SN_OR] = "||",
    };
    return (size_t)op < sizeof ops / sizeof ops[0] ? ops[op] : NULL;
}

static void print_node(const SGraph *g, const Pieces *P, int id, FILE *out)
{
    const SNode *s = &g->nodes[id];
    const char *op = infix(s->op);
    if (op) {
        print_ref(g, P, s->a, out);
        fprintf(out, " %s ", op);
        print_ref(g, P, s->b, out);
        return;
    }
    switch (s->op) {
    case SN_NEG: fputs("-", out); print_ref(g, P, s->a, out); return;
    case SN_NOT: fputs("!", out); print_ref(g, P, s->a, out); return;
    case SN_POW: fputs("pow(", out); break;
    case SN_MIN: fputs("sph_min(", out); break;
    case SN_MAX: fputs("sph_max(", out); break;
    case SN_CALL:
        fprintf(out, "%s(", BUILTIN_FUNCTION[s->fn].c);
        arg_ref(g, P, s->a, out);
        fputs(")", out);
        return;
    case SN_SELECT:
        print_ref(g, P, s->a, out);
        fputs(" ? ", out);
        print_ref(g, P, s->b, out);
        fputs(" : ", out);
        print_ref(g, P, s->c, out);
        return;
    default: return;
    }
    arg_ref(g, P, s->a, out);
    fputs(", ", out);
    arg_ref(g, P, s->b, out);
    fputs(")", out);
}

/* double tN[nout]; fn(a0, a1, a2, tN);  or, with more than four arguments (a tensor),
 * const double aN[n] = {a0, ...}; double tN[nout]; fn(aN, tN);  (valid C and C++) */
static void print_ext(const SGraph *g, const Pieces *P, int id, FILE *out, const char *indent)
{
    const SNode *s = &g->nodes[id];
    int packed = s->nargs > 4;
    if (packed)
        fprintf(out, "%sconst double a%d[%d] = {", indent, id, s->nargs);
    for (int k = 0; packed && k < s->nargs; k++) {
        if (k)
            fputs(", ", out);
        print_ref(g, P, s->args[k], out);
    }
    fprintf(out, "%s%sdouble t%d[%d];\n%s%s(", packed ? "};\n" : "", indent, id, s->b, indent,
            s->name);
    if (packed)
        fprintf(out, "a%d", id);
    for (int k = 0; !packed && k < s->nargs; k++) {
        if (k)
            fputs(", ", out);
        print_ref(g, P, s->args[k], out);
    }
    fprintf(out, ", t%d);\n", id);
}

/* Node id's statement: `const double tN = ...;` (a runtime routine's call), then, in a piece,
 * `v[S] = tN;` where a later piece reads it; a routine's output k that a later piece reads,
 * `v[S] = tE[k];`; an input a piece reads, `v[S] = F[k];`. */
static void print_statement(const SGraph *g, const Pieces *P, int id, FILE *out,
                            const char *indent)
{
    const SNode *s = &g->nodes[id];
    if (s->op == SN_EXT) {
        print_ext(g, P, id, out, indent);
    } else if (s->op != SN_PART && !is_leaf(s)) {
        fprintf(out, "%sconst double t%d = ", indent, id);
        print_node(g, P, id, out);
        fputs(";\n", out);
    }
    if (P && P->slot[id] >= 0) {
        fprintf(out, "%sv[%d] = ", indent, P->slot[id]);
        print_ref(g, NULL, id, out);
        fputs(";\n", out);
    }
}

/* The statements of nodes ids[0 .. n-1], each group under a comment naming the model line it
 * came from. */
static void print_nodes(const SGraph *g, const Pieces *P, const int *ids, int n, FILE *out,
                        const char *indent)
{
    int line = -1;
    const char *file = NULL;
    for (int k = 0; k < n; k++) {
        const SNode *s = &g->nodes[ids[k]];
        if (s->line != line || s->file != file) {
            line = s->line;
            file = s->file;
            if (file)
                fprintf(out, "%s/* %s:%d: %s */\n", indent, source_basename(file), line,
                        source_line_trimmed(file, line));
        }
        print_statement(g, P, ids[k], out, indent);
    }
}

/* The nodes the roots need, in order, into ids (the count returned): the operations, and with
 * parts, the runtime routines' outputs too. */
static int needed_nodes(const SGraph *g, const int *roots, int nroots, int parts, int *ids)
{
    char *live = calloc((size_t)g->n + 1, 1);
    sg_mark_live(g, roots, nroots, live);
    int n = 0;
    for (int id = 0; id < g->n; id++)
        if (live[id] && !is_leaf(&g->nodes[id]) && (parts || g->nodes[id].op != SN_PART))
            ids[n++] = id;
    free(live);
    return n;
}

/* `<indent>name[k] = <ref of ids[k]><end>` for k < n, one line each; `<indent>name = ...` for
 * n = -1 (one value, ids[0]). */
static void print_output(const SGraph *g, const Pieces *P, const char *indent, const char *name,
                         const int *ids, int n, const char *end, FILE *out)
{
    for (int k = 0; k < (n < 0 ? 1 : n); k++) {
        if (n < 0)
            fprintf(out, "%s%s = ", indent, name);
        else
            fprintf(out, "%s%s[%d] = ", indent, name, k);
        print_ref(g, P, ids[k], out);
        fprintf(out, "%s\n", end);
    }
}

void graph_print(const SGraph *g, const LawOutput *o, int no, int as_c, FILE *out)
{
    int roots[PLAN_MAX_ROOTS];
    const int nroots = plan_output_roots(o, no, roots);
    int *ids = malloc((size_t)(g->n + 1) * sizeof *ids);
    print_nodes(g, NULL, ids, needed_nodes(g, roots, nroots, 0, ids), out, "    ");
    free(ids);
    for (int k = 0; k < no; k++)
        print_output(g, NULL, "    ", as_c ? o[k].c_name : o[k].label, o[k].ids, o[k].n,
                     as_c ? ";" : "", out);
}

/* The operands of node s into ops, their count returned. */
static int operands(const SNode *s, int ops[SG_MAX_ARGS])
{
    if (s->op == SN_EXT) {
        for (int k = 0; k < s->nargs; k++)
            ops[k] = s->args[k];
        return s->nargs;
    }
    int n = 0;
    const int abc[3] = {s->a, s->b, s->c};
    for (int k = 0; k < 3; k++)
        if (abc[k] >= 0)
            ops[n++] = abc[k];
    return n;
}

/* Each needed node's piece, GRAPH_PIECE_OPS operations a piece (a routine's outputs in its
 * piece), then P->ids ordered by piece. */
static void assign_pieces(const SGraph *g, Pieces *P)
{
    int ops = 0;
    P->n = 1;
    for (int k = 0; k < P->nids; k++) {
        const SNode *s = &g->nodes[P->ids[k]];
        if (s->op == SN_PART) {
            P->piece[P->ids[k]] = P->piece[s->a];
            continue;
        }
        if (ops == GRAPH_PIECE_OPS) {
            P->n++;
            ops = 0;
        }
        P->piece[P->ids[k]] = P->n - 1;
        ops++;
    }
    int *start = calloc((size_t)P->n + 1, sizeof *start);
    int *sorted = malloc((size_t)P->nids * sizeof *sorted);
    for (int k = 0; k < P->nids; k++)
        start[P->piece[P->ids[k]] + 1]++;
    for (int q = 0; q < P->n; q++)
        start[q + 1] += start[q];
    for (int k = 0; k < P->nids; k++)
        sorted[start[P->piece[P->ids[k]]]++] = P->ids[k];
    memcpy(P->ids, sorted, (size_t)P->nids * sizeof *sorted);
    free(sorted);
    free(start);
}

/* The last piece that reads each value from another (n: the function's outputs), -1 for one
 * no other piece reads. */
static int *last_uses(const SGraph *g, const Pieces *P, const int *roots, int nroots)
{
    int *last = malloc((size_t)(g->n + 1) * sizeof *last), ops[SG_MAX_ARGS];
    for (int id = 0; id < g->n; id++)
        last[id] = -1;
    for (int k = 0; k < P->nids; k++) {
        const int id = P->ids[k], n = operands(&g->nodes[id], ops);
        for (int q = 0; q < n; q++)
            if (g->nodes[ops[q]].op != SN_CONST && P->piece[ops[q]] != P->piece[id] &&
                last[ops[q]] < P->piece[id])
                last[ops[q]] = P->piece[id];
    }
    for (int k = 0; k < nroots; k++)
        if (roots[k] >= 0 && !is_leaf(&g->nodes[roots[k]]))
            last[roots[k]] = P->n;
    return last;
}

/* Value id a place in v: one freed by a value last read before its piece, or a new one. */
static void take_slot(Pieces *P, int id, int *free_slots, int *nfree)
{
    P->slot[id] = *nfree ? free_slots[--*nfree] : P->nslots++;
}

/* The places in v: the inputs first, then the values of each piece, each place freed after its
 * value's last piece (next: the values of each last piece, a list from head). */
static void assign_slots(const SGraph *g, Pieces *P, const int *last)
{
    int *head = malloc((size_t)(P->n + 1) * sizeof *head);
    int *next = malloc((size_t)(g->n + 1) * sizeof *next);
    int *free_slots = malloc((size_t)(g->n + 1) * sizeof *free_slots), nfree = 0, freed = 0;
    for (int q = 0; q <= P->n; q++)
        head[q] = -1;
    for (int id = 0; id < g->n; id++) {
        P->slot[id] = -1;
        if (last[id] >= 0) {
            next[id] = head[last[id]];
            head[last[id]] = id;
        }
        if (last[id] >= 0 && is_leaf(&g->nodes[id]))
            take_slot(P, id, free_slots, &nfree);
    }
    for (int k = 0; k < P->nids; k++) {
        const int id = P->ids[k];
        for (; freed < P->piece[id]; freed++)
            for (int v = head[freed]; v >= 0; v = next[v])
                free_slots[nfree++] = P->slot[v];
        if (last[id] >= 0)
            take_slot(P, id, free_slots, &nfree);
    }
    free(free_slots);
    free(next);
    free(head);
}

/* The pieces of the graph's outputs o. */
static void plan_pieces(const SGraph *g, const LawOutput *o, int no, Pieces *P)
{
    int roots[PLAN_MAX_ROOTS];
    const int nroots = plan_output_roots(o, no, roots);
    memset(P, 0, sizeof *P);
    P->ids = malloc((size_t)(g->n + 1) * sizeof *P->ids);
    P->piece = malloc((size_t)(g->n + 1) * sizeof *P->piece);
    P->slot = malloc((size_t)(g->n + 1) * sizeof *P->slot);
    for (int id = 0; id < g->n; id++)
        P->piece[id] = -1;
    P->nids = needed_nodes(g, roots, nroots, 1, P->ids);
    assign_pieces(g, P);
    int *last = last_uses(g, P, roots, nroots);
    assign_slots(g, P, last);
    free(last);
}

static void free_pieces(Pieces *P)
{
    free(P->ids);
    free(P->piece);
    free(P->slot);
}

void graph_print_pieces(const SGraph *g, const LawOutput *o, int no, const char *name, FILE *out)
{
    Pieces P;
    plan_pieces(g, o, no, &P);
    for (int k = 0, first = 0; k < P.n; k++) {
        int end = first;
        while (end < P.nids && P.piece[P.ids[end]] == k)
            end++;
        fprintf(out, "/* %s's law, piece %d of %d (v: the values the pieces share) */\n"
                     "SPH_PIECE void %s_piece%d(double *v)\n{\n", name, k + 1, P.n, name, k + 1);
        P.cur = k;
        print_nodes(g, &P, P.ids + first, end - first, out, "    ");
        fputs("}\n\n", out);
        first = end;
    }
    free_pieces(&P);
}

void graph_print_pieced(const SGraph *g, const LawOutput *o, int no, const char *name, FILE *out)
{
    Pieces P;
    plan_pieces(g, o, no, &P);
    fprintf(out, "    double v[%d];\n", P.nslots);
    P.cur = -1;
    for (int id = 0; id < g->n; id++)
        if (P.slot[id] >= 0 && is_leaf(&g->nodes[id]))
            print_statement(g, &P, id, out, "    ");
    for (int k = 0; k < P.n; k++)
        fprintf(out, "    %s_piece%d(v);\n", name, k + 1);
    P.cur = P.n;
    for (int k = 0; k < no; k++)
        print_output(g, &P, "    ", o[k].c_name, o[k].ids, o[k].n, ";", out);
    free_pieces(&P);
}
