/* full_lists.h — a body's full pair lists as the device reads them (sph_body's fb_*, slots.h),
 * built on the host from its half lists: fixed slots on a lattice, slot masks in a box,
 * packed lists elsewhere. */
#ifndef SPHRT_CUDA_FULL_LISTS_H
#define SPHRT_CUDA_FULL_LISTS_H

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "target.h"
#include "layout_switches.h"
#include "slots.h"
#include "scene/body.h"

/* The slots of a lattice's keys (fixed slots, below): slot_of (nkey, zero on entry) holds
 * each key's slot on return, -1 for a key no pair uses; returns the number used.  The keys
 * go in the order of their mean offset j - i over the own particles' pairs, so that a warp's
 * next slot reads the neighbours of the last one shifted by a particle or a row, which the L1
 * cache still holds: on a lattice in slab order the offsets of one plane of the support lie
 * within a few rows, and the slots sweep the planes one by one instead of jumping between
 * j - i and i - j at every table entry (docs/cuda.md).  Keys only pairs with the halo use go
 * last.  With SPH_CUDA_SLOTS_BY_KEY (layout_switches.h) the slots follow the keys.
 * off[key] is the key's offset and *uniform says whether every used key's own pairs have
 * the same one (a box in slab order: j = i + off for every pair). */
static int sph_slot_ranks(const sph_body *h, size_t nkey, int *slot_of, long *off, int *uniform)
{
    double *sum = (double *)calloc(nkey, sizeof(double));
    size_t *cnt = (size_t *)calloc(nkey, sizeof(size_t));
    long *hi = (long *)calloc(nkey, sizeof(long));
    for (size_t i = 0; i < (size_t)h->nown; i++)
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++) {
            const size_t key = 2 * (size_t)h->hb_k[p];
            const long d = (long)h->hb[p] - (long)i;
            if (!cnt[key])
                off[key] = hi[key] = d, off[key + 1] = hi[key + 1] = -d;
            off[key] = std::min(off[key], d), hi[key] = std::max(hi[key], d);
            off[key + 1] = std::min(off[key + 1], -d), hi[key + 1] = std::max(hi[key + 1], -d);
            sum[key] += (double)d, sum[key + 1] -= (double)d, cnt[key]++, cnt[key + 1]++;
        }
    for (size_t i = 0; h->xb_start && i < (size_t)h->nown; i++) /* pairs with the halo */
        for (int p = h->xb_start[i]; p < h->xb_start[i + 1]; p++)
            slot_of[2 * (size_t)h->xb_k[p]] = 1;
    int used = 0;
    size_t *order = (size_t *)malloc((nkey + 1) * sizeof(size_t));
    *uniform = 1;
    for (size_t key = 0; key < nkey; key++)
        if (cnt[key] || slot_of[key]) {
            order[used++] = key;
            *uniform = *uniform && cnt[key] && off[key] == hi[key];
        }
    if constexpr (!SPH_LAYOUT_SLOTS_BY_KEY)
        std::stable_sort(order, order + used, [&](size_t a, size_t b) {
            if (!cnt[a] || !cnt[b])
                return cnt[a] > cnt[b]; /* halo-only keys last */
            return sum[a] / (double)cnt[a] < sum[b] / (double)cnt[b];
        });
    for (size_t key = 0; key < nkey; key++)
        slot_of[key] = -1;
    for (int s = 0; s < used; s++)
        slot_of[order[s]] = s;
    free(sum), free(cnt), free(hi), free(order);
    return used;
}

/* A body's full pair lists as the device reads them (scene/body.h, fb_*; sph_slot). */
struct sph_full {
    int slots, *count, *nb, *k;    /* slot s of particle i: nb[s*n + i], k[s*n + i] */
    unsigned *mask;                /* or, every pair at i + its slot's offset: mask bits */
    int *off, *slotk;              /* and the slots' offsets and table entries */
};

/* The slot masks of a body whose every pair lies at j = i + f->off[its slot] (slot_of from
 * sph_slot_ranks): bit s & 31 of word (s >> 5)*n + i says whether particle i has slot s's
 * neighbour, and count[i] is its last slot + 1 (holes before it included). */
static void sph_slot_masks(const sph_body *h, size_t nkey, const int *slot_of, sph_full *f)
{
    const size_t n = (size_t)h->n, words = ((size_t)f->slots + 31) / 32;
    f->mask = (unsigned *)calloc(words * n + 1, sizeof(unsigned));
    f->slotk = (int *)malloc(((size_t)f->slots + 1) * sizeof(int));
    for (size_t key = 0; key < nkey; key++)
        if (slot_of[key] >= 0)
            f->slotk[slot_of[key]] = key & 1 ? ~(int)(key >> 1) : (int)(key >> 1);
    for (size_t i = 0; i < (size_t)h->nown; i++)
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++) {
            const int s = slot_of[2 * (size_t)h->hb_k[p]], r = slot_of[2 * (size_t)h->hb_k[p] + 1];
            f->mask[(size_t)(s >> 5) * n + i] |= 1u << (s & 31);
            f->mask[(size_t)(r >> 5) * n + (size_t)h->hb[p]] |= 1u << (r & 31);
        }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
        f->count[i] = 0;
        for (size_t w = words; w-- > 0;)
            if (f->mask[w * n + i]) {
                f->count[i] = (int)(w * 32) + 32 - __builtin_clz(f->mask[w * n + i]);
                break;
            }
    }
}

/* Each particle's count of full-list pairs into count (n), their largest into *maxc; returns
 * where each particle's pairs start in a packed array (n + 1 prefix sums).  (On many
 * processes the rows of own particles, each with its pairs with the halo too, h->xb: a halo
 * particle has no list.) */
static size_t *sph_pair_starts(const sph_body *h, int *count, int *maxc)
{
    const size_t n = (size_t)h->n;
    size_t *start = (size_t *)calloc(n + 1, sizeof(size_t));
    for (size_t i = 0; i < (size_t)h->nown; i++) {
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++)
            start[i + 1]++, start[h->hb[p] + 1]++;
        if (h->xb_start)
            start[i + 1] += (size_t)(h->xb_start[i + 1] - h->xb_start[i]);
    }
    *maxc = 0;
    for (size_t i = 0; i < n; i++) {
        count[i] = (int)start[i + 1];
        *maxc = count[i] > *maxc ? count[i] : *maxc;
        start[i + 1] += start[i];
    }
    return start;
}

/* Every pair from both sides, packed as key << 32 | j in each particle's range of start. */
static uint64_t *sph_packed_pairs(const sph_body *h, const size_t *start)
{
    const size_t n = (size_t)h->n;
    uint64_t *packed = (uint64_t *)malloc((start[n] + 1) * sizeof(uint64_t));
    size_t *fill = (size_t *)malloc((n + 1) * sizeof(size_t));
    memcpy(fill, start, n * sizeof(size_t));
    for (size_t i = 0; i < (size_t)h->nown; i++) {
        for (int p = h->hb_start[i]; p < h->hb_start[i + 1]; p++) {
            const uint64_t j = (uint64_t)h->hb[p], key = 2 * (uint64_t)h->hb_k[p];
            packed[fill[i]++] = key << 32 | j;
            packed[fill[j]++] = (key + 1) << 32 | i;
        }
        for (int p = h->xb_start ? h->xb_start[i] : 0; h->xb_start && p < h->xb_start[i + 1]; p++)
            packed[fill[i]++] = (2 * (uint64_t)h->xb_k[p]) << 32 | (uint64_t)h->xb[p];
    }
    free(fill);
    return packed;
}

/* The lists nb and k of f from the packed pairs: with fixed slots (slot_of, and f->off the
 * slots' offsets) each pair in its key's slot, the rest holes; else packed from slot 0. */
static void sph_slot_lists(const sph_body *h, const size_t *start, uint64_t *packed,
                           const int *slot_of, sph_full *f)
{
    const size_t n = (size_t)h->n, slots = (size_t)f->slots;
    int *nb = f->nb = (int *)malloc((slots * n + 1) * sizeof(int));
    int *k = f->k = (int *)malloc((slots * n + 1) * sizeof(int));
#pragma omp parallel for schedule(static)
    for (size_t e = 0; e < slots * n; e++) { /* holes: sph_hole and the zero entry */
        const int i = (int)(e % n);
        nb[e] = slot_of ? sph_hole(i, f->off[e / n], h->nown) : i, k[e] = h->ntab;
    }
#pragma omp parallel for schedule(dynamic, 1024)
    for (size_t i = 0; i < n; i++) {
        std::sort(packed + start[i], packed + start[i + 1]);
        size_t last = 0; /* with fixed slots: the last slot used, holes before it included */
        for (size_t a = 0; a < start[i + 1] - start[i]; a++) {
            const uint64_t w = packed[start[i] + a], key = w >> 32;
            const size_t s = slot_of ? (size_t)slot_of[key] : a;
            nb[s * n + i] = (int)(w & 0xffffffffu);
            k[s * n + i] = key & 1 ? ~(int)(key >> 1) : (int)(key >> 1);
            last = s + 1 > last ? s + 1 : last;
        }
        if (slot_of)
            f->count[i] = (int)last;
    }
}

/* Full pair lists from the half lists (j > i): i gets (j, k), j gets (i, ~k), laid out slot
 * by slot (scene/body.h, fb_*).  A pair is packed as key << 32 | j, key = 2k or 2~k + 1 (every
 * offset its own key), and each particle's pairs are sorted by key.  When the body's pairs
 * use few distinct keys (a lattice: one table entry per offset) every key gets a fixed
 * slot, the same for every particle (sph_slot_ranks), and a particle's missing neighbours
 * are holes: a particle near i + the slot's offset (sph_hole) with the zero table entry
 * ntab, which adds nothing, so the passes need no branch.  A warp at one slot then reads one
 * offset in every thread, including threads whose particles lie near a surface.  Where
 * moreover every pair lies at i + its slot's offset (a box; not on many processes, whose
 * halo particles lie elsewhere) the lists are slot masks instead (sph_slot_masks): 4 bytes a
 * particle for 32 slots instead of 8 a pair, which the passes would otherwise stream from
 * memory at every step.  With SPH_CUDA_LISTS (layout_switches.h) lists always.  Off
 * a lattice the pairs are packed from slot 0. */
static void sph_full_lists(const sph_body *h, sph_full *f)
{
    const size_t n = (size_t)h->n, nkey = 2 * (size_t)h->ntab + 2;
    int maxc, used = 0, uniform = 0;
    f->count = (int *)malloc((n + 1) * sizeof(int));
    f->nb = f->k = NULL, f->mask = NULL, f->off = f->slotk = NULL;
    size_t *start = sph_pair_starts(h, f->count, &maxc);
    /* few keys (one per offset: a lattice): fixed slots, if holes fill at most half of them */
    int *slot_of = nkey <= 4 * (size_t)maxc + 4 ? (int *)calloc(nkey, sizeof(int)) : NULL;
    long *off = slot_of ? (long *)calloc(nkey, sizeof(long)) : NULL;
    if (slot_of)
        used = sph_slot_ranks(h, nkey, slot_of, off, &uniform);
    if (slot_of && used > maxc + maxc / 2)
        free(slot_of), slot_of = NULL;
    f->slots = slot_of ? used : maxc;
    if (slot_of) { /* each slot's offset: the masks' neighbours, the lists' holes */
        f->off = (int *)calloc((size_t)used + 1, sizeof(int));
        for (size_t key = 0; key < nkey; key++)
            if (slot_of[key] >= 0)
                f->off[slot_of[key]] = (int)off[key];
    }
    if constexpr (SPH_LAYOUT_LISTS)
        uniform = 0; /* lists for every body */
    if (slot_of && uniform && !h->xb_start)
        sph_slot_masks(h, nkey, slot_of, f);
    else {
        uint64_t *packed = sph_packed_pairs(h, start);
        sph_slot_lists(h, start, packed, slot_of, f);
        free(packed);
        free(f->off), f->off = NULL; /* (the device reads the lists) */
    }
    free(start), free(slot_of), free(off);
}

#endif
