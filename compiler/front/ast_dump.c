/* ast_dump.c — the syntax tree as indented S-expressions (sphc --dump=ast).
 *
 *   (program
 *     (scene
 *       (dimension 2))
 *     (let L0 0.2)
 *     (body beam
 *       (shape (- (box (from [-0.002 0 0]) (to [0.2 0 0.02])) (sphere ...)))
 *       (velocity z (if (<= x0 0) 0 skip)))
 *     (expect period tip.uz 0.2553 (within 3)))
 *
 * Expressions are fully parenthesised and printed on one line: (+ 1 (* 2 x)),
 * a call is (name args...), a vector [a b c], unary minus (- a). */
#include <stdio.h>
#include <stdlib.h>

#include "ast.h"
#include "lang/bc_kinds.h"

static void indent(FILE *out, int depth)
{
    fprintf(out, "\n%*s", 2 * depth, "");
}

/* Shortest %g form that reads back as the same double. */
static void dump_num(double v, FILE *out)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.15g", v);
    if (strtod(buf, NULL) != v)
        snprintf(buf, sizeof buf, "%.17g", v);
    fputs(buf, out);
}

void ast_dump_expr(const Expr *e, FILE *out)
{
    if (!e) {
        fputs("<null>", out);
        return;
    }
    switch (e->kind) {
    case EX_NUM:
        dump_num(e->num, out);
        return;
    case EX_NAME:
        fputs(e->name, out);
        return;
    case EX_SKIP:
        fputs("skip", out);
        return;
    case EX_VEC:
        fputc('[', out);
        for (int i = 0; i < e->nargs; i++) {
            if (i)
                fputc(' ', out);
            ast_dump_expr(e->args[i], out);
        }
        fputc(']', out);
        return;
    case EX_UNARY:
    case EX_BINARY:
        fprintf(out, "(%s", op_spelling(e->op));
        break;
    case EX_CALL:
        fprintf(out, "(%s", e->name);
        break;
    default:
        fprintf(out, "<expr kind %d>", (int)e->kind);
        return;
    }
    for (int i = 0; i < e->nargs; i++) {
        fputc(' ', out);
        ast_dump_expr(e->args[i], out);
    }
    fputc(')', out);
}

static void dump_setting(const Setting *s, FILE *out)
{
    fprintf(out, "(%s", s->key);
    if (s->text)
        fprintf(out, " \"%s\"", s->text);
    for (int i = 0; i < s->nvalues; i++) {
        fputc(' ', out);
        ast_dump_expr(s->values[i], out);
    }
    fputc(')', out);
}

static void dump_call(const NamedCall *c, FILE *out)
{
    fprintf(out, "(%s", c->name);
    for (int i = 0; i < c->args.n; i++) {
        fputc(' ', out);
        dump_setting(&c->args.items[i], out);
    }
    fputc(')', out);
}

static void dump_shape(const ShapeExpr *s, FILE *out)
{
    if (!s) {
        fputs("<null>", out);
        return;
    }
    if (s->op == 0) {
        dump_call(&s->prim, out);
        return;
    }
    fprintf(out, "(%c ", s->op);
    dump_shape(s->lhs, out);
    fputc(' ', out);
    dump_shape(s->rhs, out);
    fputc(')', out);
}

static void dump_matstmts(const MatStmtList *l, FILE *out, int depth);

static void dump_matstmt(const MatStmt *m, FILE *out, int depth)
{
    static const char *const words[] = { "let", "stress", "energy", "state", "", "", "", "", "" };
    indent(out, depth);
    switch (m->kind) {
    case MS_LET:
    case MS_STRESS:
    case MS_ENERGY:
    case MS_STATE:
        fprintf(out, "(%s %s%s%s%s ", words[m->kind], m->name, m->of ? "(" : "",
                m->of ? m->of : "", m->of ? ")" : "");
        ast_dump_expr(m->value, out);
        fputc(')', out);
        break;
    case MS_IF:
        fputs("(if ", out);
        ast_dump_expr(m->value, out);
        indent(out, depth + 1);
        fputs("(then", out);
        dump_matstmts(&m->body, out, depth + 2);
        fputc(')', out);
        if (m->orelse.n > 0) {
            indent(out, depth + 1);
            fputs("(else", out);
            dump_matstmts(&m->orelse, out, depth + 2);
            fputc(')', out);
        }
        fputc(')', out);
        break;
    case MS_DISSIPATION:
        fprintf(out, "(dissipation %s)", m->name);
        break;
    case MS_VISCOUSHEAT:
        fprintf(out, "(viscousheat %s)", m->name);
        break;
    case MS_WAVESPEED:
        fputs("(wavespeed ", out);
        ast_dump_expr(m->value, out);
        fputc(')', out);
        break;
    case MS_TEMPERATURE:
        fprintf(out, "(temperature %s ", m->name);
        ast_dump_expr(m->value, out);
        fputc(')', out);
        break;
    case MS_REQUIRE:
        fputs("(require ", out);
        ast_dump_expr(m->value, out);
        if (m->message)
            fprintf(out, " \"%s\"", m->message);
        fputc(')', out);
        break;
    case MS_ASSIGN:
        fprintf(out, "(= %s ", m->name);
        ast_dump_expr(m->value, out);
        fputc(')', out);
        break;
    case MS_BLOCK:
        fprintf(out, "(block %s", m->name);
        dump_matstmts(&m->body, out, depth + 1);
        fputc(')', out);
        break;
    }
}

static void dump_matstmts(const MatStmtList *l, FILE *out, int depth)
{
    for (int i = 0; i < l->n; i++)
        dump_matstmt(&l->items[i], out, depth);
}

static void dump_comps(int mask, FILE *out)
{
    const char *sep = "";
    for (int b = 0; b < 3; b++)
        if (mask & (1 << b)) {
            fprintf(out, "%s%c", sep, "xyz"[b]);
            sep = ",";
        }
    if (!mask)
        fputs("<none>", out);
}

static void dump_bc(const BcDecl *bc, FILE *out)
{
    fprintf(out, "(%s ", BC_KIND[bc->kind].written);
    dump_comps(bc->comps, out);
    fputc(' ', out);
    ast_dump_expr(bc->value, out);
    if (bc->t_from) {
        fputs(" (from ", out);
        ast_dump_expr(bc->t_from, out);
        fputc(')', out);
    }
    if (bc->t_to) {
        fputs(" (to ", out);
        ast_dump_expr(bc->t_to, out);
        fputc(')', out);
    }
    if (bc->near) {
        fputs(" (near ", out);
        dump_shape(bc->near, out);
        fputc(')', out);
    }
    fputc(')', out);
}

static void dump_points(const MeasureDecl *m, FILE *out)
{
    for (int i = 0; i < 4; i++) {
        fputc(' ', out);
        ast_dump_expr(m->points[i], out);
    }
}

static void dump_bodyitem(const BodyItem *b, FILE *out, int depth)
{
    indent(out, depth);
    switch (b->kind) {
    case BI_SHAPE:
        fputs("(shape ", out);
        dump_shape(b->shape, out);
        fputc(')', out);
        break;
    case BI_MATERIAL:
        fputs("(material ", out);
        dump_call(&b->material, out);
        fputc(')', out);
        break;
    case BI_SETTING:
        dump_setting(&b->setting, out);
        break;
    case BI_BC:
        dump_bc(&b->bc, out);
        break;
    case BI_MEASURE:
        fprintf(out, "(measure %s plane", b->measure.name);
        dump_points(&b->measure, out);
        fputc(')', out);
        break;
    case BI_NOTCH:
        fputs("(notch", out);
        dump_points(&b->measure, out);
        fputc(')', out);
        break;
    case BI_FRACTURE:
        dump_call(&b->material, out);
        break;
    }
}

static void dump_expect(const ExpectDecl *x, FILE *out)
{
    static const char *const kinds[] = { "period", "amplitude", "energy", "reference" };
    fprintf(out, "(%s%s", x->kind == EXPECT_REFERENCE ? "" : "expect ", kinds[x->kind]);
    if (x->measure)
        fprintf(out, " %s.%s", x->measure, x->quantity ? x->quantity : "?");
    if (x->value) {
        fputc(' ', out);
        ast_dump_expr(x->value, out);
    }
    if (x->tolerance) {
        fputs(" (within ", out);
        ast_dump_expr(x->tolerance, out);
        fputc(')', out);
    }
    fputc(')', out);
}

static void dump_item(const Item *it, FILE *out)
{
    indent(out, 1);
    switch (it->kind) {
    case IT_IMPORT:
        fprintf(out, "(import %s)", it->name);
        break;
    case IT_SCENE:
        fputs("(scene", out);
        for (int i = 0; i < it->scene.n; i++) {
            indent(out, 2);
            dump_setting(&it->scene.items[i], out);
        }
        fputc(')', out);
        break;
    case IT_LET:
        fprintf(out, "(let %s ", it->name);
        ast_dump_expr(it->value, out);
        fputc(')', out);
        break;
    case IT_FN:
        fprintf(out, "(fn %s (", it->name);
        for (int i = 0; i < it->nparams; i++)
            fprintf(out, "%s%s", i ? " " : "", it->params[i]);
        fputs(") ", out);
        ast_dump_expr(it->value, out);
        fputc(')', out);
        break;
    case IT_MATERIAL:
        fprintf(out, "(material %s (", it->material.name);
        for (int i = 0; i < it->material.nparams; i++)
            fprintf(out, "%s%s", i ? " " : "", it->material.params[i]);
        fputc(')', out);
        dump_matstmts(&it->material.body, out, 2);
        fputc(')', out);
        break;
    case IT_BODY:
        fprintf(out, "(body %s", it->body.name);
        for (int i = 0; i < it->body.n; i++)
            dump_bodyitem(&it->body.items[i], out, 2);
        fputc(')', out);
        break;
    case IT_EXPECT:
        dump_expect(&it->expect, out);
        break;
    }
}

void ast_dump(const Program *p, FILE *out)
{
    fputs("(program", out);
    for (int i = 0; i < p->n; i++)
        dump_item(&p->items[i], out);
    fputs(")\n", out);
}
