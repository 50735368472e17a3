/* run.c — sph_main: the time loop of a generated program.
 *
 * Exit codes: 0 success; 1 an expectation of the model failed; 2 bad command line;
 * 3 the run went unstable (stopped by the monitor; the last good output is kept);
 * 4 output could not be written (or the output folder holds an earlier run's outputs, without
 * --overwrite) or set-up failed; 6 a run with checkpoints stopped by a signal, after writing
 * one; 7 a run without checkpoints stopped by a signal (5, a CUDA failure, is cuda/check.h's).
 *
 * A run never leaves a mix of two runs or a part of a file: summary.json says "running"
 * from before the first output, and how the run ended at its end; the files written whole
 * (frames, .pvd lists, summary.json) are renamed into place once complete, the CSV files grow
 * by whole rows; a folder that holds another run's outputs is refused unless --overwrite
 * removes them (a run resumed with --restart continues its own). */
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "expect.h"
#include "main.h"
#include "measure.h"
#include "monitor.h"
#include "options.h"
#include "partition_report.h"
#include "run_state.h"
#include "setup.h"
#include "sim.h"
#include "time_step.h"
#include "contact/contact.h"
#include "core/clock.h"
#include "core/defs.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "core/profile.h"
#include "io/checkpoint.h"
#include "io/compat.h"
#include "io/csv.h"
#include "io/fsutil.h"
#include "io/json.h"
#include "io/profile_report.h"
#include "io/progress.h"
#include "io/vtu.h"
#include "pairs/stencil.h"
#include "par/par.h"
#include "par/team.h"
#include "scene/body.h"
#include "scene/model.h"
#include "scene/sim.h"
#include "scene/step_sums.h"

/* The stability monitor's periodic check: every this many steps (and before every output). */
enum { CHECK_EVERY = 20 };

/* The smallest h/c0 of the bodies: the time a wave takes to cross a particle's support. */
static double min_h_over_c0(const run_state *r)
{
    double lo = INFINITY;
    for (int i = 0; i < r->sim.nbodies; i++)
        lo = fmin(lo, r->sim.bodies[i].h / r->sim.bodies[i].c0);
    return lo;
}

/* The largest fixed time step, in units of the smallest h/c0, at which the explicit step is
 * stable: 1 (eq. 64), and where a body has the quadratic gradient, whose fastest modes are
 * about 2.5 times eq. 63's, what its runs were stable at (0.4 in 2D, 0.35 in 3D:
 * bench/bending/diagnose; the compiler warns of an adaptive cfl above it). */
static double stable_courant(const run_state *r)
{
    for (int i = 0; i < r->sim.nbodies; i++)
        if (r->sim.bodies[i].desc->quadratic)
            return r->m->dim == 3 ? 0.35 : 0.4;
    return 1.0;
}

/* The floor of the adaptive time step, dtmin times the smallest h/c0: a step chosen below it
 * has collapsed.  A fixed time step has none: however small, it is the user's choice and
 * stable (one too large is warned of before the run and stopped by the monitor). */
static double dt_floor(const run_state *r)
{
    return r->m->dt_fixed > 0 ? 0.0 : r->m->dtmin_coef * min_h_over_c0(r);
}

/* A run that gets SIGTERM (a batch system's notice) or SIGINT stops after the step under
 * way (on the device: after the batch of steps queued, at most 20), writes summary.json
 * ("stopped") and, with checkpoints, a checkpoint, and exits (SPH_EXIT_STOPPED with a
 * checkpoint, SPH_EXIT_SIGNALLED without); a second signal ends it at once.  One notice
 * often comes twice within microseconds: `timeout` and batch systems signal the process and
 * then its process group, and a process that takes the first at once on another core sees
 * the second as a new one.  A signal within STOP_REPEAT_SECONDS of the first is that
 * notice again and changes nothing. */
enum { STOP_REPEAT_SECONDS = 1 };
static volatile sig_atomic_t stop_signal;
static struct timespec stop_when; /* when the first came (CLOCK_MONOTONIC) */

static void on_stop_signal(int sig)
{
    struct timespec now; /* (clock_gettime, signal and raise are async-signal-safe) */
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (!stop_signal) {
        stop_when = now;
        stop_signal = sig;
        return;
    }
    const double since = (double)(now.tv_sec - stop_when.tv_sec) +
                         1e-9 * (double)(now.tv_nsec - stop_when.tv_nsec);
    if (since < STOP_REPEAT_SECONDS)
        return;
    signal(sig, SIG_DFL); /* a second notice: the default action, at once */
    raise(sig);
}

static const char *stop_name(void)
{
    return stop_signal == SIGINT ? "SIGINT" : "SIGTERM";
}

static void catch_stop_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaddset(&sa.sa_mask, SIGTERM); /* one handler at a time */
    sigaddset(&sa.sa_mask, SIGINT);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGINT, &sa, NULL);
}

/* ------------------------------------------------------------------ output */

/* The columns of energies.csv after time, one row each below: a body's column, named
 * <body>_<name>, stands in the body's block (BLOCK: strain and kinetic energy, body by body)
 * or, after the blocks, with those of the other bodies it applies to (EACH); a SCENE column
 * follows those, once.  compat.c reads the strain, kinetic and fracture columns by place:
 * new columns go after them.  The kind says which of the two totals a column joins (the
 * kinetic energy, or the rest); TOTAL is their sum. */
typedef enum { BLOCK, EACH, SCENE } energy_layout;
typedef enum { HELD, KINETIC, DISSIPATED, TOTAL, WITHIN } energy_kind; /* WITHIN: a part of
                                                                          * another column's */

typedef struct {
    const char *name;
    energy_layout layout;
    energy_kind kind;
    int (*applies)(const sph_model *m, int i); /* body i; -1: the scene */
    /* NULL: the total; e holds each body's strain and kinetic energy (e[2i], e[2i+1]),
     * from one pass over its particles */
    double (*value)(const sph_sim *s, int i, const double *e);
} energy_column;

static int every(const sph_model *m, int i) { return (void)m, (void)i, 1; }
static int with_fracture(const sph_model *m, int i) { return m->bodies[i].fracture != NULL; }
static int with_dissipation(const sph_model *m, int i) { return m->bodies[i].dissipation > 0; }
static int with_temperature(const sph_model *m, int i) { return m->bodies[i].temperature > 0; }
static int with_contact(const sph_model *m, int i) { return (void)i, m->contact != NULL; }

/* The contacts' stored (which 0) or dissipated (1) energy. */
static double contact_energy(const sph_sim *s, int which)
{
    double e[2];
    sph_contact_energies(s, &e[0], &e[1]);
    return e[which];
}

static double strain(const sph_sim *s, int i, const double *e) { return (void)s, e[2 * i]; }
static double kinetic(const sph_sim *s, int i, const double *e) { return (void)s, e[2 * i + 1]; }
/* (the columns below are this process's share on many processes, summed by record) */
static double fracture(const sph_sim *s, int i, const double *e)
{
    return (void)e, sph_fracture_energy(&s->bodies[i]);
}
static double plastic(const sph_sim *s, int i, const double *e)
{
    return (void)e, sph_dissipated_energy(&s->bodies[i]);
}
static double thermal(const sph_sim *s, int i, const double *e)
{
    return (void)e, sph_thermal_energy(&s->bodies[i]);
}

/* A body's step sum k, x on this process, as a row of energies.csv adds it up over the
 * processes: a sum, each process's share; a maximum or minimum, the scene's, on process 0
 * alone (every process asks: each holds its own until the next time step's exchange,
 * run/sim.c). */
static double step_sum_share(const sph_sim *s, int k, double x)
{
    const int r = sph_step_sum_reduce(k);
    if (r == SPH_REDUCE_ADD)
        return x;
    x = r == SPH_REDUCE_MIN ? -x : x;
    s->par->max(&x, 1);
    return s->par->rank == 0 ? (r == SPH_REDUCE_MIN ? -x : x) : 0;
}

/* The columns of the step sums (scene/step_sums.h): for each row, whether body i has it (a
 * row that is no column: never) and its value. */
#define STEP_SUM_COLUMN(member, SLOT, reduce, initial, saved, column, kind, when)               \
    static int has_##member(const sph_model *m, int i)                                        \
    {                                                                                          \
        const sph_body_desc *d = &m->bodies[i];                                                \
        return (void)m, (void)d, (when);                                                       \
    }                                                                                          \
    static double sum_##member(const sph_sim *s, int i, const double *e)                      \
    {                                                                                          \
        return (void)e, step_sum_share(s, SPH_STEP_SUM_##member, s->bodies[i].member);        \
    }
SPH_STEP_SUMS(STEP_SUM_COLUMN)
#undef STEP_SUM_COLUMN

static double contact(const sph_sim *s, int i, const double *e)
{
    return (void)i, (void)e, contact_energy(s, 0);
}
static double contact_lost(const sph_sim *s, int i, const double *e)
{
    return (void)i, (void)e, contact_energy(s, 1);
}

static const energy_column ENERGY_COLUMNS[] = {
    {"strain", BLOCK, HELD, every, strain},
    {"kinetic", BLOCK, KINETIC, every, kinetic},
    {"fracture", EACH, HELD, with_fracture, fracture}, /* crack surface energy */
    {"plastic", EACH, DISSIPATED, with_dissipation, plastic}, /* the material law's */
    /* the heat of a law with a temperature: a part of what it dissipated, not added again */
    {"thermal", EACH, WITHIN, with_temperature, thermal},
    /* the step sums' (scene/step_sums.h): viscous, artificial viscosity's */
#define STEP_SUM_ROW(member, SLOT, reduce, initial, saved, column, kind, when) \
    {column, EACH, kind, has_##member, sum_##member},
    SPH_STEP_SUMS(STEP_SUM_ROW)
#undef STEP_SUM_ROW
    {"contact", SCENE, HELD, with_contact, contact},
    /* what the contacts' damping and friction took */
    {"contact_dissipated", SCENE, DISSIPATED, with_contact, contact_lost},
    {"total", SCENE, TOTAL, every, NULL},
};
enum { ENERGY_ROWS = sizeof ENERGY_COLUMNS / sizeof *ENERGY_COLUMNS };

/* A column of energies.csv: its row and its body (-1: the scene). */
typedef struct {
    const energy_column *col;
    int body;
} energy_slot;

/* The columns of model m after time, in their order (malloc'd, *n of them). */
static energy_slot *energy_slots(const sph_model *m, int *n)
{
    energy_slot *slot = malloc((size_t)ENERGY_ROWS * ((size_t)m->nbodies + 1) * sizeof *slot);
    const energy_column *c, *end = ENERGY_COLUMNS + ENERGY_ROWS;
    *n = 0;
    for (int i = 0; i < m->nbodies; i++)
        for (c = ENERGY_COLUMNS; c < end; c++)
            if (c->layout == BLOCK && c->applies(m, i))
                slot[(*n)++] = (energy_slot){c, i};
    for (c = ENERGY_COLUMNS; c < end; c++)
        for (int i = 0; i < m->nbodies; i++)
            if (c->layout == EACH && c->applies(m, i))
                slot[(*n)++] = (energy_slot){c, i};
    for (c = ENERGY_COLUMNS; c < end; c++)
        if (c->layout == SCENE && c->applies(m, -1))
            slot[(*n)++] = (energy_slot){c, -1};
    return slot;
}

/* The two totals of a row's values v (kinetic energy in total[1], the rest in total[0]),
 * added up in a fixed order: body by body the energy each holds, then what the bodies
 * dissipated, then the scene's columns as one sum. */
static void energy_totals(const energy_slot *slot, const double *v, int n, int nbodies,
                          double total[2])
{
    double scene = 0;
    total[0] = total[1] = 0;
    for (int i = 0; i < nbodies; i++)
        for (int k = 0; k < n; k++)
            if (slot[k].body == i && slot[k].col->kind != DISSIPATED &&
                slot[k].col->kind != WITHIN)
                total[slot[k].col->kind == KINETIC] += v[k];
    for (int k = 0; k < n; k++)
        if (slot[k].body >= 0 && slot[k].col->kind == DISSIPATED)
            total[0] += v[k];
        else if (slot[k].body < 0 && slot[k].col->kind != TOTAL)
            scene += v[k];
    total[0] += scene;
}

/* The files of a run (process 0's on many processes; the others write their pieces of the
 * particle files only): the folders, energies.csv and the measurements' files. */
static int open_files(run_state *r)
{
    const sph_model *m = r->m;
    /* (--overwrite: an earlier run's files go first; refuse_used_folder checked for them) */
    if (r->opt.overwrite && sph_run_files(r->opt.out_dir, 1, NULL, 0) < 0)
        return -1;
    char *dir = joinf("%s%s/particles", r->opt.out_dir, "");
    int bad = sph_mkdirs(dir);
    free(dir);
    if (bad)
        return -1;
    int ncol;
    energy_slot *slot = energy_slots(m, &ncol);
    char **cols = calloc((size_t)ncol + 1, sizeof *cols);
    cols[0] = strdup("time");
    for (int k = 0; k < ncol; k++)
        cols[1 + k] = slot[k].body < 0 ? strdup(slot[k].col->name)
                                       : joinf("%s_%s", m->bodies[slot[k].body].name,
                                               slot[k].col->name);
    char *path = joinf("%s/energies.csv%s", r->opt.out_dir, "");
    bad = sph_csv_open(&r->energies, path, (const char *const *)cols, ncol + 1);
    free(path);
    for (int k = 0; k <= ncol; k++)
        free(cols[k]);
    free(cols);
    free(slot);
    static const char *const mcols[] = {"time", "ux", "uy", "uz", "fx", "fy", "fz"};
    for (int i = 0; i < m->nbodies; i++)
        for (int k = 0; k < m->bodies[i].nmeasures; k++) {
            path = joinf("%s/measure_%s.csv", r->opt.out_dir, m->bodies[i].measures[k].name);
            bad |= sph_csv_open(&r->measure_csv[r->rec.measure_base[i] + k], path, mcols, 7);
            free(path);
        }
    if (m->compat_outputs)
        bad |= sph_compat_open(&r->compat, m, r->opt.out_dir);
    return bad ? -1 : 0;
}

static int open_outputs(run_state *r)
{
    const sph_model *m = r->m;
    r->rec.measure_base = calloc((size_t)m->nbodies, sizeof(int));
    for (int i = 0; i < m->nbodies; i++) {
        r->rec.measure_base[i] = r->nmeasures;
        r->nmeasures += m->bodies[i].nmeasures;
    }
    r->measure_csv = calloc((size_t)r->nmeasures + 1, sizeof *r->measure_csv);
    r->rec.measures = calloc((size_t)r->nmeasures + 1, sizeof *r->rec.measures);
    r->rec.energy.width = 2;
    for (int q = 0; q < r->nmeasures; q++)
        r->rec.measures[q].width = 6;
    r->frame_files = calloc((size_t)m->nbodies, sizeof(char **));
    return r->sim.par->rank == 0 ? open_files(r) : 0;
}

/* One row of energies and measurements (every output time). */
static int record(run_state *r)
{
    const sph_sim *s = &r->sim;
    int ncol;
    energy_slot *slot = energy_slots(r->m, &ncol);
    double *row = calloc((size_t)ncol + 1, sizeof(double)), total[2];
    double *held = malloc(2 * (size_t)s->nbodies * sizeof *held);
    for (int i = 0; i < s->nbodies; i++)
        sph_body_energies_at(&s->bodies[i], s->dt, &held[2 * i], &held[2 * i + 1]);
    row[0] = s->t;
    for (int k = 0; k < ncol; k++)
        if (slot[k].col->value)
            row[1 + k] = slot[k].col->value(s, slot[k].body, held);
    free(held);
    s->par->sum(row + 1, ncol); /* (on many processes each held its own particles' share) */
    energy_totals(slot, row + 1, ncol, s->nbodies, total);
    for (int k = 0; k < ncol; k++)
        if (slot[k].col->kind == TOTAL)
            row[1 + k] = total[0] + total[1];
    free(slot);
    const int writes = s->par->rank == 0; /* (the files are the first process's) */
    int bad = writes ? sph_csv_row(&r->energies, row) : 0;
    if (r->m->compat_outputs && writes)
        bad |= sph_compat_energies(&r->compat, row);
    sph_series_push(&r->rec.energy, s->t, total);
    free(row);
    for (int i = 0; i < s->nbodies; i++)
        for (int k = 0; k < s->bodies[i].desc->nmeasures; k++) {
            int q = r->rec.measure_base[i] + k;
            double mrow[7];
            mrow[0] = s->t;
            sph_measure(&s->bodies[i], k, mrow + 1);
            if (writes)
                bad |= sph_csv_row(&r->measure_csv[q], mrow);
            if (r->m->compat_outputs && writes)
                bad |= sph_compat_plane(&r->compat, q, mrow);
            sph_series_push(&r->rec.measures[q], s->t, mrow + 1);
        }
    return bad;
}

/* On many processes a frame of a body is a .pvtu file (process 0) listing a .vtu piece of
 * each process's particles; file is the .pvtu's name, path its folder.  0, or -1 after a
 * message (any process's). */
static int write_pieces(run_state *r, const sph_body *b, const char *dir, const char *file)
{
    const sph_par *par = r->sim.par;
    char piece[300], path[4600];
    const int stem = (int)strlen(file) - 5; /* (without ".pvtu") */
    snprintf(piece, sizeof piece, "%.*s_p%d.vtu", stem, file, par->rank);
    snprintf(path, sizeof path, "%s/%s", dir, piece);
    int bad = sph_write_vtu(path, b, r->sim.t);
    if (par->agree(bad))
        return -1;
    if (par->rank != 0)
        return 0;
    char **pieces = calloc((size_t)par->size, sizeof *pieces);
    for (int k = 0; pieces && k < par->size; k++) {
        char name[300];
        snprintf(name, sizeof name, "%.*s_p%d.vtu", stem, file, k);
        pieces[k] = strdup(name);
    }
    snprintf(path, sizeof path, "%s/%s", dir, file);
    bad = !pieces || sph_write_pvtu(path, b, (const char *const *)pieces, par->size);
    for (int k = 0; pieces && k < par->size; k++)
        free(pieces[k]);
    free(pieces);
    return bad ? -1 : 0;
}

/* The particle files of every body at the current time: a frame of the .pvd series. */
static int write_particles(run_state *r)
{
    const sph_sim *s = &r->sim;
    const int many = s->par->size > 1;
    r->m->stress_output(&r->sim);
    r->frame_times = realloc(r->frame_times, (size_t)(r->nframes + 1) * sizeof(double));
    r->frame_times[r->nframes] = s->t;
    int bad = 0;
    for (int i = 0; i < s->nbodies; i++) {
        const char *name = s->bodies[i].desc->name;
        char file[256], path[4096];
        frame_file(file, sizeof file, name, r->nframes);
        if (many) {
            strcpy(file + strlen(file) - 4, ".pvtu"); /* (frame_file's ".vtu") */
            snprintf(path, sizeof path, "%s/particles", r->opt.out_dir);
            bad |= write_pieces(r, &s->bodies[i], path, file);
        } else {
            snprintf(path, sizeof path, "%s/particles/%s", r->opt.out_dir, file);
            bad |= sph_write_vtu(path, &s->bodies[i], s->t);
        }
        char **list = realloc(r->frame_files[i], (size_t)(r->nframes + 1) * sizeof(char *));
        list[r->nframes] = strdup(file);
        r->frame_files[i] = list;
        snprintf(path, sizeof path, "%s/particles/%s.pvd", r->opt.out_dir, name);
        if (s->par->rank == 0)
            bad |= sph_write_pvd(path, (const char *const *)list, r->frame_times, r->nframes + 1);
    }
    r->nframes++;
    return s->par->agree(bad);
}

/* The share of the steps of the output interval that ends now each bound set (sim.c, or a
 * device target's clock, counts them). */
static void note_bounds(run_state *r)
{
    const sph_sim *s = &r->sim;
    double row[1 + SPH_DT_NBOUNDS], counted = 0;
    for (int k = 0; k < SPH_DT_NBOUNDS; k++)
        counted += (double)(s->dt_bound_steps[k] - r->dt_bounds0[k]);
    row[0] = s->t;
    for (int k = 0; k < SPH_DT_NBOUNDS; k++) {
        row[1 + k] = counted > 0 ? (double)(s->dt_bound_steps[k] - r->dt_bounds0[k]) / counted
                                 : 0.0;
        r->dt_bounds0[k] = s->dt_bound_steps[k];
    }
    if (counted > 0)
        sph_csv_table_add(&r->dt_bounds, row, SPH_REPORT_POINTS);
}

/* The mean time step over the output interval that ends now (none at the first output), and
 * what bounded it. */
static void note_time_step(run_state *r)
{
    const sph_sim *s = &r->sim;
    if (r->dt_step0 >= 0 && s->step > r->dt_step0) {
        const double row[2] = {s->t, (s->t - r->dt_t0) / (double)(s->step - r->dt_step0)};
        sph_csv_table_add(&r->time_steps, row, SPH_REPORT_POINTS); /* (thinned when long) */
    }
    note_bounds(r);
    r->dt_t0 = s->t, r->dt_step0 = s->step;
}

/* An output time: a row of energies and measurements, and a frame of particle files when
 * one is due (every --frames interval, by default every output). */
static int write_output(run_state *r)
{
    int bad = 0;
    note_time_step(r);
    const double t = r->sim.t, eps = 1e-9 * r->t_out;
    if (t >= r->next_frame - eps) {
        bad = write_particles(r);
        while (r->next_frame <= t + eps)
            r->next_frame += r->t_frames;
    }
    return r->sim.par->agree(bad | record(r));
}

/* fmax/fmin that keep a NaN: the summary of a run that blew up says null (not finite)
 * rather than the extremes of the particles that happen to be finite still. */
static double max_nan(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : fmax(a, b);
}

static double min_nan(double a, double b)
{
    return isnan(a) || isnan(b) ? NAN : fmin(a, b);
}

/* What summary.json says of a body: its extent and largest displacement and speed now, over
 * all processes. */
typedef struct {
    double lo[3], hi[3], umax, vmax, particles, pairs, stencil, blocked, mblocked, mtasks;
    double stripes, colours;
} body_stats;

static void body_stats_of(const sph_body *b, body_stats *st)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    double umax = 0, vmax = 0;
    const int D = b->dim;
    for (int i = 0; i < b->nown; i++) {
        double x[3] = {0, b->y_plane, 0}, u2 = 0, v2 = 0;
        for (int k = 0; k < D; k++) {
            const double u = b->u[(size_t)i * D + k], v = b->v[(size_t)i * D + k];
            x[sph_axis(D, k)] = b->X[(size_t)i * D + k] + u;
            u2 += u * u, v2 += v * v;
        }
        for (int k = 0; k < 3; k++)
            lo[k] = min_nan(lo[k], x[k]), hi[k] = max_nan(hi[k], x[k]);
        umax = max_nan(umax, u2), vmax = max_nan(vmax, v2);
    }
    /* maxima over the processes, each with a flag: not a number on some process */
    double most[16] = {hi[0], hi[1], hi[2], -lo[0], -lo[1], -lo[2], umax, vmax};
    for (int k = 0; k < 8; k++)
        most[8 + k] = isnan(most[k]);
    double count[7] = {b->nown, (double)b->npairs, 0, (double)b->ob_pairs, (double)b->mb_pairs,
                       b->mb ? b->mb_start[b->nmb] : 0, b->nstripes};
    for (int r = 0; r < b->nruns; r++) /* the particles of the lattice stencil's runs */
        count[2] += b->st_run[2 * r + 1] - b->st_run[2 * r];
    double colours = b->ncolours;
    if (b->par->size > 1) {
        b->par->max(most, 16);
        b->par->sum(count, 7);
        b->par->max(&colours, 1);
    }
    for (int k = 0; k < 8; k++)
        most[k] = most[8 + k] > 0 ? NAN : most[k];
    for (int k = 0; k < 3; k++)
        st->hi[k] = most[k], st->lo[k] = -most[3 + k];
    st->umax = most[6], st->vmax = most[7];
    st->particles = count[0], st->pairs = count[1], st->stencil = count[2];
    st->blocked = count[3], st->mblocked = count[4], st->mtasks = count[5];
    st->stripes = count[6], st->colours = colours;
}

static void body_summary(sph_json *j, const sph_body *b, const body_stats *st)
{
    sph_json_key_object(j, NULL);
    sph_json_str(j, "name", b->desc->name);
    sph_json_int(j, "particles", (long)st->particles);
    sph_json_int(j, "pairs", (long)st->pairs);
    sph_json_num(j, "mean_neighbours", st->pairs / st->particles);
    sph_json_int(j, "stencil_particles", (long)st->stencil); /* (pairs/stencil.c) */
    sph_json_int(j, "offset_block_pairs", (long)st->blocked); /* (pairs/offset_blocks.c) */
    sph_json_int(j, "momentum_block_pairs", (long)st->mblocked);
    /* the share of the momentum blocks' lanes that hold a pair (particle_order.c) */
    sph_json_num(j, "momentum_block_lanes",
                 st->mtasks > 0 ? st->mblocked / (st->mtasks * SPH_OB_LANES) : 0);
    sph_json_int(j, "stripes", (long)st->stripes); /* (setup.c: the half lists' stripes) */
    sph_json_int(j, "colours", (long)st->colours);
    sph_json_num(j, "dx", b->dx);
    sph_json_num(j, "h", b->h);
    sph_json_num(j, "c0", b->c0);
    sph_json_key_object(j, "bbox");
    sph_json_key_array(j, "min");
    for (int k = 0; k < 3; k++)
        sph_json_num(j, NULL, st->lo[k]);
    sph_json_end_array(j);
    sph_json_key_array(j, "max");
    for (int k = 0; k < 3; k++)
        sph_json_num(j, NULL, st->hi[k]);
    sph_json_end_array(j);
    sph_json_end_object(j);
    sph_json_num(j, "max_displacement", sqrt(st->umax));
    sph_json_num(j, "max_velocity", sqrt(st->vmax));
    sph_json_end_object(j);
}

/* summary.json: the run and how it stands, status "running" (written before the first
 * output, so that a folder's summary never speaks of an earlier run, nor calls a run that was
 * killed stable) or how it ended: "finished" (its expectations evaluated, *failed set when
 * one failed), "unstable", "stopped" (by a signal) or "failed" (an output could not be
 * written); then the timers, the monitor's verdict and the bodies. */
/* Per process (processes: p->size numbers each): own particles, halo particles, bytes sent
 * per step, seconds waited for the halo; every process gets them. */
static double *process_table(const run_state *r)
{
    const sph_par *p = r->sim.par;
    double *x = calloc(4 * (size_t)p->size, sizeof *x);
    if (!x)
        return NULL;
    for (int i = 0; i < r->sim.nbodies; i++) {
        x[4 * p->rank] += r->sim.bodies[i].nown;
        x[4 * p->rank + 1] += r->sim.bodies[i].n - r->sim.bodies[i].nown;
    }
    x[4 * p->rank + 2] = r->sim.step > 0 ? p->bytes_sent() / (double)r->sim.step : 0.0;
    x[4 * p->rank + 3] = p->wait_seconds();
    p->sum(x, 4 * p->size); /* (each process's slots are its own) */
    return x;
}

static void processes_summary(sph_json *j, const run_state *r, const double *x)
{
    static const char *const names[4] = {"particles", "halo", "bytes_per_step", "wait_time"};
    const int n = r->sim.par->size;
    sph_json_key_object(j, "processes");
    sph_json_int(j, "count", n);
    /* 1 where the MPI library takes device memory: a device target's halo then goes from
     * device to device, not through the host */
    sph_json_int(j, "device_buffers", r->sim.par->device_buffers);
    for (int c = 0; c < 4; c++) {
        sph_json_key_array(j, names[c]);
        for (int k = 0; k < n; k++)
            sph_json_num(j, NULL, x[4 * k + c]);
        sph_json_end_array(j);
    }
    sph_json_end_object(j);
}

/* What set the time steps since this process started the run: the steps each bound set,
 * and each body's bounds (summary.json "time_step_bounds"). */
static void bounds_summary(sph_json *j, const sph_sim *s)
{
    static const char *const names[SPH_DT_NBOUNDS] = SPH_DT_BOUND_NAMES;
    long counted = 0;
    for (int k = 0; k < SPH_DT_NBOUNDS; k++)
        counted += s->dt_bound_steps[k];
    sph_json_key_object(j, "time_step_bounds");
    sph_json_int(j, "counted", counted);
    sph_json_key_object(j, "bounds");
    for (int k = 0; k < SPH_DT_NBOUNDS; k++)
        sph_json_int(j, names[k], s->dt_bound_steps[k]);
    sph_json_end_object(j);
    sph_json_key_object(j, "bodies");
    for (int i = 0; i < s->nbodies && s->dt_body_steps; i++)
        sph_json_int(j, s->bodies[i].desc->name, s->dt_body_steps[i]);
    sph_json_end_object(j);
    if (s->dt_body >= 0 && counted > 0)
        sph_json_str(j, "last_body", s->bodies[s->dt_body].desc->name);
    if (counted > 0)
        sph_json_str(j, "last", names[s->dt_bound]);
    sph_json_end_object(j);
}

/* How near the monitor's checks came to their limits (summary.json stability.margins). */
static void margins_summary(sph_json *j, const sph_monitor *mon)
{
    sph_json_key_object(j, "margins");
    sph_json_int(j, "scans", mon->scans);
    sph_json_num(j, "smallest_J", mon->scans ? mon->j_min : NAN);
    sph_json_num(j, "largest_speed_over_c0", mon->scans ? mon->speed : NAN);
    sph_json_num(j, "speed_limit", SPH_MONITOR_SPEED);
    sph_json_int(j, "energy_checks", mon->sums);
    sph_json_num(j, "largest_energy_growth", mon->sums ? mon->growth : NAN);
    sph_json_num(j, "energy_growth_limit", SPH_MONITOR_GROWTH);
    sph_json_end_object(j);
}

static int summary_file(run_state *r, const char *status, double wall, int *failed,
                        const body_stats *st, const double *procs)
{
    const sph_sim *s = &r->sim;
    const long particles = r->particles, pairs = r->pairs;
    char path[4096];
    snprintf(path, sizeof path, "%s/summary.json", r->opt.out_dir);
    sph_json j;
    if (sph_json_open(&j, path))
        return -1;
    sph_json_str(&j, "model", r->m->name);
    sph_json_str(&j, "source", r->m->source);
    sph_json_str(&j, "status", status);
    sph_json_int(&j, "dimension", r->m->dim);
    sph_json_int(&j, "threads", r->team.max);
    sph_json_int(&j, "particles", particles);
    sph_json_int(&j, "pairs", pairs);
    sph_json_int(&j, "steps", s->step);
    sph_json_num(&j, "time", s->t);
    if (r->opt.restart) { /* (the timers and counts are those of the whole run) */
        sph_json_key_object(&j, "resumed");
        sph_json_str(&j, "checkpoint", r->opt.restart);
        sph_json_num(&j, "time", r->t_resumed);
        sph_json_int(&j, "step", r->step_resumed);
        sph_json_end_object(&j);
    }
    bounds_summary(&j, s);
    if (!strcmp(status, "running")) {
        sph_json_num(&j, "end_time", r->t_end);
        const int bad = sph_json_close(&j);
        const sph_run_outcome o = {status, NULL, NAN, NULL, 0, NULL, 0};
        return sph_run_report(r, &o) | bad;
    }
    sph_json_num(&j, "wall_time", wall);
    sph_json_num(&j, "setup_time", r->setup_seconds);
    sph_json_num(&j, "step_time", r->step_seconds);
    sph_json_num(&j, "check_time", r->check_seconds);
    sph_json_num(&j, "output_time", r->output_seconds);
    const sph_team *team = &r->team; /* the threads the steps ran on (team.h) */
    sph_json_key_object(&j, "team");
    sph_json_bool(&j, "fixed", team->fixed);
    sph_json_num(&j, "mean_threads",
                 team->step_seconds > 0 ? team->thread_seconds / team->step_seconds : team->now);
    sph_json_int(&j, "last_threads", team->now);
    sph_json_int(&j, "trials", team->trials);
    sph_json_int(&j, "changes", team->changes);
    sph_json_end_object(&j);
    double ps = (double)particles * (double)s->step;
    sph_json_num(&j, "ns_per_particle_step", ps > 0 ? 1e9 * r->step_seconds / ps : NAN);
    sph_json_num(&j, "pair_interactions_per_second",
                 r->step_seconds > 0 ? (double)pairs * (double)s->step / r->step_seconds : NAN);
    if (r->opt.profile)
        sph_profile_json(&j);
    sph_json_key_object(&j, "stability");
    sph_json_str(&j, "verdict", r->unstable[0] ? "unstable" : "stable");
    if (r->unstable[0])
        sph_json_str(&j, "message", r->unstable);
    sph_json_int(&j, "checks", r->checks);
    sph_json_int(&j, "device_checks", r->device_checks);
    sph_json_num(&j, "smallest_stretch", r->stretch_seen);
    sph_json_num(&j, "largest_energy", r->mon.e_ref);
    margins_summary(&j, &r->mon);
    sph_json_end_object(&j);
    sph_json_key_array(&j, "bodies");
    for (int i = 0; i < s->nbodies; i++)
        body_summary(&j, &s->bodies[i], &st[i]);
    sph_json_end_array(&j);
    if (procs)
        processes_summary(&j, r, procs);
    if (!strcmp(status, "stopped")) { /* cut short: its expectations are for the whole run */
        sph_json_key_object(&j, "stopped");
        sph_json_str(&j, "signal", stop_name());
        sph_json_num(&j, "time", s->t);
        sph_json_num(&j, "last_frame", r->nframes ? r->frame_times[r->nframes - 1] : NAN);
        sph_json_bool(&j, "checkpoint", r->t_checkpoint > 0);
        sph_json_end_object(&j);
    }
    const int finished = !strcmp(status, "finished");
    sph_report_expect *expects = calloc((size_t)r->m->nexpects + 1, sizeof *expects);
    *failed = finished ? sph_expect_evaluate(r->m, &r->rec, &j, r->opt.quiet, r->errors,
                                             sizeof r->errors, expects)
                       : 0;
    int bad = sph_json_close(&j);
    const sph_run_outcome o = {
        status, r->unstable[0] ? r->unstable : !strcmp(status, "stopped") ? stop_name() : NULL,
        wall, expects, finished && expects ? r->m->nexpects : 0, procs,
        procs ? r->sim.par->size : 0};
    bad |= sph_run_report(r, &o);
    free(expects);
    return bad;
}

/* summary.json, written by process 0 from what all processes hold (collective). */
static int write_summary(run_state *r, const char *status, double wall, int *failed)
{
    const sph_par *par = r->sim.par;
    const int running = !strcmp(status, "running");
    const double w0 = sph_wall_time();
    body_stats *st = calloc((size_t)r->sim.nbodies + 1, sizeof *st);
    for (int i = 0; st && !running && i < r->sim.nbodies; i++)
        body_stats_of(&r->sim.bodies[i], &st[i]);
    double *procs = par->size > 1 && !running ? process_table(r) : NULL;
    int ok[2] = {0, 0}; /* the file failed; an expectation failed */
    if (!st)
        ok[0] = -1;
    else if (par->rank == 0)
        ok[0] = summary_file(r, status, wall, &ok[1], st, procs);
    par->bcast(ok, sizeof ok, 0);
    if (failed)
        *failed = ok[1];
    free(st), free(procs);
    r->summary_wall = sph_wall_time();
    r->summary_cost = r->summary_wall - w0;
    return ok[0];
}

/* While running, summary.json and its page are written again at an output once --summary
 * seconds of wall time have passed since they last were, and no sooner than SUMMARY_SHARE
 * times as long as writing them took (a long run's page reads its CSV files back), or with
 * --summary 0 at every output: a page opened during the run shows it up to a recent output.
 * Process 0 decides for all (the writing is collective).  Not at the last output, which the
 * end's summary follows. */
enum { SUMMARY_SHARE = 50 };
static int summary_due(run_state *r)
{
    const sph_par *par = r->sim.par;
    const double every = r->opt.summary;
    int due = 0;
    if (par->rank == 0 && r->sim.t < r->t_end - 1e-9 * r->t_out)
        due = every == 0 || sph_wall_time() - r->summary_wall >=
                                fmax(every, SUMMARY_SHARE * r->summary_cost);
    if (par->size > 1)
        par->bcast(&due, sizeof due, 0);
    return due;
}

/* ------------------------------------------------------------------ resuming */

/* A run resumed from --restart FILE (read, and checked as a file, before the set-up): the
 * simulation's state (set up from the model first) and the run's, the output files kept as
 * they were at the checkpoint. */
static int restart(run_state *r, sph_ckpt *c)
{
    const sph_par *par = r->sim.par;
    int bad = sph_sim_restore(c, &r->sim) || par->agree(sph_run_resume_files(c, r));
    if (!bad && r->m->copy_state)
        r->m->copy_state(&r->sim, 1);
    bad = bad || par->agree(open_outputs(r)) || sph_run_resume(c, r);
    sph_ckpt_free(c);
    r->t_resumed = r->sim.t, r->step_resumed = r->sim.step;
    r->dt_t0 = r->sim.t, r->dt_step0 = r->sim.step; /* (the time step from here on) */
    if (!bad && !r->opt.quiet)
        printf("%s: resumed from %s at t = %g s (step %ld)\n", r->m->name, r->opt.restart,
               r->sim.t, r->sim.step);
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ the loop */

/* A device target brings the bodies' host arrays up to date before the runtime reads them. */
static void sync_host(run_state *r)
{
    if (r->m->sync_host)
        r->m->sync_host(&r->sim);
}

/* A device target's periodic check: the monitor's sums from the device, without copying the
 * state.  0 when they show a sane state; 1 when the host must look itself. */
static int glance(run_state *r)
{
    sph_monitor_sums *sums = calloc((size_t)r->sim.nbodies, sizeof *sums);
    double stretch = 1.0;
    r->m->monitor(&r->sim, sums);
    const int look = sph_monitor_glance(&r->mon, &r->sim, sums, &stretch);
    free(sums);
    if (!look)
        r->stretch_seen = fmin(r->stretch_seen, stretch);
    return look;
}

/* The stability monitor, every CHECK_EVERY steps and before every output. */
static int check_now(run_state *r, int output)
{
    r->checks++;
    if (!output && r->m->monitor && !glance(r)) {
        r->device_checks++;
        return 0;
    }
    sync_host(r); /* also for the frame written right after */
    if (sph_monitor_check(&r->mon, &r->sim, r->unstable, sizeof r->unstable))
        return 1;
    r->stretch_seen = fmin(r->stretch_seen, sph_sim_stretch(&r->sim));
    return 0;
}

/* |x| of a D-vector without overflow in its square (a runaway state). */
static double magnitude(const double *x, int D)
{
    return D == 3 ? hypot(hypot(x[0], x[1]), x[2]) : hypot(x[0], x[1]);
}

/* The particle whose acceleration (eq. 66) or speed (eq. 65) limits the time step, or the
 * stiffest contact. */
static void dt_collapse_report(run_state *r, double dt, double floor_dt)
{
    const sph_sim *s = &r->sim;
    /* a state that is not finite (a velocity condition dividing by zero at a particle) makes
     * eq. 65 or 66 zero: name it, not the time step */
    if (sph_monitor_finite(s, r->unstable, sizeof r->unstable))
        return;
    /* the particle whose own bound is the smallest, by its speed (eq. 65) or its
     * acceleration (eq. 66, free particles) */
    int body = 0, particle = 0, by_speed = 0;
    double lowest = INFINITY, value = 0;
    for (int ib = 0; ib < s->nbodies; ib++) {
        const sph_body *b = &s->bodies[ib];
        for (int i = 0; i < b->nown; i++) {
            const double vn = magnitude(b->v + (size_t)i * b->dim, b->dim);
            const double an = b->fix[i] == 0 ? magnitude(b->a + (size_t)i * b->dim, b->dim) : 0;
            const double dtv = sph_body_dt(s->dt_factor, b->h, b->c0, vn * vn, 0);
            const double dta = sph_body_dt(INFINITY, b->h, b->c0, 0, an * an);
            const double own = fmin(dtv, dta), what = dtv < dta ? vn : an;
            if (own < lowest || (own == lowest && what > value)) /* (ties at 0: the largest) */
                lowest = own, body = ib, particle = i, by_speed = dtv < dta, value = what;
        }
    }
    double least = lowest; /* (on many processes: the process whose particle is lowest) */
    s->par->min(&least, 1);
    const double contact = sph_contact_dt(s, dt);
    if (contact < least) { /* the stiffest contact between bodies set it */
        snprintf(r->unstable, sizeof r->unstable,
                 "step %ld, t = %.6g s: time step collapsed to %g s, below dtmin = %g s (the "
                 "stiffest contact between bodies bounds it: 1/omega = %g s; is the scene's "
                 "`contact` stiffness too high?)",
                 s->step, s->t, dt, floor_dt, contact);
        return;
    }
    char crushed[160] = "";
    int stiffens = 0; /* a law that gives its wave speed counts it in the stretch */
    for (int i = 0; i < s->nbodies; i++)
        stiffens |= s->bodies[i].desc->wavespeed;
    if (s->dt_factor < 1) /* the bound followed a compression: factor lambda / lambda_on */
        snprintf(crushed, sizeof crushed, "; compressed to a principal stretch of %.3g%s",
                 s->dt_factor * r->m->dt_lambda_on,
                 stiffens ? " (times c0 over the wave speed a law gives, where it is larger)" : "");
    char what[256];
    if (r->m->dt_fixed > 0) /* a bound of 0: |v|^2 or |a|^2 beyond the largest double */
        snprintf(what, sizeof what, "runaway under the fixed time step %g s", r->m->dt_fixed);
    else
        snprintf(what, sizeof what, "time step collapsed to %g s, below dtmin = %g s", dt,
                 floor_dt);
    char *msg = r->unstable;
    const size_t len = sizeof r->unstable;
    const int n = sph_monitor_where(msg, len, s, &s->bodies[body], particle);
    if (n >= 0 && (size_t)n < len)
        snprintf(msg + n, len - (size_t)n, ": %s (%s %g %s%s)", what,
                 by_speed ? "speed" : "acceleration", value, by_speed ? "m/s" : "m/s^2", crushed);
    sph_monitor_share(s, lowest == least, msg, len);
}

/* Runs until t_end or instability; returns 0, or 1 when the monitor stopped it. */
static int time_loop(run_state *r)
{
    sph_sim *s = &r->sim;
    sph_progress prog;
    const sph_par *par = s->par;
    sph_progress_start(&prog, r->t_end, r->opt.quiet || par->rank != 0, r->opt.progress);
    const double floor_dt = dt_floor(r), eps = 1e-9 * r->t_out;
    while (s->t < r->t_end - eps) {
        /* the steps to the next check or output time, whichever is first */
        /* (on many processes a signal stops the run at the end of a batch, where the
         * processes agree on it: every process must take the same steps) */
        sph_advance a = {.steps = CHECK_EVERY - (int)(s->step % CHECK_EVERY),
                         .t_stop = fmin(r->next_out, r->t_end),
                         .eps = eps, .floor_dt = floor_dt,
                         .stop = par->size == 1 ? &stop_signal : NULL};
        const long batch = sph_team_batch(&r->team); /* (short while a count is tried) */
        if (a.steps > batch)
            a.steps = (int)batch;
        const int threads = sph_team_threads(&r->team);
        if (threads != omp_get_max_threads())
            omp_set_num_threads(threads);
        double w0 = sph_wall_time();
        const int watch = !r->team.fixed && r->team.max > 1; /* (team.h) */
        const double cpu0 = sph_cpu_time(), idle0 = watch ? sph_idle_time() : -1;
        sph_profile_phase = SPH_PHASE_STEPS; /* (--profile) the passes from here on */
        const int steps = sph_sim_advance(s, &a);
        sph_profile_phase = SPH_PHASE_CHECKS;
        const double wall = sph_wall_time() - w0;
        r->step_seconds += wall;
        const double idle1 = idle0 < 0 ? -1 : sph_idle_time();
        sph_team_after(&r->team, steps, wall, sph_cpu_time() - cpu0,
                       idle1 < 0 ? -1 : idle1 - idle0, w0 + wall);
        if (par->size > 1) { /* a signal that reached any process stops them all */
            double sig = stop_signal;
            par->max(&sig, 1);
            stop_signal = (sig_atomic_t)sig;
        }
        if (a.collapsed) {
            sync_host(r);
            dt_collapse_report(r, a.dt_bad, a.floor_bad);
            break;
        }
        const int output = s->t >= r->next_out - eps;
        w0 = sph_wall_time();
        if ((output || s->step % CHECK_EVERY == 0) && check_now(r, output))
            break;
        if (output) {
            if (write_output(r))
                return -1;
            r->next_out += r->t_out;
            if (sph_run_checkpoint_due(r) && sph_run_write_checkpoint(r))
                return -1;
            if (summary_due(r) && write_summary(r, "running", 0, NULL))
                return -1;
            r->output_seconds += sph_wall_time() - w0;
        } else {
            r->check_seconds += sph_wall_time() - w0;
        }
        sph_progress_update(&prog, r->m->name, s->t, s->dt, s->step);
        if (stop_signal) /* (after the step under way when it came, and its output) */
            break;
    }
    sph_progress_finish(&prog);
    return r->unstable[0] ? 1 : stop_signal ? 2 : 0;
}

static int setup(run_state *r)
{
    const sph_model *m = r->m;
    const sph_par *par = r->sim.par;
    if (sph_sim_init_par(&r->sim, m, r->t_end, !r->opt.quiet, par))
        return -1;
    double count[2] = {0, 0};
    for (int i = 0; i < r->sim.nbodies; i++) {
        count[0] += r->sim.bodies[i].nown;
        count[1] += (double)r->sim.bodies[i].npairs;
    }
    par->sum(count, 2); /* (all processes' particles; the pairs with a halo on both sides) */
    r->particles = (long)count[0], r->pairs = (long)count[1];
    const double courant = stable_courant(r);
    if (m->dt_fixed > 0 && m->dt_fixed > courant * min_h_over_c0(r)) {
        if (courant < 1)
            sph_warning("the fixed time step %g s exceeds %g h/c0 = %g s, where the explicit step "
                        "of 'gradient quadratic' was stable; the run is likely to be unstable",
                        m->dt_fixed, courant, courant * min_h_over_c0(r));
        else
            sph_warning("the fixed time step %g s exceeds h/c0 = %g s (CFL 1); the run is likely "
                        "to be unstable", m->dt_fixed, min_h_over_c0(r));
    }
    return 0;
}

/* The velocity conditions at t = 0 give the initial state; one that is not finite (an
 * expression that divides by zero at a particle) must not reach the first output, and no step
 * could start from it. */
static int initial_state_bad(run_state *r)
{
    char msg[512];
    if (!sph_monitor_finite(&r->sim, msg, sizeof msg))
        return 0;
    sph_error("the initial state is not finite: %s; the velocity conditions at t = 0 give it "
              "(does an expression divide by zero, or take the root or logarithm of a negative "
              "number, there?)", msg);
    return 1;
}

/* After an unstable run under `timestep undeformed`: when bodies were crushed far, say that
 * the default bound, which follows the current spacing, would not be fooled
 * (docs/stability.md). */
static void stretch_hint(const run_state *r)
{
    const double lam = r->stretch_seen;
    if (r->m->dt_lambda_on > 0 || r->m->dt_fixed > 0 || !(lam < 0.3))
        return;
    sph_note("particles were compressed to a principal stretch of %.3g, and the time step "
             "follows the undeformed spacing (`timestep undeformed`); the default, `timestep "
             "auto`, bounds it by the current one (docs/stability.md)", lam);
}

/* After a run given --threads N whose steps ran on fewer threads for a while (the machine
 * busy with other work: par/team.h): said, with the mean count. */
static void threads_hint(const run_state *r)
{
    const sph_team *t = &r->team;
    const double mean = t->step_seconds > 0 ? t->thread_seconds / t->step_seconds : t->now;
    if (r->opt.threads <= 0 || t->fixed || t->changes == 0 || r->sim.par->rank != 0 ||
        !(mean < t->max - 0.05))
        return;
    sph_note("--threads %d: the steps ran on %.2f threads on average (%d last), fewer while "
             "other programs held the cores; --fixed-threads keeps the count", t->max, mean,
             t->now);
}

/* The output and frame times are reached by adding the interval: beyond some 10^9 intervals
 * to the end (an interval below the spacing of doubles near t, at worst) the run would never
 * get there, stepping or writing outputs forever.  The model's own end and output interval
 * are checked when it compiles, so only the options can ask for it. */
static int too_many_outputs(const run_state *r)
{
    static const double most = 1e9;
    const double n_out = r->t_end / r->t_out, n_frames = r->t_end / r->t_frames;
    if (n_out <= most && n_frames <= most)
        return 0;
    sph_error("%s interval %g s gives %.3g %s up to the end time %g s, more than 10^9 (see "
              "--end, --every and --frames)", n_out > most ? "the output" : "the particle files'",
              n_out > most ? r->t_out : r->t_frames, n_out > most ? n_out : n_frames,
              n_out > most ? "outputs" : "frames", r->t_end);
    return 1;
}

/* The particle files a run writes, one per body at each frame time (end / frame interval):
 * beyond SPH_MOST_FRAMES, an interval given by mistake (--every 1e-12 over 50 us: 5e7 frames)
 * that would fill the disk file by file.  The energies and measurements, a row each output,
 * stay at the output interval (too_many_outputs bounds those). */
#define SPH_MOST_FRAMES 1e5
static int too_many_frames(const run_state *r)
{
    const double n = r->t_end / r->t_frames;
    if (n <= SPH_MOST_FRAMES)
        return 0;
    sph_error("the particle files' interval %g s (%s) gives %.3g frames up to the end time %g "
              "s, more than 10^5 (each a file of every body): --frames T writes them every T "
              "seconds only (the energies and measurements stay at every output)",
              r->t_frames, r->opt.t_frames > 0 ? "--frames" : r->opt.t_out > 0 ? "--every"
                                               : "the model's output interval", n, r->t_end);
    return 1;
}

/* The threads of the steps: an explicit --threads, or OpenMP's count (OMP_NUM_THREADS), above
 * SPH_THREADS_PER_CORE times the cores this process may run on is cut to that: more threads
 * than that only wait for each other, and some thousands make OpenMP fail to start them (a
 * crash).  Sets OpenMP's count when --threads is given. */
#define SPH_THREADS_PER_CORE 4
static void set_threads(run_state *r)
{
    const int cores = omp_get_num_procs(), most = SPH_THREADS_PER_CORE * cores;
    const int asked = r->opt.threads > 0 ? r->opt.threads : omp_get_max_threads();
    if (asked > most && r->sim.par->rank == 0)
        sph_note("%s %d: using %d threads, %d times the %d core%s this process may run on "
                 "(more would only wait for each other)",
                 r->opt.threads > 0 ? "--threads" : "OMP_NUM_THREADS", asked, most,
                 SPH_THREADS_PER_CORE, cores, cores == 1 ? "" : "s");
    if (asked > most || r->opt.threads > 0)
        omp_set_num_threads(asked > most ? most : asked);
    if (r->opt.threads > most)
        r->opt.threads = most;
}

/* A resumed run goes on from its checkpoint's time to the end time (--end, or the model's):
 * an end before that time would run nothing and say nothing.  Refused (bad options) before
 * the set-up.  (A checkpoint of another model, or without a clock, restart() refuses.) */
static int ends_before_checkpoint(const run_state *r, const sph_ckpt *c)
{
    size_t bytes, nl;
    const double *clock = sph_ckpt_find(c, "sim.clock", &bytes);
    const char *model = sph_ckpt_find(c, "model", &nl);
    if (!clock || bytes != 3 * sizeof(double) || !model || nl != strlen(r->m->name) ||
        memcmp(model, r->m->name, nl))
        return 0;
    const double t = clock[0], eps = 1e-9 * r->t_out;
    if (!(r->t_end < t - eps))
        return 0;
    if (r->opt.t_end > 0)
        sph_error("--end %g s is before the time of the checkpoint %s, t = %g s: a resumed run "
                  "goes on from there; give a later --end", r->t_end, r->opt.restart, t);
    else
        sph_error("the model's end time %g s is before the time of the checkpoint %s, t = %g "
                  "s: a resumed run goes on from there; give a later --end", r->t_end,
                  r->opt.restart, t);
    return 1;
}

/* A run whose outputs could not be written (reported): summary.json says so rather than
 * "running", if it can be written at all. */
static int failed_run(run_state *r)
{
    int failed = 0;
    sync_host(r);
    write_summary(r, "failed", r->wall_before + sph_wall_time() - r->wall0, &failed);
    return SPH_EXIT_SETUP;
}

/* A new run's folder must hold no outputs of another run, which the new one would leave
 * beside its own (an earlier, longer run's later frames; its summary): refused unless
 * --overwrite, which removes them when the outputs are opened.  Checked before the set-up,
 * which may be long. */
static int refuse_used_folder(const run_state *r)
{
    char first[256];
    const long n = sph_run_files(r->opt.out_dir, 0, first, sizeof first);
    if (n <= 0 || r->opt.overwrite)
        return 0;
    char more[64] = "";
    if (n > 1)
        snprintf(more, sizeof more, " and %ld more", n - 1);
    sph_error("%s holds the outputs of an earlier run (%s%s); --overwrite replaces them, "
              "--out DIR writes elsewhere", r->opt.out_dir, first, more);
    return 1;
}

int sph_main(const sph_model *m, int argc, char **argv)
{
    return sph_main_par(m, argc, argv, &sph_par_one);
}

int sph_main_par(const sph_model *m, int argc, char **argv, const sph_par *par)
{
    /* a log (stdout redirected to a file) gets each line when it is printed, not 4 KiB at a
     * time or at the end */
    setvbuf(stdout, NULL, _IOLBF, 0);
    run_state r;
    memset(&r, 0, sizeof r);
    static char *const time_step_names[] = {"time", "mean_dt"};
    r.time_steps = (sph_csv_table){.ncols = 2, .names = (char **)time_step_names};
    static const char *const bounds[SPH_DT_NBOUNDS] = SPH_DT_BOUND_NAMES;
    static char *bound_columns[1 + SPH_DT_NBOUNDS] = {"time"};
    for (int k = 0; k < SPH_DT_NBOUNDS; k++)
        bound_columns[1 + k] = (char *)bounds[k];
    r.dt_bounds = (sph_csv_table){.ncols = 1 + SPH_DT_NBOUNDS, .names = bound_columns};
    r.dt_step0 = -1;
    r.m = m;
    r.sim.par = par;
    sph_message_program(m->name);
    r.stretch_seen = 1.0;
    int rc = sph_parse_options(&r.opt, m->name, argc, argv);
    if (rc)
        return rc < 0 ? SPH_EXIT_OPTIONS : 0;
    set_threads(&r);
    if (r.opt.partition > 0) /* a report, no run (docs/mpi.md) */
        return sph_partition_report(m, r.opt.partition) ? SPH_EXIT_SETUP : 0;
    /* fewer threads while the machine is busy, --threads N the most (a device target's host
     * threads only copy and check; processes of one run keep theirs: --fixed-threads too) */
    sph_team_init(&r.team, omp_get_max_threads(),
                  r.opt.fixed_threads || m->advance || par->size > 1);
    sph_profile_on = r.opt.profile;
    sph_profile_phase = SPH_PHASE_SETUP;
    sph_stencil_off = r.opt.no_stencil || m->scalar;
    sph_fast_law_off = r.opt.whole_law;
    r.t_end = r.opt.t_end > 0 ? r.opt.t_end : m->t_end;
    r.t_out = r.opt.t_out > 0 ? r.opt.t_out : m->t_out;
    r.t_frames = r.opt.t_frames > 0 ? r.opt.t_frames : r.t_out;
    r.t_checkpoint = r.opt.t_checkpoint > 0 ? r.opt.t_checkpoint : m->t_checkpoint;
    if (too_many_outputs(&r) || too_many_frames(&r))
        return SPH_EXIT_OPTIONS;
    if (par->agree(!r.opt.restart && refuse_used_folder(&r)))
        return SPH_EXIT_SETUP;
    if (r.t_checkpoint > 0)
        catch_stop_signals();
    r.wall0 = sph_wall_time();
    r.next_out = r.t_out;
    r.next_checkpoint = r.t_checkpoint;
    sph_ckpt ckpt; /* (process 0 hashes the whole file; agree spreads its verdict) */
    if (par->agree(r.opt.restart && sph_ckpt_read(&ckpt, r.opt.restart, par->rank == 0)))
        return SPH_EXIT_SETUP;
    if (par->agree(r.opt.restart && ends_before_checkpoint(&r, &ckpt))) {
        sph_ckpt_free(&ckpt);
        return SPH_EXIT_OPTIONS;
    }
    if (setup(&r))
        return SPH_EXIT_SETUP;
    if (r.t_checkpoint <= 0) /* (without checkpoints a signal in the set-up ends it at once) */
        catch_stop_signals();
    if (r.opt.restart) {
        if (restart(&r, &ckpt))
            return SPH_EXIT_SETUP;
        r.setup_seconds += sph_wall_time() - r.wall0; /* (the run's set-ups, both) */
        if (write_summary(&r, "running", 0, NULL))
            return SPH_EXIT_SETUP;
    } else {
        sync_host(&r);
        sph_contact_overlaps(&r.sim); /* (bodies placed into each other: said, and their energy) */
        if (initial_state_bad(&r) || par->agree(open_outputs(&r)) ||
            write_summary(&r, "running", 0, NULL))
            return SPH_EXIT_SETUP;
        r.setup_seconds = sph_wall_time() - r.wall0;
        sph_profile_phase = SPH_PHASE_CHECKS; /* the first output */
        if (write_output(&r))
            return failed_run(&r);
    }
    int state = time_loop(&r);
    if (state != 1 && r.t_checkpoint > 0 && sph_run_write_checkpoint(&r)) /* to go on from */
        state = -1;
    if (state < 0)
        return failed_run(&r);
    int failed = 0;
    double wall = r.wall_before + sph_wall_time() - r.wall0;
    sync_host(&r);
    if (write_summary(&r, state == 1 ? "unstable" : state == 2 ? "stopped" : "finished", wall,
                      &failed))
        return SPH_EXIT_SETUP;
    if (par->rank == 0) {
        sph_csv_close(&r.energies);
        for (int q = 0; q < r.nmeasures; q++)
            sph_csv_close(&r.measure_csv[q]);
        if (m->compat_outputs)
            sph_compat_close(&r.compat);
    }
    sph_sim_free(&r.sim);
    free(r.time_steps.v);
    free(r.dt_bounds.v);
    if (r.opt.profile) {
        const sph_profile_times t = {r.setup_seconds, r.step_seconds, r.check_seconds,
                                     r.output_seconds};
        sph_profile_print(stdout, m->name, r.sim.step, &t);
    }
    const long particles = r.particles;
    double ps = (double)particles * (double)r.sim.step;
    if (state == 2 && r.t_checkpoint > 0) {
        sph_error("stopped by %s at t = %g s (step %ld); the checkpoint %s/checkpoint.bin "
                  "resumes the run (--restart)", stop_name(),
                  r.sim.t, r.sim.step, r.opt.out_dir);
        return SPH_EXIT_STOPPED;
    }
    if (state == 2) {
        sph_error("stopped by %s at t = %g s (step %ld); its outputs up to then are in %s/ "
                  "(no checkpoint to resume from: see --checkpoint)", stop_name(), r.sim.t,
                  r.sim.step, r.opt.out_dir);
        return SPH_EXIT_SIGNALLED;
    }
    if (state == 1) {
        sph_error("the run went unstable at %s", r.unstable);
        sph_note("the last good output is in %s/ (t = %g s)", r.opt.out_dir,
                 r.frame_times[r.nframes - 1]);
        stretch_hint(&r);
        return SPH_EXIT_UNSTABLE;
    }
    threads_hint(&r);
    if (!r.opt.quiet)
        printf("%s: %ld particles, %ld steps to t = %g s in %.2f s (%.1f ns per particle-step)"
               "%s%s\n%s: ParaView: %s/particles/%s.pvd ; energies and measurements in %s/\n",
               m->name, particles, r.sim.step, r.sim.t, wall,
               ps > 0 ? 1e9 * r.step_seconds / ps : 0.0, r.errors[0] ? "; errors: " : "",
               r.errors, m->name, r.opt.out_dir, m->bodies[0].name, r.opt.out_dir);
    return failed ? SPH_EXIT_EXPECT : 0;
}
