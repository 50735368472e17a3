/* profile.c — the time each pass of the step takes, for `--profile`.
 *
 * The CPU target's step wraps every pass it calls in SPH_PASS (sphrt.h), which adds the
 * pass's wall time here; the CUDA target times its kernels on the device instead (events
 * between launches, runtime/sph_cuda.h) and adds them here by the name of the pass that
 * launched them.  sph_main prints the table at the end of the run and writes it to
 * summary.json.  With profiling off a pass costs one test of sph_profile_on. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output.h"
#include "sphrt.h"

#define PROFILE_MAX 128 /* distinct passes: a few per body, a few for the scene */

int sph_profile_on;
int sph_profile_outside = 1; /* sph_main clears it while the steps run */

static struct {
    const char *name;
    int outside; /* run outside the steps (the monitor's pass on a device, set-up) */
    double seconds;
    long calls;
} entry[PROFILE_MAX];
static int nentries;

int sph_profile_slot(const char *pass)
{
    for (int k = 0; k < nentries; k++)
        if (entry[k].outside == sph_profile_outside &&
            (entry[k].name == pass || strcmp(entry[k].name, pass) == 0))
            return k;
    if (nentries == PROFILE_MAX)
        return PROFILE_MAX - 1; /* (never, with the passes sphc generates) */
    entry[nentries].name = pass;
    entry[nentries].outside = sph_profile_outside;
    return nentries++;
}

double sph_profile_start(int *slot, const char *pass)
{
    if (*slot < 0)
        *slot = sph_profile_slot(pass);
    return sph_wall_time();
}

void sph_profile_add(int slot, double seconds)
{
    entry[slot].seconds += seconds;
    entry[slot].calls++;
}

/* The passes by time, longest first (insertion sort: a few dozen entries). */
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
        sph_json_num(j, "seconds", entry[order[q]].seconds);
        sph_json_int(j, "calls", entry[order[q]].calls);
        sph_json_bool(j, "in_steps", !entry[order[q]].outside);
        sph_json_end_object(j);
    }
    sph_json_end_array(j);
}

static void print_rows(FILE *f, const int *order, int n, int outside, double per, double total)
{
    for (int q = 0; q < n; q++) {
        const int k = order[q];
        if (entry[k].outside != outside)
            continue;
        fprintf(f, "  %-44s %11.4f ms %6.1f %%  (%ld calls)\n", entry[k].name,
                entry[k].seconds * per, total > 0 ? 100 * entry[k].seconds / total : 0.0,
                entry[k].calls);
    }
}

void sph_profile_print(FILE *f, const char *model, long steps, double step_seconds,
                       double check_seconds, double output_seconds)
{
    int order[PROFILE_MAX];
    const int n = by_time(order);
    const double per = steps > 0 ? 1e3 / (double)steps : 0; /* s -> ms per step */
    double passes = 0;
    for (int k = 0; k < n; k++)
        passes += entry[k].outside ? 0 : entry[k].seconds;
    fprintf(f, "%s: profile of %ld steps (per step; share of the steps' time):\n", model, steps);
    print_rows(f, order, n, 0, per, step_seconds);
    fprintf(f, "  %-44s %11.4f ms %6.1f %%\n", "(the rest: time step, loop, waits)",
            (step_seconds - passes) * per,
            step_seconds > 0 ? 100 * (step_seconds - passes) / step_seconds : 0.0);
    fprintf(f, "%s: outside the steps, per step: stability checks %.4f ms, outputs %.4f ms\n",
            model, check_seconds * per, output_seconds * per);
    print_rows(f, order, n, 1, per, check_seconds + output_seconds);
}
