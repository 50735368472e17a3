/* diag.h — compiler diagnostics in the gcc style:
 *
 *   model.sph:3:14: error: unknown function 'sinn'
 *       velocity z = sinn(t)
 *                    ^
 * Every stage reports through here; the driver exits non-zero when
 * diag_error_count() > 0. */
#ifndef SPHC_DIAG_H
#define SPHC_DIAG_H

#include "source.h"

void diag_error(SrcLoc loc, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* The first 50 warnings are shown; the others are counted (with their notes left out), and
 * one line at exit says how many were not shown. */
void diag_warning(SrcLoc loc, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void diag_note(SrcLoc loc, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* An error with no source position (e.g. a missing file): "sphc: error: ..." */
void diag_fatal_noloc(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* --strict: a warning is reported as an error, "...: error: ... [--strict]", and counted as
 * one (every stage then fails as for an error). */
void diag_set_strict(int on);

int diag_error_count(void);
void diag_reset(void);

/* After too many errors the run stops: exit(1), or the handler set here, which must not
 * return (a program that runs the stages in-process, like the fuzz targets, longjmps back
 * to its own loop); NULL restores exit(1). */
void diag_set_stop(void (*handler)(void));

#endif
