/* template.c — filling the C templates in templates/ (see template.h). */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "template.h"

void tpl_set(TplEnv *e, const char *key, const char *fmt, ...)
{
    int k = 0;
    while (k < e->nvars && strcmp(e->keys[k], key))
        k++;
    if (k == e->nvars) {
        if (e->nvars == 32)
            return;
        e->keys[e->nvars++] = key;
    }
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(e->values[k], sizeof e->values[k], fmt, ap);
    va_end(ap);
}

void tpl_feature(TplEnv *e, const char *name, int on)
{
    if (on && e->nfeatures < 32)
        e->features[e->nfeatures++] = name;
}

static int feature_on(const TplEnv *e, const char *name)
{
    for (int i = 0; i < e->nfeatures; i++)
        if (!strcmp(e->features[i], name))
            return 1;
    return 0;
}

static void substitute(const char *line, const TplEnv *e, FILE *out)
{
    for (const char *p = line; *p; p++) {
        if (*p == '@') {
            const char *q = strchr(p + 1, '@');
            int matched = 0;
            for (int k = 0; q && k < e->nvars && !matched; k++)
                if ((size_t)(q - p - 1) == strlen(e->keys[k]) &&
                    !strncmp(p + 1, e->keys[k], (size_t)(q - p - 1))) {
                    fputs(e->values[k], out);
                    p = q;
                    matched = 1;
                }
            if (matched)
                continue;
        }
        fputc(*p, out);
    }
}

int tpl_expand(const char *path, const TplEnv *e, FILE *out)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        diag_fatal_noloc("cannot read template '%s'", path);
        return -1;
    }
    char line[1024];
    int depth = 0, skipping_from = 0; /* skip while depth >= skipping_from > 0 */
    while (fgets(line, sizeof line, f)) {
        const char *s = line + strspn(line, " \t");
        if (!strncmp(s, "//@if ", 6)) {
            char name[64] = {0};
            sscanf(s + 6, "%63s", name);
            depth++;
            if (!skipping_from && !feature_on(e, name))
                skipping_from = depth;
            continue;
        }
        if (!strncmp(s, "//@endif", 8)) {
            if (skipping_from == depth)
                skipping_from = 0;
            depth--;
            continue;
        }
        if (!skipping_from)
            substitute(line, e, out);
    }
    fclose(f);
    if (depth != 0) {
        diag_fatal_noloc("template '%s': unbalanced //@if", path);
        return -1;
    }
    return 0;
}
