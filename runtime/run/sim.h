/* sim.h — the simulation without the program around it (sim.c; used by sph_main and by
 * tests): set-up, time step, stepping. */
#ifndef SPHRT_RUN_SIM_H
#define SPHRT_RUN_SIM_H

#include "core/defs.h"
#include "par/par.h"
#include "scene/sim.h"

SPH_C_BEGIN

/* The simulation without the program around it (used by sph_main and by tests):
 * build every body and apply the velocity boundary conditions at t = 0 (initial
 * conditions); the stable time step of eq. 64-66 (or the fixed one); one step. */
int sph_sim_init(sph_sim *s, const sph_model *m, int verbose);
/* The same on the processes par, for a run to t_end (the model's or --end: the set-up's
 * warnings of conditions that never act); collective. */
int sph_sim_init_par(sph_sim *s, const sph_model *m, double t_end, int verbose,
                     const sph_par *par);
double sph_sim_stable_dt(sph_sim *s);
/* The smallest principal stretch of any particle (finite ones; capped at 1), from the host's
 * F (or, for a body that tracks it for its time step, its lam2min of the same F). */
double sph_sim_stretch(const sph_sim *s);
void sph_sim_step(sph_sim *s, double dt);
/* Up to a->steps steps, each of the stable time step (eq. 64-66) cut to end at a->t_stop at
 * the latest, none starting at t >= t_stop - eps: stops early at t_stop, or before a step
 * whose time step falls below its floor (a->collapsed).  A device target runs them on the
 * device, which then chooses each time step itself (sph_model.advance), and the host waits
 * once, at the end; on the CPU sph_sim_stable_dt and sph_sim_step.  Returns the steps taken. */
int sph_sim_advance(sph_sim *s, sph_advance *a);
void sph_sim_free(sph_sim *s);

SPH_C_END

#endif
