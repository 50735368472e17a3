/* json.c — a small streaming JSON writer for summary.json: pretty-printed with a
 * 2-space indent.  j->first[d] is 1 while the object or array at depth d has no
 * member yet, which decides where commas go.  Nesting is limited to 31 levels.  The file is
 * written beside its name and renamed over it when closed (sph_open_whole): a reader, or a
 * run killed while writing it, never sees a part of one. */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fsutil.h"
#include "json.h"
#include "core/message.h"

#define JSON_MAX_DEPTH 31

static int write_error(const char *what, int err)
{
    sph_error("cannot write %s: %s", what, strerror(err ? err : EIO));
    return -1;
}

static void indent(sph_json *j)
{
    for (int d = 0; d < j->depth; d++)
        fputs("  ", j->f);
}

static void write_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        switch (*p) {
        case '"':  fputs("\\\"", f); break;
        case '\\': fputs("\\\\", f); break;
        case '\n': fputs("\\n", f); break;
        case '\r': fputs("\\r", f); break;
        case '\t': fputs("\\t", f); break;
        case '\b': fputs("\\b", f); break;
        case '\f': fputs("\\f", f); break;
        default:
            if (*p < 0x20)
                fprintf(f, "\\u%04x", *p);
            else
                fputc(*p, f);
        }
    }
    fputc('"', f);
}

/* Starts a member of the current object (key) or an element of the current array
 * (key NULL): the comma after the previous one, a new line, the indent and the key.
 * Returns 0 when there is no open file (sph_json_open failed) and nothing is written. */
static int member(sph_json *j, const char *key)
{
    if (!j->f)
        return 0;
    if (!j->first[j->depth])
        fputc(',', j->f);
    j->first[j->depth] = 0;
    fputc('\n', j->f);
    indent(j);
    if (key) {
        write_string(j->f, key);
        fputs(": ", j->f);
    }
    return 1;
}

static void open_level(sph_json *j, const char *key, char bracket)
{
    if (!member(j, key))
        return;
    fputc(bracket, j->f);
    if (j->depth < JSON_MAX_DEPTH)
        j->depth++;
    j->first[j->depth] = 1;
}

/* Closes the current level; an empty object or array stays on one line. */
static void close_level(sph_json *j, char bracket)
{
    if (!j->f)
        return;
    int empty = j->first[j->depth];
    if (j->depth > 0)
        j->depth--;
    if (!empty) {
        fputc('\n', j->f);
        indent(j);
    }
    fputc(bracket, j->f);
}

int sph_json_open(sph_json *j, const char *path)
{
    j->depth = 1;
    j->first[1] = 1;
    j->path = strdup(path);
    j->f = j->path ? sph_open_whole(path) : NULL;
    if (!j->f) {
        const int err = j->path ? errno : ENOMEM;
        free(j->path);
        j->path = NULL;
        return write_error(path, err);
    }
    errno = 0;
    fputc('{', j->f);
    return 0;
}

void sph_json_key_object(sph_json *j, const char *key) { open_level(j, key, '{'); }
void sph_json_key_array(sph_json *j, const char *key) { open_level(j, key, '['); }
void sph_json_end_object(sph_json *j) { close_level(j, '}'); }
void sph_json_end_array(sph_json *j) { close_level(j, ']'); }

/* The shortest of %.15g, %.16g, %.17g that reads back as exactly v. */
static void format_number(char *buf, size_t size, double v)
{
    for (int prec = 15; prec <= 17; prec++) {
        snprintf(buf, size, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            return;
    }
}

void sph_json_num(sph_json *j, const char *key, double v)
{
    char buf[32];
    if (!member(j, key))
        return;
    if (!isfinite(v)) {
        fputs("null", j->f);
        return;
    }
    format_number(buf, sizeof buf, v);
    fputs(buf, j->f);
}

void sph_json_int(sph_json *j, const char *key, long v)
{
    if (member(j, key))
        fprintf(j->f, "%ld", v);
}

void sph_json_str(sph_json *j, const char *key, const char *s)
{
    if (!member(j, key))
        return;
    if (s)
        write_string(j->f, s);
    else
        fputs("null", j->f);
}

void sph_json_bool(sph_json *j, const char *key, int v)
{
    if (member(j, key))
        fputs(v ? "true" : "false", j->f);
}

int sph_json_close(sph_json *j)
{
    if (!j->f)
        return -1;
    close_level(j, '}'); /* the caller has closed every level it opened */
    fputc('\n', j->f);
    const int err = sph_close_whole(j->f, j->path);
    const int bad = err ? write_error(j->path, err) : 0;
    j->f = NULL;
    free(j->path);
    j->path = NULL;
    return bad;
}
