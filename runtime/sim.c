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

/* The smallest eigenvalue of the symmetric 3x3 matrix C (trigonometric solution of the
 * characteristic cubic; only a time-step bound uses it, so a few ulps do not matter). */
static double sym3_eigmin(const double C[9])
{
    const double off = C[1] * C[1] + C[2] * C[2] + C[5] * C[5];
    const double q = (C[0] + C[4] + C[8]) / 3.0;
    const double d0 = C[0] - q, d1 = C[4] - q, d2 = C[8] - q;
    const double p = sqrt((d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off) / 6.0);
    if (p <= 1e-14 * fabs(q))
        return q; /* a multiple of I */
    const double b0 = d0 / p, b1 = d1 / p, b2 = d2 / p, b01 = C[1] / p, b02 = C[2] / p,
                 b12 = C[5] / p;
    const double r = 0.5 * (b0 * (b1 * b2 - b12 * b12) - b01 * (b01 * b2 - b12 * b02) +
                            b02 * (b01 * b12 - b1 * b02));
    const double phi = acos(fmax(-1.0, fmin(1.0, r))) / 3.0;
    return q + 2.0 * p * cos(phi + 2.0943951023931957); /* + 2 pi / 3: the smallest root */
}

/* The smallest principal stretch of body b: min over particles of sqrt(eigmin(F^T F)). */
static double stretch_min(const sph_body *b)
{
    double l2 = INFINITY;
#pragma omp parallel for reduction(min : l2)
    for (int i = 0; i < b->n; i++) {
        const double *F = b->F + 9 * (size_t)i;
        double C[9];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                C[3 * r + c] = F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c];
        l2 = fmin(l2, sym3_eigmin(C));
    }
    return b->n ? sqrt(fmax(l2, 0.0)) : 1.0;
}

double sph_sim_stretch(const sph_sim *s)
{
    double lam = 1.0;
    for (int i = 0; i < s->nbodies; i++)
        lam = fmin(lam, stretch_min(&s->bodies[i]));
    return lam;
}

double sph_sim_stable_dt(sph_sim *s)
{
    const sph_model *m = s->m;
    if (m->dt_fixed > 0)
        return m->dt_fixed;
    double dt = INFINITY;
    s->stretch_min = 1.0;
    for (int i = 0; i < s->nbodies; i++) {
        const sph_body *b = &s->bodies[i];
        /* timestep stretch: eq. 65 on the current spacing along the most compressed
         * direction, lambda_min h: the reference wave speed grows like 1/lambda_min */
        const double lam = m->dt_stretch ? fmin(stretch_min(b), 1.0) : 1.0;
        s->stretch_min = fmin(s->stretch_min, lam);
        double dtv = lam * b->h / (b->c0 + sqrt(b->vmax2));                  /* eq. 65 */
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
