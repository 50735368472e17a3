/* team.c — the number of threads of a run's steps, from the share of its threads' time the
 * machine gives it and from timed trials (team.h). */

#include <string.h>

#include "team.h"

void sph_team_init(sph_team *t, int max, int fixed)
{
    memset(t, 0, sizeof *t);
    t->max = max < 1 ? 1 : max;
    t->fixed = fixed;
    t->now = t->max;
    t->wait = SPH_TEAM_WAIT;
    t->next_trial = -1e300; /* a busy machine from the start: try at once */
}

int sph_team_threads(const sph_team *t)
{
    if (t->trial && t->window % 2 == 0) /* windows 0, 2, ...: the trial count */
        return t->trial;
    return t->now;
}

long sph_team_batch(const sph_team *t)
{
    if (!t->trial || !(t->per_step > 0))
        return 1L << 40;
    const double steps = SPH_TEAM_WINDOW / t->per_step;
    return steps < 1 ? 1 : steps > 1e9 ? 1000000000L : (long)steps;
}

static void start_trial(sph_team *t, int count)
{
    t->trial = count;
    t->window = 0;
    t->trial_seconds[0] = t->trial_seconds[1] = 0;
    t->trial_steps[0] = t->trial_steps[1] = 0;
}

/* The trial's windows are all timed: keep the faster count per step, by SPH_TEAM_GAIN. */
static void end_trial(sph_team *t, double clock)
{
    const double on_now = t->trial_seconds[0] / (double)t->trial_steps[0];
    const double on_trial = t->trial_seconds[1] / (double)t->trial_steps[1];
    t->trials++;
    if (on_trial < (1 - SPH_TEAM_GAIN) * on_now) {
        t->now = t->trial;
        t->changes++;
        t->wait = SPH_TEAM_WAIT;
    }
    t->next_trial = clock + t->wait;
    t->wait = 2 * t->wait < SPH_TEAM_WAIT_MAX ? 2 * t->wait : SPH_TEAM_WAIT_MAX;
    t->trial = 0;
}

void sph_team_after(sph_team *t, long steps, double wall, double cpu, double idle,
                    double clock)
{
    const int count = sph_team_threads(t);
    t->step_seconds += wall;
    t->thread_seconds += wall * count;
    if (t->fixed || t->max <= 1 || steps <= 0)
        return;
    t->win_wall += wall, t->win_cpu += cpu, t->win_steps += steps;
    t->win_idle = idle < 0 || t->win_idle < 0 ? -1 : t->win_idle + idle;
    if (t->win_wall < SPH_TEAM_WINDOW)
        return;
    const double share = t->win_cpu / (t->win_wall * count);
    const int room = t->win_idle < 0 || t->win_idle >= 0.5 * t->win_wall; /* (or unknown) */
    if (t->trial) {
        const int k = t->window % 2 == 0; /* [1]: the trial count's window */
        t->trial_seconds[k] += t->win_wall;
        t->trial_steps[k] += t->win_steps;
    }
    if (!t->trial)
        t->per_step = t->win_wall / (double)t->win_steps;
    t->win_wall = t->win_cpu = t->win_idle = 0, t->win_steps = 0;
    if (t->trial) {
        if (++t->window == SPH_TEAM_WINDOWS)
            end_trial(t, clock);
        return;
    }
    if (clock < t->next_trial)
        return;
    if (t->now > 1 && share < SPH_TEAM_BUSY)
        start_trial(t, t->now / 2);
    else if (t->now < t->max && (room || clock >= t->next_trial + SPH_TEAM_WAIT_MAX))
        start_trial(t, 2 * t->now < t->max ? 2 * t->now : t->max);
}
