/* emit_desc.c — the scene description the runtime reads (sphrt.h): shapes, bodies, their
 * boundary conditions, measurement planes and fracture, the expectations, the scene's
 * settings, and main(). */
#include <math.h>
#include <stdio.h>

#include <string.h>

#include "emit_fracture.h"
#include "emit_internal.h"
#include "emit_quote.h"
#include "lang/bc_kinds.h"
#include "util/source.h"

/* The corners of the prisms and pyramids of region `name`, and the maps that move its
 * surfaces (4 vectors: sph_mesh_load_moved), one table each (NAME_corners_K), which its
 * sph_shape table then points to. */
static void region_corners(Emitter *E, const char *name, const Region *r)
{
    for (int k = 0; k < r->n; k++) {
        const ShapePrim *s = &r->prims[k];
        if (!s->npts)
            continue;
        fprintf(E->out, "static const double %s_corners_%d[] = {\n", name, k);
        for (int q = 0; q < s->npts; q++)
            fprintf(E->out, "    %.17g, %.17g, %.17g,\n", s->pts[3 * q], s->pts[3 * q + 1],
                    s->pts[3 * q + 2]);
        fputs("};\n", E->out);
    }
}

static void region(Emitter *E, const char *name, const Region *r)
{
    static const char *const kinds[] = {"SPH_BOX",  "SPH_CYLINDER", "SPH_SPHERE",
                                        "SPH_MESH", "SPH_PRISM",    "SPH_PYRAMID"};
    region_corners(E, name, r);
    fprintf(E->out, "static const sph_shape %s[] = {\n", name);
    for (int k = 0; k < r->n; k++) {
        const ShapePrim *s = &r->prims[k];
        fprintf(E->out, "    {%s, {%.17g, %.17g, %.17g}, {%.17g, %.17g, %.17g}, %.17g, %d, ",
                kinds[s->kind], s->a[0], s->a[1], s->a[2], s->b[0], s->b[1], s->b[2], s->r,
                s->subtract);
        if (s->file)
            emit_c_string(E->out, s->file);
        else
            fputs("NULL", E->out);
        if (s->npts)
            fprintf(E->out, ", %s_corners_%d, %d},\n", name, k, s->npts);
        else
            fputs(", NULL, 0},\n", E->out);
    }
    fputs("};\n", E->out);
}

/* What a BC sets, "velocity z" or "force surface x, z", for the runtime's messages. */
static void bc_what(const BcModel *bc, char *buf, size_t size)
{
    int len = snprintf(buf, size, "%s", BC_KIND[bc->kind].written);
    for (int axis = 0, first = 1; axis < 3 && len > 0 && (size_t)len < size; axis++)
        if (bc->comps >> axis & 1) {
            len += snprintf(buf + len, size - (size_t)len, "%s%c", first ? " " : ", ", "xyz"[axis]);
            first = 0;
        }
}

/* A time of a BC's window as C: a number, or INFINITY for an open end. */
static void emit_time(FILE *out, double t)
{
    if (isfinite(t))
        fprintf(out, "%.17g", t);
    else
        fputs(t < 0 ? "-INFINITY" : "INFINITY", out);
}

/* Entry k of a body's sph_bc_desc table: its `near` region, its line, its value function,
 * its time window. */
static void bc_desc(Emitter *E, const BodyModel *b, int k)
{
    const BcModel *bc = &b->bcs[k];
    char what[64], value[160] = "NULL";
    bc_what(bc, what, sizeof what);
    if (bc->comps)
        snprintf(value, sizeof value, "%s_bc%d", b->name, k);
    if (bc->has_near)
        fprintf(E->out, "    {1, {%s_near%d, %d, 0, {0, 0, 0}}, ", b->name, k, bc->near.n);
    else
        fputs("    {0, {NULL, 0, 0, {0, 0, 0}}, ", E->out);
    emit_where(E->out, bc->loc);
    fputs(", ", E->out);
    emit_c_string(E->out, what);
    fprintf(E->out, ", %s, ", value);
    emit_time(E->out, bc->has_window ? bc->t0 : -INFINITY);
    fputs(", ", E->out);
    emit_time(E->out, bc->has_window ? bc->t1 : INFINITY);
    fputs("},\n", E->out);
}

static void body_desc_arrays(Emitter *E, const BodyModel *b)
{
    FILE *out = E->out;
    char name[200];
    snprintf(name, sizeof name, "%s_shape", b->name);
    region(E, name, &b->region);
    for (int k = 0; k < b->nbcs; k++)
        if (b->bcs[k].has_near) {
            snprintf(name, sizeof name, "%s_near%d", b->name, k);
            region(E, name, &b->bcs[k].near);
        }
    if (b->nbcs) {
        fprintf(out, "static const sph_bc_desc %s_bcs[] = {\n", b->name);
        for (int k = 0; k < b->nbcs; k++)
            bc_desc(E, b, k);
        fputs("};\n", out);
    }
    emit_fracture_desc(out, b);
    if (b->nmeasures) {
        fprintf(out, "static const sph_measure_desc %s_measures[] = {\n", b->name);
        for (int k = 0; k < b->nmeasures; k++) {
            const MeasureModel *ms = &b->measures[k];
            fprintf(out, "    {\"%s\", {", ms->name);
            for (int c = 0; c < 4; c++)
                fprintf(out, "{%.17g, %.17g, %.17g}%s", ms->p[c][0], ms->p[c][1], ms->p[c][2],
                        c < 3 ? ", " : "");
            fputs("}},\n", out);
        }
        fputs("};\n", out);
    }
}

/* y of the x-z plane of a 2D body: its `plane`, else the middle of its shape's y range. */
static double plane_y(const BodyModel *b)
{
    if (b->has_plane)
        return b->plane;
    /* A surface, prism or pyramid is cut by the plane (runtime/geom/region.c), so the plane must
     * pass through it; boxes, cylinders and spheres are moved into whatever plane it is. */
    for (int k = 0; k < b->region.n; k++) {
        const ShapePrim *s = &b->region.prims[k];
        if (s->kind == SHAPE_SURFACE || s->kind == SHAPE_PRISM || s->kind == SHAPE_PYRAMID)
            return 0.5 * (s->a[1] + s->b[1]);
    }
    const ShapePrim *s = &b->region.prims[0];
    return s->kind == SHAPE_CYLINDER || s->kind == SHAPE_SPHERE ? s->a[1] : 0.5 * (s->a[1] + s->b[1]);
}

static void bodies_desc(Emitter *E)
{
    const Model *m = E->m;
    FILE *out = E->out;
    for (int i = 0; i < m->nbodies; i++) {
        body_desc_arrays(E, &m->bodies[i]);
        const LawRoots *r = &E->plans[i].roots;
        if (!r->nslots)
            continue;
        fprintf(out, "static const double %s_state_init[%d] = {", m->bodies[i].name, r->nslots);
        for (int k = 0; k < r->nslots; k++)
            fprintf(out, "%s%.17g", k ? ", " : "", r->init[k]);
        fputs("};\n", out);
        /* the names of the scalar state variables, which the VTU files carry */
        fprintf(out, "static const char *const %s_state_names[%d] = {", m->bodies[i].name,
                r->nslots);
        for (int v = 0; v < r->nstates; v++)
            for (int k = 0; k < r->states[v].size; k++)
                fprintf(out, "%s%s%s%s", v || k ? ", " : "", r->states[v].size == 1 ? "\"" : "",
                        r->states[v].size == 1 ? r->states[v].name : "NULL",
                        r->states[v].size == 1 ? "\"" : "");
        fputs("};\n", out);
    }
    fputs("static const sph_body_desc BODIES[] = {\n", out);
    for (int i = 0; i < m->nbodies; i++) {
        const BodyModel *b = &m->bodies[i];
        fprintf(out, "    {\n        .name = \"%s\",\n", b->name);
        fprintf(out, "        .region = {%s_shape, %d, %d, {%.17g, %.17g, %.17g}},\n", b->name,
                b->region.n, b->has_lattice, b->lattice[0], b->lattice[1], b->lattice[2]);
        fprintf(out, "        .refine = %d,\n        .nbsrange = %d,\n", b->refine, b->nbsrange);
        fprintf(out, "        .rho0 = %.17g,\n        .c0 = %.17g, /* eq. 59 */\n", b->rho0, b->c0);
        if (m->dim == 2)
            fprintf(out, "        .y_plane = %.17g,\n", plane_y(b));
        if (b->nbcs)
            fprintf(out, "        .bcs = %s_bcs,\n        .nbcs = %d,\n", b->name, b->nbcs);
        if (b->nmeasures)
            fprintf(out, "        .measures = %s_measures,\n        .nmeasures = %d,\n", b->name,
                    b->nmeasures);
        if (b->fracture.on)
            fprintf(out, "        .fracture = &%s_fracture,\n", b->name);
        if (E->plans[i].nstate)
            fprintf(out, "        .nstate = %d,\n        .state_init = %s_state_init,\n"
                         "        .state_names = %s_state_names,\n",
                    E->plans[i].nstate, b->name, b->name);
        /* (in the order of sph_body_desc's members: C++ wants it, for nvcc) */
        if (E->plans[i].roots.dissipation)
            fprintf(out, "        .dissipation = %d, /* plastic work in state value %d */\n",
                    E->plans[i].roots.dissipation, E->plans[i].roots.dissipation - 1);
        if (E->plans[i].roots.temperature)
            fprintf(out, "        .temperature = %d, /* the temperature in state value %d */\n"
                         "        .heat_capacity = %.17g, /* its specific heat, J/(kg K) */\n",
                    E->plans[i].roots.temperature, E->plans[i].roots.temperature - 1,
                    E->plans[i].roots.heat_capacity);
        if (E->plans[i].viscosity)
            fputs("        .viscous = 1,\n", out);
        if (E->plans[i].vheat)
            fprintf(out, "        .vheat = %d, /* the viscosity's heat into state value %d */\n",
                    E->plans[i].roots.viscous_heat, E->plans[i].roots.viscous_heat - 1);
        if (E->plans[i].crush)
            fputs("        .crush = 1,\n", out);
        if (b->has_clamp) {
            fprintf(out, "        .clamp = 1,\n        .clamp_p = {%.17g, %.17g, %.17g},\n"
                         "        .clamp_n = {%.17g, %.17g, %.17g},\n        .clamp_where = ",
                    b->clamp_p[0], b->clamp_p[1], b->clamp_p[2], b->clamp_n[0], b->clamp_n[1],
                    b->clamp_n[2]);
            emit_where(out, b->clamp_loc);
            fputs(",\n", out);
        }
        if (E->plans[i].quadratic)
            fputs("        .quadratic = 1, /* the gradient exact for quadratic fields */\n", out);
        if (E->plans[i].law_fdot)
            fputs("        .fdot = 1, /* the law reads the rate of F */\n", out);
        if (E->plans[i].law_wave)
            fprintf(out, "        .wavespeed = 1, /* the law gives its wave speed */\n"
                         "        .lam2_rest = %.17g, /* (c0 / its wave speed at rest)^2, at most 1 */\n",
                    E->plans[i].lam2_rest);
        const int blocks = (E->plans[i].offset_blocks ? 1 : 0) | (E->plans[i].momentum_blocks ? 2 : 0);
        if (blocks && !strcmp(E->target->name, "cpu"))
            fprintf(out, "        .offset_blocks = %d, /* the pair passes' offset blocks */\n",
                    blocks);
        if (model_has_contact(m))
            fprintf(out, "        .young = %.17g,\n        .poisson = %.17g, /* contact stiffness */\n"
                         "        .restitution = %.17g,\n        .friction = %.17g,\n",
                    b->E, b->nu, b->restitution, b->friction);
        fputs("    },\n", out);
    }
    fputs("};\n\n", out);
}

/* A reference read from a CSV file: its rows, linearly interpolated (NaN outside them). */
static void reference_table(Emitter *E, const ExpectModel *x, int i)
{
    FILE *out = E->out;
    fprintf(out, "/* %s:%d: %s\n * %d rows of %s */\n", source_basename(x->loc.file), x->loc.line,
            emit_line_of(x->loc), x->ref_n, source_basename(x->ref_file));
    for (int col = 0; col < 2; col++) {
        const double *v = col ? x->ref_v : x->ref_t;
        fprintf(out, "static const double reference%d_%c[%d] = {", i, col ? 'v' : 't', x->ref_n);
        for (int k = 0; k < x->ref_n; k++)
            fprintf(out, "%s%.17g", k % 4 ? ", " : k ? ",\n    " : "\n    ", v[k]);
        fputs("\n};\n", out);
    }
    fprintf(out, "static double reference%d(double t)\n{\n"
                 "    return sph_table_interp(reference%d_t, reference%d_v, %d, t);\n}\n\n",
            i, i, i, x->ref_n);
}

static void expects(Emitter *E)
{
    const Model *m = E->m;
    FILE *out = E->out;
    for (int i = 0; i < m->nexpects; i++)
        if (m->expects[i].kind == EXPECT_REFERENCE && m->expects[i].ref_t)
            reference_table(E, &m->expects[i], i);
        else if (m->expects[i].kind == EXPECT_REFERENCE) {
            static char *const t_only[] = {"t"};
            EmitScope s = {m, (char **)t_only, 1, ""};
            fprintf(out, "/* %s:%d: %s */\nstatic double reference%d(double t)\n{\n    return ",
                    source_basename(m->expects[i].loc.file), m->expects[i].loc.line,
                    emit_line_of(m->expects[i].loc), i);
            emit_expr(out, &s, m->expects[i].reference);
            fputs(";\n}\n\n", out);
        }
    if (!m->nexpects)
        return;
    static const char *const kinds[] = {"SPH_EXPECT_PERIOD", "SPH_EXPECT_AMPLITUDE",
                                        "SPH_EXPECT_ENERGY", "SPH_EXPECT_REFERENCE"};
    fputs("static const sph_expect_desc EXPECTS[] = {\n", out);
    for (int i = 0; i < m->nexpects; i++) {
        const ExpectModel *x = &m->expects[i];
        char ref[32] = "NULL";
        if (x->kind == EXPECT_REFERENCE)
            snprintf(ref, sizeof ref, "reference%d", i);
        fprintf(out, "    {%s, \"", kinds[x->kind]);
        for (const char *c = emit_line_of(x->loc); *c; c++)
            fprintf(out, *c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
        fprintf(out, "\", %d, %d, %d, %.17g, %.17g, %s},\n", x->body, x->measure, x->quantity,
                x->value, x->tolerance, ref);
    }
    fputs("};\n\n", out);
}

/* The runtime's entry point that main() calls: sph_mpi_main (libsphrt_mpi) runs the model on
 * the processes mpirun starts (docs/mpi.md), sph_main in one process. */
static const char *main_entry(const Emitter *E)
{
    return E->mpi ? "sph_mpi_main" : "sph_main";
}

void emit_model_desc(Emitter *E)
{
    const Model *m = E->m;
    FILE *out = E->out;
    /* timestep auto: the Courant number on the current spacing at most SPH_CFL_CURRENT
     * (lambda_on = CFL / 0.4, at most 1); stretch: lambda_on = 1; undeformed and a fixed dt:
     * none (docs/stability.md) */
    char lambda_on[64] = "";
    if (model_has_crush(m))
        snprintf(lambda_on, sizeof lambda_on, "    .dt_lambda_on = %.17g,\n",
                 m->dt_mode == TIMESTEP_STRETCH ? 1.0 : fmin(1.0, m->cfl / SPH_CFL_CURRENT));
    char checkpoint[64] = ""; /* (the scene's `checkpoint`) */
    if (m->t_checkpoint > 0)
        snprintf(checkpoint, sizeof checkpoint, "    .t_checkpoint = %.17g,\n", m->t_checkpoint);
    fputs(E->target->desc_prologue, out);
    bodies_desc(E);
    expects(E);
    if (model_has_contact(m))
        fprintf(out, "/* Contact between the bodies (runtime/contact/contact.c). */\n"
                     "static const sph_contact_desc CONTACT = {.coef = %.17g};\n\n", m->contact);
    fprintf(out,
            "static const sph_model MODEL = {\n"
            "    .name = \"%s\",\n    .source = \"%s\",\n    .dim = %d,\n    .dp = %.17g,\n"
            "    .kernel = %s,\n    .coefh = %.17g,\n    .integrator = %s,\n    .cfl = %.17g,\n"
            "    .dtmin_coef = %.17g,\n    .dt_fixed = %.17g,\n    .t_end = %.17g,\n"
            "    .t_out = %.17g,\n%s    .gravity = {%.17g, %.17g, %.17g},\n"
            "    .bodies = BODIES,\n    .nbodies = %d,\n    .expects = %s,\n    .nexpects = %d,\n"
            "    .compat_outputs = %d,\n%s%s%s"
            "    .velocity_bcs = model_velocity_bcs,\n    .step = model_step,\n"
            "    .stress_output = model_stress_output,\n%s};\n\n"
            "int main(int argc, char **argv)\n{\n    return %s(&MODEL, argc, argv);\n}\n",
            m->name, source_basename(m->source), m->dim, m->dp,
            m->kernel == KERNEL_WENDLAND ? "SPH_WENDLAND" : "SPH_CUBIC", m->coefh,
            m->integrator == INTEGRATOR_VERLET ? "SPH_VERLET" : "SPH_SYMPLECTIC", m->cfl, m->dtmin,
            m->dt, m->t_end, m->t_out, checkpoint, m->gravity[0], m->gravity[1], m->gravity[2], m->nbodies,
            m->nexpects ? "EXPECTS" : "NULL", m->nexpects, m->compat_outputs,
            lambda_on,
            model_has_contact(m) ? "    .contact = &CONTACT,\n" : "",
            m->no_simd ? "    .scalar = 1, /* sphc --no-simd: the pair passes on the lists */\n" : "",
            E->target->desc_members, main_entry(E));
}
