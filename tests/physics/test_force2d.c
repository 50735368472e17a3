/* Force boundary conditions of force2d.sph (plane strain, Verlet) against the momentum
 * balance.  Internal forces (and artificial viscosity) are pairwise equal and opposite, so
 * summed over a body they cancel to round-off and its momentum grows exactly at the applied
 * force:
 *  - force accel x = 2.5: mean velocity v0 + 2.5 t; mean displacement the Verlet sum
 *    sum_k dt_k v(t_k) (u += dt v_new), which differs from v0 t + 1.25 t^2 by 1.25 t dt;
 *  - force point: 3 N on each of the 50 particles with x0 > 15 mm, so P_x = 150 t; -2 N on
 *    the 5 particles near a box, from 0.5 ms to 1 ms: P_z = -10 N x 0.5 ms afterwards;
 *  - force surface: 4 kPa on the end layer (10 mm high, 1 m deep): P_x = 40 t.
 * The steps land on the window times (0.5 ms, 1 ms) so that the impulse is exact. */
#define main generated_main
#include "force2d.c"
#undef main

#include "check.h"

enum { D = 2 };

/* Total momentum (m sum v) and mean displacement of a body. */
static void sums(const sph_body *b, double mom[D], double ubar[D])
{
    for (int k = 0; k < D; k++) {
        double sv = 0, su = 0;
        for (int i = 0; i < b->n; i++)
            sv += b->v[(size_t)i * D + k], su += b->u[(size_t)i * D + k];
        mom[k] = b->mass * sv;
        ubar[k] = su / b->n;
    }
}

/* Time the z point force of body pt has acted by time t (window 0.5 ms .. 1 ms). */
static double window_time(double t)
{
    return fmax(0.0, fmin(t, 1e-3) - 0.5e-3);
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *acc = &sim.bodies[0], *pt = &sim.bodies[1], *surf = &sim.bodies[2];

    /* A rough initial velocity field, so that the body deforms and the internal forces
     * are far from zero while the acceleration acts. */
    double v0[D] = {0, 0};
    for (int i = 0; i < acc->n; i++) {
        const double x = acc->X[(size_t)i * D], z = acc->X[(size_t)i * D + 1];
        acc->v[(size_t)i * D] = 0.3 * sin(2900 * x + 1300 * z);
        acc->v[(size_t)i * D + 1] = 0.2 * cos(1700 * x - 2100 * z);
        v0[0] += acc->v[(size_t)i * D] / acc->n, v0[1] += acc->v[(size_t)i * D + 1] / acc->n;
    }

    int nright = 0;
    for (int i = 0; i < pt->n; i++)
        nright += pt->X[(size_t)i * D] > 15e-3;
    check_close("pt: particles with x0 > 15 mm (5 columns x 10 rows)", nright, 50, 0);
    check_close("pt: particles near the box under the corner (x0 <= 4.5 mm, z0 = 0.5 mm)",
                pt->bc_count[1], 5, 0);

    /* Largest deviations over all steps, each relative to the quantity's final size. */
    double e_vacc = 0, e_uacc = 0, e_uacc_cont = 0, e_ptx = 0, e_ptz = 0, e_surf = 0;
    double u_verlet[D] = {0, 0}, dtmax = 0;
    const double marks[] = {0.5e-3, 1e-3, MODEL.t_end};
    int mark = 0;
    while (mark < 3) {
        double dt = sph_sim_stable_dt(&sim);
        if (sim.t + dt >= marks[mark] - 1e-12)
            dt = marks[mark++] - sim.t;
        dtmax = fmax(dtmax, dt);
        sph_sim_step(&sim, dt);
        const double t = sim.t;
        double mom[D], ubar[D];

        sums(acc, mom, ubar);
        for (int k = 0; k < D; k++) {
            const double vexp = v0[k] + (k == 0 ? 2.5 * t : 0);
            u_verlet[k] += dt * vexp;
            e_vacc = fmax(e_vacc, fabs(mom[k] / (acc->mass * acc->n) - vexp));
            e_uacc = fmax(e_uacc, fabs(ubar[k] - u_verlet[k]));
            e_uacc_cont = fmax(e_uacc_cont, fabs(ubar[k] - (v0[k] * t + (k == 0 ? 1.25 * t * t : 0))));
        }
        sums(pt, mom, ubar);
        e_ptx = fmax(e_ptx, fabs(mom[0] - 150 * t));
        e_ptz = fmax(e_ptz, fabs(mom[1] - (-10 * window_time(t))));
        sums(surf, mom, ubar);
        e_surf = fmax(e_surf, fabs(mom[0] - 40 * t));
        e_surf = fmax(e_surf, fabs(mom[1]));
    }
    const double T = sim.t;
    printf("%ld steps to t = %.6g s (largest dt %.3g s)\n", sim.step, T, dtmax);
    double mom[D], ubar[D];
    sums(acc, mom, ubar);
    printf("acc: mean velocity %.12g m/s, mean displacement %.12g m\n", mom[0] / (acc->mass * acc->n), ubar[0]);
    /* round-off: a few hundred steps of sums of O(1e4 m/s^2) pair forces, ~1e-16 each */
    check_close("accel: max |mean v - (v0 + 2.5 t)| / (2.5 T)", e_vacc / (2.5 * T), 0, 1e-9);
    check_close("accel: max |mean u - sum dt (v0 + 2.5 t)| / (1.25 T^2)", e_uacc / (1.25 * T * T), 0, 1e-9);
    /* first-order Verlet: u lags v0 t + 1.25 t^2 by at most 1.25 t dt */
    check_close("accel: max |mean u - (v0 t + 1.25 t^2)| / (1.25 T dtmax) in [0, 1]",
                e_uacc_cont / (1.25 * T * dtmax), 0.5, 0.5);
    sums(pt, mom, ubar);
    printf("pt: momentum %.12g, %.12g N s\n", mom[0], mom[1]);
    check_close("point: max |P_x - 50 x 3 N x t| / (150 N x T)", e_ptx / (150 * T), 0, 1e-9);
    check_close("point, window 0.5..1 ms: max |P_z - (-10 N x time in window)| / 5e-3 N s",
                e_ptz / 5e-3, 0, 1e-9);
    check_close("point, window: P_z at the end [N s] (-10 N x 0.5 ms)", mom[1], -5e-3, 1e-12);
    sums(surf, mom, ubar);
    printf("surf: momentum %.12g N s\n", mom[0]);
    check_close("surface: max |P - 4 kPa x 10 mm x 1 m x t| / (40 N x T)", e_surf / (40 * T), 0, 1e-9);
    sph_sim_free(&sim);
    return check_result();
}
