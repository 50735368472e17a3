/* A longitudinal pulse in a thin plane-strain strip (wave2d.sph) travels at the strip wave
 * speed c = sqrt(E / ((1 - nu^2) rho)) = 48.72 m/s: the times at which the mean displacement
 * at two planes 0.2 m apart reaches half its final value differ by 0.2 / c, within 3 %. */
#define main generated_main
#include "wave2d.c"
#undef main

#include "check.h"

/* Mean x-displacement over the particles of measurement k. */
static double mean_ux(const sph_body *b, int k)
{
    double s = 0;
    for (int q = 0; q < b->ms_count[k]; q++)
        s += b->u[(size_t)b->ms_list[k][q] * 2];
    return b->ms_count[k] ? s / b->ms_count[k] : 0;
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    const sph_body *b = &sim.bodies[0];
    /* final displacement of a plane passed by the right-going half of the pulse:
     * the integral of v/2 over x divided by c; we detect the half-way time by tracking
     * the running maximum and taking the first time the value reaches half of the plateau. */
    enum { NMAX = 20000 };
    static double t[NMAX], u0[NMAX], u1[NMAX];
    int n = 0;
    while (sim.t < MODEL.t_end && n < NMAX) {
        sph_sim_step(&sim, sph_sim_stable_dt(&sim));
        t[n] = sim.t, u0[n] = mean_ux(b, 0), u1[n] = mean_ux(b, 1);
        n++;
    }
    const double plateau0 = u0[n - 1], plateau1 = u1[n - 1];
    double t0 = NAN, t1 = NAN;
    for (int i = 1; i < n; i++) {
        if (isnan(t0) && u0[i] >= 0.5 * plateau0)
            t0 = t[i - 1] + (t[i] - t[i - 1]) * (0.5 * plateau0 - u0[i - 1]) / (u0[i] - u0[i - 1]);
        if (isnan(t1) && u1[i] >= 0.5 * plateau1)
            t1 = t[i - 1] + (t[i] - t[i - 1]) * (0.5 * plateau1 - u1[i - 1]) / (u1[i] - u1[i - 1]);
    }
    const double K = 3.25e6, mu = 0.715e6, rho = 1000;
    const double E = 9 * K * mu / (3 * K + mu), nu = (3 * K - 2 * mu) / (2 * (3 * K + mu));
    const double c = sqrt(E / ((1 - nu * nu) * rho));
    printf("plateaus %.4g / %.4g m, half-way times %.6g / %.6g s\n", plateau0, plateau1, t0, t1);
    check_close("plateaus agree (same pulse passed both planes)", plateau1 / plateau0, 1, 0.02);
    check_close("wave speed [m/s] (closed form 48.72)", 0.2 / (t1 - t0), c, 0.03 * c);
    sph_sim_free(&sim);
    return check_result();
}
