/* J2 plasticity (stdlib/j2.sph through the generated p_material of j2point3d.sph: E = 200 GPa,
 * nu = 0.3, sigma_y0 = 300 MPa, H = 2 GPa) under SIMPLE SHEAR, F = I + g e_x (x) e_y, with g
 * raised from 0 to 0.5 in N increments and lowered to 0.3 with the same increment (elastic
 * unloading, then reverse flow).  Each increment calls p_material from the start-of-increment
 * state and accepts st_new.
 * Energy balance: the stress work per unit reference volume W = int 1/2 S : dC must equal the
 * stored energy change psi(end) - psi(0) plus the plastic work wp(end).  It holds because the
 * flow dC_p = 2 dg N C_p removes -dpsi/dC_p : dC_p = dg tr(Mdev N) = dg sigma_eq from psi
 * exactly when sigma_eq = sqrt(3/2 tr(Mdev Mdev)).  Simple shear is non-coaxial: C and C_p do
 * not commute, so Mdev = mu dev(J^-2/3 C C_p^-1) is not symmetric and the Frobenius form
 * sqrt(3/2 Mdev : Mdev) is larger; wp would then exceed the energy the return removes.
 * W is summed by the trapezoid rule, 1/2 (S_old + S_new)/2 : (C_new - C_old), where S is the
 * stress returned for the new F after that step's return mapping.  The balance is reported at
 * N = 500 and checked at N = 2000 (relative 1e-3 of W) to show the mismatch is discretisation.
 * Also: the path yielded (ep > 0.1 at the end), det C_p = 1 to 1e-10 at every increment, and
 * wp never decreases (by more than 1e-12 relative). */
#define main generated_main
#include "j2point3d.c"
#undef main

#include "check.h"

enum { NS = 11 }; /* state: Cp (9), ep, wp */

static const double GMAX = 0.5, GEND = 0.3;

typedef struct {
    double W, dpsi, wp, ep; /* stress work, psi(end) - psi(0), plastic work, ep at the end */
    double maxdet, wp_drop; /* max |det Cp - 1|, largest relative decrease of wp */
} Balance;

static double det3(const double *A)
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

/* C = F^T F for F = I + g e_x (x) e_y */
static void shear_C(double g, double C[9])
{
    const double c[9] = {1, g, 0, g, 1 + g * g, 0, 0, 0, 1};
    for (int k = 0; k < 9; k++)
        C[k] = c[k];
}

/* The shear path with n loading increments; returns the energy balance. */
static Balance shear_path(int n)
{
    const double dg = GMAX / n;
    const int nback = (int)((GMAX - GEND) / dg + 0.5), total = n + nback;
    double st[NS], st_new[NS], F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, S[9], S_new[9], C[9],
        C_new[9], psi0, psi;
    Balance b = {0};
    for (int k = 0; k < NS; k++)
        st[k] = MODEL.bodies[0].state_init[k];
    p_material(F, st, st_new, S, &psi0); /* undeformed: S = 0, psi = 0 */
    shear_C(0, C);
    psi = psi0;
    for (int q = 1; q <= total; q++) {
        const double g = q <= n ? q * dg : GMAX - (q - n) * dg;
        F[1] = g;
        shear_C(g, C_new);
        p_material(F, st, st_new, S_new, &psi);
        for (int k = 0; k < 9; k++)
            b.W += 0.25 * (S[k] + S_new[k]) * (C_new[k] - C[k]);
        b.wp_drop = fmax(b.wp_drop, (st[10] - st_new[10]) / fmax(fabs(st[10]), 1e-300));
        for (int k = 0; k < NS; k++)
            st[k] = st_new[k];
        for (int k = 0; k < 9; k++)
            S[k] = S_new[k], C[k] = C_new[k];
        b.maxdet = fmax(b.maxdet, fabs(det3(st) - 1));
    }
    b.dpsi = psi - psi0, b.wp = st[10], b.ep = st[9];
    return b;
}

static double mismatch(Balance b)
{
    return (b.W - b.dpsi - b.wp) / b.W;
}

static void report(int n, Balance b)
{
    printf("N = %4d: W %.9g J/m^3  psi(end)-psi(0) %.9g  wp %.9g  ep %.6g  (W - dpsi - wp)/W %.3e\n",
           n, b.W, b.dpsi, b.wp, b.ep, mismatch(b));
}

int main(void)
{
    const Balance coarse = shear_path(500), fine = shear_path(2000);
    report(500, coarse);
    report(2000, fine);
    check_close("N = 2000: (W - (psi(end) - psi(0)) - wp(end)) / W", mismatch(fine), 0, 1e-3);
    check_close("the path yielded: ep(end) > 0.1", fine.ep > 0.1, 1, 0);
    check_close("max |det Cp - 1| over all increments", fine.maxdet, 0, 1e-10);
    check_close("largest relative decrease of wp", fmax(fine.wp_drop, 0), 0, 1e-12);
    return check_result();
}
