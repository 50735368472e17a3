/* sim.c — a simulation without the program around it: set-up, time step, stepping. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "internal.h"

static void initial_speeds(sph_sim *s)
{
    for (int i = 0; i < s->nbodies; i++) {
        sph_body *b = &s->bodies[i];
        double v2max = 0;
        for (int p = 0; p < b->n * b->dim; p += b->dim) {
            double v2 = 0;
            for (int k = 0; k < b->dim; k++)
                v2 += b->v[p + k] * b->v[p + k];
            v2max = fmax(v2max, v2);
        }
        b->vmax2 = v2max;
        b->amax2 = 0;
    }
}

int sph_sim_init(sph_sim *s, const sph_model *m, int verbose)
{
    s->m = m;
    s->t = s->dt = 0;
    s->step = 0;
    s->contact = NULL;
    s->nbodies = m->nbodies;
    s->bodies = calloc((size_t)m->nbodies, sizeof(sph_body));
    for (int i = 0; i < m->nbodies; i++) {
        sph_body *b = &s->bodies[i];
        if (sph_body_setup(b, &m->bodies[i], m))
            return -1;
        if (verbose)
            printf("%s: body %s: %d particles, dx = %g m, %.1f neighbours each, c0 = %g m/s\n",
                   m->name, m->bodies[i].name, b->n, b->dx, (double)b->npairs / b->n, b->c0);
    }
    sph_contact_init(s);
    m->velocity_bcs(s, 0.0); /* initial conditions: the BCs at t = 0 */
    initial_speeds(s);
    return 0;
}

double sph_sim_stable_dt(const sph_sim *s)
{
    const sph_model *m = s->m;
    if (m->dt_fixed > 0)
        return m->dt_fixed;
    double dt = INFINITY;
    for (int i = 0; i < s->nbodies; i++) {
        const sph_body *b = &s->bodies[i];
        double dtv = b->h / (b->c0 + sqrt(b->vmax2));                        /* eq. 65 */
        double dta = b->amax2 > 0 ? sqrt(b->h / sqrt(b->amax2)) : INFINITY;  /* eq. 66 */
        dt = fmin(dt, fmin(dtv, dta));
    }
    dt = fmin(dt, sph_contact_dt(s)); /* the stiffest contact */
    return m->cfl * dt; /* eq. 64 */
}

void sph_sim_step(sph_sim *s, double dt)
{
    s->dt = dt;
    s->m->step(s, dt);
    s->t += dt;
    s->step++;
}

void sph_sim_free(sph_sim *s)
{
    sph_contact_free(s);
    for (int i = 0; i < s->nbodies; i++)
        sph_body_free(&s->bodies[i]);
    free(s->bodies);
    s->bodies = NULL;
    s->nbodies = 0;
}
