/* J2 plasticity (stdlib/j2.sph, paper eq. 32-52) along a homogeneous uniaxial-strain path
 * (j2strain2d.sph): F = diag(1 + eps, 1, 1) at every particle.  The small-strain closed form
 * of this model: the deviatoric Mandel stress has sigma_eq = 2 mu (eps - 3/2 g) where g is
 * the plastic strain along x (N = diag(1, -1/2, -1/2) for this deviator; C_p = I + 2 g N),
 * the yield stress grows with ep = sqrt(2/3) g (eq. 44, 49), so in plastic loading
 *   g = (2 mu eps - sigma_y0) / (3 mu + sqrt(2/3) H),   sigma_xx = K eps + 2/3 sigma_eq.
 * Checked while loading to 0.5 % (yield at 0.195 %): the Cauchy sigma_xx against it within
 * 1 % (the finite-strain terms are O(eps)); ep against sqrt(2/3) g within 2 %; det C_p = 1
 * to 1e-10 (eq. 51); the state is the same at every particle; unloading is elastic: from the
 * second step after the reversal (the first still sees the last loading increment: forces
 * come before the update) ep does not change, and sigma_xx falls with the elastic slope
 * K + 4/3 mu (within 2 %: Cauchy stress against F - 1, finite-strain terms of 1 %).  The
 * plastic work wp (the law's dissipation) at the top equals the integral of sigma_eq dg,
 * sigma_y0 g + sqrt(2/3) H g^2 / 2, within 2 %, and the body's dissipated energy is its
 * volume integral.  The particle files carry ep. */
#define main generated_main
#include "j2strain2d.c"
#undef main

#include <string.h>

#include "check.h"
#include "io/vtu.h"

enum { D = 2, NS = 11 }; /* Cp (9), ep, wp */

static double det3(const double *A)
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    const double E = 200e9, nu = 0.3, sy = 300e6, H = 2e9;
    const double K = E / (3 * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    check_close("state values per particle (Cp: 9, ep, wp)", b->desc->nstate, NS, 0);
    double worst_s = 0, worst_ep = 0, worst_det = 0, spread = 0;
    double ep_top = 0, s_top = 0, eps_top = 0, s_end = 0, eps_end = 0, ep_unload = -1;
    double g_top = 0, wp_top = 0;
    int plastic_checks = 0, unload_steps = 0;
    while (sim.t < MODEL.t_end - 1e-12) {
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        MODEL.stress_output(&sim);
        const double eps = b->F[0] - 1; /* small-strain measure along x */
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < b->n; i++) {
            const double *st = b->state + (size_t)i * NS;
            worst_det = fmax(worst_det, fabs(det3(st) - 1));
            lo = fmin(lo, st[9]), hi = fmax(hi, st[9]);
        }
        spread = fmax(spread, hi - lo);
        const double sxx = b->sigma[0], ep = b->state[9];
        if (sim.t < 1e-3) {
            double g = fmax(0, (2 * mu * eps - sy) / (3 * mu + sqrt(2.0 / 3) * H));
            double seq = 2 * mu * (eps - 1.5 * g);
            const double want = K * eps + 2.0 / 3 * seq;
            worst_s = fmax(worst_s, fabs(sxx - want) / fabs(want));
            if (g > 1e-4) {
                worst_ep = fmax(worst_ep, fabs(ep / (sqrt(2.0 / 3) * g) - 1));
                plastic_checks++;
            }
            ep_top = ep, s_top = sxx, eps_top = eps, g_top = g, wp_top = b->state[10];
        } else {
            s_end = sxx, eps_end = eps;
            if (++unload_steps == 2)
                ep_unload = ep;
        }
    }
    printf("%ld steps; at the top: eps %.5g sigma_xx %.5g MPa ep %.5g; at the end: eps %.5g "
           "sigma_xx %.5g MPa ep %.5g\n",
           sim.step, eps_top, s_top * 1e-6, ep_top, eps_end, s_end * 1e-6, b->state[9]);
    check_close("loading: max |sigma_xx / closed form - 1|", worst_s, 0, 0.01);
    check_close("plastic steps checked", plastic_checks > 50, 1, 0);
    check_close("loading: max |ep / (sqrt(2/3) g) - 1|", worst_ep, 0, 0.02);
    check_close("max |det Cp - 1|", worst_det, 0, 1e-10);
    check_close("plastic work at the top / (sy g + sqrt(2/3) H g^2 / 2)",
                wp_top / (sy * g_top + 0.5 * sqrt(2.0 / 3) * H * g_top * g_top), 1, 0.02);
    check_close("dissipated energy of the body / (V wp)",
                sph_dissipated_energy(b) / (b->n * b->vol * b->state[10]), 1, 1e-9);
    check_close("spread of ep over the particles", spread, 0, 1e-12);
    check_close("unloading: ep unchanged (relative)", b->state[9] / ep_unload, 1, 1e-12);
    check_close("unloading slope / (K + 4/3 mu)",
                (s_top - s_end) / (eps_top - eps_end) / (K + 4.0 / 3 * mu), 1, 0.02);
    /* the law's scalar state goes to the particle files under its own name */
    char text[4096] = {0};
    FILE *f = NULL;
    if (sph_write_vtu("test_j2_state.vtu", b, sim.t) == 0 && (f = fopen("test_j2_state.vtu", "rb"))) {
        size_t got = fread(text, 1, sizeof text - 1, f);
        text[got] = 0;
        fclose(f);
        remove("test_j2_state.vtu");
    }
    check_close("VTU file has the state variable 'ep'", strstr(text, "Name=\"ep\"") != NULL, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
