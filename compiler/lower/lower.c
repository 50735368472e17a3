/* lower.c — from the checked model to per-body kernel plans: dead-feature elimination
 * (only what the body uses is switched on) and the material law folded for the body's
 * constants and dimension. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

int lower_model(const Model *m, Plan *plan)
{
    int bad = 0;
    plan->model = m;
    plan->nbodies = m->nbodies;
    plan->bodies = calloc((size_t)m->nbodies, sizeof *plan->bodies);
    plan->contact = model_has_contact(m);
    plan->fracture = 0;
    for (int i = 0; i < m->nbodies; i++) {
        const BodyModel *b = &m->bodies[i];
        BodyPlan *p = &plan->bodies[i];
        memset(p, 0, sizeof *p);
        features(m, b, p);
        sg_init(&p->law);
        bad |= law_build(&p->law, m, b->law, b->law_args, m->dim, b->fracture.on, &p->roots) != 0;
        p->nstate = p->roots.nslots;
        plan->fracture |= p->fracture;
    }
    if (bad)
        plan_free(plan);
    return bad ? -1 : 0;
}

void plan_free(Plan *plan)
{
    for (int i = 0; i < plan->nbodies; i++)
        sg_free(&plan->bodies[i].law);
    free(plan->bodies);
    plan->bodies = NULL;
    plan->nbodies = 0;
}
