/* measure.c — what a run measures of a body (measure.h): its strain and kinetic energy, the
 * energy its material law dissipated, a measurement plane's mean displacement and force, and
 * the time series they are recorded in. */
#include <stdlib.h>
#include <string.h>

#include "measure.h"
#include "core/alloc.h"
#include "core/defs.h"
#include "par/par.h"
#include "scene/body.h"

static void *zalloc(size_t n, size_t size)
{
    return sph_alloc_setup(n * size, 1); /* (huge pages for large arrays: core/alloc.c) */
}

/* |v|^2 of particle i at the middle of the last step, of length dt: v - dt/2 a on its free
 * components (a prescribed one is held through the step: v); with dt = 0, |v|^2 */
static double v2_centred(const sph_body *b, int i, double dt)
{
    double s = 0;
    for (int c = 0; c < b->dim; c++) {
        const size_t k = (size_t)i * b->dim + c;
        const int held = dt == 0 || (b->fix && (b->fix[i] >> c & 1));
        const double v = b->v[k] - (held ? 0.0 : 0.5 * dt * b->a[k]);
        s += v * v;
    }
    return s;
}

void sph_body_energies_at(const sph_body *b, double dt, double *strain, double *kinetic)
{
    /* Summed in blocks of a fixed size, the blocks' sums in order: the same bits on any
     * number of threads (a run's team changes with the machine's load, par/team.h). */
    enum { BLOCK = 4096 };
    const int nblocks = (b->nown + BLOCK - 1) / BLOCK;
    double *part = zalloc(2 * (size_t)nblocks + 1, sizeof(double));
#pragma omp parallel for schedule(static)
    for (int k = 0; k < nblocks; k++) {
        const int end = b->nown - k * BLOCK < BLOCK ? b->nown : (k + 1) * BLOCK;
        double es = 0, ek = 0;
        for (int i = k * BLOCK; i < end; i++) {
            es += b->psi[i];
            ek += v2_centred(b, i, dt);
        }
        part[2 * k] = es, part[2 * k + 1] = ek;
    }
    double es = 0, ek = 0;
    for (int k = 0; k < nblocks; k++)
        es += part[2 * k], ek += part[2 * k + 1];
    free(part);
    for (int k = 0; k < b->nimages; k++) /* (a clamp's images are not material) */
        ek -= v2_centred(b, b->image[k], dt);
    *strain = es * b->vol;
    *kinetic = 0.5 * b->mass * ek;
}

void sph_body_energies(const sph_body *b, double *strain, double *kinetic)
{
    sph_body_energies_at(b, 0.0, strain, kinetic);
}

/* The sum over own particles of state value `slot` of the body's law less base (each term
 * apart: a temperature's rise, not the difference of two large sums); 0 without state. */
static double state_sum(const sph_body *b, int slot, double base)
{
    const int ns = b->desc->nstate;
    double sum = 0;
    for (int i = 0; slot >= 0 && b->state && i < b->nown; i++)
        sum += b->state[(size_t)i * ns + slot] - base;
    return sum;
}

double sph_dissipated_energy(const sph_body *b)
{
    return state_sum(b, b->desc->dissipation - 1, 0.0) * b->vol;
}

double sph_thermal_energy(const sph_body *b)
{
    const int slot = b->desc->temperature - 1;
    if (slot < 0 || !b->state)
        return 0.0;
    const double T0 = b->desc->state_init[slot]; /* (the same at every particle) */
    return b->mass * b->desc->heat_capacity * state_sum(b, slot, T0);
}

void sph_measure(const sph_body *b, int k, double out[6])
{
    memset(out, 0, 6 * sizeof(double));
    const int n = b->ms_count[k], D = b->dim;
    for (int q = 0; q < n; q++) {
        const int i = b->ms_list[k][q];
        for (int c = 0; c < D; c++) {
            out[sph_axis(D, c)] += b->u[(size_t)i * D + c];
            out[3 + sph_axis(D, c)] += b->mass * b->a[(size_t)i * D + c];
        }
    }
    double count = n;
    if (b->par->size > 1) { /* the sums and the particles of every process */
        double all[7];
        memcpy(all, out, 6 * sizeof(double));
        all[6] = n;
        b->par->sum(all, 7);
        memcpy(out, all, 6 * sizeof(double));
        count = all[6];
    }
    for (int c = 0; c < 3 && count > 0; c++)
        out[c] /= count;
}

void sph_series_push(sph_series *s, double t, const double *row)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 256;
        s->t = realloc(s->t, (size_t)s->cap * sizeof(double));
        s->val = realloc(s->val, (size_t)s->cap * (size_t)s->width * sizeof(double));
    }
    s->t[s->n] = t;
    memcpy(s->val + (size_t)s->n * (size_t)s->width, row, (size_t)s->width * sizeof(double));
    s->n++;
}
