/* kernel.h — the SPH kernels (support 2h; formulas in kernel.c) and a pair's kernel gradient
 * from its reference offset.  The normalisation constant aD and dW/dr / r are inline, so that
 * the CUDA target's passes can evaluate them too (SPH_CUDA_RECOMPUTE, docs/cuda.md). */
#ifndef SPHRT_CORE_KERNEL_H
#define SPHRT_CORE_KERNEL_H

#include <math.h>

#include "defs.h"

SPH_C_BEGIN

typedef enum { SPH_WENDLAND = 0, SPH_CUBIC = 1 } sph_kernel_kind;

/* Kernel value and dW/dr / r (so that grad W = (X_i - X_j) * dwdr_over_r).  h is the
 * smoothing length; the support is 2h for both kernels. */
double sph_kernel_w(sph_kernel_kind k, int dim, double r, double h);

SPH_FN double sph_kernel_norm(sph_kernel_kind k, int dim, double h)
{
    const double pi = 3.14159265358979323846;
    if (k == SPH_CUBIC)
        return dim == 2 ? 10.0 / (7.0 * pi * h * h) : 1.0 / (pi * h * h * h);
    return dim == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
}

/* Eq. 60 for one pair without gathering X_j in the hot loop: w_ij = V_j grad W is parallel
 * to dX = X_i - X_j, so G_ij = h (v_ij . dX) / (r^2 + 0.001 h^2) = g (v_ij . w_ij) with
 * g = h r^2 / ((w . dX) (r^2 + 0.001 h^2)); 0 where w vanishes (r = 2h). */
SPH_FN double sph_viscosity_factor(int dim, double h, const double *dX, const double *w)
{
    double r2 = 0, wdx = 0;
    for (int k = 0; k < dim; k++)
        r2 += dX[k] * dX[k], wdx += w[k] * dX[k];
    return wdx != 0 ? h * r2 / (wdx * (r2 + 0.001 * h * h)) : 0.0;
}

SPH_FN double sph_kernel_dwdr_over_r(sph_kernel_kind k, int dim, double r, double h)
{
    const double q = r / h, ad = sph_kernel_norm(k, dim, h) / (h * h);
    if (q >= 2.0)
        return 0.0;
    if (k == SPH_CUBIC) {
        if (q < 1.0)
            return ad * (-3.0 + 2.25 * q);
        const double t = 2.0 - q;
        return -0.75 * ad * t * t / q;
    }
    const double t = 1.0 - 0.5 * q;
    return -5.0 * ad * t * t * t;
}

/* A pair at reference offset dX = X_i - X_j: V_j grad_i W_ij = V_j (dW/dr / r) dX into w,
 * and V_j dW/dr / r returned (half the Laplacian weight of eq. 62).  What the set-up's
 * gradients and offset tables are made of (pairs/gradients.c, run/setup.c), and what the
 * CUDA target recomputes per pair with SPH_CUDA_RECOMPUTE. */
SPH_FN double sph_pair_w(sph_kernel_kind k, int dim, double h, double vol, const double *dX,
                         double *w)
{
    double r2 = 0;
    for (int c = 0; c < dim; c++)
        r2 += dX[c] * dX[c];
    const double f = vol * sph_kernel_dwdr_over_r(k, dim, sqrt(r2), h);
    for (int c = 0; c < dim; c++)
        w[c] = f * dX[c];
    return f;
}

SPH_C_END

#endif
