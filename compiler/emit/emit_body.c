/* emit_body.c — a body's passes from templates/: the features its plan switches on and the
 * numbers the templates read (template.c fills them). */
#include <stdio.h>

#include "emit_internal.h"
#include "template.h"

int emit_template(Emitter *E, const char *file, const BodyModel *b, const BodyPlan *p)
{
    TplEnv env = {0};
    tpl_set(&env, "B", "%s", b->name);
    tpl_set(&env, "DIM", "%d", E->m->dim);
    tpl_set(&env, "KERNEL", "%s", E->m->kernel == KERNEL_CUBIC ? "SPH_CUBIC" : "SPH_WENDLAND");
    tpl_set(&env, "BETA1", "%.17g", b->beta1);
    tpl_set(&env, "BETA2", "%.17g", b->beta2);
    tpl_set(&env, "C0", "%.17g", b->c0);
    tpl_set(&env, "HG", "%.17g", 0.5 * b->hourglass * b->E); /* alpha E / 2 */
#define PLAN_SWITCH(member, name, sw, value) tpl_switch(&env, #sw, p->member);
    PLAN_FEATURES(PLAN_SWITCH)
#undef PLAN_SWITCH
    tpl_set(&env, "NSTATE", "%d", p->nstate);
    const double *g = E->m->gravity; /* compact components */
    tpl_set(&env, "G0", "%.17g", g[0]);
    tpl_set(&env, "G1", "%.17g", E->m->dim == 2 ? g[2] : g[1]);
    tpl_set(&env, "G2", "%.17g", E->m->dim == 2 ? 0.0 : g[2]);
    if (p->fracture) {
        const FractureModel *f = &b->fracture;
        tpl_set(&env, "GC", "%.17g", f->Gc);
        tpl_set(&env, "EPS0", "%.17g", f->eps0);
        tpl_set(&env, "SLIMIT", "%.17g", f->limit);
        tpl_set(&env, "PF_A", "%.17g", b->c0 * b->c0 / (2 * f->eps0)); /* c^2 / (2 eps0) */
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", E->templates, file);
    int rc = tpl_expand(path, &env, E->out);
    tpl_free(&env);
    fputs("\n", E->out);
    return rc;
}

/* The CPU passes read gravity from a table; the CUDA template takes the numbers (G0..G2). */
void emit_gravity(Emitter *E, const BodyModel *b, const BodyPlan *p)
{
    if (!p->gravity)
        return;
    const double *g = E->m->gravity;
    if (E->m->dim == 2)
        fprintf(E->out, "static const double %s_gravity[2] = {%.17g, %.17g};\n\n", b->name, g[0], g[2]);
    else
        fprintf(E->out, "static const double %s_gravity[3] = {%.17g, %.17g, %.17g};\n\n", b->name,
                g[0], g[1], g[2]);
}
