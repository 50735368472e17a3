/* tensor_check.h — 3x3 tensor arithmetic (row-major) for the tests that call a material
 * law at given deformations: products, inverse, determinant, and the Kirchhoff stress's mean
 * and von Mises parts, computed here independently of the generated code. */
#ifndef SPH_TEST_TENSOR_CHECK_H
#define SPH_TEST_TENSOR_CHECK_H

#include <math.h>

static void t3_mul(const double A[9], const double B[9], double AB[9])
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            AB[r * 3 + c] = A[r * 3] * B[c] + A[r * 3 + 1] * B[3 + c] + A[r * 3 + 2] * B[6 + c];
}

static void t3_transpose(const double A[9], double At[9])
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            At[c * 3 + r] = A[r * 3 + c];
}

static double t3_det(const double A[9])
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

/* A^-1 = adj(A) / det(A). */
static void t3_inv(const double A[9], double Ai[9])
{
    const double d = t3_det(A);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            Ai[3 * i + j] = (A[3 * r0 + c0] * A[3 * r1 + c1] - A[3 * r0 + c1] * A[3 * r1 + c0]) / d;
        }
}

/* The Kirchhoff stress tau = F S F^T of the second Piola-Kirchhoff stress S: its mean p and
 * sqrt(J2) of its deviator (von Mises: sqrt(3 J2)). */
static void t3_kirchhoff_invariants(const double F[9], const double S[9], double *p, double *sj2)
{
    double FS[9], Ft[9], tau[9];
    t3_mul(F, S, FS);
    t3_transpose(F, Ft);
    t3_mul(FS, Ft, tau);
    *p = (tau[0] + tau[4] + tau[8]) / 3;
    double dd = 0;
    for (int k = 0; k < 9; k++) {
        const double d = tau[k] - (k % 4 == 0 ? *p : 0);
        dd += d * d;
    }
    *sj2 = sqrt(0.5 * dd);
}

/* The von Mises stress of the Kirchhoff stress F S F^T. */
static double t3_mises(const double F[9], const double S[9])
{
    double p, sj2;
    t3_kirchhoff_invariants(F, S, &p, &sj2);
    return sqrt(3.0) * sj2;
}

#endif
