/* A law that takes in the artificial viscosity's heat, in 3D (mgblock3d.sph: a free copper
 * cube with stdlib/miegruneisen, its particles started towards its centre; the half lists,
 * as the plan has it for such a law, where the offset blocks would run).  Each pair's heat
 * goes half to each of its particles (templates/body_forces.c): the particles' heat, sum
 * V q, must be the energy the body's viscosity dissipated (the step sums' column of
 * energies.csv) to round-off at every step, and no particle's heat may fall.  (Its energy
 * balance is test_miegruneisen.c's: this cube's violent, coarse compression, which the
 * viscosity damps within a few steps, keeps kinetic + strain energy + heat to some 8 % only,
 * with or without the thermal term: the first-order bookkeeping of so fast a dissipation.) */
#define main generated_main
#include "mgblock3d.c"
#undef main

#include <omp.h>

#include "check.h"

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0) || sim.nbodies != 1)
        return 1;
    const sph_body *b = &sim.bodies[0];
    const int ns = b->desc->nstate, kq = b->desc->vheat - 1;
    if (kq < 0 || !b->vq)
        return 1;
    double strain, kinetic, e0 = 0, worst = 0, fell = 0;
    double *last = calloc((size_t)b->nown, sizeof *last);
    int steps = 0;
    while (sim.t < MODEL.t_end - 1e-15) {
        const double dt = fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t);
        sph_sim_step(&sim, dt);
        if (steps++ == 0) { /* (the first step sets the initial velocities) */
            sph_body_energies(b, &strain, &kinetic);
            e0 = kinetic + strain;
        }
        double heat = 0;
        for (int i = 0; i < b->nown; i++) {
            const double q = b->state[(size_t)i * ns + kq];
            heat += q;
            fell = fmax(fell, last[i] - q);
            last[i] = q;
        }
        heat *= b->mass / b->rho0;
        worst = fmax(worst, fabs(heat - b->visc_dissipated) / e0);
    }
    free(last);
    sph_body_energies(b, &strain, &kinetic);
    printf("%d steps: kinetic %.6g J, strain %.6g J, plastic %.6g J, viscous %.6g J (of %.6g J "
           "at the start)\n", steps, kinetic, strain, sph_dissipated_energy(b),
           b->visc_dissipated, e0);
    check_close("the viscous heat's share of the energy (it acted)", b->visc_dissipated / e0 > 0.01,
                1, 0);
    check_close("largest |sum V q - viscous energy| / E0 over the steps", worst, 0, 1e-12);
    check_close("largest fall of a particle's heat in a step [J/m^3]", fell, 0, 0);
    sph_sim_free(&sim);
    return check_result();
}
