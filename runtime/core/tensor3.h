/* tensor3.h — per-particle helpers of 3×3 tensors (row-major), shared by generated code and
 * the runtime, on the host and the device: cofactors and determinant, the smallest principal
 * stretch, the viscosity's scale, products. */
#ifndef SPHRT_CORE_TENSOR3_H
#define SPHRT_CORE_TENSOR3_H

#include <math.h>

#include "defs.h"

SPH_C_BEGIN

/* Cofactor (i, j) of F: the (i, j) entry of J F^-T. */
SPH_HD static inline double sph_cofactor(const double F[9], int i, int j)
{
    const int r0 = (i + 1) % 3, r1 = (i + 2) % 3, c0 = (j + 1) % 3, c1 = (j + 2) % 3;
    return F[3 * r0 + c0] * F[3 * r1 + c1] - F[3 * r0 + c1] * F[3 * r1 + c0];
}

SPH_HD static inline double sph_det3(const double F[9])
{
    return F[0] * sph_cofactor(F, 0, 0) + F[1] * sph_cofactor(F, 0, 1) +
           F[2] * sph_cofactor(F, 0, 2);
}

/* cos(acos(r)/3 + 2 pi/3) for r in [-1, 1]: the smallest root t of 4 t^3 - 3 t = r, in
 * [-1, -1/2].  As a function of v = sqrt(1 - r) in [0, sqrt 2] it is smooth at both ends (at
 * r = 1 the root is double and t = -1/2 - v/sqrt 6 + ...), so a polynomial of degree 13 in v
 * (Chebyshev interpolation, in powers of v) gives it to 6e-13, for a square root and 13
 * multiply-adds where acos and cos took a tenth of a 3D J2 step. */
SPH_HD static inline double sph_cubic_smallest_root(double r)
{
    const double v = sqrt(1.0 - r);
    double t = -5.0499436039345169e-07; /* Horner, from the highest power (no table: device code too) */
    t = t * v + 5.8193484437651875e-06;
    t = t * v + -3.1639447787630489e-05;
    t = t * v + 0.00010999046411598091;
    t = t * v + -0.00028284931836711972;
    t = t * v + 0.00059839020369508908;
    t = t * v + -0.0011417008712306207;
    t = t * v + 0.002119189610894948;
    t = t * v + -0.0040388736219674473;
    t = t * v + 0.0082298344043034172;
    t = t * v + -0.018900321412135129;
    t = t * v + 0.05555555224484722;
    t = t * v + -0.40824829039446131;
    t = t * v + -0.50000000000023759;
    return t;
}

/* The square of the smallest principal stretch of F: the smallest eigenvalue of C = F^T F.
 * In 2D (plane strain, F_yy = 1) of the in-plane block, in closed form; in 3D the
 * trigonometric solution of the characteristic cubic, to about 1e-9 relative (a few 1e-7
 * where two stretches coincide; tests/unit/test_stretch.c). */
SPH_HD static inline double sph_stretch2_least(const double F[9], int dim)
{
    double C[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            C[3 * r + c] = F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c];
    if (dim == 2) {
        const double m = 0.5 * (C[0] + C[8]), d = 0.5 * (C[0] - C[8]);
        return m - sqrt(d * d + C[2] * C[2]);
    }
    const double off = C[1] * C[1] + C[2] * C[2] + C[5] * C[5];
    const double q = (C[0] + C[4] + C[8]) / 3.0;
    const double d0 = C[0] - q, d1 = C[4] - q, d2 = C[8] - q;
    const double p = sqrt((d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off) / 6.0);
    /* a multiple of I: q (a select, as the clamp below: no branch, so that a loop over
     * particles calling this can be vectorised) */
    const int iso = p <= 1e-14 * fabs(q);
    const double ip = iso ? 0.0 : 1.0 / p;
    const double b0 = d0 * ip, b1 = d1 * ip, b2 = d2 * ip, b01 = C[1] * ip, b02 = C[2] * ip,
                 b12 = C[5] * ip;
    double r = 0.5 * (b0 * (b1 * b2 - b12 * b12) - b01 * (b01 * b2 - b12 * b02) +
                      b02 * (b01 * b12 - b1 * b02));
    r = r < -1.0 ? -1.0 : r > 1.0 ? 1.0 : r;
    return iso ? q : q + 2.0 * p * sph_cubic_smallest_root(r); /* cos(acos(r) / 3 + 2 pi / 3) */
}

/* The same with the out-of-plane stretch 1 of plane strain counted in 2D.  A time-step bound
 * uses it, which does not feel the 1e-7. */
SPH_HD static inline double sph_stretch2_min(const double F[9], int dim)
{
    const double l2 = sph_stretch2_least(F, dim);
    return dim == 2 && l2 > 1.0 ? 1.0 : l2;
}

/* 1 / the largest singular value of cof F = J F^-T (in 2D of its in-plane block), which is
 * lambda_min / J: what the artificial viscosity scales its pair's approach rate by to measure
 * it in the pair's reference length as eq. 60 does (templates/body_forces.c).  1 for F = I
 * and for any rotation; 0 for a degenerate F. */
SPH_HD static inline double sph_viscous_scale(const double F[9], int dim)
{
    const double l2 = sph_stretch2_least(F, dim), J = fabs(sph_det3(F));
    return sqrt(l2 > 0.0 ? l2 : 0.0) / (J > 1e-300 ? J : 1e-300);
}

/* C = A B */
SPH_HD static inline void sph_mat3_mul(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

/* C = A B^T */
SPH_HD static inline void sph_mat3_mul_bt(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[3 * i + j] = A[3 * i] * B[3 * j] + A[3 * i + 1] * B[3 * j + 1] +
                           A[3 * i + 2] * B[3 * j + 2];
}

SPH_C_END

#endif
