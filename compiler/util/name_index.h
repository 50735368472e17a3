/* name_index.h — a hash table from names to indices, for the symbol tables whose linear
 * search made a model with tens of thousands of names take time quadratic in their number. */
#ifndef SPHC_NAME_INDEX_H
#define SPHC_NAME_INDEX_H

typedef struct {
    const char **names; /* slot -> name (not owned), NULL: empty */
    int *values;
    int cap, n;
} NameIndex;

/* Bind name (kept as a pointer: it must outlive the index) to value, replacing a binding of
 * the same name. */
void name_index_put(NameIndex *ix, const char *name, int value);
/* The value bound to name, or -1. */
int name_index_get(const NameIndex *ix, const char *name);
void name_index_free(NameIndex *ix);

#endif
