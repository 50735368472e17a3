/* emit_step.c — the scene's step: each body's passes in the order of Alg. 1 (Verlet) or
 * Alg. 2 (symplectic), with contact between the bodies' forces and their updates; and the
 * CPU target's step functions, which the runtime calls. */
#include <stdio.h>

#include "emit_internal.h"

/* One pass of body i's code in the step, as the target calls it: the functions of the body
 * whose code it runs (emit_share.c)... */
static void emit_pass(Emitter *E, int i, const char *pass, const char *args)
{
    E->target->pass(E->out, emit_code_name(E, i), pass, args);
}

/* ... and of its own: its boundary conditions and the bound of its phase field. */
static void emit_own_pass(Emitter *E, int i, const char *pass, const char *args)
{
    E->target->pass(E->out, E->m->bodies[i].name, pass, args);
}

/* A body's part of the step up to its internal forces (Alg. 1-2)... */
static void step_forces(Emitter *E, int i)
{
    const BodyPlan *p = &E->plans[i];
    if (p->velocity_bcs)
        emit_own_pass(E, i, "velocity_bcs", "b, t, dt");
    if (p->symplectic)
        emit_pass(E, i, "predict", "b, dt");
    /* the time since its law's last evaluation: the stress pass is at the step's start
     * (Verlet) or its middle (symplectic), and the state starts at t = 0; the CUDA target's
     * step has it as law_dt (emit_cuda.c: a value, or the device clock's) */
    const int arg = E->target->law_dt_argument;
    if (p->law_dt && !arg)
        fprintf(E->out, "        b->law_dt = %s;\n",
                p->symplectic ? "0.5 * (s->dt_prev + dt)" : "s->dt_prev");
    /* (its stress and momentum passes each through SPH_BODY_PASS on the CPU) */
    fprintf(E->out, "        %s_forces(b%s);\n", emit_code_name(E, i),
            p->law_dt && arg ? ", law_dt" : "");
}

/* ... and from its force boundary conditions to the end. */
static void step_update(Emitter *E, int i)
{
    const BodyPlan *p = &E->plans[i];
    if (p->force_bcs)
        emit_own_pass(E, i, "force_bcs", p->symplectic ? "b, t_half, dt" : "b, t, dt");
    emit_pass(E, i, "update", "b, dt");
    if (p->restrict_phase)
        emit_own_pass(E, i, "restrict", "b, t_next, dt");
}

void emit_step_bodies(Emitter *E, const char *body, const char *contact)
{
    const Model *m = E->m;
    FILE *out = E->out;
    const int split = model_has_contact(m); /* contact needs every body at one time level */
    for (int i = 0; i < m->nbodies; i++) {
        fputs("    {\n        sph_body *b = ", out);
        fprintf(out, body, i);
        fputs(";\n", out);
        step_forces(E, i);
        if (!split)
            step_update(E, i);
        fputs("    }\n", out);
    }
    if (!split)
        return;
    fprintf(out, "    %s; /* between the bodies: adds to their a */\n", contact);
    for (int i = 0; i < m->nbodies; i++) {
        fputs("    {\n        sph_body *b = ", out);
        fprintf(out, body, i);
        fputs(";\n", out);
        step_update(E, i);
        fputs("    }\n", out);
    }
}

/* The CPU target's scene: the runtime calls these on the host (sph_model). */
void emit_scene_cpu(Emitter *E)
{
    const Model *m = E->m;
    FILE *out = E->out;
    int sym = m->integrator == INTEGRATOR_SYMPLECTIC;
    fputs("/* Velocity boundary conditions of every body at time t (also the initial conditions). */\n"
          "static void model_velocity_bcs(sph_sim *s, double t)\n{\n", out);
    for (int i = 0; i < m->nbodies; i++)
        if (E->plans[i].velocity_bcs)
            fprintf(out, "    %s_velocity_bcs(&s->bodies[%d], t, s->dt);\n", m->bodies[i].name, i);
    fputs("    (void)s;\n    (void)t;\n}\n\n", out);
    fprintf(out, "/* One time step of every body: %s. */\n"
                 "static void model_step(sph_sim *s, double dt)\n{\n"
                 "    const double t = s->t, t_half = t + 0.5 * dt, t_next = t + dt;\n",
            sym ? "symplectic predictor-corrector (Alg. 2)" : "Verlet (Alg. 1)");
    emit_step_bodies(E, "&s->bodies[%d]", "SPH_PASS(sph_contact_forces, (s, dt))");
    fputs("    (void)t, (void)t_half, (void)t_next;\n}\n\n", out);
    emit_stress_output(E, "");
}

void emit_stress_output(Emitter *E, const char *from)
{
    fprintf(E->out, "/* Cauchy stress of every particle, for output%s. */\n"
                    "static void model_stress_output(sph_sim *s)\n{\n", from);
    for (int i = 0; i < E->m->nbodies; i++)
        fprintf(E->out, "    %s_stress_output(&s->bodies[%d]);\n", emit_code_name(E, i), i);
    fputs("}\n\n", E->out);
}

