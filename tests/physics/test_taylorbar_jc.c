/* The Taylor bar with Johnson-Cook (taylorbar_jc.sph: OFHC copper, 227 m/s, dp = 0.8 mm),
 * run to 80 us:
 *  - energy: kinetic + strain + plastic work + what the artificial viscosity took never
 *    grows (to 0.1 % of the initial kinetic energy): the wall only takes energy out (its
 *    particles are held, 2 % of the energy by the end), and the plastic work takes more than
 *    80 % of it;
 *  - the heat is 0.9 of the plastic work (Taylor-Quinney), at every step to 1e-9, and the
 *    hottest particle, at the impact end, is more than 100 K above room temperature;
 *  - it shortened (below 24 mm) and mushroomed (the outermost particle centre at more than
 *    1.5 times the radius), with the largest plastic strain at the impact end;
 *  - damage grew (above 0.1 somewhere; at this resolution it reaches 1 at a few particles
 *    of the impact end's rim, where the plastic strain is largest and the hoop stress
 *    tensile). */
#define main generated_main
#include "taylorbar_jc.c"
#undef main

#include <omp.h>

#include "check.h"

enum { D = 3, NS = 13, EP = 9, WP = 10, T = 11, DMG = 12 };

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    const double e0 = 0.5 * b->mass * b->nown * 227.0 * 227.0;
    double grow = -INFINITY, heat_err = 0, last = 0;
    while (sim.t < MODEL.t_end - 1e-15) {
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        double es, ek;
        sph_body_energies(b, &es, &ek);
        const double wp = sph_dissipated_energy(b);
        last = es + ek + wp + b->visc_dissipated;
        grow = fmax(grow, (last - e0) / e0);
        if (wp > 1e-6 * e0)
            heat_err = fmax(heat_err, fabs(sph_thermal_energy(b) - 0.9 * wp) / (0.9 * wp));
    }
    double zmax = -INFINITY, rmax = 0, ep_max = 0, z_ep = 0, T_max = 0, z_T = 0, D_max = 0;
    int broken = 0;
    for (int i = 0; i < b->n; i++) {
        double x[3];
        for (int k = 0; k < D; k++)
            x[k] = b->X[i * D + k] + b->u[i * D + k];
        zmax = fmax(zmax, x[2]);
        rmax = fmax(rmax, sqrt(x[0] * x[0] + x[1] * x[1]));
        const double *st = b->state + (size_t)i * NS;
        if (st[EP] > ep_max)
            ep_max = st[EP], z_ep = x[2];
        if (st[T] > T_max)
            T_max = st[T], z_T = x[2];
        D_max = fmax(D_max, st[DMG]);
        broken += st[DMG] >= 1;
    }
    const double wp = sph_dissipated_energy(b);
    printf("after %ld steps: length %.4g mm, outermost centre %.4g mm, ep up to %.3g (z = %.3g "
           "mm), T up to %.5g K (z = %.3g mm), damage up to %.3g (%d particles broken); plastic "
           "work %.4g of %.4g J, artificial viscosity %.4g J, the wall %.4g J\n", sim.step,
           zmax * 1e3, rmax * 1e3, ep_max, z_ep * 1e3, T_max, z_T * 1e3, D_max, broken, wp, e0,
           b->visc_dissipated, e0 - last);
    check_close("largest (kinetic + strain + plastic + viscous - initial) / initial", grow, 0, 1e-3);
    check_close("plastic work / initial kinetic energy > 0.8", wp / e0 > 0.8, 1, 0);
    check_close("|heat - 0.9 plastic work| / (0.9 plastic work)", heat_err, 0, 1e-9);
    check_close("hottest particle > 398 K, at the impact end (z < 3 mm)", T_max > 398 && z_T < 3e-3, 1, 0);
    check_close("shortened: length below 24 mm", zmax < 24e-3, 1, 0);
    check_close("mushroomed: outermost centre / radius > 1.5", rmax / 3.2e-3 > 1.5, 1, 0);
    check_close("largest ep at the impact end (z < 3 mm)", z_ep < 3e-3, 1, 0);
    check_close("damage grew: largest D > 0.1", D_max > 0.1, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
