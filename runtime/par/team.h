/* team.h — how many threads a run's steps take: OpenMP's count on a machine that gives the
 * program its cores, fewer while other work takes them.
 *
 * A step is a few short parallel passes, each ending at a barrier where every thread waits
 * for the slowest.  When other programs hold the cores, one thread of the team is often off
 * its core, and the others wait (or spin, taking time from the program holding the core):
 * the cantilever beam on a busy 2-core machine took 2.4 times as long on 2 threads as on
 * one (bench/busy-machine).  So the run watches the share of its threads' time it gets,
 * the process's CPU time over wall time times threads, batch by batch of steps: when it
 * gets less than SPH_TEAM_BUSY of it, it times windows of steps on half the threads against
 * windows on the present count, interleaved, and keeps the faster (the batches of a trial
 * cut to a window's length: a count that runs slowly is tried briefly).  Below OpenMP's
 * count it tries twice the threads when the machine has had half a core idle or more over a
 * window (the load has gone; where the machine's idle time cannot be read, from time to
 * time), and otherwise every SPH_TEAM_WAIT_MAX seconds (where the scheduler shares the
 * cores by thread, more threads that wait without spinning can get more of a busy machine).  A trial that changes nothing doubles the wait before the next one (up to
 * SPH_TEAM_WAIT_MAX seconds), so a machine that gives the program its cores sees no trial
 * at all, and one that stays busy one every SPH_TEAM_WAIT_MAX seconds.  The results do not depend on the count: every sum of the passes is taken in an
 * order fixed by the particles, not by the threads.
 *
 * The decisions are plain arithmetic on the timings given (sph_team_after), so they are
 * tested with made-up timings (tests/unit/test_team.c); run.c reads the clocks and sets
 * the count. */
#ifndef SPHRT_TEAM_H
#define SPHRT_TEAM_H

#define SPH_TEAM_BUSY 0.75     /* the share of the threads' time below which to try fewer */
#define SPH_TEAM_WINDOW 0.1    /* seconds: a timed window (whole batches of steps) */
#define SPH_TEAM_WINDOWS 4     /* windows in a trial: the trial count and the present one */
#define SPH_TEAM_GAIN 0.05     /* the trial count must be this much faster per step */
#define SPH_TEAM_WAIT 1.0      /* seconds: the wait before a trial after a change, */
#define SPH_TEAM_WAIT_MAX 30.0 /* doubled after each trial that changed nothing */

typedef struct {
    int max;            /* OpenMP's count (OMP_NUM_THREADS or the cores) or --threads */
    int fixed;          /* --threads N: the count never changes */
    int now;            /* the count the run keeps */
    int trial;          /* 0, or the count tried against `now` */
    int window;         /* during a trial: the window under way (0 .. SPH_TEAM_WINDOWS - 1) */
    double trial_seconds[2]; /* seconds and steps on `now` [0] and on `trial` [1] */
    long trial_steps[2];
    double win_wall, win_cpu, win_idle; /* the window under way: wall, CPU, idle seconds, */
    long win_steps;
    double per_step;    /* wall seconds per step on `now`, the last window outside trials */
    double next_trial;  /* the wall time (sph_team_after's clock) of the next trial */
    double wait;        /* the wait after the next trial that changes nothing */
    /* what the run reports (summary.json) */
    int changes;        /* how often the count changed */
    int trials;         /* how many trials there were */
    double step_seconds, thread_seconds; /* wall in steps; and times the count */
} sph_team;

/* max: OpenMP's count; fixed: the user gave it (--threads N). */
void sph_team_init(sph_team *t, int max, int fixed);
/* The count the next batch of steps runs on. */
int sph_team_threads(const sph_team *t);
/* The most steps the next batch should take: during a trial about a window's worth (a trial
 * on a count that runs slowly costs little), otherwise no limit (a large number). */
long sph_team_batch(const sph_team *t);
/* After a batch of `steps` steps on sph_team_threads(t) threads that took `wall` seconds of
 * wall time and `cpu` seconds of the process's CPU time, while the machine's cores were idle
 * for `idle` seconds in all (negative: not known), at wall time `clock` (any origin). */
void sph_team_after(sph_team *t, long steps, double wall, double cpu, double idle,
                    double clock);

#endif
