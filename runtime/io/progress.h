/* progress.h — the progress line of a run (progress.c). */
#ifndef SPHRT_IO_PROGRESS_H
#define SPHRT_IO_PROGRESS_H

/* Progress lines, unless quiet: on a terminal (stderr is one) rewritten in place at 4 Hz,
 * "\r[ 42.0%] t = 0.1234 s  dt = 2.1e-06 s  1234 steps/s  ETA 0:00:12" within its width;
 * in a log (stdout is not a terminal) "NAME: [ 42.0%] t = ...  ETA 0:00:12  (0:00:09)" (the
 * wall time so far) every log_every seconds (0: none), within 80 columns. */
typedef struct {
    int enabled;
    double t_end;
    double wall_start, wall_last;
    long step_last;
    double log_every, log_last;
    long log_step;
} sph_progress;
void sph_progress_start(sph_progress *p, double t_end, int quiet, double log_every);
void sph_progress_update(sph_progress *p, const char *name, double t, double dt, long step);
void sph_progress_finish(sph_progress *p);

#endif
