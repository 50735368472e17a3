/* derived_check.h — the body of test_derived2d.c and test_derived3d.c: each law's derived S
 * and psi, the standard library's svk and neohookean among them, against the hand-written
 * ones of handwritten.sph at 200 random deformation gradients (stretches of
 * up to 30 %, shears, rotations; in 2D the out-of-plane row and column of F are those of
 * plane strain).  S agrees to round-off: relative 1e-9 of the largest entry. */
#include "check.h"

typedef void (*Law)(const double F[9], double S[9], double *psi);

static double worst_difference(Law hand, Law derived)
{
    double worst = 0;
    unsigned seed = 7;
    for (int trial = 0; trial < 200; trial++) {
        double F[9];
        for (int k = 0; k < 9; k++) {
            seed = seed * 1103515245u + 12345u;
            const double u = (double)(seed >> 8) / 16777216.0 - 0.5; /* in [-0.5, 0.5) */
            F[k] = (k % 4 == 0) + 0.6 * u;
            if (DIM == 2 && (k / 3 == 1 || k % 3 == 1))
                F[k] = k == 4;
        }
        double Sh[9], Sd[9], ph, pd, scale = 0;
        hand(F, Sh, &ph);
        derived(F, Sd, &pd);
        for (int k = 0; k < 9; k++)
            scale = fmax(scale, fabs(Sh[k]));
        for (int k = 0; k < 9; k++)
            worst = fmax(worst, fabs(Sh[k] - Sd[k]) / scale);
        worst = fmax(worst, fabs(ph - pd) / fmax(fabs(ph), 1.0));
    }
    return worst;
}

int main(void)
{
    check_close("svk: derived S, psi vs hand-written (relative)",
                worst_difference(svk_hand_material, svk_derived_material), 0, 1e-9);
    check_close("neo-Hookean: derived S, psi vs hand-written (relative)",
                worst_difference(nh_hand_material, nh_derived_material), 0, 1e-9);
    check_close("svk as psi(C): S = 2 dpsi/dC vs hand-written (relative)",
                worst_difference(svk_hand_material, svk_of_c_material), 0, 1e-9);
    check_close("svk as psi(E): S = dpsi/dE vs hand-written (relative)",
                worst_difference(svk_hand_material, svk_of_e_material), 0, 1e-9);
    check_close("neo-Hookean as psi(C): S = 2 dpsi/dC vs hand-written (relative)",
                worst_difference(nh_hand_material, nh_of_c_material), 0, 1e-9);
    check_close("stdlib svk: S, psi vs hand-written (relative)",
                worst_difference(svk_hand_material, svk_lib_material), 0, 1e-9);
    check_close("stdlib neohookean: S, psi vs hand-written (relative)",
                worst_difference(nh_hand_material, nh_lib_material), 0, 1e-9);
    return check_result();
}
