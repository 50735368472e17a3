/* run_checkpoint.c — a program's own records in its checkpoint (checkpoint.c has the file
 * and the simulation's): the next output, frame and checkpoint times, the frames the .pvd
 * lists, the time series the expectations read, the timers and counts, the monitor's largest
 * energy, and how long each output file is, so that a resumed run cuts them back and goes
 * on. */
#include <errno.h>
#include <math.h>

#include "measure.h"
#include "run_state.h"
#include "core/clock.h"
#include "core/message.h"
#include "io/checkpoint.h"
#include "io/csv.h"
#include "io/vtu.h"
#include "par/par.h"

enum { RUN_TIMES = 10 }; /* the doubles of the record "run.times" */

/* Whether a checkpoint is due at this output (--checkpoint), and the next one's time. */
int sph_run_checkpoint_due(run_state *r)
{
    const double t = r->sim.t, eps = 1e-9 * r->t_out;
    const double every = r->t_checkpoint;
    if (!(every > 0) || t < r->next_checkpoint - eps)
        return 0;
    r->next_checkpoint = (floor((t + eps) / every) + 1) * every; /* (at worst: every output) */
    return 1;
}

/* The record of measurement q's time series. */
static void measure_record(char *out, size_t len, int q)
{
    snprintf(out, len, "run.series.measure.%d", q);
}

/* A time series as one record: n, the n times, the n rows. */
static void put_series(sph_ckpt_writer *w, const char *name, const sph_series *q)
{
    const size_t n = (size_t)q->n, bytes = (1 + n + n * (size_t)q->width) * sizeof(double);
    double *buf = malloc(bytes);
    if (!buf) {
        w->bad = ENOMEM;
        return;
    }
    buf[0] = (double)q->n;
    if (n) {
        memcpy(buf + 1, q->t, n * sizeof(double));
        memcpy(buf + 1 + n, q->val, n * (size_t)q->width * sizeof(double));
    }
    sph_ckpt_put(w, name, buf, bytes);
    free(buf);
}

/* The output files' names in the output folder, and their lengths now. */
static void put_files(sph_ckpt_writer *w, const run_state *r)
{
    const char **paths;
    long *lengths;
    const int n = sph_csv_open_files(&paths, &lengths);
    const size_t dir = strlen(r->opt.out_dir);
    size_t bytes = 0;
    for (int k = 0; k < n; k++)
        bytes += strlen(paths[k]) + 1;
    char *names = malloc(bytes + 1), *at = names;
    for (int k = 0; k < n && names; k++) { /* relative to the folder, which may be renamed */
        const char *p = paths[k];
        if (!strncmp(p, r->opt.out_dir, dir) && p[dir] == '/')
            p += dir + 1;
        memcpy(at, p, strlen(p) + 1);
        at += strlen(p) + 1;
    }
    if (names) {
        sph_ckpt_put(w, "run.files", names, (size_t)(at - names));
        sph_ckpt_put(w, "run.file_lengths", lengths, (size_t)n * sizeof *lengths);
    } else {
        w->bad = ENOMEM;
    }
    free(names), free(paths), free(lengths);
}

/* The whole state of the run into OUT/checkpoint.bin: the simulation's (checkpoint.c), the
 * output and checkpoint times, the frames, the time series the expectations read, the
 * timers, and how long each output file is. */
int sph_run_write_checkpoint(run_state *r)
{
    const sph_par *par = r->sim.par; /* (on many processes process 0 writes the file) */
    sph_ckpt_writer w, *wp = NULL;
    if (par->rank == 0) {
        char *path = joinf("%s/checkpoint.bin%s", r->opt.out_dir, "");
        const int bad = sph_ckpt_create(&w, path);
        free(path);
        wp = bad ? NULL : &w;
    }
    if (par->agree(par->rank == 0 && !wp))
        return -1;
    if (r->m->copy_state)
        r->m->copy_state(&r->sim, 0);
    sph_sim_checkpoint(wp, &r->sim); /* (collective) */
    if (!wp)
        return par->agree(0) ? -1 : 0;
    const double times[RUN_TIMES] = {
        r->next_out, r->next_frame, r->next_checkpoint, r->step_seconds, r->check_seconds,
        r->output_seconds, r->setup_seconds, r->wall_before + sph_wall_time() - r->wall0,
        r->stretch_seen, r->mon.e_ref};
    sph_ckpt_put(&w, "run.times", times, sizeof times);
    const long counts[2] = {r->checks, r->device_checks};
    sph_ckpt_put(&w, "run.counts", counts, sizeof counts);
    sph_ckpt_put(&w, "run.frames", r->frame_times, (size_t)r->nframes * sizeof(double));
    put_series(&w, "run.series.energy", &r->rec.energy);
    for (int q = 0; q < r->nmeasures; q++) {
        char name[64];
        measure_record(name, sizeof name, q);
        put_series(&w, name, &r->rec.measures[q]);
    }
    put_files(&w, r);
    return par->agree(sph_ckpt_commit(&w)) ? -1 : 0;
}

static int take_series(const sph_ckpt *c, const char *name, sph_series *q)
{
    size_t bytes;
    const double *p = sph_ckpt_find(c, name, &bytes);
    const double count = p && bytes >= sizeof(double) ? p[0] : -1;
    const size_t n = count >= 0 && count <= (double)bytes ? (size_t)count : 0;
    if (!p || bytes != (1 + n + n * (size_t)q->width) * sizeof(double)) {
        sph_error("cannot restart from %s: no record '%s' of its size (is it a checkpoint of "
                  "this model?)", c->path, name);
        return -1;
    }
    for (size_t k = 0; k < n; k++)
        sph_series_push(q, p[1 + k], p + 1 + n + k * (size_t)q->width);
    return 0;
}

/* Before the outputs are opened: the files they keep, cut back to their checkpoint length. */
int sph_run_resume_files(const sph_ckpt *c, const run_state *r)
{
    if (r->sim.par->rank != 0)
        return 0; /* (the files are process 0's) */
    size_t nb, lb;
    const char *names = sph_ckpt_find(c, "run.files", &nb);
    const long *lengths = sph_ckpt_find(c, "run.file_lengths", &lb);
    if (!names || !lengths || (nb && names[nb - 1])) {
        sph_error("cannot restart from %s: it lists no output files", c->path);
        return -1;
    }
    const int n = (int)(lb / sizeof(long));
    char **paths = calloc((size_t)n + 1, sizeof *paths);
    long *len = malloc(((size_t)n + 1) * sizeof *len);
    const char *at = names;
    int k = 0;
    for (; k < n && at < names + nb && paths && len; k++, at += strlen(at) + 1) {
        paths[k] = joinf("%s/%s", r->opt.out_dir, at);
        len[k] = lengths[k]; /* (records are 8-byte aligned) */
    }
    const int ok = paths && len && k == n && at == names + nb;
    if (ok)
        sph_csv_resume((const char *const *)paths, len, n);
    else
        sph_error("cannot restart from %s: its list of output files is damaged", c->path);
    for (int q = 0; paths && q < k; q++)
        free(paths[q]);
    free(paths), free(len);
    return ok ? 0 : -1;
}

/* Removes path (and path.tmp, one cut short); 1 when either was there. */
static int remove_frame_file(const char *path)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    const int gone = remove(tmp) == 0;
    return (remove(path) == 0) | gone;
}

/* The frames of body i that the run wrote after its checkpoint: the resumed run writes them
 * again, and one that ends sooner (a shorter --end, a stop) must not leave them beside its
 * own, nor its .pvd list them; on many processes a frame is a .pvtu file and its pieces
 * (NAME_k.pvtu, NAME_k_p0.vtu, ...), which the run may have written on another number of
 * processes.  Process 0's work; 0, or -1 after reporting. */
static int drop_later_frames(const run_state *r, int i)
{
    const char *body = r->sim.bodies[i].desc->name;
    char file[256], path[4096];
    for (int k = r->nframes, gone = 1; gone; k++) {
        frame_file(file, sizeof file, body, k); /* NAME_k.vtu */
        snprintf(path, sizeof path, "%s/particles/%s", r->opt.out_dir, file);
        gone = remove_frame_file(path);
        strcpy(path + strlen(path) - 4, ".pvtu");
        gone |= remove_frame_file(path);
        for (int p = 0, piece = 1; piece; p++) {
            snprintf(path, sizeof path, "%s/particles/%.*s_p%d.vtu", r->opt.out_dir,
                     (int)strlen(file) - 4, file, p);
            piece = remove_frame_file(path);
            gone |= piece;
        }
    }
    snprintf(path, sizeof path, "%s/particles/%s.pvd", r->opt.out_dir, body);
    return sph_write_pvd(path, (const char *const *)r->frame_files[i], r->frame_times,
                         r->nframes);
}

/* The file of body's earlier frame k as the run wrote it: NAME_k.pvtu when it ran on many
 * processes, NAME_k.vtu on one. */
static char *earlier_frame(const run_state *r, const char *body, int k)
{
    char file[256], path[4400];
    frame_file(file, sizeof file, body, k);
    strcpy(file + strlen(file) - 4, ".pvtu");
    snprintf(path, sizeof path, "%s/particles/%s", r->opt.out_dir, file);
    FILE *f = fopen(path, "rb");
    if (f)
        fclose(f);
    else
        frame_file(file, sizeof file, body, k);
    return strdup(file);
}

/* The run's records, after the outputs are open: times, frames, series, timers. */
int sph_run_resume(const sph_ckpt *c, run_state *r)
{
    double times[RUN_TIMES];
    long counts[2];
    size_t bytes;
    const double *frames = sph_ckpt_find(c, "run.frames", &bytes);
    if (sph_ckpt_take(c, "run.times", times, sizeof times) ||
        sph_ckpt_take(c, "run.counts", counts, sizeof counts) || !frames ||
        take_series(c, "run.series.energy", &r->rec.energy))
        return -1;
    for (int q = 0; q < r->nmeasures; q++) {
        char name[64];
        measure_record(name, sizeof name, q);
        if (take_series(c, name, &r->rec.measures[q]))
            return -1;
    }
    /* The next output is at t or after it; a frame or checkpoint time before t is due at the
     * next output, as it would be in the whole run (and one far behind would keep the loop
     * that adds intervals to it from ending). */
    const double t = r->sim.t, eps = 1e-9 * r->t_out;
    if (!(times[0] >= t - eps && times[0] < INFINITY) || !isfinite(times[1]) ||
        !isfinite(times[2])) {
        sph_error("cannot restart from %s: its next output times are damaged", c->path);
        return -1;
    }
    r->next_out = times[0], r->next_frame = fmax(times[1], t);
    r->next_checkpoint = fmax(times[2], t);
    r->step_seconds = times[3], r->check_seconds = times[4], r->output_seconds = times[5];
    r->setup_seconds = times[6], r->wall_before = times[7];
    r->stretch_seen = times[8], r->mon.e_ref = times[9];
    r->checks = counts[0], r->device_checks = counts[1];
    r->nframes = (int)(bytes / sizeof(double));
    r->frame_times = malloc(((size_t)r->nframes + 1) * sizeof(double));
    memcpy(r->frame_times, frames, (size_t)r->nframes * sizeof(double));
    for (int i = 0; i < r->sim.nbodies; i++) { /* the pvd lists the earlier frames again */
        r->frame_files[i] = calloc((size_t)r->nframes + 1, sizeof(char *));
        for (int k = 0; k < r->nframes; k++)
            r->frame_files[i][k] = earlier_frame(r, r->sim.bodies[i].desc->name, k);
    }
    /* (process 0's files; the others wait for it to be done with them) */
    int bad = 0;
    for (int i = 0; i < r->sim.nbodies && r->sim.par->rank == 0; i++)
        bad |= drop_later_frames(r, i);
    return r->sim.par->agree(bad) ? -1 : 0;
}

