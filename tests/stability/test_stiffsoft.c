/* Stiff against soft (stiffsoft2d.sph): a steel block hits a block 10^4 times softer at
 * 10 m/s; the automatic time step (eq. 64-66 and the contact bound) must keep the scene
 * stable.  Checked over the run (every tenth of its 12 500 steps):
 *  - every step finite and the stability monitor silent (the run reaches its end);
 *  - momentum conserved: |sum m v - p0| <= 1e-12 p0;
 *  - no interpenetration: the blocks' particles never come closer than 0.5 dx;
 *  - energy balance: kinetic + strain + viscous + contact stays within 2 % of the start;
 *  - the impact happened: the soft block moved off (its momentum > 30 % of p0). */
#define main generated_main
#include "stiffsoft2d.c"
#undef main

#include "check.h"
#include "contact_checks.h"
#include "run/monitor.h" /* the stability monitor */

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *steel = &sim.bodies[0], *soft = &sim.bodies[1];
    const double p0 = total_momentum(&sim), e0 = budget_energy(&sim), dx = soft->dx;
    double dp = 0, closest = INFINITY, drift = 0, dtmin = INFINITY;
    int finite = 1;
    sph_monitor mon = {0};
    char msg[512] = "";
    while (sim.t < MODEL.t_end - 1e-15 && finite) {
        const double dt = fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t);
        dtmin = fmin(dtmin, dt);
        sph_sim_step(&sim, dt);
        finite = sph_monitor_check(&mon, &sim, msg, sizeof msg) == 0;
        if (sim.step % 10)
            continue; /* the contact lasts thousands of steps: every tenth step is enough */
        dp = fmax(dp, fabs(total_momentum(&sim) - p0) / p0);
        closest = fmin(closest, closest_approach(steel, soft) / dx);
        drift = fmax(drift, fabs(budget_energy(&sim) - e0) / e0);
    }
    double psoft = 0;
    for (int i = 0; i < soft->n; i++)
        psoft += soft->mass * soft->v[i * 2 + 1];
    printf("%ld steps (smallest dt %.3g s) to t = %.4g s: momentum change <= %.3g of p0, "
           "closest pair %.3f dx, energy drift <= %.3g %%, soft block momentum %.3g of p0%s%s\n",
           sim.step, dtmin, sim.t, dp, closest, 100 * drift, -psoft / p0, *msg ? ": " : "", msg);
    check_close("stable: the run reached its end, monitor silent", finite && sim.t >= MODEL.t_end - 1e-12, 1, 0);
    check_close("momentum change / p0", dp, 0, 1e-12);
    check_close("no interpenetration: closest pair > 0.5 dx", closest > 0.5, 1, 0);
    check_close("energy balance: largest drift / initial energy", drift, 0, 0.02);
    check_close("the soft block was pushed: its momentum > 0.3 p0", -psoft / p0 > 0.3, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
