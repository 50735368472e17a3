/* Artificial viscosity only where particles approach (expand2d.sph).  A free square is given
 * the velocity of a uniform dilatation, v = e (X - X_c), expanding (e > 0) or contracting
 * (e < 0), and run for three steps, before the pull of the free surface has turned any
 * pair round (over 40 steps it has: the expanding square then dissipates too).  While it expands
 * every pair separates, so the viscosity must do no work at all: exactly zero; while it
 * contracts every pair approaches, and the viscosity (beta1 = beta2 = 1) takes a tenth of the
 * kinetic energy.  Acting on separating pairs as well, as eq. 58 is printed, the expanding
 * square loses as much as the contracting one. */
#define main generated_main
#include "expand2d.c"
#undef main

#include "check.h"

enum { STEPS = 3 };

/* The viscous work over STEPS steps from the dilatation rate e, over the initial kinetic
 * energy. */
static double viscous_share(double e)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        exit(1);
    sph_body *b = &sim.bodies[0];
    double ek0 = 0, v2max = 0;
    for (int i = 0; i < b->n; i++) {
        const double vx = e * (b->X[2 * i] - 5e-3), vz = e * (b->X[2 * i + 1] - 5e-3);
        b->v[2 * i] = vx, b->v[2 * i + 1] = vz;
        ek0 += 0.5 * b->mass * (vx * vx + vz * vz);
        v2max = fmax(v2max, vx * vx + vz * vz);
    }
    b->vmax2 = v2max; /* the time step's bound (eq. 65) from these speeds */
    double vmin = 0;
    for (int k = 0; k < STEPS; k++) {
        sph_sim_step(&sim, sph_sim_stable_dt(&sim));
        vmin = fmin(vmin, b->visc_dissipated);
    }
    const double share = b->visc_dissipated / ek0;
    printf("dilatation rate %+g 1/s: %ld steps to t = %.4g s, viscous work %.4g J of %.4g J "
           "kinetic (%.3g)\n", e, sim.step, sim.t, b->visc_dissipated, ek0, share);
    check_close("  viscous work never negative / kinetic", vmin / ek0, 0, 1e-12);
    sph_sim_free(&sim);
    return share;
}

int main(void)
{
    const double expand = viscous_share(100.0), contract = viscous_share(-100.0);
    check_close("expanding: viscous work / kinetic (exactly none)", expand, 0, 0);
    check_close("contracting: viscous work / kinetic above 1e-5", contract > 1e-5, 1, 0);
    return check_result();
}
