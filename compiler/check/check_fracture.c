/* check_fracture.c — checking a body's phase-field fracture: the fracture(...) item, its
 * notches and the restriction of the phase field (paper section 2.2 and 3.3.1).
 *
 *   fracture(Gc 3, length 0.125e-3, limit 0.1)   Gc > 0, length > 0, 0 <= limit < 1
 *   notch [p1] [p2] [p3] [p4]                     any number, each a quad
 *   restrict <expr>                                lower bound of s; skip = no bound
 *
 * Notches and the restriction need fracture; fracture needs a material law with a
 * `tension` block (the tensile parts psi+ and S+ of eq. 11-17 or 20-31). */
#include <stdlib.h>
#include <string.h>

#include "check_expr.h"
#include "check_fracture.h"
#include "quad.h"
#include "model/admissible.h"
#include "util/diag.h"

/* The phase-field limit s_l when a model does not give one (paper eq. 63). */
#define DEFAULT_LIMIT 0.1

static const Setting *find(const NamedCall *c, const char *key)
{
    return ast_find_setting(&c->args, key);
}

static int arg_names(const NamedCall *c)
{
    static const char *const known[] = {"Gc", "length", "limit"};
    int bad = 0;
    for (int i = 0; i < c->args.n; i++) {
        const Setting *s = &c->args.items[i];
        int ok = 0;
        for (size_t k = 0; k < sizeof known / sizeof known[0]; k++)
            ok |= !strcmp(s->key, known[k]);
        if (!ok) {
            diag_error(s->loc, "unknown argument '%s' of fracture() (expected Gc, length or "
                               "limit)",
                       s->key);
            bad = 1;
        } else if (s->text || s->nvalues != 1) {
            diag_error(s->loc, "argument '%s' of fracture() takes one number", s->key);
            bad = 1;
        } else if (find(c, s->key) != s) {
            diag_error(s->loc, "argument '%s' of fracture() given twice", s->key);
            bad = 1;
        }
    }
    return bad ? -1 : 0;
}

static int positive_arg(const Model *m, const NamedCall *c, const char *key, Quantity q,
                        const char *what, double *out)
{
    const Setting *s = find(c, key);
    if (!s) {
        diag_error(c->loc, "fracture() needs '%s' (%s)", key, what);
        return -1;
    }
    if (check_const_expr(m, s->values[0], key, out))
        return -1;
    return check_admissible(s->values[0]->loc, key, q, *out);
}

static int check_call(const Model *m, const BodyItem *it, FractureModel *f)
{
    const NamedCall *c = &it->material;
    if (f->on) {
        diag_error(it->loc, "fracture given twice for this body");
        return -1;
    }
    f->on = 1;
    f->loc = it->loc;
    f->limit = DEFAULT_LIMIT;
    if (arg_names(c))
        return -1;
    int bad = positive_arg(m, c, "Gc", Q_GC, "the critical energy release rate, J/m^2",
                           &f->Gc);
    bad |= positive_arg(m, c, "length", Q_LENGTH, "the phase-field length scale epsilon0",
                        &f->eps0);
    const Setting *l = find(c, "limit");
    if (l && !check_const_expr(m, l->values[0], "limit", &f->limit) &&
        check_admissible(l->values[0]->loc, "the phase-field limit", Q_LIMIT, f->limit))
        bad = 1;
    return bad ? -1 : 0;
}

static int check_notch(const Model *m, const BodyItem *it, FractureModel *f)
{
    double q[4][3];
    int bad = 0;
    for (int k = 0; k < 4; k++)
        bad |= check_vec3(m, it->measure.points[k], "a notch corner", q[k]);
    if (bad || quad_spans((const double(*)[3])q, it->loc, "notch"))
        return -1;
    f->notches = realloc(f->notches, (size_t)(f->nnotches + 1) * sizeof *f->notches);
    f->notch_locs = realloc(f->notch_locs, (size_t)(f->nnotches + 1) * sizeof *f->notch_locs);
    f->notch_locs[f->nnotches] = it->loc;
    memcpy(f->notches[f->nnotches++], q, sizeof q);
    return 0;
}

static int check_restrict(const Model *m, const Setting *s, FractureModel *f)
{
    if (s->nvalues != 1) {
        diag_error(s->loc, "'restrict' takes one expression, the lower bound of the phase field");
        return -1;
    }
    if (f->restrict_expr) {
        diag_error(s->loc, "'restrict' given twice for this body");
        return -1;
    }
    ExprScope scope = {m, NULL, 0, 1, 1, "a phase-field restriction"};
    if (check_scalar_expr(&scope, s->values[0], 1))
        return -1;
    f->restrict_expr = s->values[0];
    f->restrict_loc = s->loc;
    return 0;
}

int check_fracture_item(const Model *m, const BodyItem *it, FractureModel *f)
{
    if (it->kind == BI_FRACTURE)
        return check_call(m, it, f);
    if (it->kind == BI_NOTCH)
        return check_notch(m, it, f);
    return check_restrict(m, &it->setting, f);
}

static int has_tension(const MaterialDef *law)
{
    for (int i = 0; i < law->body.n; i++)
        if (law->body.items[i].kind == MS_BLOCK && !strcmp(law->body.items[i].name, "tension"))
            return 1;
    return 0;
}

int check_fracture_body(const BodyModel *b, const BodyDecl *d)
{
    const FractureModel *f = &b->fracture;
    if (!f->on) {
        for (int i = 0; i < d->n; i++) {
            const BodyItem *it = &d->items[i];
            if (it->kind == BI_NOTCH ||
                (it->kind == BI_SETTING && !strcmp(it->setting.key, "restrict"))) {
                diag_error(it->loc, "%s needs fracture (add fracture(Gc ..., length ...) to "
                                    "body '%s')",
                           it->kind == BI_NOTCH ? "a notch" : "'restrict'", b->name);
                return -1;
            }
        }
        return 0;
    }
    for (int i = 0; b->law && i < b->law->body.n; i++)
        if (b->law->body.items[i].kind == MS_STATE) {
            diag_error(f->loc, "fracture cannot be combined with material '%s', which has state "
                               "(plasticity): the paper's phase field is for elastic materials "
                               "only (section 2.3.3, remark 3)",
                       b->law->name);
            return -1;
        }
    if (b->law && !has_tension(b->law)) {
        diag_error(f->loc, "fracture needs the tensile part of the material: material '%s' has "
                           "no 'tension { energy ...; stress ... }' block",
                   b->law->name);
        return -1;
    }
    return 0;
}
