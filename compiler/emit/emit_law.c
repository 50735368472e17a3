/* emit_law.c — a body's material law in C: the statements of its folded scalar graph and its
 * outputs assigned to the generated function's arguments (lower/graph_print.h prints them),
 * a large law in pieces. */
#include "emit.h"
#include "emit_law.h"
#include "lower/graph_print.h"

/* Whether body p's law is printed in pieces: its operations, each call weighed as the target's
 * compiler finds it (lower/graph_print.h), more than GRAPH_WHOLE_OPS. */
static int in_pieces(const BodyPlan *p, int cuda)
{
    const int weight = cuda ? GRAPH_CUDA_CALL_OPS : GRAPH_CALL_OPS;
    return plan_law_operations(p) + (weight - 1) * plan_law_calls(p) > GRAPH_WHOLE_OPS;
}

/* The law's statements and outputs as the body of function NAME: whole, or calling its
 * pieces. */
static void print_law(FILE *out, const BodyPlan *p, int cuda, const LawOutput *o, int no,
                      const char *name)
{
    if (in_pieces(p, cuda))
        graph_print_pieced(&p->law, o, no, name, out);
    else
        graph_print(&p->law, o, no, 1, out);
}

int emit_law_in_pieces(const Plan *plan, Target t)
{
    for (int i = 0; i < plan->nbodies; i++)
        if (in_pieces(&plan->bodies[i], t == TARGET_CUDA))
            return 1;
    return 0;
}

void emit_law_pieces(FILE *out, const char *B, const BodyPlan *p, int cuda)
{
    char name[1100]; /* a name has at most 1024 characters */
    LawOutput o[LAW_MAX_OUTPUTS + 1];
    if (!in_pieces(p, cuda))
        return;
    snprintf(name, sizeof name, "%s_material", B);
    graph_print_pieces(&p->law, o, plan_law_outputs(p, p->fracture, o), name, out);
    if (!p->rare)
        return;
    snprintf(name, sizeof name, "%s_material_fast", B);
    graph_print_pieces(&p->law, o, plan_law_fast_outputs(p, o), name, out);
}

void emit_law_body(FILE *out, const char *B, const BodyPlan *p, int cuda, int degraded)
{
    char name[1100]; /* a name has at most 1024 characters */
    LawOutput o[LAW_MAX_OUTPUTS];
    snprintf(name, sizeof name, "%s_material", B);
    print_law(out, p, cuda, o, plan_law_outputs(p, degraded, o), name);
}

void emit_law_fast_body(FILE *out, const char *B, const BodyPlan *p, int cuda)
{
    char name[1100]; /* a name has at most 1024 characters */
    LawOutput o[LAW_MAX_OUTPUTS + 1];
    snprintf(name, sizeof name, "%s_material_fast", B);
    print_law(out, p, cuda, o, plan_law_fast_outputs(p, o), name);
}
