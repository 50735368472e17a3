/* xml_deform.c — <deformstrucs>: one sph body per <deformstrucbody mkbound="N">.
 *
 *   <deformstrucbody mkbound="1">          body mk1 { shape <what mk 1 was drawn as>
 *     <mapfac value="4"/>                    refine 4
 *     <nbsrange value="1"/>                  nbsrange 1
 *     <density value="1000"/>                material svk(density 1000,
 *     <u_mu value=".."/> <u_bulk value=".."/>                 shear .., bulk ..)
 *     <constitmodel value="1"/>              the law and its own cards: LAWS below
 *     <artvisc factor1=".." factor2=".."/>   viscosity .., ..   (default 0.2, 0)
 *     <fracture value="1"/> <Gc ../> ..      fracture(..), notch .., restrict ..  (xml_fracture.c)
 *     <bcvel ../> <bcforce ../>              velocity .. / force ..  (xml_bc.c)
 *     <measureplane> ..                      measure planeK plane ..  (xml_bc.c)
 *   </deformstrucbody>
 *
 * Elastic constants: youngmod + poissratio, u_lambda + u_mu or u_bulk + u_mu, where u_bulk
 * is the three-dimensional bulk modulus (the sph language's `bulk`, also in 2D); with
 * --xml-elastic2d=sdsph a 2D case's constants are those of 2D elasticity, as
 * SoliDualSPHysics reads them (elastic_args_2d).
 * Contact: <contcoeff> (in <deformstrucs>) is the scene's `contact` multiplier, <restcoef>
 * and <kfric> the body's `restitution` and `friction`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "model/elastic.h"
#include "xml_internal.h"

enum { EL_E, EL_NU, EL_LAMBDA, EL_MU, EL_K, EL_N };

/* The cards of one body that are not boundary conditions or measurements. */
typedef struct {
    int mk;
    SrcLoc loc;
    int has_density, has_el[EL_N], has_visc, has_nbs, fracture;
    double density, el[EL_N], beta1, beta2;
    SrcLoc density_loc, el_loc[EL_N], model_loc, visc_loc, refine_loc, nbs_loc;
    long model, refine, nbsrange;
    const xmlNode *fracture_card;  /* the last <fracture> */
    const xmlNode *law_card;       /* the first card of a law's own parameters */
    int has_param[XML_NLAWS + 1][XML_LAW_CARDS]; /* by law: its own cards' values */
    double param[XML_NLAWS + 1][XML_LAW_CARDS];
    SrcLoc param_loc[XML_NLAWS + 1][XML_LAW_CARDS];
    int has_rest, has_fric;        /* contact: <restcoef>, <kfric> */
    double rest, fric;
    SrcLoc rest_loc, fric_loc;
    XmlFracture frac;
} Cards;

static const char *const ELASTIC_CARDS[EL_N] = {"youngmod", "poissratio", "u_lambda", "u_mu",
                                                "u_bulk"};
static const char *const ELASTIC_ARGS[EL_N] = {"young", "poisson", "lambda", "shear", "bulk"};

/* <constitmodel value="N"> is LAWS[N - 1]. */
static const XmlLaw LAWS[XML_NLAWS] = {
    {"svk", NULL, {NULL}, {NULL}, 0},
    {"neohookean", NULL, {NULL}, {NULL}, 0},
    {"j2", "J2 plasticity", {"yieldstress", "hardening"}, {"yield", "hardening"}, 1},
};

const XmlLaw *xml_law(int n)
{
    return &LAWS[n - 1];
}

/* The index of n among the own cards of law number `law`, or -1. */
static int own_card(int law, const xmlNode *n)
{
    for (int i = 0; i < XML_LAW_CARDS && LAWS[law - 1].cards[i]; i++)
        if (xml_is(n, LAWS[law - 1].cards[i]))
            return i;
    return -1;
}

/* The first law that has n as its own card, or 0. */
static int card_law(const xmlNode *n)
{
    for (int k = 1; k <= XML_NLAWS; k++)
        if (own_card(k, n) >= 0)
            return k;
    return 0;
}

/* The value of a law's own card must not be negative. */
static int nonnegative(const XmlCtx *x, const xmlNode *n, double v)
{
    if (v >= 0)
        return 0;
    diag_error(xml_loc(x, n), "<%s> attribute 'value': must not be negative (got %g)",
               xml_name(n), v);
    return -1;
}

static int artvisc(const XmlCtx *x, const xmlNode *n, Cards *c)
{
    static const char *const attrs[] = {"factor1", "factor2", NULL};
    if (xml_check_attrs(x, n, attrs))
        return -1;
    if (xml_number(x, n, "factor1", 0, &c->beta1) < 0 ||
        xml_number(x, n, "factor2", 0, &c->beta2) < 0)
        return -1;
    c->has_visc = 1;
    c->visc_loc = xml_loc(x, n);
    return xml_admissible(x, n, "factor1", Q_VISCOSITY, c->beta1) ||
           xml_admissible(x, n, "factor2", Q_VISCOSITY, c->beta2) ? -1 : 0;
}

static int elastic_card(const XmlCtx *x, const xmlNode *n, Cards *c)
{
    for (int k = 0; k < EL_N; k++)
        if (xml_is(n, ELASTIC_CARDS[k])) {
            c->has_el[k] = 1;
            c->el_loc[k] = xml_loc(x, n);
            return xml_card_number(x, n, &c->el[k]);
        }
    return 1;
}

static int whole_card(const XmlCtx *x, const xmlNode *n, long lo, long hi, long *v)
{
    static const char *const value[] = {"value", NULL};
    if (xml_check_attrs(x, n, value))
        return -1;
    return xml_integer(x, n, "value", 1, lo, hi, v) == 1 ? 0 : -1;
}

/* A card of a law's own parameters (LAWS), kept for every law that has it; 1 when n is
 * none. */
static int law_param_card(const XmlCtx *x, const xmlNode *n, Cards *c)
{
    double v;
    if (!card_law(n))
        return 1;
    c->law_card = c->law_card ? c->law_card : n;
    if (xml_card_number(x, n, &v) || nonnegative(x, n, v))
        return -1;
    for (int k = 1; k <= XML_NLAWS; k++) {
        const int i = own_card(k, n);
        if (i < 0)
            continue;
        c->has_param[k][i] = 1;
        c->param[k][i] = v;
        c->param_loc[k][i] = xml_loc(x, n);
    }
    return 0;
}

/* Cards of fracture (phase field), the laws and contact: checked, and kept for
 * special_models(); 1 when n is none of them. */
static int other_card(XmlCtx *x, const xmlNode *n, Cards *c)
{
    if (xml_is(n, "fracture")) {
        c->fracture_card = n;
        return xml_card_bool(x, n, &c->fracture);
    }
    if (xml_is(n, "restcoef")) {
        c->has_rest = 1;
        c->rest_loc = xml_loc(x, n);
        return xml_card_admissible(x, n, Q_RESTITUTION, &c->rest);
    }
    if (xml_is(n, "kfric")) {
        c->has_fric = 1;
        c->fric_loc = xml_loc(x, n);
        return xml_card_admissible(x, n, Q_FRICTION, &c->fric);
    }
    const int r = law_param_card(x, n, c);
    return r <= 0 ? r : xml_fracture_card(x, n, &c->frac);
}

/* One card of pass 1; 1 when it is not one of these cards. */
static int card(XmlCtx *x, const xmlNode *n, Cards *c)
{
    int r = elastic_card(x, n, c);
    if (r <= 0)
        return r;
    if (xml_is(n, "density")) {
        c->has_density = 1;
        c->density_loc = xml_loc(x, n);
        return xml_card_admissible(x, n, Q_DENSITY, &c->density);
    }
    if (xml_is(n, "constitmodel")) {
        c->model_loc = xml_loc(x, n);
        return whole_card(x, n, 1, XML_NLAWS, &c->model);
    }
    if (xml_is(n, "artvisc"))
        return artvisc(x, n, c);
    if (xml_is(n, "avfactor")) {
        c->has_visc = 1;
        c->visc_loc = xml_loc(x, n);
        return xml_card_admissible(x, n, Q_VISCOSITY, &c->beta1);
    }
    if (xml_is(n, "mapfac")) {
        c->refine_loc = xml_loc(x, n);
        return whole_card(x, n, 1, SETTING_INT_MAX, &c->refine);
    }
    if (xml_is(n, "nbsrange")) {
        c->has_nbs = 1;
        c->nbs_loc = xml_loc(x, n);
        return whole_card(x, n, 1, SETTING_INT_MAX, &c->nbsrange);
    }
    return other_card(x, n, c);
}

/* ------------------------------------------------------------------ checks */

/* One of youngmod + poissratio, u_lambda + u_mu, u_bulk + u_mu. */
static int elastic_option(const Cards *c)
{
    const int *h = c->has_el;
    int opt_e = h[EL_E] || h[EL_NU], opt_l = h[EL_LAMBDA], opt_k = h[EL_K];
    if (opt_e + opt_l + opt_k > 1 || (opt_e && h[EL_MU])) {
        diag_error(c->loc, "<deformstrucbody mkbound=\"%d\">: elastic constants given more than "
                           "once (use one of youngmod + poissratio, u_lambda + u_mu, u_bulk + "
                           "u_mu)", c->mk);
        return -1;
    }
    if (opt_e && !(h[EL_E] && h[EL_NU])) {
        int k = h[EL_E] ? EL_E : EL_NU;
        diag_error(c->el_loc[k], "<%s> needs <%s>", ELASTIC_CARDS[k],
                   ELASTIC_CARDS[k == EL_E ? EL_NU : EL_E]);
        return -1;
    }
    if ((opt_l || opt_k) && !h[EL_MU]) {
        int k = opt_l ? EL_LAMBDA : EL_K;
        diag_error(c->el_loc[k], "<%s> needs <u_mu>", ELASTIC_CARDS[k]);
        return -1;
    }
    if (h[EL_MU] && !opt_l && !opt_k) {
        diag_error(c->el_loc[EL_MU], "<u_mu> needs <u_lambda> or <u_bulk>");
        return -1;
    }
    if (!opt_e && !opt_l && !opt_k) {
        diag_error(c->loc, "<deformstrucbody mkbound=\"%d\"> needs elastic constants: "
                           "<youngmod> and <poissratio>, <u_lambda> and <u_mu>, or <u_bulk> "
                           "and <u_mu>", c->mk);
        return -1;
    }
    return 0;
}

/* The law's own cards are required (J2 plasticity: <yieldstress>, <hardening>); those of
 * other laws are ignored with a warning.  Where SoliDualSPHysics turns fracture off under
 * the law, so does the importer, with a warning.  Fracture needs its cards
 * (xml_fracture_check); without it they are ignored with a warning. */
static int special_models(const XmlCtx *x, Cards *c)
{
    const int m = (int)c->model;
    const XmlLaw *law = xml_law(m);
    for (int i = 0; i < XML_LAW_CARDS && law->cards[i]; i++)
        if (!c->has_param[m][i]) {
            diag_error(c->model_loc, "<constitmodel value=\"%d\">: %s of <deformstrucbody "
                       "mkbound=\"%d\"> needs <%s value=\"...\"/>", m, law->what, c->mk,
                       law->cards[i]);
            return -1;
        }
    if (c->law_card && own_card(m, c->law_card) < 0) {
        const int k = card_law(c->law_card);
        diag_warning(xml_loc(x, c->law_card), "<%s> is ignored: only %s (<constitmodel "
                     "value=\"%d\"/>) uses it", xml_name(c->law_card), xml_law(k)->what, k);
    }
    if (law->no_fracture) {
        if (c->fracture)
            diag_warning(xml_loc(x, c->fracture_card), "<fracture> is ignored with %s "
                         "(<constitmodel value=\"%d\"/>), as SoliDualSPHysics does", law->what,
                         m);
        c->fracture = 0;
        return 0;
    }
    if (c->fracture)
        return xml_fracture_check(x, &c->frac, c->fracture_card, c->mk);
    if (c->frac.first)
        diag_warning(xml_loc(x, c->frac.first), "<%s> is ignored without <fracture "
                     "value=\"true\"/>", xml_name(c->frac.first));
    return 0;
}

/* ------------------------------------------------------------------ the body */

static void push_item(BodyDecl *b, BodyItemKind kind, SrcLoc loc, Setting s)
{
    BodyItem it = {0};
    it.kind = kind;
    it.loc = loc;
    it.setting = s;
    ast_push_bodyitem(b, it);
}

static void push_setting(BodyDecl *b, SrcLoc loc, const char *key, double v)
{
    push_item(b, BI_SETTING, loc, ast_setting(loc, key, ast_num(loc, v)));
}

/* --xml-elastic2d=sdsph in a 2D case: the cards are the constants of two-dimensional
 * elasticity, as SoliDualSPHysics reads them (its dim = 2): u_bulk = lambda + mu, and
 * youngmod, poissratio give mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - nu)). */
static void lame_2d(const Cards *c, double *lambda, double *mu)
{
    const int *h = c->has_el;
    const double *v = c->el;
    const ElasticInput in = {h[EL_E], h[EL_NU], h[EL_LAMBDA], h[EL_MU], h[EL_K],
                             v[EL_E], v[EL_NU], v[EL_LAMBDA], v[EL_MU], v[EL_K]};
    elastic_lame(&in, 2, lambda, mu);
}

/* The body gets the equivalent lambda and shear. */
static void elastic_args_2d(const Cards *c, SettingList *args)
{
    double lambda, mu;
    lame_2d(c, &lambda, &mu);
    const SrcLoc lloc = c->el_loc[c->has_el[EL_E] ? EL_NU : c->has_el[EL_K] ? EL_K : EL_LAMBDA];
    const SrcLoc mloc = c->el_loc[c->has_el[EL_E] ? EL_E : EL_MU];
    ast_push_setting(args, ast_setting(lloc, "lambda", ast_num(lloc, lambda)));
    ast_push_setting(args, ast_setting(mloc, "shear", ast_num(mloc, mu)));
}

/* And SoliDualSPHysics' reference sound speed: eq. 59 with its plane bulk modulus
 * K2 = lambda + mu. */
static double sound_speed_2d(const Cards *c)
{
    double lambda, mu;
    lame_2d(c, &lambda, &mu);
    return elastic_sound_speed(lambda + mu, mu, c->density);
}

/* The law's arguments from its own cards. */
static void push_law_args(const Cards *c, SettingList *args)
{
    const int m = (int)c->model;
    const XmlLaw *law = xml_law(m);
    for (int i = 0; i < XML_LAW_CARDS && law->cards[i]; i++) {
        const SrcLoc loc = c->param_loc[m][i];
        ast_push_setting(args, ast_setting(loc, law->args[i], ast_num(loc, c->param[m][i])));
    }
}

static void push_material(XmlCtx *x, const Cards *c, BodyDecl *b)
{
    SrcLoc loc = c->model_loc.line ? c->model_loc : c->loc;
    BodyItem it = {0};
    it.kind = BI_MATERIAL;
    it.loc = loc;
    it.material.name = ast_strdup(xml_law((int)c->model)->law);
    it.material.loc = loc;
    ast_push_setting(&it.material.args, ast_setting(c->density_loc, "density",
                                                    ast_num(c->density_loc, c->density)));
    if (x->dim == 2 && x->opt.elastic2d_sdsph)
        elastic_args_2d(c, &it.material.args);
    else
        for (int k = 0; k < EL_N; k++)
            if (c->has_el[k])
                ast_push_setting(&it.material.args, ast_setting(c->el_loc[k], ELASTIC_ARGS[k],
                                                                ast_num(c->el_loc[k], c->el[k])));
    push_law_args(c, &it.material.args);
    ast_push_bodyitem(b, it);
    if (!x->uses_law[c->model])
        x->law_loc[c->model] = loc;
    x->uses_law[c->model] = 1;
}

/* Whether a shape draws a surface file somewhere. */
static int has_surface(const ShapeExpr *e)
{
    if (!e)
        return 0;
    if (!e->op)
        return !strcmp(e->prim.name, "surface");
    return has_surface(e->lhs) || has_surface(e->rhs);
}

static int push_settings(XmlCtx *x, const Cards *c, BodyDecl *b)
{
    BodyItem shape = {0};
    int has_corner;
    double corner[3];
    shape.kind = BI_SHAPE;
    shape.loc = c->loc;
    shape.shape = xml_mk_body_shape(x, c->mk, c->loc, &has_corner, corner);
    if (!shape.shape)
        return -1;
    ast_push_bodyitem(b, shape);
    if (x->dim == 2 && has_surface(shape.shape)) /* GenCase cuts it by the case's plane */
        push_setting(b, c->loc, "plane", x->pmin[1]);
    push_setting(b, c->refine_loc.line ? c->refine_loc : c->loc, "refine", (double)c->refine);
    if (has_corner) {
        Expr **v = NULL;
        int nv = 0;
        for (int a = 0; a < 3; a++)
            ast_push_expr(&v, &nv, ast_num(c->loc, corner[a]));
        push_item(b, BI_SETTING, c->loc, ast_setting(c->loc, "lattice", ast_vec(c->loc, v, nv)));
    }
    if (c->has_nbs)
        push_setting(b, c->nbs_loc, "nbsrange", (double)c->nbsrange);
    push_material(x, c, b);
    if (x->dim == 2 && x->opt.elastic2d_sdsph)
        push_setting(b, c->loc, "soundspeed", sound_speed_2d(c));
    SrcLoc vl = c->has_visc ? c->visc_loc : c->loc;
    Setting visc = ast_setting(vl, "viscosity", ast_num(vl, c->beta1));
    if (c->beta2 != 0)
        ast_push_expr(&visc.values, &visc.nvalues, ast_num(vl, c->beta2));
    push_item(b, BI_SETTING, vl, visc);
    if (c->has_rest) /* default 1, as SoliDualSPHysics' documentation of the card says */
        push_setting(b, c->rest_loc, "restitution", c->rest);
    if (c->has_fric)
        push_setting(b, c->fric_loc, "friction", c->fric);
    if (c->fracture)
        xml_fracture_items(x, &c->frac, c->fracture_card, b);
    return 0;
}

static int is_bc_or_measure(const xmlNode *n)
{
    return xml_is(n, "bcvel") || xml_is(n, "bcforce") || xml_is(n, "measureplane");
}

/* Pass 1: material and settings cards. */
static int read_cards(XmlCtx *x, const xmlNode *n, Cards *c)
{
    int bad = 0;
    for (xmlNode *k = xml_first(n); k; k = xml_next(k)) {
        if (is_bc_or_measure(k))
            continue;
        int r = card(x, k, c);
        if (r > 0)
            diag_error(xml_loc(x, k), "<%s> is not a card of <deformstrucbody> (see the list "
                                      "in docs/xml.md)", xml_name(k));
        bad |= r != 0;
    }
    if (!bad && !c->has_density) {
        diag_error(c->loc, "<deformstrucbody mkbound=\"%d\"> needs <density value=\"...\"/>",
                   c->mk);
        bad = 1;
    }
    if (bad || elastic_option(c) || special_models(x, c))
        return -1;
    return 0;
}

static int body(XmlCtx *x, const xmlNode *n)
{
    static const char *const attrs[] = {"mkbound", NULL};
    Cards c = {0};
    long mk;
    c.loc = xml_loc(x, n);
    c.model = 1;
    c.refine = 1;
    c.beta1 = 0.2;
    if (xml_check_attrs(x, n, attrs) || xml_integer(x, n, "mkbound", 1, 0, 65535, &mk) != 1)
        return -1;
    c.mk = (int)mk;
    char name[32];
    snprintf(name, sizeof name, "mk%d", c.mk);
    for (int i = 0; i < x->nbodies; i++)
        if (!strcmp(x->bodies[i].body.name, name)) {
            diag_error(c.loc, "<deformstrucbody>: mkbound %d is already a body", c.mk);
            return -1;
        }
    if (!xml_mk_drawn(x, c.mk)) {
        diag_error(c.loc, "<deformstrucbody> attribute 'mkbound': nothing was drawn with mk %d "
                          "in <geometry> (see <setmkbound>)", c.mk);
        return -1;
    }
    if (read_cards(x, n, &c))
        return -1;
    Item it = {0};
    it.kind = IT_BODY;
    it.loc = c.loc;
    it.body.name = ast_strdup(name);
    it.body.loc = c.loc;
    /* comments just before the card and inside it go with the body */
    const xmlNode *first = n;
    while (first->prev && first->prev->type != XML_ELEMENT_NODE)
        first = first->prev;
    for (const xmlNode *k = first; k != n; k = k->next)
        xml_add_comment(k, &it.body.comment);
    for (const xmlNode *k = n->children; k; k = k->next)
        xml_add_comment(k, &it.body.comment);
    if (push_settings(x, &c, &it.body))
        return -1;
    int bad = 0;
    for (xmlNode *k = xml_first(n); k; k = xml_next(k))
        if (xml_is(k, "measureplane"))
            bad |= xml_measureplane(x, k, c.mk, (int)c.refine, &it.body) != 0;
        else if (is_bc_or_measure(k))
            bad |= xml_bc(x, k, c.mk, &it.body) != 0;
    x->bodies = ast_room(x->bodies, (size_t)x->nbodies, sizeof *x->bodies);
    x->bodies[x->nbodies++] = it;
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ <deformstrucs> */

static int top_card(XmlCtx *x, const xmlNode *n)
{
    double v;
    if (xml_is(n, "timestep")) {
        if (xml_card_number(x, n, &v))
            return -1;
        if (!(v > 0)) {
            diag_error(xml_loc(x, n), "<timestep> attribute 'value': must be positive (got %g)",
                       v);
            return -1;
        }
        xml_scene_number(x, xml_loc(x, n), "dt", v);
        return 0;
    }
    if (xml_is(n, "contcoeff")) {
        if (xml_card_number(x, n, &v))
            return -1;
        if (!(v >= 1)) { /* as SoliDualSPHysics reads it */
            diag_warning(xml_loc(x, n), "<contcoeff> value %g is below 1: 1 is used, as "
                                        "SoliDualSPHysics does", v);
            v = 1;
        }
        xml_scene_number(x, xml_loc(x, n), "contact", v);
        return 0;
    }
    diag_error(xml_loc(x, n), "<%s> is not expected in <deformstrucs> (expected "
                              "<deformstrucbody>, <timestep> or <contcoeff>)", xml_name(n));
    return -1;
}

int xml_deformstrucs(XmlCtx *x, const xmlNode *deformstrucs)
{
    int bad = 0;
    int nbodies = 0;
    for (xmlNode *c = xml_first(deformstrucs); c; c = xml_next(c)) {
        if (!xml_is(c, "deformstrucbody")) {
            bad |= top_card(x, c) != 0;
            continue;
        }
        nbodies++;
        bad |= body(x, c) != 0;
    }
    if (!nbodies) {
        diag_error(xml_loc(x, deformstrucs), "<deformstrucs> has no <deformstrucbody>");
        return -1;
    }
    return bad ? -1 : 0;
}
