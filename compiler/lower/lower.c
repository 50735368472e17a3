/* lower.c — from the checked model to per-body kernel plans: dead-feature elimination
 * (only what the body uses is switched on) and the material law folded for the body's
 * constants and dimension. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "emit/emit.h"
#include "plan.h"

static void features(const Model *m, const BodyModel *b, BodyPlan *p)
{
    p->viscosity = b->beta1 > 0 || b->beta2 > 0;
    p->beta2 = b->beta2 > 0;
    p->hourglass = b->hourglass > 0;
    p->gravity = m->gravity[0] != 0 || m->gravity[1] != 0 || m->gravity[2] != 0;
    p->symplectic = m->integrator == INTEGRATOR_SYMPLECTIC;
    p->fracture = b->fracture.on;
    p->restrict_phase = b->fracture.restrict_expr != NULL;
    p->crush = model_has_crush(m);
    p->measure = b->nmeasures > 0;
    for (int k = 0; k < b->nbcs; k++) {
        if (!b->bcs[k].comps)
            continue; /* only out-of-plane components in 2D: nothing to do */
        p->bc_fns++;
        p->velocity_bcs |= b->bcs[k].kind == BC_VELOCITY;
        p->force_bcs |= b->bcs[k].kind == BC_FORCE;
    }
}

int lower_model(const Model *m, BodyPlan *plans)
{
    int bad = 0;
    for (int i = 0; i < m->nbodies; i++) {
        const BodyModel *b = &m->bodies[i];
        BodyPlan *p = &plans[i];
        memset(p, 0, sizeof *p);
        features(m, b, p);
        sg_init(&p->law);
        bad |= law_build(&p->law, m, b->law, b->law_args, m->dim, b->fracture.on, &p->roots) != 0;
        p->nstate = p->roots.nslots;
    }
    return bad ? -1 : 0;
}

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

void plan_dump(const Model *m, FILE *out)
{
    BodyPlan *plans = calloc((size_t)m->nbodies, sizeof *plans);
    if (lower_model(m, plans)) {
        free(plans);
        return;
    }
    for (int i = 0; i < m->nbodies; i++) {
        const BodyPlan *p = &plans[i];
        const BodyModel *b = &m->bodies[i];
        fprintf(out, "body %s: dim %d, law %s, %s integrator\n", b->name, m->dim, b->law->name,
                p->symplectic ? "symplectic" : "verlet");
        fprintf(out, "  features: viscosity=%d beta2=%d gravity=%d velocity_bcs=%d "
                     "force_bcs=%d hourglass=%d fracture=%d restrict=%d state=%d contact=%d "
                     "crush=%d measure=%d bc_fns=%d\n",
                p->viscosity, p->beta2, p->gravity, p->velocity_bcs, p->force_bcs, p->hourglass,
                p->fracture, p->restrict_phase, p->nstate > 0, model_has_contact(m), p->crush,
                p->measure, p->bc_fns);
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
    free(plans);
}
