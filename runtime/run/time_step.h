/* time_step.h — the time step of eq. 64-66: one source for the host (sim.c, run.c) and a
 * device target's own choice (cuda/advance.h). */
#ifndef SPHRT_RUN_TIME_STEP_H
#define SPHRT_RUN_TIME_STEP_H

#include <math.h>

#include "core/defs.h"
#include "scene/sim.h"

SPH_C_BEGIN

/* The factor on eq. 65 of a body whose smallest squared principal stretch is lam2min: where it
 * is compressed below lambda_on (the scene's `timestep`, 0 for `undeformed`) the bound follows
 * the current spacing lambda h (the reference wave speed of total-Lagrangian SPH grows like
 * 1/lambda), scaled so that it is continuous: lambda / lambda_on (docs/stability.md).  crush:
 * whether the body follows its compression at all. */
SPH_HD static inline double sph_stretch_factor(double lambda_on, int crush, double lam2min)
{
    if (!(lambda_on > 0) || !crush || !(lam2min >= 0))
        return 1.0; /* (a non-finite state is the monitor's to report) */
    const double lam = sqrt(lam2min);
    return lam < lambda_on ? lam / lambda_on : 1.0;
}

/* The running maximum m of eq. 65-66's |v|^2 or |a|^2 with x: a value that is not a number
 * counts as infinite, so a state gone non-finite gives a time step of 0 and stops the run at
 * the very next step (reported with the particle, run.c), not at the monitor's next check. */
SPH_HD static inline double sph_max_bound(double m, double x)
{
    return x <= m ? m : x == x ? x : INFINITY;
}

/* The squared principal stretch that the compression bound of a body takes for a particle's
 * l2 (the smallest eigenvalue of C): one at or below 0 (F inverted or degenerate), or not a
 * number, is a stretch of 0, which collapses the time step. */
SPH_HD static inline double sph_bound_stretch2(double l2)
{
    return l2 > 0 ? l2 : 0.0;
}

/* A body's bound on the time step before eq. 64's CFL: eq. 65 on its factor f and eq. 66;
 * *bound (where not NULL) which of them it is: eq. 66 where it is the smaller, otherwise
 * eq. 65, as compression where the factor f cut it. */
SPH_HD static inline double sph_body_dt_which(double f, double h, double c0, double vmax2,
                                              double amax2, int *bound)
{
    const double dtv = f * h / (c0 + sqrt(vmax2));                      /* eq. 65 */
    const double dta = amax2 > 0 ? sqrt(h / sqrt(amax2)) : INFINITY;   /* eq. 66 */
    if (bound)
        *bound = dta < dtv ? SPH_DT_ACCELERATION : f < 1 ? SPH_DT_COMPRESSION : SPH_DT_SPEED;
    return fmin(dtv, dta);
}

SPH_HD static inline double sph_body_dt(double f, double h, double c0, double vmax2, double amax2)
{
    return sph_body_dt_which(f, h, c0, vmax2, amax2, NULL);
}

/* The time step from the bodies' and contacts' smallest bound: eq. 64, or the scene's fixed
 * step, which a bound of 0 (a state that is not finite, sph_max_bound) makes not a number
 * too, so that a fixed step stops at once like an adaptive one. */
SPH_HD static inline double sph_chosen_dt(double dt_fixed, double cfl, double bound)
{
    if (dt_fixed > 0)
        return bound > 0 ? dt_fixed : NAN;
    return cfl * bound; /* eq. 64 */
}

/* The step towards a stop time (the next output, the end) `left` ahead under the bound dt:
 * the interval in equal steps no longer than dt, ceil(left / dt) of them, rather than steps
 * of dt and a short last one.  A short step before each output modulates the step in a
 * period of a few steps, which pumps energy into a mode near its stability limit (a
 * parametric resonance: the quadratic gradient's checkerboard mode, tests/stability/
 * hourglass2d.sph, grew 4.6-fold in 2 ms at cfl 0.2 with an output every 4.6 steps, and not
 * at all with the steps equal).  The same number of steps; a step shorter than dt by at most
 * dt over the steps to the stop.  (A ratio within 1e-9 of a whole number is that number.) */
SPH_HD static inline double sph_landing_dt(double dt, double left)
{
    if (!(left > dt))
        return left;
    return left / ceil(left / dt - 1e-9);
}

/* Where a body is compressed the bound follows the current spacing, and so does dtmin, down
 * to a hundredth of it (a stretch below 0.005 is a collapse too): the floor of a step whose
 * smallest factor is `factor`. */
SPH_HD static inline double sph_dt_floor_now(double floor_dt, double factor)
{
    return floor_dt * fmax(factor, 0.01);
}

SPH_C_END

#endif
