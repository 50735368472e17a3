/* bending_check.h — the static bending tests (test_bending5.c, test_bending10.c; in plane
 * strain test_bending2d5.c, test_bending2d10.c): a square cantilever clamped on x = 0, its end layer loaded in -z by a total force P that is ramped up
 * over t_ramp and then held; the tip measurement's mean u_z over the rest of the run (two
 * periods or more of the beam's first mode, which averages out what the ramp leaves of its
 * ringing) against the finite-element deflection (bench/fe-references/cantilever_static.py,
 * cantilever_2d.py: the mean u_z over the loaded slab, converged Q2 elements, in units of
 * P / (E t)). */
#include "check.h"
#include "run/measure.h"
#ifdef _OPENMP
#include <omp.h>
#endif

typedef struct {
    double t_ramp;   /* the load's ramp [s] */
    double P;        /* the total end load [N] (negative: -z) */
    double E, t;     /* Young's modulus [Pa], thickness [m]; 2D: t = 1 (the load and the
                      * FE deflection are per unit width, u = fe P / E) */
    double fe;       /* the FE deflection for P = -1, E = 1, t = 1 */
    double tol;      /* the relative tolerance */
    const char *what;
} bending_case;

static int bending_run(const bending_case *c)
{
#ifdef _OPENMP
    omp_set_num_threads(1); /* (the suite runs tests side by side; a busy core stalls a team) */
#endif
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    double uz = 0, lo = INFINITY, hi = -INFINITY;
    long nav = 0;
    while (sim.t < MODEL.t_end - 1e-12) {
        sph_sim_step(&sim, fmin(sph_sim_stable_dt(&sim), MODEL.t_end - sim.t));
        if (sim.t < c->t_ramp)
            continue;
        double m[6];
        sph_measure(b, 0, m);
        uz += m[2], nav++;
        lo = fmin(lo, m[2]), hi = fmax(hi, m[2]);
    }
    uz /= nav;
    const double ref = c->fe * -c->P / (c->E * c->t);
    printf("%s: %d particles, %ld steps, tip u_z %.6g m averaged over %ld steps (range %.6g .. "
           "%.6g), finite elements %.6g m\n", c->what, b->n, sim.step, uz, nav, lo, hi, ref);
    check_close("tip deflection / finite-element deflection", uz / ref, 1, c->tol);
    sph_sim_free(&sim);
    return check_result();
}
