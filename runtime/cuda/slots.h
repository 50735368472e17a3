/* slots.h — a particle's pairs as the device's passes read them from the full lists
 * (sph_body's fb_*; built by full_lists.h): slot by slot, holes included. */
#ifndef SPHRT_CUDA_SLOTS_H
#define SPHRT_CUDA_SLOTS_H

#include "target.h"
#include "layout_switches.h"
#include "core/defs.h"
#include "scene/body.h"

/* The neighbour a hole (a slot of offset off that particle i lacks) reads, one of the nown own
 * particles: the particle at i + off, or the nearest one to it, so that the warp's load
 * stays as contiguous as at its other lanes (a lane that read i itself would add lines to
 * the load of every slot with a hole: near a surface, every slot pointing out of it).  A
 * hole's table entry is the zero entry ntab, so whatever finite values it reads add
 * nothing.  With SPH_CUDA_RECOMPUTE (layout_switches.h) the pair's gradient comes from
 * X_i - X_j instead, which would not be zero there: i itself. */
SPH_FN int sph_hole(int i, int off, int nown)
{
    if constexpr (SPH_LAYOUT_RECOMPUTE) {
        return i;
    } else {
        const int j = i + off;
        return j < 0 ? 0 : j >= nown ? nown - 1 : j;
    }
}

/* Slot s of particle i's full list: its neighbour (returned) and table entry *k (~k for the
 * reversed pair; ntab, the zero entry, for a hole, sph_hole).  A body whose every pair lies
 * at i + its slot's offset keeps only masks (sph_full_lists): the same branch for every
 * thread of a launch. */
SPH_FN int sph_slot(const sph_body *b, int i, int s, int *k)
{
    if (b->fb_mask) {
        const int in = b->fb_mask[(size_t)(s >> 5) * (size_t)b->n + (size_t)i] >> (s & 31) & 1;
        *k = in ? b->fb_slotk[s] : b->ntab;
        return in ? i + b->fb_off[s] : sph_hole(i, b->fb_off[s], b->nown);
    }
    const size_t p = (size_t)s * (size_t)b->n + (size_t)i;
    *k = b->fb_k[p];
    return b->fb[p];
}

#endif
