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
 * strains among the samples. */
#include <math.h>
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

/* The first `stress` statement of a list, or NULL. */
static const MatStmt *stress_stmt(const MatStmtList *body)
{
    for (int i = 0; i < body->n; i++)
        if (body->items[i].kind == MS_STRESS)
            return &body->items[i];
    return NULL;
}

static const MatStmt *tension_stmt(const MaterialDef *law)
{
    for (int i = 0; i < law->body.n; i++)
        if (law->body.items[i].kind == MS_BLOCK && !strcmp(law->body.items[i].name, "tension"))
            return &law->body.items[i];
    return NULL;
}

int law_verify(const Model *m, const MaterialDef *law, const double *params)
{
    const MatStmt *stress = stress_stmt(&law->body), *tension = tension_stmt(law);
    const MatStmt *stress_p = tension ? stress_stmt(&tension->body) : NULL;
    if (!stress && !stress_p)
        return 0;
    SGraph g;
    sg_init(&g);
    LawRoots r;
    int warnings = 0;
    if (law_build(&g, m, law, params, 3, 1, &r) == 0) {
        Sample s[NSAMPLES];
        samples(s);
        double worst;
        int at;
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
    if (law_build(&g, m, b->law, b->law_args, 3, 0, &r) == 0) {
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
        if (isfinite(mu) && isfinite(K) && (dmu > LAW_MODULI_TOLERANCE || dK > LAW_MODULI_TOLERANCE)) {
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
