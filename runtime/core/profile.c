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
#include <string.h>

#include "clock.h"
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

const sph_profile_entry *sph_profile_entries(int *n)
{
    *n = nentries;
    return entry;
}
