/* neighbours.c — neighbour lists in the reference configuration (cell list and brute force).
 *
 * Pair criterion (identical code for both searches, see scan): j != i and
 *     |X_i - X_j|^2 <= (radius (1 + 1e-9))^2,
 * and, when range > 0, |X_i^k - X_j^k| <= (range + 0.01) dx for every component k.
 * The 1e-9 tolerance keeps pairs at exactly r == radius (lattice neighbours at exactly 2h,
 * where W = 0) regardless of rounding: with h = sqrt(dim) dx and radius = 2h a 2D lattice
 * interior particle has 24 neighbours (the 5x5 block; 20 with a strict r < 2h), a 3D one
 * has 178 (all lattice offsets with i^2 + j^2 + k^2 <= 12; 170 with a strict r < 2h).
 * Since the test uses (X_i - X_j) componentwise and a - b == -(b - a) in IEEE arithmetic,
 * the lists are exactly symmetric.
 *
 * Output: CSR, start[n+1], every list sorted by j.  Both searches run in two parallel
 * passes (count per particle, then fill at start[i]), so the only extra memory is the cell
 * list (n + ncells ints, ncells <= 2n + 64), a copy of the coordinates (3n doubles, in
 * cell order) and two small buffers per thread.
 *
 * Cell list: cubic cells of size >= the largest accepted component distance, i.e.
 * min(radius, (range + 0.01) dx) (1 + 1e-6), so every neighbour lies in the 3^dim
 * surrounding cells, scanned as 3^(dim-1) rows of three cells that are contiguous in
 * cell order; the cell size grows when the bounding box would need more than 2n + 64
 * cells (sparse point sets).  Particles are counting-sorted into cells in index order, so
 * every cell's list is ascending and a particle's candidates form at most 3^dim ascending
 * runs, merged by a natural merge sort.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "neighbours.h"
#include "core/alloc.h"
#include "core/exit_codes.h"
#include "core/message.h"

/* The search: points, pair criterion and (for the cell list) the grid. */
typedef struct {
    const double *X;
    int n, dim;
    double rc2, lim;        /* squared cut-off radius; component limit (HUGE_VAL: none) */
    int brute;              /* 1: O(n^2) candidates */
    double lo[3], cs;       /* grid origin and cell size */
    long nc[3];             /* cells per component (1 beyond dim) */
    int *cstart, *cidx;     /* CSR cells -> particles (cell list only) */
    double *P;              /* 3 coordinates per slot (0 beyond dim): the particles in
                               cell order (cell list) or in index order (brute force) */
} search;

/* malloc that ends the program with a message when memory runs out. */
static void *xmalloc(size_t size)
{
    void *p = sph_alloc_large(size, 0); /* (huge pages for large arrays: alloc.c) */
    if (!p) {
        sph_error("out of memory in the neighbour search (%zu bytes)", size);
        exit(SPH_EXIT_SETUP);
    }
    return p;
}

/* Copies particle i's coordinates into 3 slots (padding with 0). */
static void pad3(const search *s, int i, double *o)
{
    for (int k = 0; k < 3; k++)
        o[k] = k < s->dim ? s->X[(size_t)i * s->dim + k] : 0.0;
}

/* Slots q0..q1-1 of P against point a (particle i): the pair criterion, shared by both
 * searches (padding components add exact zeros).  Counts the accepted j from m on and,
 * when out is given, writes them to out[m..] (branch-free: out[m] is always written, so
 * out needs room for one entry more than the final count). */
static int scan(const search *s, const double a[3], int i, int q0, int q1, int *out, int m)
{
    const double *P = s->P;
    for (int q = q0; q < q1; q++) {
        double d0 = a[0] - P[3 * q], d1 = a[1] - P[3 * q + 1], d2 = a[2] - P[3 * q + 2];
        double r2 = d0 * d0 + d1 * d1 + d2 * d2;
        int j = s->cidx ? s->cidx[q] : q;
        int ok = (r2 <= s->rc2) & (fabs(d0) <= s->lim) & (fabs(d1) <= s->lim) &
                 (fabs(d2) <= s->lim) & (j != i);
        if (out)
            out[m] = j;
        m += ok;
    }
    return m;
}

/* Cell coordinate of value x along compact component k. */
static long cell_coord(const search *s, int k, double x)
{
    double c = floor((x - s->lo[k]) / s->cs);
    if (!(c >= 0.0))
        return 0;
    return c >= (double)s->nc[k] ? s->nc[k] - 1 : (long)c;
}

/* Linear cell index of particle i (x fastest). */
static long cell_of(const search *s, int i)
{
    long id = 0;
    for (int k = s->dim - 1; k >= 0; k--)
        id = id * s->nc[k] + cell_coord(s, k, s->X[(size_t)i * s->dim + k]);
    return id;
}

/* Grid size for cell size cs; returns the number of cells (as double, may be huge). */
static double grid_size(search *s, double hi[3])
{
    double total = 1.0;
    for (int k = 0; k < 3; k++) {
        double m = k < s->dim ? floor((hi[k] - s->lo[k]) / s->cs) + 1.0 : 1.0;
        s->nc[k] = m < 1e15 ? (long)m : (long)1e15;
        total *= m;
    }
    return total;
}

/* Bounding box, cell size and grid dimensions (at most 2n + 64 cells). */
static void grid_shape(search *s, double cutoff)
{
    double hi[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; k++)
        s->lo[k] = 0.0;
    for (int k = 0; k < s->dim; k++) {
        s->lo[k] = HUGE_VAL;
        hi[k] = -HUGE_VAL;
        for (int i = 0; i < s->n; i++) {
            s->lo[k] = fmin(s->lo[k], s->X[(size_t)i * s->dim + k]);
            hi[k] = fmax(hi[k], s->X[(size_t)i * s->dim + k]);
        }
    }
    s->cs = cutoff * (1.0 + 1e-6);
    while (grid_size(s, hi) > 2.0 * s->n + 64.0)
        s->cs *= 1.5;
}

/* Builds the cell list (counting sort in index order, so every cell's list ascends) and
 * the cell-ordered coordinates. */
static void grid_build(search *s, double cutoff)
{
    grid_shape(s, cutoff);
    long ncells = s->nc[0] * s->nc[1] * s->nc[2];
    long *cell = xmalloc((size_t)s->n * sizeof *cell);
    s->cstart = xmalloc(((size_t)ncells + 1) * sizeof *s->cstart);
    s->cidx = xmalloc((size_t)s->n * sizeof *s->cidx);
    s->P = xmalloc((size_t)s->n * 3 * sizeof *s->P);
    memset(s->cstart, 0, ((size_t)ncells + 1) * sizeof *s->cstart);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < s->n; i++)
        cell[i] = cell_of(s, i);
    for (int i = 0; i < s->n; i++)
        s->cstart[cell[i] + 1]++;
    for (long c = 0; c < ncells; c++)
        s->cstart[c + 1] += s->cstart[c];
    for (int i = 0; i < s->n; i++)
        s->cidx[s->cstart[cell[i]]++] = i;
    for (long c = ncells; c > 0; c--)  /* the fill moved every start to the next one */
        s->cstart[c] = s->cstart[c - 1];
    s->cstart[0] = 0;
#pragma omp parallel for schedule(static)
    for (int q = 0; q < s->n; q++)
        pad3(s, s->cidx[q], s->P + 3 * (size_t)q);
    free(cell);
}

/* Candidates of i from the 3^dim cells around it, scanned as 3^(dim-1) rows of up to three
 * consecutive cells along x; writes accepted j to out (when given). */
static int visit_cells(const search *s, int i, int *out)
{
    long c0[3] = { 0, 0, 0 };
    double a[3];
    int m = 0;
    pad3(s, i, a);
    for (int k = 0; k < s->dim; k++)
        c0[k] = cell_coord(s, k, a[k]);
    long x0 = c0[0] > 0 ? c0[0] - 1 : 0, x1 = c0[0] + 1 < s->nc[0] ? c0[0] + 1 : c0[0];
    for (int dz = (s->dim == 3 ? -1 : 0); dz <= (s->dim == 3 ? 1 : 0); dz++)
        for (int dy = -1; dy <= 1; dy++) {
            long cy = c0[1] + dy, cz = c0[2] + dz;
            if (cy < 0 || cy >= s->nc[1] || cz < 0 || cz >= s->nc[2])
                continue;
            long row = (cz * s->nc[1] + cy) * s->nc[0];
            m = scan(s, a, i, s->cstart[row + x0], s->cstart[row + x1 + 1], out, m);
        }
    return m;
}

/* Candidates of i among all particles (ascending). */
static int visit_all(const search *s, int i, int *out)
{
    double a[3];
    pad3(s, i, a);
    return scan(s, a, i, 0, s->n, out, 0);
}

/* End of the ascending run of a starting at i. */
static int run_end(const int *a, int i, int n)
{
    while (i + 1 < n && a[i] < a[i + 1])
        i++;
    return i + 1;
}

/* Natural merge sort of a[0..n) (ascending runs merged pairwise), tmp of n ints. */
static void sort_runs(int *a, int *tmp, int n)
{
    while (n > 1) {
        int i = 0;
        while (i < n) {
            int m = run_end(a, i, n), e = m < n ? run_end(a, m, n) : n, p = i, q = m, o = i;
            if (i == 0 && m == n)
                return;
            while (p < m && q < e)
                tmp[o++] = a[p] < a[q] ? a[p++] : a[q++];
            while (p < m)
                tmp[o++] = a[p++];
            while (q < e)
                tmp[o++] = a[q++];
            i = e;
        }
        memcpy(a, tmp, (size_t)n * sizeof *a);
    }
}

/* Candidates of i by the configured method. */
static int visit(const search *s, int i, int *out)
{
    return s->brute ? visit_all(s, i, out) : visit_cells(s, i, out);
}

/* Two-pass CSR construction (count, prefix sum, fill + sort). */
static void build_csr(const search *s, int **start, int **nb)
{
    int *st = xmalloc(((size_t)s->n + 1) * sizeof *st), maxc = 0;
    long total = 0;
    st[0] = 0;
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < s->n; i++)
        st[i + 1] = visit(s, i, NULL);
    for (int i = 0; i < s->n; i++) {
        maxc = st[i + 1] > maxc ? st[i + 1] : maxc;
        total += st[i + 1];
        if (total > 0x7fffffffL) {
            sph_error("too many neighbour pairs (> 2^31)");
            exit(SPH_EXIT_SETUP);
        }
        st[i + 1] = (int)total;
    }
    int *list = xmalloc((size_t)total * sizeof *list);
#pragma omp parallel
    {
        int *cand = xmalloc(((size_t)maxc + 1) * sizeof *cand);
        int *tmp = xmalloc((size_t)maxc * sizeof *tmp);
#pragma omp for schedule(dynamic, 256)
        for (int i = 0; i < s->n; i++) {
            int m = visit(s, i, cand);
            sort_runs(cand, tmp, m);
            memcpy(list + st[i], cand, (size_t)m * sizeof *cand);
        }
        free(cand);
        free(tmp);
    }
    *start = st;
    *nb = list;
}

/* Common set-up of both searches. */
static void neighbours(const double *X, int n, int dim, double radius, int range, double dx,
                       int brute, int **start, int **nb)
{
    search s = { .X = X, .n = n, .dim = dim, .brute = brute };
    double rc = radius * (1.0 + 1e-9);
    s.rc2 = radius > 0.0 ? rc * rc : -1.0;
    s.lim = range > 0 ? (range + 0.01) * dx : HUGE_VAL;
    double cutoff = s.lim < rc ? s.lim : rc;
    if (!(cutoff > 0.0) || n <= 0) { /* nothing can pair */
        *start = xmalloc(((size_t)(n > 0 ? n : 0) + 1) * sizeof **start);
        memset(*start, 0, ((size_t)(n > 0 ? n : 0) + 1) * sizeof **start);
        *nb = xmalloc(0);
        return;
    }
    if (!brute) {
        grid_build(&s, cutoff);
    } else {
        s.P = xmalloc((size_t)n * 3 * sizeof *s.P);
        for (int i = 0; i < n; i++)
            pad3(&s, i, s.P + 3 * (size_t)i);
    }
    build_csr(&s, start, nb);
    free(s.cstart);
    free(s.cidx);
    free(s.P);
}

void sph_neighbours(const double *X, int n, int dim, double radius, int range, double dx,
                    int **start, int **nb)
{
    neighbours(X, n, dim, radius, range, dx, 0, start, nb);
}

void sph_neighbours_brute(const double *X, int n, int dim, double radius, int range,
                          double dx, int **start, int **nb)
{
    neighbours(X, n, dim, radius, range, dx, 1, start, nb);
}
