/* source.h — source locations, and model source lines for comments in generated code. */
#ifndef SPHC_SOURCE_H
#define SPHC_SOURCE_H

#include <stddef.h>

/* Where an item of a model is. */
typedef struct {
    const char *file; /* path as given on the command line (or the stdlib file) */
    int line, col;    /* 1-based */
} SrcLoc;

/* Line `line` (1-based) of `path`: its first character, its length in *len without the line
 * terminator; NULL when the file cannot be read or has no such line.  Each file is read
 * once. */
const char *source_line(const char *path, int line, size_t *len);
/* Line lookups of `path` read text[0 .. len-1] instead of the file: a file converted before it
 * is read (an XML case in UTF-16 shows its lines in UTF-8). */
void source_set_text(const char *path, const char *text, size_t len);
/* Forget the files read so far (a program that checks many models in one process, each
 * written to the same path, reads each anew). */
void source_forget(void);
/* The text of line `line` of `file`, leading and trailing blanks removed, with any
 * comment terminator made harmless; "" when unavailable.  Points to a static buffer. */
const char *source_line_trimmed(const char *file, int line);
/* The file name without its folders. */
const char *source_basename(const char *path);
/* A file named in `source`, relative to it (as written when `source` lies in the current
 * folder or name is absolute); malloc'ed. */
char *source_beside(const char *source, const char *name);

#endif
