/* contact_checks.h — measurements shared by the tests of scenes with contact: the whole
 * energy budget, the total momentum and the closest approach of two bodies. */
#ifndef SPH_TEST_CONTACT_CHECKS_H
#define SPH_TEST_CONTACT_CHECKS_H

#include <math.h>

#include "sphrt.h"

/* Kinetic + strain + plastic work + viscous dissipation of every body, plus the energy
 * stored in and dissipated by the contacts. */
static double budget_energy(const sph_sim *s)
{
    double e = 0, stored, dissipated;
    for (int k = 0; k < s->nbodies; k++) {
        double es, ek;
        sph_body_energies(&s->bodies[k], &es, &ek);
        e += es + ek + sph_dissipated_energy(&s->bodies[k]) + s->bodies[k].visc_dissipated;
    }
    sph_contact_energies(s, &stored, &dissipated);
    return e + stored + dissipated;
}

/* |sum m v| over every body. */
static double total_momentum(const sph_sim *s)
{
    double p[3] = {0, 0, 0};
    for (int b = 0; b < s->nbodies; b++) {
        const sph_body *B = &s->bodies[b];
        for (int i = 0; i < B->n; i++)
            for (int k = 0; k < B->dim; k++)
                p[k] += B->mass * B->v[i * B->dim + k];
    }
    return sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
}

/* Current position component k of particle i. */
static double pos(const sph_body *b, int i, int k)
{
    return b->X[i * b->dim + k] + b->u[i * b->dim + k];
}

/* The smallest distance between a particle of a and one of b (brute force). */
static double closest_approach(const sph_body *a, const sph_body *b)
{
    double best = INFINITY;
    for (int i = 0; i < a->n; i++)
        for (int j = 0; j < b->n; j++) {
            double r2 = 0;
            for (int k = 0; k < a->dim; k++)
                r2 += (pos(a, i, k) - pos(b, j, k)) * (pos(a, i, k) - pos(b, j, k));
            best = fmin(best, r2);
        }
    return sqrt(best);
}

#endif
