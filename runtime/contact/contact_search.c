/* contact_search.c — candidate contact pairs from a hashed cell list (contact_search.h).
 *
 * Cells are cubes of side (largest contact distance + skin), so every candidate lies in a
 * particle's own cell or a neighbouring one.  Cells are hashed into a table of about 2n
 * buckets, which needs no bounding box (bodies may fly apart); a bucket may hold several
 * cells, so a particle found in a bucket is kept only when its cell is the one looked for,
 * and each pair is seen exactly once per direction. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "contact_law.h"
#include "contact_search.h"

typedef struct {
    double cell;        /* cell side */
    uint64_t mask;      /* buckets - 1 (a power of two) */
    int64_t *key;       /* n*3 cell coordinates of each particle */
    int *head, *order;  /* buckets + 1 starts into order; particles by bucket */
} grid;

static uint64_t hash3(const int64_t c[3])
{
    uint64_t h = (uint64_t)c[0] * 73856093u ^ (uint64_t)c[1] * 19349663u ^
                 (uint64_t)c[2] * 83492791u;
    return h ^ (h >> 29);
}

static void grid_build(grid *g, const double *x, int n, int dim)
{
    size_t buckets = 1;
    while (buckets < 2 * (size_t)n)
        buckets <<= 1;
    g->mask = buckets - 1;
    g->key = malloc((size_t)n * 3 * sizeof *g->key);
    g->head = calloc(buckets + 1, sizeof *g->head);
    g->order = malloc((size_t)n * sizeof *g->order);
    for (int i = 0; i < n; i++) {
        int64_t *c = g->key + (size_t)i * 3;
        c[1] = c[2] = 0;
        for (int k = 0; k < dim; k++)
            c[k] = sph_contact_cell_of(x[(size_t)i * dim + k], g->cell);
        g->head[(hash3(c) & g->mask) + 1]++;
    }
    for (size_t b = 0; b < buckets; b++)
        g->head[b + 1] += g->head[b];
    int *fill = malloc(buckets * sizeof *fill);
    memcpy(fill, g->head, buckets * sizeof *fill);
    for (int i = 0; i < n; i++)
        g->order[fill[hash3(g->key + (size_t)i * 3) & g->mask]++] = i;
    free(fill);
}

static void grid_free(grid *g)
{
    free(g->key);
    free(g->head);
    free(g->order);
}

/* The candidates of particle i; writes them to out (when not NULL) and returns how many. */
static int candidates(const sph_csearch *c, const grid *g, const double *x, int i, int *out)
{
    const int dim = c->dim, bi = c->body[i];
    const int64_t *ci = g->key + (size_t)i * 3;
    const double *xi = x + (size_t)i * dim;
    int count = 0;
    const int span[3] = {1, 1, dim > 2}; /* 2D: the third cell coordinate is always 0 */
    for (int o0 = -span[0]; o0 <= span[0]; o0++)
        for (int o1 = -span[1]; o1 <= span[1]; o1++)
            for (int o2 = -span[2]; o2 <= span[2]; o2++) {
                const int64_t cj[3] = {ci[0] + o0, ci[1] + o1, ci[2] + o2};
                const uint64_t b = hash3(cj) & g->mask;
                for (int p = g->head[b]; p < g->head[b + 1]; p++) {
                    const int j = g->order[p];
                    const int64_t *kj = g->key + (size_t)j * 3;
                    if (c->body[j] == bi || kj[0] != cj[0] || kj[1] != cj[1] || kj[2] != cj[2])
                        continue;
                    const double reach = c->dc[bi * c->nbodies + c->body[j]] + c->skin;
                    double r2 = 0;
                    for (int k = 0; k < dim; k++) {
                        const double d = xi[k] - x[(size_t)j * dim + k];
                        r2 += d * d;
                    }
                    if (r2 > reach * reach)
                        continue;
                    if (out)
                        out[count] = j;
                    count++;
                }
            }
    return count;
}

static void rebuild(sph_csearch *c, const double *x)
{
    double dcmax = 0;
    for (int k = 0; k < c->nbodies * c->nbodies; k++)
        dcmax = fmax(dcmax, c->dc[k]);
    grid g = {.cell = dcmax + c->skin};
    grid_build(&g, x, c->n, c->dim);
    free(c->start);
    free(c->nb);
    c->start = calloc((size_t)c->n + 1, sizeof *c->start);
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < c->n; i++)
        c->start[i + 1] = candidates(c, &g, x, i, NULL);
    c->nactive = 0;
    for (int i = 0; i < c->n; i++) {
        if (c->start[i + 1])
            c->active[c->nactive++] = i;
        c->start[i + 1] += c->start[i];
    }
    c->nb = malloc(((size_t)c->start[c->n] + 1) * sizeof *c->nb);
#pragma omp parallel for schedule(dynamic, 64)
    for (int a = 0; a < c->nactive; a++) {
        const int i = c->active[a];
        candidates(c, &g, x, i, c->nb + c->start[i]);
    }
    grid_free(&g);
    memcpy(c->x0, x, (size_t)c->n * c->dim * sizeof *x);
    c->builds++;
    c->built = 1;
}

static void allocate(sph_csearch *c)
{
    if (c->x0)
        return;
    c->x0 = malloc((size_t)c->n * c->dim * sizeof *c->x0);
    c->active = malloc(((size_t)c->n + 1) * sizeof *c->active);
}

void sph_csearch_build_at(sph_csearch *c, const double *x0)
{
    allocate(c);
    rebuild(c, x0);
}

int sph_csearch_update(sph_csearch *c, const double *x)
{
    allocate(c);
    if (c->built) {
        double moved2 = 0;
        const size_t nd = (size_t)c->n * c->dim;
#pragma omp parallel for schedule(static) reduction(max : moved2)
        for (size_t p = 0; p < nd; p += (size_t)c->dim) {
            double d2 = 0;
            for (int k = 0; k < c->dim; k++) {
                const double d = x[p + k] - c->x0[p + k];
                d2 += d * d;
            }
            moved2 = d2 > moved2 ? d2 : moved2;
        }
        if (!sph_csearch_stale(c, moved2))
            return 0;
    }
    rebuild(c, x);
    return 1;
}

void sph_csearch_free(sph_csearch *c)
{
    free(c->x0);
    free(c->start);
    free(c->nb);
    free(c->active);
    memset(c, 0, sizeof *c);
}

void sph_csearch_reset(sph_csearch *c, int n, const int *body)
{
    free(c->x0), free(c->active);
    c->x0 = NULL, c->active = NULL;
    c->n = n, c->body = body;
    c->built = 0;
}
