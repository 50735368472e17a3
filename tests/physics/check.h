/* check.h — tiny assertion helpers for the physics tests: print what is checked, with the
 * numbers, and count failures. */
#ifndef SPH_TEST_CHECK_H
#define SPH_TEST_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check_failures;

/* |got - want| <= tol, reported with a label. */
static void check_close(const char *what, double got, double want, double tol)
{
    int ok = fabs(got - want) <= tol;
    printf("%-58s got %-14.8g want %-14.8g tol %-9.2g %s\n", what, got, want, tol, ok ? "ok" : "FAIL");
    check_failures += !ok;
}

#ifdef SPHRT_H
/* A 3D bar's extent from its particles' current centres (X + u): the lowest and highest z
 * and the largest distance from the z axis (the Taylor bars' shortening and mushrooming). */
typedef struct {
    double zmin, zmax, rmax;
} check_extent;

static check_extent check_bar_extent(const sph_body *b)
{
    check_extent e = {INFINITY, -INFINITY, 0};
    for (int i = 0; i < b->n; i++) {
        const double *X = b->X + (size_t)i * 3, *u = b->u + (size_t)i * 3;
        const double x = X[0] + u[0], y = X[1] + u[1], z = X[2] + u[2];
        e.zmin = fmin(e.zmin, z), e.zmax = fmax(e.zmax, z);
        e.rmax = fmax(e.rmax, sqrt(x * x + y * y));
    }
    return e;
}

/* The largest |entry| of a body's P L (Q): its stress, for tests of stress-free motions. */
static double check_max_stress(const sph_body *b)
{
    double q = 0;
    for (int i = 0; i < b->n; i++)
        for (int r = 0; r < b->dim; r++)
            for (int c = 0; c < b->dim; c++)
                q = fmax(q, fabs(b->Q[SPH_TENSOR(i, r, c, b->dim, b->n)]));
    return q;
}

/* A fracture body run to the model's end time under watch: over every step, the largest
 * decrease of the history field H at any particle (irreversibility, eq. 8: must be 0), the
 * range of s (must stay in [0, 1]), and the first damage (s < 0.5): its time and particle. */
typedef struct {
    double h_drop, s_lo, s_hi;
    double t_init; /* -1: no damage */
    int i_init;
} check_fracture_run;

static check_fracture_run check_run_fracture(sph_sim *sim, const sph_body *b)
{
    check_fracture_run w = {0, 1, 0, -1, -1};
    double *H0 = malloc(sizeof(double) * (size_t)b->n);
    while (sim->t < sim->m->t_end - 1e-15) {
        memcpy(H0, b->H, sizeof(double) * (size_t)b->n);
        sph_sim_step(sim, fmin(sph_sim_stable_dt(sim), sim->m->t_end - sim->t));
        for (int i = 0; i < b->n; i++) {
            w.h_drop = fmax(w.h_drop, H0[i] - b->H[i]);
            w.s_lo = fmin(w.s_lo, b->s[i]), w.s_hi = fmax(w.s_hi, b->s[i]);
            if (w.t_init < 0 && b->s[i] < 0.5)
                w.t_init = sim->t, w.i_init = i;
        }
    }
    free(H0);
    return w;
}

/* The checks of irreversibility and of the range of s on a watched run. */
static void check_fracture_bounds(const check_fracture_run *w)
{
    check_close("largest decrease of H over a step", w->h_drop, 0, 0);
    check_close("smallest s is at least 0", w->s_lo < 0 ? w->s_lo : 0, 0, 0);
    check_close("largest s is at most 1", w->s_hi > 1 ? w->s_hi : 1, 1, 0);
}
#endif

static int check_result(void)
{
    printf(check_failures ? "%d check(s) FAILED\n" : "all checks passed\n", check_failures);
    return check_failures ? 1 : 0;
}

#endif
