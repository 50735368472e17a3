/* advance.h — a batch of steps on the device (sph_model.advance): the device's clock chooses
 * each time step as sph_sim_stable_dt would, and the host queues the steps without waiting. */
#ifndef SPHRT_CUDA_ADVANCE_H
#define SPHRT_CUDA_ADVANCE_H

#include "target.h"
#include "check.h"
#include "device_clock.h"
#include "launch.h"
#include "memory.h"
#include "sums.h"
#include "contact/contact_law.h"
#include "run/time_step.h"
#include "scene/body.h"
#include "scene/model.h"
#include "scene/sim.h"

/* The time step of the next step from the last step's sums, as sph_sim_stable_dt and
 * sph_sim_advance choose it on the host; or the end of the batch. */
__device__ static inline void sph_clock_choose_on(sph_cuda_clock *c)
{
    if (c->skip)
        return;
    if (!(c->t < c->t_stop - c->eps)) {
        c->skip = 1;
        return;
    }
    double dt = INFINITY, vmax2 = 0, amax2 = 0;
    c->dt_factor = 1.0;
    c->bound = SPH_DT_SPEED, c->body = 0;
    for (int i = 0; i < c->nbodies; i++) {
        const sph_body *b = c->bodies[i];
        const double *red = b->red, v2 = red[SPH_RED_VMAX2], a2 = red[SPH_RED_AMAX2];
        const double f = sph_stretch_factor(c->lambda_on, b->lam2 != NULL, sph_red_lam2min(red));
        c->dt_factor = fmin(c->dt_factor, f);
        int bound;
        const double own = sph_body_dt_which(f, b->h, b->c0, v2, a2, &bound);
        if (own < dt) /* (what set it: as sph_sim_stable_dt says) */
            dt = own, c->body = i, c->bound = bound;
        vmax2 = fmax(vmax2, v2), amax2 = fmax(amax2, a2);
    }
    if (c->contact_sums) { /* the stiffest contact, where a pair is in contact or near it */
        const double *cs = c->contact_sums;
        const int near = sph_contact_near(cs[SPH_CSUM_CLOSE], cs[SPH_CSUM_LEVEL], vmax2, amax2,
                                          c->dt, sph_chosen_dt(c->dt_fixed, c->cfl, dt));
        const double contact = sph_contact_bound(cs[SPH_CSUM_W2], c->contact_w2ref, near);
        if (contact < dt)
            dt = contact, c->bound = SPH_DT_CONTACT, c->body = -1;
    }
    if (c->dt_fixed > 0)
        c->bound = SPH_DT_FIXED, c->body = -1;
    dt = sph_chosen_dt(c->dt_fixed, c->cfl, dt);
    const double floor_now = sph_dt_floor_now(c->floor_dt, c->dt_factor);
    if (!(dt >= floor_now)) {
        c->collapsed = 1, c->dt_bad = dt, c->floor_bad = floor_now, c->skip = 1;
        return;
    }
    c->dt_prev = c->dt; /* (the last step's: sph_sim_step's dt_prev) */
    c->dt = sph_landing_dt(dt, c->t_stop - c->t);
}

__device__ static inline void sph_clock_tick_on(sph_cuda_clock *c)
{
    if (c->skip)
        return;
    c->t += c->dt;
    c->step++;
    c->bound_steps[c->bound]++;
    if (c->body >= 0)
        c->body_steps[c->body]++;
}

__global__ void sph_clock_choose_kernel() { sph_clock_choose_on(&sph_clock); }
__global__ void sph_clock_tick_kernel() { sph_clock_tick_on(&sph_clock); }
__global__ void sph_clock_resume_kernel() { sph_clock.skip = 0; }
static void sph_cuda_clock_choose()
{
    sph_launch("the clock's choice of the time step",
               [] { SPH_ONE_THREAD(sph_clock_choose_kernel); });
}
static void sph_cuda_clock_tick()
{
    sph_launch("the clock's tick", [] { SPH_ONE_THREAD(sph_clock_tick_kernel); });
}
static void sph_cuda_clock_resume()
{
    sph_launch("the clock's resumption", [] { SPH_ONE_THREAD(sph_clock_resume_kernel); });
}

/* The clock at the start of a batch: the host's time, the batch and the scene.  At the first
 * step the host's sums (sph_sim_init's initial speeds) go to the device, where the first time
 * step is chosen from them. */
static void sph_cuda_clock_start(const sph_sim *s, const sph_advance *a, sph_body *const *dev,
                                 const double *contact_sums, double contact_w2ref)
{
    if (s->step == 0)
        for (int i = 0; i < s->nbodies; i++)
            sph_host_sums_to_device(&s->bodies[i], dev[i]->red);
    static sph_body **views; /* the device views, where the device's clock reads them */
    static long *body_steps; /* the steps each body's bound set (the clock counts them) */
    if (!views) {
        SPH_CUDA_CHECK(cudaMallocManaged(&views, (size_t)s->nbodies * sizeof *views));
        for (int i = 0; i < s->nbodies; i++)
            views[i] = dev[i];
        sph_read_mostly(views, (size_t)s->nbodies * sizeof *views);
        SPH_CUDA_CHECK(cudaMallocManaged(&body_steps, (size_t)s->nbodies * sizeof *body_steps));
    }
    for (int i = 0; i < s->nbodies; i++) /* (the host waited for the last batch) */
        body_steps[i] = 0;
    const sph_model *m = s->m;
    sph_cuda_clock c = {};
    c.t = s->t, c.dt = s->dt, c.dt_prev = s->dt_prev, c.step = s->step, c.dt_factor = s->dt_factor;
    c.t_stop = a->t_stop, c.eps = a->eps, c.floor_dt = a->floor_dt;
    c.cfl = m->cfl, c.dt_fixed = m->dt_fixed, c.lambda_on = m->dt_lambda_on;
    c.nbodies = s->nbodies, c.bodies = views;
    c.contact_sums = contact_sums, c.contact_w2ref = contact_w2ref;
    c.bound = s->dt_bound, c.body = s->dt_body, c.body_steps = body_steps;
    SPH_CUDA_CHECK(cudaMemcpyToSymbol(sph_clock, &c, sizeof c));
}

/* The batch's steps, counted by the clock by what set each, into the host's counts. */
static void sph_cuda_clock_counts(sph_sim *s, const sph_cuda_clock *c)
{
    for (int k = 0; k < SPH_DT_NBOUNDS; k++)
        s->dt_bound_steps[k] += c->bound_steps[k];
    for (int i = 0; s->dt_body_steps && i < s->nbodies; i++)
        s->dt_body_steps[i] += c->body_steps[i];
    s->dt_bound = (sph_dt_bound)c->bound, s->dt_body = c->body;
}

/* The end of a batch: the passes run again (skip cleared), and the host waits for the clock:
 * its time, step and time step, and whether the time step collapsed. */
static void sph_cuda_clock_finish(sph_sim *s, sph_advance *a)
{
    sph_cuda_clock_resume();
    SPH_CUDA_CHECK(cudaGetLastError());
    sph_cuda_clock c;
    SPH_CUDA_CHECK(cudaMemcpyFromSymbol(&c, sph_clock, sizeof c));
    sph_cuda_profile_collect(); /* (the host has waited) */
    s->t = c.t, s->dt = c.dt, s->dt_prev = c.dt_prev, s->step = c.step, s->dt_factor = c.dt_factor;
    a->collapsed = c.collapsed, a->dt_bad = c.dt_bad, a->floor_bad = c.floor_bad;
    sph_cuda_clock_counts(s, &c);
}

/* Whether the clock stopped the batch (one small copy: the host waits for the steps queued). */
static int sph_cuda_clock_stopped()
{
    sph_cuda_clock c;
    SPH_CUDA_CHECK(cudaMemcpyFromSymbol(&c, sph_clock, sizeof c));
    sph_cuda_profile_collect(); /* (the host has waited) */
    return c.skip;
}

/* Steps the host queues before it looks whether the clock stopped the batch. */
#ifndef SPH_CLOCK_CHUNK
#define SPH_CLOCK_CHUNK 20
#endif

/* A batch of steps (sph_model.advance): up to a->steps steps, each of the passes that
 * `step` queues (reading t and dt from the clock) between the clock's choice and tick.  The
 * host queues them SPH_CLOCK_CHUNK at a time and, where steps are left after a chunk, looks
 * whether the clock has stopped, so that a batch asked for many steps (up to its stop time)
 * queues only a chunk more than it takes.  contact_sums, contact_w2ref: the contact's bound
 * (NULL, 0 without contact). */
static void sph_cuda_advance(sph_sim *s, sph_advance *a, sph_body *const *dev,
                             const double *contact_sums, double contact_w2ref, void (*step)())
{
    sph_cuda_clock_start(s, a, dev, contact_sums, contact_w2ref);
    for (int done = 0; done < a->steps;) {
        const int chunk = a->steps - done < SPH_CLOCK_CHUNK ? a->steps - done : SPH_CLOCK_CHUNK;
        for (int k = 0; k < chunk; k++) {
            sph_cuda_clock_choose();
            step();
            sph_cuda_clock_tick();
        }
        done += chunk;
        if (done < a->steps && ((a->stop && *a->stop) || sph_cuda_clock_stopped()))
            break;
    }
    sph_cuda_clock_finish(s, a);
}

#endif
