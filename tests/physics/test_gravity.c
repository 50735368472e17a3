/* Gravity (gravity3d.sph): the mean velocity of a free body is g t and its mean displacement
 * g t^2 / 2 (the symplectic scheme integrates a constant acceleration exactly); the internal
 * forces sum to zero.  The second body restricts neighbours to the nearest lattice layer
 * (nbsrange 1): 26 neighbours inside instead of 170. */
#define main generated_main
#include "gravity3d.c"
#undef main

#include "check.h"

static void means(const sph_body *b, double v[3], double u[3])
{
    for (int k = 0; k < 3; k++)
        v[k] = u[k] = 0;
    for (int i = 0; i < b->n; i++)
        for (int k = 0; k < 3; k++) {
            v[k] += b->v[3 * i + k] / b->n;
            u[k] += b->u[3 * i + k] / b->n;
        }
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    while (sim.t < MODEL.t_end - 1e-15)
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
    const double g[3] = {0, -2.0, -9.81}, t = sim.t;
    for (int ib = 0; ib < 2; ib++) {
        double v[3], u[3];
        char what[96];
        means(&sim.bodies[ib], v, u);
        for (int k = 1; k < 3; k++) {
            snprintf(what, sizeof what, "%s: mean v%c / (g t)", sim.bodies[ib].desc->name, "xyz"[k]);
            check_close(what, v[k] / (g[k] * t), 1, 1e-12);
            snprintf(what, sizeof what, "%s: mean u%c / (g t^2 / 2)", sim.bodies[ib].desc->name, "xyz"[k]);
            check_close(what, u[k] / (0.5 * g[k] * t * t), 1, 1e-9);
        }
    }
    const double nb = (double)sim.bodies[1].npairs / sim.bodies[1].n;
    check_close("nbsrange 1: mean neighbours at most 26", nb <= 26, 1, 0);
    printf("neighbours per particle: %.1f (full support), %.1f (nbsrange 1)\n",
           (double)sim.bodies[0].npairs / sim.bodies[0].n, nb);
    sph_sim_free(&sim);
    return check_result();
}
