/* profile.c — where the time of a run goes, for `--profile`.
 *
 * The CPU target's step wraps every pass it calls in SPH_PASS (profile.h), which adds the
 * pass's wall time here; the CUDA target times its kernels on the device instead (events
 * between launches, cuda/launch.h) and adds them here by the name of the pass that
 * launched them.  The set-up's stages are timed the same way (SPH_TIMED, run/setup.c).
 * Each entry belongs to the phase it ran in (sph_profile_phase: the set-up, the steps, or the
 * stability checks and outputs between them).  sph_main prints the table at the end of the
 * run and writes it to summary.json (io/profile_report.c).  With profiling off a pass costs
 * one test of sph_profile_on. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "profile.h"

int sph_profile_on;
int sph_profile_phase = SPH_PHASE_SETUP; /* sph_main sets the phases as the run goes */

static sph_profile_entry entry[SPH_PROFILE_MAX];
static int nentries;

int sph_profile_slot(const char *pass)
{
    for (int k = 0; k < nentries; k++) /* the pass's own name first: no string compared */
        if (entry[k].phase == sph_profile_phase && entry[k].name == pass)
            return k;
    for (int k = 0; k < nentries; k++)
        if (entry[k].phase == sph_profile_phase && strcmp(entry[k].name, pass) == 0)
            return k;
    if (nentries == SPH_PROFILE_MAX)
        return SPH_PROFILE_MAX - 1; /* (never, with the passes sphc generates) */
    entry[nentries].name = pass;
    entry[nentries].phase = sph_profile_phase;
    return nentries++;
}

int sph_profile_body_slot(const char *body, const char *pass)
{
    static const char *of_body[SPH_PROFILE_MAX], *of_pass[SPH_PROFILE_MAX];
    for (int k = 0; k < nentries; k++) /* the same strings as before: no string compared */
        if (entry[k].phase == sph_profile_phase && of_body[k] == body && of_pass[k] == pass)
            return k;
    char *want = malloc(strlen(body) + strlen(pass) + 2); /* "BODY_PASS" */
    if (!want)
        return sph_profile_slot(pass); /* (out of memory: under the pass's name alone) */
    sprintf(want, "%s_%s", body, pass);
    const int k = sph_profile_slot(want);
    if (entry[k].name != want) /* an entry of that name already: it keeps its own */
        free(want);
    of_body[k] = body, of_pass[k] = pass;
    return k;
}

int sph_profile_slot_at(int *at, const char *pass)
{
    if (*at < 0 || entry[*at].phase != sph_profile_phase)
        *at = sph_profile_slot(pass);
    return *at;
}

void sph_profile_add(int slot, double seconds)
{
    entry[slot].seconds += seconds;
    entry[slot].calls++;
}

const sph_profile_entry *sph_profile_entries(int *n)
{
    *n = nentries;
    return entry;
}
