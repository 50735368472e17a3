/* test_neighbours.c — cell-list search == brute force (exact CSR), lattice neighbour counts,
 * nbsrange, sorted and symmetric lists. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "pairs/neighbours.h"

static int failures = 0;

/* Prints one check and counts it when it fails. */
static void check(int ok, const char *what)
{
    printf("%-4s %s\n", ok ? "ok" : "FAIL", what);
    failures += !ok;
}

/* Deterministic uniform random numbers in [0, 1). */
static double rnd(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* Random points in [0, side)^dim. */
static double *random_points(int n, int dim, double side, unsigned long long seed)
{
    double *X = malloc((size_t)n * dim * sizeof *X);
    for (int i = 0; i < n * dim; i++)
        X[i] = side * rnd(&seed);
    return X;
}

/* A lattice of m points per axis, spacing dx, cell-centred at (k + 1/2) dx. */
static double *lattice_points(int m, int dim, double dx, int *n)
{
    *n = dim == 2 ? m * m : m * m * m;
    double *X = malloc((size_t)*n * dim * sizeof *X);
    for (int i = 0; i < *n; i++)
        for (int k = 0, t = i; k < dim; k++, t /= m)
            X[i * dim + k] = (t % m + 0.5) * dx;
    return X;
}

/* 1 when every list is strictly ascending, excludes i, and (i, j) implies (j, i). */
static int sorted_symmetric(const int *st, const int *nb, int n)
{
    for (int i = 0; i < n; i++)
        for (int p = st[i]; p < st[i + 1]; p++) {
            int j = nb[p], found = 0;
            if (j == i || (p > st[i] && nb[p - 1] >= j))
                return 0;
            for (int q = st[j]; q < st[j + 1]; q++)
                found |= nb[q] == i;
            if (!found)
                return 0;
        }
    return 1;
}

/* Compares both searches on X; returns the number of pairs (or -1 on a mismatch). */
static long compare(const char *name, const double *X, int n, int dim, double radius,
                    int range, double dx)
{
    int *s1, *n1, *s2, *n2;
    char what[200];
    double t0 = omp_get_wtime();
    sph_neighbours(X, n, dim, radius, range, dx, &s1, &n1);
    double t1 = omp_get_wtime();
    sph_neighbours_brute(X, n, dim, radius, range, dx, &s2, &n2);
    double t2 = omp_get_wtime();
    int same = memcmp(s1, s2, ((size_t)n + 1) * sizeof *s1) == 0 &&
               memcmp(n1, n2, (size_t)s1[n] * sizeof *n1) == 0;
    int ok = same && sorted_symmetric(s1, n1, n);
    snprintf(what, sizeof what, "%s: n %d, range %d: cell list == brute force, sorted, symmetric "
             "(%d pairs, %.1f/particle; %.3f s vs %.3f s)", name, n, range, s1[n],
             (double)s1[n] / n, t1 - t0, t2 - t1);
    check(ok, what);
    long np = same ? s1[n] : -1;
    free(s1); free(n1); free(s2); free(n2);
    return np;
}

/* Neighbour count of the lattice particle closest to the centre. */
static int centre_count(const double *X, int n, int dim, double radius, int range, double dx,
                        int m)
{
    int *st, *nb, c = 0;
    sph_neighbours(X, n, dim, radius, range, dx, &st, &nb);
    for (int k = dim - 1; k >= 0; k--)
        c = c * m + m / 2;
    int cnt = st[c + 1] - st[c];
    free(st);
    free(nb);
    return cnt;
}

/* Random point sets, with and without nbsrange, plus a sparse set (two far clusters). */
static void test_random(void)
{
    double *X = random_points(3000, 2, 1.0, 1);
    compare("random 2D", X, 3000, 2, 0.05, 0, 0.02);
    compare("random 2D", X, 3000, 2, 0.05, 1, 0.02);
    compare("random 2D", X, 3000, 2, 0.05, 2, 0.02);
    free(X);
    X = random_points(4000, 3, 1.0, 2);
    compare("random 3D", X, 4000, 3, 0.12, 0, 0.05);
    compare("random 3D", X, 4000, 3, 0.12, 1, 0.05);
    for (int i = 0; i < 2000 * 3; i++) /* half of them far away: sparse bounding box */
        X[i] += 1000.0;
    compare("two clusters 3D", X, 4000, 3, 0.12, 0, 0.05);
    free(X);
}

/* Lattices: exact comparisons, neighbour counts, the boundary case r == 2h. */
static void test_lattice(void)
{
    char what[200];
    int n, m = 21;
    double dx = 0.01, h2 = sqrt(2.0) * dx, h3 = sqrt(3.0) * dx;
    double *X = lattice_points(m, 2, dx, &n);
    compare("lattice 2D, 2h = 2 sqrt(2) dx", X, n, 2, 2 * h2, 0, dx);
    compare("lattice 2D, nbsrange", X, n, 2, 2 * h2, 1, dx);
    int c0 = centre_count(X, n, 2, 2 * h2, 0, dx, m), c1 = centre_count(X, n, 2, 2 * h2, 1, dx, m);
    snprintf(what, sizeof what, "lattice 2D interior, h = sqrt(2) dx, r <= 2h: %d neighbours "
             "(expected 24); nbsrange 1: %d (expected 8)", c0, c1);
    check(c0 == 24 && c1 == 8, what);
    free(X);
    m = 13;
    X = lattice_points(m, 3, dx, &n);
    compare("lattice 3D, 2h = 2 sqrt(3) dx", X, n, 3, 2 * h3, 0, dx);
    compare("lattice 3D, nbsrange", X, n, 3, 2 * h3, 2, dx);
    c0 = centre_count(X, n, 3, 2 * h3, 0, dx, m);
    c1 = centre_count(X, n, 3, 2 * h3, 1, dx, m);
    int c2 = centre_count(X, n, 3, 2 * h3, 2, dx, m);
    snprintf(what, sizeof what, "lattice 3D interior, h = sqrt(3) dx, r <= 2h: %d neighbours "
             "(expected 178); nbsrange 1: %d (26), 2: %d (124)", c0, c1, c2);
    check(c0 == 178 && c1 == 26 && c2 == 124, what);
    free(X);
}

/* Edge cases: no particles, one particle, zero radius. */
static void test_edges(void)
{
    int *st, *nb;
    double x[3] = { 0, 0, 0 };
    sph_neighbours(x, 0, 3, 1.0, 0, 1.0, &st, &nb);
    int ok = st[0] == 0;
    free(st); free(nb);
    sph_neighbours(x, 1, 3, 1.0, 0, 1.0, &st, &nb);
    ok = ok && st[0] == 0 && st[1] == 0;
    free(st); free(nb);
    double y[4] = { 0, 0, 0, 0 }; /* two coincident points, zero radius */
    sph_neighbours(y, 2, 2, 0.0, 0, 1.0, &st, &nb);
    ok = ok && st[2] == 0;
    free(st); free(nb);
    check(ok, "edge cases: n = 0, n = 1, radius 0");
}

/* A larger 3D lattice for timing (reported, not checked beyond the count). */
static void test_timing(void)
{
    int n, m = 40, *st, *nb;
    double dx = 1.0, *X = lattice_points(m, 3, dx, &n), t0 = omp_get_wtime();
    sph_neighbours(X, n, 3, 2 * sqrt(3.0) * dx, 0, dx, &st, &nb);
    double t1 = omp_get_wtime();
    char what[200];
    snprintf(what, sizeof what, "timing: 3D lattice %d particles, %d pairs, %.3f s on %d threads",
             n, st[n], t1 - t0, omp_get_max_threads());
    check(st[n] > 150L * n, what);
    free(X); free(st); free(nb);
}

int main(void)
{
    test_random();
    test_lattice();
    test_edges();
    test_timing();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
