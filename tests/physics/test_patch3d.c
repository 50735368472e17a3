/* Patch tests on the generated code of patch3d.sph (3D): affine displacement gives the exact
 * F at every particle, the laws give their closed-form stresses, and a rigid rotation by 90
 * degrees gives zero stress and zero force to round-off. */
#define main generated_main
#include "patch3d.c"
#undef main

#include "check.h"

static sph_sim sim;

/* u = A X at every particle, then the stress pass; returns the largest |F - (I + A)|. */
static double impose(sph_body *b, const double A[9], void (*pass)(sph_body *))
{
    for (int i = 0; i < b->n; i++)
        for (int r = 0; r < 3; r++) {
            double s = 0;
            for (int c = 0; c < 3; c++)
                s += A[3 * r + c] * b->X[(size_t)i * 3 + c];
            b->u[(size_t)i * 3 + r] = s;
        }
    pass(b);
    double worst = 0;
    for (int i = 0; i < b->n; i++)
        for (int k = 0; k < 9; k++)
            worst = fmax(worst, fabs(b->F[(size_t)i * 9 + k] - (A[k] + (k % 4 == 0))));
    return worst;
}

static void diag_stretch(double A[9], double l1, double l2, double l3)
{
    for (int k = 0; k < 9; k++)
        A[k] = 0;
    A[0] = l1 - 1, A[4] = l2 - 1, A[8] = l3 - 1;
}

static void affine_exact(void)
{
    const double A[9] = {0.02, -0.013, 0.007, 0.011, -0.017, 0.004, -0.006, 0.009, 0.015};
    check_close("svk: max |F - (I + A)| over all particles", impose(&sim.bodies[0], A, cube_svk_stress_pass), 0, 1e-12);
    check_close("nh:  max |F - (I + A)| over all particles", impose(&sim.bodies[1], A, cube_nh_stress_pass), 0, 1e-12);
    check_close("lin: max |F - (I + A)| over all particles", impose(&sim.bodies[2], A, cube_lin_stress_pass), 0, 1e-12);
}

static void svk_uniaxial_stress(void)
{
    const sph_body *b = &sim.bodies[0];
    const double K = 3.25e6, mu = 0.715e6, l = 1.1;
    const double E = 9 * K * mu / (3 * K + mu), nu = (3 * K - 2 * mu) / (2 * (3 * K + mu));
    const double lt = sqrt(1 - nu * (l * l - 1)); /* S22 = 0: E22 = -nu E11 */
    double A[9], S[9], psi;
    diag_stretch(A, l, lt, lt);
    impose(&sim.bodies[0], A, cube_svk_stress_pass);
    cube_svk_material(b->F, S, &psi);
    check_close("svk uniaxial stress: P11 = E l (l^2 - 1) / 2 [Pa]", l * S[0], E * l * (l * l - 1) / 2, 0.05);
    check_close("svk uniaxial stress: P11 closed form 230.82 kPa", l * S[0] / 1e3, 230.82, 0.01);
    check_close("svk uniaxial stress: S22 = 0 [Pa]", S[4], 0, 1e-3);
}

static void nh_uniaxial_strain(double l, double s11, double s22)
{
    sph_body *b = &sim.bodies[1];
    double A[9];
    char what[96];
    diag_stretch(A, l, 1, 1);
    impose(b, A, cube_nh_stress_pass);
    cube_nh_stress_output(b);
    snprintf(what, sizeof what, "nh uniaxial strain %.1f: sigma11 [kPa] (every particle)", l);
    double worst = 0;
    for (int i = 0; i < b->n; i++)
        worst = fmax(worst, fabs(b->sigma[(size_t)i * 6] / 1e3 - s11));
    check_close(what, s11 + worst, s11, 0.01);
    snprintf(what, sizeof what, "nh uniaxial strain %.1f: sigma22 [kPa]", l);
    check_close(what, b->sigma[1] / 1e3, s22, 0.01);
    snprintf(what, sizeof what, "nh uniaxial strain %.1f: sigma33 = sigma22 [kPa]", l);
    check_close(what, b->sigma[2] / 1e3, s22, 0.01);
}

static void linear_user_law(void)
{
    sph_body *b = &sim.bodies[2];
    const double lam = 2e6, mu = 1e6, e = 0.01;
    double A[9], S[9], psi;
    diag_stretch(A, 1 + e, 1, 1);
    impose(b, A, cube_lin_stress_pass);
    cube_lin_material(b->F, S, &psi);
    check_close("user law (linear): S11 = (lambda + 2 mu) e / (1 + e) [Pa]", S[0],
                (lam + 2 * mu) * e / (1 + e), 1e-6);
    check_close("user law (linear): S22 = lambda e [Pa]", S[4], lam * e, 1e-6);
    check_close("user law (linear): psi = (lambda/2 + mu) e^2 [J/m^3]", psi, (lam / 2 + mu) * e * e, 1e-9);
}

static void rigid_rotation(void)
{
    sph_body *b = &sim.bodies[1];
    /* 90 degrees about y: x -> -z, z -> x.  A = R - I. */
    const double A[9] = {-1, 0, 1, 0, 0, 0, -1, 0, -1};
    double err = impose(b, A, cube_nh_stress_pass);
    check_close("rotation 90 deg: max |F - R|", err, 0, 1e-12);
    cube_nh_momentum_pass(b);
    double pmax = 0, amax = 0;
    for (int i = 0; i < b->n; i++) {
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                pmax = fmax(pmax, fabs(b->Q[SPH_TENSOR(i, r, c, 3, b->n)]));
        for (int k = 0; k < 3; k++)
            amax = fmax(amax, fabs(b->a[(size_t)i * 3 + k]));
    }
    /* scale: E / (rho dx) = 2e6 / (1000 * 1e-3) = 2e6 m/s^2 */
    check_close("rotation 90 deg: max |P L| / E", pmax / 2e6, 0, 1e-12);
    check_close("rotation 90 deg: max |a| / (E / (rho dx))", amax / 2e6, 0, 1e-12);
}

int main(void)
{
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    affine_exact();
    svk_uniaxial_stress();
    nh_uniaxial_strain(1.1, 395.62, 267.53);
    nh_uniaxial_strain(0.9, -451.01, -289.08);
    linear_user_law();
    rigid_rotation();
    sph_sim_free(&sim);
    return check_result();
}
