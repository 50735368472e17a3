/* Plane-strain patch tests on the generated code of patch2d.sph: exact F for an affine
 * displacement at every particle, SVK uniaxial strain in closed form, and zero stress
 * under a rigid rotation by 90 degrees in the x-z plane. */
#define main generated_main
#include "patch2d.c"
#undef main

#include "check.h"

static sph_sim sim;

/* u = A X (A is 2x2 over x, z) at every particle, then the stress pass. */
static double impose(sph_body *b, const double A[4], void (*pass)(sph_body *))
{
    for (int i = 0; i < b->n; i++)
        for (int r = 0; r < 2; r++)
            b->u[(size_t)i * 2 + r] = A[2 * r] * b->X[(size_t)i * 2] + A[2 * r + 1] * b->X[(size_t)i * 2 + 1];
    pass(b);
    double worst = 0;
    for (int i = 0; i < b->n; i++) {
        const double *F = b->F + (size_t)i * 9;
        const double want[9] = {1 + A[0], 0, A[1], 0, 1, 0, A[2], 0, 1 + A[3]};
        for (int k = 0; k < 9; k++)
            worst = fmax(worst, fabs(F[k] - want[k]));
    }
    return worst;
}

int main(void)
{
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    const double A[4] = {0.021, -0.013, 0.008, -0.017};
    check_close("2D svk: max |F - (I + A)| over all particles", impose(&sim.bodies[0], A, sq_svk_stress_pass), 0, 1e-12);
    check_close("2D nh:  max |F - (I + A)| over all particles", impose(&sim.bodies[1], A, sq_nh_stress_pass), 0, 1e-12);

    const double strain[4] = {0.1, 0, 0, 0};
    impose(&sim.bodies[0], strain, sq_svk_stress_pass);
    sq_svk_stress_output(&sim.bodies[0]);
    check_close("2D svk uniaxial strain 1.1: sigma11 [kPa] (closed form 485.49)", sim.bodies[0].sigma[0] / 1e3, 485.49, 0.01);

    const double rot[4] = {-1, 1, -1, -1}; /* 90 degrees in x-z: R - I */
    check_close("2D rotation 90 deg: max |F - R|", impose(&sim.bodies[1], rot, sq_nh_stress_pass), 0, 1e-12);
    sq_nh_momentum_pass(&sim.bodies[1]);
    double amax = 0;
    for (int i = 0; i < sim.bodies[1].n * 2; i++)
        amax = fmax(amax, fabs(sim.bodies[1].a[i]));
    check_close("2D rotation 90 deg: max |a| / (E / (rho dx))", amax / 2e6, 0, 1e-12);
    sph_sim_free(&sim);
    return check_result();
}
