/* monitor.c — the stability monitor: a separate pass over the state, run every few steps
 * and before every output, so that a run going unstable stops with a diagnosis and the last
 * good output kept.  It looks for: non-finite displacement, velocity or acceleration;
 * det F <= 0 (a particle turned inside out); velocities beyond ten times the sound speed;
 * and total energy growing a millionfold between two checks.
 *
 * A device target first sums what the checks need on the device (sph_model.monitor), so that
 * a periodic check moves a few numbers instead of the whole state; only when those show
 * something wrong does the runtime copy the state and look at it here, particle by particle,
 * to name what went wrong and where. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "measure.h"
#include "monitor.h"
#include "core/tensor3.h"
#include "par/par.h"
#include "scene/body.h"
#include "scene/model.h"
#include "scene/sim.h"

typedef struct {
    int particle;
    char what[96];
    double value;
} finding;

/* Whether a scalar state variable of particle i's law (a temperature, a damage, a plastic
 * strain: those the VTU files name) is not finite: named first, as the likely cause of what
 * follows from it. */
static int state_not_finite(const sph_body *b, int i, finding *f)
{
    const int ns = b->desc->nstate;
    for (int k = 0; k < ns && b->state && b->desc->state_names; k++) {
        const double x = b->state[(size_t)i * ns + k];
        if (b->desc->state_names[k] && !isfinite(x)) {
            f->particle = i, f->value = x;
            snprintf(f->what, sizeof f->what, "the law's %s is not finite",
                     b->desc->state_names[k]);
            return 1;
        }
    }
    return 0;
}

/* Whether particle i's law state, displacement, velocity or acceleration is not finite (f
 * says which). */
static int not_finite(const sph_body *b, int i, finding *f)
{
    if (state_not_finite(b, i, f))
        return 1;
    for (int k = 0; k < b->dim; k++) {
        const size_t e = (size_t)i * b->dim + k;
        const double u = b->u[e], v = b->v[e], a = b->a[e];
        if (!isfinite(u) || !isfinite(v) || !isfinite(a)) {
            f->particle = i, f->value = !isfinite(u) ? u : !isfinite(v) ? v : a;
            snprintf(f->what, sizeof f->what, "%s", !isfinite(u) ? "displacement is not finite"
                                                    : !isfinite(v) ? "velocity is not finite"
                                                                   : "acceleration is not finite");
            return 1;
        }
    }
    return 0;
}

/* Whether a particle of body b fails a check (f says which); seen[0] gets the largest -det F,
 * seen[1] the largest |v|^2 / c0^2 of those it looked at. */
static int scan_body(const sph_body *b, finding *f, double seen[2])
{
    const int D = b->dim;
    const double c2 = b->c0 * b->c0;
    const double vlim2 = SPH_MONITOR_SPEED * SPH_MONITOR_SPEED * c2;
    for (int i = 0; i < b->nown; i++) {
        if (not_finite(b, i, f))
            return 1;
        double v2 = 0;
        for (int k = 0; k < D; k++)
            v2 += b->v[(size_t)i * D + k] * b->v[(size_t)i * D + k];
        const double J = sph_det3(b->F + (size_t)i * 9);
        seen[0] = fmax(seen[0], -J), seen[1] = fmax(seen[1], v2 / c2);
        if (!(J > 0)) {
            f->particle = i, f->value = J;
            snprintf(f->what, sizeof f->what, "det F <= 0 (particle inverted)");
            return 1;
        }
        if (v2 > vlim2) {
            f->particle = i, f->value = sqrt(v2);
            snprintf(f->what, sizeof f->what, "speed above %g c0 (velocity runaway)",
                     SPH_MONITOR_SPEED);
            return 1;
        }
    }
    return 0;
}

/* The fastest particle of a body and its speed. */
static int fastest(const sph_body *b, double *speed)
{
    const int D = b->dim;
    int best = 0;
    double v2max = -1;
    for (int i = 0; i < b->nown; i++) {
        double v2 = 0;
        for (int k = 0; k < D; k++)
            v2 += b->v[(size_t)i * D + k] * b->v[(size_t)i * D + k];
        if (v2 > v2max)
            v2max = v2, best = i;
    }
    *speed = sqrt(v2max);
    return best;
}

/* "step S, t = T s, body 'B', particle P (reference position ...)" at the start of msg. */
int sph_monitor_where(char *msg, size_t len, const sph_sim *s, const sph_body *b, int particle)
{
    char id[48], at[96]; /* on many processes the global id (partition.h), the same on any number */
    if (b->gid)
        snprintf(id, sizeof id, "global id %lld", (long long)b->gid[particle]);
    else
        snprintf(id, sizeof id, "%d", particle);
    sph_reference_position(b, particle, at, sizeof at);
    return snprintf(msg, len, "step %ld, t = %.6g s, body '%s', particle %s (reference position "
                              "%s)",
                    s->step, s->t, b->desc->name, id, at);
}

/* On many processes: the lowest process where `found`, whose msg every process then gets;
 * 1 when there is one.  On one process: found. */
int sph_monitor_share(const sph_sim *s, int found, char *msg, size_t len)
{
    const sph_par *par = s->par;
    if (par->size == 1)
        return found;
    double first = found ? par->rank : par->size;
    par->min(&first, 1);
    if (first >= par->size)
        return 0;
    char buf[1024] = "";
    if (par->rank == (int)first)
        snprintf(buf, sizeof buf, "%s", msg);
    par->bcast(buf, sizeof buf, (int)first);
    snprintf(msg, len, "%s", buf);
    return 1;
}

/* A finding as msg: where, what, and its value. */
static void report(char *msg, size_t len, const sph_sim *s, const sph_body *b, const finding *f)
{
    const int n = sph_monitor_where(msg, len, s, b, f->particle);
    if (n >= 0 && (size_t)n < len)
        snprintf(msg + n, len - (size_t)n, ": %s (value %g)", f->what,
                 isnan(f->value) ? fabs(f->value) : f->value); /* "nan", not "-nan" */
}

/* A scan's smallest det F and largest |v| / c0 (seen, over the processes) into the margins. */
static void note_scan(sph_monitor *mon, const sph_sim *s, double seen[2])
{
    s->par->max(seen, 2);
    const double j = -seen[0], speed = sqrt(seen[1]);
    mon->j_min = mon->scans ? fmin(mon->j_min, j) : j;
    mon->speed = mon->scans ? fmax(mon->speed, speed) : speed;
    mon->scans++;
}

/* The total energy e at a check against the largest before it: its ratio into the margins;
 * whether it grew beyond the limit (or is not finite). */
static int energy_runaway(sph_monitor *mon, double e)
{
    if (mon->e_ref > 0)
        mon->growth = fmax(mon->growth, e / mon->e_ref);
    mon->sums++;
    return !isfinite(e) || (mon->e_ref > 0 && e > SPH_MONITOR_GROWTH * mon->e_ref);
}

int sph_monitor_check(sph_monitor *mon, const sph_sim *s, char *msg, size_t len)
{
    int found = 0;
    double seen[2] = {-INFINITY, 0};
    for (int ib = 0; ib < s->nbodies && !found; ib++) {
        finding f;
        if ((found = scan_body(&s->bodies[ib], &f, seen)))
            report(msg, len, s, &s->bodies[ib], &f);
    }
    note_scan(mon, s, seen); /* (with a finding: up to the particle that failed) */
    if (sph_monitor_share(s, found, msg, len))
        return 1;
    double e_total = 0, e_most = -1, *e = calloc((size_t)s->nbodies + 1, sizeof *e);
    int most = 0;
    if (!e)
        return 0; /* (out of memory: no energy check this time) */
    for (int ib = 0; ib < s->nbodies; ib++) {
        double es, ek;
        sph_body_energies(&s->bodies[ib], &es, &ek);
        e[ib] = es + ek;
    }
    s->par->sum(e, s->nbodies); /* (each body's, over the processes) */
    for (int ib = 0; ib < s->nbodies; ib++) {
        e_total += e[ib];
        if (!(e[ib] <= e_most)) /* also takes a non-finite energy */
            e_most = e[ib], most = ib;
    }
    free(e);
    if (energy_runaway(mon, e_total)) {
        /* Named like the other findings: the body with the most energy and its fastest
         * particle (on many processes, that of the process where it is fastest). */
        const sph_body *b = &s->bodies[most];
        double speed, top;
        const int i = fastest(b, &speed);
        top = speed;
        s->par->max(&top, 1);
        int n = sph_monitor_where(msg, len, s, b, i);
        if (n >= 0 && (size_t)n < len)
            snprintf(msg + n, len - (size_t)n,
                     ": total energy %g grew more than a millionfold since the last check (%g): "
                     "energy runaway (value: speed %g of the fastest particle of the body with "
                     "the most energy)",
                     e_total, mon->e_ref, speed);
        sph_monitor_share(s, speed == top, msg, len);
        return 1;
    }
    if (e_total > mon->e_ref)
        mon->e_ref = e_total;
    return 0;
}

int sph_monitor_finite(const sph_sim *s, char *msg, size_t len)
{
    int found = 0;
    for (int ib = 0; ib < s->nbodies && !found; ib++)
        for (int i = 0; i < s->bodies[ib].nown && !found; i++) {
            finding f;
            if ((found = not_finite(&s->bodies[ib], i, &f)))
                report(msg, len, s, &s->bodies[ib], &f);
        }
    return sph_monitor_share(s, found, msg, len);
}

int sph_monitor_glance(sph_monitor *mon, const sph_sim *s, const sph_monitor_sums *sums,
                       double *stretch)
{
    double e_total = 0, l2 = 1.0, most[2] = {0, -1.0}; /* (a check failed; -stretch^2) */
    for (int ib = 0; ib < s->nbodies; ib++) {
        most[0] = fmax(most[0], sums[ib].bad);
        e_total += sums[ib].energy;
        l2 = fmin(l2, sums[ib].stretch2);
    }
    if (s->par->size > 1) { /* (every process's sums; the energy body by body, in order) */
        most[1] = -l2;
        s->par->max(most, 2);
        l2 = -most[1];
        double *e = malloc(((size_t)s->nbodies + 1) * sizeof *e);
        for (int ib = 0; e && ib < s->nbodies; ib++)
            e[ib] = sums[ib].energy;
        if (e) {
            s->par->sum(e, s->nbodies);
            e_total = 0;
            for (int ib = 0; ib < s->nbodies; ib++)
                e_total += e[ib];
        }
        free(e);
    }
    if (most[0] > 0)
        return 1;
    if (energy_runaway(mon, e_total))
        return 1;
    if (e_total > mon->e_ref)
        mon->e_ref = e_total;
    *stretch = sqrt(fmax(l2, 0.0));
    return 0;
}
