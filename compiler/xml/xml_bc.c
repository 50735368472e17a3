/* xml_bc.c — boundary conditions and measurement planes of a body.
 *
 *   <bcvel xe="2" ye="2" z="0.0" tst=".." tend=".." mkid="4"/>
 *       velocity x, y = <expression 2> from .. to .. near <shape of mk 4>
 *       velocity z = 0 from .. to .. near <shape of mk 4>
 *   <bcforce type="1|2|3" ...>    force point | surface | accel ...   (type 2 by default;
 *                                 the kinds' xml column, lang/bc_kinds.h)
 *
 * Components with the same source (one expression id, or equal constants) share one
 * statement.  In a 2D case the y components are dropped (plane strain in x-z).
 *
 *   <measureplane> <p1 x y z/> .. <p4 x y z/> </measureplane>
 *       measure planeK plane [p1] [p2] [p3] [p4]
 *
 * The runtime measures the particles within dx/2 of the plane.  SoliDualSPHysics cases
 * put the plane at the tip, up to one dp beyond the last particle layer (appendix 3:
 * x = 100.4e-3 with the last layer at 99.5e-3).  So a plane normal to an axis that lies
 * outside the body's outermost particle layer, by more than dx/2 and at most dp, is moved
 * onto that layer: it measures the tip as SoliDualSPHysics does.  (Bodies drawn with boxes
 * only: their layers are known from the nodes.) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lang/bc_kinds.h"
#include "util/diag.h"
#include "xml_internal.h"

/* Where one component's value comes from. */
typedef struct {
    int given, expr_id;   /* expr_id < 0: constant */
    double value;
} Source;

static int same_source(const Source *a, const Source *b)
{
    return a->expr_id == b->expr_id && (a->expr_id >= 0 || a->value == b->value);
}

/* Component a (0..2) from attribute "x" or "xe". */
static int component(const XmlCtx *x, const xmlNode *n, int a, Source *s)
{
    char cattr[2] = {"xyz"[a], 0}, eattr[3] = {"xyz"[a], 'e', 0};
    long id;
    int rc = xml_number(x, n, cattr, 0, &s->value);
    int re = xml_integer(x, n, eattr, 0, 0, 1000000000, &id);
    if (rc < 0 || re < 0)
        return -1;
    if (rc && re) {
        diag_error(xml_loc(x, n), "<%s>: both '%s' and '%s' given for the %c component",
                   xml_name(n), cattr, eattr, "xyz"[a]);
        return -1;
    }
    s->given = rc || re;
    s->expr_id = re ? (int)id : -1;
    if (re && !xml_user_expr(x, id)) {
        diag_error(xml_loc(x, n), "<%s> attribute '%s': expression %ld is not defined in "
                                  "<mathexpressions>", xml_name(n), eattr, id);
        return -1;
    }
    return 0;
}

/* <bcforce>'s type when it has none: a surface traction. */
enum { BCFORCE_DEFAULT_TYPE = 2 };

/* "type is 1 (point force), 2 (surface traction) or 3 (acceleration)": the kinds of
 * lang/bc_kinds.h that SoliDualSPHysics has. */
static void types_note(SrcLoc loc)
{
    char buf[256] = "";
    int n = 0;
    for (int t = 1; t <= bc_kind_xml_max(); t++)
        n += bc_kind_of_xml(t) >= 0;
    for (int t = 1, i = 0; t <= bc_kind_xml_max(); t++) {
        int k = bc_kind_of_xml(t);
        if (k < 0)
            continue;
        i++;
        snprintf(buf + strlen(buf), sizeof buf - strlen(buf), "%s%d (%s)",
                 i == 1 ? "" : i == n ? " or " : ", ", t, BC_KIND[k].what);
    }
    diag_note(loc, "type is %s", buf);
}

/* The options shared by the statements of one card: window, near, force kind. */
static int options(XmlCtx *x, const xmlNode *n, int mk, BcDecl *opt)
{
    SrcLoc loc = xml_loc(x, n);
    double t;
    long v;
    int r = xml_number(x, n, "tst", 0, &t);
    if (r < 0)
        return -1;
    if (r)
        opt->t_from = ast_num(loc, t);
    if ((r = xml_number(x, n, "tend", 0, &t)) < 0)
        return -1;
    if (r)
        opt->t_to = ast_num(loc, t);
    if ((r = xml_integer(x, n, "mkid", 0, 0, 65535, &v)) < 0)
        return -1;
    if (r && v == mk) {
        diag_error(loc, "<%s> attribute 'mkid': %ld is the body's own mk; give the mk of an "
                        "auxiliary geometry", xml_name(n), v);
        return -1;
    }
    if (r && !xml_mk_drawn(x, (int)v)) {
        diag_error(loc, "<%s> attribute 'mkid': nothing was drawn with mk %ld in <geometry>",
                   xml_name(n), v);
        return -1;
    }
    if (r && !(opt->near = xml_mk_shape(x, (int)v, loc)))
        return -1;
    if (!xml_is(n, "bcforce")) {
        opt->kind = BC_KIND_velocity;
        return 0;
    }
    if ((r = xml_integer(x, n, "type", 0, 1, bc_kind_xml_max(), &v)) < 0 ||
        (r && bc_kind_of_xml((int)v) < 0)) {
        if (r > 0)
            diag_error(loc, "<%s> attribute 'type': %ld is no force type", xml_name(n), v);
        types_note(loc);
        return -1;
    }
    opt->kind = bc_kind_of_xml(r ? (int)v : BCFORCE_DEFAULT_TYPE);
    return 0;
}

static void push_bc(const XmlCtx *x, const xmlNode *n, BcDecl bc, int comps, const Source *s,
                    BodyDecl *body)
{
    SrcLoc loc = xml_loc(x, n);
    BodyItem it = {0};
    it.kind = BI_BC;
    it.loc = loc;
    it.bc = bc;
    it.bc.loc = it.bc.comps_loc = loc;
    it.bc.comps = comps;
    it.bc.value = s->expr_id >= 0 ? xml_user_expr(x, s->expr_id)->value : ast_num(loc, s->value);
    ast_push_bodyitem(body, it);
}

int xml_bc(XmlCtx *x, const xmlNode *n, int mk, BodyDecl *body)
{
    static const char *const vel[] = {"x", "y", "z", "xe", "ye", "ze", "tst", "tend", "mkid", NULL};
    static const char *const frc[] = {"x",  "y",    "z",    "xe",   "ye",
                                      "ze", "tst", "tend", "mkid", "type", NULL};
    Source s[3] = {{0}};
    BcDecl opt = {0};
    int bad = xml_check_attrs(x, n, xml_is(n, "bcforce") ? frc : vel) != 0;
    for (int a = 0; a < 3; a++)
        bad |= component(x, n, a, &s[a]) != 0;
    if (bad || options(x, n, mk, &opt))
        return -1;
    if (!s[0].given && !s[1].given && !s[2].given) {
        diag_error(xml_loc(x, n), "<%s> sets no component (give x, y, z or xe, ye, ze)",
                   xml_name(n));
        return -1;
    }
    if (x->dim == 2 && s[1].given) {
        if (BC_KIND[opt.kind].pass == BC_FORCE && (s[1].expr_id >= 0 || s[1].value != 0))
            diag_warning(xml_loc(x, n), "<%s>: the y component is ignored in a 2D case",
                         xml_name(n));
        s[1].given = 0;
    }
    for (int a = 0; a < 3; a++) {
        if (!s[a].given)
            continue;
        int comps = 0;
        for (int b = a; b < 3; b++)
            if (s[b].given && same_source(&s[a], &s[b])) {
                comps |= 1 << b;
                if (b > a)
                    s[b].given = 0;
            }
        push_bc(x, n, opt, comps, &s[a], body);
    }
    return 0;
}

/* ------------------------------------------------------------------ <measureplane> */

/* Moves a plane normal to an axis onto the outermost particle layer when it lies beyond it
 * by more than dx/2 and at most dp (see the header comment). */
static void onto_layer(const XmlCtx *x, int mk, int refine, double p[4][3])
{
    double lo[3], hi[3], dx = x->dp / refine, tol = 1e-9 * x->dp;
    if (!xml_mk_boxes_only(x, mk))
        return; /* the layers of other shapes are not known here */
    xml_mk_bbox(x, mk, lo, hi);
    for (int a = 0; a < 3; a++) {
        if (x->dim == 2 && a == 1)
            continue;
        int normal = 1;
        for (int k = 1; k < 4; k++)
            normal &= fabs(p[k][a] - p[0][a]) <= tol;
        if (!normal)
            continue;
        double c = p[0][a], first = lo[a] + dx / 2, last = hi[a] - dx / 2;
        if (c - last > dx / 2 + tol && c - last <= x->dp + tol)
            c = last;
        else if (first - c > dx / 2 + tol && first - c <= x->dp + tol)
            c = first;
        for (int k = 0; k < 4; k++)
            p[k][a] = xml_snap(c, tol);
    }
}

int xml_measureplane(XmlCtx *x, const xmlNode *n, int mk, int refine, BodyDecl *body)
{
    static const char *const corners[] = {"p1", "p2", "p3", "p4", NULL};
    static const char *const none[] = {NULL};
    SrcLoc loc = xml_loc(x, n);
    double p[4][3];
    int bad = xml_check_attrs(x, n, none) != 0;
    bad |= xml_check_children(x, n, corners) != 0;
    for (int k = 0; k < 4; k++) {
        const xmlNode *c = xml_child(n, corners[k]);
        if (!c) {
            diag_error(loc, "<measureplane> needs <%s>", corners[k]);
            bad = 1;
        } else {
            bad |= xml_point(x, c, p[k]) != 0;
        }
    }
    if (bad)
        return -1;
    onto_layer(x, mk, refine, p);
    BodyItem it = {0};
    it.kind = BI_MEASURE;
    it.loc = loc;
    char name[32];
    snprintf(name, sizeof name, "plane%d", ++x->nmeasures);
    it.measure.name = ast_strdup(name);
    it.measure.loc = loc;
    for (int k = 0; k < 4; k++) {
        Expr **v = NULL;
        int nv = 0;
        for (int a = 0; a < 3; a++)
            ast_push_expr(&v, &nv, ast_num(loc, xml_snap(p[k][a], 1e-9 * x->dp)));
        it.measure.points[k] = ast_vec(loc, v, nv);
    }
    ast_push_bodyitem(body, it);
    return 0;
}
