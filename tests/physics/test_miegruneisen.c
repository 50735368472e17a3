/* 1D plate impacts with the Mie-Grueneisen equation of state (mgimpact2d.sph: copper,
 * stdlib/miegruneisen with c0 = 3940 m/s, s = 1.49, Gamma0 = 2, pistons at u_p = 200 and
 * 1000 m/s).  Behind a steady shock the material's internal energy is the Hugoniot's
 * E_H = p_H eta / 2 (Rankine-Hugoniot), of which the Hugoniot energy U(eta) is elastic and
 * the rest, E_H - U, the shock's entropy: the artificial viscosity's heat (with the small
 * plastic work).  Checked, over the particles between 3 and 8 mm, long shocked:
 *  - at every particle, the law's pressure (-tr sigma / 3) against the Mie-Grueneisen
 *    formula p_H + Gamma0 (U + E_th - E_H) at its compression and its thermal energy
 *    E_th = B exp(-Gamma0 J) (1e-9 of p_H: the derived stress at the held state);
 *  - the heat q + wp against E_H - U at each particle's compression, in the strong shock
 *    (3 %; the weak one's, third order in the compression, is printed: its viscosity heats
 *    it some 2.4 times as much, which moves its pressure by 0.3 %);
 *  - the pressure against the Hugoniot's p_H at each particle's compression (2 %): the
 *    thermal pressure Gamma0 (U + E_th - E_H) cancels where the heat is the Hugoniot's;
 *  - the shock speed (from the arrivals at two planes) against c0 + s u_p, the velocity
 *    behind it against u_p and -sigma_xx behind against rho0 U_s u_p (2 %), as the shock
 *    law's test_plateimpact.c (impact_check.h);
 * and over the whole run, the heat given to the particles, sum V q, against the energy the
 * body's viscosity dissipated (energies.csv's column), to round-off: each pair's heat is
 * split between its two particles, none lost or counted twice. */
#define main generated_main
#include "mgimpact2d.c"
#undef main

#include <omp.h>
#include <string.h>

#include "impact_check.h"

static const double C0 = 3940, S = 1.49, G0 = 2.0, RHO0 = 8930, UP[2] = {200, 1000};

/* kinetic + strain energy + the heat (plastic and viscous): energies.csv's total */
static double energy(const sph_body *b)
{
    double strain, kinetic;
    sph_body_energies(b, &strain, &kinetic);
    return strain + kinetic + sph_dissipated_energy(b) + b->visc_dissipated;
}

/* the state value of the law's scalar named name */
static int slot(const sph_body *b, const char *name)
{
    for (int k = 0; k < b->desc->nstate; k++)
        if (b->desc->state_names[k] && !strcmp(b->desc->state_names[k], name))
            return k;
    return -1;
}

int main(void)
{
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0) || sim.nbodies != 2)
        return 1;
    impact_run run = {0};
    double e0[2];
    for (int q = 0; q < 2; q++)
        e0[q] = energy(&sim.bodies[q]);
    while (sim.t < MODEL.t_end - 1e-15) {
        const double dt = fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t);
        sph_sim_step(&sim, dt);
        impact_step(&sim, &run, UP, dt);
    }
    MODEL.stress_output(&sim);
    const double K = 138.6e9; /* the model's bulk (rho0 c0^2 to 2e-4) */
    for (int q = 0; q < 2; q++) {
        const sph_body *b = &sim.bodies[q];
        const double up = UP[q];
        const int ns = b->desc->nstate, kq = b->desc->vheat - 1, kw = b->desc->dissipation - 1;
        const int kb = slot(b, "B"), kh = slot(b, "H");
        if (kq != slot(b, "q") || kw != slot(b, "wp") || kb < 0 || kh < 0)
            return 1;
        char what[128];
        /* the heat of every particle against the body's viscous dissipation, and the energy
         * gained against the piston's work */
        double heat = 0;
        for (int i = 0; i < b->nown; i++)
            heat += b->state[(size_t)i * ns + kq];
        heat *= b->mass / b->rho0;
        snprintf(what, sizeof what, "u_p %g: sum V q / viscous energy dissipated", up);
        check_close(what, heat / b->visc_dissipated, 1, 1e-10);
        snprintf(what, sizeof what, "u_p %g: energy gained / the piston's work", up);
        check_close(what, (energy(b) - e0[q]) / run.work[q], 1, 1e-3);
        /* behind the shock, between 3 and 8 mm: the pressure against p_H and the formula,
         * the heat against E_H - U, each at the particle's own compression */
        double p = 0, pH = 0, h = 0, hH = 0, eta = 0, mg = 0;
        int nb = 0;
        for (int i = 0; i < b->nown; i++) {
            if (b->X[i * 2] <= 3e-3 || b->X[i * 2] >= 8e-3)
                continue;
            const double *sg = b->sigma + (size_t)i * 6, *st = b->state + (size_t)i * ns;
            const double e = 1 - sph_det3(b->F + (size_t)i * 9), y = 1 - S * e;
            const double ph = K * e / (y * y), U = K / (S * S) * (log(y) + 1 / y - 1);
            /* E_th as the output's evaluation of the law has it: B with the last step's heat */
            const double Eth = st[kb] * exp(-G0 * (1 - e)) + st[kq] + st[kw] - st[kh];
            const double pi = -(sg[0] + sg[1] + sg[2]) / 3;
            mg = fmax(mg, fabs(pi - (ph + G0 * (U + Eth - 0.5 * ph * e))) / ph);
            p += pi;
            pH += ph;
            h += st[kq] + st[kw];
            hH += 0.5 * ph * e - U;
            eta += e;
            nb++;
        }
        printf("u_p %g m/s behind the shock: compression %.4g, pressure %.4g Pa against p_H "
               "%.4g Pa, heat %.4g J/m^3 against E_H - U %.4g J/m^3\n", up, eta / nb, p / nb,
               pH / nb, h / nb, hH / nb);
        snprintf(what, sizeof what, "u_p %g: largest |p - p_MG| / p_H behind", up);
        check_close(what, mg, 0, 1e-9);
        if (up > 500) {
            snprintf(what, sizeof what, "u_p %g: heat behind / (E_H - U)", up);
            check_close(what, h / hH, 1, 0.03);
        }
        snprintf(what, sizeof what, "u_p %g: pressure behind / p_H", up);
        check_close(what, p / pH, 1, 0.02);
        impact_jump_checks(&sim, &run, q, up, C0, S, RHO0);
    }
    sph_sim_free(&sim);
    return check_result();
}
