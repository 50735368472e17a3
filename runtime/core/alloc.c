/* alloc.c — the set-up's large arrays on transparent huge pages.
 *
 * A body of a million particles in 3D has some 170 million pairs; the set-up touches its
 * lists, tables and per-particle arrays page by page as it fills them, and with 4 KiB pages
 * the page faults took a quarter of the set-up's time (the 3D plate at dp 1 mm, one thread:
 * 5.0 s with ordinary pages, 3.6 s on huge pages).  Arrays of 4 MiB and more are therefore
 * aligned on 2 MiB and advised as huge pages; where the kernel does not have them (or not
 * Linux) they are ordinary pages.  The memory is freed with free(). */
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE */
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "alloc.h"
#include "exit_codes.h"
#include "message.h"

void *sph_alloc_large(size_t bytes, int zero)
{
    const size_t huge = (size_t)2 << 20;
    if (bytes < 2 * huge)
        return zero ? calloc(bytes ? bytes : 1, 1) : malloc(bytes ? bytes : 1);
    const size_t size = (bytes + huge - 1) / huge * huge;
    void *p = aligned_alloc(huge, size);
    if (!p)
        return NULL;
#ifdef MADV_HUGEPAGE
    madvise(p, size, MADV_HUGEPAGE); /* advice: ordinary pages where it is not taken */
#endif
    return zero ? memset(p, 0, bytes) : p;
}

void *sph_alloc_setup(size_t bytes, int zero)
{
    void *p = sph_alloc_large(bytes, zero);
    if (!p) {
        sph_error("out of memory (%zu bytes)", bytes);
        exit(SPH_EXIT_SETUP);
    }
    return p;
}
