/* source.c — model source lines, for comments in generated code and for diagnostics. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "source.h"

const char *source_basename(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

/* Each file read once, with where its lines start: the emitter comments its code with the
 * model's lines and the diagnostics show them, without reading the file again each time. */
typedef struct {
    char *path;
    char *text;      /* NULL: the file could not be read */
    size_t *starts;  /* line k (0-based) starts at text + starts[k] */
    int nlines;
} SourceFile;

static SourceFile *files;
static int nfiles;

static void index_lines(SourceFile *f, size_t size)
{
    size_t cap = 64;
    f->starts = malloc(cap * sizeof *f->starts);
    for (size_t at = 0; at < size;) {
        if ((size_t)f->nlines == cap)
            f->starts = realloc(f->starts, (cap *= 2) * sizeof *f->starts);
        f->starts[f->nlines++] = at;
        const char *nl = memchr(f->text + at, '\n', size - at);
        at = nl ? (size_t)(nl - f->text) + 1 : size;
    }
}

/* The entry of path, a new empty one when it has none. */
static SourceFile *file_entry(const char *path, int *found)
{
    for (int i = 0; i < nfiles; i++)
        if (!strcmp(files[i].path, path)) {
            *found = 1;
            return &files[i];
        }
    files = realloc(files, (size_t)(nfiles + 1) * sizeof *files);
    SourceFile *f = &files[nfiles++];
    *f = (SourceFile){strdup(path), NULL, NULL, 0};
    *found = 0;
    return f;
}

void source_set_text(const char *path, const char *text, size_t len)
{
    int found;
    SourceFile *f = file_entry(path, &found);
    free(f->text);
    free(f->starts);
    f->text = malloc(len + 1);
    memcpy(f->text, text, len);
    f->starts = NULL;
    f->nlines = 0;
    index_lines(f, len);
    f->text[len] = 0;
}

static const SourceFile *source_file(const char *path)
{
    int found;
    SourceFile *f = file_entry(path, &found);
    if (found)
        return f;
    FILE *in = fopen(path, "rb");
    if (!in)
        return f;
    size_t size = 0, cap = 1 << 16, n;
    char *text = malloc(cap);
    while ((n = fread(text + size, 1, cap - size, in)) > 0)
        if ((size += n) == cap)
            text = realloc(text, cap *= 2);
    fclose(in);
    f->text = text;
    index_lines(f, size);
    f->text[size] = 0;
    return f;
}

void source_forget(void)
{
    for (int i = 0; i < nfiles; i++) {
        free(files[i].path);
        free(files[i].text);
        free(files[i].starts);
    }
    free(files);
    files = NULL;
    nfiles = 0;
}

const char *source_line(const char *path, int line, size_t *len)
{
    const SourceFile *f = path ? source_file(path) : NULL;
    if (!f || !f->text || line < 1 || line > f->nlines)
        return NULL;
    const char *s = f->text + f->starts[line - 1];
    const char *end = line < f->nlines ? f->text + f->starts[line] : s + strlen(s);
    if (end > s && end[-1] == '\n')
        end--;
    if (end > s && end[-1] == '\r')
        end--;
    *len = (size_t)(end - s);
    return s;
}

const char *source_line_trimmed(const char *file, int line)
{
    static char buf[512];
    size_t n = 0;
    const char *s = source_line(file, line, &n);
    if (!s)
        n = 0;
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\r'))
        n--;
    while (n && (*s == ' ' || *s == '\t'))
        s++, n--;
    if (n > sizeof buf - 1)
        n = sizeof buf - 1;
    memcpy(buf, s, n);
    buf[n] = 0;
    for (char *q = buf; *q; q++)
        if (q[0] == '*' && q[1] == '/')
            q[1] = '_'; /* never close the surrounding C comment */
    return buf;
}

char *source_beside(const char *source, const char *name)
{
    const char *slash = source ? strrchr(source, '/') : NULL;
    if (name[0] == '/' || !slash)
        return strdup(name);
    size_t n = (size_t)(slash - source) + 1;
    char *path = malloc(n + strlen(name) + 1);
    memcpy(path, source, n);
    strcpy(path + n, name);
    return path;
}
