/* particle_order.c — the order of a body's particles in memory.
 *
 * Particles are sorted lexicographically along three axes: slabs across the slowest,
 * lines along the fastest within them.  By default the longest extent is the slowest and
 * the shortest the fastest: for beams, plates and columns every neighbour of a particle
 * is then within a few slabs in memory (the gathers of the pair passes stay in cache), and
 * the half lists' reach, the largest j - i, is short, so their stripes are many (setup.c).
 *
 * In 3D the fastest axis must also give lines that are all alike: the momentum pass does
 * eight consecutive particles at once for each distinct offset j - i among them
 * (pairs/offset_blocks.c), and where consecutive lines differ (the rows of a round
 * cross-section) a block that spans two has its neighbours at two offsets for most
 * directions, some of its lanes idle.  So the fastest axis is the shortest along which the
 * body is a prism: every line along it holds the same positions (the Taylor bar's axis,
 * not the rows of its disc: its blocks' lanes 0.70 full across, 0.975 along; its run took
 * 0.87 of the time on one thread).  Where no axis is one, the default order stays.  The
 * order depends on the particles alone, never on the threads. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "particle_order.h"
#include "core/alloc.h"

/* The sort's key: the axes, slowest first, and the positions (qsort passes no context). */
static int order_axes[3];
static const double *order_X;
static int order_dim;

static int by_slab(const void *pa, const void *pb)
{
    const double *a = order_X + (size_t)(*(const int *)pa) * order_dim;
    const double *b = order_X + (size_t)(*(const int *)pb) * order_dim;
    for (int q = 0; q < order_dim; q++) {
        int k = order_axes[q];
        if (a[k] != b[k])
            return a[k] < b[k] ? -1 : 1;
    }
    return 0;
}

/* The permutation that sorts the n particles of X by axes (slowest first). */
static int *sorted(const double *X, int n, int dim, const int axes[3])
{
    int *perm = sph_alloc_setup((size_t)n * sizeof *perm, 0);
    for (int i = 0; i < n; i++)
        perm[i] = i;
    memcpy(order_axes, axes, sizeof order_axes);
    order_X = X;
    order_dim = dim;
    qsort(perm, (size_t)n, sizeof(int), by_slab);
    return perm;
}

/* Whether, in the order perm (sorted by axes), every line along the fastest axis (a run of
 * particles with the same positions along the other two) holds as many particles as the
 * first, at the same positions along it. */
static int lines_alike(const double *X, const int *perm, int n, const int axes[3])
{
    const int s = axes[0], m = axes[1], f = axes[2];
    int len = 0; /* the first line's */
    while (len < n && X[3 * (size_t)perm[len] + s] == X[3 * (size_t)perm[0] + s] &&
           X[3 * (size_t)perm[len] + m] == X[3 * (size_t)perm[0] + m])
        len++;
    if (len == 0 || n % len)
        return 0;
    for (int i = len; i < n; i++) {
        const double *x = X + 3 * (size_t)perm[i], *x0 = X + 3 * (size_t)perm[i - i % len];
        const double *y = X + 3 * (size_t)perm[i % len];
        if (x[s] != x0[s] || x[m] != x0[m] || x[f] != y[f])
            return 0;
    }
    return 1;
}

/* 3D, for a body that is not a prism along its shortest axis: the order with the shortest
 * axis along which it is one fastest (of axes, the default's, longest first), the other two
 * longest first; NULL where it is a prism along none. */
static int *prism_order(const double *X, int n, const int axes[3], const double ext[3])
{
    for (int q = 1; q >= 0; q--) {
        int other[3] = {axes[0], axes[1], axes[2]};
        other[2] = axes[q], other[q] = axes[2]; /* the candidate fastest */
        if (ext[other[0]] < ext[other[1]]) {
            const int t = other[0];
            other[0] = other[1], other[1] = t;
        }
        int *perm = sorted(X, n, 3, other);
        if (lines_alike(X, perm, n, other))
            return perm;
        free(perm);
    }
    return NULL;
}

/* The body's own particles (X, gid) put in the order perm. */
static void apply_order(sph_body *b, const int *perm)
{
    const int D = b->dim, n = b->nown;
    double *X = sph_alloc_setup((size_t)b->n * D * sizeof *X, 0);
    memcpy(X, b->X, (size_t)b->n * D * sizeof *X);
    for (int i = 0; i < n; i++)
        for (int k = 0; k < D; k++)
            X[(size_t)i * D + k] = b->X[(size_t)perm[i] * D + k];
    free(b->X);
    b->X = X;
    if (!b->gid)
        return;
    int64_t *gid = sph_alloc_setup((size_t)b->n * sizeof *gid, 0);
    memcpy(gid, b->gid, (size_t)b->n * sizeof *gid);
    for (int i = 0; i < n; i++)
        gid[i] = b->gid[perm[i]];
    free(b->gid);
    b->gid = gid;
}

void sph_order_particles(sph_body *b)
{
    const int D = b->dim, n = b->nown; /* (a halo stays after the own particles) */
    double ext[3] = {0, 0, 0};
    for (int k = 0; k < D; k++) {
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < n; i++) {
            lo = fmin(lo, b->X[(size_t)i * D + k]);
            hi = fmax(hi, b->X[(size_t)i * D + k]);
        }
        ext[k] = hi - lo;
    }
    int axes[3] = {0, 1, 2};
    for (int a = 0; a < D; a++) /* longest extent first (slowest), shortest last */
        for (int c = a + 1; c < D; c++)
            if (ext[axes[c]] > ext[axes[a]]) {
                const int t = axes[a];
                axes[a] = axes[c];
                axes[c] = t;
            }
    int *perm = sorted(b->X, n, D, axes);
    if (D == 3 && n > 0 && !lines_alike(b->X, perm, n, axes)) {
        int *p = prism_order(b->X, n, axes, ext);
        if (p)
            free(perm), perm = p;
    }
    apply_order(b, perm);
    free(perm);
}
