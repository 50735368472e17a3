/* test_gradients.c — corrected kernel gradients reproduce linear fields exactly.
 *
 * For a filled box and u = A X with a random A, F_i = I + sum_j (u_j - u_i) ⊗ (L_i w_ij)
 * must equal I + A at every particle (boundaries and corners included); without the
 * correction (L = I) only interior particles come close. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "core/kernel.h"
#include "geom/fill.h"
#include "geom/region.h"
#include "pairs/gradients.h"
#include "pairs/neighbours.h"
#include "unit_check.h"

/* Deterministic uniform random numbers in [-1, 1). */
static double rnd(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return 2.0 * (double)(*s >> 11) / 9007199254740992.0 - 1.0;
}

/* max_rc |F_i - I - A| for particle i, with L_i (or the identity when L is NULL). */
static double f_error(const double *X, int i, int dim, const int *st, const int *nb,
                      const double *w, const double *L, const double *A)
{
    double G[9] = { 0 }, err = 0.0;  /* G = sum (u_j - u_i) ⊗ (L_i w) */
    for (int p = st[i]; p < st[i + 1]; p++) {
        double du[3] = { 0 }, g[3] = { 0 };
        for (int r = 0; r < dim; r++)
            for (int k = 0; k < dim; k++)
                du[r] += A[r * dim + k] * (X[nb[p] * dim + k] - X[i * dim + k]);
        for (int c = 0; c < dim; c++)
            for (int k = 0; k < dim; k++)
                g[c] += (L ? L[i * dim * dim + c * dim + k] : (c == k)) * w[p * dim + k];
        for (int r = 0; r < dim; r++)
            for (int c = 0; c < dim; c++)
                G[r * dim + c] += du[r] * g[c];
    }
    for (int k = 0; k < dim * dim; k++)
        err = fmax(err, fabs(G[k] - A[k]));
    return err;
}

/* Distance of particle i to the box [lo, hi] boundary (compact components). */
static double depth(const double *X, int i, int dim, const double *lo, const double *hi)
{
    double d = HUGE_VAL;
    for (int k = 0; k < dim; k++)
        d = fmin(d, fmin(X[i * dim + k] - lo[k], hi[k] - X[i * dim + k]));
    return d;
}

/* One box in dim dimensions with one kernel. */
static void test_box(int dim, sph_kernel_kind kern, const double hi3[3], double dx)
{
    sph_shape box = { SPH_BOX, { 0, 0, 0 }, { hi3[0], dim == 2 ? 0 : hi3[1], hi3[2] }, 0, 0, NULL, NULL, 0 };
    sph_region reg = { .prims = &box, .n = 1 };
    double *X, *w, *L, A[9], lo[3] = { 0, 0, 0 }, hi[3];
    int *st, *nb, n = sph_fill_region(&reg, dim, dx, 0.0, &X);
    double h = sqrt((double)dim) * dx, vol = pow(dx, dim);
    unsigned long long seed = 12345 + dim;
    for (int k = 0; k < dim; k++)
        hi[k] = hi3[sph_axis(dim, k)];
    for (int k = 0; k < dim * dim; k++)
        A[k] = rnd(&seed);
    sph_neighbours(X, n, dim, 2 * h, 0, dx, &st, &nb);
    sph_gradients(X, n, dim, st, nb, kern, h, vol, &w, &L, NULL);
    double ec = 0.0, eu = 0.0, asym = 0.0, wmax = 0.0;
    int interior = 0;
    for (int i = 0; i < n; i++) {
        ec = fmax(ec, f_error(X, i, dim, st, nb, w, L, A));
        if (depth(X, i, dim, lo, hi) > 2 * h) {
            eu = fmax(eu, f_error(X, i, dim, st, nb, w, NULL, A));
            interior++;
        }
        for (int p = st[i]; p < st[i + 1]; p++)  /* w_ij = -w_ji (lists are symmetric) */
            for (int q = st[nb[p]]; q < st[nb[p] + 1]; q++)
                if (nb[q] == i)
                    for (int k = 0; k < dim; k++)
                        asym = fmax(asym, fabs(w[p * dim + k] + w[q * dim + k]));
        for (int p = st[i] * dim; p < st[i + 1] * dim; p++)
            wmax = fmax(wmax, fabs(w[p]));
    }
    char what[160];
    const char *kn = kern == SPH_CUBIC ? "cubic" : "wendland";
    snprintf(what, sizeof what, "%dD %s, %d particles: corrected max |F - I - A| (all)", dim, kn, n);
    check(ec < 1e-10, what, ec, 1e-10);
    snprintf(what, sizeof what, "%dD %s: uncorrected max |F - I - A|, %d interior (report)", dim,
             kn, interior);
    check(interior > 0 && eu < 5e-2, what, eu, 5e-2);
    snprintf(what, sizeof what, "%dD %s: max |w_ij + w_ji| / max |w|", dim, kn);
    check(asym <= 1e-12 * wmax, what, asym / wmax, 1e-12);
    free(X); free(st); free(nb); free(w); free(L);
}

/* Too few neighbours: an isolated particle and a pair get L = I. */
static void test_singular(void)
{
    double X[6] = { 0, 0, 1, 0, 10, 10 }, *w, *L, e = 0.0;
    int st[4] = { 0, 1, 2, 2 }, nb[2] = { 1, 0 };
    int first = -2;
    const int n = sph_gradients(X, 3, 2, st, nb, SPH_WENDLAND, 1.0, 1.0, &w, &L, &first);
    check(n == 3 && first == 0, "singular M counted (3, from particle 0)", n * 10 + first, 30);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++)
            e = fmax(e, fabs(L[i * 4 + k] - (k == 0 || k == 3)));
    check(e == 0.0, "singular M (pair, isolated particle): L = I, max deviation", e, 0.0);
    free(w);
    free(L);
}

int main(void)
{
    const double box2[3] = { 0.2, 0, 0.05 }, box3[3] = { 0.12, 0.1, 0.08 };
    for (int k = 0; k < 2; k++) {
        test_box(2, (sph_kernel_kind)k, box2, 0.005);
        test_box(3, (sph_kernel_kind)k, box3, 0.01);
    }
    test_singular();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
