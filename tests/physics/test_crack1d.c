/* A fixed crack in an unloaded plane-strain block (crack1d.sph): s is held at 0 on the
 * column x = xc, everything else starts intact.  Without load (H = 0) the steady state of
 * eq. 6 is  s(x) = 1 - exp(-|x - xc| / (2 eps0)), and its fracture energy per unit crack
 * area is Gc (the integral of Gc ((1 - s)^2/(4 eps0) + eps0 s'^2) over x).  Checked after
 * the hyperbolic relaxation (eq. 61) has settled:
 *  - the profile on the middle row of particles, away from the free top and bottom faces
 *    (where the SPH Laplacian of eq. 62 misses neighbours), within 0.02 of the closed form;
 *  - the body's fracture energy divided by its height (the crack area per unit thickness)
 *    within 5 % of Gc;
 *  - s stays in [0, 1] and the run has settled (s changes by less than 1e-3 over the last
 *    fifth of the run). */
#define main generated_main
#include "crack1d.c"
#undef main

#include <string.h>

#include "check.h"

enum { D = 2 };

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    const double xc = 0.0505, zc = 0.0205, eps0 = 4e-3, Gc = 2, height = 0.04;
    double *before = malloc(sizeof(double) * (size_t)b->n);
    int pinned = 0;
    while (sim.t < MODEL.t_end - 1e-12) {
        if (sim.t <= 0.8 * MODEL.t_end)
            memcpy(before, b->s, sizeof(double) * (size_t)b->n);
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        pinned = 0;
        for (int i = 0; i < b->n; i++)
            if (fabs(b->X[i * D] - xc) < 1e-9) {
                b->s[i] = 0, b->sd[i] = 0;
                pinned++;
            }
    }
    double err = 0, change = 0, lo = 1, hi = 0;
    for (int i = 0; i < b->n; i++) {
        lo = fmin(lo, b->s[i]), hi = fmax(hi, b->s[i]);
        change = fmax(change, fabs(b->s[i] - before[i]));
        if (fabs(b->X[i * D + 1] - zc) > 1e-9)
            continue;
        double want = 1 - exp(-fabs(b->X[i * D] - xc) / (2 * eps0));
        err = fmax(err, fabs(b->s[i] - want));
    }
    double ef = sph_fracture_energy(b);
    printf("%ld steps to t = %.4g s, %d pinned particles\n", sim.step, sim.t, pinned);
    check_close("pinned column: 40 particles", pinned, 40, 0);
    check_close("max |s - (1 - exp(-|x|/(2 eps0)))| on the middle row", err, 0, 0.02);
    check_close("fracture energy / crack area / Gc", ef / height / Gc, 1, 0.05);
    check_close("smallest s", lo, 0, 0);
    check_close("largest s is at most 1", hi > 1 ? hi : 1, 1, 0);
    check_close("largest change of s over the last fifth of the run", change, 0, 1e-3);
    free(before);
    sph_sim_free(&sim);
    return check_result();
}
