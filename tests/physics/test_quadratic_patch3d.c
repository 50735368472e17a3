/* Patch tests of `gradient quadratic` (quadratic_patch3d.sph, templates/body_quadratic.c):
 *  - a quadratic displacement gives the exact F = I + grad u(X_i) at every particle of a
 *    free cube, its corners and edges included (eq. 63's gradient is exact for linear
 *    fields only: there it errs by about dx times the second derivative at the surfaces);
 *  - a rigid rotation by 90 degrees gives zero stress and zero force to round-off (the
 *    strain-gradient term is objective: it reads the gradient of E = (F^T F - I) / 2);
 *  - with a clamp by images, the images move with minus their particles' displacement, and
 *    a displacement odd about the plane gives its exact F next to the plane as well. */
#define main generated_main
#include "quadratic_patch3d.c"
#undef main

#include "check.h"

static sph_sim sim;

/* u = A X + (X^T B_r X) / 2 per component r (B symmetric), its gradient at X into g. */
static void field(const double *x, const double A[9], const double B[3][9], double *u,
                  double *g)
{
    for (int r = 0; r < 3; r++) {
        u[r] = 0;
        for (int c = 0; c < 3; c++) {
            double bx = 0;
            for (int k = 0; k < 3; k++)
                bx += B[r][3 * c + k] * x[k];
            u[r] += A[3 * r + c] * x[c] + 0.5 * x[c] * bx;
            g[3 * r + c] = A[3 * r + c] + bx;
        }
    }
}

/* Imposes the field on body b (its images too: the clamp sets them) and runs its stress
 * pass; returns the largest |F - (I + grad u)| over the particles in front of x = xmin. */
static double impose(sph_body *b, const double A[9], const double B[3][9],
                     void (*pass)(sph_body *), double xmin)
{
    double g[9], worst = 0;
    for (int i = 0; i < b->n; i++)
        field(b->X + (size_t)i * 3, A, B, b->u + (size_t)i * 3, g);
    pass(b);
    for (int i = 0; i < b->n; i++) {
        if (b->X[(size_t)i * 3] < xmin)
            continue;
        field(b->X + (size_t)i * 3, A, B, (double[3]){0}, g);
        for (int k = 0; k < 9; k++)
            worst = fmax(worst, fabs(b->F[(size_t)i * 9 + k] - (g[k] + (k % 4 == 0))));
    }
    return worst;
}

int main(void)
{
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    const double A[9] = {0.02, -0.013, 0.007, 0.011, -0.017, 0.004, -0.006, 0.009, 0.015};
    /* second derivatives of about 10 per metre: 0.06 across the cube */
    const double B[3][9] = {{3, 1, -2, 1, 5, 0.5, -2, 0.5, -4},
                            {-1, 2, 0, 2, 3, -1, 0, -1, 6},
                            {4, -0.5, 1, -0.5, -2, 3, 1, 3, 2}};
    const double Z[3][9] = {{0}};
    check_close("affine: max |F - (I + A)|", impose(&sim.bodies[0], A, Z, cube_stress_pass, -1), 0,
                1e-12);
    check_close("quadratic: max |F - (I + grad u)|, corners and edges included",
                impose(&sim.bodies[0], A, B, cube_stress_pass, -1), 0, 1e-12);

    /* 90 degrees about y: x -> -z, z -> x */
    const double R[9] = {-1, 0, 1, 0, 0, 0, -1, 0, -1};
    sph_body *b = &sim.bodies[0];
    check_close("rotation 90 deg: max |F - R|", impose(b, R, Z, cube_stress_pass, -1), 0, 1e-12);
    cube_momentum_pass(b);
    double amax = 0, psi = 0;
    for (int i = 0; i < b->n; i++) {
        psi = fmax(psi, fabs(b->psi[i]));
        for (int k = 0; k < 3; k++)
            amax = fmax(amax, fabs(b->a[(size_t)i * 3 + k]));
    }
    /* scale: E / (rho dx) = 2e6 / (1000 * 1e-3) = 2e6 m/s^2 */
    check_close("rotation 90 deg: max |a| / (E / (rho dx))", amax / 2e6, 0, 1e-12);
    check_close("rotation 90 deg: max psi / E", psi / 2e6, 0, 1e-12);

    /* odd about x = 0 (u(-x, y, z) = -u(x, y, z)): linear in x times a function of y, z */
    const double Ao[9] = {0.01, 0, 0, -0.02, 0, 0, 0.015, 0, 0};
    const double Bo[3][9] = {{0, 2, -1, 2, 0, 0, -1, 0, 0},
                             {0, -3, 1, -3, 0, 0, 1, 0, 0},
                             {0, 1, 4, 1, 0, 0, 4, 0, 0}};
    check_close("clamp by images, odd field: max |F - (I + grad u)| in front of the plane",
                impose(&sim.bodies[1], Ao, Bo, held_stress_pass, 0), 0, 1e-12);
    check_close("clamp by images: 3 layers of 36 images", sim.bodies[1].nimages, 108, 0);
    sph_sim_free(&sim);
    return check_result();
}
