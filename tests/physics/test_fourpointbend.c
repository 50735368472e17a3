/* Four-point bending with the 90 degree slit at test-suite resolution
 * (fourpointbend_coarse.sph): an 80 x 10 x 20 mm beam, dx = 2 mm, notched at x = 40 mm from
 * the bottom to z = 5.6 mm, bent by supports below at x = 4 and 76 mm and loading points
 * above at x = 20 and 60 mm.  Between the loading points the bending moment is constant and
 * the scene is mirror-symmetric about x = 40 mm, so the crack is mode I and planar:
 *  - the notch cuts the beam at set-up: no pair of the half lists crosses x = 40 mm below
 *    z = 5.6 mm, while pairs across the plane above the notch are kept;
 *  - the crack starts above the notch, in the two columns beside the plane (x = 39, 41 mm);
 *  - at 80 us every damaged particle (s < 0.5) lies in those columns, nothing at the loading
 *    points (their phase field is restricted) or elsewhere;
 *  - the crack has run up from the notch, past mid-height (z > 10 mm);
 *  - the two halves mirror each other: s and the vertical displacement of every particle
 *    equal those of its mirror image to 1e-6 (of s; of the largest |u_z|).  Only the order of
 *    the floating-point sums differs between the halves;
 *  - the history field never decreases, s stays in [0, 1], and the fracture energy is at
 *    least Gc times the crack's area, W (z_top - 5.6 mm) (at this spacing, with eps0 an
 *    eighth of dx, the discrete crack energy is about four times that; test_crack1d checks
 *    the energy per area where the phase field is resolved). */
#define main generated_main
#include "fourpointbend_coarse.c"
#undef main

#include <stdlib.h>

#include "check.h"

enum { D = 3, NX = 40, NY = 5, NZ = 10 };
#define DX 2e-3
#define XN 40e-3    /* the notch plane */
#define ZN 5.6e-3   /* the notch's top */
#define WIDTH 10e-3
#define GC 11.8e3

/* Pairs crossing x = 40 mm below and above the notch's top. */
static void pairs_across(const sph_body *b, long *below, long *above)
{
    *below = *above = 0;
    for (int i = 0; i < b->n; i++)
        for (int p = b->hb_start[i]; p < b->hb_start[i + 1]; p++) {
            const double *Xi = b->X + (size_t)i * D, *Xj = b->X + (size_t)b->hb[p] * D;
            const double di = Xi[0] - XN, dj = Xj[0] - XN;
            if (di * dj >= 0)
                continue;
            const double z = Xi[2] + (Xj[2] - Xi[2]) * di / (di - dj);
            *(z < ZN ? below : above) += 1;
        }
}

/* mirror[i]: the particle at (80 mm - x, y, z), from the lattice cell of each particle. */
static int *mirror_map(const sph_body *b)
{
    int *cell = malloc(sizeof(int) * NX * NY * NZ), *mirror = malloc(sizeof(int) * (size_t)b->n);
    for (int c = 0; c < NX * NY * NZ; c++)
        cell[c] = -1;
    for (int i = 0; i < b->n; i++) {
        const double *X = b->X + (size_t)i * D;
        const int ix = (int)(X[0] / DX), iy = (int)(X[1] / DX), iz = (int)(X[2] / DX);
        cell[(iz * NY + iy) * NX + ix] = i;
    }
    for (int i = 0; i < b->n; i++) {
        const double *X = b->X + (size_t)i * D;
        const int ix = (int)(X[0] / DX), iy = (int)(X[1] / DX), iz = (int)(X[2] / DX);
        mirror[i] = cell[(iz * NY + iy) * NX + (NX - 1 - ix)];
    }
    free(cell);
    return mirror;
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    check_close("particles", b->n, NX * NY * NZ, 0);
    if (b->n != NX * NY * NZ)
        return check_result();
    long below, above;
    pairs_across(b, &below, &above);
    check_close("pairs across x = 40 mm below the notch's top", below, 0, 0);
    check_close("pairs across x = 40 mm above it > 0", above > 0, 1, 0);
    int *mirror = mirror_map(b);
    const check_fracture_run w = check_run_fracture(&sim, b);
    const double t_init = w.t_init;
    const double x_init = w.i_init < 0 ? NAN : b->X[w.i_init * D];
    const double z_init = w.i_init < 0 ? NAN : b->X[w.i_init * D + 2];
    int ndamaged = 0, outside = 0;
    double ztop = ZN, ds = 0, duz = 0, uzmax = 0;
    for (int i = 0; i < b->n; i++) {
        const double *X = b->X + (size_t)i * D;
        ds = fmax(ds, fabs(b->s[i] - b->s[mirror[i]]));
        duz = fmax(duz, fabs(b->u[i * D + 2] - b->u[mirror[i] * D + 2]));
        uzmax = fmax(uzmax, fabs(b->u[i * D + 2]));
        if (b->s[i] >= 0.5)
            continue;
        ndamaged++;
        if (fabs(X[0] - XN) > 0.5 * DX + 1e-9)
            outside++;
        else
            ztop = fmax(ztop, X[2]);
    }
    const double ef = sph_fracture_energy(b), area = WIDTH * (ztop - ZN);
    printf("%ld steps to %.3g us: first damage at %.4g us at x = %.4g mm, z = %.4g mm; %d damaged "
           "particles, the highest at z = %.4g mm; fracture energy %.4g J, Gc x area %.4g J\n",
           sim.step, sim.t * 1e6, t_init * 1e6, x_init * 1e3, z_init * 1e3, ndamaged, ztop * 1e3,
           ef, GC * area);
    check_close("first damage found", t_init > 0, 1, 0);
    check_close("first damage beside the plane: |x - 40 mm| (mm)", fabs(x_init - XN) * 1e3, 1, 1e-6);
    check_close("first damage above the notch's top (z > 5.6 mm)", z_init > ZN, 1, 0);
    check_close("damaged particles off the columns beside the plane", outside, 0, 0);
    check_close("the crack passes mid-height (z_top > 10 mm)", ztop > 10e-3, 1, 0);
    check_close("mirror symmetry: largest |s - s mirrored|", ds, 0, 1e-6);
    check_close("mirror symmetry: largest |u_z - u_z mirrored| / max |u_z|", duz / uzmax, 0, 1e-6);
    check_fracture_bounds(&w);
    check_close("fracture energy >= Gc x crack area", ef >= GC * area, 1, 0);
    free(mirror);
    sph_sim_free(&sim);
    return check_result();
}
