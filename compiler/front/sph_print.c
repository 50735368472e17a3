/* sph_print.c — a Program printed back as an .sph model (sphc --to-sph).
 *
 * The output reads like a hand-written model: one statement per line, consecutive `let`s
 * on one line, named arguments of shapes without commas and of materials with commas,
 * expressions with only the parentheses that precedence needs, and numbers in their
 * shortest form that reads back as the same double.  Only the items of the main file are
 * printed: what an `import` brings in stays an `import`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sph_print.h"
#include "lang/bc_kinds.h"

/* ------------------------------------------------------------------ expressions */

/* "1.75e+09" -> "1.75e9", "1e-05" -> "1e-5". */
static void tidy_exponent(char *s)
{
    char *e = strchr(s, 'e');
    if (!e)
        return;
    char *d = e + 1, *src = e + 1;
    if (*src == '+')
        src++;
    else if (*src == '-')
        *d++ = *src++;
    while (*src == '0' && src[1])
        src++;
    memmove(d, src, strlen(src) + 1);
}

/* Plain decimal form with the given significant digits ("715000", "0.0095"). */
static void plain(double v, int digits, char *buf, size_t size)
{
    int mag = 0;
    for (double a = v < 0 ? -v : v; a >= 10; a /= 10)
        mag++;
    int decimals = digits - 1 - mag;
    if (v != 0 && (v < 0 ? -v : v) < 1)
        for (double a = v < 0 ? -v : v; a < 1; a *= 10)
            decimals++;
    snprintf(buf, size, "%.*f", decimals > 0 ? decimals : 0, v);
    if (strchr(buf, '.')) {
        size_t n = strlen(buf);
        while (buf[n - 1] == '0')
            buf[--n] = 0;
        if (buf[n - 1] == '.')
            buf[n - 1] = 0;
    }
}

/* The shortest text that reads back as v: plain decimals unless the exponent form is
 * more than two characters shorter ("1000" rather than "1e3", "2.1e11"). */
static void print_num(double v, FILE *out)
{
    char sci[40], dec[64];
    int digits = 1;
    for (; digits <= 17; digits++) {
        snprintf(sci, sizeof sci, "%.*g", digits, v);
        if (strtod(sci, NULL) == v)
            break;
    }
    tidy_exponent(sci);
    double a = v < 0 ? -v : v;
    if (a >= 1e-5 && a < 1e16) {
        plain(v, digits, dec, sizeof dec);
        if (strtod(dec, NULL) == v && strlen(dec) <= strlen(sci) + 2) {
            fputs(dec, out);
            return;
        }
    }
    fputs(sci, out);
}

/* Binding strength, loosest first, as in the grammar (docs/language.md). */
enum { P_OR = 1, P_AND, P_CMP, P_ADD, P_MUL, P_UNARY, P_POW, P_PRIMARY };

static int binary_prec(OpKind op)
{
    switch (op) {
    case OP_OR: return P_OR;
    case OP_AND: return P_AND;
    case OP_ADD: case OP_SUB: return P_ADD;
    case OP_MUL: case OP_DIV: return P_MUL;
    case OP_POW: return P_POW;
    default: return P_CMP;
    }
}

static int prec(const Expr *e)
{
    switch (e->kind) {
    case EX_BINARY: return binary_prec(e->op);
    case EX_UNARY: return P_UNARY;
    case EX_NUM: return e->num < 0 ? P_UNARY : P_PRIMARY;
    default: return P_PRIMARY;
    }
}

/* n expressions separated by sep. */
static void print_joined(Expr *const *args, int n, const char *sep, FILE *out)
{
    for (int i = 0; i < n; i++) {
        if (i)
            fputs(sep, out);
        sph_print_expr(args[i], out);
    }
}

static void print_list(Expr *const *args, int n, FILE *out)
{
    print_joined(args, n, ", ", out);
}

static void print_operand(const Expr *e, int min_prec, FILE *out)
{
    int paren = prec(e) < min_prec;
    if (paren)
        fputc('(', out);
    sph_print_expr(e, out);
    if (paren)
        fputc(')', out);
}

static void print_binary(const Expr *e, FILE *out)
{
    int p = binary_prec(e->op);
    if (e->op == OP_POW) {
        print_operand(e->args[0], P_PRIMARY, out);
        fputc('^', out);
        print_operand(e->args[1], P_UNARY, out);
        return;
    }
    print_operand(e->args[0], p, out);
    fprintf(out, " %s ", op_spelling(e->op));
    print_operand(e->args[1], p + 1, out);
}

void sph_print_expr(const Expr *e, FILE *out)
{
    switch (e->kind) {
    case EX_NUM:
        print_num(e->num, out);
        return;
    case EX_NAME:
        fputs(e->name, out);
        return;
    case EX_SKIP:
        fputs("skip", out);
        return;
    case EX_VEC:
        fputc('[', out);
        print_list(e->args, e->nargs, out);
        fputc(']', out);
        return;
    case EX_CALL:
        fprintf(out, "%s(", e->name);
        print_list(e->args, e->nargs, out);
        fputc(')', out);
        return;
    case EX_UNARY:
        fputs(e->op == OP_NOT ? "not " : "-", out);
        print_operand(e->args[0], P_UNARY, out);
        return;
    case EX_BINARY:
        print_binary(e, out);
        return;
    }
}

/* ------------------------------------------------------------------ pieces */

/* A setting's text ("file") and values, the values separated by sep. */
static void print_values_sep(const Setting *s, const char *sep, FILE *out)
{
    if (s->text)
        fprintf(out, "\"%s\"", s->text);
    print_joined(s->values, s->nvalues, sep, out);
}

static void print_values(const Setting *s, FILE *out)
{
    print_values_sep(s, ", ", out);
}

/* name(key value ...): an argument of several values (the corners of a prism) lists them
 * after its key, separated by spaces. */
static void print_call(const NamedCall *c, const char *sep, FILE *out)
{
    fprintf(out, "%s(", c->name);
    for (int i = 0; i < c->args.n; i++) {
        fprintf(out, "%s%s ", i ? sep : "", c->args.items[i].key);
        print_values_sep(&c->args.items[i], " ", out);
    }
    fputc(')', out);
}

static void print_shape(const ShapeExpr *s, FILE *out)
{
    if (s->op == 0) {
        print_call(&s->prim, " ", out);
        return;
    }
    print_shape(s->lhs, out);
    fprintf(out, " %c ", s->op);
    if (s->rhs->op)
        fputc('(', out);
    print_shape(s->rhs, out);
    if (s->rhs->op)
        fputc(')', out);
}

static void print_comps(int comps, FILE *out)
{
    const char *sep = "";
    for (int a = 0; a < 3; a++)
        if (comps & (1 << a)) {
            fprintf(out, "%s%c", sep, "xyz"[a]);
            sep = ", ";
        }
}

static void print_bc(const BcDecl *bc, FILE *out)
{
    fprintf(out, "%s ", BC_KIND[bc->kind].written);
    print_comps(bc->comps, out);
    fputs(" = ", out);
    sph_print_expr(bc->value, out);
    if (bc->t_from) {
        fputs(" from ", out);
        sph_print_expr(bc->t_from, out);
    }
    if (bc->t_to) {
        fputs(" to ", out);
        sph_print_expr(bc->t_to, out);
    }
    if (bc->near) {
        fputs(" near ", out);
        print_shape(bc->near, out);
    }
}

static void print_points(Expr *const *p, FILE *out)
{
    for (int k = 0; k < 4; k++) {
        fputc(' ', out);
        sph_print_expr(p[k], out);
    }
}

static void print_body_item(const BodyItem *it, FILE *out)
{
    fputs("  ", out);
    switch (it->kind) {
    case BI_SHAPE:
        fputs("shape ", out);
        print_shape(it->shape, out);
        break;
    case BI_MATERIAL:
        fputs("material ", out);
        print_call(&it->material, ", ", out);
        break;
    case BI_SETTING:
        fprintf(out, "%s ", it->setting.key);
        print_values(&it->setting, out);
        break;
    case BI_BC:
        print_bc(&it->bc, out);
        break;
    case BI_MEASURE:
        fprintf(out, "measure %s plane", it->measure.name);
        print_points(it->measure.points, out);
        break;
    case BI_NOTCH:
        fputs("notch", out);
        print_points(it->measure.points, out);
        break;
    case BI_FRACTURE:
        print_call(&it->material, ", ", out);
        break;
    }
    fputc('\n', out);
}

/* ------------------------------------------------------------------ material laws */

static void print_stmts(const MatStmtList *l, int depth, FILE *out);

static void print_stmt(const MatStmt *s, int depth, FILE *out)
{
    static const char *const words[] = {"let", "stress", "energy", "state", "", "", "", "", ""};
    fprintf(out, "%*s", 2 * depth, "");
    switch (s->kind) {
    case MS_LET: case MS_STRESS: case MS_ENERGY: case MS_STATE:
        fprintf(out, "%s %s%s%s%s = ", words[s->kind], s->name, s->of ? "(" : "",
                s->of ? s->of : "", s->of ? ")" : "");
        sph_print_expr(s->value, out);
        fputc('\n', out);
        return;
    case MS_IF:
        fputs("if ", out);
        sph_print_expr(s->value, out);
        fputs(" {\n", out);
        print_stmts(&s->body, depth + 1, out);
        if (s->orelse.n) {
            fprintf(out, "%*s} else {\n", 2 * depth, "");
            print_stmts(&s->orelse, depth + 1, out);
        }
        fprintf(out, "%*s}\n", 2 * depth, "");
        return;
    case MS_DISSIPATION:
        fprintf(out, "dissipation %s\n", s->name);
        return;
    case MS_VISCOUSHEAT:
        fprintf(out, "viscousheat %s\n", s->name);
        return;
    case MS_WAVESPEED:
        fputs("wavespeed ", out);
        sph_print_expr(s->value, out);
        fputc('\n', out);
        return;
    case MS_TEMPERATURE:
        fprintf(out, "temperature %s, ", s->name);
        sph_print_expr(s->value, out);
        fputc('\n', out);
        return;
    case MS_REQUIRE:
        fputs("require ", out);
        sph_print_expr(s->value, out);
        if (s->message)
            fprintf(out, ", \"%s\"", s->message);
        fputc('\n', out);
        return;
    case MS_ASSIGN:
        fprintf(out, "%s = ", s->name);
        sph_print_expr(s->value, out);
        fputc('\n', out);
        return;
    case MS_BLOCK:
        fprintf(out, "%s {\n", s->name);
        print_stmts(&s->body, depth + 1, out);
        fprintf(out, "%*s}\n", 2 * depth, "");
        return;
    }
}

static void print_stmts(const MatStmtList *l, int depth, FILE *out)
{
    for (int i = 0; i < l->n; i++)
        print_stmt(&l->items[i], depth, out);
}

static void print_material(const MaterialDef *m, FILE *out)
{
    fprintf(out, "material %s(", m->name);
    for (int i = 0; i < m->nparams; i++)
        fprintf(out, "%s%s", i ? ", " : "", m->params[i]);
    fputs(") {\n", out);
    print_stmts(&m->body, 1, out);
    fputs("}\n", out);
}

/* ------------------------------------------------------------------ items */

static void print_expect(const ExpectDecl *x, FILE *out)
{
    static const char *const kinds[] = {"period", "amplitude"};
    if (x->kind == EXPECT_ENERGY) {
        fputs("expect energy within ", out);
    } else {
        if (x->kind == EXPECT_REFERENCE)
            fprintf(out, "reference %s.%s = ", x->measure, x->quantity);
        else
            fprintf(out, "expect %s %s.%s = ", kinds[x->kind], x->measure, x->quantity);
        if (x->file)
            fprintf(out, "file \"%s\"", x->file);
        else
            sph_print_expr(x->value, out);
        if (x->kind == EXPECT_REFERENCE && !x->tolerance) {
            fputc('\n', out);
            return;
        }
        fputs(" within ", out);
    }
    sph_print_expr(x->tolerance, out);
    fputs("%\n", out);
}

/* "name = value" of a let, in a malloc'ed string. */
static char *let_text(const Item *it)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f)
        return NULL;
    fprintf(f, "%s = ", it->name);
    sph_print_expr(it->value, f);
    fclose(f);
    return buf;
}

/* Consecutive lets from item i on, as one statement (wrapped after 80 columns); returns
 * the index of the next item. */
static int print_lets(const Item *items, int n, int i, FILE *out)
{
    size_t col = 4;
    fputs("let ", out);
    for (int k = i; k < n && items[k].kind == IT_LET; k++) {
        char *text = let_text(&items[k]);
        size_t len = text ? strlen(text) : 0;
        if (k > i && col + len + 2 > 80) {
            fputs(",\n    ", out);
            col = 4;
        } else if (k > i) {
            fputs(", ", out);
            col += 2;
        }
        fputs(text ? text : "", out);
        col += len;
        free(text);
    }
    fputc('\n', out);
    while (i < n && items[i].kind == IT_LET)
        i++;
    return i;
}

void sph_print_comment(const char *text, FILE *out)
{
    for (const char *s = text; s && *s;) {
        const char *end = strchr(s, '\n') ? strchr(s, '\n') : s + strlen(s);
        fprintf(out, "# %.*s\n", (int)(end - s), s);
        s = *end ? end + 1 : end;
    }
}

static void print_body(const BodyDecl *b, FILE *out)
{
    sph_print_comment(b->comment, out);
    fprintf(out, "body %s {\n", b->name);
    for (int i = 0; i < b->n; i++)
        print_body_item(&b->items[i], out);
    fputs("}\n", out);
}

static void print_scene(const SettingList *l, FILE *out)
{
    fputs("scene {\n", out);
    for (int i = 0; i < l->n; i++) {
        fprintf(out, "  %s ", l->items[i].key);
        print_values(&l->items[i], out);
        fputc('\n', out);
    }
    fputs("}\n", out);
}

/* Prints item i (and the lets after it); returns the index of the next item. */
static int print_item(const Item *items, int n, int i, FILE *out)
{
    const Item *it = &items[i];
    switch (it->kind) {
    case IT_IMPORT:
        fprintf(out, "import %s\n", it->name);
        break;
    case IT_SCENE:
        print_scene(&it->scene, out);
        break;
    case IT_LET:
        return print_lets(items, n, i, out);
    case IT_FN:
        fprintf(out, "fn %s(", it->name);
        for (int k = 0; k < it->nparams; k++)
            fprintf(out, "%s%s", k ? ", " : "", it->params[k]);
        fputs(") = ", out);
        sph_print_expr(it->value, out);
        fputc('\n', out);
        break;
    case IT_MATERIAL:
        print_material(&it->material, out);
        break;
    case IT_BODY:
        print_body(&it->body, out);
        break;
    case IT_EXPECT:
        print_expect(&it->expect, out);
        break;
    }
    return i + 1;
}

static int from_main_file(const Program *p, const Item *it)
{
    return !it->loc.file || !p->file || strcmp(it->loc.file, p->file) == 0;
}

void sph_print_program(const Program *p, FILE *out)
{
    ItemKind last = IT_IMPORT;
    int first = 1;
    for (int i = 0; i < p->n;) {
        const Item *it = &p->items[i];
        if (!from_main_file(p, it)) {
            i++;
            continue;
        }
        /* a blank line between groups, and around blocks */
        if (!first && (it->kind != last || it->kind == IT_BODY || it->kind == IT_MATERIAL ||
                       it->kind == IT_SCENE))
            fputc('\n', out);
        first = 0;
        last = it->kind;
        i = print_item(p->items, p->n, i, out);
    }
}
