/* run_state.h — the state of a generated program's run (run.c), which its checkpoint records
 * (run_checkpoint.c) save and restore. */
#ifndef SPHRT_RUN_STATE_H
#define SPHRT_RUN_STATE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expect.h"
#include "monitor.h"
#include "options.h"
#include "io/checkpoint.h"
#include "io/compat.h"
#include "io/csv.h"
#include "io/report.h"
#include "par/team.h"
#include "scene/model.h"
#include "scene/sim.h"

typedef struct {
    const sph_model *m;
    sph_options opt;
    double t_end, t_out;
    double next_out;             /* the next output time */
    double t_frames, next_frame; /* particle files every t_frames (at output times) */
    double t_checkpoint;         /* --checkpoint or the scene's: the interval, 0 none; */
    double next_checkpoint;      /* the next one at the first output from then */
    double wall_before;          /* a resumed run: the wall time of the run up to its checkpoint, */
    double t_resumed;            /* and the time and step it resumed at */
    long step_resumed;
    sph_sim sim;
    long particles, pairs;       /* of all bodies */
    sph_csv energies;
    sph_csv *measure_csv;
    int nmeasures;
    sph_compat compat;   /* SoliDualSPHysics' files, when m->compat_outputs */
    sph_record rec;
    char ***frame_files; /* per body: the frame files listed in its pvd */
    double *frame_times;
    int nframes;
    double wall0;         /* the wall clock when this process started the run */
    double step_seconds;
    sph_team team;        /* the threads of the steps (team.h) */
    double setup_seconds; /* particles, neighbours, tables, (device upload) */
    double check_seconds; /* the monitor's periodic checks (those before outputs count as */
    double output_seconds;/* output time, with the outputs and a device's copy for them) */
    sph_monitor mon;      /* the stability monitor: its checks (summary.json), */
    double stretch_seen;  /* the smallest principal stretch they saw, */
    long checks;          /* how many there were, */
    long device_checks;   /* and how many a device target's sums answered alone */
    /* the mean time step of each output interval since this process started the run: rows
     * of time and step ((t - t0) / (step - step0) over the interval), for the report page */
    sph_csv_table time_steps;
    double dt_t0;
    long dt_step0;        /* -1: no output yet */
    /* the share of each interval's steps each bound set (sim.dt_bound_steps over the
     * interval; rows of time and SPH_DT_NBOUNDS shares), and the counts at its start */
    sph_csv_table dt_bounds;
    long dt_bounds0[SPH_DT_NBOUNDS];
    double summary_wall;  /* process 0: when summary.json was last written while running, */
    double summary_cost;  /* and how long writing it (and the page) took */
    char unstable[512];
    char errors[512];     /* the declared expectations' errors, for the final line */
} run_state;

/* A string of fmt with its two %s filled in (malloc'd). */
static inline char *joinf(const char *fmt, const char *a, const char *b)
{
    size_t n = strlen(fmt) + strlen(a) + strlen(b) + 32;
    char *s = malloc(n);
    snprintf(s, n, fmt, a, b);
    return s;
}

/* The file of body's frame k, in OUT/particles/ (and listed so in the body's .pvd). */
static inline void frame_file(char *out, size_t len, const char *body, int k)
{
    snprintf(out, len, "%s_%04d.vtu", body, k);
}

/* run_checkpoint.c: the run's own records of a checkpoint (output and checkpoint times,
 * frames, the expectations' time series, timers, the output files' lengths). */
/* Whether a checkpoint is due at this output, and the next one's time. */
int sph_run_checkpoint_due(run_state *r);
/* The whole state of the run into OUT/checkpoint.bin; -1 after reporting. */
int sph_run_write_checkpoint(run_state *r);
/* Before the outputs are opened: the files they keep, cut back to their checkpoint length. */
int sph_run_resume_files(const sph_ckpt *c, const run_state *r);
/* After the outputs are opened: times, frames, series, timers. */
int sph_run_resume(const sph_ckpt *c, run_state *r);

/* How a run stands for its report page: the status and message (where it went unstable, the
 * signal; NULL: none), the wall time (NAN while running), the expectations' results, and on
 * many processes, each process's own particles, halo particles, bytes sent per step and
 * seconds waited for the halo (4 numbers per process; NULL: none). */
typedef struct {
    const char *status, *message;
    double wall;
    const sph_report_expect *expects;
    int nexpects;
    const double *processes;
    int nprocesses;
} sph_run_outcome;

/* run_report.c: summary.html in the output folder (process 0, with summary.json): how the run
 * stands, the CSV files read back; 0, or -1 after reporting. */
int sph_run_report(const run_state *r, const sph_run_outcome *o);

#endif
