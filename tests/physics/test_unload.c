/* Irreversibility and the uniform steady state of the phase field (unload2d.sph).  With the
 * same F at every particle, psi+ and so H are uniform, the SPH Laplacian of a uniform s is
 * zero (also at free faces), and eq. 61 reduces at every particle to one ODE whose steady
 * state is  s = 1 / (1 + 4 eps0 H / Gc).  Checked:
 *  - H during the hold equals the closed-form psi+ of SVK for the stretch (eq. 11): with
 *    E = diag(e, 0, 0), e > 0:  psi+ = (lambda/2 + mu) e^2, to 1e-9 relative;
 *  - s stays uniform (spread below 1e-9) and reaches the steady state within 1e-3 by the
 *    end of the hold; while loaded it rises over a step by at most 1e-6 (the damping M of
 *    eq. 9 is critical: when the stretch stops, s, still moving, passes the steady state
 *    once by about 1e-7 and comes back);
 *  - after unloading psi+ is 0 but H keeps its value (eq. 8), s never increases over a step
 *    and stays at the steady state: the crack does not heal;
 *  - the strain energy is the degraded one, A s^2 psi+, and the fracture energy of the
 *    uniform s is A Gc (1 - s)^2 / (4 eps0). */
#ifndef MODEL_C /* the same checks run on unload2d_symplectic.c */
#define MODEL_C "unload2d.c"
#endif
#define main generated_main
#include MODEL_C
#undef main

#include "check.h"

enum { D = 2 };

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    const double E = 1e6, nu = 0.3, Gc = 1, eps0 = 2.5e-3;
    const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    double s_prev = 1, rise = 0, rise_after = 0, spread = 0, s_hold = 0, H_hold = 0, e_hold = 0;
    double es_hold = 0;
    while (sim.t < MODEL.t_end - 1e-12) {
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        double lo = 1, hi = 0;
        for (int i = 0; i < b->n; i++)
            lo = fmin(lo, b->s[i]), hi = fmax(hi, b->s[i]);
        spread = fmax(spread, hi - lo);
        if (sim.t <= 3e-3)
            rise = fmax(rise, hi - s_prev);
        else
            rise_after = fmax(rise_after, hi - s_prev);
        s_prev = hi;
        if (sim.t <= 3e-3) { /* the end of the hold */
            s_hold = b->s[0], H_hold = b->H[0];
            e_hold = b->F[0] - 1 + 0.5 * (b->F[0] - 1) * (b->F[0] - 1); /* (F^2 - 1)/2 */
            double ek;
            sph_body_energies(b, &es_hold, &ek);
        }
    }
    const double psi_plus = (0.5 * lam + mu) * e_hold * e_hold;
    const double s_eq = 1 / (1 + 4 * eps0 * H_hold / Gc);
    printf("%ld steps; stretch strain %.6g; H %.8g (closed form %.8g); s %.8g at 3 ms, %.8g at "
           "the end; steady state %.8g\n",
           sim.step, e_hold, H_hold, psi_plus, s_hold, b->s[0], s_eq);
    check_close("H / closed-form psi+ at the end of the hold", H_hold / psi_plus, 1, 1e-9);
    check_close("s at the end of the hold - 1/(1 + 4 eps0 H/Gc)", s_hold - s_eq, 0, 1e-3);
    check_close("s is damaged (below 0.6)", s_hold < 0.6, 1, 0);
    /* the strain energy is the degraded one: psi- = 0 in tension, so A s^2 psi+ */
    check_close("strain energy at the hold / A s^2 psi+",
                es_hold / (0.04 * 0.01 * s_hold * s_hold * psi_plus), 1, 1e-6);
    check_close("spread of s over the particles", spread, 0, 1e-9);
    check_close("largest increase of s over a step, loaded", rise > 0 ? rise : 0, 0, 1e-6);
    check_close("largest increase of s over a step, unloaded", rise_after > 0 ? rise_after : 0, 0,
                1e-12);
    check_close("H after unloading / H at the end of the hold", b->H[0] / H_hold, 1, 0);
    /* the windows of the velocity close between steps: 1e-5 of strain is left */
    check_close("stretch undone: |F_xx - 1|", fabs(b->F[0] - 1), 0, 1e-5);
    check_close("s after unloading - 1/(1 + 4 eps0 H/Gc)", b->s[0] - s_eq, 0, 1e-3);
    /* the fracture energy of a uniform s (no gradient): the strip's area times
     * Gc (1 - s)^2 / (4 eps0) */
    const double area = 0.04 * 0.01, ef = area * Gc * (1 - b->s[0]) * (1 - b->s[0]) / (4 * eps0);
    check_close("fracture energy / A Gc (1 - s)^2 / (4 eps0)", sph_fracture_energy(b) / ef, 1,
                1e-9);
    sph_sim_free(&sim);
    return check_result();
}
