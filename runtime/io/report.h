/* report.h — summary.html, a run's report page (report.c). */
#ifndef SPHRT_IO_REPORT_H
#define SPHRT_IO_REPORT_H

#include "csv.h"

/* The most rows of a table the page draws (sph_csv_read, sph_csv_table_add: and the last). */
enum { SPH_REPORT_POINTS = 2000 };

/* An expectation of the model as evaluated (NAN where it has no such number). */
typedef struct {
    const char *kind;      /* "period", "amplitude", "energy", "reference" */
    const char *text;      /* the model's line */
    double value, expected, max_abs_error, relative_error;
    double tolerance;      /* < 0: none (reported, never failed) */
    int pass;
} sph_report_expect;

/* A check of the stability monitor: the nearest to its limit the run came, and the limit. */
typedef struct {
    const char *key;       /* data-check: "J", "speed", "energy_growth" */
    const char *text;      /* what it checks */
    double seen, limit;    /* seen NAN: not checked yet */
    const char *rule;      /* "above" or "at most": how seen must stand to the limit */
} sph_report_margin;

/* An expectation drawn over its measurement plane's plot, at the times of the plane's table
 * rows: a reference's values; an expected period's sinusoid y = mid + amplitude sin(2 pi (t
 * - t0) / period) (the measured mid-line, half range and first crossing of the mid-line,
 * amplitude negative where it falls there); an expected amplitude's two lines, mid plus and
 * minus it (two curves). */
typedef struct {
    const char *kind;      /* "period", "amplitude", "reference" */
    const char *text;      /* the model's line */
    int plane, column;     /* its measurement plane, and the column of the plane's table */
    double *y;             /* a value per row of the plane's table (NAN: none there) */
    double period, mid, amplitude, t0; /* period: the sinusoid's numbers */
} sph_report_curve;

/* What the page shows: how the run stands, its expectations, and its CSV files as plots
 * (column 0 the time, the others a line each; every row of a table is drawn). */
typedef struct {
    const char *model;
    const char *status;    /* "running", "finished", "unstable", "stopped", "failed" */
    const char *message;   /* unstable: where and how; stopped: the signal; NULL: none */
    double time, end_time, wall_time; /* wall_time NAN: not known yet */
    long steps;
    const sph_report_expect *expects;
    int nexpects;
    const sph_csv_table *energies; /* NULL: none */
    const sph_csv_table *time_steps; /* time, mean time step of each output interval; NULL */
    /* what bounded the time step: each output interval's share of steps by bound (time and
     * a column per bound, named; NULL: none counted), and the steps each bound and each
     * body's bounds set over the run (ncounts names and steps, then nbodies of each) */
    const sph_csv_table *dt_bounds;
    const char *const *count_names;
    const long *counts;
    int nbounds, nbodies;
    const sph_report_margin *margins; /* the stability monitor's checks, nmargins of them */
    int nmargins;
    const sph_csv_table *planes;   /* nplanes measurement planes, */
    const char *const *plane_names; /* their names */
    int nplanes;
    const sph_report_curve *curves; /* expectations drawn over the planes, ncurves */
    int ncurves;
    /* many processes: each one's own particles, halo particles, bytes sent per step and
     * seconds waited for the halo (4 numbers per process, nprocesses; NULL: one process) */
    const double *processes;
    int nprocesses;
    int dim;               /* 2: the planes' uy and fy (zero) are not drawn */
} sph_report;

/* The page at path, written whole (sph_open_whole); 0, or -1 after reporting. */
int sph_report_write(const char *path, const sph_report *r);

#endif
