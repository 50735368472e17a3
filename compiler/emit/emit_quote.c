/* emit_quote.c — the model's text in the generated program: C string literals, where a model
 * item is ("file.sph:LINE", for the runtime's messages), its line for a comment. */
#include <stdio.h>

#include "emit_quote.h"

void emit_c_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (; *s; s++)
        if (*s == '"' || *s == '\\')
            fprintf(out, "\\%c", *s);
        else if ((unsigned char)*s < 0x20 || (unsigned char)*s >= 0x7f)
            fprintf(out, "\\%03o", (unsigned char)*s);
        else
            fputc(*s, out);
    fputc('"', out);
}

void emit_where(FILE *out, SrcLoc loc)
{
    char buf[300];
    snprintf(buf, sizeof buf, "%s:%d", source_basename(loc.file), loc.line);
    emit_c_string(out, buf);
}

const char *emit_line_of(SrcLoc loc)
{
    return source_line_trimmed(loc.file, loc.line);
}
