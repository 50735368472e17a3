/* alloc.h — the set-up's large arrays (alloc.c). */
#ifndef SPHRT_CORE_ALLOC_H
#define SPHRT_CORE_ALLOC_H

#include <stddef.h>

/* Bytes for a large array of the set-up (on huge pages from 4 MiB; zeroed when zero is set),
 * freed with free(); NULL when memory runs out. */
void *sph_alloc_large(size_t bytes, int zero);

#endif
