/* reference_csv.c — a reference solution from a CSV file of (t, value) rows
 * (`reference M.Q = file "F.csv"`, docs/language.md).
 *
 * Rows are two numbers separated by a comma (blanks allowed); one line before the first
 * row may be a header (anything that is not a row); empty lines and lines starting with '#' are skipped.
 * Times must increase strictly, and there must be at least two rows.  The compiler reads
 * the file once and puts the numbers into the generated program. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reference_csv.h"
#include "util/diag.h"
#include "core/regular_file.h"

static int blank(const char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n')
        s++;
    return *s == '\0' || *s == '#';
}

/* Parses "t, v"; 0 on success. */
static int row(const char *line, double *t, double *v)
{
    char *end;
    errno = 0;
    *t = strtod(line, &end);
    if (end == line || errno)
        return -1;
    while (*end == ' ' || *end == '\t')
        end++;
    if (*end++ != ',')
        return -1;
    const char *rest = end;
    *v = strtod(rest, &end);
    if (end == rest || errno || !isfinite(*t) || !isfinite(*v))
        return -1;
    return blank(end) ? 0 : -1;
}

int reference_csv_read(const char *path, SrcLoc loc, double **t, double **v, int *n)
{
    if (sph_not_regular_file(path)) {
        diag_error(loc, "the reference file '%s' is not a regular file", path);
        return -1;
    }
    FILE *f = fopen(path, "r");
    if (!f) {
        diag_error(loc, "cannot open the reference file '%s': %s", path, strerror(errno));
        return -1;
    }
    char line[4096];
    int cap = 64, lineno = 0, bad = 0, header = 0;
    *n = 0;
    *t = malloc(cap * sizeof **t);
    *v = malloc(cap * sizeof **v);
    while (!bad && fgets(line, sizeof line, f)) {
        lineno++;
        if (!strchr(line, '\n') && !feof(f)) {
            diag_error(loc, "%s:%d: the line is longer than %d characters", path, lineno,
                       (int)sizeof line - 2);
            bad = 1;
            break;
        }
        if (blank(line))
            continue;
        double a, b;
        if (row(line, &a, &b)) {
            if (*n == 0 && !header++)
                continue; /* a header */
            diag_error(loc, "%s:%d: expected a row 't, value' of two numbers", path, lineno);
            bad = 1;
            break;
        }
        if (*n > 0 && !(a > (*t)[*n - 1])) {
            diag_error(loc, "%s:%d: times must increase (t = %g after %g)", path, lineno, a,
                       (*t)[*n - 1]);
            bad = 1;
            break;
        }
        if (*n == cap) {
            cap *= 2;
            *t = realloc(*t, cap * sizeof **t);
            *v = realloc(*v, cap * sizeof **v);
        }
        (*t)[*n] = a;
        (*v)[(*n)++] = b;
    }
    fclose(f);
    if (!bad && *n < 2) {
        diag_error(loc, "the reference file '%s' has %d row%s of data; it needs at least two", path,
                   *n, *n == 1 ? "" : "s");
        bad = 1;
    }
    if (bad) {
        free(*t);
        free(*v);
        *t = *v = NULL;
        *n = 0;
        return -1;
    }
    return 0;
}
