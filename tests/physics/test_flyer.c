/* Flyer plates at test-suite resolution (flyer2d.sph): two J2 steel plates meet at
 * 2 x 200 m/s; contact with restitution 0.95.  Checked over the whole run (600 us: the
 * impact at 125 us, the waves' return and the plates' separation):
 *  - linear momentum stays zero to round-off (1e-12 of one plate's momentum);
 *  - the motion is mirror symmetric about the mid-plane z = 1.075 m (each particle of the
 *    top plate against the mirror image of its partner in the bottom plate);
 *  - no interpenetration: particles of different plates never come closer than 0.7 dx,
 *    and the top plate stays above the bottom one;
 *  - energy balance: kinetic + strain + plastic work + viscous dissipation + contact
 *    (stored and dissipated) stays within 2 % of the initial kinetic energy;
 *  - the impact made plastic strain, and the contact dissipated energy (e < 1);
 *  - the time step: while the plates fly at each other the contact does not bound it (the
 *    plates' own step, as without contact), from a step or two before they touch it does,
 *    and the step in which they first touch was bounded by it. */
#define main generated_main
#include "flyer2d.c"
#undef main

#include "check.h"
#include "contact_checks.h"

enum { D = 2, NS = 11 }; /* state: Cp (9), ep, wp */

/* The partner of every bottom particle in the top plate: reference position mirrored. */
static int *mirror_map(const sph_body *top, const sph_body *bot, double zm)
{
    int *map = malloc((size_t)bot->n * sizeof *map);
    for (int i = 0; i < bot->n; i++) {
        map[i] = -1;
        for (int j = 0; j < top->n; j++)
            if (fabs(top->X[j * D] - bot->X[i * D]) < 1e-9 &&
                fabs(top->X[j * D + 1] - (2 * zm - bot->X[i * D + 1])) < 1e-9)
                map[i] = j;
    }
    return map;
}

int main(void)
{
    const double zm = 1.075, v0 = 200;
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *top = &sim.bodies[0], *bot = &sim.bodies[1];
    const double dx = top->dx, p_plate = top->n * top->mass * v0;
    const double e0 = budget_energy(&sim);
    int *map = mirror_map(top, bot, zm), unmatched = 0;
    for (int i = 0; i < bot->n; i++)
        unmatched += map[i] < 0;
    double pmax = 0, closest = INFINITY, order = INFINITY, drift = 0, asym = 0;
    long free_steps = 0, approach_steps = 0, touch_step = -1;
    int touch_bounded = 0;
    while (sim.t < MODEL.t_end - 1e-15) {
        const double dt = sph_sim_stable_dt(&sim);
        const int bounded = isfinite(sph_contact_dt(&sim, dt)); /* in or near contact */
        sph_sim_step(&sim, fmin(dt, MODEL.t_end - sim.t));
        if (touch_step < 0 && sph_contact_w2max(&sim) > 0) /* the first step in contact */
            touch_step = sim.step, touch_bounded = bounded;
        if (touch_step < 0)
            free_steps += !bounded, approach_steps += bounded;
        double ztop = INFINITY, zbot = -INFINITY;
        pmax = fmax(pmax, total_momentum(&sim) / p_plate);
        for (int i = 0; i < top->n; i++)
            ztop = fmin(ztop, pos(top, i, 1));
        for (int i = 0; i < bot->n; i++)
            zbot = fmax(zbot, pos(bot, i, 1));
        order = fmin(order, ztop - zbot);
        for (int i = 0; i < bot->n; i++)
            if (map[i] >= 0) {
                const int j = map[i];
                asym = fmax(asym, hypot(pos(top, j, 0) - pos(bot, i, 0),
                                        pos(top, j, 1) - (2 * zm - pos(bot, i, 1))) / dx);
            }
        closest = fmin(closest, closest_approach(top, bot) / dx);
        drift = fmax(drift, fabs(budget_energy(&sim) - e0) / e0);
    }
    double ep_max = 0, stored, dissipated;
    for (int b = 0; b < 2; b++)
        for (int i = 0; i < sim.bodies[b].n; i++)
            ep_max = fmax(ep_max, sim.bodies[b].state[(size_t)i * NS + 9]);
    sph_contact_energies(&sim, &stored, &dissipated);
    double ek_top, es_top;
    sph_body_energies(top, &es_top, &ek_top);
    printf("%ld steps: |momentum| <= %.3g of a plate's, asymmetry <= %.3g dx, closest pair "
           "%.3f dx, top - bottom >= %.3f dx, energy drift <= %.3g %%, largest ep %.3g, "
           "plastic work %.4g J, contact dissipated %.4g J, top kinetic %.4g J of %.4g J\n",
           sim.step, pmax, asym, closest, order / dx, 100 * drift, ep_max,
           sph_dissipated_energy(top) + sph_dissipated_energy(bot), dissipated, ek_top, e0 / 2);
    printf("before the plates touched (step %ld): %ld steps at their own time step, %ld "
           "bounded by the contact\n", touch_step, free_steps, approach_steps);
    check_close("the plates touched", touch_step > 0, 1, 0);
    check_close("the first step in contact was bounded by the contact", touch_bounded, 1, 0);
    /* the first step (before any contact pass it counts as touching) and the approach */
    check_close("steps before touching bounded by the contact (a few)", (double)approach_steps,
                0, 5);
    check_close("steps before touching at the plates' own step (> 10 x the bounded)",
                free_steps > 10 * approach_steps, 1, 0);
    check_close("mirror partners found for every particle", unmatched, 0, 0);
    check_close("|total momentum| / plate momentum", pmax, 0, 1e-12);
    check_close("mirror asymmetry (dx)", asym, 0, 1e-6);
    check_close("no interpenetration: closest pair > 0.7 dx", closest > 0.7, 1, 0);
    check_close("no interpenetration: top plate above the bottom one", order > 0, 1, 0);
    check_close("energy balance: largest drift / initial energy", drift, 0, 0.02);
    check_close("plastic strain from the impact: largest ep > 0.01", ep_max > 0.01, 1, 0);
    check_close("contact dissipated energy > 0 (e = 0.95)", dissipated > 0, 1, 0);
    check_close("plates slowed: top kinetic energy / initial < 0.8", ek_top / (e0 / 2) < 0.8, 1, 0);
    free(map);
    sph_sim_free(&sim);
    return check_result();
}
