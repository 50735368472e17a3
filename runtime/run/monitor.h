/* monitor.h — the stability monitor's checks (monitor.c). */
#ifndef SPHRT_RUN_MONITOR_H
#define SPHRT_RUN_MONITOR_H

#include <stddef.h>

#include "scene/sim.h"

/* Stability checks; returns 0 when the state is sane, otherwise fills msg. */
typedef struct {
    double e_ref;     /* largest total energy seen (for runaway detection) */
    /* how near the checks came to their limits, since this process started the run: */
    long scans;       /* the checks that looked at every particle (sph_monitor_check) */
    double j_min;     /* of those, the smallest det F (the limit: above 0), */
    double speed;     /* the largest |v| / c0 (the limit: 10) */
    long sums;        /* the checks that compared the energy, */
    double growth;    /* and the largest ratio of the total energy to the largest before it
                       * (the limit: 1e6; 0 while that was 0) */
} sph_monitor;
/* The limits of the checks (monitor.c): speed over c0, growth of the total energy. */
#define SPH_MONITOR_SPEED 10.0
#define SPH_MONITOR_GROWTH 1e6
int sph_monitor_check(sph_monitor *mon, const sph_sim *s, char *msg, size_t len);
/* 0 when every displacement, velocity and acceleration is finite, otherwise 1 with msg as
 * sph_monitor_check's (step, time, body, particle, what; the initial state, a collapsed step). */
int sph_monitor_finite(const sph_sim *s, char *msg, size_t len);
/* "step S, t = T s, body 'B', particle P (reference position ...)" at the start of msg (P: on
 * many processes the global id); what snprintf returns. */
int sph_monitor_where(char *msg, size_t len, const sph_sim *s, const sph_body *b, int particle);
/* On many processes: the lowest process where `found`, whose msg every process then gets;
 * 1 when there is one.  On one process: found.  Collective. */
int sph_monitor_share(const sph_sim *s, int found, char *msg, size_t len);
/* The same checks from a device target's per-body sums (sph_model.monitor): 0 when they show
 * a sane state (*stretch then gets the smallest principal stretch), 1 when the state must be
 * copied to the host and looked at with sph_monitor_check.  Collective: on many processes
 * the sums of all. */
int sph_monitor_glance(sph_monitor *mon, const sph_sim *s, const sph_monitor_sums *sums,
                       double *stretch);

#endif
