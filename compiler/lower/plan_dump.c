/* plan_dump.c — the plan as text (sphc --dump=plan): per body its features and the
 * material law's graph as the generated code will compute it. */
#include <string.h>

#include "plan.h"

static int count_ops(const SGraph *g)
{
    int n = 0;
    for (int id = 0; id < g->n; id++)
        n += g->nodes[id].op > SN_PARAM;
    return n;
}

/* With fracture: the degraded stress and energy (the phase field is `s`) and psi+. */
static void dump_degraded(const SGraph *g, const LawRoots *r, FILE *out)
{
    int roots[11];
    memcpy(roots, r->Sd, sizeof r->Sd);
    roots[9] = r->psid;
    roots[10] = r->psip;
    fputs("  degraded by the phase field (eq. 7, 18):\n", out);
    sg_emit(g, roots, 11, out, "    ");
    sg_emit_outputs(g, "    ", "S", r->Sd, 9, "", out);
    sg_emit_outputs(g, "    ", "psi", &r->psid, -1, "", out);
    sg_emit_outputs(g, "    ", "psi+", &r->psip, -1, "", out);
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
        int roots[10 + LAW_MAX_SLOTS];
        memcpy(roots, p->roots.S, sizeof p->roots.S);
        roots[9] = p->roots.psi;
        memcpy(roots + 10, p->roots.next, (size_t)p->nstate * sizeof(int));
        sg_emit(&p->law, roots, 10 + p->nstate, out, "    ");
        sg_emit_outputs(&p->law, "    ", "S", p->roots.S, 9, "", out);
        sg_emit_outputs(&p->law, "    ", "psi", &p->roots.psi, -1, "", out);
        sg_emit_outputs(&p->law, "    ", "st_new", p->roots.next, p->nstate, "", out);
        if (p->roots.has_tension)
            dump_degraded(&p->law, &p->roots, out);
    }
}
