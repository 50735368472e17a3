/* csv.c — CSV time series: a header line of column names, then one row of values per
 * call (%.10g, separated by commas or the file's separator), flushed at once so that the
 * data survive a run that is stopped early. */
#include "output.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

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

int sph_csv_open_sep(sph_csv *c, const char *path, const char *const *columns, int ncols,
                     char sep)
{
    c->ncols = ncols;
    c->sep = sep;
    c->f = fopen(path, "w");
    if (!c->f)
        return write_error(path, errno);
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
}
