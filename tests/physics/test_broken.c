/* Eq. 63 and `restrict` (broken2d.sph).  The strip is stretched uniformly, so away from the
 * broken column and the restricted quarter s falls to the steady state of unload2d.sph
 * (about 0.5).  Checked:
 *  - a particle with s below the limit s_l = 0.1 carries no deformation (eq. 63): its F is
 *    exactly I, its strain energy and its stress exactly 0, while its neighbours are
 *    stretched;
 *  - the restricted particles (x0 < 10 mm) keep s >= 0.9999 the whole run, while the free
 *    ones are damaged below 0.6. */
#define main generated_main
#include "broken2d.c"
#undef main

#include "check.h"

enum { D = 2 };

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    int nbroken = 0;
    for (int i = 0; i < b->n; i++) /* break the column at x0 = 25.5 mm for good (H huge) */
        if (fabs(b->X[i * D] - 0.0255) < 0.25e-3)
            b->s[i] = 0.05, b->H[i] = 1e9, nbroken++;
    double fdev = 0, psi = 0, q = 0, s_restricted = 1, s_free = 1, fxx_free = 0;
    while (sim.t < MODEL.t_end - 1e-12) {
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        for (int i = 0; i < b->n; i++) {
            const double x0 = b->X[i * D];
            if (fabs(x0 - 0.0255) < 0.25e-3) {
                for (int k = 0; k < 9; k++)
                    fdev = fmax(fdev, fabs(b->F[9 * i + k] - (k % 4 == 0)));
                for (int r = 0; r < D; r++)
                    for (int c = 0; c < D; c++)
                        q = fmax(q, fabs(b->Q[SPH_TENSOR(i, r, c, D, b->n)]));
                psi = fmax(psi, fabs(b->psi[i]));
            } else if (x0 < 0.01)
                s_restricted = fmin(s_restricted, b->s[i]);
            else if (x0 > 0.03) {
                s_free = fmin(s_free, b->s[i]);
                fxx_free = fmax(fxx_free, b->F[9 * i]);
            }
        }
    }
    printf("%ld steps, %d broken particles; free F_xx up to %.6g, s down to %.6g\n", sim.step,
           nbroken, fxx_free, s_free);
    check_close("broken column: particles (one column of the 10-high strip)", nbroken, 10, 0);
    check_close("broken particles: max |F - I| (eq. 63)", fdev, 0, 0);
    check_close("broken particles: max |psi|", psi, 0, 0);
    check_close("broken particles: max |P L|", q, 0, 0);
    check_close("free particles stretched: F_xx - 1 > 1 %", fxx_free - 1 > 0.01, 1, 0);
    check_close("restricted particles: smallest s >= 0.9999", s_restricted >= 0.9999, 1, 0);
    check_close("free particles damaged: smallest s < 0.6", s_free < 0.6, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
