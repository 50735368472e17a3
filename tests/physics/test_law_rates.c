/* A law that reads the rate of F (rates3d.sph) on bodies whose every particle's velocity is
 * prescribed, stepped a few times; at every step and every particle, what the law read (its
 * state after the step's stress pass):
 *  - the homogeneous flow v = G X: Fdot = G (the corrected gradient is exact for a linear
 *    field), and the equivalent rate sqrt(2/3 D:D), D = sym(G F^-1) with the particle's F,
 *    both as the law computes it from Edot = (Fdot^T F + F^T Fdot)/2 in C's metric and from D
 *    itself: to 1e-10 of the rate;
 *  - the rigid rotation v = W (x - c) about z: Fdot = W F, and the rate of deformation is
 *    zero (Edot = F^T sym(W) F = 0: a spinning body does not strain at any rate), to 1e-10 of
 *    |W|.
 * With -DTWO_D, rates2d.sph: the same in plane strain (the rotation about y). */
#ifdef TWO_D /* rates2d.sph: the same in the x-z plane (plane strain) */
#define MODEL_C "rates2d.c"
#else
#define MODEL_C "rates3d.c"
#endif
#define main generated_main
#include MODEL_C
#undef main

#include <omp.h>

#include "check.h"
#include "tensor_check.h"

#ifdef TWO_D
static const double G[9] = {30, 0, 20, 0, 0, 0, 5, 0, -25};
static const double W[9] = {0, 0, -400, 0, 0, 0, 400, 0, 0};
#else
static const double G[9] = {30, 20, 0, 0, -10, 15, 5, 0, -25};
static const double W[9] = {0, -400, 0, 400, 0, 0, 0, 0, 0};
#endif
enum { NS = 11 }; /* Fr[9], er, dr */

/* sqrt(2/3 D:D), D = sym(L), L = Fdot F^-1. */
static double equivalent_rate(const double Fdot[9], const double F[9])
{
    double Fi[9], L[9], dd = 0;
    t3_inv(F, Fi);
    t3_mul(Fdot, Fi, L);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            const double d = 0.5 * (L[r * 3 + c] + L[c * 3 + r]);
            dd += d * d;
        }
    return sqrt(2.0 / 3 * dd);
}

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0) || sim.nbodies != 2)
        return 1;
    double fdot_err[2] = {0}, rate_err = 0, rate_most = 0, spin_rate = 0, stretch_most = 0;
    while (sim.t < MODEL.t_end - 1e-15) {
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        for (int k = 0; k < 2; k++) {
            const sph_body *b = &sim.bodies[k];
            for (int i = 0; i < b->nown; i++) {
                const double *F = b->F + (size_t)i * 9, *st = b->state + (size_t)i * NS;
                double want[9];
                if (k == 0)
                    memcpy(want, G, sizeof want);
                else
                    t3_mul(W, F, want);
                for (int c = 0; c < 9; c++)
                    fdot_err[k] = fmax(fdot_err[k], fabs(st[c] - want[c]) / (k ? 400 : 30));
                if (k == 0) {
                    const double rate = equivalent_rate(G, F);
                    rate_err = fmax(rate_err, fmax(fabs(st[9] - rate), fabs(st[10] - rate)) / rate);
                    rate_most = fmax(rate_most, rate);
                    stretch_most = fmax(stretch_most, fabs(F[0] - 1));
                } else {
                    spin_rate = fmax(spin_rate, fmax(st[9], st[10]) / 400);
                }
            }
        }
    }
    printf("after %ld steps (t = %.3g s): F_xx - 1 up to %.3g; equivalent rate up to %.4g 1/s\n",
           sim.step, sim.t, stretch_most, rate_most);
    check_close("v = G X: max |Fdot - G| / |G|", fdot_err[0], 0, 1e-10);
    check_close("v = G X: max |rate - sqrt(2/3 D:D)| / rate (Edot and D)", rate_err, 0, 1e-10);
    check_close("rigid rotation: max |Fdot - W F| / |W|", fdot_err[1], 0, 1e-10);
    check_close("rigid rotation: largest rate / |W| (no deformation)", spin_rate, 0, 1e-10);
    sph_sim_free(&sim);
    return check_result();
}
