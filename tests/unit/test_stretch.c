/* test_stretch.c — the smallest principal stretch squared of the time step's compression bound
 * (sph_stretch2_min, sphrt.h) against the Jacobi eigenvalues of C = F^T F (sph_tensor.h):
 * random deformation gradients in 3D and in plane strain, rotations (which must not change
 * it), repeated and nearly repeated stretches, the identity, and a body crushed to 1/50 along
 * one direction.  And the artificial viscosity's scale lambda_min / J (sph_viscous_scale: 1 /
 * the largest singular value of cof F) against the stretches F was made of, in 3D and in the
 * plane, where it must not count the out-of-plane 1. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include "core/tensor3.h"
#include "sph_tensor.h"
#include "unit_check.h"

/* The reference: the smallest eigenvalue of F^T F by Jacobi (sph_tensor.h). */
static double jacobi_min(const double F[9])
{
    double C[9], lam[3], Q[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            C[3 * r + c] = F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c];
    sph_sym_eig3(C, lam, Q);
    return lam[2];
}

/* F = R V diag(u) V^T: stretches u in a random frame V, turned by a random rotation R (in
 * plane strain both turn about y, so that F keeps F_yy = 1 and no coupling to y). */
static void make_F(const double u[3], double F[9], int dim)
{
    double V[9], R[9], D[9] = {0}, T[9], U[9];
    for (int pass = 0; pass < 2; pass++) {
        double *M = pass ? R : V;
        double ax[3] = {urand() - 0.5, urand() - 0.5, urand() - 0.5}, n = 0;
        if (dim == 2)
            ax[0] = 0, ax[2] = 0, ax[1] = 1; /* plane strain: turns in the x-z plane */
        for (int k = 0; k < 3; k++)
            n += ax[k] * ax[k];
        n = sqrt(n);
        const double a = 6.283185307179586 * urand(), c = cos(a), s = sin(a);
        const double x = ax[0] / n, y = ax[1] / n, z = ax[2] / n;
        const double d = 1 - c; /* Rodrigues: c I + s [n]x + (1 - c) n n^T */
        M[0] = c + x * x * d, M[1] = x * y * d - z * s, M[2] = x * z * d + y * s;
        M[3] = y * x * d + z * s, M[4] = c + y * y * d, M[5] = y * z * d - x * s;
        M[6] = z * x * d - y * s, M[7] = z * y * d + x * s, M[8] = c + z * z * d;
    }
    for (int k = 0; k < 3; k++)
        D[4 * k] = u[k];
    double Vt[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            Vt[3 * r + c] = V[3 * c + r];
    sph_mat3_mul(V, D, T);
    sph_mat3_mul(T, Vt, U);
    sph_mat3_mul(R, U, F);
}

int main(void)
{
    lcg_state = 2024u;
    const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int dim = 2; dim <= 3; dim++) {
        const double e = fabs(sph_stretch2_min(I, dim) - 1);
        check(e < 1e-15, dim == 2 ? "identity, 2D: 1" : "identity, 3D: 1", e, 1e-15);
    }
    double worst3 = 0, worst2 = 0, worst_rep = 0, worst_crush = 0, worst_vs3 = 0, worst_vs2 = 0;
    double worst_rot = 0;
    for (int t = 0; t < 20000; t++) {
        double u[3] = {0.05 + 2 * urand(), 0.05 + 2 * urand(), 0.05 + 2 * urand()}, F[9];
        make_F(u, F, 3);
        const double ref = jacobi_min(F);
        worst3 = fmax(worst3, fabs(sph_stretch2_min(F, 3) - ref) / ref);
        /* plane strain: F_yy = 1 and no y coupling; the stretch of y is 1 */
        double u2[3] = {0.05 + 2 * urand(), 1.0, 0.05 + 2 * urand()}, F2[9];
        make_F(u2, F2, 2);
        const double ref2 = jacobi_min(F2);
        worst2 = fmax(worst2, fabs(sph_stretch2_min(F2, 2) - ref2) / ref2);
        /* repeated and nearly repeated stretches */
        const double r = 0.2 + urand();
        double ur[3] = {r, r * (1 + 1e-9 * urand()), 0.3 + urand()}, Fr[9];
        make_F(ur, Fr, 3);
        const double refr = jacobi_min(Fr);
        worst_rep = fmax(worst_rep, fabs(sph_stretch2_min(Fr, 3) - refr) / refr);
        /* crushed to 1/50 along one direction (the Taylor bar's foot) */
        double uc[3] = {0.02, 1 + urand(), 1 + urand()}, Fc[9];
        make_F(uc, Fc, 3);
        worst_crush = fmax(worst_crush, fabs(sph_stretch2_min(Fc, 3) / (0.02 * 0.02) - 1));
        /* the viscosity's scale: lambda_min / J of the stretches F was made of */
        const double vs3 = fmin(u[0], fmin(u[1], u[2])) / (u[0] * u[1] * u[2]);
        worst_vs3 = fmax(worst_vs3, fabs(sph_viscous_scale(F, 3) / vs3 - 1));
        const double vs2 = fmin(u2[0], u2[2]) / (u2[0] * u2[2]);
        worst_vs2 = fmax(worst_vs2, fabs(sph_viscous_scale(F2, 2) / vs2 - 1));
        const double one[3] = {1, 1, 1};
        double Rot[9];
        make_F(one, Rot, 2 + t % 2);
        worst_rot = fmax(worst_rot, fabs(sph_viscous_scale(Rot, 2 + t % 2) - 1));
    }
    check(worst3 < 1e-8, "3D, random R U: relative error of lambda_min^2", worst3, 1e-8);
    check(worst2 < 1e-10, "2D plane strain, random R U: relative error", worst2, 1e-10);
    /* the trigonometric solution loses digits where two eigenvalues meet (acos near +-1):
     * a few 1e-7, which a time-step bound does not feel */
    check(worst_rep < 1e-6, "repeated stretches: relative error", worst_rep, 1e-6);
    check(worst_crush < 1e-6, "crushed to 0.02: lambda_min^2 / 0.0004 - 1", worst_crush, 1e-6);
    check(worst_vs3 < 1e-8, "viscous scale, 3D: relative error of lambda_min / J", worst_vs3, 1e-8);
    check(worst_vs2 < 1e-10, "viscous scale, plane strain: relative error", worst_vs2, 1e-10);
    check(worst_rot < 1e-6, "viscous scale of a rotation: 1", worst_rot, 1e-6);
    printf(failures ? "%d check(s) FAILED\n" : "all checks passed\n", failures);
    return failures ? 1 : 0;
}
