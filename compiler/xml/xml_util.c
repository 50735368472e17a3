/* xml_util.c — elements, attributes and their values for the XML importer.
 *
 * Errors name the element and the attribute, at the line where the element starts:
 *   case.xml:58: error: <density>: attribute 'value': expected a number, got 'abc' */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "xml_internal.h"

SrcLoc xml_loc(const XmlCtx *x, const xmlNode *n)
{
    SrcLoc l = {x->file, (int)xmlGetLineNo((xmlNode *)n), 0};
    if (n->type == XML_ELEMENT_NODE && n->line >= XML_NODE_LINE_MAX && n->psvi) /* xml_read.c */
        l.line = (int)(intptr_t)n->psvi;
    if (l.line < 0)
        l.line = 0;
    return l;
}

const char *xml_name(const xmlNode *n)
{
    return (const char *)n->name;
}

int xml_is(const xmlNode *n, const char *name)
{
    return strcmp(xml_name(n), name) == 0;
}

static xmlNode *element_from(xmlNode *c)
{
    while (c && c->type != XML_ELEMENT_NODE)
        c = c->next;
    return c;
}

void xml_add_comment(const xmlNode *c, char **acc)
{
    if (c->type != XML_COMMENT_NODE || !c->content)
        return;
    const char *s = (const char *)c->content;
    size_t len = *acc ? strlen(*acc) : 0;
    char *out = realloc(*acc, len + strlen(s) + 2);
    while (*s) { /* line by line, without the indentation and the trailing blanks */
        while (*s == ' ' || *s == '\t')
            s++;
        const char *end = strchr(s, '\n') ? strchr(s, '\n') : s + strlen(s), *e = end;
        while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r'))
            e--;
        if (e > s) {
            memcpy(out + len, s, (size_t)(e - s));
            len += (size_t)(e - s);
            out[len++] = '\n';
        }
        s = *end ? end + 1 : end;
    }
    out[len] = 0;
    *acc = out;
}

xmlNode *xml_first(const xmlNode *n)
{
    return element_from(n->children);
}

xmlNode *xml_next(const xmlNode *n)
{
    return element_from(n->next);
}

xmlNode *xml_child(const xmlNode *n, const char *name)
{
    for (xmlNode *c = xml_first(n); c; c = xml_next(c))
        if (xml_is(c, name))
            return c;
    return NULL;
}

/* A value made of text and entity references is read in one pass into a buffer
 * (xmlGetProp appends piece by piece, in time quadratic in their number). */
char *xml_attr(const xmlNode *n, const char *name)
{
    const xmlAttr *a = xmlHasProp(n, (const xmlChar *)name);
    if (!a)
        return NULL;
    if (a->type != XML_ATTRIBUTE_NODE || !a->children || !a->children->next) {
        xmlChar *v = xmlGetProp(n, (const xmlChar *)name);
        if (!v)
            return NULL;
        char *s = ast_strdup((const char *)v);
        xmlFree(v);
        return s;
    }
    xmlBuffer *buf = xmlBufferCreate();
    if (!buf)
        return NULL;
    xmlNodeBufGetContent(buf, (const xmlNode *)a);
    const xmlChar *v = xmlBufferContent(buf);
    char *s = ast_strdup(v ? (const char *)v : "");
    xmlBufferFree(buf);
    return s;
}

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r')
        s++;
    size_t n = strlen(s);
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\n' || s[n - 1] == '\r'))
        s[--n] = 0;
    return s;
}

char *xml_text(const xmlNode *n)
{
    xmlChar *v = xmlNodeGetContent(n);
    char *s = ast_strdup(v ? (const char *)v : "");
    xmlFree(v);
    return trim(s);
}

static int listed(const char *name, const char *const *list)
{
    for (int i = 0; list && list[i]; i++)
        if (strcmp(name, list[i]) == 0)
            return 1;
    return 0;
}

/* "value" or "x, y or z" for messages. */
static void describe(const char *const *list, char *buf, size_t size)
{
    buf[0] = 0;
    int n = 0;
    while (list && list[n])
        n++;
    for (int i = 0; i < n; i++) {
        size_t len = strlen(buf);
        snprintf(buf + len, size - len, "%s%s", i == 0 ? "" : i == n - 1 ? " or " : ", ",
                 list[i]);
    }
}

int xml_check_attrs(const XmlCtx *x, const xmlNode *n, const char *const *allowed)
{
    static const char *const always[] = {"comment", "units_comment", NULL};
    int bad = 0;
    for (xmlAttr *a = n->properties; a; a = a->next) {
        const char *name = (const char *)a->name;
        if (listed(name, allowed) || listed(name, always))
            continue;
        char expected[256];
        describe(allowed, expected, sizeof expected);
        if (expected[0])
            diag_error(xml_loc(x, n), "<%s>: unknown attribute '%s' (expected %s)",
                       xml_name(n), name, expected);
        else
            diag_error(xml_loc(x, n), "<%s>: unknown attribute '%s' (it takes none)",
                       xml_name(n), name);
        bad = 1;
    }
    return bad ? -1 : 0;
}

int xml_check_children(const XmlCtx *x, const xmlNode *n, const char *const *allowed)
{
    int bad = 0;
    for (xmlNode *c = xml_first(n); c; c = xml_next(c))
        if (!listed(xml_name(c), allowed)) {
            char expected[512];
            describe(allowed, expected, sizeof expected);
            diag_error(xml_loc(x, c), "<%s> is not expected in <%s> (expected %s)",
                       xml_name(c), xml_name(n), expected);
            bad = 1;
        }
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ values */

int xml_number(const XmlCtx *x, const xmlNode *n, const char *attr, int required, double *out)
{
    char *text = xml_attr(n, attr);
    SrcLoc loc = xml_loc(x, n);
    if (!text) {
        if (!required)
            return 0;
        diag_error(loc, "<%s>: missing attribute '%s'", xml_name(n), attr);
        return -1;
    }
    char what[160];
    snprintf(what, sizeof what, "<%s> attribute '%s'", xml_name(n), attr);
    if (!*trim(text)) {
        diag_error(loc, "%s: expected a number, got an empty value", what);
        return -1;
    }
    Expr *e = xml_parse_expr(text, loc, what);
    if (!e || xml_eval(e, x->var_names, x->var_values, x->nvars, what, out))
        return -1;
    if (!isfinite(*out)) {
        diag_error(loc, "%s: the value '%s' is not a finite number", what, text);
        return -1;
    }
    return 1;
}

int xml_integer(const XmlCtx *x, const xmlNode *n, const char *attr, int required, long lo,
                long hi, long *out)
{
    double v;
    int r = xml_number(x, n, attr, required, &v);
    if (r <= 0)
        return r;
    if (v != floor(v) || v < (double)lo || v > (double)hi) {
        diag_error(xml_loc(x, n), "<%s> attribute '%s': expected a whole number from %ld to %ld, "
                                  "got %g", xml_name(n), attr, lo, hi, v);
        return -1;
    }
    *out = (long)v;
    return 1;
}

int xml_card_number(const XmlCtx *x, const xmlNode *n, double *out)
{
    static const char *const value[] = {"value", NULL};
    if (xml_check_attrs(x, n, value))
        return -1;
    return xml_number(x, n, "value", 1, out) == 1 ? 0 : -1;
}

int xml_card_positive(const XmlCtx *x, const xmlNode *n, double *out)
{
    if (xml_card_number(x, n, out))
        return -1;
    if (*out > 0)
        return 0;
    diag_error(xml_loc(x, n), "<%s> attribute 'value': must be positive (got %g)", xml_name(n),
               *out);
    return -1;
}

int xml_admissible(const XmlCtx *x, const xmlNode *n, const char *attr, Quantity q, double v)
{
    const char *why = inadmissible(q, v);
    if (why)
        diag_error(xml_loc(x, n), "<%s> attribute '%s': %s (got %g)", xml_name(n), attr, why, v);
    return why ? -1 : 0;
}

int xml_card_admissible(const XmlCtx *x, const xmlNode *n, Quantity q, double *out)
{
    return xml_card_number(x, n, out) || xml_admissible(x, n, "value", q, *out) ? -1 : 0;
}

int xml_card_bool(const XmlCtx *x, const xmlNode *n, int *out)
{
    static const char *const value[] = {"value", NULL};
    if (xml_check_attrs(x, n, value))
        return -1;
    char *text = xml_attr(n, "value");
    if (!text) {
        diag_error(xml_loc(x, n), "<%s>: missing attribute 'value'", xml_name(n));
        return -1;
    }
    text = trim(text);
    if (!strcmp(text, "true") || !strcmp(text, "1"))
        *out = 1;
    else if (!strcmp(text, "false") || !strcmp(text, "0"))
        *out = 0;
    else {
        diag_error(xml_loc(x, n), "<%s> attribute 'value': expected true, false, 1 or 0, got '%s'",
                   xml_name(n), text);
        return -1;
    }
    return 0;
}

int xml_point(const XmlCtx *x, const xmlNode *n, double out[3])
{
    static const char *const xyz[] = {"x", "y", "z", NULL};
    int bad = xml_check_attrs(x, n, xyz) != 0;
    for (int k = 0; k < 3; k++)
        bad |= xml_number(x, n, xyz[k], 1, &out[k]) != 1;
    return bad ? -1 : 0;
}

double *xml_points(const XmlCtx *x, const xmlNode *n, int copies, int *count)
{
    int bad = 0;
    *count = 0;
    for (xmlNode *c = xml_first(n); c; c = xml_next(c))
        *count += xml_is(c, "point");
    double *pts = ast_alloc(((size_t)*count * (size_t)copies + 1) * 3 * sizeof *pts), *p = pts;
    for (xmlNode *c = xml_first(n); c; c = xml_next(c))
        if (xml_is(c, "point")) {
            bad |= xml_point(x, c, p) != 0;
            p += 3;
        }
    return bad ? NULL : pts;
}

double xml_snap(double v, double tol)
{
    char buf[40];
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(buf, sizeof buf, "%.*g", digits, v);
        double r = strtod(buf, NULL);
        if (fabs(r - v) <= tol)
            return r;
    }
    return v;
}
