/* A viscoelastic square stretched by a velocity prescribed at every particle, then held
 * (visco_ramp2d.sph; visco_ramp2d_symplectic.sph with -DSYMPLECTIC): F is the same at every
 * particle, so each particle's law sees the strain history eps(t_n) = F_xx - 1 at the times
 * t_n of the stress passes (the step's start with Verlet, its middle with the symplectic
 * integrator), and its state must advance over t_n - t_n-1 each time (the law's dt), from
 * t = 0.  Checked at every step against
 *  - the same update written for small strain here, eps_v <- a eps_v + (1 - a) dev(eps),
 *    a = exp(-(t_n - t_n-1) / tau), sigma = K tr(eps) I + 2 mu_inf dev(eps)
 *    + 2 mu_1 (dev(eps) - eps_v): to 1e-4 of the largest stress (the strain is 1e-5: the
 *    law's finite-strain terms are of that order).  The steps are uneven (0.35 to 1 of the
 *    stable step), and a law that advanced over each step's own length instead is off by
 *    some 1e-3;
 *  - and at the end, after the hold, the exact linear viscoelastic response to the ramp
 *    eps(t) = r min(t, t1) (t1 the first step at or after 0.1 ms), sigma_xx = K eps + 4/3 (mu_inf eps + mu_1 r tau (e^(-(t - t1)/tau)
 *    - e^(-t/tau))), within (dt / tau) of the relaxing part's share (the update holds the
 *    strain of each step through it: first order in dt / tau). */
#ifdef SYMPLECTIC
#define MODEL_C "visco_ramp2d_symplectic.c"
#define LAW_AT 0.5 /* the stress pass at the step's middle */
#else
#define MODEL_C "visco_ramp2d.c"
#define LAW_AT 0.0 /* at its start */
#endif
#define main generated_main
#include MODEL_C
#undef main

#include <omp.h>

#include "check.h"

static const double K = 5e6, MU = 1e6, G1 = 0.6, TAU = 1e-4, RATE = 0.1;

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    const sph_body *b = &sim.bodies[0];
    double t_law = 0, ev[3] = {0, 0, 0}, worst = 0, spread = 0, scale = 0, dt_most = 0;
    while (sim.t < MODEL.t_end - 1e-15) {
        /* uneven steps, so that the time since the law's last evaluation is not this step's
         * length (with even steps the two agree) */
        const double uneven = 0.35 + 0.65 * fmod((double)sim.step * 0.6180339887498949, 1.0);
        const double dt = fmin(uneven * sph_sim_stable_dt(&sim), MODEL.t_end - sim.t);
        const double t_eval = sim.t + LAW_AT * dt;
        sph_sim_step(&sim, dt);
        MODEL.stress_output(&sim);
        dt_most = fmax(dt_most, dt);
        /* the small-strain update over t_eval - t_law */
        const double eps = b->F[0] - 1, dev[3] = {2 * eps / 3, -eps / 3, -eps / 3};
        const double a = exp(-(t_eval - t_law) / TAU);
        t_law = t_eval;
        for (int k = 0; k < 3; k++)
            ev[k] = a * ev[k] + (1 - a) * dev[k];
        const double sxx = K * eps + 2 * (1 - G1) * MU * dev[0] + 2 * G1 * MU * (dev[0] - ev[0]);
        scale = fmax(scale, fabs(sxx));
        worst = fmax(worst, fabs(b->sigma[0] - sxx));
        for (int i = 1; i < b->nown; i++)
            spread = fmax(spread, fabs(b->sigma[(size_t)i * 6] - b->sigma[0]));
    }
    /* the velocity stops at the first step at or after T1: the ramp ends there */
    const double t = t_law, eps = b->F[0] - 1, t1 = eps / RATE;
    const double relax = 4.0 / 3 * G1 * MU * RATE * TAU * (exp(-(t - t1) / TAU) - exp(-t / TAU));
    const double exact = K * eps + 4.0 / 3 * (1 - G1) * MU * eps + relax;
    printf("after %ld steps (dt up to %.3g s, tau %.3g s): sigma_xx %.8g Pa at t = %.4g s, "
           "exact linear ramp-and-hold %.8g Pa\n", sim.step, dt_most, TAU, b->sigma[0], t, exact);
    check_close("max |sigma_xx - small-strain update| / max |sigma_xx|", worst / scale, 0, 1e-4);
    check_close("max |sigma_xx(i) - sigma_xx(0)| / max |sigma_xx|", spread / scale, 0, 1e-9);
    check_close("sigma_xx at the end - exact ramp-and-hold, over dt/tau x the relaxing part",
                fabs(b->sigma[0] - exact) / (dt_most / TAU * 4.0 / 3 * G1 * MU * eps), 0, 1);
    sph_sim_free(&sim);
    return check_result();
}
