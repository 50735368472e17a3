/* graph_print.h — a law's scalar graph printed as C statements (graph_print.c): the text of
 * the generated material functions (emit/) and of the law in --dump=plan (plan_dump.c). */
#ifndef SPHC_GRAPH_PRINT_H
#define SPHC_GRAPH_PRINT_H

#include <stdio.h>

#include "plan.h"

/* The statements of graph g computing outputs o[0 .. no-1], then the outputs, at the indent
 * of a function body: each node the outputs need as `const double tN = ...;`, under a
 * comment naming the model line it came from; each output as C, `c_name[k] = tN;` (as_c),
 * or as the dump shows it, `label[k] = tN`. */
void graph_print(const SGraph *g, const LawOutput *o, int no, int as_c, FILE *out);

/* A law of more than GRAPH_WHOLE_OPS operations (plan_law_operations) is printed in pieces of
 * GRAPH_PIECE_OPS: the time the C compiler takes for one function grows with the square of its
 * size (its register allocation over the values live across it), for the pieces linearly with
 * the law.  The standard library's largest law, ogden in 3D, has 9772. */
enum { GRAPH_WHOLE_OPS = 10000, GRAPH_PIECE_OPS = 200 };
/* A call (pow, exp, ...; plan_law_calls) counts as this many operations: on the CPU every
 * value live across it is spilled around it (the register allocation of 2450 chained lets,
 * 4900 pows among 9840 operations, took gcc 42 s); nvcc writes each one's code out in place
 * (some 85 PTX instructions a pow), and a function of many takes it minutes (1000 chained lets
 * whole, 2000 pows: more than 3 minutes). */
enum { GRAPH_CALL_OPS = 4, GRAPH_CUDA_CALL_OPS = 20 };

/* The pieces as C functions `SPH_PIECE void NAME_pieceK(double *v)`, K from 1, before function
 * NAME: each piece's statements, those a later piece reads stored in v. */
void graph_print_pieces(const SGraph *g, const LawOutput *o, int no, const char *name, FILE *out);
/* The body of function NAME with pieces: `double v[N];`, the inputs the pieces read copied
 * into v, the pieces called in order, and the outputs from v. */
void graph_print_pieced(const SGraph *g, const LawOutput *o, int no, const char *name, FILE *out);

#endif
