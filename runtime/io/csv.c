/* csv.c — CSV time series: a header line of column names, then one row of values per
 * call (%.10g, separated by commas or the file's separator).  Each line is made whole in
 * memory and handed to the system in one write(2), past any stdio buffer: the rows are in
 * the file as soon as they are written, and a run killed (or a disk filled) between two
 * rows leaves whole rows only (a row whose write fails is cut off again).
 *
 * A checkpoint records how long every open file is (sph_csv_open_files); a run resumed from
 * it keeps those files, cut back to that length, and appends to them (sph_csv_resume). */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "csv.h"
#include "core/message.h"

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

/* Appends line (len bytes) to c's file with one write; returns 0, or the error, after
 * cutting the file back to where the line began. */
static int write_line(sph_csv *c, const char *line, size_t len)
{
    const int fd = fileno(c->f);
    const off_t at = lseek(fd, 0, SEEK_CUR);
    size_t done = 0;
    while (done < len) { /* (a regular file takes it whole but for a full disk) */
        const ssize_t n = write(fd, line + done, len - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const int err = n < 0 && errno ? errno : ENOSPC;
            if (at >= 0 && !ftruncate(fd, at))
                lseek(fd, at, SEEK_SET);
            return err;
        }
        done += (size_t)n;
    }
    return 0;
}

/* A line of text in a growing buffer. */
typedef struct {
    char *s;
    size_t len, cap;
} line_buf;

static void put(line_buf *b, const char *text)
{
    const size_t n = strlen(text);
    if (b->len + n + 1 > b->cap) {
        const size_t cap = 2 * (b->len + n + 1);
        char *grown = realloc(b->s, cap);
        if (!grown) {
            free(b->s);
            *b = (line_buf){0};
            return;
        }
        b->s = grown, b->cap = cap;
    }
    if (b->s) {
        memcpy(b->s + b->len, text, n + 1);
        b->len += n;
    }
}

/* The line of fields k < n, given as text (text[k]) or as numbers (values[k], %.10g); 0,
 * or the error of writing it. */
static int write_fields(sph_csv *c, const char *const *text, const double *values)
{
    line_buf b = {malloc(64), 0, 64};
    if (b.s)
        b.s[0] = '\0';
    for (int k = 0; k < c->ncols; k++) {
        char num[40], sep[2] = {c->sep, '\0'};
        if (k)
            put(&b, sep);
        if (!text)
            snprintf(num, sizeof num, "%.10g", values[k]);
        put(&b, text ? text[k] : num);
    }
    put(&b, "\n");
    const int err = b.s ? write_line(c, b.s, b.len) : ENOMEM;
    free(b.s);
    return err;
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
    if (ftruncate(fileno(c->f), (off_t)files.keep_len[k]) ||
        lseek(fileno(c->f), 0, SEEK_END) < 0) {
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
    const int err = write_fields(c, columns, NULL);
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
    const int err = write_fields(c, NULL, values);
    return err ? write_error(c->path ? c->path : "CSV file", err) : 0;
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
        const long len = files.open[k]->f ? (long)lseek(fileno(files.open[k]->f), 0, SEEK_CUR)
                                          : -1;
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

/* ------------------------------------------------------------------ reading */

/* The comma-separated fields of line (cut in place, the newline dropped): how many. */
static int split(char *line, char **field, int max)
{
    int n = 0;
    line[strcspn(line, "\r\n")] = '\0';
    for (char *p = line; n < max; p++) {
        field[n++] = p;
        p = strchr(p, ',');
        if (!p)
            break;
        *p = '\0';
    }
    return n;
}

void sph_csv_table_free(sph_csv_table *t)
{
    for (int k = 0; t->names && k < t->ncols; k++)
        free(t->names[k]);
    free(t->names);
    free(t->v);
    *t = (sph_csv_table){0};
}

int sph_csv_table_add(sph_csv_table *t, const double *row, long max)
{
    const size_t w = (size_t)t->ncols;
    const long index = t->total++;
    if (t->stride < 1)
        t->stride = 1;
    if (t->tail) /* (the previous last row, off the stride) */
        t->nrows--, t->tail = 0;
    if (!t->v && !(t->v = malloc(((size_t)max + 1) * w * sizeof *t->v)))
        return -1;
    if (index % t->stride == 0 && t->nrows >= max) { /* every other row goes */
        for (long r = 0; 2 * r < t->nrows; r++)
            memmove(t->v + (size_t)r * w, t->v + (size_t)(2 * r) * w, w * sizeof *t->v);
        t->nrows = (t->nrows + 1) / 2;
        t->stride *= 2;
    }
    t->tail = index % t->stride != 0;
    memcpy(t->v + (size_t)t->nrows++ * w, row, w * sizeof *t->v);
    return 0;
}

int sph_csv_read(const char *path, sph_csv_table *t, long max)
{
    *t = (sph_csv_table){0};
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char *line = NULL;
    size_t cap = 0;
    int bad = getline(&line, &cap, f) < 0;
    char **field = bad ? NULL : calloc(strlen(line) + 2, sizeof *field);
    const int nfield = field ? (int)strlen(line) + 1 : 0;
    if (field) {
        t->ncols = split(line, field, nfield);
        t->names = calloc((size_t)t->ncols, sizeof *t->names);
        for (int k = 0; t->names && k < t->ncols; k++)
            t->names[k] = strdup(field[k]);
        bad = !t->names;
    }
    double *row = bad ? NULL : malloc((size_t)t->ncols * sizeof *row);
    bad = bad || !row;
    while (!bad && getline(&line, &cap, f) >= 0 && split(line, field, nfield) == t->ncols) {
        int whole = 1;
        for (int k = 0; k < t->ncols; k++) {
            char *end;
            row[k] = strtod(field[k], &end);
            whole &= end != field[k];
        }
        if (!whole)
            break;
        bad = sph_csv_table_add(t, row, max);
    }
    free(row);
    free(field);
    free(line);
    fclose(f);
    if (bad)
        sph_csv_table_free(t);
    return bad ? -1 : 0;
}
