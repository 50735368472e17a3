/* xml_fracture.c — the phase-field fracture cards of a body (paper section 3.3.1).
 *
 *   <fracture value="1"/>                  fracture(Gc 3, length 0.00012501, limit 0.05)
 *   <Gc value="3.0"/>                        Gc      (required with fracture)
 *   <pflenscale value="0.12501e-3"/>         length  (required with fracture)
 *   <pflim value="0.05"/>                    limit   (default 0.05, written explicitly)
 *   <notch> <p1 x y z/> .. <p4/> </notch>  notch [p1] [p2] [p3] [p4]     (any number)
 *   <restrictphi value="1"/>               restrict <user expression 1>
 *
 * The limit is always written: SoliDualSPHysics' default is 0.05 where the sph language's
 * is 0.1, and the imported model must mean what SoliDualSPHysics does.  Every item is
 * located at its card.  Whether fracture is on, and what happens to the cards when it is
 * off, is decided in xml_deform.c. */
#include <stdio.h>

#include "util/diag.h"
#include "xml_internal.h"

/* SoliDualSPHysics' phase-field limit when <pflim> is absent. */
#define SDSPH_DEFAULT_LIMIT 0.05

static const char *const NUMBER_CARDS[XF_N] = {"Gc", "pflenscale", "pflim"};
static const char *const NUMBER_ARGS[XF_N] = {"Gc", "length", "limit"};
static const Quantity NUMBER_RULES[XF_N] = {Q_GC, Q_LENGTH, Q_LIMIT};

/* <notch>: the quad as a BI_NOTCH item, each corner located at its <pK>. */
static int notch(const XmlCtx *x, const xmlNode *n, XmlFracture *f)
{
    static const char *const corners[] = {"p1", "p2", "p3", "p4", NULL};
    static const char *const none[] = {NULL};
    BodyItem it = {0};
    it.kind = BI_NOTCH;
    it.loc = it.measure.loc = xml_loc(x, n);
    int bad = xml_check_attrs(x, n, none) != 0;
    bad |= xml_check_children(x, n, corners) != 0;
    for (int k = 0; corners[k]; k++) {
        const xmlNode *p = xml_child(n, corners[k]);
        double q[3];
        if (!p) {
            diag_error(it.loc, "<notch> needs <%s>", corners[k]);
            bad = 1;
            continue;
        }
        if (xml_point(x, p, q)) {
            bad = 1;
            continue;
        }
        SrcLoc pl = xml_loc(x, p);
        Expr **v = NULL;
        int nv = 0;
        for (int a = 0; a < 3; a++)
            ast_push_expr(&v, &nv, ast_num(pl, q[a]));
        it.measure.points[k] = ast_vec(pl, v, nv);
    }
    if (bad)
        return -1;
    f->notches = ast_room(f->notches, (size_t)f->nnotches, sizeof *f->notches);
    f->notches[f->nnotches++] = it;
    return 0;
}

/* <restrictphi value="ID"/>: names a <userexpression>. */
static int restrictphi(const XmlCtx *x, const xmlNode *n, XmlFracture *f)
{
    static const char *const value[] = {"value", NULL};
    long id;
    if (xml_check_attrs(x, n, value) || xml_integer(x, n, "value", 1, 0, 1000000000, &id) != 1)
        return -1;
    if (!xml_user_expr(x, id)) {
        diag_error(xml_loc(x, n), "<restrictphi> attribute 'value': expression %ld is not "
                                  "defined in <mathexpressions>", id);
        return -1;
    }
    f->restrict_card = n;
    f->restrict_id = id;
    return 0;
}

int xml_fracture_card(const XmlCtx *x, const xmlNode *n, XmlFracture *f)
{
    int k = 0;
    while (k < XF_N && !xml_is(n, NUMBER_CARDS[k]))
        k++;
    if (k == XF_N && !xml_is(n, "notch") && !xml_is(n, "restrictphi"))
        return 1;
    f->first = f->first ? f->first : n;
    if (k < XF_N) {
        f->card[k] = n;
        return xml_card_admissible(x, n, NUMBER_RULES[k], &f->value[k]);
    }
    return xml_is(n, "notch") ? notch(x, n, f) : restrictphi(x, n, f);
}

int xml_fracture_check(const XmlCtx *x, const XmlFracture *f, const xmlNode *fracture, int mk)
{
    static const char *const what[] = {"the critical energy release rate, J/m^2",
                                       "the phase-field length scale, m"};
    int bad = 0;
    for (int k = XF_GC; k <= XF_LENGTH; k++)
        if (!f->card[k]) {
            diag_error(xml_loc(x, fracture), "<fracture>: fracture of <deformstrucbody "
                       "mkbound=\"%d\"> needs <%s value=\"...\"/> (%s)", mk, NUMBER_CARDS[k],
                       what[k]);
            bad = 1;
        }
    return bad ? -1 : 0;
}

void xml_fracture_items(const XmlCtx *x, const XmlFracture *f, const xmlNode *fracture,
                        BodyDecl *b)
{
    BodyItem it = {0};
    it.kind = BI_FRACTURE;
    it.loc = xml_loc(x, fracture);
    it.material.name = ast_strdup("fracture");
    it.material.loc = it.loc;
    for (int k = 0; k < XF_N; k++) {
        SrcLoc loc = f->card[k] ? xml_loc(x, f->card[k]) : it.loc;
        double v = f->card[k] ? f->value[k] : SDSPH_DEFAULT_LIMIT;
        ast_push_setting(&it.material.args, ast_setting(loc, NUMBER_ARGS[k], ast_num(loc, v)));
    }
    ast_push_bodyitem(b, it);
    if (f->restrict_card) {
        BodyItem r = {0};
        r.kind = BI_SETTING;
        r.loc = xml_loc(x, f->restrict_card);
        r.setting = ast_setting(r.loc, "restrict", xml_user_expr(x, f->restrict_id)->value);
        ast_push_bodyitem(b, r);
    }
    for (int i = 0; i < f->nnotches; i++)
        ast_push_bodyitem(b, f->notches[i]);
}
