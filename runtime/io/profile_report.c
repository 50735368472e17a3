/* profile_report.c — the profile of a run (core/profile.h's entries) in summary.json and as
 * the table sph_main prints at the end of a run with --profile (profile_report.h). */
#include <stdio.h>

#include "json.h"
#include "profile_report.h"
#include "core/profile.h"

static const char *const phase_name[] = {
    [SPH_PHASE_STEPS] = "steps", [SPH_PHASE_CHECKS] = "checks", [SPH_PHASE_SETUP] = "set-up"};

/* The entries by time, longest first (insertion sort: a few dozen entries). */
static void by_time(const sph_profile_entry *entry, int nentries, int *order)
{
    for (int k = 0; k < nentries; k++) {
        int q = k;
        while (q > 0 && entry[order[q - 1]].seconds < entry[k].seconds) {
            order[q] = order[q - 1];
            q--;
        }
        order[q] = k;
    }
}

void sph_profile_json(sph_json *j)
{
    int order[SPH_PROFILE_MAX], n;
    const sph_profile_entry *entry = sph_profile_entries(&n);
    by_time(entry, n, order);
    sph_json_key_array(j, "profile");
    for (int q = 0; q < n; q++) {
        sph_json_key_object(j, NULL);
        sph_json_str(j, "pass", entry[order[q]].name);
        sph_json_str(j, "phase", phase_name[entry[order[q]].phase]);
        sph_json_num(j, "seconds", entry[order[q]].seconds);
        sph_json_int(j, "calls", entry[order[q]].calls);
        sph_json_end_object(j);
    }
    sph_json_end_array(j);
}

/* The rows of one phase: `scale` times the seconds in `unit`, and the share of `total`. */
static void print_rows(FILE *f, const sph_profile_entry *entry, const int *order, int n,
                       int phase, double scale, const char *unit, double total)
{
    for (int q = 0; q < n; q++) {
        const int k = order[q];
        if (entry[k].phase != phase)
            continue;
        fprintf(f, "  %-44s %11.4f %s %6.1f %%  (%ld calls)\n", entry[k].name,
                entry[k].seconds * scale, unit,
                total > 0 ? 100 * entry[k].seconds / total : 0.0, entry[k].calls);
    }
}

void sph_profile_print(FILE *f, const char *model, long steps, const sph_profile_times *t)
{
    int order[SPH_PROFILE_MAX], n;
    const sph_profile_entry *entry = sph_profile_entries(&n);
    by_time(entry, n, order);
    const double per = steps > 0 ? 1e3 / (double)steps : 0; /* s -> ms per step */
    double passes = 0, stages = 0;
    for (int k = 0; k < n; k++) {
        passes += entry[k].phase == SPH_PHASE_STEPS ? entry[k].seconds : 0;
        stages += entry[k].phase == SPH_PHASE_SETUP ? entry[k].seconds : 0;
    }
    fprintf(f, "%s: set-up %.3f s:\n", model, t->setup);
    print_rows(f, entry, order, n, SPH_PHASE_SETUP, 1, "s ", t->setup);
    fprintf(f, "  %-44s %11.4f s  %6.1f %%\n", "(the rest: start, copies, other)",
            t->setup - stages, t->setup > 0 ? 100 * (t->setup - stages) / t->setup : 0.0);
    fprintf(f, "%s: %ld steps, %.3f s (per step; share of the steps' time):\n", model, steps,
            t->steps);
    print_rows(f, entry, order, n, SPH_PHASE_STEPS, per, "ms", t->steps);
    fprintf(f, "  %-44s %11.4f ms %6.1f %%\n", "(the rest: time step, loop, waits)",
            (t->steps - passes) * per, t->steps > 0 ? 100 * (t->steps - passes) / t->steps : 0.0);
    fprintf(f, "%s: between the steps, per step: stability checks %.4f ms, outputs %.4f ms\n",
            model, t->checks * per, t->outputs * per);
    print_rows(f, entry, order, n, SPH_PHASE_CHECKS, per, "ms", t->checks + t->outputs);
}
