/* csv.c — CSV time series: a header line of column names, then one row of values per
 * call (%.10g, separated by commas or the file's separator), flushed at once so that the
 * data survive a run that is stopped early.
 *
 * A checkpoint records how long every open file is (sph_csv_open_files); a run resumed from
 * it keeps those files, cut back to that length, and appends to them (sph_csv_resume). */
#include "output.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The files open now (for a checkpoint), and those a resumed run keeps. */
static struct {
    sph_csv **open;
    int nopen;
    char **keep;
    long *keep_len;
    int nkeep;
} files;

static int write_error(const char *what, int err)
{
    sph_error("cannot write %s: %s", what, strerror(err ? err : EIO));
    return -1;
}

/* Flushes f; returns 0, or the error of the failed write. */
static int flush_checked(FILE *f)
{
    if (fflush(f) != 0 || ferror(f))
        return errno ? errno : EIO;
    return 0;
}

int sph_csv_open(sph_csv *c, const char *path, const char *const *columns, int ncols)
{
    return sph_csv_open_sep(c, path, columns, ncols, ',');
}

static void track(sph_csv *c, const char *path)
{
    c->path = strdup(path);
    sph_csv **grown = realloc(files.open, (size_t)(files.nopen + 1) * sizeof *grown);
    if (!c->path || !grown) {
        free(c->path);
        c->path = NULL; /* (not listed: a checkpoint then reports it missing) */
        return;
    }
    files.open = grown;
    files.open[files.nopen++] = c;
}

/* A resumed run's file at path: opened, cut back to its recorded length and wound to its
 * end; -1 after reporting when it is not one of them, is missing or is shorter. */
static int keep(sph_csv *c, const char *path)
{
    int k = 0;
    while (k < files.nkeep && strcmp(files.keep[k], path))
        k++;
    if (k == files.nkeep) {
        sph_error("cannot resume %s: the checkpoint has no record of it (is it a checkpoint "
                  "of this model?)", path);
        return -1;
    }
    struct stat st;
    c->f = fopen(path, "r+");
    if (!c->f || fstat(fileno(c->f), &st) || st.st_size < files.keep_len[k]) {
        sph_error("cannot resume %s: %s", path, !c->f ? strerror(errno)
                  : "it is shorter than when the checkpoint was written");
        if (c->f)
            fclose(c->f);
        c->f = NULL;
        return -1;
    }
    if (ftruncate(fileno(c->f), (off_t)files.keep_len[k]) || fseek(c->f, 0, SEEK_END)) {
        const int err = errno;
        fclose(c->f);
        c->f = NULL;
        return write_error(path, err);
    }
    track(c, path);
    return 0;
}

int sph_csv_open_sep(sph_csv *c, const char *path, const char *const *columns, int ncols,
                     char sep)
{
    c->ncols = ncols;
    c->sep = sep;
    c->path = NULL;
    if (files.nkeep)
        return keep(c, path);
    c->f = fopen(path, "w");
    if (!c->f)
        return write_error(path, errno);
    track(c, path);
    errno = 0;
    for (int k = 0; k < ncols; k++) {
        if (k)
            fputc(c->sep, c->f);
        fputs(columns[k], c->f);
    }
    fputc('\n', c->f);
    int err = flush_checked(c->f);
    if (err) {
        fclose(c->f);
        c->f = NULL;
        return write_error(path, err);
    }
    return 0;
}

int sph_csv_row(sph_csv *c, const double *values)
{
    if (!c->f)
        return -1;
    errno = 0;
    for (int k = 0; k < c->ncols; k++) {
        if (k)
            fputc(c->sep, c->f);
        fprintf(c->f, "%.10g", values[k]);
    }
    fputc('\n', c->f);
    int err = flush_checked(c->f);
    return err ? write_error("CSV file", err) : 0;
}

void sph_csv_close(sph_csv *c)
{
    if (c->f)
        fclose(c->f);
    c->f = NULL;
    for (int k = 0; k < files.nopen; k++)
        if (files.open[k] == c) {
            files.open[k] = files.open[--files.nopen];
            break;
        }
    free(c->path);
    c->path = NULL;
}

int sph_csv_open_files(const char ***paths, long **lengths)
{
    *paths = malloc(((size_t)files.nopen + 1) * sizeof **paths);
    *lengths = malloc(((size_t)files.nopen + 1) * sizeof **lengths);
    int n = 0;
    for (int k = 0; k < files.nopen && *paths && *lengths; k++) {
        const long len = files.open[k]->f ? ftell(files.open[k]->f) : -1;
        if (len < 0)
            continue;
        (*paths)[n] = files.open[k]->path;
        (*lengths)[n++] = len;
    }
    return n;
}

void sph_csv_resume(const char *const *paths, const long *lengths, int n)
{
    for (int k = 0; k < files.nkeep; k++)
        free(files.keep[k]);
    free(files.keep);
    free(files.keep_len);
    files.keep = calloc((size_t)n + 1, sizeof *files.keep);
    files.keep_len = calloc((size_t)n + 1, sizeof *files.keep_len);
    files.nkeep = files.keep && files.keep_len ? n : 0;
    for (int k = 0; k < files.nkeep; k++) {
        files.keep[k] = strdup(paths[k]);
        files.keep_len[k] = lengths[k];
    }
}
