/* mesh_check.c — a closed, consistently oriented surface (mesh.h).
 *
 * Closed: every edge (a pair of vertices) belongs to exactly two triangles.  An edge of one
 * triangle only is the rim of a hole; one of three or more makes a non-manifold surface.
 * Oriented: two triangles that share an edge run through it in opposite directions.
 * Triangles are flipped to reach that, piece by piece (connected through shared edges); a
 * piece where it cannot be reached is not orientable.  Each piece is then turned outwards
 * (positive enclosed volume); a piece that lies inside an odd number of the others bounds a
 * cavity and is turned inwards.  The volume is the divergence theorem's
 * V = sum over triangles of a . (b x c) / 6, taken about the centre of the bounding box. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"

typedef struct {
    int a, b;      /* the edge's vertices, a < b */
    int tri;       /* the triangle */
    int forward;   /* 1: the triangle runs from a to b */
} edge;

static int by_vertices(const void *pa, const void *pb)
{
    const edge *x = pa, *y = pb;
    if (x->a != y->a)
        return x->a < y->a ? -1 : 1;
    if (x->b != y->b)
        return x->b < y->b ? -1 : 1;
    return x->tri - y->tri;
}

static void flip(sph_mesh *m, int k)
{
    int s = m->t[3 * k + 1];
    m->t[3 * k + 1] = m->t[3 * k + 2];
    m->t[3 * k + 2] = s;
}

/* "FILE: the surface is not closed ...: N edges belong to one triangle only, e.g. ..." */
static int fail(const sph_mesh *m, char *err, size_t len, const char *what, const char *how,
                const edge *e, int count)
{
    const double *p = m->v + 3 * e->a, *q = m->v + 3 * e->b;
    snprintf(err, len, "%s: %s: %d edge%s %s, e.g. the edge from (%g, %g, %g) to (%g, %g, %g)",
             m->file, what, count, count == 1 ? "" : "s", how, p[0], p[1], p[2], q[0], q[1],
             q[2]);
    return -1;
}

/* Sorted edges; checks that each is shared by exactly two triangles. */
static edge *edges(const sph_mesh *m, char *err, size_t len)
{
    long ne = 3L * m->nt;
    edge *e = malloc((size_t)ne * sizeof *e);
    for (int k = 0; k < m->nt; k++)
        for (int c = 0; c < 3; c++) {
            int u = m->t[3 * k + c], w = m->t[3 * k + (c + 1) % 3];
            e[3 * k + c] = (edge){u < w ? u : w, u < w ? w : u, k, u < w};
        }
    qsort(e, (size_t)ne, sizeof *e, by_vertices);
    int open = 0, many = 0;
    const edge *first_open = NULL, *first_many = NULL;
    for (long i = 0; i < ne;) {
        long j = i;
        while (j < ne && e[j].a == e[i].a && e[j].b == e[i].b)
            j++;
        if (j - i == 1 && !open++)
            first_open = &e[i];
        if (j - i > 2 && !many++)
            first_many = &e[i];
        i = j;
    }
    if (open)
        fail(m, err, len, "the surface is not closed (it has a hole)",
             open == 1 ? "belongs to one triangle only" : "belong to one triangle only",
             first_open, open);
    else if (many)
        fail(m, err, len, "the surface is not a manifold",
             many == 1 ? "is shared by more than two triangles" :
                         "are shared by more than two triangles", first_many, many);
    if (open || many) {
        free(e);
        return NULL;
    }
    return e;
}

/* Orients every piece consistently (flips), numbering the pieces in comp[]; -1 when a piece
 * cannot be oriented. */
static int orient(sph_mesh *m, const edge *e, int *comp, char *err, size_t len)
{
    size_t nt = (size_t)m->nt;
    int *nbr = malloc(nt * 3 * sizeof *nbr), *same = malloc(nt * 3 * sizeof *same);
    int *queue = malloc(nt * sizeof *queue), *flipped = calloc(nt, sizeof *flipped);
    int *slot = calloc(nt, sizeof *slot);
    /* The sorted edges come in pairs (edges() checked it): per triangle, the neighbour
     * across each of its edges and whether the two run through it the same way. */
    for (long i = 0; i < 3L * m->nt; i += 2) {
        const edge *x = &e[i], *y = &e[i + 1];
        nbr[3 * x->tri + slot[x->tri]] = y->tri;
        same[3 * x->tri + slot[x->tri]++] = x->forward == y->forward;
        nbr[3 * y->tri + slot[y->tri]] = x->tri;
        same[3 * y->tri + slot[y->tri]++] = x->forward == y->forward;
    }
    int bad = 0, ncomp = 0;
    for (int k = 0; k < m->nt; k++)
        comp[k] = -1;
    for (int s = 0; s < m->nt && !bad; s++) {
        if (comp[s] >= 0)
            continue;
        int head = 0, tail = 0;
        comp[s] = ncomp;
        queue[tail++] = s;
        while (head < tail && !bad) {
            int k = queue[head++];
            for (int c = 0; c < 3; c++) {
                int j = nbr[3 * k + c];
                /* j must run through the edge opposite to k: with both as stored, that is
                 * `same == 0`; each flip toggles it. */
                int want_flip = same[3 * k + c] ^ flipped[k];
                if (comp[j] < 0) {
                    comp[j] = ncomp;
                    flipped[j] = want_flip;
                    queue[tail++] = j;
                } else if (flipped[j] != want_flip) {
                    snprintf(err, len, "%s: the surface cannot be oriented (its two sides are "
                                       "one, as on a Moebius strip)", m->file);
                    bad = 1;
                    break;
                }
            }
        }
        ncomp++;
    }
    for (int k = 0; k < m->nt && !bad; k++)
        if (flipped[k])
            flip(m, k);
    m->ncomponents = ncomp;
    free(nbr), free(queue), free(flipped), free(slot), free(same);
    return bad ? -1 : 0;
}

/* Six times the signed volume of triangle k about the point o. */
static double volume6(const sph_mesh *m, int k, const double o[3])
{
    double a[3], b[3], c[3];
    for (int d = 0; d < 3; d++) {
        a[d] = m->v[3 * m->t[3 * k] + d] - o[d];
        b[d] = m->v[3 * m->t[3 * k + 1] + d] - o[d];
        c[d] = m->v[3 * m->t[3 * k + 2] + d] - o[d];
    }
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/* Whether a point of piece c lies inside an odd number of the other pieces. */
static int is_cavity(const sph_mesh *m, const int *comp, int c)
{
    int k0 = 0;
    while (comp[k0] != c)
        k0++;
    double p[3] = {0, 0, 0}, z;
    for (int d = 0; d < 3; d++)
        for (int v = 0; v < 3; v++)
            p[d] += m->v[3 * m->t[3 * k0 + v] + d] / 3.0;
    int crossings = 0;
    for (int k = 0; k < m->nt; k++)
        if (comp[k] != c && sph_mesh_ray_hits(m, k, p, &z) && z > p[2])
            crossings++;
    return crossings % 2;
}

int sph_mesh_close(sph_mesh *m, char *err, size_t len)
{
    for (int d = 0; d < 3; d++) {
        m->lo[d] = HUGE_VAL;
        m->hi[d] = -HUGE_VAL;
    }
    for (int i = 0; i < m->nv; i++)
        for (int d = 0; d < 3; d++) {
            m->lo[d] = fmin(m->lo[d], m->v[3 * i + d]);
            m->hi[d] = fmax(m->hi[d], m->v[3 * i + d]);
        }
    m->eps = 0;
    for (int d = 0; d < 3; d++)
        m->eps = fmax(m->eps, 1e-6 * fmax(fabs(m->lo[d]), fabs(m->hi[d])));
    edge *e = edges(m, err, len);
    if (!e)
        return -1;
    int *comp = malloc((size_t)m->nt * sizeof *comp);
    int bad = orient(m, e, comp, err, len);
    free(e);
    double o[3], *vol = calloc((size_t)m->ncomponents + 1, sizeof *vol);
    for (int d = 0; d < 3; d++)
        o[d] = 0.5 * (m->lo[d] + m->hi[d]);
    for (int k = 0; k < m->nt && !bad; k++)
        vol[comp[k]] += volume6(m, k, o) / 6.0;
    m->volume = 0;
    for (int c = 0; c < m->ncomponents && !bad; c++) {
        int outwards = m->ncomponents > 1 && is_cavity(m, comp, c) ? -1 : 1;
        if (vol[c] * outwards < 0) {
            for (int k = 0; k < m->nt; k++)
                if (comp[k] == c)
                    flip(m, k);
            vol[c] = -vol[c];
        }
        m->volume += vol[c];
    }
    free(comp);
    free(vol);
    if (!bad && !(m->volume > 0)) {
        snprintf(err, len, "%s: the surface encloses no volume", m->file);
        bad = 1;
    }
    return bad ? -1 : 0;
}
