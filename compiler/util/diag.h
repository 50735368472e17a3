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
void diag_warning(SrcLoc loc, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void diag_note(SrcLoc loc, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* An error with no source position (e.g. a missing file): "sphc: error: ..." */
void diag_fatal_noloc(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

int diag_error_count(void);
void diag_reset(void);

#endif
