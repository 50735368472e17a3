/* A material law of 3000 chained `let`s (biglaw2d.sph, written by CMakeLists.txt), which sphc
 * prints in pieces, against its closed form at random deformations (2D): with t = tr(E),
 * a0 = 1 + t^4 and q = 1.0001^3000, a3000 = a0^q, so
 *   psi = lambda/2 t^2 + mu tr(E E) + mu (a0^q - 1),
 *   S   = (lambda t + 4 mu q a0^(q-1) t^3) I + 2 mu E;
 * the same law with a state that keeps Fdot and tr(Fdot Fdot) (body c) returns them too. */
#define main generated_main
#include "biglaw2d.c"
#undef main

#include "check.h"

static void closed_form(const double F[9], double lambda, double mu, double S[9], double *psi)
{
    double E[9], EE = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            E[3 * i + j] =
                0.5 * (F[i] * F[j] + F[3 + i] * F[3 + j] + F[6 + i] * F[6 + j] - (i == j));
    for (int k = 0; k < 9; k++)
        EE += E[k] * E[k];
    const double t = E[0] + E[4] + E[8], a0 = 1 + t * t * t * t, q = pow(1.0001, 3000);
    *psi = 0.5 * lambda * t * t + mu * EE + mu * (pow(a0, q) - 1);
    for (int k = 0; k < 9; k++)
        S[k] = 2 * mu * E[k] +
               (k % 4 == 0) * (lambda * t + 4 * mu * q * pow(a0, q - 1) * t * t * t);
}

/* Body c's law (the same, with a state that keeps Fdot and tr(Fdot Fdot)) at F and a rate in
 * the plane: the largest difference of its stress from S (relative) and of its state. */
static double state_difference(const double F[9], const double S[9])
{
    double Sc[9], psi, st[10] = {0}, st_new[10], Fd[9], FdFd = 0, worst = 0;
    for (int k = 0; k < 9; k++)
        Fd[k] = k / 3 == 1 || k % 3 == 1 ? 0 : F[(k + 2) % 9] - F[k];
    for (int k = 0; k < 9; k++)
        FdFd += Fd[k] * Fd[3 * (k % 3) + k / 3];
    c_material(F, Fd, st, st_new, Sc, &psi);
    for (int k = 0; k < 9; k++)
        worst = fmax(worst, fmax(fabs(Sc[k] - S[k]) / fmax(fabs(S[k]), 1.0),
                                 fabs(st_new[k] - Fd[k])));
    return fmax(worst, fabs(st_new[9] - FdFd));
}

int main(void)
{
    (void)b_material_piece1; /* printed in pieces */
    (void)c_material_piece1;
    const double mu = 1e6, lambda = 3e6 - 2 * mu / 3; /* the body's shear and bulk */
    double worst = 0;
    unsigned seed = 11;
    for (int trial = 0; trial < 200; trial++) {
        double F[9], S[9], Sc[9], psi, psic, scale = 0;
        for (int k = 0; k < 9; k++) {
            seed = seed * 1103515245u + 12345u;
            F[k] = (k % 4 == 0) + 0.6 * ((double)(seed >> 8) / 16777216.0 - 0.5);
            if (k / 3 == 1 || k % 3 == 1) /* plane strain: y's row and column of I */
                F[k] = k == 4;
        }
        b_material(F, S, &psi);
        closed_form(F, lambda, mu, Sc, &psic);
        worst = fmax(worst, state_difference(F, S));
        for (int k = 0; k < 9; k++)
            scale = fmax(scale, fabs(Sc[k]));
        for (int k = 0; k < 9; k++)
            worst = fmax(worst, fabs(S[k] - Sc[k]) / scale);
        worst = fmax(worst, fabs(psi - psic) / fmax(fabs(psic), 1.0));
    }
    check_close("3000 chained lets in pieces: S, psi, state vs closed form", worst, 0, 1e-9);
    return check_result();
}
