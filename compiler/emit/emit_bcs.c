/* emit_bcs.c — a body's boundary conditions: each one's value as a function of the
 * particle (SPH_FN), and the velocity and force passes that apply them (Alg. 1, step 3),
 * over the whole body or over the particles near a shape, within their time windows. */
#include <math.h>
#include <stdio.h>

#include "emit_internal.h"
#include "emit_quote.h"
#include "lang/bc_kinds.h"
#include "util/source.h"

/* Compact component index of 3D axis `axis` (0 x, 1 y, 2 z) in a dim-D body. */
static int compact(int dim, int axis)
{
    return dim == 2 ? axis / 2 : axis;
}

static void bc_values(Emitter *E, const BodyModel *b)
{
    for (int k = 0; k < b->nbcs; k++) {
        const BcModel *bc = &b->bcs[k];
        if (!bc->comps)
            continue;
        char fname[160];
        snprintf(fname, sizeof fname, "%s_bc%d", b->name, k);
        fprintf(E->out, "/* %s:%d: %s */\n", source_basename(bc->loc.file), bc->loc.line,
                emit_line_of(bc->loc));
        emit_value_function(E->out, E->m, fname, bc->value);
        fputs("\n", E->out);
    }
}

/* The statement applying BC k to particle i (inside the particle loop). */
static void bc_apply(Emitter *E, const BodyModel *b, int k, const char *indent)
{
    const BcModel *bc = &b->bcs[k];
    const int dim = E->m->dim;
    FILE *out = E->out;
    fprintf(out, "%s/* %s:%d */\n%sif (%s_bc%d(&p, &val)) {\n", indent,
            source_basename(bc->loc.file), bc->loc.line, indent, b->name, k);
    for (int axis = 0; axis < 3; axis++) {
        if (!(bc->comps >> axis & 1))
            continue;
        int c = compact(dim, axis);
        if (BC_KIND[bc->kind].pass == BC_VELOCITY)
            fprintf(out, "%s    b->v[(size_t)i * D + %d] = val;\n%s    fix |= %d;\n", indent, c,
                    indent, 1 << c);
        else
            fprintf(out, "%s    b->a[(size_t)i * D + %d] += val * scale%d;\n", indent, c, k);
    }
    fprintf(out, "%s}\n", indent);
}

/* The factor of force BC k's value in the acceleration (its kind's scale, lang/bc_kinds.h). */
static void force_scale(Emitter *E, const BcModel *bc, int k)
{
    fprintf(E->out, "    const double scale%d = %s;\n", k,
            BC_KIND[bc->kind].scale[E->m->dim == 3]);
}

/* `from t0 to t1`: the BC acts in a step when the middle of the step lies in [t0, t1].  A
 * step that starts at t1 (or ends at t0) is outside the window whatever the round-off in
 * t, so steps landing on t0 and t1 give a force exactly the impulse over t1 - t0 and hold a
 * velocity exactly from t0 to t1.  The symplectic force pass is called at the middle of the
 * step already (at_middle); the other passes at its start (the initial conditions with
 * dt = 0, i.e. at t = 0).  `const int onK = ...;` with the given indent: in the function on
 * the CPU; inside the loops in the CUDA target, where t and dt are read on the device. */
static void window_open(Emitter *E, const BcModel *bc, int k, int middle, const char *indent)
{
    const char *tm = middle ? "t" : "(t + 0.5 * dt)";
    fprintf(E->out, "%sconst int on%d = ", indent, k);
    if (isfinite(bc->t0))
        fprintf(E->out, "%s >= %.17g%s", tm, bc->t0, isfinite(bc->t1) ? " && " : "");
    if (isfinite(bc->t1))
        fprintf(E->out, "%s <= %.17g", tm, bc->t1);
    if (!isfinite(bc->t0) && !isfinite(bc->t1))
        fputs("1", E->out);
    fputs(";\n", E->out);
}

/* Whether a BC is one of the pass's: its kind's pass, with components, with or without
 * `near`. */
static int bc_in_pass(const BcModel *bc, BcPass pass, int near)
{
    return BC_KIND[bc->kind].pass == pass && bc->comps && bc->has_near == near;
}

/* Whether the pass is called at the middle of the step (the symplectic force pass). */
static int at_middle(const Emitter *E, BcPass pass)
{
    return pass == BC_FORCE && E->m->integrator == INTEGRATOR_SYMPLECTIC;
}

/* The windows of the pass's BCs without `near`, at the top of the CUDA target's loop. */
static void windows_open(Emitter *E, const BodyModel *b, BcPass pass, const char *indent)
{
    for (int k = 0; k < b->nbcs; k++)
        if (bc_in_pass(&b->bcs[k], pass, 0) && b->bcs[k].has_window)
            window_open(E, &b->bcs[k], k, at_middle(E, pass), indent);
}

/* The loop over the BCs with `near`, one per BC: over its particle list. */
static void bc_near_loops(Emitter *E, const BodyModel *b, BcPass pass)
{
    FILE *out = E->out;
    const int vel = pass == BC_VELOCITY;
    for (int k = 0; k < b->nbcs; k++) {
        const BcModel *bc = &b->bcs[k];
        if (!bc_in_pass(bc, pass, 1))
            continue;
        const int in_loop = E->target->windows_in_loops;
        if (bc->has_window && !in_loop)
            fprintf(out, "    if (on%d) {\n", k);
        else
            fputs("    {\n", out);
        char count[64];
        snprintf(count, sizeof count, "b->bc_count[%d]", k);
        E->target->loop_open(out, "        ", "q", count);
        if (bc->has_window && in_loop) {
            window_open(E, bc, k, at_middle(E, pass), "            ");
            fprintf(out, "            if (!on%d)\n                return;\n", k);
        }
        fprintf(out, "            const int i = b->bc_list[%d][q];\n"
                     "            sph_pt p;\n            sph_point(b, i, D, t, dt, &p);\n"
                     "            double val;\n",
                k);
        if (vel)
            fputs("            uint8_t fix = b->fix[i];\n", out);
        bc_apply(E, b, k, "            ");
        if (vel)
            fputs("            b->fix[i] = fix;\n", out);
        E->target->loop_close(out, "        ");
        fputs("    }\n", out);
    }
}

/* One pass over the whole body for the BCs without `near`, then one loop per `near` list. */
static void bc_pass(Emitter *E, const BodyModel *b, BcPass pass)
{
    FILE *out = E->out;
    int vel = pass == BC_VELOCITY;
    fprintf(out, "/* %s boundary conditions of body %s at time t (Alg. 1, step 3). */\n",
            vel ? "Velocity" : "Force", b->name);
    fprintf(out, "static void %s_%s_bcs(sph_body *b, sph_time t, sph_time dt)\n{\n"
                 "    enum { D = %d };\n",
            b->name, vel ? "velocity" : "force", E->m->dim);
    int any_whole = 0;
    for (int k = 0; k < b->nbcs; k++) {
        const BcModel *bc = &b->bcs[k];
        if (BC_KIND[bc->kind].pass != pass || !bc->comps)
            continue;
        if (bc->has_window && !E->target->windows_in_loops)
            window_open(E, bc, k, at_middle(E, pass), "    ");
        if (!vel)
            force_scale(E, bc, k);
        any_whole |= !bc->has_near;
    }
    if (vel || any_whole) {
        E->target->loop_open(out, "    ", "i", "b->nown");
        if (E->target->windows_in_loops)
            windows_open(E, b, pass, "        ");
        /* Without a whole-body BC, the velocity pass's loop only clears the fix bits. */
        if (any_whole)
            fputs("        sph_pt p;\n        sph_point(b, i, D, t, dt, &p);\n        double val;\n", out);
        if (vel)
            fputs("        uint8_t fix = 0;\n", out);
        for (int k = 0; k < b->nbcs; k++) {
            const BcModel *bc = &b->bcs[k];
            if (!bc_in_pass(bc, pass, 0))
                continue;
            if (bc->has_window)
                fprintf(out, "        if (on%d)\n", k);
            fputs(bc->has_window ? "        {\n" : "", out);
            bc_apply(E, b, k, bc->has_window ? "            " : "        ");
            fputs(bc->has_window ? "        }\n" : "", out);
        }
        if (vel)
            fputs("        b->fix[i] = fix;\n", out);
        E->target->loop_close(out, "    ");
    }
    bc_near_loops(E, b, pass);
    fputs("    (void)t;\n    (void)dt;\n}\n\n", out);
}

void emit_bc_passes(Emitter *E, const BodyModel *b, const BodyPlan *p)
{
    bc_values(E, b);
    if (p->velocity_bcs)
        bc_pass(E, b, BC_VELOCITY);
    if (p->force_bcs)
        bc_pass(E, b, BC_FORCE);
}
