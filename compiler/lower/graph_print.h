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

#endif
