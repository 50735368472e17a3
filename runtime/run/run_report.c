/* run_report.c — the run's report page, summary.html (io/report.c), beside summary.json and
 * written with it: how the run stands, its expectations, and its CSV files read back from
 * the output folder (all their rows, those of the run before a checkpoint it resumed from
 * included), with the expectations drawn over the measurement planes' plots. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run_state.h"
#include "io/report.h"

#define SPH_REPORT_PI 3.14159265358979323846

/* The stability monitor's margins (monitor.h), NAN where no check looked yet. */
static int monitor_margins(const sph_monitor *mon, sph_report_margin m[3])
{
    m[0] = (sph_report_margin){"J", "det F, the smallest", mon->scans ? mon->j_min : NAN, 0,
                               "above"};
    m[1] = (sph_report_margin){"speed", "speed over c0, the largest",
                               mon->scans ? mon->speed : NAN, SPH_MONITOR_SPEED, "at most"};
    m[2] = (sph_report_margin){"energy_growth", "total energy over the largest before it, "
                               "the largest ratio", mon->sums ? mon->growth : NAN,
                               SPH_MONITOR_GROWTH, "at most"};
    return 3;
}

/* The measurement planes' CSV files read back: planes[] and names[] of those that could be
 * (*np), and plane_of[q], measure q's place among them (-1: none). */
typedef struct {
    sph_csv_table *tables;
    const char **names;
    int *plane_of;
    int n;
} plane_files;

static void read_planes(const run_state *r, plane_files *p)
{
    const sph_model *m = r->m;
    const size_t n = (size_t)r->nmeasures + 1;
    p->tables = calloc(n, sizeof *p->tables);
    p->names = calloc(n, sizeof *p->names);
    p->plane_of = calloc(n, sizeof *p->plane_of);
    p->n = 0;
    for (int i = 0, q = 0; p->tables && p->names && p->plane_of && i < m->nbodies; i++)
        for (int k = 0; k < m->bodies[i].nmeasures; k++, q++) {
            char *path = joinf("%s/measure_%s.csv", r->opt.out_dir,
                               m->bodies[i].measures[k].name);
            p->plane_of[q] = -1;
            if (!sph_csv_read(path, &p->tables[p->n], SPH_REPORT_POINTS)) {
                p->plane_of[q] = p->n;
                p->names[p->n++] = m->bodies[i].measures[k].name;
            }
            free(path);
        }
}

static void free_planes(plane_files *p)
{
    for (int q = 0; q < p->n; q++)
        sph_csv_table_free(&p->tables[q]);
    free(p->tables), free(p->names), free(p->plane_of);
}

/* Curve c's values at the times of table t (column 0): a reference's; a period's sinusoid;
 * an amplitude's line, mid + amplitude.  0, or -1 out of memory. */
static int curve_values(sph_report_curve *c, const sph_csv_table *t,
                        double (*reference)(double))
{
    c->y = malloc(((size_t)t->nrows + 1) * sizeof *c->y);
    if (!c->y)
        return -1;
    for (long row = 0; row < t->nrows; row++) {
        const double time = t->v[(size_t)row * (size_t)t->ncols];
        const double phase = 2 * SPH_REPORT_PI * (time - c->t0) / c->period;
        c->y[row] = reference ? reference(time)
                    : c->period > 0 ? c->mid + c->amplitude * sin(phase)
                                    : c->mid + c->amplitude;
    }
    return 0;
}

/* The curves of expectation x on its plane (table t, plane index q, its series s) into c:
 * how many (a reference or period one, an amplitude two, a period whose quantity never
 * crossed its mid-line none). */
static int expect_curves(const sph_expect_desc *x, const sph_series *s,
                         const sph_csv_table *t, int q, sph_report_curve c[2])
{
    static const char *const kinds[] = {"period", "amplitude", "energy", "reference"};
    double mid, half, t0;
    const int rising = sph_expect_phase(s, x->quantity, &mid, &half, &t0);
    const sph_report_curve base = {kinds[x->kind], x->text, q, 1 + x->quantity, NULL,
                                   0, mid, 0, t0};
    int n = 0;
    if (x->kind == SPH_EXPECT_REFERENCE) {
        c[0] = base;
        n = curve_values(&c[0], t, x->reference) ? 0 : 1;
    } else if (x->kind == SPH_EXPECT_PERIOD && rising) {
        c[0] = base, c[0].period = x->value, c[0].amplitude = rising * half;
        n = curve_values(&c[0], t, NULL) ? 0 : 1;
    } else if (x->kind == SPH_EXPECT_AMPLITUDE) {
        for (int k = 0; k < 2; k++) {
            c[n] = base, c[n].amplitude = k ? -x->value : x->value;
            n += !curve_values(&c[n], t, NULL);
        }
    }
    return n;
}

/* The expectations drawn over the planes (malloc'd, *n of them). */
static sph_report_curve *report_curves(const run_state *r, const plane_files *p, int *n)
{
    const sph_model *m = r->m;
    sph_report_curve *c = calloc(2 * (size_t)m->nexpects + 1, sizeof *c);
    *n = 0;
    for (int k = 0; c && p->plane_of && k < m->nexpects; k++) {
        const sph_expect_desc *x = &m->expects[k];
        if (x->kind == SPH_EXPECT_ENERGY)
            continue;
        const int g = r->rec.measure_base[x->body] + x->measure, q = p->plane_of[g];
        if (q >= 0)
            *n += expect_curves(x, &r->rec.measures[g], &p->tables[q], q, c + *n);
    }
    return c;
}

/* The steps each bound and each body's bounds set (sph_report's counts; malloc'd, names in
 * *names), NULL out of memory. */
static long *bound_counts(const sph_sim *s, const char ***names)
{
    static const char *const bound_names[SPH_DT_NBOUNDS] = SPH_DT_BOUND_NAMES;
    const size_t n = SPH_DT_NBOUNDS + (size_t)s->nbodies;
    *names = calloc(n, sizeof **names);
    long *counts = calloc(n, sizeof *counts);
    if (!*names || !counts) {
        free(*names), free(counts);
        *names = NULL;
        return NULL;
    }
    for (int k = 0; k < (int)n; k++) {
        const int body = k - SPH_DT_NBOUNDS;
        (*names)[k] = body < 0 ? bound_names[k] : s->bodies[body].desc->name;
        counts[k] = body < 0 ? s->dt_bound_steps[k]
                    : s->dt_body_steps ? s->dt_body_steps[body] : 0;
    }
    return counts;
}

int sph_run_report(const run_state *r, const sph_run_outcome *o)
{
    const sph_model *m = r->m;
    sph_csv_table energies;
    char *path = joinf("%s/energies.csv%s", r->opt.out_dir, "");
    const int have_energies = !sph_csv_read(path, &energies, SPH_REPORT_POINTS);
    free(path);
    plane_files planes;
    read_planes(r, &planes);
    int ncurves;
    sph_report_curve *curves = report_curves(r, &planes, &ncurves);
    const char **count_names;
    long *counts = bound_counts(&r->sim, &count_names);
    sph_report_margin margins[3];
    const int nmargins = monitor_margins(&r->mon, margins);
    const sph_report page = {
        .model = m->name, .status = o->status, .message = o->message,
        .time = r->sim.t, .end_time = r->t_end, .wall_time = o->wall, .steps = r->sim.step,
        .expects = o->expects, .nexpects = o->nexpects,
        .processes = o->processes, .nprocesses = o->nprocesses,
        .energies = have_energies ? &energies : NULL,
        .time_steps = r->time_steps.nrows ? &r->time_steps : NULL,
        .dt_bounds = r->dt_bounds.nrows ? &r->dt_bounds : NULL,
        .count_names = count_names, .counts = counts,
        .nbounds = counts ? SPH_DT_NBOUNDS : 0, .nbodies = counts ? r->sim.nbodies : 0,
        .margins = margins, .nmargins = nmargins,
        .planes = planes.tables, .plane_names = planes.names, .nplanes = planes.n,
        .curves = curves, .ncurves = curves ? ncurves : 0, .dim = m->dim,
    };
    path = joinf("%s/summary.html%s", r->opt.out_dir, "");
    const int bad = sph_report_write(path, &page);
    free(path);
    if (have_energies)
        sph_csv_table_free(&energies);
    free_planes(&planes);
    for (int k = 0; curves && k < ncurves; k++)
        free(curves[k].y);
    free(curves), free(count_names), free(counts);
    return bad;
}
