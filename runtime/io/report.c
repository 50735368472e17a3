/* report.c — summary.html, a run's report page: self-contained XHTML-compatible markup (no
 * script, no network) with the verdict, the expectations, and inline SVG plots of energies.csv
 * and of each measurement plane's CSV file, and of the mean time step.  Written whole beside its name and renamed over it
 * (sph_open_whole), like summary.json, at the same moments.
 *
 * Every plotted line is a <polyline> that also carries the values it draws, as written in
 * the CSV file, in data-x and data-y (space-separated, the shortest text that reads back as
 * the same double); its <svg> names the file in data-csv (none for the time step, which the
 * run keeps in memory), the line its column in
 * data-column, and data-stride k says which of its data-rows rows were drawn: 0, k, 2k, ...
 * and the last (the tables handed over keep at most SPH_REPORT_POINTS rows and the last: a
 * longer file is drawn downsampled, which the page says). */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fsutil.h"
#include "report.h"
#include "core/message.h"

static const char *const COLORS[] = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
};
enum { NCOLORS = sizeof COLORS / sizeof *COLORS };

/* text with &, <, >, " escaped */
static void put_text(FILE *f, const char *s)
{
    for (; s && *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
}

/* The shortest of %.15g, %.16g, %.17g that reads back as exactly v ("nan", "inf" as such). */
static void put_number(FILE *f, double v)
{
    char buf[40];
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, sizeof buf, "%.*g", prec, v);
        if (!isfinite(v) || strtod(buf, NULL) == v)
            break;
    }
    fputs(buf, f);
}

/* ------------------------------------------------------------------ plots */

/* An axis: from lo to hi with ticks every step (lo and hi on ticks). */
typedef struct {
    double lo, hi, step;
} axis;

/* A range with about 5 ticks at 1, 2 or 5 times a power of ten. */
static axis nice_axis(double lo, double hi)
{
    if (!(lo <= hi)) /* (no finite value) */
        lo = 0, hi = 1;
    if (!isfinite(hi - lo)) /* (values near the largest double) */
        lo = -1e300, hi = 1e300;
    if (hi - lo <= 1e-6 * fmax(fabs(lo), fabs(hi)) || hi - lo <= 1e-300) { /* (a constant,
                                                            or as good as one: round-off) */
        const double pad = lo != 0 ? 0.5 * fabs(lo) : 1.0;
        lo -= pad, hi += pad;
    }
    const double raw = (hi - lo) / 5, mag = pow(10, floor(log10(raw))), r = raw / mag;
    const double step = (r < 1.5 ? 1 : r < 3.5 ? 2 : r < 7.5 ? 5 : 10) * mag;
    return (axis){floor(lo / step) * step, ceil(hi / step) * step, step};
}

/* A plot's frame: its size in pixels and the plotting area's margins. */
typedef struct {
    int width, height, left, right, top, bottom;
} frame;

static double px(const frame *fr, const axis *a, double x)
{
    return fr->left + (x - a->lo) / (a->hi - a->lo) * (fr->width - fr->left - fr->right);
}

static double py(const frame *fr, const axis *a, double y)
{
    return fr->height - fr->bottom -
           (y - a->lo) / (a->hi - a->lo) * (fr->height - fr->top - fr->bottom);
}

/* The significant digits that tell a's ticks apart: 4, or more where the ticks are close
 * beside their size (a time step that varies in its fifth digit; nice_axis makes a range
 * below 1e-6 of its size a constant's). */
static int tick_digits(const axis *a)
{
    const double size = fmax(fabs(a->lo), fabs(a->hi));
    const int digits = (int)ceil(log10(size / a->step)) + 1;
    return digits < 4 ? 4 : digits > 9 ? 9 : digits;
}

/* The axes: the box, the ticks with their labels, grid lines, and the axes' names. */
static void put_axes(FILE *f, const frame *fr, const axis *ax, const axis *ay,
                     const char *xname, const char *yname)
{
    const double x0 = fr->left, x1 = fr->width - fr->right;
    const double y0 = fr->height - fr->bottom, y1 = fr->top;
    const long nx = lround((ax->hi - ax->lo) / ax->step), ny = lround((ay->hi - ay->lo) / ay->step);
    const int dx = tick_digits(ax), dy = tick_digits(ay);
    for (long k = 0; k <= nx; k++) {
        const double v = ax->lo + (double)k * ax->step, x = px(fr, ax, v);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%g\" x2=\"%.1f\" y2=\"%g\" stroke=\"#e4e4e4\"/>"
                   "<text x=\"%.1f\" y=\"%g\" text-anchor=\"middle\">%.*g</text>\n",
                x, y0, x, y1, x, y0 + 14, dx, fabs(v) < 1e-9 * ax->step ? 0.0 : v);
    }
    for (long k = 0; k <= ny; k++) {
        const double v = ay->lo + (double)k * ay->step, y = py(fr, ay, v);
        fprintf(f, "<line x1=\"%g\" y1=\"%.1f\" x2=\"%g\" y2=\"%.1f\" stroke=\"#e4e4e4\"/>"
                   "<text x=\"%g\" y=\"%.1f\" text-anchor=\"end\">%.*g</text>\n",
                x0, y, x1, y, x0 - 4, y + 4, dy, fabs(v) < 1e-9 * ay->step ? 0.0 : v);
    }
    fprintf(f, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" "
               "stroke=\"#444\"/>\n", x0, y1, x1 - x0, y0 - y1);
    fprintf(f, "<text x=\"%g\" y=\"%d\" text-anchor=\"middle\">", (x0 + x1) / 2, fr->height - 4);
    put_text(f, xname);
    fprintf(f, "</text>\n<text x=\"12\" y=\"%g\" text-anchor=\"middle\" "
               "transform=\"rotate(-90 12 %g)\">", (y0 + y1) / 2, (y0 + y1) / 2);
    put_text(f, yname);
    fputs("</text>\n", f);
}

/* A line's values at the rows of table t: column k of t's, or ys (one per row). */
typedef struct {
    const sph_csv_table *t;
    int k;
    const double *ys; /* NULL: column k */
} line_values;

static double value_at(const line_values *l, long r)
{
    return l->ys ? l->ys[r] : l->t->v[(size_t)r * (size_t)l->t->ncols + (size_t)l->k];
}

/* The attribute name="..." of l's values, each number as put_number writes it. */
static void put_values(FILE *f, const char *name, const line_values *l)
{
    fprintf(f, "\n %s=\"", name);
    for (long r = 0; r < l->t->nrows; r++) {
        if (r)
            fputc(' ', f);
        put_number(f, value_at(l, r));
    }
    fputc('"', f);
}

/* What a plot is: its id (NULL: none), the file it draws (its name in the output folder;
 * NULL: a table of the run's memory, the <svg> without data-csv), the name of its y axis,
 * its size in pixels; the expectations drawn over it (those of curves whose plane is plane
 * and whose column is one of the plot's). */
typedef struct {
    const char *id, *file, *yname;
    int width, height;
    const sph_report_curve *curves;
    int ncurves, plane;
    double ylo, yhi; /* the y axis' range where the data's may not change it (0, 0: none) */
} plot_spec;

/* Whether curve c is drawn over the plot of p with columns cols[0..ncols). */
static int curve_in(const plot_spec *p, const sph_report_curve *c, const int *cols, int ncols)
{
    for (int k = 0; k < ncols && c->plane == p->plane; k++)
        if (cols[k] == c->column)
            return 1;
    return 0;
}

/* The range of l's finite values into lo, hi. */
static void widen(const line_values *l, double *lo, double *hi)
{
    for (long r = 0; r < l->t->nrows; r++) {
        const double v = value_at(l, r);
        if (isfinite(v))
            *lo = fmin(*lo, v), *hi = fmax(*hi, v);
    }
}

/* The rest of a polyline whose opening tag and own attributes are written: l's data-x,
 * data-y and points (a pair that is not finite is left out). */
static void put_line(FILE *f, const frame *fr, const axis *ax, const axis *ay,
                     const line_values *l)
{
    const line_values x = {l->t, 0, NULL};
    put_values(f, "data-x", &x);
    put_values(f, "data-y", l);
    fputs("\n points=\"", f);
    int first = 1;
    for (long r = 0; r < l->t->nrows; r++) {
        const double tx = value_at(&x, r), v = value_at(l, r);
        if (isfinite(tx) && isfinite(v)) {
            fprintf(f, "%s%.1f,%.1f", first ? "" : " ", px(fr, ax, tx), py(fr, ay, v));
            first = 0;
        }
    }
    fputs("\"/>\n", f);
}

/* A column's line and its legend entry (the c-th). */
static void put_column_line(FILE *f, const frame *fr, const axis *ax, const axis *ay,
                            const sph_csv_table *t, int k, int c)
{
    const int total = !strcmp(t->names[k], "total");
    const char *color = total ? "#000" : COLORS[c % NCOLORS];
    fputs("<polyline fill=\"none\" data-column=\"", f);
    put_text(f, t->names[k]);
    fprintf(f, "\" stroke=\"%s\" stroke-width=\"%s\"", color, total ? "2" : "1.3");
    put_line(f, fr, ax, ay, &(line_values){t, k, NULL});
    const int ly = fr->top + 8 + 16 * c, lx = fr->width - fr->right + 10;
    fprintf(f, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\" "
               "stroke-width=\"2\"/><text x=\"%d\" y=\"%d\">", lx, ly, lx + 20, ly, color,
            lx + 26, ly + 4);
    put_text(f, t->names[k]);
    fputs("</text>\n", f);
}

/* An expectation's curve, dashed, in its column's colour (the c-th column of the plot):
 * data-expect its kind, data-column its column, data-model its line; a period's sinusoid
 * also its numbers. */
static void put_curve(FILE *f, const frame *fr, const axis *ax, const axis *ay,
                      const sph_csv_table *t, const sph_report_curve *cv, int c)
{
    fprintf(f, "<polyline fill=\"none\" data-expect=\"%s\" data-column=\"", cv->kind);
    put_text(f, t->names[cv->column]);
    fputs("\" data-model=\"", f);
    put_text(f, cv->text);
    fputc('"', f);
    if (!strcmp(cv->kind, "period")) {
        const double v[4] = {cv->period, cv->mid, cv->amplitude, cv->t0};
        static const char *const names[4] = {"period", "mid", "amplitude", "t0"};
        for (int k = 0; k < 4; k++) {
            fprintf(f, " data-%s=\"", names[k]);
            put_number(f, v[k]);
            fputc('"', f);
        }
    }
    fprintf(f, " stroke=\"%s\" stroke-width=\"1\" stroke-dasharray=\"5,3\"",
            COLORS[c % NCOLORS]);
    put_line(f, fr, ax, ay, &(line_values){t, 0, cv->y});
}

/* A line plot of table t as p says: column 0, the time, along x, columns cols[0..ncols) each
 * a line, named in a legend on the right, and the expectations drawn over them dashed. */
static void line_plot(FILE *f, const plot_spec *p, const sph_csv_table *t, const int *cols,
                      int ncols)
{
    int legend = 0; /* (the longest name) */
    for (int c = 0; c < ncols; c++)
        legend = (int)fmax(legend, (double)strlen(t->names[cols[c]]));
    const long stride = t->stride > 1 ? t->stride : 1;
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    widen(&(line_values){t, 0, NULL}, &xlo, &xhi);
    for (int c = 0; c < ncols; c++)
        widen(&(line_values){t, cols[c], NULL}, &ylo, &yhi);
    for (int k = 0; k < p->ncurves; k++)
        if (curve_in(p, &p->curves[k], cols, ncols))
            widen(&(line_values){t, 0, p->curves[k].y}, &ylo, &yhi);
    if (p->ylo < p->yhi)
        ylo = p->ylo, yhi = p->yhi;
    const axis ax = nice_axis(xlo, xhi), ay = nice_axis(ylo, yhi);
    const frame fr = {p->width, p->height, 84 + 7 * (tick_digits(&ay) - 4), 48 + 7 * legend,
                      12, 36}; /* (the y ticks' labels and the legend beside the plot) */
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "viewBox=\"0 0 %d %d\"", p->width, p->height, p->width, p->height);
    if (p->id)
        fprintf(f, " id=\"%s\"", p->id);
    if (p->file) {
        fputs(" data-csv=\"", f);
        put_text(f, p->file);
        fputc('"', f);
    }
    fprintf(f, " data-stride=\"%ld\" data-rows=\"%ld\">\n", stride, t->total);
    put_axes(f, &fr, &ax, &ay, "time (s)", p->yname);
    for (int c = 0; c < ncols; c++) {
        put_column_line(f, &fr, &ax, &ay, t, cols[c], c);
        for (int k = 0; k < p->ncurves; k++)
            if (curve_in(p, &p->curves[k], &cols[c], 1))
                put_curve(f, &fr, &ax, &ay, t, &p->curves[k], c);
    }
    fputs("</svg>\n", f);
    if (stride > 1)
        fprintf(f, "<p class=\"note\">%ld rows: one in %ld drawn, and the last.</p>\n",
                t->total, stride);
    else if (t->nrows == 0)
        fputs("<p class=\"note\">No rows yet.</p>\n", f);
}

/* ------------------------------------------------------------------ the page */

static const char STYLE[] =
    "body{font-family:sans-serif;margin:1.5em;color:#222}"
    "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 8px;"
    "text-align:right}td.text{text-align:left;font-family:monospace}"
    ".pass{color:#1a7f37}.fail{color:#c62828;font-weight:bold}"
    ".verdict{font-size:1.2em;padding:6px 10px;border-radius:4px;display:inline-block}"
    ".finished{background:#e6f4ea}.running{background:#e8f0fe}"
    ".unstable,.failed{background:#fdecea}.stopped{background:#fff4e5}"
    "svg text{font-size:11px;font-family:sans-serif}.note{color:#666;font-size:0.9em}"
    ".planes svg{margin-right:1em}";

static void put_verdict(FILE *f, const sph_report *r)
{
    fprintf(f, "<p id=\"verdict\" class=\"verdict %s\">", r->status);
    if (!strcmp(r->status, "running"))
        fprintf(f, "Running: t = %g s of %g s, step %ld (this page is written again as the "
                   "run goes on, and at its end).", r->time, r->end_time, r->steps);
    else if (!strcmp(r->status, "finished"))
        fprintf(f, "Finished: t = %g s, %ld steps.", r->time, r->steps);
    else if (!strcmp(r->status, "unstable"))
        fputs("Unstable: ", f);
    else if (!strcmp(r->status, "stopped"))
        fprintf(f, "Stopped by %s at t = %g s (step %ld).", r->message ? r->message : "a signal",
                r->time, r->steps);
    else
        fprintf(f, "Failed at t = %g s (step %ld): an output could not be written.", r->time,
                r->steps);
    if (r->message && !strcmp(r->status, "unstable"))
        put_text(f, r->message);
    fputs("</p>\n", f);
    if (isfinite(r->wall_time))
        fprintf(f, "<p>Wall time %.3g s.</p>\n", r->wall_time);
}

static void put_cell(FILE *f, double v, double scale)
{
    if (isfinite(v))
        fprintf(f, "<td>%.4g</td>", scale * v);
    else
        fputs("<td></td>", f);
}

/* The stability monitor's checks: how near each came to its limit (data-seen: the number in
 * full). */
static void put_margins(FILE *f, const sph_report *r)
{
    if (!r->nmargins)
        return;
    fputs("<h2>Stability margins</h2>\n<p class=\"note\">The nearest the stability "
          "monitor's checks saw the run come to their limits.</p>\n<table id=\"margins\">\n"
          "<tr><th>check</th><th>nearest seen</th><th>limit</th></tr>\n", f);
    for (int k = 0; k < r->nmargins; k++) {
        const sph_report_margin *m = &r->margins[k];
        fprintf(f, "<tr data-check=\"%s\" data-seen=\"", m->key);
        put_number(f, m->seen);
        fputs("\"><td class=\"text\">", f);
        put_text(f, m->text);
        fputs("</td>", f);
        put_cell(f, m->seen, 1);
        fprintf(f, "<td>%s %g</td></tr>\n", m->rule, m->limit);
    }
    fputs("</table>\n", f);
}

static void put_expectations(FILE *f, const sph_report *r)
{
    if (!r->nexpects)
        return;
    fputs("<h2>Expectations</h2>\n<table id=\"expectations\">\n<tr><th>expectation</th>"
          "<th>value</th><th>expected</th><th>max |error|</th><th>relative error %</th>"
          "<th>tolerance %</th><th>result</th></tr>\n", f);
    for (int k = 0; k < r->nexpects; k++) {
        const sph_report_expect *x = &r->expects[k];
        fputs("<tr><td class=\"text\">", f);
        put_text(f, x->text);
        fputs("</td>", f);
        put_cell(f, x->value, 1);
        put_cell(f, x->expected, 1);
        put_cell(f, x->max_abs_error, 1);
        put_cell(f, x->relative_error, 100);
        put_cell(f, x->tolerance >= 0 ? x->tolerance : NAN, 100);
        fprintf(f, "<td class=\"%s\">%s</td></tr>\n", x->pass ? "pass" : "fail",
                x->pass ? "pass" : "FAIL");
    }
    fputs("</table>\n", f);
}

/* The processes of a run on many: a row each (data-process: its rank; data-NAME: each
 * number in full, named as summary.json's processes). */
static void put_processes(FILE *f, const sph_report *r)
{
    static const char *const keys[4] = {"particles", "halo", "bytes_per_step", "wait_time"};
    if (!r->processes)
        return;
    fputs("<h2>Processes</h2>\n<table id=\"processes\">\n<tr><th>process</th>"
          "<th>particles</th><th>halo particles</th><th>bytes sent per step</th>"
          "<th>waited for the halo (s)</th></tr>\n", f);
    for (int k = 0; k < r->nprocesses; k++) {
        const double *x = r->processes + 4 * (size_t)k;
        fprintf(f, "<tr data-process=\"%d\"", k);
        for (int c = 0; c < 4; c++) {
            fprintf(f, " data-%s=\"", keys[c]);
            put_number(f, x[c]);
            fputc('"', f);
        }
        fprintf(f, "><td>%d</td>", k);
        for (int c = 0; c < 4; c++)
            put_cell(f, x[c], 1);
        fputs("</tr>\n", f);
    }
    fputs("</table>\n", f);
}

static void put_energies(FILE *f, const sph_csv_table *t)
{
    fputs("<h2>Energies</h2>\n", f);
    int *cols = malloc(((size_t)t->ncols + 1) * sizeof *cols), n = 0;
    for (int k = 1; cols && k < t->ncols; k++)
        cols[n++] = k;
    const plot_spec p = {.id = "energies", .file = "energies.csv", .yname = "energy",
                         .width = 760, .height = 380, .plane = -1};
    line_plot(f, &p, t, cols, n);
    free(cols);
}

static void put_time_steps(FILE *f, const sph_csv_table *t)
{
    const int col = 1;
    fputs("<h2>Time step</h2>\n<p class=\"note\">The mean time step of each output interval "
          "(its time over its steps), since this process started the run.</p>\n", f);
    const plot_spec p = {.id = "time-step", .yname = "time step (s)", .width = 560,
                         .height = 260, .plane = -1};
    line_plot(f, &p, t, &col, 1);
}

/* The steps each bound set over the run, and each body's, with their shares of the steps
 * counted: a row each (those that set none left out), named in data-bound or data-body. */
static void put_bound_table(FILE *f, const sph_report *r)
{
    long counted = 0;
    for (int k = 0; k < r->nbounds; k++)
        counted += r->counts[k];
    fputs("<table id=\"time-step-bounds\">\n<tr><th>set by</th><th>steps</th>"
          "<th>share %</th></tr>\n", f);
    for (int k = 0; k < r->nbounds + r->nbodies; k++) {
        if (r->counts[k] <= 0)
            continue;
        fprintf(f, "<tr %s=\"", k < r->nbounds ? "data-bound" : "data-body");
        put_text(f, r->count_names[k]);
        fprintf(f, "\"><td class=\"text\">%s", k < r->nbounds ? "" : "body ");
        put_text(f, r->count_names[k]);
        fprintf(f, "</td><td>%ld</td><td>%.4g</td></tr>\n", r->counts[k],
                100.0 * (double)r->counts[k] / (double)counted);
    }
    fputs("</table>\n", f);
}

/* What bounded the time step, where the host counted steps: the table, and each interval's
 * share of steps by bound (the bounds that set a step at all), when an interval ended. */
static void put_bounds(FILE *f, const sph_report *r)
{
    const sph_csv_table *t = r->dt_bounds;
    long counted = 0;
    for (int k = 0; k < r->nbounds; k++)
        counted += r->counts[k];
    if (counted <= 0)
        return;
    fputs("<h3>What bounded it</h3>\n<p class=\"note\">The steps each bound set (speed: "
          "eq. 65, the sound speed and the particles' speed; acceleration: eq. 66; "
          "compression: eq. 65 under the factor of a compressed body; contact: the stiffest "
          "contact; fixed: the scene's step), and each body's bounds.</p>\n", f);
    put_bound_table(f, r);
    if (!t)
        return;
    int cols[16], n = 0;
    for (int k = 1; k < t->ncols && n < 16; k++) {
        int any = 0;
        for (long row = 0; row < t->nrows && !any; row++)
            any = t->v[(size_t)row * (size_t)t->ncols + (size_t)k] > 0;
        if (any)
            cols[n++] = k;
    }
    const plot_spec p = {.id = "time-step-shares", .yname = "share of steps", .width = 560,
                         .height = 260, .plane = -1, .ylo = 0, .yhi = 1};
    line_plot(f, &p, t, cols, n);
}

/* Measurement plane q's plots, its displacements' and its forces', with the expectations
 * on them. */
static void put_plane(FILE *f, const sph_report *r, int q)
{
    const char *name = r->plane_names[q];
    const sph_csv_table *t = &r->planes[q];
    const int dim = r->dim;
    char file[300];
    snprintf(file, sizeof file, "measure_%s.csv", name);
    fputs("<h3>", f);
    put_text(f, name);
    fputs("</h3>\n<div class=\"planes\">\n", f);
    for (int what = 0; what < 2; what++) { /* displacements, then forces */
        int cols[3], n = 0;
        for (int k = 1; k < t->ncols; k++) {
            const char *c = t->names[k];
            if (n < 3 && c[0] == (what ? 'f' : 'u') && !(dim == 2 && c[1] == 'y'))
                cols[n++] = k;
        }
        const plot_spec p = {.file = file, .yname = what ? "force" : "displacement (m)",
                             .width = 420, .height = 240, .curves = r->curves,
                             .ncurves = r->ncurves, .plane = q};
        line_plot(f, &p, t, cols, n);
    }
    fputs("</div>\n", f);
}

int sph_report_write(const char *path, const sph_report *r)
{
    FILE *f = sph_open_whole(path);
    if (!f) {
        sph_error("cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    fputs("<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n"
          "<head>\n<meta charset=\"utf-8\"/>\n<title>", f);
    put_text(f, r->model);
    fprintf(f, " — run report</title>\n<style>%s</style>\n</head>\n<body>\n<h1>", STYLE);
    put_text(f, r->model);
    fputs("</h1>\n", f);
    put_verdict(f, r);
    put_expectations(f, r);
    put_margins(f, r);
    put_processes(f, r);
    if (r->energies)
        put_energies(f, r->energies);
    if (r->time_steps)
        put_time_steps(f, r->time_steps);
    if (r->counts && r->nbounds)
        put_bounds(f, r);
    if (r->nplanes)
        fputs("<h2>Measurement planes</h2>\n", f);
    for (int q = 0; q < r->nplanes; q++)
        put_plane(f, r, q);
    fputs("<p class=\"note\">The numbers in full: summary.json and the CSV files beside "
          "this page.</p>\n</body>\n</html>\n", f);
    const int err = sph_close_whole(f, path);
    if (err)
        sph_error("cannot write %s: %s", path, strerror(err));
    return err ? -1 : 0;
}
