/* cuda_cache_model.cpp — what the CUDA target's pair passes ask of a GPU's L1 cache, worked
 * out on the CPU from a model's real pair lists: a trace of the loads of the momentum and
 * stress passes (templates/body_cuda.cu) of the model's first body, 2D or 3D, through a
 * model of one multiprocessor's L1.
 *
 *   cuda_cache_model [--l1 KB] [--resident B] [--block T] [--groups G]
 *
 * Built by bench/cuda-cache (g++, the CUDA target's model.cu emulated on the host, which this
 * file includes): the set-up and the device's full lists (sph_full_lists,
 * runtime/cuda/full_lists.h) are the program's own.  It answers how the order of the fixed slots changes the traffic
 * between L1 and L2 before a GPU times it: each layout of the same pairs is traced.
 *   offset  the fixed slots in the order of their offsets j - i (sph_slot_ranks), as lists;
 *   key     the fixed slots in the order of the table's keys (+o, -o of each entry in turn),
 *           holes at i itself: the layout timed at 3.94 ns/particle-step (built with
 *           -DSPH_CUDA_SLOTS_BY_KEY, but for its holes, sph_hole);
 *   packed  each particle's pairs from slot 0 in key order (timed at 4.49; Nsight Compute
 *           measured an L1 hit rate of 57 % for the momentum pass with it: the calibration);
 *   masks   the offsets' order read through slot masks instead of lists (sph_slot_masks: a
 *           box, whose every pair lies at i + its slot's offset; the lists are the layout
 *           built with -DSPH_CUDA_LISTS);
 *   soa     the masks with the neighbours' u and v read by component (stride n: `us`, `vs`,
 *           sph_cuda_components) instead of particle by particle (the layout built with
 *           -DSPH_CUDA_AOS): the default for a box.
 *
 * The model: blocks of T threads (default 256) of consecutive particles, B of them resident
 * on one multiprocessor (default 2: 128 registers a thread), B blocks far apart in the body
 * (the hardware hands out blocks in turn to 132 multiprocessors).  Their warps run in
 * lockstep, slot by slot; at each slot every warp loads its neighbours' values (the momentum
 * pass with viscosity: Q and cof(F) L entry by entry, D*D + D*D arrays, v, Cs; the stress
 * pass: u), its slot's neighbour index and table entry, and the table entry's row.  A warp's
 * load touches the 32-byte sectors its 32 lanes address; the cache holds 128-byte lines of
 * four sectors, 16 ways a set, least recently used out first, KB kilobytes (default 200).
 * A sector found is a hit, a sector missing comes from L2.  G groups of B blocks (default 48)
 * spread over the body are traced, each from a cold cache, and their counts added.  Printed
 * per layout and pass: the L1 hit rate of sectors, the bytes from L2 per pair, those bytes
 * for the whole pass per step, and the distinct 128-byte lines a warp's loads touch per pair
 * (what the L1 itself must serve, a line a clock at best: 2 or 3 for a load of 32
 * consecutive doubles, 6 or 7 for one component of 32 consecutive particles' u, a warp's
 * lines counted once for its 32 pairs); last, per pass, the offsets' layout's bytes from L2
 * over the keys' (and the masks' over the offsets' lists, and the default's L1 lines over the
 * keys').  A hole (a missing neighbour: the
 * particle itself) is loaded like a pair but not counted as one. */
#define main generated_main
#include "model.cu"
#undef main

#include <cstdint>
#include <vector>

enum { LINE = 128, SECTOR = 32, WAYS = 16, WARP = 32 };

struct l1_cache {
    size_t sets = 0;
    uint64_t clock = 0;
    std::vector<uint64_t> tag, used; /* per way: line address + 1 (0: empty), last use */
    std::vector<uint8_t> valid;      /* per way: the sectors present, a bit each */
    uint64_t hits = 0, misses = 0, lines = 0; /* lines: a warp's load's distinct lines */
    explicit l1_cache(size_t bytes)
        : sets(bytes / LINE / WAYS), tag(sets * WAYS), used(sets * WAYS), valid(sets * WAYS) {}
    void sector(uint64_t addr)
    {
        const uint64_t line = addr / LINE, bit = 1u << (addr % LINE / SECTOR);
        const size_t set = (size_t)((line * 0x9E3779B97F4A7C15ull) >> 40) % sets, w0 = set * WAYS;
        size_t victim = w0;
        clock++;
        for (size_t w = w0; w < w0 + WAYS; w++) {
            if (tag[w] == line + 1) {
                used[w] = clock;
                (valid[w] & bit ? hits : misses)++;
                valid[w] |= (uint8_t)bit;
                return;
            }
            if (used[w] < used[victim])
                victim = w;
        }
        misses++;
        tag[victim] = line + 1, used[victim] = clock, valid[victim] = (uint8_t)bit;
    }
};

/* One warp's load: the distinct sectors of its lanes' addresses. */
static void warp_load(l1_cache &c, const uint64_t *addr, int lanes)
{
    uint64_t s[WARP];
    int m = 0;
    for (int l = 0; l < lanes; l++)
        s[m++] = addr[l] / SECTOR * SECTOR;
    std::sort(s, s + m);
    for (int l = 0; l < m; l++)
        if (l == 0 || s[l] != s[l - 1]) {
            c.sector(s[l]);
            c.lines += l == 0 || s[l] / LINE != s[l - 1] / LINE;
        }
}

/* The pair lists of one layout: entry s * n + i of nb and kk, count[i] slots per particle. */
struct layout {
    const char *name;
    std::vector<int> nb, kk, count;
    int slots = 0;
    bool masks = false; /* read as slot masks (sph_slot) instead of lists */
    bool soa = false;   /* u and v by component (stride n) instead of particle by particle */
    int dim = 3;        /* the body's: D values of u and v, D * D of Q and Cv a particle */
};

/* Array a of the trace lives at its own address range. */
static uint64_t at(int a, size_t index, size_t bytes)
{
    return ((uint64_t)a << 40) + index * bytes;
}

/* One pass over G groups: mom = 1 the momentum pass's loads, 0 the stress pass's. */
static void trace(const layout &L, size_t n, int ntab, int mom, size_t l1, int resident,
                  int block, int groups, double *hit, double *bytes_per_pair,
                  double *lines_per_pair)
{
    uint64_t hits = 0, misses = 0, lines = 0, pairs = 0;
    const int D = L.dim;
    const size_t nblocks = (n + block - 1) / block;
    for (int g = 0; g < groups; g++) {
        l1_cache c(l1);
        std::vector<size_t> first(resident);
        for (int r = 0; r < resident; r++) /* B blocks 132 apart, the group's place spread */
            first[r] = ((size_t)g * nblocks / groups + (size_t)r * 132) % nblocks * block;
        int most = 0;
        for (int r = 0; r < resident; r++)
            for (size_t i = first[r]; i < std::min(n, first[r] + block); i++)
                most = std::max(most, L.count[i]);
        for (int s = 0; s < most; s++)
            for (int r = 0; r < resident; r++)
                for (size_t w0 = first[r]; w0 < std::min(n, first[r] + block); w0 += WARP) {
                    uint64_t a[WARP];
                    size_t ids[WARP];
                    int lanes = 0;
                    for (size_t i = w0; i < std::min(n, w0 + WARP); i++)
                        if (s < L.count[i])
                            ids[lanes++] = i;
                    if (!lanes)
                        continue;
                    for (int l = 0; l < lanes; l++) /* holes are loaded, not counted */
                        pairs += L.kk[(size_t)s * n + ids[l]] != ntab;
                    auto load = [&](int array, auto index, size_t bytes) {
                        for (int l = 0; l < lanes; l++)
                            a[l] = at(array, index(ids[l]), bytes);
                        warp_load(c, a, lanes);
                    };
                    const size_t base = (size_t)s * n;
                    if (L.masks) { /* the slot's mask word, offset and entry */
                        load(10, [&](size_t i) { return (size_t)(s >> 5) * n + i; }, 4);
                        load(11, [&](size_t) { return (size_t)s; }, 4);
                        load(12, [&](size_t) { return (size_t)s; }, 4);
                    } else {
                        load(1, [&](size_t i) { return base + i; }, 4); /* fb */
                        load(2, [&](size_t i) { return base + i; }, 4); /* fb_k */
                    }
                    auto entry = [&](size_t i) {
                        const int k = L.kk[base + i];
                        return (size_t)(k < 0 ? ~k : k);
                    };
                    load(3, [&](size_t i) { return entry(i) * SPH_ROW(D); }, sizeof(sph_real));
                    load(4, entry, sizeof(sph_real)); /* gtab */
                    auto j = [&](size_t i) { return (size_t)L.nb[base + i]; };
                    if (!mom) {
                        for (int r = 0; r < D; r++) /* u */
                            load(5, [&](size_t i) { return L.soa ? r * n + j(i) : j(i) * D + r; },
                                 8);
                        continue;
                    }
                    for (int e = 0; e < D * D; e++) { /* Q and Cv entry by entry (SPH_TENSOR) */
                        load(6, [&](size_t i) { return e * n + j(i); }, sizeof(sph_real));
                        load(7, [&](size_t i) { return e * n + j(i); }, sizeof(sph_real));
                    }
                    for (int r = 0; r < D; r++) /* v */
                        load(8, [&](size_t i) { return L.soa ? r * n + j(i) : j(i) * D + r; }, 8);
                    load(9, j, sizeof(sph_real)); /* Cs */
                }
        hits += c.hits, misses += c.misses, lines += c.lines;
    }
    *hit = (double)hits / (double)(hits + misses);
    *bytes_per_pair = (double)(misses * SECTOR) / (double)pairs;
    *lines_per_pair = (double)lines / (double)pairs;
}

/* The key of a slot's pairs (2k forward, 2~k + 1 reversed; holes have none). */
static long slot_key(int k) { return k >= 0 ? 2L * k : 2L * ~k + 1; }

int main(int argc, char **argv)
{
    size_t l1 = 200 << 10;
    int resident = 2, block = 256, groups = 48;
    for (int a = 1; a + 1 < argc; a += 2) {
        const long v = atol(argv[a + 1]);
        if (!strcmp(argv[a], "--l1"))
            l1 = (size_t)v << 10;
        else if (!strcmp(argv[a], "--resident"))
            resident = (int)v;
        else if (!strcmp(argv[a], "--block"))
            block = (int)v;
        else if (!strcmp(argv[a], "--groups"))
            groups = (int)v;
        else {
            fprintf(stderr, "cuda_cache_model: unknown option %s\n", argv[a]);
            return 2;
        }
    }
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    const sph_body *h = &sim.bodies[0];
    const size_t n = (size_t)h->n;
    sph_full f;
    sph_full_lists(h, &f);
    if (f.mask) { /* the masks as lists, which the layouts below rearrange */
        f.nb = (int *)malloc((size_t)f.slots * n * sizeof(int));
        f.k = (int *)malloc((size_t)f.slots * n * sizeof(int));
        sph_body v = *h;
        v.fb_mask = f.mask, v.fb_off = f.off, v.fb_slotk = f.slotk;
        for (int s = 0; s < f.slots; s++)
            for (size_t i = 0; i < n; i++)
                f.nb[(size_t)s * n + i] = sph_slot(&v, (int)i, s, &f.k[(size_t)s * n + i]);
    }
    int *count = f.count, *nb = f.nb, *k = f.k, slots = f.slots;
    layout off{"offset"}, key{"key"}, packed{"packed"}, masks{"masks"};
    off.nb.assign(nb, nb + (size_t)slots * n), off.kk.assign(k, k + (size_t)slots * n);
    off.count.assign(count, count + n), off.slots = slots, off.dim = h->dim;
    /* the same slots in key order: each slot's key from any pair it holds */
    std::vector<long> skey(slots, -1);
    for (int s = 0; s < slots; s++)
        for (size_t i = 0; i < n && skey[s] < 0; i++)
            if (k[(size_t)s * n + i] != h->ntab)
                skey[s] = slot_key(k[(size_t)s * n + i]);
    std::vector<int> order(slots), rank(slots);
    for (int s = 0; s < slots; s++)
        order[s] = s;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return skey[a] < skey[b]; });
    for (int s = 0; s < slots; s++)
        rank[order[s]] = s;
    key = off, key.name = "key", packed = off, packed.name = "packed";
    for (size_t i = 0; i < n; i++) {
        int last = 0, fill = 0;
        for (int r = 0; r < slots; r++) { /* r: rank in key order */
            const size_t from = (size_t)order[r] * n + i, to = (size_t)r * n + i;
            key.nb[to] = k[from] == h->ntab ? (int)i : nb[from], key.kk[to] = k[from];
            if (k[from] != h->ntab) {
                last = r + 1;
                packed.nb[(size_t)fill * n + i] = nb[from];
                packed.kk[(size_t)fill * n + i] = k[from];
                fill++;
            }
        }
        key.count[i] = last, packed.count[i] = fill;
        for (int r = fill; r < slots; r++)
            packed.nb[(size_t)r * n + i] = (int)i, packed.kk[(size_t)r * n + i] = h->ntab;
    }
    double pairs = 0;
    for (size_t i = 0; i < n; i++)
        pairs += packed.count[i];
    printf("%zu particles, %d slots, %.1f pairs a particle; L1 %zu KB, %d blocks of %d resident, "
           "%d groups\n", n, slots, pairs / (double)n, l1 >> 10, resident, block, groups);
    printf("%-8s %-9s %9s %14s %16s %16s\n", "layout", "pass", "L1 hits", "L2 B/pair",
           "L2 GB/step", "L1 lines/pair");
    masks = off, masks.name = "masks", masks.masks = true;
    layout soa = masks;
    soa.name = "soa", soa.soa = true;
    double bytes[5][2], lines[5][2];
    const layout *all[5] = {&packed, &key, &off, &masks, &soa};
    for (int l = 0; l < (f.mask ? 5 : 3); l++)
        for (int mom = 1; mom >= 0; mom--) {
            double hit;
            trace(*all[l], n, h->ntab, mom, l1, resident, block, groups, &hit, &bytes[l][mom],
                  &lines[l][mom]);
            printf("%-8s %-9s %8.1f%% %14.1f %16.2f %16.1f\n", all[l]->name,
                   mom ? "momentum" : "stress", 100 * hit, bytes[l][mom],
                   bytes[l][mom] * pairs / 1e9, lines[l][mom]);
        }
    for (int mom = 1; mom >= 0; mom--) {
        printf("%s: bytes from L2, offset / key %.3f", mom ? "momentum" : "stress",
               bytes[2][mom] / bytes[1][mom]);
        if (f.mask)
            printf(", masks / offset %.3f; L1 lines, soa / key %.3f", bytes[3][mom] / bytes[2][mom],
                   lines[4][mom] / lines[1][mom]);
        printf("\n");
    }
    free(f.count), free(f.nb), free(f.k), free(f.mask), free(f.off), free(f.slotk);
    sph_sim_free(&sim);
    return 0;
}
