/* xml_geometry.c — <geometry>: GenCase's particle lattice and the shapes drawn on it.
 *
 * GenCase places particles on the lattice nodes pointmin + k dp of <definition> (2D when
 * pointmin.y == pointmax.y: the nodes of the plane y = pointmin.y).  A <drawbox> with
 * <point> p and <size> s covers, along each axis, the nodes
 *
 *     k = round((p - pointmin) / dp)  ...  round((p + s - pointmin) / dp)
 *
 * with round(v) = floor(v + 0.5) in double precision, and no node outside the domain
 * [pointmin, pointmax].  (This gives the particle counts of the paper's appendices: 202 x
 * 20 nodes for the 2D beam; a size ending half-way between two nodes is decided by the
 * rounding of the division, as in GenCase.)  The importer writes such a node range as the
 * sph box [first node - dp/2, last node + dp/2]: sph fills cell centres, so refine 1 gives
 * the same particles as GenCase and refine m (mapfac) the same mapped ones.
 *
 * A later drawing with another mk takes its nodes over from the earlier ones, so the
 * shape of an mk is its boxes in drawing order less the later boxes of other mks that
 * overlap them. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "xml_internal.h"

static long gc_round(double v)
{
    return (long)floor(v + 0.5);
}

/* ------------------------------------------------------------------ <definition> */

static int definition(XmlCtx *x, const xmlNode *n)
{
    static const char *const attrs[] = {"dp", NULL};
    static const char *const kids[] = {"pointmin", "pointmax", NULL};
    int bad = xml_check_attrs(x, n, attrs) != 0;
    bad |= xml_check_children(x, n, kids) != 0;
    bad |= xml_number(x, n, "dp", 1, &x->dp) != 1;
    const xmlNode *lo = xml_child(n, "pointmin"), *hi = xml_child(n, "pointmax");
    if (!lo || !hi) {
        diag_error(xml_loc(x, n), "<definition> needs <pointmin> and <pointmax>");
        return -1;
    }
    bad |= xml_point(x, lo, x->pmin) != 0;
    bad |= xml_point(x, hi, x->pmax) != 0;
    if (bad)
        return -1;
    if (!(x->dp > 0)) {
        diag_error(xml_loc(x, n), "<definition> attribute 'dp': must be positive (got %g)", x->dp);
        return -1;
    }
    for (int a = 0; a < 3; a++) {
        if (!(x->pmax[a] >= x->pmin[a])) {
            diag_error(xml_loc(x, hi), "<pointmax>: %c = %g is below pointmin's %g", "xyz"[a],
                       x->pmax[a], x->pmin[a]);
            return -1;
        }
        x->nodes[a] = (long)floor((x->pmax[a] - x->pmin[a]) / x->dp + 1e-9);
    }
    x->dim = x->pmin[1] == x->pmax[1] ? 2 : 3;
    x->has_domain = 1;
    xml_scene_number(x, xml_loc(x, n), "dimension", x->dim);
    xml_scene_number(x, xml_loc(x, n), "dp", x->dp);
    return 0;
}

/* ------------------------------------------------------------------ <newvar> */

static void set_var(XmlCtx *x, const char *name, double v)
{
    for (int i = 0; i < x->nvars; i++)
        if (!strcmp(x->var_names[i], name)) {
            x->var_values[i] = v;
            return;
        }
    x->var_names = xml_grow(x->var_names, x->nvars + 1, sizeof *x->var_names);
    x->var_values = xml_grow(x->var_values, x->nvars + 1, sizeof *x->var_values);
    x->var_names[x->nvars] = ast_strdup(name);
    x->var_values[x->nvars++] = v;
}

static int newvar(XmlCtx *x, const xmlNode *n)
{
    int bad = 0;
    for (xmlAttr *a = n->properties; a; a = a->next) {
        const char *name = (const char *)a->name;
        double v;
        if (!strcmp(name, "comment") || !strcmp(name, "units_comment"))
            continue;
        if (xml_number(x, n, name, 1, &v) == 1)
            set_var(x, name, v);
        else
            bad = 1;
    }
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ <drawbox> */

static int boxfill(const XmlCtx *x, const xmlNode *box)
{
    const xmlNode *fill = xml_child(box, "boxfill");
    if (!fill)
        return 0; /* solid */
    const char *mode = xml_text(fill);
    if (!strcmp(mode, "solid"))
        return 0;
    diag_error(xml_loc(x, fill), "<boxfill>: '%s' is not supported by the importer yet (only "
                                 "solid boxes are)", mode);
    return -1;
}

/* Nodes of one axis; 0 when some lie in the domain. */
static int node_range(const XmlCtx *x, int a, double p, double s, long *lo, long *hi)
{
    *lo = gc_round((p - x->pmin[a]) / x->dp);
    *hi = gc_round((p + s - x->pmin[a]) / x->dp);
    if (x->dim == 2 && a == 1) {
        int hit = *lo <= 0 && *hi >= 0;
        *lo = *hi = 0;
        return hit ? 0 : -1;
    }
    if (*lo < 0)
        *lo = 0;
    if (*hi > x->nodes[a])
        *hi = x->nodes[a];
    return *lo <= *hi ? 0 : -1;
}

static int drawbox(XmlCtx *x, const xmlNode *n, int mk)
{
    static const char *const kids[] = {"boxfill", "point", "size", NULL};
    static const char *const none[] = {NULL};
    SrcLoc loc = xml_loc(x, n);
    int bad = xml_check_attrs(x, n, none) != 0;
    bad |= xml_check_children(x, n, kids) != 0;
    bad |= boxfill(x, n) != 0;
    const xmlNode *point = xml_child(n, "point"), *size = xml_child(n, "size");
    if (!point || !size) {
        diag_error(loc, "<drawbox> needs <point> and <size>");
        return -1;
    }
    double p[3], s[3];
    bad |= xml_point(x, point, p) != 0;
    bad |= xml_point(x, size, s) != 0;
    if (bad)
        return -1;
    if (mk < 0) {
        diag_error(loc, "<drawbox> comes before any <setmkbound mk=\"...\"/>: it has no mk");
        return -1;
    }
    XmlDraw d = {mk, {0}, {0}, loc};
    for (int a = 0; a < 3; a++) {
        if (s[a] < 0) {
            diag_error(xml_loc(x, size), "<size>: %c = %g is negative", "xyz"[a], s[a]);
            return -1;
        }
        if (node_range(x, a, p[a], s[a], &d.lo[a], &d.hi[a]) == 0)
            continue;
        if (x->dim == 2 && a == 1)
            diag_error(loc, "<drawbox> does not reach the plane y = %g of this 2D case "
                            "(pointmin.y == pointmax.y): it holds no particles", x->pmin[1]);
        else
            diag_error(loc, "<drawbox> lies outside the domain of <definition> along %c: it "
                            "holds no particles", "xyz"[a]);
        return -1;
    }
    x->draws = xml_grow(x->draws, x->ndraws + 1, sizeof *x->draws);
    x->draws[x->ndraws++] = d;
    return 0;
}

/* ------------------------------------------------------------------ the mainlist */

/* Commands that only change how GenCase writes or draws shapes. */
static int is_accepted(const xmlNode *n)
{
    static const char *const ok[] = {"setdrawmode", "setshapemode", "shapeout", "setfrdrawmode",
                                     NULL};
    for (int i = 0; ok[i]; i++)
        if (xml_is(n, ok[i]))
            return 1;
    return 0;
}

/* Drawings the importer does not handle yet: their attributes are read, then refused. */
static int unsupported_drawing(const XmlCtx *x, const xmlNode *n)
{
    SrcLoc loc = xml_loc(x, n);
    if (xml_is(n, "drawcylinder")) {
        static const char *const attrs[] = {"radius", NULL};
        double r;
        if (xml_check_attrs(x, n, attrs) || xml_number(x, n, "radius", 1, &r) != 1)
            return -1;
        int npoints = 0;
        for (xmlNode *c = xml_first(n); c; c = xml_next(c)) {
            double p[3];
            if (xml_is(c, "point") && xml_point(x, c, p) == 0)
                npoints++;
        }
        if (npoints != 2) {
            diag_error(loc, "<drawcylinder> needs two <point>s (the ends of its axis)");
            return -1;
        }
    } else if (!strncmp(xml_name(n), "drawfile", 8) && !xml_attr(n, "file")) {
        diag_error(loc, "<%s>: missing attribute 'file'", xml_name(n));
        return -1;
    }
    diag_error(loc, "<%s>: this drawing command is not supported by the importer yet (only "
                    "<drawbox> is)", xml_name(n));
    return -1;
}

static int command(XmlCtx *x, const xmlNode *n, int *mk)
{
    if (xml_is(n, "newvar"))
        return newvar(x, n);
    if (xml_is(n, "setmkbound")) {
        static const char *const attrs[] = {"mk", NULL};
        long v;
        if (xml_check_attrs(x, n, attrs) || xml_integer(x, n, "mk", 1, 0, 65535, &v) != 1)
            return -1;
        *mk = (int)v;
        return 0;
    }
    if (xml_is(n, "setmkfluid")) {
        diag_error(xml_loc(x, n), "<setmkfluid>: fluids are not supported (sphc simulates "
                                  "deformable solids)");
        return -1;
    }
    if (xml_is(n, "drawbox"))
        return drawbox(x, n, *mk);
    if (is_accepted(n))
        return 0;
    if (!strncmp(xml_name(n), "draw", 4))
        return unsupported_drawing(x, n);
    diag_error(xml_loc(x, n), "<%s>: this GenCase command is not supported by the importer yet",
               xml_name(n));
    return -1;
}

static int mainlist(XmlCtx *x, const xmlNode *list)
{
    int mk = -1, bad = 0;
    for (xmlNode *c = xml_first(list); c; c = xml_next(c))
        bad |= command(x, c, &mk) != 0;
    return bad ? -1 : 0;
}

int xml_geometry(XmlCtx *x, const xmlNode *geometry)
{
    static const char *const kids[] = {"definition", "commands", NULL};
    static const char *const lists[] = {"mainlist", NULL};
    if (xml_check_children(x, geometry, kids))
        return -1;
    const xmlNode *def = xml_child(geometry, "definition");
    const xmlNode *commands = xml_child(geometry, "commands");
    const xmlNode *list = commands ? xml_child(commands, "mainlist") : NULL;
    if (!def || !list) {
        diag_error(xml_loc(x, geometry), "<geometry> needs <definition> and "
                                         "<commands><mainlist>");
        return -1;
    }
    if (definition(x, def) || xml_check_children(x, commands, lists))
        return -1;
    return mainlist(x, list);
}

/* ------------------------------------------------------------------ shapes of an mk */

int xml_mk_drawn(const XmlCtx *x, int mk)
{
    for (int i = 0; i < x->ndraws; i++)
        if (x->draws[i].mk == mk)
            return 1;
    return 0;
}

/* Coordinate of node k (a half-integer for a box face) along axis a. */
static double node_coord(const XmlCtx *x, int a, double k)
{
    return xml_snap(x->pmin[a] + k * x->dp, 1e-9 * x->dp);
}

static void draw_volume(const XmlCtx *x, const XmlDraw *d, double lo[3], double hi[3])
{
    for (int a = 0; a < 3; a++) {
        int flat = x->dim == 2 && a == 1;
        lo[a] = flat ? 0.0 : node_coord(x, a, (double)d->lo[a] - 0.5);
        hi[a] = flat ? 0.0 : node_coord(x, a, (double)d->hi[a] + 0.5);
    }
}

static Expr *vec3(SrcLoc loc, const double v[3])
{
    Expr **args = NULL;
    int n = 0;
    for (int a = 0; a < 3; a++)
        ast_push_expr(&args, &n, ast_num(loc, v[a]));
    return ast_vec(loc, args, n);
}

static ShapeExpr *box_shape(const XmlCtx *x, const XmlDraw *d)
{
    double lo[3], hi[3];
    draw_volume(x, d, lo, hi);
    NamedCall call = {ast_strdup("box"), d->loc, {0}};
    ast_push_setting(&call.args, ast_setting(d->loc, "from", vec3(d->loc, lo)));
    ast_push_setting(&call.args, ast_setting(d->loc, "to", vec3(d->loc, hi)));
    return ast_shape_prim(call);
}

static int overlap(const XmlDraw *a, const XmlDraw *b)
{
    for (int k = 0; k < 3; k++)
        if (a->hi[k] < b->lo[k] || b->hi[k] < a->lo[k])
            return 0;
    return 1;
}

/* Whether draw i overlaps one of mk's draws before it. */
static int takes_over(const XmlCtx *x, int i, int mk)
{
    for (int j = 0; j < i; j++)
        if (x->draws[j].mk == mk && overlap(&x->draws[j], &x->draws[i]))
            return 1;
    return 0;
}

ShapeExpr *xml_mk_shape(const XmlCtx *x, int mk, SrcLoc loc)
{
    ShapeExpr *s = NULL;
    for (int i = 0; i < x->ndraws; i++) {
        const XmlDraw *d = &x->draws[i];
        if (d->mk == mk)
            s = s ? ast_shape_op(loc, '+', s, box_shape(x, d)) : box_shape(x, d);
        else if (s && takes_over(x, i, mk))
            s = ast_shape_op(loc, '-', s, box_shape(x, d));
    }
    return s;
}

void xml_mk_bbox(const XmlCtx *x, int mk, double lo[3], double hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = HUGE_VAL;
        hi[a] = -HUGE_VAL;
    }
    for (int i = 0; i < x->ndraws; i++) {
        double dl[3], dh[3];
        if (x->draws[i].mk != mk)
            continue;
        draw_volume(x, &x->draws[i], dl, dh);
        for (int a = 0; a < 3; a++) {
            lo[a] = fmin(lo[a], dl[a]);
            hi[a] = fmax(hi[a], dh[a]);
        }
    }
}
