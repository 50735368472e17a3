/* setup.c — building a body: particles from its region, neighbour lists and corrected
 * kernel gradients in the reference configuration (total Lagrangian: done once), the
 * particle selections of its boundary conditions and measurements, and its arrays. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"
#include "select.h"

static void *zalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (!p) {
        fprintf(stderr, "sph: error: out of memory\n");
        exit(3);
    }
    return p;
}

static void allocate(sph_body *b)
{
    size_t n = (size_t)b->n, D = (size_t)b->dim;
    b->u = zalloc(n * D, sizeof(double));
    b->v = zalloc(n * D, sizeof(double));
    b->a = zalloc(n * D, sizeof(double));
    b->work = zalloc(n * D, sizeof(double));
    b->F = zalloc(n * 9, sizeof(double));
    for (size_t i = 0; i < n; i++)
        b->F[9 * i] = b->F[9 * i + 4] = b->F[9 * i + 8] = 1.0;
    b->Q = zalloc(n * D * D, sizeof(double));
    b->Cv = zalloc(n * D * D, sizeof(double));
    b->psi = zalloc(n, sizeof(double));
    b->sigma = zalloc(n * 6, sizeof(double));
    b->fix = zalloc(n, 1);
}

/* Eq. 60 per pair without gathering X_j in the hot loop: w_ij is parallel to X_i - X_j, so
 * G_ij = h (v_ij . dX) / (r^2 + 0.001 h^2) = nb_g (v_ij . w_ij) with
 * nb_g = h r^2 / ((w . dX) (r^2 + 0.001 h^2)); 0 where w vanishes (r = 2h). */
static void viscosity_factors(sph_body *b)
{
    const int D = b->dim;
    b->nb_g = zalloc((size_t)b->npairs, sizeof(double));
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->n; i++)
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++) {
            const int j = b->nb[p];
            double r2 = 0, wdx = 0;
            for (int k = 0; k < D; k++) {
                const double dX = b->X[(size_t)i * D + k] - b->X[(size_t)j * D + k];
                r2 += dX * dX;
                wdx += b->nb_w[(size_t)p * D + k] * dX;
            }
            b->nb_g[p] = wdx != 0 ? b->h * r2 / (wdx * (r2 + 0.001 * b->h * b->h)) : 0.0;
        }
}

static void selections(sph_body *b, const sph_body_desc *d)
{
    b->bc_list = zalloc((size_t)d->nbcs, sizeof(int *));
    b->bc_count = zalloc((size_t)d->nbcs, sizeof(int));
    for (int k = 0; k < d->nbcs; k++)
        if (d->bcs[k].has_near)
            b->bc_count[k] = sph_select_near(b->X, b->n, b->dim, b->y_plane, b->dx,
                                             &d->bcs[k].near, &b->bc_list[k]);
    b->ms_list = zalloc((size_t)d->nmeasures, sizeof(int *));
    b->ms_count = zalloc((size_t)d->nmeasures, sizeof(int));
    for (int k = 0; k < d->nmeasures; k++) {
        b->ms_count[k] = sph_select_plane(b->X, b->n, b->dim, b->dx, d->measures[k].p,
                                          &b->ms_list[k]);
        if (b->ms_count[k] == 0)
            fprintf(stderr, "sph: warning: measurement '%s' of body '%s' selects no particle\n",
                    d->measures[k].name, d->name);
    }
}

int sph_body_setup(sph_body *b, const sph_body_desc *d, const sph_model *m)
{
    memset(b, 0, sizeof *b);
    b->desc = d;
    b->dim = m->dim;
    b->dx = m->dp / d->refine;
    b->h = m->coefh * sqrt((double)m->dim) * b->dx; /* h = coefh sqrt(dim) dx */
    b->vol = pow(b->dx, m->dim);                    /* 2D: unit thickness */
    b->rho0 = d->rho0;
    b->mass = b->rho0 * b->vol;
    b->c0 = d->c0;
    b->y_plane = d->y_plane;
    b->n = sph_fill_region(&d->region, m->dim, b->dx, d->y_plane, &b->X);
    if (b->n <= 0) {
        fprintf(stderr, "sph: error: body '%s' has no particles (its shape is smaller than the "
                        "particle spacing %g)\n", d->name, b->dx);
        return -1;
    }
    sph_neighbours(b->X, b->n, b->dim, 2.0 * b->h, d->nbsrange, b->dx, &b->nb_start, &b->nb);
    b->npairs = b->nb_start[b->n];
    sph_gradients(b->X, b->n, b->dim, b->nb_start, b->nb, m->kernel, b->h, b->vol, &b->nb_w,
                  &b->L);
    viscosity_factors(b);
    allocate(b);
    selections(b, d);
    return 0;
}

void sph_body_free(sph_body *b)
{
    for (int k = 0; k < b->desc->nbcs; k++)
        free(b->bc_list[k]);
    for (int k = 0; k < b->desc->nmeasures; k++)
        free(b->ms_list[k]);
    free(b->bc_list), free(b->bc_count), free(b->ms_list), free(b->ms_count);
    free(b->X), free(b->u), free(b->v), free(b->a), free(b->work), free(b->F), free(b->L);
    free(b->Q), free(b->Cv), free(b->psi), free(b->sigma), free(b->fix);
    free(b->nb_start), free(b->nb), free(b->nb_w), free(b->nb_g);
}

/* ------------------------------------------------------------------ measured quantities */

void sph_body_energies(const sph_body *b, double *strain, double *kinetic)
{
    double es = 0, ek = 0;
    const int D = b->dim;
#pragma omp parallel for reduction(+ : es, ek)
    for (int i = 0; i < b->n; i++) {
        es += b->psi[i];
        for (int k = 0; k < D; k++)
            ek += b->v[(size_t)i * D + k] * b->v[(size_t)i * D + k];
    }
    *strain = es * b->vol;
    *kinetic = 0.5 * b->mass * ek;
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
    for (int c = 0; c < 3 && n; c++)
        out[c] /= n;
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
