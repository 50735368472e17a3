/* emit_law.c — a body's material law in C: the statements of its folded scalar graph and its
 * outputs assigned to the generated function's arguments (lower/graph_print.h prints them). */
#include "emit_law.h"
#include "lower/graph_print.h"

void emit_law_body(FILE *out, const BodyPlan *p, int degraded)
{
    LawOutput o[LAW_MAX_OUTPUTS];
    graph_print(&p->law, o, plan_law_outputs(p, degraded, o), 1, out);
}

void emit_law_fast_body(FILE *out, const BodyPlan *p)
{
    LawOutput o[LAW_MAX_OUTPUTS + 1];
    graph_print(&p->law, o, plan_law_fast_outputs(p, o), 1, out);
}
