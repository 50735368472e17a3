/* run_report.c — the run's report page, summary.html (io/report.c), beside summary.json and
 * written with it: how the run stands, its expectations, and its CSV files read back from
 * the output folder (all their rows, those of the run before a checkpoint it resumed from
 * included). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run_state.h"
#include "io/report.h"

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

int sph_run_report(const run_state *r, const char *status, const char *message, double wall,
                   const sph_report_expect *expects, int nexpects)
{
    const sph_model *m = r->m;
    sph_csv_table energies;
    char *path = joinf("%s/energies.csv%s", r->opt.out_dir, "");
    const int have_energies = !sph_csv_read(path, &energies, SPH_REPORT_POINTS);
    free(path);
    sph_csv_table *planes = calloc((size_t)r->nmeasures + 1, sizeof *planes);
    const char **names = calloc((size_t)r->nmeasures + 1, sizeof *names);
    int np = 0;
    for (int i = 0; planes && names && i < m->nbodies; i++)
        for (int k = 0; k < m->bodies[i].nmeasures; k++) {
            path = joinf("%s/measure_%s.csv", r->opt.out_dir, m->bodies[i].measures[k].name);
            if (!sph_csv_read(path, &planes[np], SPH_REPORT_POINTS))
                names[np++] = m->bodies[i].measures[k].name;
            free(path);
        }
    static const char *const bound_names[SPH_DT_NBOUNDS] = SPH_DT_BOUND_NAMES;
    const int nb = r->sim.nbodies;
    const char **count_names = calloc(SPH_DT_NBOUNDS + (size_t)nb, sizeof *count_names);
    long *counts = calloc(SPH_DT_NBOUNDS + (size_t)nb, sizeof *counts);
    for (int k = 0; count_names && counts && k < SPH_DT_NBOUNDS + nb; k++) {
        count_names[k] = k < SPH_DT_NBOUNDS ? bound_names[k]
                                            : r->sim.bodies[k - SPH_DT_NBOUNDS].desc->name;
        counts[k] = k < SPH_DT_NBOUNDS ? r->sim.dt_bound_steps[k]
                    : r->sim.dt_body_steps ? r->sim.dt_body_steps[k - SPH_DT_NBOUNDS] : 0;
    }
    const int have_bounds = r->dt_bounds.nrows > 0 && count_names && counts;
    sph_report_margin margins[3];
    const int nmargins = monitor_margins(&r->mon, margins);
    const sph_report page = {
        .model = m->name, .status = status, .message = message,
        .time = r->sim.t, .end_time = r->t_end, .wall_time = wall, .steps = r->sim.step,
        .expects = expects, .nexpects = nexpects,
        .energies = have_energies ? &energies : NULL,
        .time_steps = r->time_steps.nrows ? &r->time_steps : NULL,
        .dt_bounds = have_bounds ? &r->dt_bounds : NULL,
        .margins = margins, .nmargins = nmargins,
        .count_names = count_names, .counts = counts, .nbounds = SPH_DT_NBOUNDS, .nbodies = nb,
        .planes = planes, .plane_names = names, .nplanes = np, .dim = m->dim,
    };
    path = joinf("%s/summary.html%s", r->opt.out_dir, "");
    const int bad = sph_report_write(path, &page);
    free(path);
    if (have_energies)
        sph_csv_table_free(&energies);
    for (int q = 0; q < np; q++)
        sph_csv_table_free(&planes[q]);
    free(planes);
    free(names);
    free(count_names);
    free(counts);
    return bad;
}
