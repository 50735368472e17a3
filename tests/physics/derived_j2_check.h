/* derived_j2_check.h — the body of test_derived_j2.c and test_derived_j2_2d.c: laws with
 * state written as their energy only (derived_j2.sph, derived_j2_2d.sph) against the
 * hand-written law (handwritten.sph's j2_written), and the standard library's j2 with it, at
 * 400 random deformations, each from a random state.
 *
 * A trial stretches a point from the initial state to a random F1 with the hand-written law
 * (its state then holds the plastic metric, ep and wp of one return), then moves it to F2 =
 * F1 + a random increment of 1e-5 to 3e-2: some trials flow again, some unload elastically.
 * At F2, from that state, the derived law must give the hand-written S (relative 1e-9 of
 * the largest entry: both are 2 dpsi/dC at the returned C_p, eq. 37-38, only written
 * differently) and the same state at the end (C_p, ep, wp: relative 1e-12).  Both branches
 * of the return must be met (at least 50 trials each).  The damage law (psi = (1 - d/2)
 * psi_svk, d = max(d, tr E)) has the closed form S = (1 - d/2)(lambda tr(E) I + 2 mu E) with
 * d its value at the end of the step (relative 1e-12; differentiated through d's update it
 * would have a term -psi_svk/2 I where d grows: at least 50 trials grow d, 50 keep it). */
#include "check.h"

typedef void (*StateLaw)(const double F[9], const double *st, double *st_new, double S[9],
                         double *psi);

enum { TRIALS = 400, NS = 11 };

static unsigned seed = 11;

static double uniform(void) /* in [-0.5, 0.5) */
{
    seed = seed * 1103515245u + 12345u;
    return (double)(seed >> 8) / 16777216.0 - 0.5;
}

/* A random F near I (entries perturbed by up to amp / 2); plane strain in 2D. */
static void random_F(double F[9], const double *base, double amp)
{
    for (int k = 0; k < 9; k++) {
        F[k] = (base ? base[k] : (k % 4 == 0)) + amp * uniform();
        if (DIM == 2 && (k / 3 == 1 || k % 3 == 1))
            F[k] = k == 4;
    }
}

static double rel_diff(const double *a, const double *b, int n, double floor)
{
    double scale = floor, diff = 0;
    for (int k = 0; k < n; k++) {
        scale = fmax(scale, fmax(fabs(a[k]), fabs(b[k])));
        diff = fmax(diff, fabs(a[k] - b[k]));
    }
    return diff / scale;
}

/* The derived J2 law against the hand-written one; *plastic, *elastic: the trials whose
 * second step flows or not. */
static double j2_difference(StateLaw hand, StateLaw derived, double *state_diff, int *plastic,
                            int *elastic)
{
    double worst = 0;
    *state_diff = 0, *plastic = 0, *elastic = 0;
    for (int t = 0; t < TRIALS; t++) {
        double F1[9], F2[9], S[9], Sh[9], Sd[9], psi, ph, pd;
        double st0[NS] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0}, st1[NS], sh[NS], sd[NS];
        random_F(F1, NULL, 0.4);
        hand(F1, st0, st1, S, &psi);
        random_F(F2, F1, pow(10, -5 + 3.5 * (uniform() + 0.5)));
        hand(F2, st1, sh, Sh, &ph);
        derived(F2, st1, sd, Sd, &pd);
        worst = fmax(worst, rel_diff(Sh, Sd, 9, 0));
        worst = fmax(worst, fabs(ph - pd) / fmax(fabs(ph), 1.0));
        *state_diff = fmax(*state_diff, rel_diff(sh, sd, NS, 1));
        if (sh[9] > st1[9])
            ++*plastic;
        else
            ++*elastic;
    }
    return worst;
}

/* The damage law against its closed form; *grows, *keeps: trials where d grows or not. */
static double damage_difference(StateLaw law, int *grows, int *keeps)
{
    const double lambda = 2e6, mu = 1e6;
    double worst = 0;
    *grows = 0, *keeps = 0;
    for (int t = 0; t < TRIALS; t++) {
        double F[9], E[9], S[9], want[9], psi, d1;
        const double d0 = 0.1 * (uniform() + 0.5);
        random_F(F, NULL, 0.4);
        law(F, &d0, &d1, S, &psi);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double c = 0;
                for (int k = 0; k < 3; k++)
                    c += F[3 * k + i] * F[3 * k + j];
                E[3 * i + j] = 0.5 * (c - (i == j));
            }
        const double trE = E[0] + E[4] + E[8], d = fmax(d0, trE);
        for (int k = 0; k < 9; k++)
            want[k] = (1 - 0.5 * d) * (lambda * trE * (k % 4 == 0) + 2 * mu * E[k]);
        worst = fmax(worst, rel_diff(S, want, 9, 0));
        worst = fmax(worst, fabs(d1 - d));
        if (trE > d0)
            ++*grows;
        else
            ++*keeps;
    }
    return worst;
}

int main(void)
{
    double state_diff, state_diff_c, state_diff_l;
    int plastic, elastic, plastic_c, elastic_c, plastic_l, elastic_l, grows, keeps;
    const double s = j2_difference(j2_hand_material, j2_derived_material, &state_diff, &plastic,
                                   &elastic);
    const double sc = j2_difference(j2_hand_material, j2_of_c_material, &state_diff_c,
                                    &plastic_c, &elastic_c);
    const double sl = j2_difference(j2_hand_material, j2_lib_material, &state_diff_l,
                                    &plastic_l, &elastic_l);
    check_close("J2 energy only: S, psi vs hand-written (relative)", s, 0, 1e-9);
    check_close("J2 energy only: Cp, ep, wp at the end (relative)", state_diff, 0, 1e-12);
    check_close("J2 as psi(C): S, psi vs hand-written (relative)", sc, 0, 1e-9);
    check_close("J2 as psi(C): Cp, ep, wp at the end (relative)", state_diff_c, 0, 1e-12);
    check_close("stdlib j2: S, psi vs hand-written (relative)", sl, 0, 1e-9);
    check_close("stdlib j2: Cp, ep, wp at the end (relative)", state_diff_l, 0, 1e-12);
    check_close("trials whose second step flows (at least 50)", plastic >= 50, 1, 0);
    check_close("trials whose second step is elastic (at least 50)", elastic >= 50, 1, 0);
    printf("  flowing %d, elastic %d of %d trials\n", plastic, elastic, TRIALS);
    const double dd = damage_difference(damage_material, &grows, &keeps);
    check_close("damage: S = (1 - d/2) S_svk at the end value of d (relative)", dd, 0, 1e-12);
    check_close("damage: trials where d grows (at least 50)", grows >= 50, 1, 0);
    check_close("damage: trials where d keeps its value (at least 50)", keeps >= 50, 1, 0);
    printf("  d grows in %d, keeps in %d of %d trials\n", grows, keeps, TRIALS);
    return check_result();
}
