/* The standard library's Perzyna viscoplasticity (stdlib/perzyna.sph; model perzyna3d.sph:
 * mu = 80 GPa, K = 160 GPa, sigma_y = 300 MPa), called step by step:
 *  - eta -> 0 (1e-9 Pa s) is stdlib/j2 along a path of plastic deformations at uneven
 *    steps: S and psi to 1e-9 (1.6e-10 measured: the return's round-off, amplified where the
 *    flow is strong), the state to 1e-10;
 *  - a simple shear of 0.01 held from t = 0 (H = 2 GPa, eta = 2.42 MPa s): the overstress
 *    f = sigma_eq - (sigma_y + H ep) relaxes as the backward-Euler steps of
 *    df/dt = -f / t_r, t_r = eta / (3 mu + H sqrt(2/3)) = 1e-5 s, that is
 *    f_n = f_0 prod 1 / (1 + dt_k / t_r), to 1e-3 of f_0 (1.7e-5 measured: the finite
 *    strain), and the
 *    exponential within dt / t_r of it;
 *  - simple shear at a constant rate (H = 0), 1e3 and 3e3 1/s, to 8 t_r past yield: the
 *    overstress is eta times the plastic rate (the flow rule, to 1e-3; ep grows by sqrt(2/3)
 *    of it, eq. 49), and at the steady
 *    state all the deformation is plastic, sigma_eq = sigma_y + eta gamma_dot / sqrt(3), to
 *    5e-3 of the overstress (4e-4 and 9e-4 measured: the shear's finite strain);
 *  - the plastic work grows at every step.
 * sigma_eq is the von Mises stress of the Kirchhoff stress F S F^T, which is the Mandel
 * stress's the law returns with at small elastic strain. */
#define main generated_main
#include "perzyna3d.c"
#undef main

#include "check.h"
#include "tensor_check.h"

static const double MU = 80e9, SY = 300e6, H = 2e9, ETA = 2.42e6;
enum { NS = 11 }; /* Cp (9), ep, wp */

typedef void (*Law)(const double F[9], double dt, const double *st, double *st_new,
                    double S[9], double *psi);

static void at_rest(double *st)
{
    memset(st, 0, NS * sizeof *st);
    st[0] = st[4] = st[8] = 1;
}

/* Uneven steps between lo and hi, in a fixed order. */
static double uneven(int n, double lo, double hi)
{
    return lo + (hi - lo) * fmod(n * 0.6180339887498949, 1.0);
}

static void limit_is_j2(void)
{
    static const double M1[9] = {0.3, 0.2, -0.1, 0.05, -0.2, 0.15, -0.12, 0.08, 0.1};
    static const double M2[9] = {-0.1, 0.1, 0.2, -0.15, 0.25, 0.05, 0.1, -0.2, -0.3};
    double a[NS], b[NS], an[NS], bn[NS], worst = 0, worst_st = 0, ep = 0;
    at_rest(a), at_rest(b);
    for (int n = 0; n < 300; n++) {
        double F[9], Sa[9], Sb[9], pa, pb, smax = 0, d = 0;
        for (int k = 0; k < 9; k++)
            F[k] = (k % 4 == 0) + 0.03 * sin(0.05 * n) * M1[k] + 0.02 * sin(0.031 * n) * M2[k];
        vp_tiny_material(F, uneven(n, 1e-7, 3e-7), a, an, Sa, &pa);
        jref_material(F, b, bn, Sb, &pb);
        for (int k = 0; k < 9; k++)
            smax = fmax(smax, fabs(Sb[k])), d = fmax(d, fabs(Sa[k] - Sb[k]));
        worst = fmax(worst, fmax(d / smax, fabs(pa - pb) / fabs(pb)));
        for (int k = 0; k < NS; k++)
            worst_st = fmax(worst_st, fabs(an[k] - bn[k]) / fmax(fabs(bn[k]), 1e-3));
        memcpy(a, an, sizeof a), memcpy(b, bn, sizeof b);
        ep = bn[9];
    }
    printf("eta = 1e-9 Pa s against j2: ep reached %.4g\n", ep);
    check_close("eta -> 0: max rel. difference from j2 in S, psi", worst, 0, 1e-9);
    check_close("eta -> 0: max rel. difference from j2 in the state", worst_st, 0, 1e-10);
    check_close("eta -> 0: the path flows (ep > 0.01)", ep > 0.01, 1, 0);
}

static void held_shear(void)
{
    const double F[9] = {1, 0.01, 0, 0, 1, 0, 0, 0, 1};
    const double tr = ETA / (3 * MU + H * sqrt(2.0 / 3));
    double st[NS], sn[NS], S[9], psi, f0 = 0, discrete = 1, t = 0, worst = 0, worst_exp = 0;
    double dt_most = 0, least_work = INFINITY;
    at_rest(st);
    for (int n = 0; t < 5 * tr; n++) {
        const double dt = n == 0 ? 0 : uneven(n, 0.02 * tr, 0.3 * tr);
        t += dt;
        vp_material(F, dt, st, sn, S, &psi);
        least_work = fmin(least_work, sn[10] - st[10]);
        memcpy(st, sn, sizeof st);
        const double f = t3_mises(F, S) - (SY + H * st[9]);
        if (n == 0) {
            f0 = f;
            continue;
        }
        discrete /= 1 + dt / tr;
        dt_most = fmax(dt_most, dt);
        worst = fmax(worst, fabs(f - f0 * discrete) / f0);
        worst_exp = fmax(worst_exp, fabs(f - f0 * exp(-t / tr)) / f0);
    }
    printf("held shear 0.01: overstress %.4g Pa at t = 0, relaxation time %.4g s\n", f0, tr);
    check_close("held shear: max |f - f0 prod 1/(1 + dt/t_r)| / f0", worst, 0, 1e-3);
    check_close("held shear: max |f - f0 exp(-t/t_r)| / f0, over dt/t_r", worst_exp / (dt_most / tr), 0, 1);
    check_close("held shear: plastic work of every step >= 0", least_work >= 0, 1, 0);
}

/* Simple shear at rate gdot to 8 relaxation times past yield (H = 0). */
static void steady_shear(double gdot)
{
    const double tr = ETA / (3 * MU), dt = tr / 50;
    const double t_end = SY / sqrt(3.0) / MU / gdot + 8 * tr;
    double st[NS], sn[NS], S[9], psi, flow = 0, seq = 0, rate = 0;
    at_rest(st);
    for (int n = 0; n * dt < t_end; n++) {
        const double F[9] = {1, gdot * n * dt, 0, 0, 1, 0, 0, 0, 1};
        vp0_material(F, n == 0 ? 0 : dt, st, sn, S, &psi);
        rate = (sn[9] - st[9]) / dt / sqrt(2.0 / 3); /* (ep grows by sqrt(2/3) dg) */
        memcpy(st, sn, sizeof st);
        seq = t3_mises(F, S);
        flow = fabs(seq - SY - ETA * rate) / (ETA * rate); /* the flow rule at the step */
    }
    const double steady = SY + ETA * gdot / sqrt(3.0);
    char what[160];
    printf("shear at %.3g 1/s: sigma_eq %.6g Pa, closed form of the steady state %.6g Pa\n",
           gdot, seq, steady);
    snprintf(what, sizeof what, "shear at %g 1/s: |f - eta dep/dt| / (eta dep/dt)", gdot);
    check_close(what, flow, 0, 1e-3);
    snprintf(what, sizeof what, "shear at %g 1/s: |sigma_eq - steady| / overstress", gdot);
    check_close(what, fabs(seq - steady) / (steady - SY), 0, 5e-3);
}

int main(void)
{
    limit_is_j2();
    held_shear();
    steady_shear(1e3);
    steady_shear(3e3);
    return check_result();
}
