/* gradients.c — kernel gradients per pair and the kernel-gradient correction per particle.
 *
 * For every pair p = (i, j) of the CSR lists (sph_pair_gradient, stored only when asked):
 *     w[p*dim + k] = vol * (dW/dr / r)(|X_i - X_j|) * (X_i - X_j)_k      (= V_j grad_i W_ij)
 * and for every particle
 *     M_i[r][c] = sum_j (X_j - X_i)_r w_c,     L_i = M_i^{-T} = cof(M_i) / det(M_i),
 * so that sum_j V_j (X_j - X_i) ⊗ (L_i grad_i W_ij) = M_i L_i^T = I exactly.  M_i is
 * dimensionless (about I in the interior); where |det M_i| < 1e-6 (too few or collinear
 * neighbours) L_i = I.  Parallel over particles with OpenMP.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "gradients.h"
#include "core/exit_codes.h"
#include "core/kernel.h"
#include "core/message.h"

/* Cofactor matrix of the dim×dim matrix m (row-major) into c; returns det m. */
static double cofactor(const double *m, int dim, double *c)
{
    if (dim == 2) {
        c[0] = m[3];
        c[1] = -m[2];
        c[2] = -m[1];
        c[3] = m[0];
        return m[0] * m[3] - m[1] * m[2];
    }
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            c[r * 3 + k] = m[r1 * 3 + k1] * m[r2 * 3 + k2] - m[r1 * 3 + k2] * m[r2 * 3 + k1];
        }
    return m[0] * c[0] + m[1] * c[1] + m[2] * c[2];
}

void sph_pair_gradient(const double *X, int dim, int i, int j, sph_kernel_kind kernel, double h,
                       double vol, double *w)
{
    double d[3];
    for (int k = 0; k < dim; k++)
        d[k] = X[(size_t)i * dim + k] - X[(size_t)j * dim + k];
    sph_pair_w(kernel, dim, h, vol, d, w);
}

/* The pairs of particle i: M_i (dim×dim) in m, and their w unless w is NULL. */
static void particle_pairs(const double *X, int i, int dim, const int *start, const int *nb,
                           sph_kernel_kind kernel, double h, double vol, double *w, double *m)
{
    const double *xi = X + (size_t)i * dim;
    for (int k = 0; k < dim * dim; k++)
        m[k] = 0.0;
    for (int p = start[i]; p < start[i + 1]; p++) {
        const double *xj = X + (size_t)nb[p] * dim;
        double wp[3];
        sph_pair_gradient(X, dim, i, nb[p], kernel, h, vol, wp);
        for (int r = 0; r < dim; r++)
            for (int c = 0; c < dim; c++)
                m[r * dim + c] -= (xi[r] - xj[r]) * wp[c];
        for (int k = 0; w && k < dim; k++)
            w[(size_t)p * dim + k] = wp[k];
    }
}

/* L = M^{-T}, or the identity where M is (nearly) singular: returns 1 there. */
static int correction(const double *m, int dim, double *L)
{
    double c[9];
    double det = cofactor(m, dim, c);
    int singular = !(fabs(det) >= 1e-6);
    for (int k = 0; k < dim * dim; k++)
        L[k] = singular ? (k % (dim + 1) == 0 ? 1.0 : 0.0) : c[k] / det;
    return singular;
}

int sph_gradients(const double *X, int n, int dim, const int *start, const int *nb,
                  sph_kernel_kind kernel, double h, double vol, double **w, double **L,
                  int *first_singular)
{
    size_t npairs = n > 0 ? (size_t)start[n] : 0;
    double *wp = w ? malloc(npairs * dim * sizeof *wp + 1) : NULL;
    *L = malloc((size_t)(n > 0 ? n : 0) * dim * dim * sizeof **L + 1);
    if ((w && !wp) || !*L) {
        sph_error("out of memory for kernel gradients (%zu pairs)", npairs);
        exit(SPH_EXIT_SETUP);
    }
    int nsingular = 0, first = n;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : nsingular) reduction(min : first)
    for (int i = 0; i < n; i++) {
        double m[9];
        particle_pairs(X, i, dim, start, nb, kernel, h, vol, wp, m);
        if (correction(m, dim, *L + (size_t)i * dim * dim)) {
            nsingular++;
            first = i < first ? i : first;
        }
    }
    if (w)
        *w = wp;
    if (first_singular)
        *first_singular = nsingular ? first : -1;
    return nsingular;
}
