/* xml_mathexpr.c — <mathexpressions>: user expressions and their locals.
 *
 *   <userexpression id="1">
 *     <locals value="L0=0.2; kw=9.375; cs=57.0"/>
 *     <expression value="if(x0<=0.0, 0.0, ...)"/>
 *   </userexpression>
 *
 * Locals become the model's `let`s.  Expressions that define the same local with the same
 * value share one `let`; a local whose name is taken (by another expression's local with a
 * different value, a built-in name or a keyword of the sph language) is qualified with its
 * expression's id, e.g. e2_L0, and renamed in that expression.  A local may use the locals
 * before it in the same list. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "model/model.h"
#include "xml_internal.h"
#include "lang/builtins.h"

/* Words of the sph language that cannot name a `let`. */
static int is_keyword(const char *s)
{
    static const char *const words[] = {
        "import", "scene", "let", "fn", "material", "body", "shape", "stress", "energy",
        "dissipation", "require", "temperature", "wavespeed", "viscousheat",
        "state", "if", "else", "velocity", "force", "from", "to", "near", "measure", "plane",
        "expect", "reference", "within", "and", "or", "not", "skip", "Skip", "notch",
        "fracture", NULL};
    for (int i = 0; words[i]; i++)
        if (!strcmp(s, words[i]))
            return 1;
    return 0;
}

/* The let called name: its index, or -1. */
static int find_let(const XmlCtx *x, const char *name)
{
    for (int i = 0; i < x->nlets; i++)
        if (!strcmp(x->lets[i].name, name))
            return i;
    return -1;
}

static int is_identifier(const char *s)
{
    if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || *s == '_'))
        return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= 'A' && *s <= 'Z') || *s == '_' ||
              (*s >= '0' && *s <= '9')))
            return 0;
    return 1;
}

/* The locals of one expression while they are read: names as written, their lets. */
typedef struct {
    char **names, **lets;
    double *values;
    int n;
} Locals;

static void push_local(Locals *l, const char *name, const char *let, double v)
{
    l->names = ast_room(l->names, (size_t)l->n, sizeof *l->names);
    l->lets = ast_room(l->lets, (size_t)l->n, sizeof *l->lets);
    l->values = ast_room(l->values, (size_t)l->n, sizeof *l->values);
    l->names[l->n] = ast_strdup(name);
    l->lets[l->n] = ast_strdup(let);
    l->values[l->n++] = v;
}

/* The let for local name = v of expression id: an existing one with the same value, or a
 * new one, qualified when the plain name is taken. */
static const char *let_for(XmlCtx *x, long id, const char *name, double v, Expr *value,
                           SrcLoc loc)
{
    const size_t size = strlen(name) + 48; /* every candidate fits whole: none repeats */
    char *buf = ast_alloc(size);
    snprintf(buf, size, "%s", name);
    for (int round = 0;; round++) {
        int i = find_let(x, buf);
        if (i >= 0 && x->lets[i].value->kind == EX_NUM && x->lets[i].value->num == v)
            return x->lets[i].name;
        int taken = i >= 0 || is_keyword(buf) || builtin_variable(buf) >= 0 ||
                    builtin_function_arity(buf) >= 0;
        if (!taken)
            break;
        if (round == 0)
            snprintf(buf, size, "e%ld_%s", id, name);
        else
            snprintf(buf, size, "e%ld_%s_%d", id, name, round + 1);
    }
    Item it = {0};
    it.kind = IT_LET;
    it.loc = loc;
    it.name = buf;
    it.value = value->kind == EX_NUM ? value : ast_num(loc, v);
    x->lets = ast_room(x->lets, (size_t)x->nlets, sizeof *x->lets);
    x->lets[x->nlets++] = it;
    return it.name;
}

/* One "name = value" of a <locals> list. */
static int local(XmlCtx *x, long id, char *entry, SrcLoc loc, Locals *l)
{
    char *eq = strchr(entry, '=');
    char what[80];
    snprintf(what, sizeof what, "<locals> of expression %ld", id);
    if (!eq) {
        diag_error(loc, "%s: expected name=value, got '%s'", what, entry);
        return -1;
    }
    *eq = 0;
    char *name = entry, *end = eq;
    while (*name == ' ' || *name == '\t')
        name++;
    while (end > name && (end[-1] == ' ' || end[-1] == '\t'))
        *--end = 0;
    if (!is_identifier(name)) {
        diag_error(loc, "%s: '%s' is not a valid name", what, name);
        return -1;
    }
    if (strlen(name) > XML_MAX_NAME) { /* as in expressions (xml_expr.c) */
        diag_error(loc, "%s: the name '%.20s...' is longer than %d characters", what, name,
                   XML_MAX_NAME);
        return -1;
    }
    char vwhat[256];
    snprintf(vwhat, sizeof vwhat, "%s, value of '%s'", what, name);
    Expr *e = xml_parse_expr(eq + 1, loc, vwhat);
    double v;
    if (!e || xml_eval(e, l->names, l->values, l->n, vwhat, &v))
        return -1;
    push_local(l, name, let_for(x, id, name, v, e, loc), v);
    return 0;
}

static int read_locals(XmlCtx *x, long id, const xmlNode *n, Locals *l)
{
    static const char *const attrs[] = {"value", NULL};
    if (xml_check_attrs(x, n, attrs))
        return -1;
    char *text = xml_attr(n, "value");
    if (!text) {
        diag_error(xml_loc(x, n), "<locals>: missing attribute 'value'");
        return -1;
    }
    int bad = 0;
    for (char *entry = strtok(text, ";"); entry; entry = strtok(NULL, ";")) {
        if (strspn(entry, " \t\n\r") == strlen(entry))
            continue; /* "a=1; b=2;" */
        bad |= local(x, id, entry, xml_loc(x, n), l) != 0;
    }
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ <userexpression> */

static int user_expression(XmlCtx *x, const xmlNode *n)
{
    static const char *const attrs[] = {"id", NULL};
    static const char *const kids[] = {"locals", "expression", NULL};
    static const char *const value[] = {"value", NULL};
    long id;
    if (xml_check_attrs(x, n, attrs) || xml_integer(x, n, "id", 1, 0, 1000000000, &id) != 1 ||
        xml_check_children(x, n, kids))
        return -1;
    if (xml_user_expr(x, id)) {
        diag_error(xml_loc(x, n), "<userexpression>: id %ld is already defined", id);
        diag_note(xml_user_expr(x, id)->loc, "expression %ld is defined here", id);
        return -1;
    }
    const xmlNode *en = xml_child(n, "expression"), *ln = xml_child(n, "locals");
    if (!en) {
        diag_error(xml_loc(x, n), "<userexpression id=\"%ld\"> needs an <expression>", id);
        return -1;
    }
    Locals l = {0};
    if (ln && read_locals(x, id, ln, &l))
        return -1;
    char *text = xml_attr(en, "value");
    if (xml_check_attrs(x, en, value))
        return -1;
    if (!text) {
        diag_error(xml_loc(x, en), "<expression>: missing attribute 'value'");
        return -1;
    }
    Expr *e = xml_parse_expr(text, xml_loc(x, en), "<expression> attribute 'value'");
    if (!e)
        return -1;
    for (int i = 0; i < l.n; i++)
        if (strcmp(l.names[i], l.lets[i]) != 0)
            xml_rename(e, l.names[i], l.lets[i]);
    x->exprs = ast_room(x->exprs, (size_t)x->nexprs, sizeof *x->exprs);
    x->exprs[x->nexprs++] = (XmlUserExpr){(int)id, e, xml_loc(x, en)};
    return 0;
}

int xml_mathexpressions(XmlCtx *x, const xmlNode *mathexpressions)
{
    static const char *const kids[] = {"userexpression", NULL};
    int bad = xml_check_children(x, mathexpressions, kids) != 0;
    for (xmlNode *c = xml_first(mathexpressions); c; c = xml_next(c))
        if (xml_is(c, "userexpression"))
            bad |= user_expression(x, c) != 0;
    return bad ? -1 : 0;
}

const XmlUserExpr *xml_user_expr(const XmlCtx *x, long id)
{
    for (int i = 0; i < x->nexprs; i++)
        if (x->exprs[i].id == id)
            return &x->exprs[i];
    return NULL;
}
