/* The tension/compression split of the material laws with fracture (split3d.sph), through
 * the generated material functions X_material(F, s, S, &psi, &psi_plus):
 *  - pure compression (SVK: every principal strain negative; neo-Hookean: hydrostatic,
 *    J < 1): psi+ = 0 and the stress is not degraded, S(s) = S(1);
 *  - pure tension (every principal strain positive, J > 1): S(s) = s^2 S(1), psi(s) = s^2
 *    psi(1);
 *  - mixed SVK strain E = diag(e1, e2, e3) with e1 > 0 > e2, e3 and tr E < 0: psi+ = mu e1^2
 *    (eq. 11), S+ = 2 mu diag(e1, 0, 0) (eq. 17) against the generated S(s) = s^2 S+ + S-;
 *  - the same strain seen in rotated axes, F = diag(l) R^T (then E = R diag(e) R^T):
 *    psi+ is unchanged and S = R S_diag R^T (the eigen-decomposition of a full 3x3 E);
 *  - repeated principal strains (E = e I, e > 0 and < 0) give the whole or nothing.
 * Tolerance 1e-12 relative to the stress scale. */
#define main generated_main
#include "split3d.c"
#undef main

#include "check.h"

static const double LAMBDA = 2e6, MU = 1e6;

typedef void (*law_fn)(const double F[9], double s, double S[9], double *psi, double *psip);

static void diag(double F[9], double a, double b, double c)
{
    for (int k = 0; k < 9; k++)
        F[k] = 0;
    F[0] = a, F[4] = b, F[8] = c;
}

static double max_diff(const double *x, const double *y, double scale)
{
    double d = 0;
    for (int k = 0; k < 9; k++)
        d = fmax(d, fabs(x[k] - y[k] * scale));
    return d;
}

static void compression_and_tension(const char *name, law_fn law, const double Fc[9],
                                    const double Ft[9])
{
    char what[128];
    double S1[9], Ss[9], p1, ps, pp1, pps;
    const double s = 0.3;
    law(Fc, 1.0, S1, &p1, &pp1);
    law(Fc, s, Ss, &ps, &pps);
    snprintf(what, sizeof what, "%s compression: psi+ / mu", name);
    check_close(what, pp1 / MU, 0, 1e-12);
    snprintf(what, sizeof what, "%s compression: |S(0.3) - S(1)| / mu", name);
    check_close(what, max_diff(Ss, S1, 1.0) / MU, 0, 1e-12);
    snprintf(what, sizeof what, "%s compression: stress is nonzero (|S_xx| / mu)", name);
    check_close(what, fabs(S1[0]) / MU > 1e-3, 1, 0);
    law(Ft, 1.0, S1, &p1, &pp1);
    law(Ft, s, Ss, &ps, &pps);
    snprintf(what, sizeof what, "%s tension: |S(0.3) - 0.09 S(1)| / mu", name);
    check_close(what, max_diff(Ss, S1, s * s) / MU, 0, 1e-12);
    snprintf(what, sizeof what, "%s tension: psi(0.3) / (0.09 psi(1))", name);
    check_close(what, ps / (s * s * p1), 1, 1e-12);
    snprintf(what, sizeof what, "%s tension: psi+ = psi", name);
    check_close(what, pp1 / p1, 1, 1e-12);
}

/* F = diag(l) R^T with R a rotation about axis (1, 2, 3) by 0.7 rad. */
static void rotation(double R[9])
{
    const double n[3] = {1 / sqrt(14.0), 2 / sqrt(14.0), 3 / sqrt(14.0)}, a = 0.7;
    const double c = cos(a), s = sin(a);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            R[3 * i + j] = (1 - c) * n[i] * n[j] + (i == j ? c : 0);
        }
    R[1] -= s * n[2], R[2] += s * n[1];
    R[3] += s * n[2], R[5] -= s * n[0];
    R[6] -= s * n[1], R[7] += s * n[0];
}

static void mixed_svk(void)
{
    const double l[3] = {1.04, 0.95, 0.97}, s = 0.5;
    double e[3], F[9], S[9], psi, psip;
    for (int k = 0; k < 3; k++)
        e[k] = 0.5 * (l[k] * l[k] - 1);
    const double tr = e[0] + e[1] + e[2]; /* < 0: the trace term is all compressive */
    diag(F, l[0], l[1], l[2]);
    a_material(F, s, S, &psi, &psip);
    double Sd[3];
    for (int k = 0; k < 3; k++) { /* s^2 S+ + S-, eq. 17-18 */
        double Sp = (k == 0 ? 2 * MU * e[0] : 0);
        double Sfull = LAMBDA * tr + 2 * MU * e[k];
        Sd[k] = s * s * Sp + (Sfull - Sp);
    }
    check_close("svk mixed: psi+ / (mu e1^2)", psip / (MU * e[0] * e[0]), 1, 1e-12);
    double d = 0;
    for (int k = 0; k < 3; k++)
        d = fmax(d, fabs(S[4 * k] - Sd[k]));
    check_close("svk mixed: |S - (s^2 S+ + S-)| / mu (diagonal)", d / MU, 0, 1e-12);
    /* rotated axes */
    double R[9], Fr[9], Sr[9], pr, ppr;
    rotation(R);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Fr[3 * i + j] = l[i] * R[3 * j + i]; /* diag(l) R^T */
    a_material(Fr, s, Sr, &pr, &ppr);
    check_close("svk mixed, rotated: psi+ unchanged (ratio)", ppr / psip, 1, 1e-12);
    check_close("svk mixed, rotated: psi unchanged (ratio)", pr / psi, 1, 1e-12);
    d = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) { /* S_rot = R diag(Sd) R^T */
            double want = 0;
            for (int k = 0; k < 3; k++)
                want += R[3 * i + k] * Sd[k] * R[3 * j + k];
            d = fmax(d, fabs(Sr[3 * i + j] - want));
        }
    check_close("svk mixed, rotated: |S - R S_diag R^T| / mu", d / MU, 0, 1e-12);
}

static void repeated(void)
{
    double F[9], S1[9], Ss[9], p1, pp1, ps, pps;
    diag(F, 1.01, 1.01, 1.01);
    a_material(F, 1.0, S1, &p1, &pp1);
    a_material(F, 0.5, Ss, &ps, &pps);
    check_close("svk E = e I, e > 0: |S(0.5) - 0.25 S(1)| / mu", max_diff(Ss, S1, 0.25) / MU, 0, 1e-12);
    diag(F, 0.99, 0.99, 0.99);
    a_material(F, 1.0, S1, &p1, &pp1);
    a_material(F, 0.5, Ss, &ps, &pps);
    check_close("svk E = e I, e < 0: psi+ / mu", pp1 / MU, 0, 1e-12);
    check_close("svk E = e I, e < 0: |S(0.5) - S(1)| / mu", max_diff(Ss, S1, 1.0) / MU, 0, 1e-12);
}

int main(void)
{
    double Fc[9], Ft[9];
    diag(Fc, 0.95, 0.97, 0.98);
    diag(Ft, 1.05, 1.03, 1.02);
    compression_and_tension("svk", a_material, Fc, Ft);
    diag(Fc, 0.95, 0.95, 0.95); /* neo-Hookean: psi+ = psi_bar, zero only for hydrostatic */
    compression_and_tension("neo-Hookean", b_material, Fc, Ft);
    mixed_svk();
    repeated();
    return check_result();
}
