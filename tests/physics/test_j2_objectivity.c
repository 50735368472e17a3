/* Objectivity of the J2 law (stdlib/j2.sph through the generated p_material of
 * j2point3d.sph): a material point is stretched plastically along x in 20 increments
 * (F = diag(1 + e, 1 - e/2, 1 - e/2), e to 1 %), then turned rigidly, F' = R F, by a rotation
 * of 0.7 rad about (1, 2, 3).  The rotated step must not flow (ep and C_p unchanged, to
 * 1e-12), the second Piola-Kirchhoff stress must be the same (S(RF) = S(F): C = F^T F is
 * unchanged), so the Cauchy stress turns with the body: sigma' = R sigma R^T (relative
 * 1e-12 of |sigma|), and the energy the same (1e-9: it cancels to a small number).  Also:
 * the stretch did yield (ep > 0) and det C_p = 1 to 1e-12. */
#define main generated_main
#include "j2point3d.c"
#undef main

#include "check.h"

enum { NS = 11 }; /* Cp (9), ep, wp */

static void mul(const double *A, const double *B, double *C)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            C[3 * i + j] = 0;
            for (int k = 0; k < 3; k++)
                C[3 * i + j] += A[3 * i + k] * B[3 * k + j];
        }
}

static void mul_bt(const double *A, const double *B, double *C) /* A B^T */
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            C[3 * i + j] = 0;
            for (int k = 0; k < 3; k++)
                C[3 * i + j] += A[3 * i + k] * B[3 * j + k];
        }
}

static void cauchy(const double *F, const double *S, double *sig)
{
    double FS[9];
    mul(F, S, FS);
    mul_bt(FS, F, sig);
    const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                     F[2] * (F[3] * F[7] - F[4] * F[6]);
    for (int k = 0; k < 9; k++)
        sig[k] /= J;
}

static void rotation(double R[9])
{
    const double n[3] = {1 / sqrt(14.0), 2 / sqrt(14.0), 3 / sqrt(14.0)}, a = 0.7;
    const double c = cos(a), s = sin(a);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[3 * i + j] = (1 - c) * n[i] * n[j] + (i == j ? c : 0);
    R[1] -= s * n[2], R[2] += s * n[1];
    R[3] += s * n[2], R[5] -= s * n[0];
    R[6] -= s * n[1], R[7] += s * n[0];
}

int main(void)
{
    double st[NS], st_new[NS], F[9] = {0}, S[9], psi;
    for (int k = 0; k < NS; k++)
        st[k] = MODEL.bodies[0].state_init[k];
    for (int q = 1; q <= 20; q++) {
        const double e = 0.01 * q / 20;
        F[0] = 1 + e, F[4] = F[8] = 1 - 0.5 * e;
        p_material(F, st, st_new, S, &psi);
        for (int k = 0; k < NS; k++)
            st[k] = st_new[k];
    }
    p_material(F, st, st_new, S, &psi); /* the state the stretch left: settled */
    const double det = st[0] * (st[4] * st[8] - st[5] * st[7]) -
                       st[1] * (st[3] * st[8] - st[5] * st[6]) +
                       st[2] * (st[3] * st[7] - st[4] * st[6]);
    double R[9], RF[9], Sr[9], psir, sig[9], sigr[9], Rsig[9], want[9];
    rotation(R);
    mul(R, F, RF);
    p_material(RF, st, st_new, Sr, &psir);
    double dst = 0, dS = 0, dsig = 0, smax = 0, sigmax = 0;
    for (int k = 0; k < NS; k++)
        dst = fmax(dst, fabs(st_new[k] - st[k]));
    cauchy(F, S, sig);
    cauchy(RF, Sr, sigr);
    mul(R, sig, Rsig);
    mul_bt(Rsig, R, want);
    for (int k = 0; k < 9; k++) {
        dS = fmax(dS, fabs(Sr[k] - S[k]));
        smax = fmax(smax, fabs(S[k]));
        dsig = fmax(dsig, fabs(sigr[k] - want[k]));
        sigmax = fmax(sigmax, fabs(sig[k]));
    }
    printf("after the stretch: ep %.6g, sigma_xx %.6g MPa\n", st[9], sig[0] * 1e-6);
    check_close("the stretch yielded: ep > 1e-3", st[9] > 1e-3, 1, 0);
    check_close("|det Cp - 1|", fabs(det - 1), 0, 1e-12);
    check_close("rotated: max change of the state (Cp, ep)", dst, 0, 1e-12);
    check_close("rotated: |S(RF) - S(F)| / |S|", dS / smax, 0, 1e-12);
    check_close("rotated: |sigma' - R sigma R^T| / |sigma|", dsig / sigmax, 0, 1e-12);
    /* psi = K/4 (J^2 - 1 - 2 ln J) + ... cancels to a small number: 1e-9 relative */
    check_close("rotated: energy unchanged (ratio)", psir / psi, 1, 1e-9);
    return check_result();
}
