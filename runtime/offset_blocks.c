/* offset_blocks.c — the offset blocks of a 3D body's gradient pass (sph_body's ob_*, sphrt.h).
 *
 * The CPU's gradient pass sums A_i = sum_j (u_j - u_i) (x) w_ij.  Over the half lists each
 * pair is visited once and adds its tensor to both A_i and A_j; in 3D that is a read, an add
 * and a write of j's twelve entries a pair, one pair at a time in vectors of four.  On a
 * lattice, blocks of 8 consecutive particles share most of their offsets: the neighbour at a
 * given lattice offset is j = i + o for the block's particles, with the same table entry, so
 * one such task of a block is 8 pairs in one vector of eight, u_j one unaligned load from u
 * stored by component, and A's nine entries nine multiply-adds, held in registers over the
 * block's tasks and written once.  Each pair is summed from both sides (the full lists) and
 * nothing is written to j: the 3D Taylor bar's stress pass (the gradient pass in it) took
 * 0.6 of its time with the half lists, its step 0.84 (templates/body_forces.c,
 * OFFSET_BLOCKS).
 *
 * A block's tasks are the distinct (o, entry) of its particles' full lists of own pairs,
 * each with the mask of the block's particles that have that pair (near surfaces, notches
 * and the ends of lattice rows, fewer than 8).  Built from the full lists (before the half
 * lists replace them), in parallel, block by block; used only where the masks hold at least
 * 0.45 of the tasks' lanes (the Taylor bar's blocks 0.73, a body of 138 particles 0.5): a
 * task took about as long as three directions of pairs of the half lists (2.6 ns against
 * 0.8, the bar on one thread), so below 0.4 the lists are faster, and off a lattice, where
 * every pair has its own entry and a task holds one pair, they stay.  Pairs with the
 * halo (many processes) stay on their lists (xb_*).  None with sph_stencil_off (the
 * program's --no-stencil), in 2D (its lattice stencil) or for bodies with fracture. */
#include <stdlib.h>
#include <string.h>

#include "internal.h"

enum { LANES = SPH_OB_LANES, MIN_PERMILLE = 450, KBITS = 24, OBITS = 28 };

/* A task's sort key: the offset j - i (made non-negative) above the table entry. */
static long long task_key(int off, int k)
{
    return ((long long)off + (1LL << OBITS)) << KBITS | k;
}

static int by_key(const void *pa, const void *pb)
{
    const long long a = *(const long long *)pa, b = *(const long long *)pb;
    return a < b ? -1 : a > b;
}

/* Block B's tasks: its particles' own pairs as keys, lane l's from keys + l degree (its
 * count in m[l]), ascending (the lists are sorted by j; sorted here where one is not),
 * merged lane by lane into tasks.  Returns their number, and writes them to out where
 * given: offset, entry << 8 | lane mask. */
static int block_tasks(const sph_body *b, int B, int degree, long long *keys, sph_ob_task *out)
{
    int m[LANES] = {0}, at[LANES] = {0};
    for (int l = 0; l < LANES && LANES * B + l < b->nown; l++) {
        const int i = LANES * B + l;
        long long *k = keys + (size_t)l * degree;
        int sorted = 1;
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++)
            if (b->nb[p] < b->nown) {
                k[m[l]] = task_key(b->nb[p] - i, b->nb_k[p]);
                sorted &= m[l] == 0 || k[m[l]] > k[m[l] - 1];
                m[l]++;
            }
        if (!sorted)
            qsort(k, (size_t)m[l], sizeof *k, by_key);
    }
    int nt = 0;
    long long last = -1;
    for (;;) { /* the smallest key at the lanes' heads, with every lane that has it */
        long long least = -1;
        for (int l = 0; l < LANES; l++)
            if (at[l] < m[l] && (least < 0 || keys[(size_t)l * degree + at[l]] < least))
                least = keys[(size_t)l * degree + at[l]];
        if (least < 0)
            return nt;
        if (least != last) {
            if (out)
                out[nt] = (sph_ob_task){(int)((least >> KBITS) - (1LL << OBITS)),
                                        (unsigned)(least & ((1 << KBITS) - 1)) << 8};
            nt++;
            last = least;
        }
        for (int l = 0; l < LANES; l++)
            if (at[l] < m[l] && keys[(size_t)l * degree + at[l]] == least) {
                at[l]++;
                if (out)
                    out[nt - 1].key |= 1u << l;
            }
    }
}

static void *xmalloc(size_t bytes)
{
    void *p = sph_alloc_large(bytes ? bytes : 1, 0);
    if (!p) {
        sph_error("out of memory (the offset blocks)");
        exit(SPH_EXIT_SETUP);
    }
    return p;
}

void sph_offset_blocks_setup(sph_body *b, int fracture)
{
    const int n = b->nown;
    if (sph_stencil_off || b->dim != 3 || fracture || n < LANES || b->ntab >= (1 << KBITS))
        return;
    const int nblocks = (n + LANES - 1) / LANES;
    int degree = 0, reach = 0; /* the longest own list; the longest |j - i| */
    long pairs = 0;
#pragma omp parallel for schedule(static) reduction(max : degree, reach) reduction(+ : pairs)
    for (int i = 0; i < n; i++) {
        int c = 0;
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++)
            if (b->nb[p] < n) {
                c++;
                reach = abs(b->nb[p] - i) > reach ? abs(b->nb[p] - i) : reach;
            }
        degree = c > degree ? c : degree;
        pairs += c;
    }
    if (reach >= (1 << OBITS))
        return;
    int *start = xmalloc(((size_t)nblocks + 1) * sizeof *start);
    start[0] = 0;
#pragma omp parallel
    {
        long long *keys = xmalloc((size_t)LANES * degree * sizeof *keys + 1);
#pragma omp for schedule(dynamic, 64)
        for (int B = 0; B < nblocks; B++)
            start[B + 1] = block_tasks(b, B, degree, keys, NULL);
        free(keys);
    }
    for (int B = 0; B < nblocks; B++)
        start[B + 1] += start[B];
    const long ntasks = start[nblocks];
    if (pairs == 0 || 1000 * pairs < (long)MIN_PERMILLE * LANES * ntasks) { /* not a lattice */
        free(start);
        return;
    }
    b->ob = xmalloc((size_t)ntasks * sizeof *b->ob);
#pragma omp parallel
    {
        long long *keys = xmalloc((size_t)LANES * degree * sizeof *keys + 1);
#pragma omp for schedule(dynamic, 64)
        for (int B = 0; B < nblocks; B++)
            block_tasks(b, B, degree, keys, b->ob + start[B]);
        free(keys);
    }
    b->ob_start = start;
    b->nob = nblocks;
    long lanes = 0; /* the pairs the masks hold (the summary's offset_block_pairs: all own) */
#pragma omp parallel for schedule(static) reduction(+ : lanes)
    for (long t = 0; t < ntasks; t++)
        lanes += __builtin_popcount(b->ob[t].key & 255);
    b->ob_pairs = lanes;
    /* u by component, each row with room for reach particles (and a vector) before the
     * first and after the last, so that every lane's u_j load stays in the array */
    b->ob_pad = (reach + LANES + LANES - 1) / LANES * LANES;
    b->ob_stride = LANES * nblocks + 2 * b->ob_pad;
    const size_t bytes = 3 * (size_t)b->ob_stride * sizeof *b->ob_u;
    b->ob_u = aligned_alloc(64, (bytes + 63) / 64 * 64);
    if (!b->ob_u) {
        sph_error("out of memory (the offset blocks)");
        exit(SPH_EXIT_SETUP);
    }
    memset(b->ob_u, 0, bytes);
}
