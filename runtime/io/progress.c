/* progress.c — the progress line of a run (progress.h).
 *
 * Two kinds of line: on a terminal (stderr is one, not quiet) one line rewritten in place
 * four times a second, as wide as the terminal allows; in a log (stdout is not a terminal: a
 * batch job's output file) a line of its own every p->log_every seconds, at most 80 columns,
 * with the wall time so far, so that a log shows how far the run got while it goes.  A line
 * too wide leaves out its least useful parts (dt, the wall time, the step rate) before it is
 * cut.
 *
 * p->enabled is 0 when no terminal line is shown, 1 when lines may be shown, and 2 once one
 * has been printed (so finish ends it with a newline). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include "progress.h"
#include "core/clock.h"

#define PROGRESS_INTERVAL 0.25 /* seconds between updates on a terminal: 4 Hz */
#define LOG_WIDTH 80           /* a log's lines, and a terminal's of unknown width */

void sph_progress_start(sph_progress *p, double t_end, int quiet, double log_every)
{
    p->enabled = !quiet && isatty(fileno(stderr));
    p->t_end = t_end;
    p->wall_start = p->wall_last = p->log_last = sph_wall_time();
    p->step_last = p->log_step = -1; /* (the first update's step) */
    p->log_every = !quiet && log_every > 0 && !isatty(fileno(stdout)) ? log_every : 0;
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

/* The columns of the terminal on stderr, less one (a line that reaches the last column
 * wraps on some terminals, and \r then goes back to the wrong line); 80 when unknown. */
static int terminal_width(void)
{
    struct winsize ws;
    if (ioctl(fileno(stderr), TIOCGWINSZ, &ws) == 0 && ws.ws_col > 1)
        return ws.ws_col - 1 < 159 ? ws.ws_col - 1 : 159;
    return LOG_WIDTH - 1;
}

enum { F_PREFIX, F_PERCENT, F_TIME, F_DT, F_RATE, F_ETA, F_WALL, NFIELDS };
/* The order in which fields are left out of a line too wide (the first, first). */
static const int DROP[] = {F_DT, F_WALL, F_RATE, F_TIME};

/* The fields ("": none) joined by two spaces (one after the prefix), without those that do
 * not fit in width columns (in the order of DROP), cut at width when even that is too wide. */
static void join_fields(char *out, size_t size, char field[NFIELDS][48], int width)
{
    int left_out = 0;
    for (;;) {
        size_t len = 0;
        out[0] = '\0';
        for (int k = 0; k < NFIELDS; k++) {
            int dropped = 0;
            for (int d = 0; d < left_out; d++)
                dropped |= DROP[d] == k;
            if (dropped || !field[k][0])
                continue;
            len += (size_t)snprintf(out + len, len < size ? size - len : 0, "%s%s",
                                    !len ? "" : k == F_PERCENT ? " " : "  ", field[k]);
        }
        if ((int)len <= width || left_out == (int)(sizeof DROP / sizeof *DROP))
            break;
        left_out++;
    }
    if ((int)strlen(out) > width && width >= 0 && (size_t)width < size)
        out[width] = '\0';
}

/* The line's fields; steps and seconds are those since the previous line, for the rate. */
static void fill_fields(char field[NFIELDS][48], const sph_progress *p, double t, double dt,
                        long steps, double seconds, double now)
{
    const double frac = p->t_end > 0 ? fmin(fmax(t / p->t_end, 0.0), 1.0) : 0;
    const double eta = frac > 0 ? (now - p->wall_start) * (1 - frac) / frac : -1;
    char eta_text[32], wall_text[32];
    format_duration(eta_text, sizeof eta_text, eta);
    format_duration(wall_text, sizeof wall_text, now - p->wall_start);
    memset(field, 0, NFIELDS * sizeof *field);
    snprintf(field[F_PERCENT], 48, "[%5.1f%%]", 100 * frac);
    snprintf(field[F_TIME], 48, "t = %.4g s", t);
    snprintf(field[F_DT], 48, "dt = %.2g s", dt);
    snprintf(field[F_RATE], 48, "%.0f steps/s", seconds > 0 ? (double)steps / seconds : 0.0);
    snprintf(field[F_WALL], 48, "(%s)", wall_text);
    snprintf(field[F_ETA], 48, "ETA %s", eta_text);
}

void sph_progress_update(sph_progress *p, const char *name, double t, double dt, long step)
{
    if (!p->enabled && !(p->log_every > 0))
        return;
    const double now = sph_wall_time();
    if (p->step_last < 0)
        p->step_last = p->log_step = step;
    char field[NFIELDS][48], line[NFIELDS * 50];
    if (p->enabled && now - p->wall_last >= PROGRESS_INTERVAL) {
        fill_fields(field, p, t, dt, step - p->step_last, now - p->wall_last, now);
        field[F_WALL][0] = '\0';
        const int width = terminal_width();
        join_fields(line, sizeof line, field, width);
        fprintf(stderr, "\r%-*s", width, line);
        fflush(stderr);
        p->wall_last = now;
        p->step_last = step;
        p->enabled = 2;
    }
    if (p->log_every > 0 && now - p->log_last >= p->log_every) {
        fill_fields(field, p, t, dt, step - p->log_step, now - p->log_last, now);
        snprintf(field[F_PREFIX], 48, "%s:", name ? name : "sph");
        join_fields(line, sizeof line, field, LOG_WIDTH);
        printf("%s\n", line);
        fflush(stdout);
        p->log_last = now;
        p->log_step = step;
    }
}

void sph_progress_finish(sph_progress *p)
{
    if (p->enabled == 2) {
        fputc('\n', stderr);
        fflush(stderr);
    }
    p->enabled = 0;
    p->log_every = 0;
}
