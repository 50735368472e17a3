/* profile.c — where the time of a run goes, for `--profile`.
 *
 * The CPU target's step wraps every pass it calls in SPH_PASS (sphrt.h), which adds the
 * pass's wall time here; the CUDA target times its kernels on the device instead (events
 * between launches, runtime/sph_cuda.h) and adds them here by the name of the pass that
 * launched them.  The set-up's stages are timed the same way (SPH_TIMED, setup.c).  Each
 * entry belongs to the phase it ran in (sph_profile_phase: the set-up, the steps, or the
 * stability checks and outputs between them).  sph_main prints the table at the end of the
 * run and writes it to summary.json.  With profiling off a pass costs one test of
 * sph_profile_on. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output.h"
#include "sphrt.h"

#define PROFILE_MAX 128 /* distinct entries: a few per body, a few for the scene */

int sph_profile_on;
int sph_profile_phase = SPH_PHASE_SETUP; /* sph_main sets the phases as the run goes */

static const char *const phase_name[] = {
    [SPH_PHASE_STEPS] = "steps", [SPH_PHASE_CHECKS] = "checks", [SPH_PHASE_SETUP] = "set-up"};

static struct {
    const char *name;
    int phase;
    double seconds;
    long calls;
} entry[PROFILE_MAX];
static int nentries;

int sph_profile_slot(const char *pass)
{
    for (int k = 0; k < nentries; k++) /* the pass's own name first: no string compared */
        if (entry[k].phase == sph_profile_phase && entry[k].name == pass)
            return k;
    for (int k = 0; k < nentries; k++)
        if (entry[k].phase == sph_profile_phase && strcmp(entry[k].name, pass) == 0)
            return k;
    if (nentries == PROFILE_MAX)
        return PROFILE_MAX - 1; /* (never, with the passes sphc generates) */
    entry[nentries].name = pass;
    entry[nentries].phase = sph_profile_phase;
    return nentries++;
}

double sph_profile_start(int *slot, const char *pass)
{
    if (*slot < 0 || entry[*slot].phase != sph_profile_phase)
        *slot = sph_profile_slot(pass);
    return sph_wall_time();
}

void sph_profile_add(int slot, double seconds)
{
    entry[slot].seconds += seconds;
    entry[slot].calls++;
}

/* The entries by time, longest first (insertion sort: a few dozen entries). */
static int by_time(int *order)
{
    for (int k = 0; k < nentries; k++) {
        int q = k;
        while (q > 0 && entry[order[q - 1]].seconds < entry[k].seconds) {
            order[q] = order[q - 1];
            q--;
        }
        order[q] = k;
    }
    return nentries;
}

void sph_profile_json(sph_json *j)
{
    int order[PROFILE_MAX];
    const int n = by_time(order);
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
static void print_rows(FILE *f, const int *order, int n, int phase, double scale,
                       const char *unit, double total)
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
    int order[PROFILE_MAX];
    const int n = by_time(order);
    const double per = steps > 0 ? 1e3 / (double)steps : 0; /* s -> ms per step */
    double passes = 0, stages = 0;
    for (int k = 0; k < n; k++) {
        passes += entry[k].phase == SPH_PHASE_STEPS ? entry[k].seconds : 0;
        stages += entry[k].phase == SPH_PHASE_SETUP ? entry[k].seconds : 0;
    }
    fprintf(f, "%s: set-up %.3f s:\n", model, t->setup);
    print_rows(f, order, n, SPH_PHASE_SETUP, 1, "s ", t->setup);
    fprintf(f, "  %-44s %11.4f s  %6.1f %%\n", "(the rest: start, copies, other)",
            t->setup - stages, t->setup > 0 ? 100 * (t->setup - stages) / t->setup : 0.0);
    fprintf(f, "%s: %ld steps, %.3f s (per step; share of the steps' time):\n", model, steps,
            t->steps);
    print_rows(f, order, n, SPH_PHASE_STEPS, per, "ms", t->steps);
    fprintf(f, "  %-44s %11.4f ms %6.1f %%\n", "(the rest: time step, loop, waits)",
            (t->steps - passes) * per, t->steps > 0 ? 100 * (t->steps - passes) / t->steps : 0.0);
    fprintf(f, "%s: between the steps, per step: stability checks %.4f ms, outputs %.4f ms\n",
            model, t->checks * per, t->outputs * per);
    print_rows(f, order, n, SPH_PHASE_CHECKS, per, "ms", t->checks + t->outputs);
}
