/* sim.c — a simulation without the program around it: set-up, time step, stepping. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "setup.h"
#include "sim.h"
#include "time_step.h"
#include "contact/contact.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "core/tensor3.h"
#include "par/par.h"
#include "scene/body.h"
#include "scene/model.h"
#include "scene/sim.h"
#include "scene/step_sums.h"

static void initial_speeds(sph_sim *s)
{
    for (int i = 0; i < s->nbodies; i++) {
        sph_body *b = &s->bodies[i];
        double v2max = 0;
        for (int p = 0; p < b->nown * b->dim; p += b->dim) {
            double v2 = 0;
            for (int k = 0; k < b->dim; k++)
                v2 += b->v[p + k] * b->v[p + k];
            v2max = fmax(v2max, v2);
        }
        s->par->max(&v2max, 1);
        b->vmax2 = v2max;
        b->amax2 = 0;
    }
}

int sph_sim_init(sph_sim *s, const sph_model *m, int verbose)
{
    return sph_sim_init_par(s, m, m->t_end, verbose, &sph_par_one);
}

int sph_sim_init_par(sph_sim *s, const sph_model *m, double t_end, int verbose,
                     const sph_par *par)
{
    sph_message_program(m->name);
    s->m = m;
    s->par = par;
    s->t = s->dt = s->dt_prev = 0;
    s->step = 0;
    s->contact = NULL;
    s->nbodies = m->nbodies;
    s->bodies = calloc((size_t)m->nbodies, sizeof(sph_body));
    s->dt_body_steps = calloc((size_t)m->nbodies + 1, sizeof *s->dt_body_steps);
    for (int k = 0; k < SPH_DT_NBOUNDS; k++)
        s->dt_bound_steps[k] = 0;
    for (int i = 0; i < m->nbodies; i++) {
        sph_body *b = &s->bodies[i];
        if (sph_body_setup(b, &m->bodies[i], m, t_end, par))
            return -1;
        double count[2] = {b->nown, (double)b->npairs}; /* (on all processes) */
        par->sum(count, 2);
        if (verbose && par->rank == 0)
            printf("%s: body %s: %.0f particles, dx = %g m, %.1f neighbours each, c0 = %g m/s\n",
                   m->name, m->bodies[i].name, count[0], b->dx, count[1] / count[0], b->c0);
    }
    for (int i = 0; i < m->nbodies; i++) /* the plans of the halo exchanges */
        if (par->agree(par->body_ready(&s->bodies[i])))
            return -1;
    sph_contact_init(s);
    s->dt_factor = 1.0;
    m->velocity_bcs(s, 0.0); /* initial conditions: the BCs at t = 0 */
    initial_speeds(s);
    return 0;
}

/* The smallest principal stretch of body b: min over particles of sqrt(eigmin(F^T F)).  A
 * body whose time step follows its compression (lam2) has it from its last stress and update
 * passes already, from the same F. */
static double stretch_min(const sph_body *b)
{
    if (b->lam2)
        return sqrt(fmax(b->lam2min, 0.0));
    double l2 = INFINITY;
#pragma omp parallel for reduction(min : l2)
    for (int i = 0; i < b->nown; i++)
        l2 = fmin(l2, sph_stretch2_min(b->F + 9 * (size_t)i, b->dim));
    return b->nown ? sqrt(fmax(l2, 0.0)) : 1.0;
}

double sph_sim_stretch(const sph_sim *s)
{
    double lam = 1.0;
    for (int i = 0; i < s->nbodies; i++)
        lam = fmin(lam, stretch_min(&s->bodies[i]));
    s->par->min(&lam, 1);
    return lam;
}

/* Whether step sum k is the scene's, a maximum or minimum (scene/step_sums.h), and its value
 * as a maximum: a minimum negated (the same map back). */
static int scene_sum(int k) { return sph_step_sum_reduce(k) != SPH_REDUCE_ADD; }
static double as_max(int k, double x) { return sph_step_sum_reduce(k) == SPH_REDUCE_MIN ? -x : x; }

/* Body b's scene sums into x, each as a maximum. */
static void scene_sums_out(const sph_body *b, double *x)
{
    double all[SPH_STEP_NSUMS];
    sph_step_sums_get(b, all);
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        if (scene_sum(k))
            *x++ = as_max(k, all[k]);
}

/* Body b's scene sums from x, as scene_sums_out wrote them. */
static void scene_sums_in(sph_body *b, const double *x)
{
    double all[SPH_STEP_NSUMS];
    sph_step_sums_get(b, all);
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        if (scene_sum(k))
            all[k] = as_max(k, *x++);
    sph_step_sums_set(b, all);
}

/* On many processes: each body's maxima and minima of a step over all of them, one exchange
 * for the scene (the bounds of eq. 65-66: the largest |v|^2 and |a|^2, the smallest stretch).
 * The sums stay each process's share. */
static void global_bounds(sph_sim *s)
{
    if (s->par->size == 1)
        return;
    int per = 0;
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        per += scene_sum(k);
    double stack[SPH_STEP_NSUMS * 8];
    double *x = s->nbodies <= 8 ? stack : malloc((size_t)per * sizeof *x * s->nbodies);
    if (!x) {
        sph_error("out of memory");
        exit(SPH_EXIT_SETUP);
    }
    for (int i = 0; i < s->nbodies; i++)
        scene_sums_out(&s->bodies[i], x + per * i);
    s->par->max(x, per * s->nbodies);
    for (int i = 0; i < s->nbodies; i++)
        scene_sums_in(&s->bodies[i], x + per * i);
    if (x != stack)
        free(x);
}

double sph_sim_stable_dt(sph_sim *s)
{
    const sph_model *m = s->m;
    double dt = INFINITY;
    s->dt_factor = 1.0;
    global_bounds(s);
    s->dt_bound = SPH_DT_SPEED, s->dt_body = 0;
    for (int i = 0; i < s->nbodies; i++) {
        const sph_body *b = &s->bodies[i];
        const double f = sph_stretch_factor(m->dt_lambda_on, b->lam2 != NULL, b->lam2min);
        s->dt_factor = fmin(s->dt_factor, f);
        int bound;
        const double own = sph_body_dt_which(f, b->h, b->c0, b->vmax2, b->amax2, &bound);
        if (own < dt)
            dt = own, s->dt_body = i, s->dt_bound = (sph_dt_bound)bound;
    }
    /* the stiffest contact, where a pair is in contact or near it */
    const double contact = sph_contact_dt(s, sph_chosen_dt(m->dt_fixed, m->cfl, dt));
    if (contact < dt)
        dt = contact, s->dt_bound = SPH_DT_CONTACT, s->dt_body = -1;
    if (m->dt_fixed > 0)
        s->dt_bound = SPH_DT_FIXED, s->dt_body = -1;
    return sph_chosen_dt(m->dt_fixed, m->cfl, dt);
}

/* A step taken: counted under the bound that set its time step, and its body. */
static void count_bound(sph_sim *s)
{
    s->dt_bound_steps[s->dt_bound]++;
    if (s->dt_body >= 0 && s->dt_body_steps)
        s->dt_body_steps[s->dt_body]++;
}

void sph_sim_step(sph_sim *s, double dt)
{
    s->dt_prev = s->dt;
    s->dt = dt;
    s->m->step(s, dt);
    s->t += dt;
    s->step++;
}

int sph_sim_advance(sph_sim *s, sph_advance *a)
{
    const long step0 = s->step;
    a->collapsed = 0;
    /* the device chooses the time steps (cuda/advance.h); on many processes they must
     * agree on each, so the host chooses it after every step, as on the CPU */
    if (s->m->advance && s->par->size == 1) {
        s->m->advance(s, a);
        return (int)(s->step - step0);
    }
    /* F is read after a batch only (the monitor, outputs, checkpoints), so only a batch's last
     * step stores it: storing it every step took a fifth of crack branching's stress pass.
     * A stop signal ends the batch after a step that stored it (one step more where the
     * signal came during another). */
    int stored = 1; /* (the batch before this one ended with it) */
    while (s->step - step0 < a->steps && s->t < a->t_stop - a->eps &&
           !(a->stop && *a->stop && stored)) {
        const double dt = sph_sim_stable_dt(s);
        const double floor_now = sph_dt_floor_now(a->floor_dt, s->dt_factor);
        if (!(dt >= floor_now)) {
            a->collapsed = 1, a->dt_bad = dt, a->floor_bad = floor_now;
            break;
        }
        const double h = sph_landing_dt(dt, a->t_stop - s->t); /* land on output times */
        stored = s->step + 1 - step0 >= a->steps || !(s->t + h < a->t_stop - a->eps) ||
                 (a->stop && *a->stop);
        for (int i = 0; i < s->nbodies; i++)
            s->bodies[i].want_F = stored;
        sph_sim_step(s, h);
        count_bound(s);
    }
    return (int)(s->step - step0);
}

void sph_sim_free(sph_sim *s)
{
    sph_contact_free(s);
    for (int i = 0; i < s->nbodies; i++)
        sph_body_free(&s->bodies[i]);
    free(s->bodies);
    free(s->dt_body_steps);
    s->bodies = NULL;
    s->dt_body_steps = NULL;
    s->nbodies = 0;
}
