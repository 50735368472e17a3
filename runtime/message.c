/* message.c — the runtime's error and warning lines, "NAME: error: ..." on stderr, named
 * after the program (its model's name) once sph_sim_init has set it; "sph" before. */
#include <stdarg.h>
#include <stdio.h>

#include "sphrt.h"

static const char *program = "sph";

void sph_message_program(const char *name)
{
    program = name && *name ? name : "sph";
}

static void line(const char *kind, const char *fmt, va_list ap)
{
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
