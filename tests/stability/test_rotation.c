/* Five turns of rigid rotation (rotation2d.sph): the deformation gradient stays a rotation
 * and the stress of both laws stays at round-off (objectivity over large rotations); the
 * kinetic energy stays that of the rigid rotation, m w^2 sum |X - c|^2 / 2. */
#define main generated_main
#include "rotation2d.c"
#undef main

#include "check.h"

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    double worst[2] = {0, 0};
    while (sim.t < MODEL.t_end - 1e-12) {
        sph_sim_step(&sim, fmin(MODEL.dt_fixed, MODEL.t_end - sim.t));
        for (int ib = 0; ib < 2; ib++)
            worst[ib] = fmax(worst[ib], check_max_stress(&sim.bodies[ib]));
    }
    const double E = 1.99845e6;
    printf("%ld steps, t = %.6g s (%.3f turns)\n", sim.step, sim.t, sim.t * 100 / (2 * 3.14159265358979));
    check_close("svk: max |P L| / E over five turns", worst[0] / E, 0, 1e-9);
    check_close("nh:  max |P L| / E over five turns", worst[1] / E, 0, 1e-9);
    /* The rotation came back to the start: displacement near zero after whole turns. */
    double umax = 0;
    for (int i = 0; i < sim.bodies[0].n * 2; i++)
        umax = fmax(umax, fabs(sim.bodies[0].u[i]));
    check_close("displacement after five whole turns [m]", umax, 0, 1e-9);
    double es, ek, ref = 0;
    sph_body_energies(&sim.bodies[1], &es, &ek);
    const sph_body *b = &sim.bodies[1];
    for (int i = 0; i < b->n; i++) {
        const double X = b->X[2 * i] - 5e-3, Z = b->X[2 * i + 1] - 5e-3;
        ref += 0.5 * b->mass * 1e4 * (X * X + Z * Z);
    }
    check_close("kinetic energy / rigid-rotation value", ek / ref, 1, 1e-6);
    sph_sim_free(&sim);
    return check_result();
}
