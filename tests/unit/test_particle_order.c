/* test_particle_order.c — the order of a body's particles in memory
 * (runtime/run/particle_order.c): the shortest extent fastest, except in 3D where the body
 * is a prism along a longer axis only (a cylinder), which is then the fastest; the
 * particles themselves unchanged. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/fill.h"
#include "geom/region.h"
#include "run/particle_order.h"
#include "scene/body.h"
#include "unit_check.h"

enum { X_, Y_, Z_ };

static int by_position(const void *pa, const void *pb)
{
    const double *a = pa, *b = pb;
    for (int k = 0; k < 3; k++)
        if (a[k] != b[k])
            return a[k] < b[k] ? -1 : 1;
    return 0;
}

/* Fills the shapes at spacing dx, orders them, and checks that the first two particles
 * differ along `fast` alone (by dx) and the particles are the ones filled. */
static void order_of(const char *name, const sph_shape *prims, int np, double dx, int fast)
{
    sph_region r = {.prims = prims, .n = np};
    sph_body b;
    memset(&b, 0, sizeof b);
    b.dim = 3;
    b.n = b.nown = sph_fill_region(&r, 3, dx, 0.0, &b.X);
    const size_t bytes = (size_t)b.n * 3 * sizeof(double);
    double *before = malloc(bytes), *after = malloc(bytes);
    memcpy(before, b.X, bytes);
    sph_order_particles(&b);
    memcpy(after, b.X, bytes);
    double step[3], off = 0;
    for (int k = 0; k < 3; k++) {
        step[k] = b.X[3 + k] - b.X[k];
        off += k == fast ? fabs(step[k] - dx) : fabs(step[k]);
    }
    char what[120];
    snprintf(what, sizeof what, "%s (%d particles): axis %c fastest", name, b.n, "xyz"[fast]);
    check(b.n > 2 && off < 1e-9 * dx, what, off, 1e-9 * dx);
    qsort(before, (size_t)b.n, 3 * sizeof(double), by_position);
    qsort(after, (size_t)b.n, 3 * sizeof(double), by_position);
    snprintf(what, sizeof what, "%s: the same particles", name);
    const int same = memcmp(before, after, bytes) == 0;
    check(same, what, same, 1);
    free(before), free(after), free(b.X);
}

int main(void)
{
    /* a prism along the shortest extent, or none: the shortest fastest */
    const sph_shape box = {SPH_BOX, {0, 0, 0}, {2, 1, 0.5}, 0, 0, NULL, NULL, 0};
    order_of("box 2 x 1 x 0.5", &box, 1, 0.1, Z_);
    const sph_shape flat = {SPH_BOX, {0, 0, 0}, {0.4, 1, 2}, 0, 0, NULL, NULL, 0};
    order_of("box 0.4 x 1 x 2", &flat, 1, 0.1, X_);
    const sph_shape ball = {SPH_SPHERE, {0, 0, 0}, {0, 0, 0}, 1, 0, NULL, NULL, 0};
    order_of("sphere", &ball, 1, 0.1, Z_);
    const sph_shape disc = {SPH_CYLINDER, {0, 0, 0}, {0, 0.3, 0}, 1, 0, NULL, NULL, 0};
    order_of("cylinder shorter than wide, along y", &disc, 1, 0.1, Y_);
    /* a prism along a longer axis only: that axis fastest */
    const sph_shape bar = {SPH_CYLINDER, {0, 0, 0}, {0, 0, 4}, 0.6, 0, NULL, NULL, 0};
    order_of("cylinder along z", &bar, 1, 0.1, Z_);
    const sph_shape rod = {SPH_CYLINDER, {0, 0, 0}, {3, 0, 0}, 0.5, 0, NULL, NULL, 0};
    order_of("cylinder along x", &rod, 1, 0.1, X_);
    const sph_shape step[2] = {{SPH_BOX, {0, 0, 0}, {2, 1, 0.6}, 0, 0, NULL, NULL, 0},
                               {SPH_BOX, {1, -1, 0.3}, {3, 2, 1}, 0, 1, NULL, NULL, 0}};
    order_of("step (a box less a corner) along y", step, 2, 0.1, Y_);
    const sph_shape notched[2] = {{SPH_BOX, {0, 0, 0}, {2, 1, 0.6}, 0, 0, NULL, NULL, 0},
                                  {SPH_BOX, {0.9, 0.45, 0.3}, {1.1, 0.55, 1}, 0, 1, NULL, NULL,
                                   0}};
    order_of("box with a pocket (no prism)", notched, 2, 0.1, Z_);
    return failures != 0;
}
