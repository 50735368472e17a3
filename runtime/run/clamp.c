/* clamp.c — a body clamped on a plane by the mirror images of its particles.
 *
 * A clamp made of particles held still (a velocity condition on the body's part behind the
 * plane) puts a kink into the displacement the pair sums see: zero on one side, growing
 * linearly on the other.  A gradient fitted across the kink misses a fifth of the bending
 * strain next to a clamped face at 5 particles through a thickness, even where it is exact
 * for smooth fields (docs/verification.md).  Here the particles behind the plane are the
 * images of those in front: each moves with minus its particle's displacement and velocity,
 * the odd extension of the field, which is zero on the plane and smooth across it; the images
 * carry no mass, stress or energy (they are not material), and the force the pair sums put
 * on an image acts on its particle with the opposite sign (the image's displacement is minus
 * the particle's: the exact derivative of the particles' energy).  The plane must lie on the
 * faces of the particles' cells, so that every particle behind it has its image. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "clamp.h"
#include "clamp_image.h"
#include "core/alloc.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "pairs/quadratic.h"
#include "scene/body_desc.h"
#include "scene/pass_types.h"

typedef struct {
    uint64_t key;
    int i;
} keyed;

static int by_key(const void *a, const void *b)
{
    const uint64_t x = ((const keyed *)a)->key, y = ((const keyed *)b)->key;
    return (x > y) - (x < y);
}

enum { KEY_BITS = 21 };

static void *zalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (!p) {
        sph_error("out of memory for a clamp's images");
        exit(SPH_EXIT_SETUP);
    }
    return p;
}

/* The lattice key of point x (b->dim compact components) from particle 0's position:
 * 1 with *key set where x is a lattice point (to 1e-6 spacings) within range, else 0. */
static int lattice_key(const sph_body *b, const double *x, uint64_t *key)
{
    const double half = (double)(1 << (KEY_BITS - 1));
    *key = 0;
    for (int c = 0; c < b->dim; c++) {
        const double q = (x[c] - b->X[c]) / b->dx, r = nearbyint(q);
        if (!(fabs(q - r) <= 1e-6) || !(fabs(r) < half))
            return 0;
        *key = *key << KEY_BITS | (uint64_t)(r + half);
    }
    return 1;
}

/* The clamp's point and normal in the body's compact components. */
static void plane(const sph_body *b, double p[3], double n[3])
{
    for (int c = 0; c < b->dim; c++) {
        p[c] = b->desc->clamp_p[sph_axis(b->dim, c)];
        n[c] = b->desc->clamp_n[sph_axis(b->dim, c)];
    }
}

int sph_clamp_setup(sph_body *b)
{
    const int D = b->dim, n = b->nown;
    double p[3], nv[3];
    plane(b, p, nv);
    keyed *all = zalloc((size_t)n + 1, sizeof *all);
    for (int i = 0; i < n; i++) {
        all[i].i = i;
        if (!lattice_key(b, b->X + (size_t)i * D, &all[i].key))
            all[i].key = UINT64_MAX; /* (off the lattice: never an image) */
    }
    qsort(all, (size_t)n, sizeof *all, by_key);
    b->image = zalloc((size_t)n + 1, sizeof *b->image);
    b->image_of = zalloc((size_t)n + 1, sizeof *b->image_of);
    b->nimages = 0;
    for (int i = 0; i < n; i++) {
        const double *x = b->X + (size_t)i * D;
        double s = 0, y[3];
        for (int c = 0; c < D; c++)
            s += (x[c] - p[c]) * nv[c];
        char where[96];
        sph_reference_position(b, i, where, sizeof where);
        if (fabs(s) <= 1e-6 * b->dx) {
            sph_error("%s: body '%s': the clamp's plane passes through the particle at %s; "
                      "place it on the faces of the particles' cells",
                      b->desc->clamp_where, b->desc->name, where);
            free(all);
            return -1;
        }
        if (s > 0)
            continue;
        for (int c = 0; c < D; c++)
            y[c] = x[c] - 2 * s * nv[c];
        keyed k = {0, -1}, *hit = NULL;
        if (lattice_key(b, y, &k.key))
            hit = bsearch(&k, all, (size_t)n, sizeof *all, by_key);
        if (!hit) {
            sph_error("%s: body '%s': the particle at %s, behind the clamp's plane, has no "
                      "mirror image in the body (the plane must lie on the faces of the "
                      "particles' cells, and the body in front of it must reach as far as "
                      "the part behind)", b->desc->clamp_where, b->desc->name, where);
            free(all);
            return -1;
        }
        b->image[b->nimages] = i;
        b->image_of[b->nimages++] = hit->i;
    }
    free(all);
    return 0;
}

void sph_clamp_images(sph_body *b)
{
    for (int k = 0; k < b->nimages; k++)
        sph_clamp_image_move(b, k);
}

void sph_clamp_quiet(sph_body *b)
{
    for (int k = 0; k < b->nimages; k++)
        sph_clamp_image_quiet(b, k);
}

void sph_clamp_reactions(sph_body *b, const double *g)
{
    for (int k = 0; k < b->nimages; k++)
        sph_clamp_image_reaction(b, k, g);
}
