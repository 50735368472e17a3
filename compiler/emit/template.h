/* template.h — filling the C templates in templates/.
 *
 * A template is C source with two kinds of marks:
 *   //@if NAME ... //@endif    kept only when feature NAME is on (nesting allowed)
 *   @KEY@                      replaced by the value bound to KEY
 * so that generated code holds only what the scene uses. */
#ifndef SPHC_TEMPLATE_H
#define SPHC_TEMPLATE_H

#include <stdio.h>

typedef struct {
    const char *keys[32];
    char values[32][128];
    int nvars;
    const char *features[32];
    int nfeatures;
} TplEnv;

void tpl_set(TplEnv *e, const char *key, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
void tpl_feature(TplEnv *e, const char *name, int on);

/* Expand template file `path` into out.  Returns 0, or -1 (reported) when the file cannot
 * be read or a mark is malformed. */
int tpl_expand(const char *path, const TplEnv *e, FILE *out);

#endif
