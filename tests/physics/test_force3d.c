/* Force boundary conditions of force3d.sph (3D, symplectic) against the momentum balance
 * (internal forces cancel to round-off in a body's momentum):
 *  - force accel x = 2.5 with a rough initial velocity field v0: mean velocity v0 + 2.5 t
 *    and mean displacement v0 t + 1.25 t^2 exactly (the corrector's trapezoidal rule is
 *    exact for a constant acceleration);
 *  - force surface: 5 kPa on the 6 x 4 end particles near a plate, i.e. on the end face
 *    6 mm x 4 mm (a force of 0.12 N, checking the dx^2 / m scaling of a traction in 3D),
 *    from 0.5 ms to 1.5 ms: momentum 0.12 N x (time in the window).
 * The steps land on the window times. */
#define main generated_main
#include "force3d.c"
#undef main

#include "check.h"

enum { D = 3 };

static void sums(const sph_body *b, double mom[D], double ubar[D])
{
    for (int k = 0; k < D; k++) {
        double sv = 0, su = 0;
        for (int i = 0; i < b->n; i++)
            sv += b->v[(size_t)i * D + k], su += b->u[(size_t)i * D + k];
        mom[k] = b->mass * sv;
        ubar[k] = su / b->n;
    }
}

static double window_time(double t)
{
    return fmax(0.0, fmin(t, 1.5e-3) - 0.5e-3);
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *acc = &sim.bodies[0], *surf = &sim.bodies[1];

    double v0[D] = {0, 0, 0};
    for (int i = 0; i < acc->n; i++) {
        const double *X = acc->X + (size_t)i * D;
        double *v = acc->v + (size_t)i * D;
        v[0] = 0.5 * sin(3111 * X[0] + 1700 * X[1]);
        v[1] = 0.3 * cos(2300 * X[2] - 900 * X[0]);
        v[2] = 0.4 * sin(1.9e6 * X[1] * X[2]);
        for (int k = 0; k < D; k++)
            v0[k] += v[k] / acc->n;
    }
    check_close("surf3: particles near the plate (the 6 x 4 end layer)", surf->bc_count[0], 24, 0);

    double e_v = 0, e_u = 0, e_surf = 0;
    const double marks[] = {0.5e-3, 1.5e-3, MODEL.t_end};
    int mark = 0;
    while (mark < 3) {
        double dt = sph_sim_stable_dt(&sim);
        if (sim.t + dt >= marks[mark] - 1e-12)
            dt = marks[mark++] - sim.t;
        sph_sim_step(&sim, dt);
        const double t = sim.t;
        double mom[D], ubar[D];
        sums(acc, mom, ubar);
        for (int k = 0; k < D; k++) {
            const double a = k == 0 ? 2.5 : 0;
            e_v = fmax(e_v, fabs(mom[k] / (acc->mass * acc->n) - (v0[k] + a * t)));
            e_u = fmax(e_u, fabs(ubar[k] - (v0[k] * t + 0.5 * a * t * t)));
        }
        sums(surf, mom, ubar);
        e_surf = fmax(e_surf, fabs(mom[0] - 0.12 * window_time(t)));
        e_surf = fmax(e_surf, fmax(fabs(mom[1]), fabs(mom[2])));
    }
    const double T = sim.t;
    double mom[D], ubar[D];
    sums(acc, mom, ubar);
    double es, ek;
    sph_body_energies(acc, &es, &ek);
    printf("%ld steps to t = %.6g s; acc3: mean v %.12g m/s, mean u %.12g m, strain energy %.3g J\n",
           sim.step, T, mom[0] / (acc->mass * acc->n), ubar[0], es);
    /* tolerances: round-off of a few hundred steps of pair-force sums (~1e-16 relative) */
    check_close("accel: max |mean v - (v0 + 2.5 t)| / (2.5 T)", e_v / (2.5 * T), 0, 1e-9);
    check_close("accel: max |mean u - (v0 t + 1.25 t^2)| / (1.25 T^2)", e_u / (1.25 * T * T), 0, 1e-9);
    check_close("accel: the body deformed (strain energy > 0)", es > 0, 1, 0);
    sums(surf, mom, ubar);
    printf("surf3: momentum %.12g N s\n", mom[0]);
    check_close("surface 3D: max |P - 5 kPa x 6 mm x 4 mm x (time in window)| / 1.2e-4 N s",
                e_surf / 1.2e-4, 0, 1e-9);
    check_close("surface 3D: P_x at the end [N s]", mom[0], 1.2e-4, 1e-15);
    sph_sim_free(&sim);
    return check_result();
}
