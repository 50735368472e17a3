/* template.c — filling the C templates in templates/ (see template.h). */
#include <ctype.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "template.h"
#include "util/diag.h"

void tpl_set(TplEnv *e, const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char *value = malloc((size_t)len + 1);
    va_start(ap, fmt);
    vsnprintf(value, (size_t)len + 1, fmt, ap);
    va_end(ap);
    for (int k = 0; k < e->nkeys; k++)
        if (!strcmp(e->keys[k].name, key)) {
            free(e->keys[k].value);
            e->keys[k].value = value;
            return;
        }
    if (e->nkeys == e->keys_cap) {
        e->keys_cap = e->keys_cap ? 2 * e->keys_cap : 32;
        e->keys = realloc(e->keys, (size_t)e->keys_cap * sizeof *e->keys);
    }
    e->keys[e->nkeys++] = (TplKey){strdup(key), value};
}

void tpl_switch(TplEnv *e, const char *name, int on)
{
    for (int i = 0; i < e->nswitches; i++)
        if (!strcmp(e->switches[i].name, name)) {
            e->switches[i].on = on;
            return;
        }
    if (e->nswitches == e->switches_cap) {
        e->switches_cap = e->switches_cap ? 2 * e->switches_cap : 32;
        e->switches = realloc(e->switches, (size_t)e->switches_cap * sizeof *e->switches);
    }
    e->switches[e->nswitches++] = (TplSwitch){name, on};
}

void tpl_free(TplEnv *e)
{
    for (int k = 0; k < e->nkeys; k++) {
        free(e->keys[k].name);
        free(e->keys[k].value);
    }
    free(e->keys);
    free(e->switches);
    memset(e, 0, sizeof *e);
}

/* The switch's state, or -1 when it was not declared. */
static int switch_state(const TplEnv *e, const char *name)
{
    for (int i = 0; i < e->nswitches; i++)
        if (!strcmp(e->switches[i].name, name))
            return e->switches[i].on;
    return -1;
}

static const TplKey *find_key(const TplEnv *e, const char *name, size_t len)
{
    for (int k = 0; k < e->nkeys; k++)
        if (strlen(e->keys[k].name) == len && !strncmp(e->keys[k].name, name, len))
            return &e->keys[k];
    return NULL;
}

/* Length of the key name at p ([A-Z0-9_]+ followed by '@'), or 0 when p starts none. */
static size_t key_length(const char *p)
{
    size_t n = 0;
    while (isupper((unsigned char)p[n]) || isdigit((unsigned char)p[n]) || p[n] == '_')
        n++;
    return n && p[n] == '@' ? n : 0;
}

/* The line with its @KEY@s replaced; -1 after reporting an unbound key. */
static int substitute(const char *line, const TplEnv *e, FILE *out, const char *path, int lineno)
{
    for (const char *p = line; *p; p++) {
        size_t n = *p == '@' ? key_length(p + 1) : 0;
        if (!n) {
            fputc(*p, out);
            continue;
        }
        const TplKey *k = find_key(e, p + 1, n);
        if (!k) {
            diag_fatal_noloc("template '%s', line %d: no value for @%.*s@", path, lineno, (int)n,
                             p + 1);
            return -1;
        }
        fputs(k->value, out);
        p += n + 1;
    }
    return 0;
}

/* One //@if level: whether its lines are kept, and whether it has seen its //@else. */
typedef struct {
    int keep, on, in_else;
} Level;

enum { MAX_DEPTH = 32 };

/* A directive line (s starts with "//@"): updates the levels; -1 after reporting. */
static int directive(const char *s, const TplEnv *e, Level *lv, int *depth, const char *path,
                     int lineno)
{
    char word[16] = {0}, name[64] = {0};
    sscanf(s + 3, "%15s %63s", word, name);
    const int outer = *depth ? lv[*depth - 1].keep : 1;
    if (!strcmp(word, "if")) {
        int on = switch_state(e, name);
        if (on < 0 || *depth == MAX_DEPTH) {
            diag_fatal_noloc("template '%s', line %d: %s '%s'", path, lineno,
                             on < 0 ? "unknown switch" : "//@if nested too deep in", name);
            return -1;
        }
        lv[(*depth)++] = (Level){outer && on, on, 0};
        return 0;
    }
    if (!strcmp(word, "else") && *depth && !lv[*depth - 1].in_else) {
        Level *l = &lv[*depth - 1];
        l->in_else = 1;
        l->keep = (*depth > 1 ? lv[*depth - 2].keep : 1) && !l->on;
        return 0;
    }
    if (!strcmp(word, "endif") && *depth) {
        (*depth)--;
        return 0;
    }
    diag_fatal_noloc("template '%s', line %d: unexpected '//@%s'", path, lineno, word);
    return -1;
}

int tpl_expand(const char *path, const TplEnv *e, FILE *out)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        diag_fatal_noloc("cannot read template '%s'", path);
        return -1;
    }
    char *line = NULL;
    size_t cap = 0;
    Level lv[MAX_DEPTH];
    int depth = 0, lineno = 0, bad = 0;
    while (!bad && getline(&line, &cap, f) >= 0) {
        lineno++;
        const char *s = line + strspn(line, " \t");
        if (!strncmp(s, "//@", 3))
            bad = directive(s, e, lv, &depth, path, lineno);
        else if (!depth || lv[depth - 1].keep)
            bad = substitute(line, e, out, path, lineno);
    }
    free(line);
    fclose(f);
    if (!bad && depth) {
        diag_fatal_noloc("template '%s': %d //@if without //@endif", path, depth);
        bad = -1;
    }
    return bad ? -1 : 0;
}
