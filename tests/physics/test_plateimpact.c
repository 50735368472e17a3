/* 1D plate impacts (plateimpact2d.sph: copper, stdlib/shock with c0 = 3940 m/s, s = 1.49,
 * pistons at u_p = 200 and 1000 m/s, the second compressing by 18 %): the shock speed from
 * its arrival at two planes must be the Hugoniot's U_s = c0 + s u_p within 2 %; and the
 * jump conditions: the particle velocity behind it is u_p (the planes' velocity, within
 * 2 %), and the stress behind it (the mean of -sigma_xx over the particles between 3 and
 * 8 mm, long shocked) the momentum jump's rho0 U_s u_p with the measured U_s, within 2 %
 * (impact_check.h). */
#define main generated_main
#include "plateimpact2d.c"
#undef main

#include <omp.h>

#include "impact_check.h"

static const double C0 = 3940, S = 1.49, RHO0 = 8930, UP[2] = {200, 1000};

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0) || sim.nbodies != 2)
        return 1;
    impact_run run = {0};
    while (sim.t < MODEL.t_end - 1e-15) {
        const double dt = fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t);
        sph_sim_step(&sim, dt);
        impact_step(&sim, &run, UP, dt);
    }
    MODEL.stress_output(&sim);
    for (int q = 0; q < 2; q++)
        impact_jump_checks(&sim, &run, q, UP[q], C0, S, RHO0);
    sph_sim_free(&sim);
    return check_result();
}
