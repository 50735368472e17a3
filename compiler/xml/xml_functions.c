/* xml_functions.c — user functions for the shapes an imported case writes out twice.
 *
 * SoliDualSPHysics' expressions have no functions, so a case spells a formula out once for
 * every argument: appendix 2's initial velocity is 0.01 cs f(x0) / f(L0) with the mode
 * shape f written in full at x0 and again at L0.  A model written by hand says
 * `fn f(x) = ...` once.  This pass gives the imported tree that form, which both the
 * compiled program and `sphc --to-sph` then use:
 *
 *  - every subtree of the boundary conditions' expressions with at least MIN_NODES nodes
 *    is compared with every other one that is disjoint from it;
 *  - two match when they are the same tree except for leaves (names or numbers) that
 *    differ in one consistent way, e.g. every x0 in the first is L0 in the second;
 *  - the pair whose shape saves the most (its size times its uses less one) becomes
 *    `fn f(x) = <the first, its differing leaf x>`, and every use calls it, f(x0) and
 *    f(L0); then the next one, and so on;
 *  - a shape qualifies only if its other names are the case's constants (lets), so the
 *    function depends on its argument alone.
 * The function is the same arithmetic in the same order, so results do not change. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "xml_internal.h"
#include "lang/builtins.h"

enum { MIN_NODES = 8, MAX_FUNCTIONS = 16 };

/* The slots of the expressions' subtrees, in pre-order. */
typedef struct {
    Expr **slot[4096];
    int n;
} Subtrees;

static int nodes(const Expr *e)
{
    int n = 1;
    for (int k = 0; k < e->nargs; k++)
        n += nodes(e->args[k]);
    return n;
}

static int same(const Expr *a, const Expr *b)
{
    if (a->kind != b->kind || a->nargs != b->nargs)
        return 0;
    if (a->kind == EX_NUM && a->num != b->num)
        return 0;
    if ((a->kind == EX_NAME || a->kind == EX_CALL) && strcmp(a->name, b->name))
        return 0;
    if ((a->kind == EX_UNARY || a->kind == EX_BINARY) && a->op != b->op)
        return 0;
    for (int k = 0; k < a->nargs; k++)
        if (!same(a->args[k], b->args[k]))
            return 0;
    return 1;
}

static int leaf(const Expr *e) { return e->kind == EX_NUM || e->kind == EX_NAME; }

/* Whether a and b are the same tree up to leaves that differ as *da in a and *db in b
 * (set by the first difference). */
static int match(const Expr *a, const Expr *b, const Expr **da, const Expr **db)
{
    if (same(a, b))
        return 1;
    if (leaf(a) && leaf(b)) {
        if (!*da) {
            *da = a, *db = b;
            return 1;
        }
        return same(*da, a) && same(*db, b);
    }
    if (a->kind != b->kind || a->nargs != b->nargs || leaf(a) || a->kind == EX_SKIP)
        return 0;
    if (a->kind == EX_CALL && strcmp(a->name, b->name))
        return 0;
    if ((a->kind == EX_UNARY || a->kind == EX_BINARY) && a->op != b->op)
        return 0;
    for (int k = 0; k < a->nargs; k++)
        if (!match(a->args[k], b->args[k], da, db))
            return 0;
    return 1;
}

static int is_let(const XmlCtx *x, const char *name)
{
    for (int i = 0; i < x->nlets; i++)
        if (!strcmp(x->lets[i].name, name))
            return 1;
    return 0;
}

/* Whether e, with leaf d as the parameter, depends on nothing but the case's constants. */
static int closed(const XmlCtx *x, const Expr *e, const Expr *d)
{
    if (same(e, d))
        return 1;
    if (e->kind == EX_SKIP || (e->kind == EX_NAME && !is_let(x, e->name)))
        return 0;
    for (int k = 0; k < e->nargs; k++)
        if (!closed(x, e->args[k], d))
            return 0;
    return 1;
}

/* A copy of e with every leaf equal to d replaced by the name p. */
static Expr *generalise(const Expr *e, const Expr *d, const char *p)
{
    if (same(e, d))
        return ast_name(e->loc, p);
    Expr *c = ast_alloc(sizeof *c);
    *c = *e;
    c->name = e->name ? ast_strdup(e->name) : NULL;
    c->args = e->nargs ? ast_alloc((size_t)e->nargs * sizeof *c->args) : NULL;
    for (int k = 0; k < e->nargs; k++)
        c->args[k] = generalise(e->args[k], d, p);
    return c;
}

static void collect(Expr **slot, Subtrees *s)
{
    if (s->n == (int)(sizeof s->slot / sizeof s->slot[0]))
        return;
    s->slot[s->n++] = slot;
    for (int k = 0; k < (*slot)->nargs; k++)
        collect(&(*slot)->args[k], s);
}

static void collect_all(XmlCtx *x, Subtrees *s)
{
    s->n = 0;
    for (int i = 0; i < x->nbodies; i++) {
        BodyDecl *b = &x->bodies[i].body;
        for (int k = 0; k < b->n; k++)
            if (b->items[k].kind == BI_BC && b->items[k].bc.value)
                collect(&b->items[k].bc.value, s);
    }
}

/* A name that no constant, built-in variable or function uses: base, base2, base3, ... */
static char *fresh(const XmlCtx *x, const Item *fns, int nfns, const char *base)
{
    char name[32];
    for (int k = 1;; k++) {
        snprintf(name, sizeof name, k == 1 ? "%s" : "%s%d", base, k);
        int used = is_let(x, name) || builtin_variable(name) >= 0 ||
                   builtin_function_arity(name) >= 0;
        for (int f = 0; f < nfns && !used; f++)
            used = !strcmp(fns[f].name, name);
        if (!used)
            return ast_strdup(name);
    }
}

/* How many subtrees are a with its leaf d replaced by something (a itself included). */
static int instances(const Subtrees *s, const Expr *a, const Expr *d)
{
    int count = 0;
    for (int k = 0; k < s->n; k++) {
        const Expr *pa = NULL, *pb = NULL;
        count += nodes(*s->slot[k]) == nodes(a) && match(a, *s->slot[k], &pa, &pb) &&
                 (!pa || same(pa, d));
    }
    return count;
}

/* The best matching pair of disjoint subtrees, by the nodes a function saves (its size
 * times its uses less one): 0 with *ia < *ib, -1 when none. */
static int best_pair(const XmlCtx *x, const Subtrees *s, int *ia, int *ib, const Expr **da,
                     const Expr **db)
{
    long best = 0;
    for (int i = 0; i < s->n; i++) {
        const Expr *a = *s->slot[i];
        const int na = nodes(a);
        if (na < MIN_NODES)
            continue;
        for (int j = i + na; j < s->n; j++) { /* pre-order: i's subtree is i .. i+na-1 */
            const Expr *b = *s->slot[j], *pa = NULL, *pb = NULL;
            if (nodes(b) != na || !match(a, b, &pa, &pb) || !pa || !closed(x, a, pa) ||
                !closed(x, b, pb))
                continue;
            const long saved = (long)na * (instances(s, a, pa) - 1);
            if (saved > best)
                best = saved, *ia = i, *ib = j, *da = pa, *db = pb;
            break;
        }
    }
    return best ? 0 : -1;
}

/* A copy of leaf d. */
static Expr *copy_leaf(const Expr *d)
{
    return d->kind == EX_NUM ? ast_num(d->loc, d->num) : ast_name(d->loc, d->name);
}

static Expr *call1(SrcLoc loc, const char *fn, const Expr *arg)
{
    Expr **args = ast_alloc(sizeof *args);
    args[0] = copy_leaf(arg);
    return ast_call(loc, fn, args, 1);
}

/* Replaces the first subtree that is a function's body at some argument by a call to it;
 * returns whether it found one. */
static int call_known(Subtrees *s, const Item *fns, int nfns)
{
    for (int i = 0; i < s->n; i++)
        for (int f = 0; f < nfns; f++) {
            const Expr *e = *s->slot[i], *pa = NULL, *pb = NULL;
            if (nodes(e) != nodes(fns[f].value) || !match(fns[f].value, e, &pa, &pb) || !pa ||
                pa->kind != EX_NAME || strcmp(pa->name, fns[f].params[0]))
                continue;
            *s->slot[i] = call1(e->loc, fns[f].name, pb);
            return 1;
        }
    return 0;
}

int xml_factor_functions(XmlCtx *x, Item **fns_out, int *nfns_out)
{
    Item *fns = NULL;
    int nfns = 0;
    Subtrees *s = ast_alloc(sizeof *s);
    for (;;) {
        collect_all(x, s);
        if (call_known(s, fns, nfns))
            continue;
        int i, j;
        const Expr *da, *db;
        if (nfns == MAX_FUNCTIONS || best_pair(x, s, &i, &j, &da, &db))
            break;
        Item fn = {0};
        fn.kind = IT_FN;
        fn.loc = (*s->slot[i])->loc;
        fn.name = fresh(x, fns, nfns, "f");
        fn.params = ast_alloc(sizeof *fn.params);
        fn.params[0] = ast_strdup(is_let(x, "x") ? "s" : "x");
        fn.nparams = 1;
        fn.value = generalise(*s->slot[i], da, fn.params[0]);
        /* the two subtrees are disjoint (j lies after i's), so either slot can go first */
        *s->slot[i] = call1((*s->slot[i])->loc, fn.name, da);
        *s->slot[j] = call1((*s->slot[j])->loc, fn.name, db);
        fns = realloc(fns, (size_t)(nfns + 1) * sizeof *fns);
        fns[nfns++] = fn;
    }
    free(s);
    *fns_out = fns;
    *nfns_out = nfns;
    return nfns;
}
