/* emit_body.c — a body's passes from templates/: the features its plan switches on and the
 * numbers the templates read (template.c fills them). */
#include <stdio.h>

#include "emit_internal.h"
#include "template.h"

/* The element types a body's pair terms are filled in for (templates/physics/pairs.c): T,
 * the type of a value (one pair's, or several pairs' in the lanes of a vector), E, the type
 * of a constant multiplying it, W, that of a table entry w, and S, the functions' suffix. */
typedef struct {
    const char *S, *T, *E, *W;
    int v8; /* the vector of eight doubles (switch LANES_V8) */
} Lanes;

static const Lanes LANES_D = {"d", "double", "sph_real", "sph_real", 0};
static const Lanes LANES_F = {"f", "float", "sph_real", "sph_real", 0};
static const Lanes LANES_V8 = {"v8", NULL, "double", "double", 1}; /* T: the body's B_v8 */

/* What every template of body b reads: its name, dimension and kernel, its features as
 * switches and its numbers as keys. */
static void body_env(const Emitter *E, const BodyModel *b, const BodyPlan *p, TplEnv *env)
{
    tpl_set(env, "B", "%s", b->name);
    tpl_set(env, "DIM", "%d", E->m->dim);
    tpl_set(env, "KERNEL", "%s", E->m->kernel == KERNEL_CUBIC ? "SPH_CUBIC" : "SPH_WENDLAND");
#define PLAN_SWITCH(member, name, sw, value) tpl_switch(env, #sw, p->member);
    PLAN_FEATURES(PLAN_SWITCH)
#undef PLAN_SWITCH
    /* Declared for every template, on or off, since an undeclared switch is an error: the
     * parts a program on many processes adds (//@if MPI). */
    tpl_switch(env, "MPI", E->mpi);
    /* whether the code takes one particle's stress from the body's arrays (B_particle_stress):
     * the device's threads always, the CPU unless its stress pass goes by blocks (STAGED) */
    tpl_switch(env, "ONE_PARTICLE", E->target == emit_target(TARGET_CUDA) || !p->staged);
    tpl_switch(env, "LANES_V8", 0);
    /* the suffix of the pair terms in sph_real, the pair lists' type (_d or _f) */
    tpl_set(env, "RS", "%s", E->m->single ? LANES_F.S : LANES_D.S);
    tpl_set(env, "NSTATE", "%d", p->nstate);
    /* what the law reads besides F among its material function's arguments: Fd, dt */
    tpl_set(env, "LAW_ARGS", "%s%s", p->law_fdot ? "Fd, " : "", p->law_dt ? "dt, " : "");
    /* and what it gives besides S and psi: its wave speed, into cw */
    tpl_set(env, "LAW_OUTS", "%s", p->law_wave ? ", &cw" : "");
    /* the loops over particles the compiler is told to vectorise (` simd`), none with
     * sphc --no-simd */
    tpl_set(env, "OMP_SIMD", "%s", p->simd ? " simd" : "");
    int k = 0;
#define PLAN_KEY(member, key, value, when)                                                    \
    if (p->numbers >> k++ & 1)                                                                 \
        tpl_set(env, #key, "%.17g", p->member);
    PLAN_NUMBERS(PLAN_KEY)
#undef PLAN_KEY
    /* the terms of the body's settings: switch on and key its value where nonzero */
    for (k = 0; k < BODY_NSETTINGS; k++) {
        const BodySetting *s = &BODY_SETTING_ROWS[k];
        if (!s->sw)
            continue;
        tpl_switch(env, s->sw, p->terms >> k & 1);
        if (p->terms >> k & 1)
            tpl_set(env, s->sw, "%.17g", body_setting_value(b, s));
    }
}

static int expand(Emitter *E, const char *file, const TplEnv *env)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", E->templates, file);
    int rc = tpl_expand(path, env, E->out);
    fputs("\n", E->out);
    return rc;
}

int emit_template(Emitter *E, const char *file, const BodyModel *b, const BodyPlan *p)
{
    TplEnv env = {0};
    body_env(E, b, p, &env);
    int rc = expand(E, file, &env);
    tpl_free(&env);
    return rc;
}

/* One filling of the pair terms: its element type and which of the terms its loops call
 * (the others are left out: nvcc warns of a function never called). */
typedef struct {
    const Lanes *lanes;
    int gradient; /* B_gradient_term (eq. 53) */
    int momentum; /* B_momentum_term, and B_viscosity_term with viscosity (eq. 55, 57-60) */
    int pressure; /* B_viscous_pressure alone (eq. 58-60) */
} Filling;

/* The fillings body b's pair loops use.  The CPU: the half lists sum in sph_real and call
 * the viscous pressure alone (their own loops hold a tensor's column in a vector); eight
 * doubles for the offset blocks (3D: gradient, momentum) and the lattice stencil (2D: its
 * runs' x and y side by side; the viscous pressure).  The device: sph_real for the momentum
 * pass, double for the gradient, which sums in double. */
static int body_fillings(const Emitter *E, const BodyPlan *p, Filling out[3])
{
    const Lanes *real = E->m->single ? &LANES_F : &LANES_D;
    int n = 0;
    if (E->target == emit_target(TARGET_CUDA)) {
        out[n++] = (Filling){real, !E->m->single, 1, 0};
        if (E->m->single)
            out[n++] = (Filling){&LANES_D, 1, 0, 0};
        return n;
    }
    if (p->viscosity)
        out[n++] = (Filling){real, 0, 0, 1};
    if (p->stencil)
        out[n++] = (Filling){&LANES_V8, 0, 0, p->viscosity && p->stencil_momentum};
    else if (p->offset_blocks || p->momentum_blocks)
        out[n++] = (Filling){&LANES_V8, p->offset_blocks, p->momentum_blocks, 0};
    return n;
}

int emit_template_lanes(Emitter *E, const char *file, const BodyModel *b, const BodyPlan *p)
{
    Filling fill[3];
    const int n = body_fillings(E, p, fill);
    int rc = 0;
    for (int k = 0; k < n && !rc; k++) {
        const Lanes *l = fill[k].lanes;
        TplEnv env = {0};
        body_env(E, b, p, &env);
        tpl_set(&env, "S", "%s", l->S);
        if (l->v8)
            tpl_set(&env, "T", "%s_v8", b->name);
        else
            tpl_set(&env, "T", "%s", l->T);
        tpl_set(&env, "E", "%s", l->E);
        tpl_set(&env, "W", "%s", l->W);
        tpl_switch(&env, "LANES_V8", l->v8);
        tpl_switch(&env, "TERM_GRADIENT", fill[k].gradient);
        tpl_switch(&env, "TERM_MOMENTUM", fill[k].momentum);
        tpl_switch(&env, "TERM_PRESSURE", fill[k].pressure || (fill[k].momentum && p->viscosity));
        tpl_switch(&env, "FIRST", k == 0);
        rc = expand(E, file, &env);
        tpl_free(&env);
    }
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
