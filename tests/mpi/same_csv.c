/* same_csv A.csv B.csv TOL — whether two runs' CSV files (energies, measurements) agree: the
 * same header and rows, and every value of B within TOL times its column's scale of A's
 * value.  The scale of a column is its largest magnitude in A over the run, and for the
 * components of a vector (ux uy uz, fx fy fz: two-letter names with the same first letter)
 * the largest of its components': a measured force that passes through zero, or a component
 * that stays near zero, is compared with the size the quantity has, not with its value there.
 * Prints the worst difference; exit 0 when they agree, 1 when not, 2 when a file cannot be
 * read. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAXCOL = 64, MAXROW = 100000 };

typedef struct {
    char header[4096];
    int ncol, nrow;
    double *v; /* nrow x ncol */
} table;

static int read_table(const char *path, table *t)
{
    FILE *f = fopen(path, "r");
    if (!f || !fgets(t->header, sizeof t->header, f))
        return fprintf(stderr, "same_csv: cannot read %s\n", path), -1;
    t->ncol = 1; /* (columns apart by commas, or by tabs: the SoliDualSPHysics files) */
    for (const char *c = t->header; *c; c++)
        t->ncol += *c == ',' || *c == '\t';
    if (t->ncol > MAXCOL)
        return fprintf(stderr, "same_csv: %s: too many columns\n", path), -1;
    t->v = malloc(sizeof *t->v * MAXCOL * MAXROW);
    t->nrow = 0;
    char line[8192];
    while (t->v && t->nrow < MAXROW && fgets(line, sizeof line, f)) {
        char *p = line;
        for (int c = 0; c < t->ncol; c++) {
            t->v[(size_t)t->nrow * t->ncol + c] = strtod(p, &p);
            if (*p == ',' || *p == '\t')
                p++;
        }
        t->nrow++;
    }
    fclose(f);
    return t->v ? 0 : -1;
}

int main(int argc, char **argv)
{
    if (argc != 4)
        return fprintf(stderr, "usage: same_csv A.csv B.csv TOL\n"), 2;
    table a, b;
    if (read_table(argv[1], &a) || read_table(argv[2], &b))
        return 2;
    const double tol = atof(argv[3]);
    if (strcmp(a.header, b.header) || a.nrow != b.nrow) {
        printf("FAIL %s: header or rows (%d) differ from %s (%d)\n", argv[2], b.nrow, argv[1],
               a.nrow);
        return 1;
    }
    char name[MAXCOL][64] = {{0}};
    const char *h = a.header;
    for (int c = 0; c < a.ncol; c++) { /* the column names */
        size_t n = strcspn(h, ",\t\n");
        snprintf(name[c], sizeof name[c], "%.*s", (int)n, h);
        h += n + (h[n] == ',' || h[n] == '\t');
    }
    double worst = 0;
    int wr = 0, wc = 0;
    for (int c = 0; c < a.ncol; c++) {
        double scale = 0;
        for (int g = 0; g < a.ncol; g++) /* the column, or its vector's components */
            if (g == c || (strlen(name[c]) == 2 && strlen(name[g]) == 2 && name[g][0] == name[c][0]))
                for (int r = 0; r < a.nrow; r++)
                    scale = fmax(scale, fabs(a.v[(size_t)r * a.ncol + g]));
        for (int r = 0; r < a.nrow; r++) {
            const double x = a.v[(size_t)r * a.ncol + c], y = b.v[(size_t)r * a.ncol + c];
            const double d = scale > 0 ? fabs(x - y) / scale : fabs(x - y);
            if (!(d <= worst)) /* (also a value that is not a number) */
                worst = d, wr = r, wc = c;
        }
    }
    const int ok = worst <= tol;
    printf("%s %s: %d rows, largest difference %.3g of the column's scale (row %d, column %d; "
           "limit %g)\n", ok ? "ok" : "FAIL", argv[2], a.nrow, worst, wr + 1, wc + 1, tol);
    return ok ? 0 : 1;
}
