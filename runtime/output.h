/* output.h — files a run writes: ParaView particles, CSV time series, summary.json,
 * and the terminal progress line.  All functions return 0 on success, -1 on an I/O
 * error (after printing "sph: error: cannot write PATH: reason" to stderr). */
#ifndef SPHRT_OUTPUT_H
#define SPHRT_OUTPUT_H

#include <stdio.h>
#include "sphrt.h"

/* mkdir -p */
int sph_mkdirs(const char *path);

/* A file written whole: sph_open_whole opens PATH.tmp beside it (NULL and errno when it
 * cannot), sph_close_whole closes it and renames it over PATH once complete (0, or the
 * error, the temporary file removed), so that a run killed while writing leaves the
 * previous file or none, never a part of one. */
FILE *sph_open_whole(const char *path);
int sph_close_whole(FILE *f, const char *path);

/* The files a run writes in folder dir (summary.json, the CSV files, the checkpoint, the
 * frames and .pvd lists in particles/, and those cut short while being written), by their
 * names: how many there are, the first one's in first (len bytes; NULL: not wanted), and
 * all of them removed when remove_them (-1 after reporting one that cannot be). */
long sph_run_files(const char *dir, int remove_them, char *first, size_t len);

/* One VTK XML UnstructuredGrid (.vtu) file of a body's particles (VTK_VERTEX cells), binary
 * "raw" appended data with UInt64 headers, Float64 values.  Points are the current positions
 * X+u in 3D (2D: y = body->y_plane).  Point data: "displacement" (3), "velocity" (3),
 * "cauchy_stress" (6 components xx yy zz xy yz zx, from body->sigma), "sigma_vm" (von Mises),
 * "J" (det F), "strain_energy" (psi); with fracture also
 * "phase_field" (s) and "history" (H, eq. 8). */
int sph_write_vtu(const char *path, const sph_body *b, double t);

/* The frame of a body on many processes: a .pvtu file listing the pieces, one .vtu file of
 * each process's own particles (relative to the .pvtu), with the arrays body b's have. */
int sph_write_pvtu(const char *path, const sph_body *b, const char *const *pieces, int npieces);

/* A ParaView collection (.pvd) listing files[k] (relative to the pvd) at times[k]. */
int sph_write_pvd(const char *path, const char *const *files, const double *times, int n);

/* A CSV time series: opened once with a header line, appended row by row, each line with
 * one write (no half row is left by a run killed between two).
 * Fields are separated by commas, or by `sep` with sph_csv_open_sep. */
typedef struct {
    FILE *f;
    int ncols;
    char sep;
    char *path;
} sph_csv;
int sph_csv_open(sph_csv *c, const char *path, const char *const *columns, int ncols);
int sph_csv_open_sep(sph_csv *c, const char *path, const char *const *columns, int ncols,
                     char sep);
int sph_csv_row(sph_csv *c, const double *values); /* ncols values, %.10g */
void sph_csv_close(sph_csv *c);
/* The CSV files open now and their lengths in bytes, for a checkpoint: n, with paths[k]
 * and lengths[k] (k < n) in arrays the caller frees (not the strings). */
int sph_csv_open_files(const char ***paths, long **lengths);
/* A run resumed from a checkpoint: from now on opening one of these n files keeps it, cut
 * back to its length, and appends to it (no header); opening any other is an error. */
void sph_csv_resume(const char *const *paths, const long *lengths, int n);

/* A small JSON writer (pretty-printed, 2-space indent) for summary.json, written whole
 * (sph_open_whole). */
typedef struct {
    FILE *f;
    char *path;
    int depth;
    int first[32]; /* per depth: no member written yet */
} sph_json;
int sph_json_open(sph_json *j, const char *path);  /* writes "{" */
void sph_json_key_object(sph_json *j, const char *key);  /* "key": {   (key NULL inside arrays) */
void sph_json_key_array(sph_json *j, const char *key);   /* "key": [ */
void sph_json_end_object(sph_json *j);
void sph_json_end_array(sph_json *j);
void sph_json_num(sph_json *j, const char *key, double v);  /* non-finite -> null */
void sph_json_int(sph_json *j, const char *key, long v);
void sph_json_str(sph_json *j, const char *key, const char *s); /* escaped */
void sph_json_bool(sph_json *j, const char *key, int v);
int sph_json_close(sph_json *j);  /* writes the final "}" and closes */

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

/* The profile (profile.c): the passes' times in summary.json ("profile"), and as a table. */
void sph_profile_json(sph_json *j);
typedef struct {
    double setup, steps, checks, outputs; /* the run's timers, in seconds */
} sph_profile_times;
void sph_profile_print(FILE *f, const char *model, long steps, const sph_profile_times *t);

/* Command-line options of a generated program. */
typedef struct {
    const char *out_dir;  /* --out DIR (default "<model>_out") */
    int threads;          /* --threads N (0 = OpenMP default) */
    int partition;        /* --partition N: report the decomposition and exit (0: run) */
    double t_end;         /* --end T   (< 0: model's) */
    double t_out;         /* --every T (< 0: model's) */
    double t_frames;      /* --frames T: particle files every T (< 0: every output) */
    double t_checkpoint;  /* --checkpoint T: the state every T (< 0: none) */
    const char *restart;  /* --restart FILE: resume from this checkpoint (NULL: none) */
    int quiet;            /* --quiet */
    int profile;          /* --profile: the time of each pass of the step */
    int no_stencil;       /* --no-stencil: no lattice stencil in the pair passes */
    int whole_law;        /* --whole-law: no fast path of the material laws */
    int overwrite;        /* --overwrite: replace the outputs of an earlier run in out_dir */
    double progress;      /* --progress T: a progress line every T s in a log (0: none) */
} sph_options;
/* Parses argv; prints usage and returns -1 on a bad option (the caller exits 2);
 * returns 1 after printing --help, 0 otherwise. */
int sph_parse_options(sph_options *o, const char *model_name, int argc, char **argv);

#endif
