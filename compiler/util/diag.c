/* diag.c — diagnostics in the gcc style, on stderr, without colour:
 *
 *   model.sph:3:14: error: unknown function 'sinn'
 *       3 |   velocity z = sinn(t)
 *         |                ^
 *
 * The source line comes from the file named in the location (source.c); when it
 * cannot be read only the first line is printed.  Columns count bytes; tabs
 * before the caret are copied so that the caret lines up. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"

/* The run stops after this many errors: a broken construct can make the parser report
 * an error every few tokens, each with its source line, which may be very long. */
enum { MAX_ERRORS = 50 };
/* Warnings are shown up to this many; the rest are counted, and one line at exit says how
 * many were not shown: a case with a million unknown cards would otherwise write a warning,
 * and its source line, for each. */
enum { MAX_WARNINGS = 50 };

static int n_errors;
static long n_warnings;
static long n_hidden;   /* warnings not shown */
static int hide_notes;  /* the last warning was not shown: neither are its notes */
static int strict;
static void (*stop_handler)(void);

/* Line `line` (1-based) of `path` in a malloc'ed string without its line terminator, or
 * NULL. */
static char *read_source_line(const char *path, int line)
{
    size_t len;
    const char *s = source_line(path, line, &len);
    return s ? strndup(s, len) : NULL;
}

/* A line longer than this many bytes is shown as the part around the column, between
 * "...": a generated model may have a line of megabytes. */
enum { SHOW_MAX = 400 };

static void show_source(SrcLoc loc)
{
    if (!loc.file || loc.line <= 0)
        return;
    char *text = read_source_line(loc.file, loc.line);
    if (!text)
        return;
    char num[16];
    int width = snprintf(num, sizeof num, "%d", loc.line);
    if (width < 4)
        width = 4;
    size_t len = strlen(text), col = loc.col > 0 ? (size_t)loc.col - 1 : 0;
    if (col > len)
        col = len;
    size_t from = 0, to = len;
    if (len > SHOW_MAX) {
        from = col > SHOW_MAX / 2 ? col - SHOW_MAX / 2 : 0;
        to = from + SHOW_MAX < len ? from + SHOW_MAX : len;
    }
    fprintf(stderr, " %*d | %s%.*s%s\n", width, loc.line, from ? "..." : "", (int)(to - from),
            text + from, to < len ? "..." : "");
    if (loc.col > 0) {
        fprintf(stderr, " %*s | %s", width, "", from ? "   " : "");
        for (size_t i = from; i < col; i++)
            fputc(text[i] == '\t' ? '\t' : ' ', stderr);
        fputs("^\n", stderr);
    }
    free(text);
}

static void report(SrcLoc loc, const char *kind, const char *suffix, const char *fmt, va_list ap)
{
    fflush(stdout);
    if (loc.file && loc.line > 0 && loc.col > 0)
        fprintf(stderr, "%s:%d:%d: %s: ", loc.file, loc.line, loc.col, kind);
    else if (loc.file && loc.line > 0)
        fprintf(stderr, "%s:%d: %s: ", loc.file, loc.line, kind);
    else if (loc.file)
        fprintf(stderr, "%s: %s: ", loc.file, kind);
    else
        fprintf(stderr, "sphc: %s: ", kind);
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "%s\n", suffix);
    show_source(loc);
}

/* One more error: the run stops after MAX_ERRORS. */
static void count_error(void)
{
    if (++n_errors < MAX_ERRORS)
        return;
    fprintf(stderr, "sphc: error: too many errors (%d), stopping\n", n_errors);
    if (stop_handler)
        stop_handler();
    exit(1);
}

void diag_error(SrcLoc loc, const char *fmt, ...)
{
    hide_notes = 0;
    va_list ap;
    va_start(ap, fmt);
    report(loc, "error", "", fmt, ap);
    va_end(ap);
    count_error();
}

/* At exit, the count of the warnings not shown. */
static void report_hidden(void)
{
    if (n_hidden > 0) {
        fflush(stdout);
        fprintf(stderr, "sphc: note: %ld more warning%s not shown (only the first %d are)\n",
                n_hidden, n_hidden == 1 ? "" : "s", MAX_WARNINGS);
    }
    n_hidden = 0;
}

/* Whether a warning is past MAX_WARNINGS: it is counted, not shown. */
static int hide_warning(void)
{
    static int registered;
    hide_notes = !strict && n_warnings >= MAX_WARNINGS;
    if (!hide_notes)
        return 0;
    if (!registered && atexit(report_hidden) == 0)
        registered = 1;
    n_warnings++;
    n_hidden++;
    return 1;
}

void diag_warning(SrcLoc loc, const char *fmt, ...)
{
    if (hide_warning())
        return;
    va_list ap;
    va_start(ap, fmt);
    report(loc, strict ? "error" : "warning", strict ? " [--strict]" : "", fmt, ap);
    va_end(ap);
    n_warnings++;
    if (strict)
        count_error();
}

void diag_note(SrcLoc loc, const char *fmt, ...)
{
    if (hide_notes)
        return;
    va_list ap;
    va_start(ap, fmt);
    report(loc, "note", "", fmt, ap);
    va_end(ap);
}

void diag_fatal_noloc(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fflush(stdout);
    fputs("sphc: error: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    n_errors++;
}

int diag_error_count(void)
{
    return n_errors;
}

void diag_reset(void)
{
    n_errors = 0;
    n_warnings = 0;
    n_hidden = 0;
    hide_notes = 0;
}

void diag_set_strict(int on)
{
    strict = on;
}

void diag_set_stop(void (*handler)(void))
{
    stop_handler = handler;
}
