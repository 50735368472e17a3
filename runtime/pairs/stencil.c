/* stencil.c — the lattice stencil of a body's pair passes (sph_body's st_*, scene/body.h).
 *
 * On a lattice the particles are ordered slab by slab (run/particle_order.c), so away from
 * the surfaces, notches and the halo the neighbour at a given lattice offset is j = i + o,
 * the same o for every particle, and its offset table entry is the same too.  The CPU's pair passes then
 * run such particles offset by offset (templates/body_forces.c): for one offset, the same
 * arithmetic on consecutive particles with the table entry a constant, which the compiler
 * does several particles to a vector instruction, without the lists' indices.
 *
 * The stencil is the longest half list that two consecutive particles share (relative to
 * their indices).  A particle is in a run when its half list is the stencil, the only other
 * pairs it has are the stencil's mirror images (i - o at the same entries, which the half
 * lists of i - o hold), and it has no pair with the halo: then every pair sum over its
 * neighbours is a sum over the stencil's offsets, in both directions.  Runs shorter than
 * MIN_RUN are left to the lists.
 *
 * In 2D only: in 3D the slab order puts a body's shortest extent fastest (or the axis of a
 * prism such as the Taylor bar), and runs are the few particles across it more than a
 * support radius from both faces (4 a run on the benchmarks' plate and column), too short
 * to gain anything. */
#include <stdlib.h>
#include <string.h>

#include "stencil.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "scene/body.h"

int sph_stencil_off;

enum { MIN_RUN = 4 };

/* Whether particle i's half list is the m pairs (k[q], i + o[q]), in that order. */
static int has_list(const sph_body *b, int i, int m, const int *k, const int *o)
{
    const int p0 = b->hb_start[i];
    if (b->hb_start[i + 1] - p0 != m)
        return 0;
    for (int q = 0; q < m; q++)
        if (b->hb_k[p0 + q] != k[q] || b->hb[p0 + q] - i != o[q])
            return 0;
    return 1;
}

/* The stencil: the first particle's half list, of the greatest length, that the next
 * particle has too (relative to its index); 0 when no two do. */
static int find_stencil(sph_body *b)
{
    const int n = b->nown;
    int m = 0;
    for (int i = 0; i < n; i++)
        m = b->hb_start[i + 1] - b->hb_start[i] > m ? b->hb_start[i + 1] - b->hb_start[i] : m;
    if (m == 0)
        return 0;
    int *k = malloc((size_t)m * sizeof *k), *o = malloc((size_t)m * sizeof *o);
    if (!k || !o) {
        sph_error("out of memory");
        exit(SPH_EXIT_SETUP);
    }
    for (int i = 0; i + 1 < n; i++) {
        if (b->hb_start[i + 1] - b->hb_start[i] != m)
            continue;
        for (int q = 0; q < m; q++) {
            k[q] = b->hb_k[b->hb_start[i] + q];
            o[q] = b->hb[b->hb_start[i] + q] - i;
        }
        if (has_list(b, i + 1, m, k, o)) {
            b->st_m = m, b->st_k = k, b->st_o = o;
            return 1;
        }
    }
    free(k), free(o);
    return 0;
}

/* Whether the half list of particle p holds the pair with i at entry k (sorted by j). */
static int holds_pair(const sph_body *b, int p, int i, int k)
{
    const int p0 = b->hb_start[p], len = b->hb_start[p + 1] - p0;
    const int at = p0 + sph_first_at_least(b->hb + p0, len, 1, i);
    return at < p0 + len && b->hb[at] == i && b->hb_k[at] == k;
}

/* in[i]: whether particle i's pairs are exactly the stencil's and their mirror images. */
static void stencil_particles(const sph_body *b, uint8_t *in)
{
    const int n = b->nown, m = b->st_m;
    int *back = calloc((size_t)n, sizeof *back); /* pairs that have i as their j */
    uint8_t *list = calloc((size_t)n, 1);
    if (!back || !list) {
        sph_error("out of memory");
        exit(SPH_EXIT_SETUP);
    }
    for (int p = 0; p < b->hb_start[n]; p++)
        back[b->hb[p]]++;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++)
        list[i] = (uint8_t)has_list(b, i, m, b->st_k, b->st_o);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        int ok = list[i] && back[i] == m && (!b->xb_start || b->xb_start[i] == b->xb_start[i + 1]);
        for (int q = 0; q < m && ok; q++) {
            const int p = i - b->st_o[q];
            ok = p >= 0 && (list[p] || holds_pair(b, p, i, b->st_k[q]));
        }
        in[i] = (uint8_t)ok;
    }
    free(back), free(list);
}

/* Whether the pair of particles i and j is left to the rest lists: one is not in a run. */
static inline int rest_pair(const uint8_t *in, int i, int j)
{
    return !in[i] || !in[j];
}

/* The rest lists (scene/body.h), from the half lists; in[i]: particle i is in a run. */
static void rest_lists(sph_body *b, const uint8_t *in)
{
    const int n = b->nown;
    int nrest = 0, npairs = 0;
    for (int i = 0; i < n; i++) {
        int c = 0;
        for (int p = b->hb_start[i]; p < b->hb_start[i + 1]; p++)
            c += rest_pair(in, i, b->hb[p]);
        nrest += !in[i] || c > 0;
        npairs += c;
    }
    b->nrest = nrest;
    b->rest = malloc(((size_t)nrest + 1) * sizeof *b->rest);
    b->rest_start = malloc(((size_t)nrest + 1) * sizeof *b->rest_start);
    b->rest_j = malloc(((size_t)npairs + 1) * sizeof *b->rest_j);
    b->rest_k = malloc(((size_t)npairs + 1) * sizeof *b->rest_k);
    if (!b->rest || !b->rest_start || !b->rest_j || !b->rest_k) {
        sph_error("out of memory");
        exit(SPH_EXIT_SETUP);
    }
    int c = 0, q = 0;
    for (int i = 0; i < n; i++) {
        const int q0 = q;
        for (int p = b->hb_start[i]; p < b->hb_start[i + 1]; p++)
            if (rest_pair(in, i, b->hb[p])) {
                b->rest_j[q] = b->hb[p];
                b->rest_k[q++] = b->hb_k[p];
            }
        if (!in[i] || q > q0) {
            b->rest[c] = i;
            b->rest_start[c++] = q0;
        }
    }
    b->rest_start[c] = q;
}

void sph_stencil_setup(sph_body *b)
{
    const int n = b->nown;
    if (sph_stencil_off || b->dim != 2 || n < MIN_RUN || !find_stencil(b))
        return;
    uint8_t *in = calloc((size_t)n, 1);
    b->st_run = malloc(((size_t)n / MIN_RUN + 1) * 2 * sizeof *b->st_run);
    if (!in || !b->st_run) {
        sph_error("out of memory");
        exit(SPH_EXIT_SETUP);
    }
    stencil_particles(b, in);
    int nr = 0;
    for (int i = 0; i < n;) { /* the runs, MIN_RUN particles or more; the rest: not in one */
        int e = i;
        while (e < n && in[e])
            e++;
        if (e - i >= MIN_RUN) {
            b->st_run[2 * nr] = i, b->st_run[2 * nr + 1] = e;
            nr++;
        } else
            memset(in + i, 0, (size_t)(e - i));
        i = e > i ? e : i + 1;
    }
    b->nruns = nr;
    if (nr > 0)
        rest_lists(b, in);
    else {
        free(b->st_k), free(b->st_o), free(b->st_run);
        b->st_k = b->st_o = b->st_run = NULL;
        b->st_m = 0;
    }
    free(in);
}
