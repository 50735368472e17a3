/* progress.c — the progress line on the terminal and the wall clock.
 *
 * p->enabled is 0 when no line is shown (quiet, or stderr is not a terminal), 1 when
 * lines may be shown, and 2 once one has been printed (so finish ends it with a newline). */
#include "output.h"

#include <math.h>
#include <stdio.h>
#include <time.h>
#include <unistd.h>

#define PROGRESS_INTERVAL 0.25 /* seconds between updates: 4 Hz */
#define PROGRESS_WIDTH 78      /* a line is padded to this width to cover the previous one */

double sph_wall_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void sph_progress_start(sph_progress *p, double t_end, int quiet)
{
    p->enabled = !quiet && isatty(fileno(stderr));
    p->t_end = t_end;
    p->wall_start = p->wall_last = sph_wall_time();
    p->step_last = 0;
}

/* "h:mm:ss", or "-:--:--" when unknown. */
static void format_duration(char *buf, size_t size, double s)
{
    if (!isfinite(s) || s < 0 || s > 1e8) {
        snprintf(buf, size, "-:--:--");
        return;
    }
    long total = lround(s);
    snprintf(buf, size, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
}

void sph_progress_update(sph_progress *p, double t, double dt, long step)
{
    if (!p->enabled)
        return;
    double now = sph_wall_time();
    if (now - p->wall_last < PROGRESS_INTERVAL)
        return;
    double frac = p->t_end > 0 ? fmin(fmax(t / p->t_end, 0.0), 1.0) : 0;
    double rate = (double)(step - p->step_last) / (now - p->wall_last);
    double eta = frac > 0 ? (now - p->wall_start) * (1 - frac) / frac : -1;
    char eta_text[32], line[160];
    format_duration(eta_text, sizeof eta_text, eta);
    snprintf(line, sizeof line, "[%5.1f%%] t = %.4g s  dt = %.2g s  %.0f steps/s  ETA %s",
             100 * frac, t, dt, rate, eta_text);
    fprintf(stderr, "\r%-*s", PROGRESS_WIDTH, line);
    fflush(stderr);
    p->wall_last = now;
    p->step_last = step;
    p->enabled = 2;
}

void sph_progress_finish(sph_progress *p)
{
    if (p->enabled == 2) {
        fputc('\n', stderr);
        fflush(stderr);
    }
    p->enabled = 0;
}
