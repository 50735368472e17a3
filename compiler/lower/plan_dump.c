/* plan_dump.c — the plan as text (sphc --dump=plan): per body its features and the
 * material law's graph as the generated code will compute it. */

#include "plan.h"

static int count_ops(const SGraph *g)
{
    int n = 0;
    for (int id = 0; id < g->n; id++)
        n += g->nodes[id].op > SN_PARAM;
    return n;
}

void plan_dump(const Plan *plan, FILE *out)
{
    const Model *m = plan->model;
    for (int i = 0; i < m->nbodies; i++) {
        const BodyPlan *p = &plan->bodies[i];
        const BodyModel *b = &m->bodies[i];
        fprintf(out, "body %s: dim %d, law %s, %s integrator\n", b->name, m->dim, b->law->name,
                p->symplectic ? "symplectic" : "verlet");
        fputs("  features:", out);
#define PLAN_DUMP(member, name, sw, value)                                                    \
    if (name)                                                                                  \
        fprintf(out, " %s=%d", (const char *)name, p->member);
        PLAN_FEATURES(PLAN_DUMP)
#undef PLAN_DUMP
        fputs("\n", out);
        fprintf(out, "  material law: %d graph nodes\n", count_ops(&p->law));
        plan_law_print(p, 0, 0, out);
        if (p->roots.has_tension) {
            fputs("  degraded by the phase field (eq. 7, 18):\n", out);
            plan_law_print(p, 1, 0, out);
        }
    }
}
