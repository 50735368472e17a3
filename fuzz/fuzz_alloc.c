/* fuzz_alloc.c — the allocator of the compiler's code in the fuzz targets (fuzz_alloc.h): the
 * system's, with every live block in a hash set, so that what one input leaves allocated
 * (the syntax tree, the model, the scanner after a longjmp) is freed before the next.  A
 * block the C library allocated (getline, open_memstream) and the compiler frees is not in
 * the set and goes straight to free(). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void *sphc_fuzz_malloc(size_t size);
void *sphc_fuzz_calloc(size_t n, size_t size);
void *sphc_fuzz_realloc(void *p, size_t size);
void sphc_fuzz_free(void *p);
char *sphc_fuzz_strdup(const char *s);
char *sphc_fuzz_strndup(const char *s, size_t n);
size_t sphc_fuzz_release(void);

/* Open addressing with linear probing; a removed block leaves a tombstone. */
#define TOMB ((void *)1)
static void **slots;
static size_t cap;  /* a power of two, or 0 */
static size_t used; /* live blocks and tombstones */
static size_t live;

static size_t slot_of(const void *p)
{
    uint64_t h = (uint64_t)(uintptr_t)p;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    return (size_t)h & (cap - 1);
}

static void grow(void)
{
    size_t ncap = cap ? cap : 1024;
    while (4 * (live + 1) > ncap)
        ncap *= 2;
    void **old = slots;
    size_t ocap = cap;
    slots = calloc(ncap, sizeof *slots);
    if (!slots)
        abort();
    cap = ncap;
    used = live;
    for (size_t i = 0; i < ocap; i++)
        if (old[i] && old[i] != TOMB) {
            size_t k = slot_of(old[i]);
            while (slots[k])
                k = (k + 1) & (cap - 1);
            slots[k] = old[i];
        }
    free(old);
}

static void add(void *p)
{
    if (!p)
        return;
    if (2 * (used + 1) > cap)
        grow();
    size_t k = slot_of(p);
    while (slots[k] && slots[k] != TOMB)
        k = (k + 1) & (cap - 1);
    if (!slots[k])
        used++;
    slots[k] = p;
    live++;
}

/* Removes p from the set: 1 when it was there. */
static int take(const void *p)
{
    if (!p || !cap)
        return 0;
    for (size_t k = slot_of(p); slots[k]; k = (k + 1) & (cap - 1))
        if (slots[k] == p) {
            slots[k] = TOMB;
            live--;
            return 1;
        }
    return 0;
}

void *sphc_fuzz_malloc(size_t size)
{
    void *p = malloc(size);
    add(p);
    return p;
}

void *sphc_fuzz_calloc(size_t n, size_t size)
{
    void *p = calloc(n, size);
    add(p);
    return p;
}

void *sphc_fuzz_realloc(void *p, size_t size)
{
    if (!p)
        return sphc_fuzz_malloc(size);
    void *q = realloc(p, size);
    if (q || size == 0) { /* p is gone (moved, or freed by realloc(p, 0)) */
        take(p);
        add(q);
    }
    return q;
}

void sphc_fuzz_free(void *p)
{
    take(p);
    free(p);
}

char *sphc_fuzz_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = sphc_fuzz_malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

char *sphc_fuzz_strndup(const char *s, size_t n)
{
    size_t len = strnlen(s, n);
    char *d = sphc_fuzz_malloc(len + 1);
    if (d) {
        memcpy(d, s, len);
        d[len] = 0;
    }
    return d;
}

size_t sphc_fuzz_release(void)
{
    size_t n = live;
    for (size_t i = 0; i < cap; i++)
        if (slots[i] && slots[i] != TOMB)
            free(slots[i]);
    free(slots);
    slots = NULL;
    cap = used = live = 0;
    return n;
}
