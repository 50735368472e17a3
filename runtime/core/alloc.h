/* alloc.h — the set-up's large arrays (alloc.c). */
#ifndef SPHRT_CORE_ALLOC_H
#define SPHRT_CORE_ALLOC_H

#include <stddef.h>

/* Bytes for a large array of the set-up (on huge pages from 4 MiB; zeroed when zero is set),
 * freed with free(); NULL when memory runs out. */
void *sph_alloc_large(size_t bytes, int zero);
/* The same for the set-up, which cannot go on without it: where memory runs out, an error
 * and the exit code of a failed set-up (core/exit_codes.h). */
void *sph_alloc_setup(size_t bytes, int zero);

#endif
