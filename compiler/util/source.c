/* source.c — reading model source lines back, for comments in generated code. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "source.h"

const char *source_basename(const char *path)
{
    const char *s = strrchr(path, '/');
    return s ? s + 1 : path;
}

const char *source_line_trimmed(const char *file, int line)
{
    static char buf[512];
    buf[0] = 0;
    FILE *f = fopen(file, "r");
    if (!f)
        return buf;
    for (int l = 1; l <= line && fgets(buf, sizeof buf, f); l++)
        if (l == line)
            break;
    fclose(f);
    size_t n = strlen(buf);
    while (n && (buf[n - 1] == '\n' || buf[n - 1] == '\r' || buf[n - 1] == ' '))
        buf[--n] = 0;
    char *p = buf;
    while (*p == ' ' || *p == '\t')
        p++;
    for (char *q = p; *q; q++)
        if (q[0] == '*' && q[1] == '/')
            q[1] = '_'; /* never close the surrounding C comment */
    memmove(buf, p, strlen(p) + 1);
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
