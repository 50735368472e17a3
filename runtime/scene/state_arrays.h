/* state_arrays.h — the arrays of a body that its passes carry from one step to the next. */
#ifndef SPHRT_SCENE_STATE_ARRAYS_H
#define SPHRT_SCENE_STATE_ARRAYS_H

#include <stddef.h>

#include "body.h"
#include "core/defs.h"

SPH_C_BEGIN

/* The arrays of body b that its passes carry from one step to the next: what a checkpoint
 * saves (io/checkpoint.c) and a device target copies both ways for it (cuda/transfer.h), in
 * this order, those the body has.  nstate: the law's state values per particle (b->desc->nstate;
 * a device view has no desc).  The rest (Q, Cv, A, sigma) every step or output makes anew. */
#define SPH_STATE_ARRAYS 15
typedef struct {
    const char *name;
    void *data;
    size_t bytes;
} sph_state_array;
static inline int sph_body_state_arrays(sph_body *b, int nstate, sph_state_array *out)
{
    const size_t n = (size_t)b->n, n1 = n * sizeof(double), nd = n1 * (size_t)b->dim;
    const sph_state_array all[SPH_STATE_ARRAYS] = {
        {"u", b->u, nd},       {"v", b->v, nd},        {"a", b->a, nd},
        {"work", b->work, nd}, {"F", b->F, 9 * n1},    {"psi", b->psi, n1},
        {"fix", b->fix, n},    {"lam2", b->lam2, n1},  {"state", b->state, n1 * (size_t)nstate},
        {"s", b->s, n1},       {"sd", b->sd, n1},      {"sdd", b->sdd, n1},
        {"H", b->H, n1},       {"lap", b->lap, n1},    {"sd_n", b->sd_n, n1}};
    int k = 0;
    for (int i = 0; i < SPH_STATE_ARRAYS; i++)
        if (all[i].data && all[i].bytes)
            out[k++] = all[i];
    return k;
}

SPH_C_END

#endif
