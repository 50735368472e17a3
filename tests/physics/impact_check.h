/* impact_check.h — what the 1D plate impact tests measure of their two strips (bodies 0 and
 * 1, driven by pistons at up[0], up[1]; two measurement planes each, 15 mm apart): the
 * planes' velocities and the pistons' work step by step, then the shock's speed from its
 * arrival at the planes and the jump conditions behind it.  Behind the shock the material
 * moves at u_p, so a plane's mean displacement grows as u_p (t - t_a) once the shock has
 * passed it at t_a; from the two planes' t_a, U_s = (x2 - x1) / (t_a2 - t_a1). */
#ifndef IMPACT_CHECK_H
#define IMPACT_CHECK_H

#include "check.h"

typedef struct {
    double prev[2][2], vel[2][2]; /* the planes' last mean displacement and its velocity */
    double work[2];               /* the pistons' work on their strips */
} impact_run;

/* After a step of length dt: the pistons' work (their force -m a times their velocity, on
 * the particles whose x velocity is held) and the planes' velocities. */
static void impact_step(const sph_sim *sim, impact_run *r, const double up[2], double dt)
{
    for (int q = 0; q < 2; q++) {
        const sph_body *b = &sim->bodies[q];
        for (int i = 0; i < b->nown; i++)
            if (b->fix[i] & 1)
                r->work[q] -= dt * b->mass * b->a[i * 2] * up[q];
        for (int k = 0; k < 2; k++) {
            double m[6];
            sph_measure(b, k, m);
            r->vel[q][k] = (m[0] - r->prev[q][k]) / dt, r->prev[q][k] = m[0];
        }
    }
}

/* Strip q at the end (its stress output made): the shock speed against the Hugoniot's
 * c0 + s u_p, the velocity behind it against u_p and -sigma_xx behind (the mean over the
 * particles between 3 and 8 mm, long shocked) against the momentum jump rho0 U_s u_p, each
 * within 2 %. */
static void impact_jump_checks(const sph_sim *sim, const impact_run *r, int q, double up,
                               double c0, double s, double rho0)
{
    const sph_body *b = &sim->bodies[q];
    double ta[2];
    for (int k = 0; k < 2; k++)
        ta[k] = sim->t - r->prev[q][k] / up;
    const double us = 15e-3 / (ta[1] - ta[0]), want = c0 + s * up;
    double sxx = 0;
    int nb = 0;
    for (int i = 0; i < b->nown; i++)
        if (b->X[i * 2] > 3e-3 && b->X[i * 2] < 8e-3)
            sxx -= b->sigma[(size_t)i * 6], nb++;
    sxx /= nb;
    printf("u_p %g m/s: shock arrivals %.4g and %.4g us, U_s = %.6g m/s (Hugoniot %.6g); "
           "the planes' velocities %.5g, %.5g m/s; the stress behind %.4g Pa against "
           "rho0 U_s u_p %.4g Pa\n", up, ta[0] * 1e6, ta[1] * 1e6, us, want, r->vel[q][0],
           r->vel[q][1], sxx, rho0 * us * up);
    char what[128];
    snprintf(what, sizeof what, "u_p %g: U_s / (c0 + s u_p)", up);
    check_close(what, us / want, 1, 0.02);
    for (int k = 0; k < 2; k++) {
        snprintf(what, sizeof what, "u_p %g: velocity behind the shock / u_p (plane %d)", up,
                 k + 1);
        check_close(what, r->vel[q][k] / up, 1, 0.02);
    }
    snprintf(what, sizeof what, "u_p %g: -sigma_xx behind / (rho0 U_s u_p)", up);
    check_close(what, sxx / (rho0 * us * up), 1, 0.02);
}

#endif
