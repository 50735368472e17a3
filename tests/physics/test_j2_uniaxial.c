/* J2 plasticity (stdlib/j2.sph through the generated p_material of j2point3d.sph: E = 200 GPa,
 * nu = 0.3, sigma_y0 = 300 MPa, H = 2 GPa) along a homogeneous UNIAXIAL STRESS path:
 * F = diag(lam, lt, lt), eps = ln(lam) raised to 2 % in 400 increments, then lowered by 0.3 %
 * in 60; at each increment lt is solved by the secant method (every iterate calls the pure
 * material function from the same start-of-increment state) until the lateral Cauchy stress
 * |sigma_yy| < 1e-9 sigma_y0; then the state advances (st = st_new).
 * Closed form the model implies: F, C_p, C_e are diagonal, so C_e has the eigenvalues of
 * b_e = F C_p^-1 F^T and the Mandel deviator mu dev(J^-2/3 C_e) equals the Kirchhoff deviator
 * dev(tau) of the stress S; with tau_yy = tau_zz = 0, sigma_eq = |tau_xx| exactly.  The flow
 * direction N = 1.5 Mdev / sigma_eq = diag(1, -1/2, -1/2) and C_p grows by 2 dg N C_p (eq. 50),
 * so the axial plastic log strain eps_p grows by dg per step while ep grows by sqrt(2/3) dg
 * (eq. 49): ep = sqrt(2/3) eps_p.  On the yield surface tau = sigma_y0 + H ep
 * = sigma_y0 + H' eps_p with H' = sqrt(2/3) H, and with small elastic strains
 * (eps_e = eps - eps_p = tau / E) tau = J sigma_xx against eps follows
 *   elastic: tau = E eps up to tau = sigma_y0;
 *   plastic: tau = sigma_y0 + H' (eps - tau / E) = (sigma_y0 + H' eps) E / (E + H'),
 * tangent slope E H' / (E + H') (not E H / (E + H): ep is not the axial plastic strain).
 * Checks: first yield (the last elastic tau within one stress step E deps below sigma_y0, the
 * first plastic one within 0.5 % of it); the elastic secant slope at 0.1 % = E within 0.5 %
 * (neo-Hookean); the plastic slope between 1 % and 2 % = E H'/(E + H') within 1 % (and
 * E H/(E + H) is off by more);
 * tau at 2 % against the closed form within 0.5 %; ep there = sqrt(2/3) (eps - tau/E) within
 * 1 %; det C_p = 1 to 1e-10 and |sigma_yy|, |sigma_zz| <= 1e-6 sigma_y0 at every increment;
 * unloading is elastic: ep unchanged (1e-14) and the slope = E within 1 %. */
#define main generated_main
#include "j2point3d.c"
#undef main

#include "check.h"

enum { NS = 11, NLOAD = 400, NUNLOAD = 60 }; /* state: Cp (9), ep, wp */

static const double E = 200e9, SY = 300e6, H = 2e9;

static double det3(const double *A)
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

/* The Cauchy stress of F = diag(lam, lt, lt) from state st: its diagonal (F diagonal, so
 * sigma_ii = F_ii^2 S_ii / J); st_new gets the state after the step's return mapping. */
static void stress(double lam, double lt, const double *st, double *st_new, double sig[3])
{
    double F[9] = {lam, 0, 0, 0, lt, 0, 0, 0, lt}, S[9], psi;
    p_material(F, st, st_new, S, &psi);
    const double J = lam * lt * lt;
    sig[0] = lam * lam * S[0] / J, sig[1] = lt * lt * S[4] / J, sig[2] = lt * lt * S[8] / J;
}

/* Solves sigma_yy(lt) = 0 by the secant method from the guess lt; returns lt, with the
 * stress and the new state of the converged point. */
static double solve_lateral(double lam, double lt, const double *st, double *st_new, double sig[3])
{
    double l0 = lt, l1 = lt * (1 + 1e-6), s0, s1[3];
    stress(lam, l0, st, st_new, s1);
    s0 = s1[1];
    for (int it = 0; it < 60; it++) {
        stress(lam, l1, st, st_new, s1);
        if (fabs(s1[1]) < 1e-9 * SY || s1[1] == s0)
            break;
        const double l2 = l1 - s1[1] * (l1 - l0) / (s1[1] - s0);
        l0 = l1, s0 = s1[1], l1 = l2;
    }
    sig[0] = s1[0], sig[1] = s1[1], sig[2] = s1[2];
    return l1;
}

int main(void)
{
    const double Hs = sqrt(2.0 / 3.0) * H, slope_p = E * Hs / (E + Hs), slope_H = E * H / (E + H);
    const double deps = 0.02 / NLOAD;
    double st[NS], st_new[NS], sig[3], lt = 1;
    double tau[NLOAD + NUNLOAD + 1] = {0}, eps[NLOAD + NUNLOAD + 1] = {0};
    double maxlat = 0, maxdet = 0, ep_top = 0, ep_change = 0;
    int first = -1;
    for (int k = 0; k < NS; k++)
        st[k] = MODEL.bodies[0].state_init[k];
    for (int q = 1; q <= NLOAD + NUNLOAD; q++) {
        eps[q] = q <= NLOAD ? q * deps : 0.02 - (q - NLOAD) * 0.003 / NUNLOAD;
        const double lam = exp(eps[q]);
        /* guess: lateral strain -nu (elastic) or -1/2 (plastic) of the axial increment */
        lt = solve_lateral(lam, lt * exp(-0.4 * (eps[q] - eps[q - 1])), st, st_new, sig);
        tau[q] = lam * lt * lt * sig[0];
        maxlat = fmax(maxlat, fmax(fabs(sig[1]), fabs(sig[2])));
        for (int k = 0; k < NS; k++)
            st[k] = st_new[k];
        maxdet = fmax(maxdet, fabs(det3(st) - 1));
        if (first < 0 && st[9] > 0)
            first = q;
        if (q == NLOAD)
            ep_top = st[9];
        if (q > NLOAD)
            ep_change = fmax(ep_change, fabs(st[9] - ep_top));
        if (q % 40 == 0 || q == first || q == NLOAD + NUNLOAD)
            printf("step %3d  eps %.5f  tau %9.4f MPa  sigma_xx %9.4f MPa  lt %.7f  ep %.6g\n", q,
                   eps[q], tau[q] * 1e-6, sig[0] * 1e-6, lt, st[9]);
    }
    printf("first yield at step %d: tau %.4f MPa (step before: %.4f MPa)\n", first,
           first > 0 ? tau[first] * 1e-6 : 0, first > 0 ? tau[first - 1] * 1e-6 : 0);
    /* the step before is elastic and within one stress step E deps below sigma_y0: 0..1 */
    check_close("first yield: (sigma_y0 - tau(step before)) / (E deps)",
                first > 1 ? (SY - tau[first - 1]) / (E * deps) : -1, 0.5, 0.5);
    check_close("first yield: tau / sigma_y0", first > 0 ? tau[first] / SY : 0, 1, 5e-3);
    const int q1 = (int)(0.001 / deps + 0.5); /* eps = 0.1 % */
    check_close("elastic secant slope tau/eps at 0.1 % / E", tau[q1] / eps[q1] / E, 1, 5e-3);
    const int qa = NLOAD / 2, qb = NLOAD; /* eps = 1 % and 2 % */
    const double slope = (tau[qb] - tau[qa]) / (eps[qb] - eps[qa]);
    printf("plastic slope %.6g GPa: E H'/(E+H') %.6g GPa, E H/(E+H) %.6g GPa (%.1f %% off)\n",
           slope * 1e-9, slope_p * 1e-9, slope_H * 1e-9, 100 * (slope_H / slope - 1));
    check_close("plastic slope / (E H'/(E+H')), H' = sqrt(2/3) H", slope / slope_p, 1, 1e-2);
    check_close("unscaled E H/(E+H) would be off by > 1 %", fabs(slope / slope_H - 1) > 1e-2, 1, 0);
    const double tau_cf = (SY + Hs * eps[qb]) * E / (E + Hs);
    check_close("tau at 2 % / closed form", tau[qb] / tau_cf, 1, 5e-3);
    check_close("ep at 2 % / (sqrt(2/3) (eps - tau/E))", ep_top / (sqrt(2.0 / 3.0) * (eps[qb] - tau[qb] / E)),
                1, 1e-2);
    check_close("max |det Cp - 1| over all increments", maxdet, 0, 1e-10);
    check_close("max lateral |sigma_yy|, |sigma_zz| / sigma_y0", maxlat / SY, 0, 1e-6);
    check_close("unloading: max |ep - ep(top)|", ep_change, 0, 1e-14);
    const int qe = NLOAD + NUNLOAD;
    check_close("unloading slope / E", (tau[qe] - tau[qb]) / (eps[qe] - eps[qb]) / E, 1, 1e-2);
    return check_result();
}
