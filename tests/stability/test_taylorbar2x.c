/* The coarse Taylor bar at twice its speed (taylorbar2x.sph: 454 m/s, dp = 1 mm) with the
 * automatic time step (`timestep auto`, the default; docs/stability.md).  Checked over 40 us:
 *  - the run needed the compression bound: the smallest principal stretch fell below 0.1
 *    (the foot is crushed), so the reference bound of eq. 65 alone would allow steps over
 *    ten times too long there (taylorbar2x_plain.sph, `timestep undeformed`, goes non-finite
 *    at 35 us), and the step's factor on eq. 65 went below 0.2;
 *  - every step's state is finite and no particle is inverted (det F > 0);
 *  - energy: kinetic + strain + plastic work + viscous dissipation never grows (to 0.1 % of
 *    the initial kinetic energy): the wall only takes energy out; a step above the stable
 *    bound makes it grow (the plain run gains 20 % before it fails);
 *  - the bar shortened below 20 mm and mushroomed beyond twice its radius. */
#define main generated_main
#include "taylorbar2x.c"
#undef main

#include "check.h"

static double det3(const double *F)
{
    return F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
           F[2] * (F[3] * F[7] - F[4] * F[6]);
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    double e0 = 0, grow = 0, lam = 1, jmin = INFINITY, fmin_dt = 1;
    int finite = 1;
    for (int i = 0; i < b->n; i++)
        e0 += 0.5 * b->mass * 454.0 * 454.0;
    while (sim.t < MODEL.t_end - 1e-15 && finite) {
        const double dt = sph_sim_stable_dt(&sim);
        lam = fmin(lam, sqrt(b->lam2min));
        fmin_dt = fmin(fmin_dt, sim.dt_factor);
        sph_sim_step(&sim, fmin(dt, MODEL.t_end - sim.t));
        double es, ek;
        sph_body_energies(b, &es, &ek);
        const double e = es + ek + sph_dissipated_energy(b) + b->visc_dissipated;
        finite = isfinite(e);
        grow = fmax(grow, e - e0);
        for (int i = 0; i < b->n; i++)
            jmin = fmin(jmin, det3(b->F + 9 * (size_t)i));
    }
    const check_extent ext = check_bar_extent(b);
    const double zmin = ext.zmin, zmax = ext.zmax, rmax = ext.rmax;
    printf("%ld steps to %.3g us: smallest stretch %.3g, smallest det F %.3g, length %.4g mm, "
           "outermost centre %.4g mm, energy growth %.3g J of %.4g J; smallest factor on eq. 65 "
           "%.3g\n",
           sim.step, sim.t * 1e6, lam, jmin, (zmax - zmin) * 1e3, rmax * 1e3, grow, e0, fmin_dt);
    const int ended = finite && sim.t >= MODEL.t_end * (1 - 1e-9);
    check_close("reached the end time with finite energies", ended, 1, 0);
    check_close("smallest principal stretch < 0.1", lam < 0.1, 1, 0);
    check_close("the step followed the current spacing (factor < 0.2)", fmin_dt < 0.2, 1, 0);
    check_close("no particle inverted (det F > 0)", jmin > 0, 1, 0);
    check_close("energy growth / initial kinetic energy", grow / e0, 0, 1e-3);
    check_close("shortened below 20 mm", zmax - zmin < 20e-3, 1, 0);
    check_close("mushroomed: outermost centre / radius > 2", rmax / 3.2e-3 > 2, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
