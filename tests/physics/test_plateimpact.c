/* 1D plate impacts (plateimpact2d.sph: copper, stdlib/shock with c0 = 3940 m/s, s = 1.49,
 * pistons at u_p = 200 and 1000 m/s, the second compressing by 18 %): behind the shock the material moves at u_p, so a plane's mean
 * displacement grows as u_p (t - t_a) once the shock has passed it at t_a.  From the two
 * planes' t_a, the shock speed (x2 - x1) / (t_a2 - t_a1) must be the Hugoniot's
 * U_s = c0 + s u_p within 2 %; and the jump conditions: the particle velocity behind it is
 * u_p (the planes' velocity, within 2 %), and the stress behind it (the mean of -sigma_xx
 * over the particles between 3 and 8 mm, long shocked) the momentum jump's rho0 U_s u_p
 * with the measured U_s, within 2 %. */
#define main generated_main
#include "plateimpact2d.c"
#undef main

#include <omp.h>

#include "check.h"

static const double C0 = 3940, S = 1.49, RHO0 = 8930, UP[2] = {200, 1000};

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0) || sim.nbodies != 2)
        return 1;
    double prev[2][2] = {{0}}, vel[2][2] = {{0}};
    while (sim.t < MODEL.t_end - 1e-15) {
        const double dt = fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t);
        sph_sim_step(&sim, dt);
        for (int q = 0; q < 2; q++)
            for (int k = 0; k < 2; k++) {
                double m[6];
                sph_measure(&sim.bodies[q], k, m);
                vel[q][k] = (m[0] - prev[q][k]) / dt, prev[q][k] = m[0];
            }
    }
    MODEL.stress_output(&sim);
    for (int q = 0; q < 2; q++) {
        const sph_body *b = &sim.bodies[q];
        const double up = UP[q];
        double ta[2];
        for (int k = 0; k < 2; k++)
            ta[k] = sim.t - prev[q][k] / up;
        const double us = 15e-3 / (ta[1] - ta[0]), want = C0 + S * up;
        /* the stress behind the shock: the mean of -sigma_xx between 3 and 8 mm */
        double sxx = 0;
        int nb = 0;
        for (int i = 0; i < b->nown; i++)
            if (b->X[i * 2] > 3e-3 && b->X[i * 2] < 8e-3)
                sxx -= b->sigma[(size_t)i * 6], nb++;
        sxx /= nb;
        char what[128];
        printf("u_p %g m/s: shock arrivals %.4g and %.4g us, U_s = %.6g m/s (Hugoniot %.6g); "
               "the planes' velocities %.5g, %.5g m/s; the stress behind %.4g Pa against "
               "rho0 U_s u_p %.4g Pa\n", up, ta[0] * 1e6, ta[1] * 1e6, us, want, vel[q][0],
               vel[q][1], sxx, RHO0 * us * up);
        snprintf(what, sizeof what, "u_p %g: U_s / (c0 + s u_p)", up);
        check_close(what, us / want, 1, 0.02);
        for (int k = 0; k < 2; k++) {
            snprintf(what, sizeof what, "u_p %g: velocity behind the shock / u_p (plane %d)", up,
                     k + 1);
            check_close(what, vel[q][k] / up, 1, 0.02);
        }
        snprintf(what, sizeof what, "u_p %g: -sigma_xx behind / (rho0 U_s u_p)", up);
        check_close(what, sxx / (RHO0 * us * up), 1, 0.02);
    }
    sph_sim_free(&sim);
    return check_result();
}
