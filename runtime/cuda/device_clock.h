/* device_clock.h — the device's clock: the time loop's state that the passes read
 * (sph_time) when the device runs a batch of steps by itself (advance.h). */
#ifndef SPHRT_CUDA_DEVICE_CLOCK_H
#define SPHRT_CUDA_DEVICE_CLOCK_H

#include "target.h"
#include "core/defs.h"
#include "scene/body.h"
#include "scene/sim.h"

/* The time loop's state that the passes read (t and dt) when the device runs a batch of
 * steps by itself (sph_model.advance, sph_sim_advance): before each step it chooses the time
 * step from the last step's sums as sph_sim_stable_dt does (sph_cuda_clock_choose in
 * advance.h, with run/time_step.h's helpers), after it adds it to t (sph_cuda_clock_tick), so
 * the host queues the batch's steps without waiting between them.  Once the batch reaches its stop time, or its
 * time step collapses, `skip` makes every pass of the steps left return at once. */
enum { SPH_CLOCK_T, SPH_CLOCK_DT, SPH_CLOCK_T_HALF, SPH_CLOCK_T_NEXT, SPH_CLOCK_DT_PREV,
       SPH_CLOCK_DT_MEAN };

struct sph_cuda_clock {
    double t, dt;              /* the step: from t, of dt */
    double dt_prev;            /* the step before (sph_sim.dt_prev) */
    long step;
    int skip;                  /* 1: the passes return at once (until the batch ends) */
    double t_stop, eps;        /* the batch (sph_advance): no step from t >= t_stop - eps */
    double floor_dt;
    int collapsed;             /* the time step fell below its floor: it and the floor */
    double dt_bad, floor_bad;
    double dt_factor;          /* sph_sim.dt_factor */
    double cfl, dt_fixed, lambda_on; /* the scene's (sph_model) */
    int nbodies;
    sph_body *const *bodies;   /* the device views (managed) */
    const double *contact_sums; /* the contact's sums of the step (device, contact_law.h), */
    double contact_w2ref;      /* the laws' reference omega^2: the contact's bound (contact.c) */
    int bound, body;           /* what set the time step chosen (sph_sim.dt_bound, dt_body), */
    long bound_steps[SPH_DT_NBOUNDS]; /* and the batch's steps by it (sph_sim.dt_bound_steps) */
    long *body_steps;          /* and by body (managed, nbodies; sph_sim.dt_body_steps) */
};

__device__ static sph_cuda_clock sph_clock;

/* A time the passes read (scene/pass_types.h): a value, or a field of the device's clock, read where
 * the passes use it, on the device. */
struct sph_time {
    double value;
    int field; /* SPH_CLOCK_*, or -1: value */
    SPH_HD sph_time(double v) : value(v), field(-1) {}
    static sph_time clock(int f)
    {
        sph_time c(0.0);
        c.field = f;
        return c;
    }
    __device__ operator double() const
    {
        switch (field) {
        case SPH_CLOCK_T: return sph_clock.t;
        case SPH_CLOCK_DT: return sph_clock.dt;
        case SPH_CLOCK_T_HALF: return sph_clock.t + 0.5 * sph_clock.dt;
        case SPH_CLOCK_T_NEXT: return sph_clock.t + sph_clock.dt;
        /* the time since a law's last evaluation: Verlet's, the symplectic step's */
        case SPH_CLOCK_DT_PREV: return sph_clock.dt_prev;
        case SPH_CLOCK_DT_MEAN: return 0.5 * (sph_clock.dt_prev + sph_clock.dt);
        default: return value;
        }
    }
};

#endif
