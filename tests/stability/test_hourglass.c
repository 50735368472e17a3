/* Hourglass modes (hourglass2d.sph): a checkerboard velocity field excites the zero-energy
 * mode of TLSPH.  Without control its displacement grows freely (close to v0 t in the
 * interior); with the penalty of Ganzenmueller (2015) it stays bounded, far below that.
 * The penalty must not act on affine deformations: for u = A X both bodies get the same
 * accelerations. */
#define main generated_main
#include "hourglass2d.c"
#undef main

#include <string.h>

#include "check.h"

/* RMS over interior particles of u_z times the checkerboard sign (-1)^(ix + iz). */
static double checkerboard(const sph_body *b)
{
    double s = 0;
    int n = 0;
    for (int i = 0; i < b->n; i++) {
        const double x = b->X[2 * i], z = b->X[2 * i + 1];
        if (x < 4e-3 || x > 16e-3 || z < 4e-3 || z > 16e-3)
            continue;
        const int ix = (int)floor(x / b->dx), iz = (int)floor(z / b->dx);
        const double sign = (ix + iz) % 2 ? -1.0 : 1.0;
        s += b->u[2 * i + 1] * sign;
        n++;
    }
    return s / n;
}

static void affine_untouched(sph_sim *sim)
{
    const double A[4] = {0.01, -0.004, 0.006, -0.008};
    for (int ib = 0; ib < 2; ib++) {
        sph_body *b = &sim->bodies[ib];
        for (int i = 0; i < b->n; i++)
            for (int r = 0; r < 2; r++)
                b->u[2 * i + r] = A[2 * r] * b->X[2 * i] + A[2 * r + 1] * b->X[2 * i + 1];
        memset(b->v, 0, sizeof(double) * 2 * (size_t)b->n);
    }
    plain_forces(&sim->bodies[0]);
    controlled_forces(&sim->bodies[1]);
    double diff = 0, scale = 0;
    for (int i = 0; i < 2 * sim->bodies[0].n; i++) {
        diff = fmax(diff, fabs(sim->bodies[0].a[i] - sim->bodies[1].a[i]));
        scale = fmax(scale, fabs(sim->bodies[0].a[i]));
    }
    check_close("affine u = A X: max |a(control) - a(plain)| / max |a|", diff / scale, 0, 1e-10);
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    while (sim.t < MODEL.t_end)
        sph_sim_step(&sim, sph_sim_stable_dt(&sim));
    const double free_growth = 0.01 * sim.t; /* v0 t */
    const double plain = checkerboard(&sim.bodies[0]), controlled = checkerboard(&sim.bodies[1]);
    printf("after %ld steps (t = %.4g s): checkerboard amplitude %.4g m without control, "
           "%.4g m with, v0 t = %.4g m\n", sim.step, sim.t, plain, controlled, free_growth);
    /* Without control the mode is free: at least half of v0 t remains in the interior. */
    check_close("no control: checkerboard amplitude / (v0 t) >= 0.5", plain / free_growth >= 0.5, 1, 0);
    /* With alpha = 0.1 the mode oscillates with amplitude about v0 / omega_hg (a few 1e-7 m). */
    check_close("control: |amplitude| / (v0 t) below 0.1", fabs(controlled) / free_growth < 0.1, 1, 0);
    affine_untouched(&sim);
    sph_sim_free(&sim);
    return check_result();
}
