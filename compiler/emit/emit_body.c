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
#define PLAN_SWITCH(member, name, sw, value) tpl_switch(&env, #sw, p->member);
    PLAN_FEATURES(PLAN_SWITCH)
#undef PLAN_SWITCH
    /* Declared for every template, on or off, since an undeclared switch is an error: the
     * parts a program on many processes adds (//@if MPI). */
    tpl_switch(&env, "MPI", E->mpi);
    /* whether the code takes one particle's stress from the body's arrays (B_particle_stress):
     * the device's threads always, the CPU unless its stress pass goes by blocks (STAGED) */
    tpl_switch(&env, "ONE_PARTICLE", E->target == emit_target(TARGET_CUDA) || !p->staged);
    tpl_set(&env, "NSTATE", "%d", p->nstate);
    int k = 0;
#define PLAN_KEY(member, key, value, when)                                                    \
    if (p->numbers >> k++ & 1)                                                                 \
        tpl_set(&env, #key, "%.17g", p->member);
    PLAN_NUMBERS(PLAN_KEY)
#undef PLAN_KEY
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
