/* contact_partners.c — contact between bodies on many processes (docs/mpi.md): the particles
 * of other processes that may touch this process's, for its contact pass (contact.c, and the
 * CUDA target's sph_cuda_contact.h).  Each process sends every other one its particles within
 * `reach` (the search's cell: the largest contact distance plus the skin) of the box of that
 * process's particles of another body, with their bodies and velocities. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "par/par.h"

static void *alloc_or_exit(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) {
        sph_error("out of memory for contact between processes");
        exit(SPH_EXIT_SETUP);
    }
    return p;
}

/* The boxes of this process's particles of each body (lo[3] then hi[3] a body; an empty
 * body's lo above its hi). */
static void boxes_of(int D, int nbodies, int n, const int *body, const double *x, double *box)
{
    for (int i = 0; i < nbodies; i++)
        for (int k = 0; k < 3; k++)
            box[6 * i + k] = k < D ? INFINITY : 0, box[6 * i + 3 + k] = k < D ? -INFINITY : 0;
    for (int p = 0; p < n; p++)
        for (int k = 0; k < D; k++) {
            double *b = box + 6 * body[p];
            b[k] = fmin(b[k], x[(size_t)p * D + k]), b[3 + k] = fmax(b[3 + k], x[(size_t)p * D + k]);
        }
}

/* Whether position x (of body `own`) is within reach of process q's box of another body. */
static int near_other(const double *boxes, int nbodies, int D, int own, const double *x,
                      double reach)
{
    for (int j = 0; j < nbodies; j++) {
        const double *b = boxes + 6 * j;
        double d2 = 0;
        for (int k = 0; k < D; k++) {
            const double d = fmax(fmax(b[k] - x[k], x[k] - b[3 + k]), 0.0);
            d2 += d * d;
        }
        if (j != own && b[0] <= b[3] && d2 <= reach * reach)
            return 1;
    }
    return 0;
}

int sph_contact_partners(const sph_par *par, int D, int nbodies, int n, const int *body,
                         const double *x, const double *v, double reach, double **partners)
{
    const int np = par->size, rec = 1 + 2 * D;
    double *box = alloc_or_exit(6 * (size_t)nbodies * sizeof *box);
    double *boxes = alloc_or_exit(6 * (size_t)nbodies * (size_t)np * sizeof *boxes);
    double **out = alloc_or_exit((size_t)np * sizeof *out);
    size_t *bytes = alloc_or_exit(2 * (size_t)np * sizeof *bytes), *got = bytes + np;
    boxes_of(D, nbodies, n, body, x, box);
    par->allgather(box, boxes, (int)(6 * (size_t)nbodies * sizeof *box));
    for (int q = 0; q < np; q++) {
        out[q] = alloc_or_exit(((size_t)n * rec + 1) * sizeof **out);
        int count = 0;
        for (int p = 0; q != par->rank && p < n; p++) {
            const double *xp = x + (size_t)p * D;
            if (!near_other(boxes + 6 * (size_t)q * nbodies, nbodies, D, body[p], xp, reach))
                continue;
            double *r = out[q] + (size_t)count++ * rec;
            r[0] = body[p];
            memcpy(r + 1, xp, (size_t)D * sizeof *xp);
            memcpy(r + 1 + D, v + (size_t)p * D, (size_t)D * sizeof *xp);
        }
        bytes[q] = (size_t)count * rec * sizeof **out;
    }
    void *in;
    par->swap((const void *const *)out, bytes, &in, got);
    size_t total = 0;
    for (int q = 0; q < np; q++)
        total += got[q] / (rec * sizeof(double)), free(out[q]);
    free(box), free(boxes), free(out), free(bytes);
    *partners = in;
    return (int)total;
}
