/* The cylinder impact test of Johnson & Cook (1983) at 146 m/s (taylorbar_jc1983.sph) against
 * its measured shape: the final length 0.736 L0 and the largest diameter 1.40 D0 (Zerilli &
 * Armstrong 1987's table of the test).  The run goes on until the cylinder is at rest (its
 * kinetic energy under 0.5 % of the impact's); then
 *  - the length from the anvil (the top particles' centres plus half a spacing, L0 at t = 0)
 *    over L0 within 7 % of the test's: sphc gives it 4.8 % long at this spacing, 5.1-5.3 % at
 *    48 and 64 spacings along the length (docs/verification.md, the Johnson-Cook constants'
 *    own difference from the test, not the spacing's);
 *  - the foot's diameter, measured as the outermost particle centre plus half a spacing over
 *    the same at t = 0, within 5 % of the test's 1.40: sphc gives 1.373 here, 1.422 and
 *    1.453 at the finer spacings.
 * (The law's rate hardening is a part of it: with C = 0 the length is 0.739 L0 here.) */
#define main generated_main
#include "taylorbar_jc1983.c"
#undef main

#include <omp.h>

#include "check.h"

/* The cylinder's length from the anvil (z = 0) and its radius, from the outermost particle
 * centres plus half a spacing. */
static void extent(const sph_body *b, double dp, double *length, double *radius)
{
    const check_extent e = check_bar_extent(b);
    *length = e.zmax + 0.5 * dp;
    *radius = e.rmax + 0.5 * dp;
}

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    const double e0 = 0.5 * b->mass * b->nown * 146.0 * 146.0;
    double L0, R0, L, R, es, ek;
    extent(b, MODEL.dp, &L0, &R0);
    while (sim.t < MODEL.t_end - 1e-15)
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
    sph_body_energies(b, &es, &ek);
    extent(b, MODEL.dp, &L, &R);
    printf("after %ld steps: length %.4g mm (L0 %.4g mm), foot radius %.4g mm (%.4g mm at t = 0), "
           "kinetic energy %.3g of %.4g J\n", sim.step, L * 1e3, L0 * 1e3, R * 1e3, R0 * 1e3, ek, e0);
    check_close("the length at t = 0: 25.4 mm", L0, 25.4e-3, 1e-9);
    check_close("at rest: kinetic energy / the impact's < 0.005", ek / e0 < 0.005, 1, 0);
    check_close("final length / L0 against the test's 0.736 (7 %)", L / L0, 0.736, 0.07 * 0.736);
    check_close("foot diameter / D0 against the test's 1.40 (5 %)", R / R0, 1.40, 0.05 * 1.40);
    sph_sim_free(&sim);
    return check_result();
}
