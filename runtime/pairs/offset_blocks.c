/* offset_blocks.c — the offset blocks of a 3D body's pair passes (sph_body's ob_* and mb_*,
 * scene/body.h; templates/body_forces.c, OFFSET_BLOCKS and MOMENTUM_BLOCKS).
 *
 * On a lattice, blocks of 8 consecutive particles share most of their offsets: the
 * neighbour at a given lattice offset is j = i + o for the block's particles, with the same
 * table entry, so one task of a block (one offset, one entry) is 8 pairs in vectors of
 * eight, j's values unaligned loads from copies by component, and the block's sums held in
 * registers over its tasks and written once.  A block's tasks are the distinct (o, entry)
 * of its particles' pairs, each with the mask of the particles that have it (near surfaces,
 * notches and the ends of lattice rows, fewer than 8); the 8 lists, sorted by j, merged.
 *
 * The gradient pass (ob_*): blocks of the full lists of own pairs (built before the half
 * lists replace them), each pair from both sides, nothing written to j, u by component.  A
 * task took about as long as three directions of the half lists' pairs (2.6 ns against 0.8,
 * the Taylor bar on one thread), so they are used where the masks fill 0.45 of the lanes
 * (the bar 0.73, a body of 138 particles 0.5); the bar's stress pass (the gradient pass in
 * it) took 0.6 of its time with the half lists, its step 0.84.
 *
 * The momentum pass (mb_*): blocks of the half lists within each stripe, each pair once,
 * j's share subtracted from j's sums by component, so that the stripes' colours stay
 * parallel.  A task took about as long as 4.7 pairs of the lists (65 cycles against 13.7),
 * so they are used where the masks fill 0.65 of the lanes; the bar's momentum pass took
 * 0.80 of its time on two threads, its step 0.86.
 *
 * Off a lattice, where every pair has its own entry and a task holds one pair, the lists
 * stay.  Pairs with the halo (many processes) stay on their lists (xb_*).  None with
 * sph_stencil_off (the program's --no-stencil), in 2D (its lattice stencil), or for a pass
 * the body's desc leaves out (offset_blocks: the compiler's plan, CPU only). */
#include <stdlib.h>
#include <string.h>

#include "offset_blocks.h"
#include "stencil.h"
#include "core/alloc.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "scene/body.h"

/* the lanes' share (per mille) the masks must fill: the gradient's blocks, the momentum's */
enum { LANES = SPH_OB_LANES, OB_PERMILLE = 450, MB_PERMILLE = 650, KBITS = 24, OBITS = 28 };

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

/* Pair lists in CSR form (the full lists, own pairs only, or the half lists). */
typedef struct {
    const int *start, *j, *k;
    int nown;
} lists;

/* The tasks of the block of count particles from first: their pairs as keys, lane l's from
 * keys + l degree (its count in m[l]), ascending (the lists are sorted by j; sorted here
 * where one is not), merged lane by lane into tasks.  Returns their number, and writes them
 * to out where given: offset, entry << 8 | lane mask. */
static int block_tasks(const lists *L, int first, int count, int degree, long long *keys,
                       sph_ob_task *out)
{
    int m[LANES] = {0}, at[LANES] = {0};
    for (int l = 0; l < count; l++) {
        const int i = first + l;
        long long *k = keys + (size_t)l * degree;
        int sorted = 1;
        for (int p = L->start[i]; p < L->start[i + 1]; p++)
            if (L->j[p] < L->nown) {
                k[m[l]] = task_key(L->j[p] - i, L->k[p]);
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

/* Whether body b may have offset blocks (bit `bit` of its desc's offset_blocks). */
static int blocks_wanted(const sph_body *b, int bit)
{
    return !sph_stencil_off && b->dim == 3 && (b->desc->offset_blocks & bit) &&
           b->nown >= LANES && b->ntab < (1 << KBITS);
}

/* The tasks of nblocks blocks from lists L (block B: count[B] particles from first[B]; lists
 * of at most degree pairs), counted and then written, in parallel; NULL where their masks
 * would hold fewer than permille of the lanes, or no pair.  *start gets the blocks' first
 * tasks (nblocks + 1 of them), *lanes the pairs the masks hold. */
static sph_ob_task *build_tasks(const lists *L, int nblocks, const int *first,
                                const unsigned char *count, int degree, int permille,
                                int **start_out, long *lanes_out)
{
    int *start = xmalloc(((size_t)nblocks + 1) * sizeof *start);
    start[0] = 0;
    sph_ob_task *tasks = NULL;
    for (int pass = 0; pass < 2; pass++) {
#pragma omp parallel
        {
            long long *keys = xmalloc((size_t)LANES * degree * sizeof *keys + 1);
#pragma omp for schedule(dynamic, 64)
            for (int B = 0; B < nblocks; B++) {
                const int nt = block_tasks(L, first[B], count[B], degree, keys,
                                           tasks ? tasks + start[B] : NULL);
                if (!tasks)
                    start[B + 1] = nt;
            }
            free(keys);
        }
        if (tasks)
            break;
        for (int B = 0; B < nblocks; B++)
            start[B + 1] += start[B];
        long pairs = 0;
#pragma omp parallel for schedule(static) reduction(+ : pairs)
        for (int B = 0; B < nblocks; B++)
            for (int p = L->start[first[B]]; p < L->start[first[B] + count[B]]; p++)
                pairs += L->j[p] < L->nown;
        const long ntasks = start[nblocks];
        if (pairs == 0 || 1000 * pairs < (long)permille * LANES * ntasks) { /* not a lattice */
            free(start);
            return NULL;
        }
        tasks = xmalloc((size_t)ntasks * sizeof *tasks);
    }
    long lanes = 0;
#pragma omp parallel for schedule(static) reduction(+ : lanes)
    for (long t = 0; t < start[nblocks]; t++)
        lanes += __builtin_popcount(tasks[t].key & 255);
    *start_out = start, *lanes_out = lanes;
    return tasks;
}

/* rows rows of stride doubles, zero, each particle i at pad + i of its row, with pad room
 * for reach particles and a vector before the first and after the last (n) particle, so
 * that every lane's load stays in the array. */
static double *rows_of(int rows, int n, int reach, int *pad, int *stride)
{
    *pad = (reach + LANES + LANES - 1) / LANES * LANES;
    *stride = (n + LANES - 1) / LANES * LANES + 2 * *pad;
    const size_t bytes = (size_t)rows * (size_t)*stride * sizeof(double);
    double *p = aligned_alloc(64, (bytes + 63) / 64 * 64);
    if (!p) {
        sph_error("out of memory (the offset blocks)");
        exit(SPH_EXIT_SETUP);
    }
    return memset(p, 0, bytes);
}

/* The longest list of L's first n particles and its longest |j - i|, in *degree, *reach. */
static void list_extent(const lists *L, int n, int *degree, int *reach)
{
    int d = 0, r = 0;
#pragma omp parallel for schedule(static) reduction(max : d, r)
    for (int i = 0; i < n; i++) {
        int c = 0;
        for (int p = L->start[i]; p < L->start[i + 1]; p++)
            if (L->j[p] < L->nown) {
                c++;
                r = abs(L->j[p] - i) > r ? abs(L->j[p] - i) : r;
            }
        d = c > d ? c : d;
    }
    *degree = d, *reach = r;
}

void sph_offset_blocks_setup(sph_body *b)
{
    const int n = b->nown;
    if (!blocks_wanted(b, 1))
        return;
    const lists L = {b->nb_start, b->nb, b->nb_k, n};
    int degree, reach;
    list_extent(&L, n, &degree, &reach);
    if (reach >= (1 << OBITS))
        return;
    const int nblocks = (n + LANES - 1) / LANES;
    int *first = xmalloc((size_t)nblocks * sizeof *first);
    unsigned char *count = xmalloc((size_t)nblocks);
    for (int B = 0; B < nblocks; B++)
        first[B] = LANES * B, count[B] = (unsigned char)(n - LANES * B < LANES ? n - LANES * B : LANES);
    b->ob = build_tasks(&L, nblocks, first, count, degree, OB_PERMILLE, &b->ob_start, &b->ob_pairs);
    free(first), free(count);
    if (!b->ob)
        return;
    b->nob = nblocks;
    b->ob_u = rows_of(3, n, reach, &b->ob_pad, &b->ob_stride); /* u by component */
    if (b->desc->fdot) { /* and v, for the velocity's gradient (the same pad and stride) */
        int pad, stride;
        b->ob_v = rows_of(3, n, reach, &pad, &stride);
    }
}

/* The momentum pass's blocks: stripe by stripe, a block's pairs touch its stripe and the
 * next ncolours - 1 only, as the half lists' do. */
void sph_momentum_blocks_setup(sph_body *b)
{
    if (!blocks_wanted(b, 2) || b->nstripes < 1)
        return;
    const int n = b->nown, ns = b->nstripes;
    const lists L = {b->hb_start, b->hb, b->hb_k, n};
    int degree, reach;
    list_extent(&L, n, &degree, &reach);
    if (reach >= (1 << OBITS))
        return;
    int *stripe = xmalloc(((size_t)ns + 1) * sizeof *stripe), nmb = 0;
    for (int s = 0; s < ns; s++) {
        stripe[s] = nmb;
        nmb += (b->stripe[s + 1] - b->stripe[s] + LANES - 1) / LANES;
    }
    stripe[ns] = nmb;
    int *first = xmalloc(((size_t)nmb + 1) * sizeof *first);
    unsigned char *count = xmalloc((size_t)nmb + 1);
    for (int s = 0; s < ns; s++)
        for (int B = stripe[s]; B < stripe[s + 1]; B++) {
            first[B] = b->stripe[s] + LANES * (B - stripe[s]);
            count[B] = (unsigned char)(b->stripe[s + 1] - first[B] < LANES ? b->stripe[s + 1] - first[B]
                                                                           : LANES);
        }
    b->mb = build_tasks(&L, nmb, first, count, degree, MB_PERMILLE, &b->mb_start, &b->mb_pairs);
    free(count);
    if (!b->mb) {
        free(stripe), free(first);
        return;
    }
    b->nmb = nmb, b->mb_stripe = stripe, b->mb_i0 = first;
    b->mb_soa = rows_of(SPH_MB_ROWS, n, reach, &b->mb_pad, &b->mb_stride);
}
