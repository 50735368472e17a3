/* csv.h — CSV time series (csv.c).  0 on success, -1 on an I/O error (reported). */
#ifndef SPHRT_IO_CSV_H
#define SPHRT_IO_CSV_H

#include <stdio.h>

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

/* A time series kept in at most max + 1 rows (a CSV file read back, or a series a run keeps):
 * names of ncols columns; of the total rows added, those at 0, stride, 2 stride, ... and the
 * last; nrows of ncols numbers in v (row r, column k: v[r * ncols + k]).  When max rows are
 * kept every other one goes and the stride doubles.  A zero table ({ncols, names}) is empty. */
typedef struct {
    int ncols;
    char **names;
    long nrows;
    double *v;
    long total, stride; /* stride 0: 1 */
    int tail;           /* the last row is there only as the last (not on the stride) */
} sph_csv_table;
/* Adds a row of ncols numbers (0, or -1 out of memory: the row is not kept). */
int sph_csv_table_add(sph_csv_table *t, const double *row, long max);
/* A CSV file (comma-separated, a header line of names) read back, at most max + 1 rows kept;
 * a line without ncols numbers (none is written so) ends it.  0, or -1 (t then empty). */
int sph_csv_read(const char *path, sph_csv_table *t, long max);
void sph_csv_table_free(sph_csv_table *t); /* (the names too) */

#endif
