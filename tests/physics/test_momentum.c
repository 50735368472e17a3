/* Total linear momentum of a free body (free3d.sph, with artificial viscosity) is conserved
 * to round-off: the symmetric corrected momentum equation makes every pair force equal and
 * opposite. */
#define main generated_main
#include "free3d.c"
#undef main

#include "check.h"

static void momentum(const sph_body *b, double p[3], double *scale)
{
    p[0] = p[1] = p[2] = 0;
    *scale = 0;
    for (int i = 0; i < b->n; i++)
        for (int k = 0; k < 3; k++) {
            p[k] += b->mass * b->v[(size_t)i * 3 + k];
            *scale += b->mass * fabs(b->v[(size_t)i * 3 + k]);
        }
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    double p0[3], p1[3], scale;
    momentum(&sim.bodies[0], p0, &scale);
    for (int s = 0; s < 300; s++)
        sph_sim_step(&sim, sph_sim_stable_dt(&sim));
    momentum(&sim.bodies[0], p1, &scale);
    printf("after %ld steps (t = %.3g s), sum m|v| = %.4g\n", sim.step, sim.t, scale);
    for (int k = 0; k < 3; k++) {
        char what[64];
        snprintf(what, sizeof what, "change of momentum %c / sum m|v|", "xyz"[k]);
        check_close(what, (p1[k] - p0[k]) / scale, 0, 1e-12);
    }
    double ds = 0, dk = 0;
    sph_body_energies(&sim.bodies[0], &ds, &dk);
    check_close("the body deformed (strain energy > 0)", ds > 0, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
