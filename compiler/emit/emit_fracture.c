/* emit_fracture.c — the generated code that only bodies with phase-field fracture get:
 * the material law with its tension/compression split and degradation (eq. 7, 18), the
 * restriction of the phase field, and the fracture part of the body description (notches).
 * The passes themselves are in templates/ under //@if FRACTURE. */

#include "emit_fracture.h"
#include "emit_law.h"
#include "emit_quote.h"
#include "util/source.h"

/* static inline void B_material(F, s, S, psi, psip): S = s^2 S+ + S- (eq. 18), psi = s^2 psi+
 * + psi- (eq. 7), and psi+ itself for the history field (eq. 8). */
void emit_fracture_material(FILE *out, const BodyModel *b, const BodyPlan *p, int cuda)
{
    fprintf(out, ".\n * In: deformation gradient F (3x3), phase field s. Out: degraded second "
                 "Piola-Kirchhoff stress\n * S = s^2 S+ + S- (eq. 18), degraded strain energy "
                 "density psi = s^2 psi+ + psi- (eq. 7),\n * tensile energy psi+ (eq. 11/20). */\n");
    fprintf(out, "SPH_FLAT void %s_material(const double F[9], double s, double S[9], "
                 "double *psi, double *psip)\n{\n",
            b->name);
    fputs("    (void)F;\n    (void)s;\n", out);
    emit_law_body(out, b->name, p, cuda, 1);
    fputs("}\n\n", out);
}

/* The lower bound of the phase field: after each update s = max(s, bound) wherever the
 * expression gives a value (skip: no bound there). */
void emit_fracture_restrict(Emitter *E, const BodyModel *b)
{
    FILE *out = E->out;
    const FractureModel *f = &b->fracture;
    if (!f->restrict_expr)
        return;
    char fname[160];
    snprintf(fname, sizeof fname, "%s_phase_min", b->name);
    fprintf(out, "/* %s:%d: %s */\n", source_basename(f->restrict_loc.file), f->restrict_loc.line,
            source_line_trimmed(f->restrict_loc.file, f->restrict_loc.line));
    emit_value_function(out, E->m, fname, f->restrict_expr);
    fprintf(out, "\n/* The restriction of body %s's phase field at time t (after its update). */\n"
                 "static void %s_restrict(sph_body *b, sph_time t, sph_time dt)\n{\n"
                 "    enum { D = %d };\n",
            b->name, b->name, E->m->dim);
    E->target->loop_open(out, "    ", "i", "b->nown");
    fprintf(out, "        sph_pt p;\n        sph_point(b, i, D, t, dt, &p);\n"
                 "        double smin;\n"
                 "        if (%s(&p, &smin) && b->s[i] < smin)\n"
                 "            b->s[i] = smin;\n",
            fname);
    E->target->loop_close(out, "    ");
    fputs("}\n\n", out);
}

/* static const sph_quad B_notches[]; static const sph_fracture_desc B_fracture */
void emit_fracture_desc(FILE *out, const BodyModel *b)
{
    const FractureModel *f = &b->fracture;
    if (!f->on)
        return;
    if (f->nnotches) {
        fprintf(out, "static const sph_quad %s_notches[] = {\n", b->name);
        for (int k = 0; k < f->nnotches; k++) {
            fputs("    {{", out);
            for (int c = 0; c < 4; c++)
                fprintf(out, "{%.17g, %.17g, %.17g}%s", f->notches[k][c][0], f->notches[k][c][1],
                        f->notches[k][c][2], c < 3 ? ", " : "");
            fputs("}},\n", out);
        }
        fputs("};\n", out);
        fprintf(out, "static const char *const %s_notch_where[] = {", b->name);
        for (int k = 0; k < f->nnotches; k++) {
            fputs(k ? ", " : "", out);
            emit_where(out, f->notch_locs[k]);
        }
        fputs("};\n", out);
    }
    fprintf(out, "static const sph_fracture_desc %s_fracture = {\n"
                 "    .Gc = %.17g,\n    .eps0 = %.17g,\n    .limit = %.17g,\n",
            b->name, f->Gc, f->eps0, f->limit);
    if (f->nnotches)
        fprintf(out, "    .notches = %s_notches,\n    .nnotches = %d,\n"
                     "    .notch_where = %s_notch_where,\n",
                b->name, f->nnotches, b->name);
    if (f->restrict_expr) {
        fputs("    .restrict_where = ", out);
        emit_where(out, f->restrict_loc);
        fprintf(out, ",\n    .restrict_value = %s_phase_min,\n", b->name);
    }
    fputs("};\n", out);
}
