/* emit_functions.c — the generated program's functions that both targets compile for the
 * host and the device (SPH_FN): the model's constants and user functions, and each body's
 * material law from its folded scalar graph. */
#include <stdlib.h>
#include <string.h>

#include "emit_fracture.h"
#include "emit_internal.h"
#include "emit_law.h"
#include "emit_quote.h"
#include "util/source.h"

/* Whether expression e names `name`: as a variable (kind EX_NAME) or as a function it
 * calls (EX_CALL). */
static int names(const Expr *e, ExprKind kind, const char *name)
{
    if (e->kind == kind && !strcmp(e->name, name))
        return 1;
    for (int i = 0; i < e->nargs; i++)
        if (names(e->args[i], kind, name))
            return 1;
    return 0;
}

/* Whether an expression the program evaluates at run time names `name` (names): a boundary
 * condition's value, a phase field's bound, a reference solution.  The others (shapes,
 * settings, the material laws) were folded into numbers or law graphs by the compiler. */
static int run_time_names(const Model *m, ExprKind kind, const char *name)
{
    for (int i = 0; i < m->nbodies; i++) {
        const BodyModel *b = &m->bodies[i];
        for (int k = 0; k < b->nbcs; k++)
            if (b->bcs[k].comps && names(b->bcs[k].value, kind, name))
                return 1;
        if (b->fracture.restrict_expr && names(b->fracture.restrict_expr, kind, name))
            return 1;
    }
    for (int i = 0; i < m->nexpects; i++)
        if (m->expects[i].reference && names(m->expects[i].reference, kind, name))
            return 1;
    return 0;
}

/* used[i]: whether user function i is called at run time, by a run-time expression or by a
 * function that is (a function only a material law calls is in the law's graph). */
static void fns_used(const Model *m, char *used)
{
    for (int i = 0; i < m->nfns; i++)
        used[i] = (char)run_time_names(m, EX_CALL, m->fns[i].name);
    for (int changed = 1; changed;) {
        changed = 0;
        for (int i = 0; i < m->nfns; i++)
            for (int j = 0; j < m->nfns && !used[i]; j++)
                if (used[j] && names(m->fns[j].body, EX_CALL, m->fns[i].name))
                    used[i] = changed = 1;
    }
}

/* Whether constant `name` appears in an expression the program evaluates at run time (the
 * others were folded into numbers by the compiler and need no C constant). */
static int const_used(const Model *m, const char *used, const char *name)
{
    for (int i = 0; i < m->nfns; i++) {
        int shadowed = 0;
        for (int k = 0; k < m->fns[i].nparams; k++)
            shadowed |= !strcmp(m->fns[i].params[k], name);
        if (used[i] && !shadowed && names(m->fns[i].body, EX_NAME, name))
            return 1;
    }
    return run_time_names(m, EX_NAME, name);
}

void emit_consts_fns(Emitter *E)
{
    const Model *m = E->m;
    char *used = calloc((size_t)m->nfns + 1, 1);
    fns_used(m, used);
    int any = 0;
    for (int i = 0; i < m->nconsts; i++)
        if (const_used(m, used, m->consts[i].name)) {
            fprintf(E->out, "static const double k_%s = %.17g; /* %s:%d */\n", m->consts[i].name,
                m->consts[i].value, source_basename(m->consts[i].loc.file), m->consts[i].loc.line);
            any = 1;
        }
    for (int i = 0; i < m->nfns; i++) {
        const FnDef *f = &m->fns[i];
        if (!used[i])
            continue;
        fprintf(E->out, "\n/* %s:%d: %s */\nSPH_FN double f_%s(", source_basename(f->loc.file),
                f->loc.line, emit_line_of(f->loc), f->name);
        for (int k = 0; k < f->nparams; k++)
            fprintf(E->out, "%sdouble a_%s", k ? ", " : "", f->params[k]);
        if (!f->nparams)
            fputs("void", E->out);
        fputs(")\n{\n    return ", E->out);
        EmitScope s = {m, f->params, f->nparams, "a_"};
        emit_expr(E->out, &s, f->body);
        fputs(";\n}\n", E->out);
        any = 1;
    }
    free(used);
    if (any)
        fputs("\n", E->out);
}

/* The material function's argument after psi: the wave speed, where its law gives one. */
static const char *wave_output(const BodyPlan *p)
{
    return p->law_wave ? ", double *cw" : "";
}

/* The material function's arguments after F: Fdot and dt, where its law reads them. */
static const char *extra_inputs(const BodyPlan *p)
{
    static const char *const args[2][2] = {{"", "double dt, "},
                                           {"const double Fd[9], ", "const double Fd[9], double dt, "}};
    return args[p->law_fdot][p->law_dt];
}

void emit_material(Emitter *E, const BodyModel *b, const BodyPlan *p)
{
    FILE *out = E->out;
    fprintf(out, "/* ==== body %s ==== */\n\n", b->name);
    const int cuda = E->target == emit_target(TARGET_CUDA);
    emit_law_pieces(out, b->name, p, cuda);
    fprintf(out, "/* Material law '%s' (%s:%d), constants folded:",
            b->law->name, source_basename(b->law->loc.file), b->law->loc.line);
    for (int k = 0; k < b->law->nparams; k++)
        fprintf(out, " %s = %g", b->law->params[k], b->law_args[k]);
    if (p->fracture) {
        emit_fracture_material(out, b, p, cuda);
        return;
    }
    const LawRoots *r = &p->roots;
    if (p->nstate) {
        fprintf(out, ".\n * In: deformation gradient F (3x3),%s%s the particle's state st (%d values:",
                p->law_fdot ? " its rate Fd," : "",
                p->law_dt ? " dt (the time since the law's last evaluation)," : "", p->nstate);
        for (int k = 0; k < r->nstates; k++)
            fprintf(out, " %s%s", r->states[k].name, r->states[k].size == 9 ? "[9]" : "");
        fprintf(out, ").\n * Out: second Piola-Kirchhoff stress S, strain energy density psi, "
                     "the state at the end of the step st_new. */\n");
        fprintf(out, "SPH_FLAT void %s_material(const double F[9], %sconst double *st, "
                     "double *st_new, double S[9],\n                                   double *psi%s)\n{\n",
                b->name, extra_inputs(p), wave_output(p));
    } else {
        fprintf(out, ".\n * In: deformation gradient F (3x3)%s%s. Out: second Piola-Kirchhoff "
                     "stress S, strain energy density psi. */\n", p->law_fdot ? ", its rate Fd" : "",
                p->law_dt ? ", dt" : "");
        fprintf(out, "SPH_FLAT void %s_material(const double F[9], %sdouble S[9], double *psi%s)\n{\n",
                b->name, extra_inputs(p), wave_output(p));
    }
    fputs(p->nstate ? "    (void)F;\n    (void)st;\n" : "    (void)F;\n", out);
    if (p->law_dt)
        fputs("    (void)dt;\n", out);
    if (p->law_fdot)
        fputs("    (void)Fd;\n", out);
    emit_law_body(out, b->name, p, cuda, 0);
    fputs("}\n\n", out);
    if (!p->rare)
        return;
    fprintf(out, "/* The same law as if none of its `if` blocks without `else` were taken (the\n"
                 " * return map's correction of a particle that does not yield), and *rare nonzero\n"
                 " * where one should have been: there the results are not the law's, and the\n"
                 " * stress pass takes %s_material's instead (templates/body_forces.c). */\n",
            b->name);
    fprintf(out, "SPH_FLAT void %s_material_fast(const double F[9], %sconst double *st, "
                 "double *st_new,\n                                        double S[9], "
                 "double *psi%s, double *rare)\n{\n", b->name, extra_inputs(p), wave_output(p));
    fputs(p->law_dt ? "    (void)F;\n    (void)dt;\n    (void)st;\n" : "    (void)F;\n    (void)st;\n", out);
    if (p->law_fdot)
        fputs("    (void)Fd;\n", out);
    emit_law_fast_body(out, b->name, p, cuda);
    fputs("}\n\n", out);
}
