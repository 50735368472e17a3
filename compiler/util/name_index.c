/* name_index.c — open addressing with linear probing, grown to keep it at most half full. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "name_index.h"

static uint32_t hash(const char *s)
{
    uint32_t h = 2166136261u; /* FNV-1a */
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

/* The slot of name, or the empty slot where it would go. */
static int slot_of(const NameIndex *ix, const char *name)
{
    int k = (int)(hash(name) & (uint32_t)(ix->cap - 1));
    while (ix->names[k] && strcmp(ix->names[k], name))
        k = (k + 1) & (ix->cap - 1);
    return k;
}

static void grow(NameIndex *ix)
{
    NameIndex big = {0};
    big.cap = ix->cap ? 2 * ix->cap : 64;
    big.names = calloc((size_t)big.cap, sizeof *big.names);
    big.values = malloc((size_t)big.cap * sizeof *big.values);
    for (int k = 0; k < ix->cap; k++)
        if (ix->names[k])
            name_index_put(&big, ix->names[k], ix->values[k]);
    name_index_free(ix);
    *ix = big;
}

void name_index_put(NameIndex *ix, const char *name, int value)
{
    if (2 * (ix->n + 1) > ix->cap)
        grow(ix);
    int k = slot_of(ix, name);
    if (!ix->names[k]) {
        ix->names[k] = name;
        ix->n++;
    }
    ix->values[k] = value;
}

int name_index_get(const NameIndex *ix, const char *name)
{
    if (!ix->cap)
        return -1;
    int k = slot_of(ix, name);
    return ix->names[k] ? ix->values[k] : -1;
}

void name_index_free(NameIndex *ix)
{
    free(ix->names);
    free(ix->values);
    memset(ix, 0, sizeof *ix);
}
