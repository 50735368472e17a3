/* A law that gives its wave speed (wavespeed2d.sph: three times the body's c0) bounds the
 * time step as a compression of the spacing by c0 / cw would: with the default `timestep
 * auto` at cfl 0.2 (lambda_on = cfl / 0.4 = 0.5) the factor on eq. 65 is (1/3) / 0.5 = 2/3,
 * so that the Courant number at the law's wave speed stays 0.4; the same body without it
 * keeps the factor 1.  Checked before the first step (the wave speed at rest, which the
 * compiler evaluates: lam2_rest) and after it, to 1e-12. */
#define main generated_main
#include "wavespeed2d.c"
#undef main

#include "check.h"

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0) || sim.nbodies != 2)
        return 1;
    double f0 = sph_stretch_factor(MODEL.dt_lambda_on, sim.bodies[0].lam2 != NULL,
                                   sim.bodies[0].lam2min);
    check_close("before the first step: factor of the body whose law gives 3 c0", f0, 2.0 / 3,
                1e-12);
    sph_sim_step(&sim, sph_sim_stable_dt(&sim));
    double f[2];
    for (int k = 0; k < 2; k++) {
        const sph_body *b = &sim.bodies[k];
        f[k] = sph_stretch_factor(MODEL.dt_lambda_on, b->lam2 != NULL, b->lam2min);
    }
    printf("the factors on eq. 65: %.15g (wave speed 3 c0), %.15g (none)\n", f[0], f[1]);
    check_close("factor of the body whose law gives 3 c0", f[0], 2.0 / 3, 1e-12);
    check_close("factor of the same body without", f[1], 1, 1e-12);
    sph_sim_free(&sim);
    return check_result();
}
