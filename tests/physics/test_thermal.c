/* J2 with adiabatic heating written in the model (thermo2d.sph: copper-like, T0 = 298 K,
 * c = 383 J/(kg K), beta = 0.9), sheared homogeneously until it flows: at every step and
 * particle its temperature is T0 + beta w / (rho0 c), w the plastic work the law reports
 * (to 1e-10 K: T's round-off at 298 K), and the body's heat, sum m c (T - T0), is beta times
 * its dissipated energy (to 1e-9 of it once it flows: that round-off over a few kelvin). */
#define main generated_main
#include "thermo2d.c"
#undef main

#include <omp.h>

#include "check.h"

static const double RHO0 = 8960, T0 = 298, CP = 383, BETA = 0.9;
enum { NS = 12, EP = 9, WP = 10, T = 11 }; /* Cp (9), ep, wp, T */

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    const sph_body *b = &sim.bodies[0];
    double worst_T = 0, worst_heat = 0, hottest = T0;
    while (sim.t < MODEL.t_end - 1e-15) {
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        for (int i = 0; i < b->nown; i++) {
            const double *st = b->state + (size_t)i * NS;
            worst_T = fmax(worst_T, fabs(st[T] - (T0 + BETA * st[WP] / (RHO0 * CP))));
            hottest = fmax(hottest, st[T]);
        }
        const double heat = sph_thermal_energy(b), w = sph_dissipated_energy(b);
        if (hottest > T0 + 0.1) /* (once it flows: before, both are round-off) */
            worst_heat = fmax(worst_heat, fabs(heat - BETA * w) / (BETA * w));
    }
    printf("after %ld steps: ep %.4g, the hottest particle %.6g K, heat %.6g J, dissipated "
           "%.6g J\n", sim.step, b->state[EP], hottest, sph_thermal_energy(b),
           sph_dissipated_energy(b));
    check_close("max |T - (T0 + beta w / (rho0 c))| [K]", worst_T, 0, 1e-10);
    check_close("max |heat - beta dissipated| / (beta dissipated)", worst_heat, 0, 1e-9);
    check_close("the body flowed and heated (T > T0 + 1 K)", hottest > T0 + 1, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
