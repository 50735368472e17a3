/* The number of threads a run's steps take (runtime/par/team.h), on made-up machines: a step's
 * wall time and the share of its threads' time the process gets, as functions of the
 * thread count and of the time, with noise; batches of 20 steps as the run takes them. */
#include <math.h>
#include <stdio.h>

#include "par/team.h"
#include "unit_check.h"

typedef struct {
    double ms[9];    /* ms per step on 1..8 threads, */
    double share[9]; /* the share of the threads' time the process gets, */
    double idle[9];  /* and the machine's idle cores meanwhile */
} machine;

static int idle_known = 1; /* 0: as where /proc/stat cannot be read */

/* What a run of `seconds` on machine `at(clock)` does; returns the count at the end. */
typedef const machine *(*schedule)(double clock);

static double noise(void) { return 1 + 0.1 * (urand() - 0.5); } /* +-5 % */

static int run(sph_team *t, schedule at, double seconds, double probe, int *count_at_probe)
{
    double clock = 0;
    while (clock < seconds) {
        const machine *m = at(clock);
        const int n = sph_team_threads(t);
        const long batch = sph_team_batch(t), steps = batch < 20 ? batch : 20;
        const double wall = steps * m->ms[n] * 1e-3 * noise();
        const double cpu = wall * n * fmin(1.0, m->share[n] * noise());
        clock += wall;
        sph_team_after(t, steps, wall, cpu, idle_known ? wall * m->idle[n] : -1, clock);
        if (count_at_probe && clock >= probe && *count_at_probe == 0)
            *count_at_probe = sph_team_threads(t);
    }
    return t->now;
}

/* Two cores. Idle: twice as fast on two threads, all of their time. Busy (a spinning
 * program per core): two threads 1.9 times as slow as one, half their time each. */
static const machine IDLE2 = {{0, 1.0, 0.52}, {0, 1.0, 0.98}, {0, 0.95, 0.02}};
static const machine BUSY2 = {{0, 1.3, 2.5}, {0, 0.85, 0.5}, {0, 0, 0}};
/* Busy, but the second thread still helps (a lighter load). */
static const machine HALF2 = {{0, 1.0, 0.7}, {0, 0.95, 0.6}, {0, 0.3, 0.1}};
/* Eight threads on four free cores. */
static const machine FOUR8 = {{0, 8.0, 4.0, 2.8, 2.0, 2.6, 2.5, 2.4, 2.4},
                              {0, 1, 1, 1, 1, 0.8, 0.67, 0.57, 0.5},
                              {0, 3, 2, 1, 0, 0, 0, 0, 0}};

static const machine *idle(double c) { (void)c; return &IDLE2; }
static const machine *busy(double c) { (void)c; return &BUSY2; }
static const machine *half(double c) { (void)c; return &HALF2; }
static const machine *four(double c) { (void)c; return &FOUR8; }
/* Idle, then busy from 5 s to 25 s, then idle again. */
static const machine *comes_and_goes(double c) { return c >= 5 && c < 25 ? &BUSY2 : &IDLE2; }

int main(void)
{
    sph_team t;

    sph_team_init(&t, 2, 0);
    run(&t, idle, 60, 0, NULL);
    check(t.now == 2, "idle: stays on 2 threads", t.now, 2);
    check(t.trials == 0, "idle: never tries another count (no cost)", t.trials, 0);

    sph_team_init(&t, 2, 0);
    run(&t, busy, 60, 0, NULL);
    check(t.now == 1, "busy: 1 thread", t.now, 1);
    const double mean = t.thread_seconds / t.step_seconds;
    check(mean < 1.05, "busy: mean threads over the run's steps", mean, 1.05);
    check(t.trials <= 2, "busy: trials in 60 s (no core idle: 2 threads every 30 s)", t.trials, 2);
    check(t.changes == 1, "busy: changes", t.changes, 1);

    idle_known = 0; /* the machine's idle time unknown: 2 threads tried from time to time */
    sph_team_init(&t, 2, 0);
    run(&t, busy, 60, 0, NULL);
    check(t.now == 1, "busy, idle time unknown: 1 thread", t.now, 1);
    check(t.trials <= 7, "busy, idle time unknown: trials in 60 s (waits 1, 2, 4 .. 30 s)",
          t.trials, 7);
    check(t.thread_seconds / t.step_seconds < 1.05, "busy, idle time unknown: mean threads",
          t.thread_seconds / t.step_seconds, 1.05);
    idle_known = 1;

    sph_team_init(&t, 2, 0);
    int during = 0;
    run(&t, comes_and_goes, 60, 20, &during);
    check(during == 1, "load from 5 s to 25 s: 1 thread at 20 s", during, 1);
    check(t.now == 2, "load gone: 2 threads again at 60 s", t.now, 2);
    check(t.changes == 2, "load comes and goes: changes", t.changes, 2);

    sph_team_init(&t, 2, 0);
    run(&t, half, 60, 0, NULL);
    check(t.now == 2, "lighter load, 2 threads still faster: stays on 2", t.now, 2);
    check(t.trials <= 8, "lighter load: trials in 60 s", t.trials, 8);

    sph_team_init(&t, 8, 0);
    run(&t, four, 60, 0, NULL);
    check(t.now == 4, "8 threads, 4 free cores: 4 threads", t.now, 4);

    sph_team_init(&t, 2, 1);
    run(&t, busy, 10, 0, NULL);
    check(t.now == 2 && t.trials == 0, "--threads 2: 2 threads, no trial, even when busy",
          t.trials, 0);

    sph_team_init(&t, 1, 0);
    run(&t, busy, 10, 0, NULL);
    check(t.now == 1 && t.trials == 0, "one thread at most: nothing to choose", t.trials, 0);

    printf("%d failure(s)\n", failures);
    return failures != 0;
}
