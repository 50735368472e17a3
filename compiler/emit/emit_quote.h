/* emit_quote.h — the model's text in the generated program (emit_quote.c): C string
 * literals, where a model item is, its line for a comment. */
#ifndef SPHC_EMIT_QUOTE_H
#define SPHC_EMIT_QUOTE_H

#include <stdio.h>

#include "util/source.h"

/* s as a C string literal (quotes, backslashes and control characters escaped). */
void emit_c_string(FILE *out, const char *s);
/* "file.sph:LINE" of loc as a C string literal: where a model item is, for the runtime's
 * messages. */
void emit_where(FILE *out, SrcLoc loc);
/* The model line at loc, trimmed, for a comment. */
const char *emit_line_of(SrcLoc loc);

#endif
