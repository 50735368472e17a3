/* id_index.c — finding particles by global id (partition.h): a process's own particles
 * sorted by id, for the halo plan and for checkpoints read on another number of processes. */
#include <stdlib.h>

#include "partition.h"

static int by_id(const void *a, const void *b)
{
    const int64_t x = ((const sph_id_index *)a)->id, y = ((const sph_id_index *)b)->id;
    return x < y ? -1 : x > y;
}

sph_id_index *sph_id_sort(const int64_t *id, int n)
{
    sph_id_index *s = malloc(((size_t)n + 1) * sizeof *s);
    if (!s)
        return NULL;
    for (int i = 0; i < n; i++)
        s[i] = (sph_id_index){id[i], i};
    qsort(s, (size_t)n, sizeof *s, by_id);
    return s;
}

int sph_id_find(const sph_id_index *s, int n, int64_t id)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        const int mid = lo + (hi - lo) / 2;
        if (s[mid].id == id)
            return s[mid].index;
        if (s[mid].id < id)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}
