/* gradients.h — kernel gradients per pair and the kernel-gradient correction per particle
 * (gradients.c). */
#ifndef SPHRT_PAIRS_GRADIENTS_H
#define SPHRT_PAIRS_GRADIENTS_H

#include "core/defs.h"
#include "core/kernel.h"

SPH_C_BEGIN

/* Every particle's correction matrix L_i = M_i^{-T}, M_i = sum_j V_j (X_j - X_i) ⊗
 * grad_i W_ij, so that sum_j V_j (X_j - X_i) ⊗ (L_i grad_i W_ij) = I exactly (dim×dim per
 * particle, malloc'ed; where M_i is singular, too few neighbours, L_i = I), and unless w is
 * NULL every pair's w = V_j grad_i W_ij (dim values per pair, malloc'ed: 24 bytes a pair in
 * 3D, which the set-up does not keep but recomputes where it needs them).  Returns the
 * number of particles whose M_i is singular, the first of them in *first_singular (-1 for
 * none) unless it is NULL. */
int sph_gradients(const double *X, int n, int dim, const int *start, const int *nb,
                  sph_kernel_kind kernel, double h, double vol, double **w, double **L,
                  int *first_singular);
/* One pair's w = V_j grad_i W_ij (dim values), as sph_gradients computes it. */
void sph_pair_gradient(const double *X, int dim, int i, int j, sph_kernel_kind kernel, double h,
                       double vol, double *w);

SPH_C_END

#endif
