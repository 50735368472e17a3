/* quadratic.c — the moment matrices of the corrected gradient exact for quadratic fields.
 *
 * A first-order corrected gradient (gradients.c) is exact for linear fields; where a
 * particle's neighbours lie on one side, at a surface, a curved field's gradient comes out
 * as that at the neighbours' centre, and a bent plate's surface strain is 20-30 % low at
 * 4-5 particles through its thickness (docs/verification.md).  A least-squares fit of the
 * gradient and the second derivatives, weighted by the kernel as the first-order one is,
 * is exact for quadratic fields everywhere; in the interior of a lattice its gradient is
 * the first-order one (the odd moments vanish).  Set-up cost only: the pair sums of a step
 * take the monomials from the offset table, and M_i^{-1} from here. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "quadratic.h"
#include "core/exit_codes.h"
#include "core/message.h"

enum { QM_MAX = 9 };

/* The inverse of the symmetric positive definite m x m matrix a (scaled to unit diagonal
 * first: its entries mix lengths and squared lengths) by Cholesky; 0 where a pivot falls
 * below 1e-9 of its diagonal (singular), 1 otherwise. */
static int spd_inverse(double *a, int m, double *inv)
{
    double s[QM_MAX], l[QM_MAX * QM_MAX] = {0}, y[QM_MAX];
    for (int k = 0; k < m; k++) {
        if (!(a[k * m + k] > 0))
            return 0;
        s[k] = 1.0 / sqrt(a[k * m + k]);
    }
    for (int r = 0; r < m; r++) /* L L^T = S a S */
        for (int c = 0; c <= r; c++) {
            double v = a[r * m + c] * s[r] * s[c];
            for (int k = 0; k < c; k++)
                v -= l[r * m + k] * l[c * m + k];
            if (r == c) {
                if (!(v > 1e-9))
                    return 0;
                l[r * m + r] = sqrt(v);
            } else
                l[r * m + c] = v / l[c * m + c];
        }
    for (int e = 0; e < m; e++) { /* column e of (S a S)^{-1}, then scaled back */
        for (int r = 0; r < m; r++) {
            double v = r == e;
            for (int k = 0; k < r; k++)
                v -= l[r * m + k] * y[k];
            y[r] = v / l[r * m + r];
        }
        for (int r = m - 1; r >= 0; r--) {
            double v = y[r];
            for (int k = r + 1; k < m; k++)
                v -= l[k * m + r] * y[k];
            y[r] = v / l[r * m + r];
        }
        for (int r = 0; r < m; r++)
            inv[r * m + e] = s[r] * y[r] * s[e];
    }
    return 1;
}

/* Particle i's moment matrix into a (m x m, m = SPH_QM(dim)). */
static void moments(const double *X, int i, int dim, const int *start, const int *nb,
                    sph_kernel_kind kernel, double h, double vol, double *a)
{
    const int m = SPH_QM(dim);
    for (int k = 0; k < m * m; k++)
        a[k] = 0;
    for (int p = start[i]; p < start[i + 1]; p++) {
        double dX[3], d[3], w[3], pv[QM_MAX];
        for (int c = 0; c < dim; c++)
            dX[c] = X[(size_t)i * dim + c] - X[(size_t)nb[p] * dim + c];
        const double f = sph_pair_w(kernel, dim, h, vol, dX, w);
        for (int c = 0; c < dim; c++)
            d[c] = -dX[c], pv[c] = d[c];
        sph_quad_monomials(dim, d, pv + dim);
        for (int r = 0; r < m; r++)
            for (int c = 0; c < m; c++)
                a[r * m + c] -= f * pv[r] * pv[c];
    }
}

int sph_quadratic_moments(const double *X, int n, int dim, const int *start, const int *nb,
                          sph_kernel_kind kernel, double h, double vol, const double *L,
                          double **Mq)
{
    const int m = SPH_QM(dim);
    *Mq = malloc((size_t)(n > 0 ? n : 0) * m * m * sizeof **Mq + 1);
    if (!*Mq) {
        sph_error("out of memory for the quadratic gradient's moments (%d particles)", n);
        exit(SPH_EXIT_SETUP);
    }
    int nsingular = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : nsingular)
    for (int i = 0; i < n; i++) {
        double a[QM_MAX * QM_MAX], *inv = *Mq + (size_t)i * m * m;
        moments(X, i, dim, start, nb, kernel, h, vol, a);
        if (spd_inverse(a, m, inv))
            continue;
        /* the linear correction alone: c = A L for the gradient, no second derivatives */
        nsingular++;
        for (int k = 0; k < m * m; k++)
            inv[k] = 0;
        for (int r = 0; r < dim; r++)
            for (int c = 0; c < dim; c++)
                inv[r * m + c] = L[(size_t)i * dim * dim + r * dim + c];
    }
    return nsingular;
}
