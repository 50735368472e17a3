/* The cubic spline kernel end to end, on the generated code of cubic2d.sph:
 *  - the kernel's normalisation: at an interior particle the uncorrected moment
 *    sum_j V_j (X_j - X_i) (x) grad W_ij is the identity to the lattice's quadrature error,
 *    i.e. the correction L_i = M_i^-T is close to I (a wrong normalisation constant or
 *    gradient would show here, while the corrected tests below would hide it);
 *  - patch test: an affine displacement gives the exact F at every particle, SVK uniaxial
 *    strain its closed-form stress, a rigid rotation zero force;
 *  - a longitudinal pulse travels at the strip wave speed sqrt(E / ((1 - nu^2) rho)) =
 *    48.72 m/s between planes 0.1 m apart (as test_wave.c, within 3 %). */
#define main generated_main
#include "cubic2d.c"
#undef main

#include "check.h"

enum { D = 2 };
static sph_sim sim;

static double impose(sph_body *b, const double A[4])
{
    for (int i = 0; i < b->n; i++)
        for (int r = 0; r < 2; r++)
            b->u[(size_t)i * 2 + r] = A[2 * r] * b->X[(size_t)i * 2] + A[2 * r + 1] * b->X[(size_t)i * 2 + 1];
    sq_stress_pass(b);
    double worst = 0;
    for (int i = 0; i < b->n; i++) {
        const double *F = b->F + (size_t)i * 9;
        const double want[9] = {1 + A[0], 0, A[1], 0, 1, 0, A[2], 0, 1 + A[3]};
        for (int k = 0; k < 9; k++)
            worst = fmax(worst, fabs(F[k] - want[k]));
    }
    return worst;
}

static double mean_ux(const sph_body *b, int k)
{
    double s = 0;
    for (int q = 0; q < b->ms_count[k]; q++)
        s += b->u[(size_t)b->ms_list[k][q] * 2];
    return b->ms_count[k] ? s / b->ms_count[k] : 0;
}

static void patch(void)
{
    sph_body *b = &sim.bodies[0];
    /* particle (3.5, 3.5) mm: more than 2h = 2.83 mm from every edge */
    int centre = -1;
    for (int i = 0; i < b->n; i++)
        if (fabs(b->X[2 * i] - 3.5e-3) < 1e-9 && fabs(b->X[2 * i + 1] - 3.5e-3) < 1e-9)
            centre = i;
    const double *L = b->L + (size_t)centre * D * D;
    double dev = 0;
    for (int k = 0; k < 4; k++)
        dev = fmax(dev, fabs(L[k] - (k % 3 == 0)));
    printf("interior L = [%.6f %.6f; %.6f %.6f]\n", L[0], L[1], L[2], L[3]);
    /* 3 %: the lattice sum of the cubic spline at h = 1.41 dx is 1.6 % off the integral; a
     * wrong normalisation constant is off by tens of % (15 / (7 pi h^2), a common variant,
     * gives |L - I| = 0.34) */
    check_close("cubic: interior particle max |L - I|", dev, 0, 0.03);

    const double A[4] = {0.021, -0.013, 0.008, -0.017};
    check_close("cubic patch: max |F - (I + A)| over all particles", impose(b, A), 0, 1e-12);
    const double strain[4] = {0.1, 0, 0, 0};
    impose(b, strain);
    sq_stress_output(b);
    check_close("cubic patch: svk uniaxial strain 1.1: sigma11 [kPa] (485.49)", b->sigma[0] / 1e3, 485.49, 0.01);
    const double rot[4] = {-1, 1, -1, -1};
    check_close("cubic patch: rotation 90 deg: max |F - R|", impose(b, rot), 0, 1e-12);
    sq_momentum_pass(b);
    double amax = 0;
    for (int i = 0; i < b->n * 2; i++)
        amax = fmax(amax, fabs(b->a[i]));
    check_close("cubic patch: rotation 90 deg: max |a| / (E / (rho dx))", amax / 2e6, 0, 1e-12);
    /* back to rest for the dynamic part */
    for (int i = 0; i < b->n * 2; i++)
        b->u[i] = b->a[i] = 0;
}

static void wave(void)
{
    const sph_body *b = &sim.bodies[1];
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
    printf("%d steps; plateaus %.4g / %.4g m, half-way times %.6g / %.6g s\n", n, plateau0, plateau1, t0, t1);
    check_close("cubic wave: plateaus agree (same pulse passed both planes)", plateau1 / plateau0, 1, 0.02);
    /* 3 %: as test_wave.c (dispersion of the discrete pulse, half-way time detection) */
    check_close("cubic wave: speed [m/s] (closed form 48.72)", 0.1 / (t1 - t0), c, 0.03 * c);
}

int main(void)
{
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    check_close("the model uses the cubic spline kernel", MODEL.kernel == SPH_CUBIC, 1, 0);
    patch();
    wave();
    sph_sim_free(&sim);
    return check_result();
}
