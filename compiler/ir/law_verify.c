/* law_verify.c — a law's hand-written stress against the derivative of its energy.
 *
 * A law that writes both `stress` and `energy` states its stress twice: S, and
 * S_d = F^-1 dpsi/dF (eq. 10, 17, 31: S = 2 dpsi/dC).  Both are evaluated (sg_eval) at a few
 * fixed deformations in 3D with a body's parameter values; where they differ by more than
 * round-off the stress is not the energy's (a typo, a factor of 2, eq. 52 as printed), and
 * the compiler warns at the `stress` statement.  A law with state is differentiated at its
 * returned state (the state's end values held fixed, as the derived stress is); the
 * `tension` block's S+ is checked against psi+ alike, pos and neg differentiated by their
 * adjoint routine (spectral.c): stdlib svk's S+ = lambda max(tr E, 0) I + 2 mu pos(E)
 * (eq. 17) agrees with its psi+ (eq. 11) to 1e-15, compression and mixed-sign principal
 * strains among the samples.
 *
 * At the same samples every law's energy is checked for objectivity (psi(Q F) = psi(F) for
 * rotations Q: a warning), and each body's law for values that are not finite at and near
 * F = I, where its particles start (an error); its small-strain moduli are compared with the
 * body's elastic constants. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "law.h"

/* The largest relative difference max |S - S_d| / max(|S|, |S_d|) a correct law may show.
 * Both are the same function of F, evaluated in double through different expressions: they
 * agree to 7e-14 for the laws of stdlib/ (J2 with its return included); a wrong law differs
 * by a fraction of S (a factor, a missing term: 0.5 for svk with mu for 2 mu), eq. 52 for J2
 * by 1.9 at a plastic simple shear.  1e-6 leaves round-off eight digits and catches the
 * rest. */
#define LAW_VERIFY_TOLERANCE 1e-6

enum { NSAMPLES = 5 };

typedef struct {
    const char *what;
    double F[9];
} Sample;

/* R(axis, angle) by Rodrigues' formula. */
static void rotation(const double n[3], double a, double R[9])
{
    const double c = cos(a), s = sin(a);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[3 * i + j] = (1 - c) * n[i] * n[j] + (i == j ? c : 0);
    R[1] -= s * n[2], R[2] += s * n[1];
    R[3] += s * n[2], R[5] -= s * n[0];
    R[6] -= s * n[1], R[7] += s * n[0];
}

/* The sample deformations: uniaxial stretch, simple shear, uniaxial compression, a rotation
 * times a stretch, and a general F (no symmetry, J = 1.058). */
static void samples(Sample s[NSAMPLES])
{
    static const Sample fixed[NSAMPLES] = {
        {"F = diag(1.2, 1, 1), a uniaxial stretch", {1.2, 0, 0, 0, 1, 0, 0, 0, 1}},
        {"F = I + 0.3 e_x e_y, a simple shear", {1, 0.3, 0, 0, 1, 0, 0, 0, 1}},
        {"F = diag(0.7, 1, 1), a uniaxial compression", {0.7, 0, 0, 0, 1, 0, 0, 0, 1}},
        {"F = R diag(1.1, 0.9, 1.05), R a rotation by 0.5 about (1, 2, 3)", {0}},
        {"F = [1.1 0.2 -0.1; 0.05 0.95 0.15; -0.12 0.08 1.05]",
         {1.1, 0.2, -0.1, 0.05, 0.95, 0.15, -0.12, 0.08, 1.05}},
    };
    memcpy(s, fixed, sizeof fixed);
    const double n[3] = {1 / sqrt(14.0), 2 / sqrt(14.0), 3 / sqrt(14.0)};
    const double U[3] = {1.1, 0.9, 1.05};
    double R[9];
    rotation(n, 0.5, R);
    for (int k = 0; k < 9; k++)
        s[3].F[k] = R[k] * U[k % 3];
}

typedef struct {
    const double *F;
    const LawRoots *r;
} Point;

/* The graph's inputs at a sample: F, the state at its initial value, an intact phase field. */
static double input_at(const char *name, int index, void *ctx)
{
    const Point *p = ctx;
    if (!strcmp(name, LAW_INPUT_F))
        return p->F[index];
    if (!strcmp(name, LAW_INPUT_STATE))
        return p->r->init[index];
    if (!strcmp(name, LAW_INPUT_S))
        return 1.0;
    if (!strcmp(name, LAW_INPUT_DT) || !strcmp(name, LAW_INPUT_FDOT))
        return 0.0; /* the response at rest: no time for the state, no rate */
    return NAN; /* C or E: replaced by F's, dead */
}

/* F^-1 P (adjugate / det). */
static void solve(const double F[9], const double P[9], double S[9])
{
    double inv[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) { /* inv_ij = cof_ji / det */
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            inv[3 * i + j] = F[3 * r0 + c0] * F[3 * r1 + c1] - F[3 * r0 + c1] * F[3 * r1 + c0];
        }
    const double det = F[0] * inv[0] + F[1] * inv[3] + F[2] * inv[6];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double acc = 0;
            for (int k = 0; k < 3; k++)
                acc += inv[3 * i + k] * P[3 * k + j];
            S[3 * i + j] = acc / det;
        }
}

/* The largest max |S - S_d| / max(|S|, |S_d|), S_d = F^-1 dpsi/dF with the state's end
 * values held, over the samples (*at: where).  Returns 0, or -1 when psi's derivative is not
 * available (a runtime routine without a rule). */
static int worst_difference(SGraph *g, const LawRoots *r, const int *S, int psi,
                            double *worst, int *at)
{
    int Fin[9], P[9];
    for (int k = 0; k < 9; k++)
        Fin[k] = sg_input(g, LAW_INPUT_F, k);
    if (sg_derivatives_held(g, psi, Fin, 9, r->next, r->nslots, P))
        return -1;
    double *val = malloc((size_t)g->n * sizeof *val);
    Sample s[NSAMPLES];
    samples(s);
    *worst = 0, *at = 0;
    for (int q = 0; q < NSAMPLES; q++) {
        Point p = {s[q].F, r};
        sg_eval(g, g->n - 1, input_at, &p, NULL, val);
        double Pv[9], Sd[9], scale = 0, diff = 0;
        for (int k = 0; k < 9; k++)
            Pv[k] = val[P[k]];
        solve(s[q].F, Pv, Sd);
        for (int k = 0; k < 9; k++) {
            scale = fmax(scale, fmax(fabs(val[S[k]]), fabs(Sd[k])));
            diff = fmax(diff, fabs(val[S[k]] - Sd[k]));
        }
        const double rel = scale > 0 ? diff / scale : 0;
        if (isfinite(rel) && rel > *worst) /* a sample outside the law's domain is skipped */
            *worst = rel, *at = q;
    }
    free(val);
    return 0;
}

/* The first statement of a kind in a list, or NULL. */
static const MatStmt *stmt_of_kind(const MatStmtList *body, MatStmtKind kind)
{
    for (int i = 0; i < body->n; i++)
        if (body->items[i].kind == kind)
            return &body->items[i];
    return NULL;
}

static const MatStmt *stress_stmt(const MatStmtList *body)
{
    return stmt_of_kind(body, MS_STRESS);
}

static const MatStmt *tension_stmt(const MaterialDef *law)
{
    for (int i = 0; i < law->body.n; i++)
        if (law->body.items[i].kind == MS_BLOCK && !strcmp(law->body.items[i].name, "tension"))
            return &law->body.items[i];
    return NULL;
}

/* ------------------------------------------------------------------ objectivity */

/* An energy is a function of F through C = F^T F only (objectivity): psi(R F) = psi(F) for
 * every rotation Q, so a rigid rotation stores no energy.  One written with F itself (the
 * small-strain eps = sym(F - I)) changes under a rotation: a spinning body would be
 * stressed by its spin and deform.  psi(F) and psi(Q F) are both evaluated at the samples
 * for two rotations (one in the x-z plane of a 2D body, one about a general axis); they
 * agree to round-off for a function of C (stdlib's laws to 1e-14) and differ by a fraction
 * of psi otherwise (0.3 for linear elasticity at a rotation of 0.7). */
#define LAW_OBJECTIVE_TOLERANCE 1e-6

enum { NROTATIONS = 2 };

static const struct {
    const char *what;
    double axis[3], angle;
} ROTATIONS[NROTATIONS] = {
    {"a rotation by 0.7 about y (in the x-z plane)", {0, 1, 0}, 0.7},
    {"a rotation by 2 about (1, 2, 3)", {1, 2, 3}, 2.0},
};

static void rotated(int rot, const double F[9], double QF[9])
{
    double n[3], Q[9];
    const double *a = ROTATIONS[rot].axis, len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (int k = 0; k < 3; k++)
        n[k] = a[k] / len;
    rotation(n, ROTATIONS[rot].angle, Q);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            QF[3 * i + j] = Q[3 * i] * F[j] + Q[3 * i + 1] * F[3 + j] + Q[3 * i + 2] * F[6 + j];
}

static double energy_at(const SGraph *g, const LawRoots *r, int psi, const double F[9],
                        double *val)
{
    Point p = {F, r};
    sg_eval(g, psi, input_at, &p, NULL, val);
    return val[psi];
}

/* The largest |psi(Q F) - psi(F)| over the samples and the rotations (*at, *rot: where),
 * relative to the largest |psi| at the samples (a tensile energy is 0 at a compression, where
 * the round-off of Q F may give it 1e-30); samples outside the law's domain are skipped. */
static double worst_rotation(const SGraph *g, const LawRoots *r, int psi, int *at, int *rot)
{
    double *val = malloc((size_t)g->n * sizeof *val), worst = 0, scale = 0;
    double e[NSAMPLES], eq[NSAMPLES][NROTATIONS];
    Sample s[NSAMPLES];
    samples(s);
    *at = *rot = 0;
    for (int q = 0; q < NSAMPLES; q++) {
        e[q] = energy_at(g, r, psi, s[q].F, val);
        for (int k = 0; k < NROTATIONS; k++) {
            double QF[9];
            rotated(k, s[q].F, QF);
            eq[q][k] = energy_at(g, r, psi, QF, val);
            if (isfinite(e[q]) && isfinite(eq[q][k]))
                scale = fmax(scale, fmax(fabs(e[q]), fabs(eq[q][k])));
        }
    }
    for (int q = 0; q < NSAMPLES && scale > 0; q++)
        for (int k = 0; k < NROTATIONS; k++) {
            const double rel = fabs(eq[q][k] - e[q]) / scale;
            if (isfinite(rel) && rel > worst)
                worst = rel, *at = q, *rot = k;
        }
    free(val);
    return worst;
}

static int check_objective(const SGraph *g, const LawRoots *r, const MaterialDef *law,
                           int psi, const MatStmt *energy, const char *what)
{
    Sample s[NSAMPLES];
    samples(s);
    int at, rot;
    const double worst = worst_rotation(g, r, psi, &at, &rot);
    if (!(worst > LAW_OBJECTIVE_TOLERANCE))
        return 0;
    diag_warning(energy ? energy->loc : law->loc, "the %s of material '%s' is not objective: a "
                 "rigid rotation Q changes it (|psi(Q F) - psi(F)| is %.3g of the largest |psi| "
                 "at the samples, at %s, Q %s): a spinning body would be strained by its spin "
                 "(write the energy as a function of C = F^T F, E or J)", what, law->name, worst,
                 s[at].what, ROTATIONS[rot].what);
    return 1;
}

int law_verify(const Model *m, const BodyModel *b)
{
    const MaterialDef *law = b->law;
    const MatStmt *stress = stress_stmt(&law->body), *tension = tension_stmt(law);
    const MatStmt *stress_p = tension ? stress_stmt(&tension->body) : NULL;
    SGraph g;
    sg_init(&g);
    LawRoots r;
    int warnings = 0;
    if (law_build(&g, m, law, b, 3, 1, &r) == 0) {
        Sample s[NSAMPLES];
        samples(s);
        double worst;
        int at;
        warnings += check_objective(&g, &r, law, r.psi, stmt_of_kind(&law->body, MS_ENERGY),
                                    "energy");
        if (r.has_tension && tension)
            warnings += check_objective(&g, &r, law, r.psip,
                                        stmt_of_kind(&tension->body, MS_ENERGY), "tensile energy");
        if (stress && !worst_difference(&g, &r, r.S, r.psi, &worst, &at) &&
            worst > LAW_VERIFY_TOLERANCE) {
            diag_warning(stress->loc, "the stress of material '%s' is not the derivative of its "
                         "energy%s: S and F^-1 dpsi/dF differ by %.3g of their largest entry at %s",
                         law->name, r.nslots ? " at the returned state" : "", worst, s[at].what);
            warnings++;
        }
        if (stress_p && r.has_tension && !worst_difference(&g, &r, r.Sp, r.psip, &worst, &at) &&
            worst > LAW_VERIFY_TOLERANCE) {
            diag_warning(stress_p->loc, "the tensile stress of material '%s' is not the "
                         "derivative of its tensile energy: S+ and F^-1 dpsi+/dF differ by %.3g of "
                         "their largest entry at %s",
                         law->name, worst, s[at].what);
            warnings++;
        }
    }
    sg_free(&g);
    return warnings;
}

/* ------------------------------------------------------------------ at the identity */

/* Every particle starts at F = I and its first steps stay near it: a law whose energy,
 * stress or state is not finite there (mu sqrt(tr E), whose derived stress divides by
 * sqrt(tr E) = 0; ln(det C - 1)) fails at the first step of every run.  These deformations
 * lie in the x-z plane, so that they are a 2D body's too. */
#define NEAR_EPS 1e-4
static const Sample NEAR_IDENTITY[] = {
    {"F = I, the undeformed state", {1, 0, 0, 0, 1, 0, 0, 0, 1}},
    {"F = diag(1 + 1e-4, 1, 1), a small stretch", {1 + NEAR_EPS, 0, 0, 0, 1, 0, 0, 0, 1}},
    {"F = diag(1 - 1e-4, 1, 1), a small compression", {1 - NEAR_EPS, 0, 0, 0, 1, 0, 0, 0, 1}},
    {"F = I + 1e-4 e_x e_z, a small shear", {1, 0, NEAR_EPS, 0, 1, 0, 0, 0, 1}},
    {"F = diag(1 + 1e-4, 1, 1 + 1e-4), a small dilatation",
     {1 + NEAR_EPS, 0, 0, 0, 1, 0, 0, 0, 1 + NEAR_EPS}},
    {"F = diag(1 - 1e-4, 1, 1 - 1e-4), a small compaction",
     {1 - NEAR_EPS, 0, 0, 0, 1, 0, 0, 0, 1 - NEAR_EPS}},
};
enum { NNEAR = sizeof NEAR_IDENTITY / sizeof NEAR_IDENTITY[0] };

/* A result of the law checked there: its name, its nodes, the statement it is reported at. */
typedef struct {
    const char *what;
    const int *ids;
    int n;
    const MatStmt *stmt;
} Result;

static int results_checked(const MaterialDef *law, const LawRoots *r, Result out[5])
{
    const MatStmt *energy = stmt_of_kind(&law->body, MS_ENERGY), *stress = stress_stmt(&law->body);
    const MatStmt *tension = tension_stmt(law);
    int n = 0;
    out[n++] = (Result){"energy", &r->psi, 1, energy};
    out[n++] = (Result){stress ? "stress" : "stress (derived from its energy)", r->S, 9,
                        stress ? stress : energy};
    if (r->has_tension && tension) {
        const MatStmt *e = stmt_of_kind(&tension->body, MS_ENERGY);
        const MatStmt *sp = stress_stmt(&tension->body);
        out[n++] = (Result){"tensile energy", &r->psip, 1, e ? e : tension};
        out[n++] = (Result){sp ? "tensile stress" : "tensile stress (derived from its tensile "
                                                    "energy)",
                            r->Sp, 9, sp ? sp : e ? e : tension};
    }
    if (r->nslots)
        out[n++] = (Result){"state", r->next, r->nslots, NULL};
    return n;
}

/* Where a value that is not finite comes from: from node id down through the operands that
 * are not finite (a select through its branch taken) to a node whose operands all are. */
static int nonfinite_origin(const SGraph *g, const double *val, int id)
{
    for (;;) {
        const SNode *s = &g->nodes[id];
        int ops[SG_MAX_ARGS], nops = 0, next = -1;
        if (s->op == SN_SELECT)
            ops[nops++] = s->a, ops[nops++] = val[s->a] != 0.0 ? s->b : s->c;
        else if (s->op == SN_PART)
            for (int k = 0; k < g->nodes[s->a].nargs; k++)
                ops[nops++] = g->nodes[s->a].args[k];
        else if (s->op != SN_CONST && s->op != SN_INPUT && s->op != SN_PARAM && s->op != SN_EXT)
            for (int k = 0; k < 2; k++)
                if ((k ? s->b : s->a) >= 0 && (k == 0 || s->op != SN_CALL))
                    ops[nops++] = k ? s->b : s->a;
        for (int k = 0; k < nops && next < 0; k++)
            if (!isfinite(val[ops[k]]))
                next = ops[k];
        if (next < 0)
            return id;
        id = next;
    }
}

/* "lambda = 2e+06, mu = 1e+06" */
static void parameter_values(const MaterialDef *law, const double *params, char *buf, size_t size)
{
    size_t len = 0;
    buf[0] = 0;
    for (int k = 0; params && k < law->nparams && len + 64 < size; k++)
        len += (size_t)snprintf(buf + len, size - len, "%s%s = %g", k ? ", " : "",
                                law->params[k], params[k]);
}

static const char *nonfinite_name(double v)
{
    return isnan(v) ? "nan" : v > 0 ? "inf" : "-inf";
}

static void report_nonfinite(const BodyModel *b, const SGraph *g, const double *val,
                             const Result *res, int entry, int sample, int reads_dt)
{
    const MaterialDef *law = b->law;
    char name[32], values[512];
    if (res->n == 9)
        snprintf(name, sizeof name, "%s_%d%d", res->what[0] == 't' ? "S+" : "S",
                 entry / 3 + 1, entry % 3 + 1);
    else if (res->n == 1)
        snprintf(name, sizeof name, "%s", res->what[0] == 't' ? "psi+" : "psi");
    else
        snprintf(name, sizeof name, "state value %d", entry);
    parameter_values(law, b->law_args, values, sizeof values);
    const double v = val[res->ids[entry]];
    const SrcLoc at = res->stmt ? res->stmt->loc : law->loc;
    diag_error(at, "the %s of material '%s' is not finite at %s (%s = %s) with body '%s''s "
               "parameters%s%s%s: every particle starts at F = I and deforms from there%s",
               res->what, law->name, NEAR_IDENTITY[sample].what, name, nonfinite_name(v),
               b->name, *values ? " (" : "", values, *values ? ")" : "",
               reads_dt ? ", and the law's first evaluation, at t = 0, has dt = 0" : "");
    const SNode *o = &g->nodes[nonfinite_origin(g, val, res->ids[entry])];
    if (o->file && o->line > 0 && o->line != at.line)
        diag_note((SrcLoc){o->file, o->line, 0}, "the first value that is not finite (%s) is "
                  "computed here", nonfinite_name(val[o - g->nodes]));
}

double law_wavespeed_at_rest(const SGraph *g, const LawRoots *r)
{
    if (!r->has_wavespeed)
        return NAN;
    static const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    Point p = {identity, r};
    double *val = malloc((size_t)g->n * sizeof *val);
    sg_eval(g, r->wavespeed, input_at, &p, NULL, val);
    const double c = val[r->wavespeed];
    free(val);
    return c;
}

int law_verify_finite(const BodyModel *b, const SGraph *g, const LawRoots *r)
{
    Result res[5];
    const int nres = results_checked(b->law, r, res);
    double *val = malloc((size_t)g->n * sizeof *val);
    const int reads_dt = law_reads(g, r, LAW_INPUT_DT); /* (evaluated at dt = 0: input_at) */
    int bad = 0;
    for (int q = 0; q < NNEAR && !bad; q++) {
        Point p = {NEAR_IDENTITY[q].F, r};
        sg_eval(g, g->n - 1, input_at, &p, NULL, val);
        for (int i = 0; i < nres && !bad; i++)
            for (int k = 0; k < res[i].n && !bad; k++)
                if (!isfinite(val[res[i].ids[k]])) {
                    report_nonfinite(b, g, val, &res[i], k, q, reads_dt);
                    bad = 1;
                }
    }
    free(val);
    return bad ? -1 : 0;
}

/* The law's small-strain moduli against the body's elastic constants, from which the sound
 * speed (eq. 59), hence the time step (eq. 64) and the artificial viscosity (eq. 58), come:
 * a law with parameters of its own (Mooney-Rivlin's c10, c01) may mean a shear modulus the
 * body does not give.  S at a simple shear gamma is mu gamma, at a dilatation (1 + eps) I it is
 * 3 K (eps + eps^2 / 2): both to a relative 1e-6 at 1e-6; LAW_MODULI_TOLERANCE is far above. */
#define LAW_MODULI_TOLERANCE 1e-3

int law_verify_moduli(const Model *m, const BodyModel *b)
{
    if (b->soundspeed > 0) /* the body gives its sound speed */
        return 0;
    SGraph g;
    sg_init(&g);
    LawRoots r;
    int warnings = 0;
    if (law_build(&g, m, b->law, b, 3, 0, &r) == 0) {
        const double t = 1e-6;
        double shear[9] = {1, t, 0, 0, 1, 0, 0, 0, 1}, dilate[9] = {1 + t, 0, 0, 0, 1 + t, 0, 0,
                                                                      0, 1 + t};
        double *val = malloc((size_t)g.n * sizeof *val);
        Point p = {shear, &r};
        sg_eval(&g, g.n - 1, input_at, &p, NULL, val);
        const double mu = val[r.S[1]] / t;
        p.F = dilate;
        sg_eval(&g, g.n - 1, input_at, &p, NULL, val);
        const double K = val[r.S[0]] / (3 * (t + 0.5 * t * t));
        free(val);
        const double dmu = fabs(mu - b->mu) / b->mu, dK = fabs(K - b->K) / b->K;
        if (!isfinite(mu) || !isfinite(K)) {
            char smu[32], sK[32];
            snprintf(smu, sizeof smu, "%g", mu);
            snprintf(sK, sizeof sK, "%g", K);
            diag_error(b->loc, "body '%s': its material '%s' has a small-strain shear modulus "
                       "%s Pa and bulk modulus %s Pa (S at a shear and a dilatation of 1e-6): "
                       "not a finite number", b->name, b->law->name,
                       isfinite(mu) ? smu : nonfinite_name(mu), isfinite(K) ? sK : nonfinite_name(K));
            warnings++;
        } else if (dmu > LAW_MODULI_TOLERANCE || dK > LAW_MODULI_TOLERANCE) {
            diag_warning(b->loc, "body '%s': its material '%s' has a small-strain shear modulus "
                         "%.6g Pa and bulk modulus %.6g Pa, the body's elastic constants %.6g and "
                         "%.6g; the sound speed (eq. 59), the time step and the viscosity follow "
                         "the body's (give them as shear and bulk, or the body's soundspeed)",
                         b->name, b->law->name, mu, K, b->mu, b->K);
            warnings++;
        }
    }
    sg_free(&g);
    return warnings;
}
