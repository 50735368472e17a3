/* graph_print.c — a law's scalar graph printed as C statements: the body of a generated
 * material function (emit/emit_law.c) and, with the outputs named as the dump names them,
 * the law in --dump=plan (plan_dump.c). */
#include <math.h>
#include <stdlib.h>

#include "graph_print.h"
#include "lang/builtins.h"
#include "util/source.h"

static int is_leaf(const SNode *s)
{
    return s->op == SN_CONST || s->op == SN_INPUT || s->op == SN_PARAM;
}

static void print_ref(const SGraph *g, int id, FILE *out)
{
    const SNode *s = &g->nodes[id];
    if (s->op == SN_CONST) {
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
static void arg_ref(const SGraph *g, int id, FILE *out)
{
    const SNode *s = &g->nodes[id];
    if (s->op != SN_CONST || s->v != floor(s->v) || fabs(s->v) >= 1e15) {
        print_ref(g, id, out);
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

static void print_node(const SGraph *g, int id, FILE *out)
{
    const SNode *s = &g->nodes[id];
    const char *op = infix(s->op);
    if (op) {
        print_ref(g, s->a, out);
        fprintf(out, " %s ", op);
        print_ref(g, s->b, out);
        return;
    }
    switch (s->op) {
    case SN_NEG: fputs("-", out); print_ref(g, s->a, out); return;
    case SN_NOT: fputs("!", out); print_ref(g, s->a, out); return;
    case SN_POW: fputs("pow(", out); break;
    case SN_MIN: fputs("sph_min(", out); break;
    case SN_MAX: fputs("sph_max(", out); break;
    case SN_CALL:
        fprintf(out, "%s(", BUILTIN_FUNCTION[s->fn].c);
        arg_ref(g, s->a, out);
        fputs(")", out);
        return;
    case SN_SELECT:
        print_ref(g, s->a, out);
        fputs(" ? ", out);
        print_ref(g, s->b, out);
        fputs(" : ", out);
        print_ref(g, s->c, out);
        return;
    default: return;
    }
    arg_ref(g, s->a, out);
    fputs(", ", out);
    arg_ref(g, s->b, out);
    fputs(")", out);
}

/* double tN[nout]; fn(a0, a1, a2, tN);  or, with more than four arguments (a tensor),
 * const double aN[n] = {a0, ...}; double tN[nout]; fn(aN, tN);  (valid C and C++) */
static void print_ext(const SGraph *g, int id, FILE *out, const char *indent)
{
    const SNode *s = &g->nodes[id];
    int packed = s->nargs > 4;
    if (packed)
        fprintf(out, "%sconst double a%d[%d] = {", indent, id, s->nargs);
    for (int k = 0; packed && k < s->nargs; k++) {
        if (k)
            fputs(", ", out);
        print_ref(g, s->args[k], out);
    }
    fprintf(out, "%s%sdouble t%d[%d];\n%s%s(", packed ? "};\n" : "", indent, id, s->b, indent,
            s->name);
    if (packed)
        fprintf(out, "a%d", id);
    for (int k = 0; !packed && k < s->nargs; k++) {
        if (k)
            fputs(", ", out);
        print_ref(g, s->args[k], out);
    }
    fprintf(out, ", t%d);\n", id);
}

/* The nodes the roots need as `const double tN = ...;` lines, each group under a comment
 * naming the model line it came from. */
static void print_nodes(const SGraph *g, const int *roots, int nroots, FILE *out,
                        const char *indent)
{
    char *live = calloc((size_t)g->n + 1, 1);
    sg_mark_live(g, roots, nroots, live);
    int line = -1;
    const char *file = NULL;
    for (int id = 0; id < g->n; id++) {
        const SNode *s = &g->nodes[id];
        if (!live[id] || is_leaf(s) || s->op == SN_PART)
            continue;
        if (s->line != line || s->file != file) {
            line = s->line;
            file = s->file;
            if (file)
                fprintf(out, "%s/* %s:%d: %s */\n", indent, source_basename(file), line,
                        source_line_trimmed(file, line));
        }
        if (s->op == SN_EXT) {
            print_ext(g, id, out, indent);
            continue;
        }
        fprintf(out, "%sconst double t%d = ", indent, id);
        print_node(g, id, out);
        fputs(";\n", out);
    }
    free(live);
}

/* `<indent>name[k] = <ref of ids[k]><end>` for k < n, one line each; `<indent>name = ...` for
 * n = -1 (one value, ids[0]). */
static void print_output(const SGraph *g, const char *indent, const char *name, const int *ids,
                         int n, const char *end, FILE *out)
{
    for (int k = 0; k < (n < 0 ? 1 : n); k++) {
        if (n < 0)
            fprintf(out, "%s%s = ", indent, name);
        else
            fprintf(out, "%s%s[%d] = ", indent, name, k);
        print_ref(g, ids[k], out);
        fprintf(out, "%s\n", end);
    }
}

void graph_print(const SGraph *g, const LawOutput *o, int no, int as_c, FILE *out)
{
    int roots[PLAN_MAX_ROOTS];
    print_nodes(g, roots, plan_output_roots(o, no, roots), out, "    ");
    for (int k = 0; k < no; k++)
        print_output(g, "    ", as_c ? o[k].c_name : o[k].label, o[k].ids, o[k].n,
                     as_c ? ";" : "", out);
}
