/* plan_dump.c — the plan as text (sphc --dump=plan): per body its features, how its material
 * law gets its stress (written, or derived from its energy) with the size of what the
 * generated function computes, and the law's graph as the generated code will compute it. */
#include <string.h>

#include "graph_print.h"
#include "plan.h"

/* The law's top-level energy statement, or its tension block. */
static const MatStmt *law_statement(const MatStmtList *l, MatStmtKind kind, const char *name)
{
    for (int i = 0; i < l->n; i++)
        if (l->items[i].kind == kind && (!name || !strcmp(l->items[i].name, name)))
            return &l->items[i];
    return NULL;
}

/* How the law gets its stress: written, or derived from the energy (and how). */
static void stress_source(const MaterialDef *law, FILE *out)
{
    if (law_statement(&law->body, MS_STRESS, NULL)) {
        fputs("stress written", out);
        return;
    }
    const MatStmt *e = law_statement(&law->body, MS_ENERGY, NULL);
    const char *of = e ? e->of : NULL;
    fprintf(out, "stress derived from energy psi(%s), S = %s", of ? of : "F",
            !of ? "F^-1 dpsi/dF" : !strcmp(of, "C") ? "2 dpsi/dC" : "dpsi/dE");
    if (law_statement(&law->body, MS_STATE, NULL))
        fputs(" at the returned state", out);
}

/* "material law: stress ...; N operations (S a, psi b, state c)" and, with fracture, the
 * tension block's line: what the body's material function computes. */
static void law_summary(const BodyPlan *p, const MaterialDef *law, FILE *out)
{
    const LawRoots *r = &p->roots;
    const SGraph *g = &p->law;
    LawOutput o[LAW_MAX_OUTPUTS];
    int all[PLAN_MAX_ROOTS];
    const int n = plan_output_roots(o, plan_law_outputs(p, 0, o), all); /* S, psi, state */
    fputs("  material law: ", out);
    stress_source(law, out);
    if (r->has_tension) { /* the function computes the degraded law only */
        fprintf(out, "; S %d, psi %d operations\n", sg_operations(g, r->S, 9),
                sg_operations(g, &r->psi, 1));
        const MatStmt *t = law_statement(&law->body, MS_BLOCK, "tension");
        const int written = t && law_statement(&t->body, MS_STRESS, NULL);
        int deg[9 + 2];
        memcpy(deg, r->Sd, sizeof r->Sd);
        deg[9] = r->psid, deg[10] = r->psip;
        fprintf(out, "  tension block: S+ %s; S+ %d, psi+ %d operations; degraded S, psi, psi+ "
                     "(eq. 7, 18): %d operations\n",
                written ? "written" : "derived from psi+", sg_operations(g, r->Sp, 9),
                sg_operations(g, &r->psip, 1), sg_operations(g, deg, 11));
        return;
    }
    fprintf(out, "; %d operations (S %d, psi %d", sg_operations(g, all, n),
            sg_operations(g, r->S, 9), sg_operations(g, &r->psi, 1));
    if (p->nstate > 0)
        fprintf(out, ", state %d", sg_operations(g, r->next, p->nstate));
    fputs(")\n", out);
}

/* The operations of the law's fast path: its S, psi, state and flag. */
static int fast_operations(const BodyPlan *p)
{
    LawOutput o[LAW_MAX_OUTPUTS + 1];
    int roots[PLAN_MAX_ROOTS];
    const int n = plan_output_roots(o, plan_law_fast_outputs(p, o), roots);
    return sg_operations(&p->law, roots, n);
}

/* The law's graph and its outputs (degraded: those of eq. 7 and 18) as the generated function
 * computes them, the outputs named as the dump names them. */
static void law_graph(const BodyPlan *p, int degraded, FILE *out)
{
    LawOutput o[LAW_MAX_OUTPUTS];
    graph_print(&p->law, o, plan_law_outputs(p, degraded, o), 0, out);
}

/* The same for the law's fast path: its outputs and `rare`, the flag. */
static void fast_graph(const BodyPlan *p, FILE *out)
{
    LawOutput o[LAW_MAX_OUTPUTS + 1];
    graph_print(&p->law, o, plan_law_fast_outputs(p, o), 0, out);
}

/* The name of the state variable the law's `viscousheat` names. */
static const char *viscous_heat_name(const BodyPlan *p)
{
    const LawRoots *r = &p->roots;
    for (int k = 0; k < r->nstates; k++)
        if (r->states[k].offset == r->viscous_heat - 1)
            return r->states[k].name;
    return "?";
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
        for (int k = 0; k < BODY_NSETTINGS; k++)
            if (BODY_SETTING_ROWS[k].sw)
                fprintf(out, " %s=%u", BODY_SETTING_ROWS[k].keyword, p->terms >> k & 1);
        fputs("\n", out);
        layouts_dump(m, p, out);
        law_summary(p, b->law, out);
        if (p->law_dt || p->law_fdot)
            fprintf(out, "  the law reads:%s%s\n",
                    p->law_dt ? " dt (the time since its last evaluation)" : "",
                    p->law_fdot ? (p->law_dt ? ", Fdot (the velocity's gradient)"
                                             : " Fdot (the velocity's gradient)") : "");
        if (p->vheat)
            fprintf(out, "  the program adds the artificial viscosity's heat to state value %d "
                         "(%s)\n", p->roots.viscous_heat - 1, viscous_heat_name(p));
        law_graph(p, 0, out);
        if (p->rare) {
            fprintf(out, "  fast path (the CPU's stress pass; no `if` without `else` taken, rare "
                         "the flag that one was due): %d operations\n", fast_operations(p));
            fast_graph(p, out);
        }
        if (p->roots.has_tension) {
            fputs("  degraded by the phase field (eq. 7, 18):\n", out);
            law_graph(p, 1, out);
        }
    }
}
