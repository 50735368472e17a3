/* message.c — the runtime's error and warning lines, "NAME: error: ..." on stderr, named
 * after the program (its model's name) once sph_sim_init has set it; "sph" before. */
#include <stdarg.h>
#include <stdio.h>

#include "message.h"

static const char *program = "sph";

/* Processes other than the first of a run on many processes keep their messages: warnings
 * and notes are dropped (the first process gives the same), the first error is kept for
 * sph_message_kept (a failure of this process alone, which the first reports for it). */
static int keeping;
static char kept[1024];

void sph_message_program(const char *name)
{
    program = name && *name ? name : "sph";
}

void sph_message_keep(int keep)
{
    keeping = keep;
}

const char *sph_message_kept(void)
{
    return kept;
}

static void line(const char *kind, const char *fmt, va_list ap)
{
    if (keeping) {
        if (kind[0] == 'e' && !kept[0])
            vsnprintf(kept, sizeof kept, fmt, ap);
        return;
    }
    fprintf(stderr, "%s: %s: ", program, kind);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void sph_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    line("error", fmt, ap);
    va_end(ap);
}

void sph_warning(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    line("warning", fmt, ap);
    va_end(ap);
}

void sph_note(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    line("note", fmt, ap);
    va_end(ap);
}
