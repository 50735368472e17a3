/* derived_tension_check.h — the body of test_derived_tension2d.c and _3d.c: each fracture
 * body's law, whose tension block gives psi+ only (S+ derived through pos or neg), and
 * stdlib svk's, against svk_written's, whose S+ = lambda max(tr E, 0) I + 2 mu pos(E) is
 * written (eq. 11, 17), at
 * 200 random deformation gradients (stretches of up to 30 %, shears, rotations, a quarter
 * of them compressed by 15 % and a quarter stretched by 15 %; in 2D the out-of-plane row
 * and column of F are those of plane strain).  Compared: S+ = S(s = 1) - S(s = 0), the
 * degraded S = s^2 S+ + S- (eq. 18) at s = 0, 1 and a random s, relative to the largest
 * entry of S; psi+ and the degraded psi (eq. 7) relative to psi.  Round-off: 1e-9. */
#include "check.h"

typedef void (*Law)(const double F[9], double s, double S[9], double *psi, double *psip);

typedef struct {
    double splus, degraded, energy;
} Worst;

/* The signs of the principal strains of F (in-plane ones in 2D): counted into kinds[0]
 * (all compressive), kinds[1] (mixed), kinds[2] (all tensile). */
static void count_kind(const double F[9], int kinds[3])
{
    double E[9], lam[3], Q[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            E[3 * i + j] = -0.5 * (i == j);
            for (int k = 0; k < 3; k++)
                E[3 * i + j] += 0.5 * F[3 * k + i] * F[3 * k + j];
        }
    sph_sym_eig3(E, lam, Q);
    int pos = 0, neg = 0;
    for (int k = 0; k < 3; k++) { /* the out-of-plane strain of plane strain is 0 */
        pos += lam[k] > 1e-12;
        neg += lam[k] < -1e-12;
    }
    kinds[!pos ? 0 : !neg ? 2 : 1]++;
}

static void random_F(unsigned *seed, int trial, double F[9])
{
    const double scale = trial % 4 == 1 ? 0.85 : trial % 4 == 2 ? 1.15 : 1.0;
    for (int k = 0; k < 9; k++) {
        *seed = *seed * 1103515245u + 12345u;
        const double u = (double)(*seed >> 8) / 16777216.0 - 0.5; /* in [-0.5, 0.5) */
        F[k] = scale * ((k % 4 == 0) + 0.6 * u);
        if (DIM == 2 && (k / 3 == 1 || k % 3 == 1))
            F[k] = k == 4;
    }
}

static Worst worst_difference(Law hand, Law derived, int kinds[3])
{
    Worst w = {0, 0, 0};
    unsigned seed = 7;
    for (int trial = 0; trial < 200; trial++) {
        double F[9];
        random_F(&seed, trial, F);
        if (kinds)
            count_kind(F, kinds);
        seed = seed * 1103515245u + 12345u;
        const double svals[3] = {1.0, 0.0, (double)(seed >> 8) / 16777216.0};
        double Sh[3][9], Sd[3][9], ph[3], pd[3], pph[3], ppd[3], scale = 0;
        for (int q = 0; q < 3; q++) {
            hand(F, svals[q], Sh[q], &ph[q], &pph[q]);
            derived(F, svals[q], Sd[q], &pd[q], &ppd[q]);
        }
        for (int k = 0; k < 9; k++)
            scale = fmax(scale, fabs(Sh[0][k]));
        for (int k = 0; k < 9; k++) {
            const double sp_h = Sh[0][k] - Sh[1][k], sp_d = Sd[0][k] - Sd[1][k];
            w.splus = fmax(w.splus, fabs(sp_h - sp_d) / scale);
            for (int q = 0; q < 3; q++)
                w.degraded = fmax(w.degraded, fabs(Sh[q][k] - Sd[q][k]) / scale);
        }
        const double escale = fmax(fabs(ph[0]), 1e-300);
        for (int q = 0; q < 3; q++)
            w.energy = fmax(w.energy, fmax(fabs(ph[q] - pd[q]), fabs(pph[q] - ppd[q])) / escale);
    }
    return w;
}

static void check_law(const char *name, Law derived)
{
    const Worst w = worst_difference(svk_hand_material, derived, NULL);
    char what[3][128];
    snprintf(what[0], sizeof what[0], "%s: S+ vs svk's written S+ (rel.)", name);
    snprintf(what[1], sizeof what[1], "%s: s^2 S+ + S- at s = 0, 1, random (rel.)", name);
    snprintf(what[2], sizeof what[2], "%s: psi+ and degraded psi (rel.)", name);
    check_close(what[0], w.splus, 0, 1e-9);
    check_close(what[1], w.degraded, 0, 1e-9);
    check_close(what[2], w.energy, 0, 1e-9);
}

int main(void)
{
    int kinds[3] = {0, 0, 0};
    worst_difference(svk_hand_material, svk_hand_material, kinds);
    check_close("samples with all principal strains compressive", kinds[0] >= 10, 1, 0);
    check_close("samples with principal strains of both signs", kinds[1] >= 10, 1, 0);
    check_close("samples with all principal strains tensile", kinds[2] >= 10, 1, 0);
    printf("(%d compressive, %d mixed, %d tensile)\n", kinds[0], kinds[1], kinds[2]);
    check_law("S written, psi+ only", svk_tp_b_material);
    check_law("psi and psi+ only", svk_all_b_material);
    check_law("psi+ = psi - psi-, through neg", svk_neg_b_material);
    check_law("psi(E) and psi+ only", svk_of_e_b_material);
    check_law("stdlib svk", svk_lib_material);
    return check_result();
}
