/* quadratic.h — the corrected gradient exact for quadratic fields (quadratic.c): a body's
 * `gradient quadratic` (docs/language.md), which the scene chooses for bending at a few
 * particles through a thickness (docs/verification.md). */
#ifndef SPHRT_PAIRS_QUADRATIC_H
#define SPHRT_PAIRS_QUADRATIC_H

#include "core/defs.h"
#include "core/kernel.h"

SPH_C_BEGIN

/* The quadratic monomials of an offset d, in this order: 3D x^2, y^2, z^2, xy, yz, xz;
 * 2D (x, z compact) x^2, z^2, xz. */
enum { SPH_QN3 = 6, SPH_QN2 = 3 };
#define SPH_QN(dim) ((dim) == 3 ? SPH_QN3 : SPH_QN2)
/* The fit's coefficients: the gradient's dim and the monomials' (9 in 3D, 5 in 2D). */
#define SPH_QM(dim) ((dim) + SPH_QN(dim))
/* A row of monomial values padded with zeros to a short vector's length (8 in 3D, 4 in 2D):
 * an offset table entry of qtab, a row of Aq (templates/body_quadratic.c). */
#define SPH_QR(dim) ((dim) == 3 ? 8 : 4)

SPH_FN void sph_quad_monomials(int dim, const double *d, double *q)
{
    if (dim == 3) {
        q[0] = d[0] * d[0], q[1] = d[1] * d[1], q[2] = d[2] * d[2];
        q[3] = d[0] * d[1], q[4] = d[1] * d[2], q[5] = d[0] * d[2];
        return;
    }
    q[0] = d[0] * d[0], q[1] = d[1] * d[1], q[2] = d[0] * d[1];
}

/* Every own particle's inverse moment matrix, SPH_QM(dim)^2 values a particle (malloc'ed
 * into *Mq): M_i = sum_j e_ij p_ij^T with p = (d, q(d)), d = X_j - X_i, and the pair weight
 * e = -f p, f = V_j (dW/dr)/r (sph_pair_w), so that e's first dim values are the pair's
 * w_ij = V_j grad_i W_ij.  The gradient and the second derivatives of a field at i are
 * then the coefficients c = (sum_j (u_j - u_i) (x) e_ij) M_i^{-1}, exact where the field is
 * quadratic.  Where M_i is singular (too few neighbours off a line or a plane to fit a
 * quadratic: a body one or two particles thick), the particle keeps the linear correction
 * L (dim x dim a particle, as sph_gradients gives it) and no second derivatives.  Returns
 * the number of such particles. */
int sph_quadratic_moments(const double *X, int n, int dim, const int *start, const int *nb,
                          sph_kernel_kind kernel, double h, double vol, const double *L,
                          double **Mq);

SPH_C_END

#endif
