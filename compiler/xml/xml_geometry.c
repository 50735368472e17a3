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
 * A <drawcylinder radius> with two <point>s is the sph cylinder between them; it keeps the
 * free drawing mode in force (<setfrdrawmode auto="true|false"/>) for --xml-fill=gencase.
 * <drawfilevtk file autofill="true"/> and <drawfilestl ...> are the closed surface in the file
 * (relative to the case file), filled: the sph surface(file "...").
 * <drawprism>, <drawpyramid> and <drawextrude> are the sph prism or pyramid of their corners.
 * Every drawing goes through GenCase's transformation matrix (xml_transform.c), and after
 * <setmkvoid/> its mk is XML_MK_VOID: it only takes nodes over.  <runlist> runs the commands
 * of a <list>.  xml_shape.c turns the drawings of an mk into the shape of a body or of a
 * `near`. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "geom/mesh.h"
#include "util/source.h"
#include "xml_internal.h"

/* Node indices stay well inside the range of long: the conversion of a coordinate far
 * outside the domain would overflow it; results are clipped to the domain anyway. */
#define NODE_LIMIT 1e15

static long to_node(double v)
{
    if (!(v > -NODE_LIMIT))
        return (long)-NODE_LIMIT;
    if (v > NODE_LIMIT)
        return (long)NODE_LIMIT;
    return (long)v;
}

static long gc_round(double v)
{
    return to_node(floor(v + 0.5));
}

/* ------------------------------------------------------------------ <definition> */

static void set_var(XmlCtx *x, const char *name, double v)
{
    for (int i = 0; i < x->nvars; i++)
        if (!strcmp(x->var_names[i], name)) {
            x->var_values[i] = v;
            return;
        }
    x->var_names = ast_room(x->var_names, (size_t)x->nvars, sizeof *x->var_names);
    x->var_values = ast_room(x->var_values, (size_t)x->nvars, sizeof *x->var_values);
    x->var_names[x->nvars] = ast_strdup(name);
    x->var_values[x->nvars++] = v;
}

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
        double span = floor((x->pmax[a] - x->pmin[a]) / x->dp + 1e-9);
        if (!(span < NODE_LIMIT)) {
            diag_error(xml_loc(x, n), "<definition> attribute 'dp': %g is too small for the "
                       "domain (%g nodes along %c)", x->dp, span, "xyz"[a]);
            return -1;
        }
        x->nodes[a] = (long)span;
    }
    x->dim = x->pmin[1] == x->pmax[1] ? 2 : 3;
    x->has_domain = 1;
    set_var(x, "Dp", x->dp); /* GenCase's own variables of the domain */
    for (int a = 0; a < 3; a++) {
        char name[16];
        snprintf(name, sizeof name, "PosMin_%c", "xyz"[a]);
        set_var(x, name, x->pmin[a]);
        snprintf(name, sizeof name, "PosMax_%c", "xyz"[a]);
        set_var(x, name, x->pmax[a]);
    }
    xml_scene_number(x, xml_loc(x, n), "dimension", x->dim);
    xml_scene_number(x, xml_loc(x, n), "dp", x->dp);
    return 0;
}

/* ------------------------------------------------------------------ <newvar> */

static int has_var(const XmlCtx *x, const char *name)
{
    for (int i = 0; i < x->nvars; i++)
        if (!strcmp(x->var_names[i], name))
            return 1;
    return 0;
}

/* <newvar a="..">, <newvarcte a="..">: new variables, each value an expression of those
 * before it; <setvar a=".."> gives an existing one a new value.  Attributes starting with
 * '_' (GenCase's _rem, _print) are remarks. */
static int newvar(XmlCtx *x, const xmlNode *n)
{
    const int set = xml_is(n, "setvar");
    int bad = 0;
    for (xmlAttr *a = n->properties; a; a = a->next) {
        const char *name = (const char *)a->name;
        double v;
        if (!strcmp(name, "comment") || !strcmp(name, "units_comment") || name[0] == '_')
            continue;
        if (set && !has_var(x, name)) {
            diag_error(xml_loc(x, n), "<setvar>: no variable '%s' (define it with <newvar>)",
                       name);
            bad = 1;
        } else if (xml_number(x, n, name, 1, &v) == 1)
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

/* The errors and the last step every drawing shares. */
static int no_mk(const char *tag, SrcLoc loc)
{
    diag_error(loc, "<%s> comes before any <setmkbound mk=\"...\"/>: it has no mk", tag);
    return -1;
}

static int off_plane(const XmlCtx *x, const char *tag, SrcLoc loc)
{
    diag_error(loc, "<%s> does not reach the plane y = %g of this 2D case (pointmin.y == "
                    "pointmax.y): it holds no particles", tag, x->pmin[1]);
    return -1;
}

static int outside(const char *tag, int a, SrcLoc loc)
{
    diag_error(loc, "<%s> lies outside the domain of <definition> along %c: it holds no "
                    "particles", tag, "xyz"[a]);
    return -1;
}

/* A drawing of kind by mk at loc, in the free drawing mode in force, its fields zero. */
static XmlDraw new_draw(const XmlCtx *x, XmlDrawKind kind, int mk, SrcLoc loc)
{
    XmlDraw d;
    memset(&d, 0, sizeof d);
    d.kind = kind;
    d.mk = mk;
    d.freedraw = x->freedraw;
    d.loc = loc;
    return d;
}

/* Drawings a case may make: each body's shape is found by comparing its drawings with the
 * others' (xml_shape.c), which at worst takes their number squared. */
#define MAX_DRAWINGS 100000

static int add_draw(XmlCtx *x, const XmlDraw *d)
{
    if (x->ndraws == MAX_DRAWINGS) {
        if (!x->refused_drawings++) /* (reported once) */
            diag_error(d->loc, "more than %d drawings: give so fine a shape as a surface file",
                       MAX_DRAWINGS);
        return -1;
    }
    x->draws = ast_room(x->draws, (size_t)x->ndraws, sizeof *x->draws);
    x->draws[x->ndraws++] = *d;
    return 0;
}

/* Nodes of one axis between coordinates lo and hi; 0 when some lie in the domain. */
static int node_range(const XmlCtx *x, int a, double lo, double hi, long *klo, long *khi)
{
    *klo = gc_round((lo - x->pmin[a]) / x->dp);
    *khi = gc_round((hi - x->pmin[a]) / x->dp);
    if (x->dim == 2 && a == 1) {
        int hit = *klo <= 0 && *khi >= 0;
        *klo = *khi = 0;
        return hit ? 0 : -1;
    }
    if (*klo < 0)
        *klo = 0;
    if (*khi > x->nodes[a])
        *khi = x->nodes[a];
    return *klo <= *khi ? 0 : -1;
}

static int add_solid(XmlCtx *x, XmlDraw *d, const char *tag);

/* A box the matrix tilts: the prism of its corners, the base its face at its low y and the
 * top its face at its high y, so that in a 2D case a box turned about y is a prism along y
 * (re-spanned across the plane of the case by prism_in_plane).  p, q: opposite corners. */
static int tilted_box(XmlCtx *x, const double p[3], const double q[3], int mk, SrcLoc loc)
{
    static const int xz[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}; /* around the face */
    const XmlMatrix *m = &x->matrix;
    XmlDraw d = new_draw(x, XD_PRISM, mk, loc);
    if (x->dim == 2) {
        long klo, khi;
        if (!xml_matrix_keeps_y(m)) {
            diag_error(loc, "<drawbox>: in a 2D case a box may be turned about y only (the "
                            "transformation would tilt it out of the plane of the case)");
            return -1;
        }
        const double y0 = m->a[1][1] * p[1] + m->a[1][3], y1 = m->a[1][1] * q[1] + m->a[1][3];
        if (node_range(x, 1, fmin(y0, y1), fmax(y0, y1), &klo, &khi))
            return off_plane(x, "drawbox", loc);
    }
    double lo[3], hi[3]; /* a flat box is one layer of nodes: half a spacing each side */
    for (int a = 0; a < 3; a++) {
        lo[a] = p[a] - (q[a] == p[a] ? 0.5 * x->dp : 0.0);
        hi[a] = q[a] + (q[a] == p[a] ? 0.5 * x->dp : 0.0);
    }
    d.pts = ast_alloc(8 * 3 * sizeof *d.pts);
    d.npts = 8;
    for (int f = 0; f < 2; f++)
        for (int k = 0; k < 4; k++) {
            const double c[3] = {xz[k][0] ? hi[0] : lo[0], f ? hi[1] : lo[1],
                                 xz[k][1] ? hi[2] : lo[2]};
            double *out = d.pts + 3 * (4 * f + k);
            xml_matrix_point(m, c, out);
            if (x->dim == 2) /* along y across the plane, whatever the box's own y extent */
                out[1] = x->pmin[1] + (f ? x->dp : -x->dp);
        }
    return add_solid(x, &d, "drawbox");
}

/* <point> and either <size> or <endpoint>: the box's opposite corners p and q. */
static int box_corners(XmlCtx *x, const xmlNode *n, double p[3], double q[3])
{
    const xmlNode *point = xml_child(n, "point"), *size = xml_child(n, "size");
    const xmlNode *end = xml_child(n, "endpoint");
    if (!point || !size == !end) {
        diag_error(xml_loc(x, n), "<drawbox> needs <point> and either <size> or <endpoint>");
        return -1;
    }
    double s[3];
    if (xml_point(x, point, p) | xml_point(x, size ? size : end, size ? s : q))
        return -1;
    for (int a = 0; a < 3; a++) {
        if (size && s[a] < 0) {
            diag_error(xml_loc(x, size), "<size>: %c = %g is negative", "xyz"[a], s[a]);
            return -1;
        }
        if (!size && q[a] < p[a]) {
            diag_error(xml_loc(x, end), "<endpoint>: %c = %g is below <point>'s %g", "xyz"[a],
                       q[a], p[a]);
            return -1;
        }
        if (size)
            q[a] = p[a] + s[a];
    }
    return 0;
}

/* A box GenCase fills node by node (the header comment); through a transformation that
 * keeps the axes, the box between its moved corners; through one that tilts it, a prism. */
static int drawbox(XmlCtx *x, const xmlNode *n, int mk)
{
    static const char *const kids[] = {"boxfill", "point", "size", "endpoint", NULL};
    static const char *const none[] = {NULL};
    SrcLoc loc = xml_loc(x, n);
    int bad = xml_check_attrs(x, n, none) != 0;
    bad |= xml_check_children(x, n, kids) != 0;
    bad |= boxfill(x, n) != 0;
    double p[3], q[3];
    if (box_corners(x, n, p, q) || bad)
        return -1;
    if (mk == XML_MK_NONE)
        return no_mk("drawbox", loc);
    if (!xml_matrix_keeps_axes(&x->matrix))
        return tilted_box(x, p, q, mk, loc);
    xml_matrix_point(&x->matrix, p, p);
    xml_matrix_point(&x->matrix, q, q);
    XmlDraw d = new_draw(x, XD_BOX, mk, loc);
    for (int a = 0; a < 3; a++) {
        if (node_range(x, a, fmin(p[a], q[a]), fmax(p[a], q[a]), &d.lo[a], &d.hi[a]) == 0)
            continue;
        return x->dim == 2 && a == 1 ? off_plane(x, "drawbox", loc) : outside("drawbox", a, loc);
    }
    return add_draw(x, &d);
}

/* ------------------------------------------------------------------ the mainlist */

/* Commands that only change how GenCase writes or draws shapes. */
static int is_accepted(const xmlNode *n)
{
    static const char *const ok[] = {"setdrawmode", "setshapemode", "shapeout", NULL};
    for (int i = 0; ok[i]; i++)
        if (xml_is(n, ok[i]))
            return 1;
    return 0;
}

/* ------------------------------------------------------------------ <drawcylinder> */

/* Nodes of axis a spanned by [lo, hi], clipped to the domain; 0 when some lie in it. */
static int node_span(const XmlCtx *x, int a, double lo, double hi, long *klo, long *khi)
{
    *klo = to_node(ceil((lo - x->pmin[a]) / x->dp - 1e-9));
    *khi = to_node(floor((hi - x->pmin[a]) / x->dp + 1e-9));
    if (*klo < 0)
        *klo = 0;
    if (*khi > x->nodes[a])
        *khi = x->nodes[a];
    return *klo <= *khi ? 0 : -1;
}

/* What <drawcylinder> and <drawsphere> share: the radius, `want` <point>s into d->p (more or
 * fewer are an error that names `points`, what they should be), a positive radius, an mk. */
static int read_round(XmlCtx *x, const xmlNode *n, int mk, const char *tag, int want,
                      const char *points, XmlDraw *d)
{
    static const char *const attrs[] = {"radius", NULL};
    static const char *const kids[] = {"point", NULL};
    int bad = xml_check_attrs(x, n, attrs) != 0;
    bad |= xml_check_children(x, n, kids) != 0;
    bad |= xml_number(x, n, "radius", 1, &d->r) != 1;
    int npoints;
    const double *pts = xml_points(x, n, 1, &npoints);
    if (bad || !pts)
        return -1;
    if (npoints != want) {
        diag_error(d->loc, "<%s> needs %s, got %d", tag, points, npoints);
        return -1;
    }
    memcpy(d->p, pts, (size_t)want * sizeof d->p[0]);
    if (!(d->r > 0)) {
        diag_error(d->loc, "<%s> attribute 'radius': must be positive (got %g)", tag, d->r);
        return -1;
    }
    return mk == XML_MK_NONE ? no_mk(tag, d->loc) : 0;
}

/* A cylinder's or sphere's npoints points through the transformation, its radius scaled
 * with it; a scale that differs between axes would make it elliptic. */
static int transform_round(const XmlCtx *x, XmlDraw *d, int npoints, const char *tag)
{
    if (xml_matrix_is_identity(&x->matrix))
        return 0;
    const double s = xml_matrix_similarity(&x->matrix);
    if (s == 0) {
        diag_error(d->loc, "<%s>: a <scale> that differs between axes would make it elliptic, "
                           "which the importer does not support", tag);
        return -1;
    }
    for (int k = 0; k < npoints; k++)
        xml_matrix_point(&x->matrix, d->p[k], d->p[k]);
    d->r *= s;
    return 0;
}

/* The nodes that [lo, hi] along axis a covers into d, or an error that the shape is outside
 * the domain. */
static int draw_span(XmlCtx *x, const char *tag, int a, double lo, double hi, XmlDraw *d)
{
    if (node_span(x, a, lo, hi, &d->lo[a], &d->hi[a]))
        return outside(tag, a, d->loc);
    d->reach[0][a] = lo; /* (where it leaves the domain, xml_shape.c cuts it) */
    d->reach[1][a] = hi;
    return 0;
}

static int drawcylinder(XmlCtx *x, const xmlNode *n, int mk)
{
    XmlDraw d = new_draw(x, XD_CYLINDER, mk, xml_loc(x, n));
    if (read_round(x, n, mk, "drawcylinder", 2, "two <point>s (the ends of its axis)", &d) ||
        transform_round(x, &d, 2, "drawcylinder"))
        return -1;
    double len2 = 0;
    for (int a = 0; a < 3; a++)
        len2 += (d.p[1][a] - d.p[0][a]) * (d.p[1][a] - d.p[0][a]);
    for (int a = 0; a < 3; a++) { /* the bounding box: end discs reach r sqrt(1 - u_a^2) */
        double u2 = len2 > 0 ? (d.p[1][a] - d.p[0][a]) * (d.p[1][a] - d.p[0][a]) / len2 : 0;
        double ext = d.r * sqrt(fmax(0.0, 1.0 - u2));
        double lo = fmin(d.p[0][a], d.p[1][a]) - ext, hi = fmax(d.p[0][a], d.p[1][a]) + ext;
        if (x->dim == 2 && a == 1) {
            if (lo > x->pmin[1] + 1e-9 * x->dp || hi < x->pmin[1] - 1e-9 * x->dp)
                return off_plane(x, "drawcylinder", d.loc);
            continue;
        }
        if (draw_span(x, "drawcylinder", a, lo, hi, &d))
            return -1;
    }
    return add_draw(x, &d);
}

/* <drawsphere radius="r"><point .../></drawsphere>: the sph sphere; in a 2D case the disc
 * the sphere cuts from the plane y = pointmin.y. */
static int drawsphere(XmlCtx *x, const xmlNode *n, int mk)
{
    XmlDraw d = new_draw(x, XD_SPHERE, mk, xml_loc(x, n));
    if (read_round(x, n, mk, "drawsphere", 1, "one <point> (its centre)", &d) ||
        transform_round(x, &d, 1, "drawsphere"))
        return -1;
    if (x->dim == 2) { /* the disc in the plane of the case */
        const double off = x->pmin[1] - d.p[0][1];
        if (fabs(off) >= d.r)
            return off_plane(x, "drawsphere", d.loc);
        d.r = sqrt(d.r * d.r - off * off);
        d.p[0][1] = x->pmin[1];
    }
    for (int a = 0; a < 3; a++)
        if (!(x->dim == 2 && a == 1) &&
            draw_span(x, "drawsphere", a, d.p[0][a] - d.r, d.p[0][a] + d.r, &d))
            return -1;
    return add_draw(x, &d);
}

/* <setfrdrawmode auto="true|false"/>: GenCase's free drawing mode. */
static int setfrdrawmode(XmlCtx *x, const xmlNode *n)
{
    static const char *const attrs[] = {"auto", NULL};
    if (xml_check_attrs(x, n, attrs))
        return -1;
    const char *v = xml_attr(n, "auto");
    if (!v) {
        diag_error(xml_loc(x, n), "<setfrdrawmode>: missing attribute 'auto'");
        return -1;
    }
    if (!strcmp(v, "true") || !strcmp(v, "1"))
        x->freedraw = 1;
    else if (!strcmp(v, "false") || !strcmp(v, "0"))
        x->freedraw = 0;
    else {
        diag_error(xml_loc(x, n), "<setfrdrawmode> attribute 'auto': expected true or false, "
                                  "got '%s'", v);
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ <drawfilevtk/stl> */

/* The surface file of a drawing, beside the case file: it must open and be a closed surface
 * (the model's checker reads it again with the body; here the error can name the card). */
static int surface_file_ok(const XmlCtx *x, const xmlNode *n, const char *file,
                           const XmlMatrix *map, double lo[3], double hi[3], SrcLoc loc)
{
    char *path = source_beside(x->file, file), err[1024];
    double xf[12];
    sph_mesh mesh;
    if (map)
        xml_matrix_columns(map, xf);
    int rc = sph_mesh_load_moved(path, map ? xf : NULL, &mesh, err, sizeof err);
    if (rc)
        diag_error(loc, "<%s> attribute 'file': %s", xml_name(n), err);
    else {
        memcpy(lo, mesh.lo, sizeof mesh.lo);
        memcpy(hi, mesh.hi, sizeof mesh.hi);
        sph_mesh_free(&mesh);
    }
    free(path);
    return rc ? -1 : 0;
}

/* A closed surface from a file, filled (autofill="true"), under the transformation in force
 * and its own <drawscale> or <drawmove> (xml_file_transform).  The file is read and checked
 * with the body (check_body.c), relative to the case file. */
static int drawfile(XmlCtx *x, const xmlNode *n, int mk)
{
    static const char *const attrs[] = {"file", "objname", "autofill", NULL};
    SrcLoc loc = xml_loc(x, n);
    XmlMatrix m;
    if (xml_check_attrs(x, n, attrs) || xml_file_transform(x, n, &m))
        return -1;
    const char *file = xml_attr(n, "file"), *fill = xml_attr(n, "autofill");
    if (!file || !*file) {
        diag_error(loc, "<%s>: missing attribute 'file'", xml_name(n));
        return -1;
    }
    if (!fill || (strcmp(fill, "true") && strcmp(fill, "1"))) {
        diag_error(loc, "<%s>: without autofill=\"true\" GenCase puts particles on the surface "
                        "only; sphc fills closed surfaces: give autofill=\"true\"", xml_name(n));
        return -1;
    }
    if (mk == XML_MK_NONE)
        return no_mk(xml_name(n), loc);
    XmlDraw d = new_draw(x, XD_SURFACE, mk, loc);
    d.file = file;
    if (!xml_matrix_is_identity(&m)) {
        XmlMatrix *map = ast_alloc(sizeof *map);
        *map = m;
        d.map = map;
    }
    double lo[3], hi[3];
    if (surface_file_ok(x, n, file, d.map, lo, hi, loc))
        return -1;
    for (int a = 0; a < 3; a++) { /* the nodes of its bounding box */
        if (x->dim == 2 && a == 1) { /* a 2D case: its cut by the plane (the body's `plane`) */
            if (lo[1] > x->pmin[1] || hi[1] < x->pmin[1])
                return off_plane(x, xml_name(n), d.loc);
            continue;
        }
        if (draw_span(x, xml_name(n), a, lo[a], hi[a], &d))
            return -1;
    }
    return add_draw(x, &d);
}

/* ------------------------------------------------------------------ <drawprism/pyramid> */

/* In a 2D case a prism must be drawn along y (its top its base moved along y) across the
 * plane of the case: its cut is then the same at every y, and it is redrawn over the y of
 * both that plane and of the boxes' (0), so that a body of boxes and prisms has one plane. */
static int prism_in_plane(const XmlCtx *x, XmlDraw *d, const char *tag)
{
    const int m = d->npts / 2;
    const double dy = d->pts[3 * m + 1] - d->pts[1];
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k < m; k++) {
        const double *b = d->pts + 3 * k, *t = d->pts + 3 * (m + k);
        if (b[1] != d->pts[1] || t[0] != b[0] || t[2] != b[2] || t[1] - b[1] != dy || dy == 0) {
            diag_error(d->loc, "<%s> in a 2D case: only prisms drawn along y (the top "
                               "the base moved along y) are supported", tag);
            return -1;
        }
        lo = fmin(lo, fmin(b[1], t[1]));
        hi = fmax(hi, fmax(b[1], t[1]));
    }
    if (lo > x->pmin[1] + 1e-9 * x->dp || hi < x->pmin[1] - 1e-9 * x->dp)
        return off_plane(x, tag, d->loc);
    const double y0 = fmin(0.0, x->pmin[1]) - x->dp, y1 = fmax(0.0, x->pmin[1]) + x->dp;
    for (int k = 0; k < m; k++) {
        d->pts[3 * k + 1] = y0;
        d->pts[3 * (m + k) + 1] = y1;
    }
    return 0;
}

/* The solid's surface can be built (the model's checker builds it again with the body; here
 * the error can name the card). */
static int solid_ok(const XmlDraw *d, const char *tag)
{
    const char *what = d->kind == XD_PRISM ? "prism: " : "pyramid: ";
    char err[1024];
    sph_mesh mesh;
    if (sph_mesh_solid(d->kind == XD_PRISM ? SPH_SOLID_PRISM : SPH_SOLID_PYRAMID, d->pts,
                       d->npts, &mesh, err, sizeof err)) {
        const size_t len = strlen(what);
        diag_error(d->loc, "<%s>: %s", tag, strncmp(err, what, len) ? err : err + len);
        return -1;
    }
    sph_mesh_free(&mesh);
    return 0;
}

/* <drawprism> (the base's corners, then the top's, as many) and <drawpyramid> (the apex,
 * then the base's corners): the sph prism and pyramid (runtime/geom/mesh_solid.c).  The card's
 * mask chooses the faces GenCase draws in its face mode; a body is the filled solid. */
static int drawsolid(XmlCtx *x, const xmlNode *n, int mk)
{
    static const char *const attrs[] = {"mask", NULL};
    static const char *const kids[] = {"point", NULL};
    const int prism = xml_is(n, "drawprism");
    const char *tag = xml_name(n);
    XmlDraw d = new_draw(x, prism ? XD_PRISM : XD_PYRAMID, mk, xml_loc(x, n));
    int bad = xml_check_attrs(x, n, attrs) != 0;
    bad |= xml_check_children(x, n, kids) != 0;
    int npoints;
    d.pts = xml_points(x, n, 1, &npoints);
    d.npts = npoints;
    if (bad || !d.pts)
        return -1;
    if (prism ? npoints < 6 || npoints % 2 : npoints < 4) {
        diag_error(d.loc, "<%s> needs %s, got %d <point>s", tag,
                   prism ? "an even number of <point>s, at least 6 (the base's corners, then "
                           "the top's)"
                         : "at least 4 <point>s (the apex, then the base's corners)",
                   npoints);
        return -1;
    }
    if (mk == XML_MK_NONE)
        return no_mk(tag, d.loc);
    xml_matrix_points(&x->matrix, d.pts, d.npts);
    return add_solid(x, &d, tag);
}

/* A prism or pyramid d drawn by card tag, its corners transformed: checked in a 2D case,
 * built once to check it, and added with the nodes of its bounding box. */
static int add_solid(XmlCtx *x, XmlDraw *d, const char *tag)
{
    if (x->dim == 2 && d->kind == XD_PYRAMID) {
        diag_error(d->loc, "<drawpyramid>: pyramids are supported in 3D cases only");
        return -1;
    }
    if (x->dim == 2 && prism_in_plane(x, d, tag))
        return -1;
    if (solid_ok(d, tag))
        return -1;
    for (int a = 0; a < 3; a++) { /* the nodes of the bounding box */
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (int k = 0; k < d->npts; k++) {
            lo = fmin(lo, d->pts[3 * k + a]);
            hi = fmax(hi, d->pts[3 * k + a]);
        }
        if (!(x->dim == 2 && a == 1) && draw_span(x, tag, a, lo, hi, d))
            return -1;
    }
    return add_draw(x, d);
}

/* <drawextrude closed="true"> with the <point>s of a polygon and <extrude x y z>: the
 * prism whose top is the polygon moved by the extrusion vector.  (closed="false" draws
 * an open wall of the polyline, not a solid.) */
static int drawextrude(XmlCtx *x, const xmlNode *n, int mk)
{
    static const char *const attrs[] = {"closed", NULL};
    static const char *const kids[] = {"point", "extrude", NULL};
    XmlDraw d = new_draw(x, XD_PRISM, mk, xml_loc(x, n));
    int bad = xml_check_attrs(x, n, attrs) != 0;
    bad |= xml_check_children(x, n, kids) != 0;
    const char *closed = xml_attr(n, "closed");
    const xmlNode *ext = xml_child(n, "extrude");
    double v[3];
    int m;
    d.pts = xml_points(x, n, 2, &m); /* room for the top */
    bad |= !d.pts;
    if (!ext) {
        diag_error(d.loc, "<drawextrude> needs <extrude x=\"..\" y=\"..\" z=\"..\"/> (the "
                          "vector the polygon is extruded along)");
        return -1;
    }
    bad |= xml_point(x, ext, v) != 0;
    if (bad)
        return -1;
    if (closed && strcmp(closed, "true") && strcmp(closed, "1")) {
        diag_error(d.loc, "<drawextrude> attribute 'closed': only closed polygons (\"true\", "
                          "the default) extrude into a solid, got '%s'", closed);
        return -1;
    }
    if (m < 3) {
        diag_error(d.loc, "<drawextrude> needs at least 3 <point>s (the polygon's corners), "
                          "got %d", m);
        return -1;
    }
    if (mk == XML_MK_NONE)
        return no_mk("drawextrude", d.loc);
    for (int k = 0; k < m; k++)
        for (int a = 0; a < 3; a++)
            d.pts[3 * (m + k) + a] = d.pts[3 * k + a] + v[a];
    d.npts = 2 * m;
    xml_matrix_points(&x->matrix, d.pts, d.npts);
    return add_solid(x, &d, "drawextrude");
}

/* Drawings the importer does not handle yet. */
static int unsupported_drawing(const XmlCtx *x, const xmlNode *n)
{
    diag_error(xml_loc(x, n), "<%s>: this drawing command is not supported by the importer yet "
                              "(<drawbox>, <drawcylinder>, <drawsphere>, <drawprism>, "
                              "<drawpyramid>, <drawextrude>, <drawfilevtk> and <drawfilestl> are)",
               xml_name(n));
    return -1;
}

static int setmk(XmlCtx *x, const xmlNode *n, int *mk)
{
    static const char *const attrs[] = {"mk", NULL};
    static const char *const none[] = {NULL};
    long v;
    if (xml_is(n, "setmkvoid")) { /* what follows removes particles */
        if (xml_check_attrs(x, n, none))
            return -1;
        *mk = XML_MK_VOID;
        return 0;
    }
    if (xml_check_attrs(x, n, attrs) || xml_integer(x, n, "mk", 1, 0, 65535, &v) != 1)
        return -1;
    *mk = (int)v;
    return 0;
}

static int drawing(XmlCtx *x, const xmlNode *n, int mk)
{
    if (xml_is(n, "drawbox"))
        return drawbox(x, n, mk);
    if (xml_is(n, "drawcylinder"))
        return drawcylinder(x, n, mk);
    if (xml_is(n, "drawsphere"))
        return drawsphere(x, n, mk);
    if (xml_is(n, "drawfilevtk") || xml_is(n, "drawfilestl"))
        return drawfile(x, n, mk);
    if (xml_is(n, "drawprism") || xml_is(n, "drawpyramid"))
        return drawsolid(x, n, mk);
    if (xml_is(n, "drawextrude"))
        return drawextrude(x, n, mk);
    return unsupported_drawing(x, n);
}

/* <list>s run by <runlist> may run others: a list that runs itself stops here. */
#define MAX_LIST_DEPTH 32
/* Commands a case may run, lists included: lists that run lists many times would
 * otherwise run for ever in effect (10^5 times 10^5 moves). */
#define MAX_COMMANDS 1000000L

static int run_commands(XmlCtx *x, const xmlNode *list, int *mk, int depth);

/* <runlist name="L" times="k"/>: the commands of <list name="L"> k times (default 1). */
static int runlist(XmlCtx *x, const xmlNode *n, int *mk, int depth)
{
    static const char *const attrs[] = {"name", "times", NULL};
    long times = 1;
    if (xml_check_attrs(x, n, attrs) || xml_integer(x, n, "times", 0, 0, 100000, &times) < 0)
        return -1;
    const char *name = xml_attr(n, "name");
    const xmlNode *list = NULL;
    for (xmlNode *c = name ? xml_first(x->commands) : NULL; c && !list; c = xml_next(c)) {
        const char *cn = xml_is(c, "list") ? xml_attr(c, "name") : NULL;
        if (cn && !strcmp(cn, name))
            list = c;
    }
    if (!name) {
        diag_error(xml_loc(x, n), "<runlist>: missing attribute 'name'");
        return -1;
    }
    if (!list) {
        diag_error(xml_loc(x, n), "<runlist>: no <list name=\"%s\"> in <commands>", name);
        return -1;
    }
    if (depth >= MAX_LIST_DEPTH) {
        diag_error(xml_loc(x, n), "<runlist name=\"%s\">: lists run one another more than %d "
                                  "deep (does a list run itself?)", name, MAX_LIST_DEPTH);
        return -1;
    }
    for (long k = 0; k < times; k++)
        if (run_commands(x, list, mk, depth + 1))
            return -1;
    return 0;
}

static int command(XmlCtx *x, const xmlNode *n, int *mk, int depth)
{
    int rc = xml_transform_command(x, n);
    if (rc <= 0)
        return rc;
    if (xml_is(n, "newvar") || xml_is(n, "newvarcte") || xml_is(n, "setvar"))
        return newvar(x, n);
    if (xml_is(n, "setmkbound") || xml_is(n, "setmkvoid"))
        return setmk(x, n, mk);
    if (xml_is(n, "setmkfluid")) {
        diag_error(xml_loc(x, n), "<setmkfluid>: fluids are not supported (sphc simulates "
                                  "deformable solids)");
        return -1;
    }
    if (xml_is(n, "runlist"))
        return runlist(x, n, mk, depth);
    if (xml_is(n, "setfrdrawmode"))
        return setfrdrawmode(x, n);
    if (is_accepted(n))
        return 0;
    if (!strncmp(xml_name(n), "draw", 4))
        return drawing(x, n, *mk);
    diag_error(xml_loc(x, n), "<%s>: this GenCase command is not supported by the importer yet",
               xml_name(n));
    return -1;
}

/* The commands of the mainlist (depth 0; every error reported) or of a list (which stops at
 * its first error: it may be run many times). */
static int run_commands(XmlCtx *x, const xmlNode *list, int *mk, int depth)
{
    int bad = 0;
    for (xmlNode *c = xml_first(list); c; c = xml_next(c)) {
        if (++x->ncommands > MAX_COMMANDS) {
            if (x->ncommands == MAX_COMMANDS + 1)
                diag_error(xml_loc(x, c), "<%s>: the case runs more than %ld commands (its "
                                          "lists included)", xml_name(c), MAX_COMMANDS);
            return -1;
        }
        bad |= command(x, c, mk, depth) != 0;
        if (bad && depth > 0)
            return -1;
    }
    return bad ? -1 : 0;
}

/* <predefinition>: variables for <definition> itself. */
static int predefinition(XmlCtx *x, const xmlNode *n)
{
    static const char *const kids[] = {"newvar", "newvarcte", "setvar", NULL};
    int bad = xml_check_children(x, n, kids) != 0;
    for (xmlNode *c = xml_first(n); c; c = xml_next(c))
        bad |= newvar(x, c) != 0;
    return bad ? -1 : 0;
}

int xml_geometry(XmlCtx *x, const xmlNode *geometry)
{
    static const char *const kids[] = {"predefinition", "definition", "commands", NULL};
    static const char *const lists[] = {"mainlist", "list", NULL};
    if (xml_check_children(x, geometry, kids))
        return -1;
    const xmlNode *pre = xml_child(geometry, "predefinition");
    const xmlNode *def = xml_child(geometry, "definition");
    const xmlNode *commands = xml_child(geometry, "commands");
    const xmlNode *list = commands ? xml_child(commands, "mainlist") : NULL;
    if (!def || !list) {
        diag_error(xml_loc(x, geometry), "<geometry> needs <definition> and "
                                         "<commands><mainlist>");
        return -1;
    }
    if ((pre && predefinition(x, pre)) || definition(x, def) ||
        xml_check_children(x, commands, lists))
        return -1;
    x->commands = commands;
    xml_matrix_identity(&x->matrix);
    int mk = XML_MK_NONE;
    return run_commands(x, list, &mk, 0);
}

/* ------------------------------------------------------------------ drawn mks */

int xml_mk_drawn(const XmlCtx *x, int mk)
{
    for (int i = 0; i < x->ndraws; i++)
        if (x->draws[i].mk == mk)
            return 1;
    return 0;
}
