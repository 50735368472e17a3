/* model_dump.c — printing the checked model (sphc --dump=model). */
#include <stdio.h>
#include <string.h>

#include "model.h"
#include "lang/bc_kinds.h"

static void region(FILE *out, const char *what, const Region *r)
{
    static const char *const kinds[] = {"box", "cylinder", "sphere", "surface", "prism",
                                        "pyramid"};
    fprintf(out, "    %s:", what);
    for (int k = 0; k < r->n; k++) {
        const ShapePrim *s = &r->prims[k];
        fprintf(out, " %s%s a=[%g %g %g] b=[%g %g %g] r=%g", s->subtract ? "- " : k ? "+ " : "",
                kinds[s->kind], s->a[0], s->a[1], s->a[2], s->b[0], s->b[1], s->b[2], s->r);
        if (s->kind == SHAPE_SURFACE)
            fprintf(out, " volume=%.6g file=%s%s", s->volume, s->file, s->npts ? " moved" : "");
        else if (s->npts)
            fprintf(out, " volume=%.6g corners=%d", s->volume, s->npts);
    }
    fputs("\n", out);
}

/* A body's settings as a model would give them (body_settings.h), those with members of their
 * own as theirs. */
static void settings(FILE *out, const BodyModel *b)
{
    fputs("    settings:", out);
    for (int k = 0; k < BODY_NSETTINGS; k++) {
        const BodySetting *s = &BODY_SETTING_ROWS[k];
        const double *v = body_setting_point(b, s);
        if (s->form == SET_INT || s->form == SET_NUMBER)
            fprintf(out, " %s %g", s->keyword, body_setting_value(b, s));
        else if (s->form == SET_POINT && body_setting_value(b, s))
            fprintf(out, " %s [%g %g %g]", s->keyword, v[0], v[1], v[2]);
        else if (!strcmp(s->keyword, "viscosity"))
            fprintf(out, " viscosity %g %g", b->beta1, b->beta2);
        else if (!strcmp(s->keyword, "plane") && b->has_plane)
            fprintf(out, " plane %g", b->plane);
        else if (!strcmp(s->keyword, "clamp") && b->has_clamp)
            fprintf(out, " clamp [%g %g %g] [%g %g %g]", b->clamp_p[0], b->clamp_p[1],
                    b->clamp_p[2], b->clamp_n[0], b->clamp_n[1], b->clamp_n[2]);
    }
    fputs("\n", out);
}

static void body(FILE *out, const BodyModel *b)
{
    fprintf(out, "  body %s\n", b->name);
    region(out, "shape", &b->region);
    settings(out, b);
    fprintf(out, "    density %g\n", b->rho0);
    fprintf(out, "    elastic E %g nu %g lambda %g mu %g K %g  c0 %g m/s\n", b->E, b->nu, b->lambda,
            b->mu, b->K, b->c0);
    fprintf(out, "    material %s(", b->law->name);
    for (int k = 0; k < b->law->nparams; k++)
        fprintf(out, "%s%s = %g", k ? ", " : "", b->law->params[k], b->law_args[k]);
    fputs(")\n", out);
    for (int k = 0; k < b->nbcs; k++) {
        const BcModel *bc = &b->bcs[k];
        fprintf(out, "    bc %d: %s comps %s%s%s window [%g, %g]%s (line %d)\n", k,
                BC_KIND[bc->kind].written,
                bc->comps & 1 ? "x" : "", bc->comps & 2 ? "y" : "", bc->comps & 4 ? "z" : "",
                bc->t0, bc->t1, bc->has_near ? " near shape" : "", bc->loc.line);
    }
    for (int k = 0; k < b->nmeasures; k++)
        fprintf(out, "    measure %s\n", b->measures[k].name);
    const FractureModel *f = &b->fracture;
    if (!f->on)
        return;
    fprintf(out, "    fracture Gc %g length %g limit %g%s\n", f->Gc, f->eps0, f->limit,
            f->restrict_expr ? "  restricted" : "");
    for (int k = 0; k < f->nnotches; k++) {
        fputs("    notch", out);
        for (int c = 0; c < 4; c++)
            fprintf(out, " [%g %g %g]", f->notches[k][c][0], f->notches[k][c][1],
                    f->notches[k][c][2]);
        fputs("\n", out);
    }
}

void model_dump(const Model *m, FILE *out)
{
    fprintf(out, "model %s (%s)\n", m->name, m->source);
    fprintf(out, "  scene: dim %d dp %g kernel %s coefh %g integrator %s cfl %g dtmin %g dt %g "
                 "end %g output %g gravity [%g %g %g] precision %s\n",
            m->dim, m->dp, m->kernel == KERNEL_WENDLAND ? "wendland" : "cubic", m->coefh,
            m->integrator == INTEGRATOR_VERLET ? "verlet" : "symplectic", m->cfl, m->dtmin, m->dt,
            m->t_end, m->t_out, m->gravity[0], m->gravity[1], m->gravity[2],
            m->single ? "single" : "double");
    if (m->gradient == GRADIENT_QUADRATIC)
        fputs("  gradient: quadratic (exact for quadratic fields, strain-gradient quadrature)\n",
              out);
    if (model_has_contact(m))
        fprintf(out, "  contact between the bodies: stiffness multiplier %g\n", m->contact);
    if (m->t_checkpoint > 0)
        fprintf(out, "  checkpoints every %g s\n", m->t_checkpoint);
    if (m->compat_outputs)
        fputs("  outputs: also SoliDualSPHysics' DeformStruc_Energies.csv and "
              "MeasuringPlData_MK<mk>_PL<k>.csv\n", out);
    for (int i = 0; i < m->nconsts; i++)
        fprintf(out, "  let %s = %.17g\n", m->consts[i].name, m->consts[i].value);
    for (int i = 0; i < m->nfns; i++)
        fprintf(out, "  fn %s/%d\n", m->fns[i].name, m->fns[i].nparams);
    for (int i = 0; i < m->nlaws; i++)
        fprintf(out, "  material law %s/%d\n", m->laws[i]->name, m->laws[i]->nparams);
    for (int i = 0; i < m->nbodies; i++)
        body(out, &m->bodies[i]);
    for (int i = 0; i < m->nexpects; i++)
        fprintf(out, "  expect kind %d body %d measure %d quantity %d value %g tolerance %g\n",
                m->expects[i].kind, m->expects[i].body, m->expects[i].measure,
                m->expects[i].quantity, m->expects[i].value, m->expects[i].tolerance);
}
