/* template.h — filling the C templates in templates/.
 *
 * A template is C source with two kinds of marks:
 *   //@if NAME ... [//@else ...] //@endif   the first part kept when switch NAME is on, the
 *                                          second when it is off (nesting allowed)
 *   @KEY@                                  replaced by the value bound to KEY
 * so that generated code holds only what the scene uses.  Nothing is dropped or kept
 * silently: a switch that was not declared (on or off), a key that was not bound and a
 * malformed mark are errors naming the template's file and line. */
#ifndef SPHC_TEMPLATE_H
#define SPHC_TEMPLATE_H

#include <stdio.h>

typedef struct {
    char *name;
    char *value;
} TplKey;

typedef struct {
    const char *name;
    int on;
} TplSwitch;

typedef struct {
    TplKey *keys;
    int nkeys, keys_cap;
    TplSwitch *switches;
    int nswitches, switches_cap;
} TplEnv;

/* Bind @key@ to the formatted value (a key bound again takes the new value). */
void tpl_set(TplEnv *e, const char *key, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* Declare switch `name` (a static string), on or off (declared again: the new state). */
void tpl_switch(TplEnv *e, const char *name, int on);
void tpl_free(TplEnv *e);

/* Expand template file `path` into out.  Returns 0, or -1 after reporting (the file cannot
 * be read, or a mark is unknown or malformed). */
int tpl_expand(const char *path, const TplEnv *e, FILE *out);

#endif
