/* emit_cuda.c — the CUDA target's own part of the program (model.cu, docs/architecture.md):
 * the scene's step runs every body's passes on its device view (runtime/sph_cuda.h), the
 * device chooses the time steps (its clock), and the stability monitor's periodic look sums
 * on the device too.  The rest is shared with the CPU target (emit_target.c). */
#include <stdio.h>

#include "emit_internal.h"

/* The scene's step for the CUDA target: every body's passes on its device view. */
static void scene_step_cuda(Emitter *E)
{
    const Model *m = E->m;
    FILE *out = E->out;
    const int contact = model_has_contact(m);
    fprintf(out, "/* The bodies' device views (runtime/sph_cuda.h)%s,\n"
                 " * made at the first device pass. */\nstatic sph_body *DEV[%d];\n%s\n"
                 "static void model_upload(sph_sim *s)\n{\n    if (DEV[0])\n        return;\n"
                 "    for (int i = 0; i < %d; i++)\n        DEV[i] = sph_cuda_body(&s->bodies[i]);\n",
            contact ? " and the contact state (sph_cuda_contact.h)" : "", m->nbodies,
            contact ? "static sph_cuda_contact CONTACT_DEV;\n" : "", m->nbodies);
    if (contact)
        fputs("    sph_cuda_contact_init(&CONTACT_DEV, s);\n", out);
    fputs("}\n\n", out);
    fputs("/* Velocity boundary conditions at time t, on the device (the initial conditions: the\n"
          " * host copy follows for the runtime's first look). */\n"
          "static void model_velocity_bcs(sph_sim *s, double t)\n{\n    model_upload(s);\n", out);
    for (int i = 0; i < m->nbodies; i++)
        if (E->plans[i].velocity_bcs)
            fprintf(out, "    %s_velocity_bcs(DEV[%d], t, s->dt);\n", m->bodies[i].name, i);
    for (int i = 0; i < m->nbodies; i++)
        fprintf(out, "    sph_cuda_to_host(&s->bodies[%d], DEV[%d]);\n", i, i);
    fputs("    (void)t;\n}\n\n", out);
    fprintf(out, "/* One time step of every body on the device: %s, from t, of dt (values, or\n"
                 " * the device clock's: sph_cuda.h). */\n"
                 "static void model_passes(sph_time t, sph_time dt, sph_time t_half, sph_time t_next,\n"
                 "                         sph_time law_dt)\n{\n",
            m->integrator == INTEGRATOR_SYMPLECTIC ? "symplectic predictor-corrector (Alg. 2)"
                                                    : "Verlet (Alg. 1)");
    emit_step_bodies(E, "DEV[%d]", "sph_cuda_contact_forces(&CONTACT_DEV, DEV, dt)");
    fputs("    (void)t, (void)t_half, (void)t_next, (void)law_dt;\n}\n\n", out);
    fputs("/* The step's sums into the host bodies: the time step, energies and output read them. */\n"
          "static void model_sums_to_host(sph_sim *s)\n{\n", out);
    for (int i = 0; i < m->nbodies; i++)
        fprintf(out, "    sph_cuda_reductions(&s->bodies[%d], DEV[%d]);\n", i, i);
    if (contact)
        fputs("    sph_cuda_contact_to_host(&CONTACT_DEV, s);\n", out);
    fputs("    (void)s;\n}\n\n", out);
    /* the time since a law's last evaluation: the stress pass is at the step's start
     * (Verlet) or its middle (symplectic) */
    const int sym = m->integrator == INTEGRATOR_SYMPLECTIC;
    fprintf(out, "/* One time step of dt, which the host chose (sph_sim_step); the host waits at its end\n"
                 " * for the sums the next time step needs (eq. 64-66). */\n"
                 "static void model_step(sph_sim *s, double dt)\n{\n"
                 "    model_passes(s->t, dt, s->t + 0.5 * dt, s->t + dt, %s);\n"
                 "    SPH_CUDA_CHECK(cudaGetLastError());\n    model_sums_to_host(s);\n}\n\n",
            sym ? "0.5 * (s->dt_prev + dt)" : "s->dt_prev");
    fprintf(out, "/* One time step of every body, of the time step the device's clock chooses. */\n"
                 "static void model_clock_step()\n{\n"
                 "    model_passes(sph_time::clock(SPH_CLOCK_T), sph_time::clock(SPH_CLOCK_DT),\n"
                 "                 sph_time::clock(SPH_CLOCK_T_HALF), sph_time::clock(SPH_CLOCK_T_NEXT),\n"
                 "                 sph_time::clock(%s));\n"
                 "}\n\n"
                 "/* Up to a->steps steps until a->t_stop (sph_sim_advance): the device chooses each\n"
                 " * time step itself (its clock, sph_cuda.h), so the host queues them without waiting\n"
                 " * for the sums. */\n"
                 "static void model_advance(sph_sim *s, sph_advance *a)\n{\n"
                 "    sph_cuda_advance(s, a, DEV, %s, model_clock_step);\n"
                 "    model_sums_to_host(s);\n}\n\n",
            sym ? "SPH_CLOCK_DT_MEAN" : "SPH_CLOCK_DT_PREV",
            contact ? "sph_cuda_contact_sums(&CONTACT_DEV), CONTACT_DEV.w2ref" : "NULL, 0.0");
    fputs("/* The device state into the host bodies, for the runtime to read. */\n"
          "static void model_sync_host(sph_sim *s)\n{\n", out);
    for (int i = 0; i < m->nbodies; i++)
        fprintf(out, "    sph_cuda_to_host(&s->bodies[%d], DEV[%d]);\n", i, i);
    fputs("}\n\n/* The whole state between the device and the host bodies: to the host for a\n"
          " * checkpoint, to the device for a run resumed from one. */\n"
          "static void model_copy_state(sph_sim *s, int to_device)\n{\n", out);
    for (int i = 0; i < m->nbodies; i++)
        fprintf(out, "    sph_cuda_state_copy(&s->bodies[%d], DEV[%d], to_device);\n", i, i);
    if (contact)
        fputs("    if (to_device)\n        sph_cuda_contact_from_host(&CONTACT_DEV, s);\n", out);
    fputs("}\n\n", out);
    emit_stress_output(E, " (from the host copy)");
}

/* The stability monitor's pass: every body's sums on the device, back to the host. */
static void scene_monitor_cuda(Emitter *E)
{
    const Model *m = E->m;
    FILE *out = E->out;
    fputs("/* The stability monitor's sums of every body, summed on the device so that a\n"
          " * periodic check copies a few numbers, not the state (runtime/run/monitor.c). */\n"
          "static void model_monitor(sph_sim *s, sph_monitor_sums *out)\n{\n", out);
    for (int i = 0; i < m->nbodies; i++)
        fprintf(out, "    %s_monitor(DEV[%d]);\n", emit_code_name(E, i), i);
    fputs("    SPH_CUDA_CHECK(cudaGetLastError());\n", out);
    for (int i = 0; i < m->nbodies; i++)
        fprintf(out, "    sph_cuda_monitor_sums(DEV[%d], &out[%d]);\n", i, i);
    fputs("    (void)s;\n}\n\n", out);
}

/* The CUDA target's scene: the step on the device views and the glue the runtime calls
 * (sph_model's step, advance, sync_host, copy_state, monitor). */
void emit_scene_cuda(Emitter *E)
{
    scene_step_cuda(E);
    scene_monitor_cuda(E);
}
