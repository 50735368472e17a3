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

/* A shape of one or two primitives (the second subtracted) and its expected fastest axis. */
typedef struct {
    const char *name;
    sph_shape prims[2];
    int nprims, fast;
} shape_case;

#define BOX(x0, y0, z0, x1, y1, z1, sub)                                                     \
    {SPH_BOX, {x0, y0, z0}, {x1, y1, z1}, 0, sub, NULL, NULL, 0}
#define CYL(x1, y1, z1, r) {SPH_CYLINDER, {0, 0, 0}, {x1, y1, z1}, r, 0, NULL, NULL, 0}

static const shape_case cases[] = {
    /* a prism along the shortest extent, or none: the shortest fastest */
    {"box 2 x 1 x 0.5", {BOX(0, 0, 0, 2, 1, 0.5, 0)}, 1, Z_},
    {"box 0.4 x 1 x 2", {BOX(0, 0, 0, 0.4, 1, 2, 0)}, 1, X_},
    {"sphere", {{SPH_SPHERE, {0, 0, 0}, {0, 0, 0}, 1, 0, NULL, NULL, 0}}, 1, Z_},
    {"cylinder shorter than wide, along y", {CYL(0, 0.3, 0, 1)}, 1, Y_},
    {"box with a pocket (no prism)",
     {BOX(0, 0, 0, 2, 1, 0.6, 0), BOX(0.9, 0.45, 0.3, 1.1, 0.55, 1, 1)}, 2, Z_},
    /* a prism along a longer axis only: that axis fastest */
    {"cylinder along z", {CYL(0, 0, 4, 0.6)}, 1, Z_},
    {"cylinder along x", {CYL(3, 0, 0, 0.5)}, 1, X_},
    {"step (a box less a corner) along y",
     {BOX(0, 0, 0, 2, 1, 0.6, 0), BOX(1, -1, 0.3, 3, 2, 1, 1)}, 2, Y_},
};

int main(void)
{
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        order_of(cases[c].name, cases[c].prims, cases[c].nprims, 0.1, cases[c].fast);
    return failures != 0;
}
