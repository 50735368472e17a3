/* emit_law.h — a body's material law as the body of its generated function (emit_law.c). */
#ifndef SPHC_EMIT_LAW_H
#define SPHC_EMIT_LAW_H

#include <stdio.h>

#include "lower/plan.h"

/* Before body B's material functions: the pieces of those whose law is printed in pieces
 * (more than GRAPH_WHOLE_OPS operations, lower/graph_print.h; for the CUDA target, cuda, its
 * calls weighed); nothing for a smaller law. */
void emit_law_pieces(FILE *out, const char *B, const BodyPlan *p, int cuda);
/* The statements of body B's material function after its opening brace: its law's graph and
 * the outputs assigned, S[k], *psi and st_new[k]; degraded (fracture, eq. 7 and 18): S[k],
 * *psi and *psip. */
void emit_law_body(FILE *out, const char *B, const BodyPlan *p, int cuda, int degraded);
/* The same for its fast path (a body with `rare`): S[k], *psi, st_new[k] and *rare. */
void emit_law_fast_body(FILE *out, const char *B, const BodyPlan *p, int cuda);

#endif
