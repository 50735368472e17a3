/* xml_shape.c — the drawings of an mk as an sph shape: of a body, or of the auxiliary
 * geometry of a `near`.
 *
 * A <drawbox> is the sph box around the nodes it covers, [first node - dp/2, last node +
 * dp/2] (xml_geometry.c), a <drawcylinder> or <drawsphere> the sph cylinder or sphere as
 * drawn (a 2D case's sphere: the disc in its plane), a <drawfilevtk> or
 * <drawfilestl> the sph surface of its file.  A later drawing with another mk takes its
 * nodes over from the earlier ones, so the shape of an mk is its drawings in drawing order
 * less the later drawings of other mks that overlap them; drawings after <setmkvoid/> (mk
 * XML_MK_VOID) are such drawings of no body.
 *
 * Bodies (docs/xml.md, "Geometry"): sph fills cell centres inside the shape, so a drawn
 * cylinder or surface keeps its true volume.  A body whose boxes are joined by other
 * drawings gets the lattice of GenCase's nodes (`lattice` at pointmin - dp/2), so that its
 * boxes stay exactly GenCase's.  With --xml-fill=gencase every body with a drawing other
 * than a box gets that lattice, and so the nodes GenCase would fill: those inside the drawn
 * shape or on its surface; a cylinder drawn in free drawing mode instead gets the lattice
 * and the grown cylinder that reproduce the one count known of GenCase's free drawing
 * (docs/xml.md): a lattice with a cell corner on the axis across it and a layer on the first
 * end point along it, filled within dp / sqrt(2) of the cylinder. */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "xml_internal.h"

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

static ShapeExpr *cylinder_shape(const double a[3], const double b[3], double r, SrcLoc loc)
{
    NamedCall call = {ast_strdup("cylinder"), loc, {0}};
    ast_push_setting(&call.args, ast_setting(loc, "from", vec3(loc, a)));
    ast_push_setting(&call.args, ast_setting(loc, "to", vec3(loc, b)));
    ast_push_setting(&call.args, ast_setting(loc, "radius", ast_num(loc, r)));
    return ast_shape_prim(call);
}

static ShapeExpr *sphere_shape(const XmlDraw *d)
{
    NamedCall call = {ast_strdup("sphere"), d->loc, {0}};
    ast_push_setting(&call.args, ast_setting(d->loc, "center", vec3(d->loc, d->p[0])));
    ast_push_setting(&call.args, ast_setting(d->loc, "radius", ast_num(d->loc, d->r)));
    return ast_shape_prim(call);
}

/* surface(file "..."), under a transformation with its matrix (rows) and move. */
static ShapeExpr *surface_shape(const XmlDraw *d)
{
    NamedCall call = {ast_strdup("surface"), d->loc, {0}};
    ast_push_setting(&call.args, ast_setting_text(d->loc, "file", d->file));
    if (d->map) { /* (a quarter turn's round-off is 0 already: xml_transform.c) */
        double row[3][3], move[3];
        for (int r = 0; r < 3; r++) {
            memcpy(row[r], d->map->a[r], sizeof row[r]);
            move[r] = d->map->a[r][3];
        }
        Setting m = ast_setting(d->loc, "matrix", vec3(d->loc, row[0]));
        ast_push_expr(&m.values, &m.nvalues, vec3(d->loc, row[1]));
        ast_push_expr(&m.values, &m.nvalues, vec3(d->loc, row[2]));
        ast_push_setting(&call.args, m);
        ast_push_setting(&call.args, ast_setting(d->loc, "move", vec3(d->loc, move)));
    }
    return ast_shape_prim(call);
}

/* prism(base [..] .. top [..] ..), pyramid(apex [..] base [..] ..): the card's corners */
static ShapeExpr *solid_shape(const XmlDraw *d)
{
    const int prism = d->kind == XD_PRISM, first = prism ? d->npts / 2 : 1;
    NamedCall call = {ast_strdup(prism ? "prism" : "pyramid"), d->loc, {0}};
    Setting s0 = ast_setting(d->loc, prism ? "base" : "apex", vec3(d->loc, d->pts));
    Setting s1 = ast_setting(d->loc, prism ? "top" : "base", vec3(d->loc, d->pts + 3 * first));
    for (int k = 1; k < first; k++)
        ast_push_expr(&s0.values, &s0.nvalues, vec3(d->loc, d->pts + 3 * k));
    for (int k = first + 1; k < d->npts; k++)
        ast_push_expr(&s1.values, &s1.nvalues, vec3(d->loc, d->pts + 3 * k));
    ast_push_setting(&call.args, s0);
    ast_push_setting(&call.args, s1);
    return ast_shape_prim(call);
}

static ShapeExpr *draw_shape(const XmlCtx *x, const XmlDraw *d)
{
    if (d->kind == XD_PRISM || d->kind == XD_PYRAMID)
        return solid_shape(d);
    if (d->kind == XD_CYLINDER)
        return cylinder_shape(d->p[0], d->p[1], d->r, d->loc);
    if (d->kind == XD_SURFACE)
        return surface_shape(d);
    if (d->kind == XD_SPHERE)
        return sphere_shape(d);
    return box_shape(x, d);
}

static int overlap(const XmlDraw *a, const XmlDraw *b)
{
    for (int k = 0; k < 3; k++)
        if (a->hi[k] < b->lo[k] || b->hi[k] < a->lo[k])
            return 0;
    return 1;
}

/* Whether draw i overlaps one of mk's draws before it; `before` holds the nodes of their
 * bounding box (lo > hi: none), which most draws of other mks miss. */
static int takes_over(const XmlCtx *x, int i, int mk, const XmlDraw *before)
{
    if (!overlap(before, &x->draws[i]))
        return 0;
    for (int j = 0; j < i; j++)
        if (x->draws[j].mk == mk && overlap(&x->draws[j], &x->draws[i]))
            return 1;
    return 0;
}

/* Grows the node box `box` to cover draw d. */
static void cover(XmlDraw *box, const XmlDraw *d)
{
    for (int k = 0; k < 3; k++) {
        box->lo[k] = d->lo[k] < box->lo[k] ? d->lo[k] : box->lo[k];
        box->hi[k] = d->hi[k] > box->hi[k] ? d->hi[k] : box->hi[k];
    }
}

/* The union of shapes p[0..n-1] as a balanced tree (union is associative), so that an mk
 * of thousands of drawings nests some log2 levels, not thousands; for n <= 3 it is the
 * left-to-right union ((p0 + p1) + p2). */
static ShapeExpr *union_of(SrcLoc loc, ShapeExpr **p, int n)
{
    if (n == 1)
        return p[0];
    const int left = (n + 1) / 2;
    return ast_shape_op(loc, '+', union_of(loc, p, left), union_of(loc, p + left, n - left));
}

/* mk's drawings in order, less the overlapping later drawings of other mks; `own` (may be
 * NULL) replaces mk's own drawing number `which` (-1: none).  A run of drawings of one kind
 * (mk's own, or others' taking nodes over) is joined first: ((a + b) - c) - d is
 * (a + b) - (c + d). */
static ShapeExpr *combine(const XmlCtx *x, int mk, SrcLoc loc, int which, ShapeExpr *own)
{
    ShapeExpr *s = NULL, **run = ast_alloc(((size_t)x->ndraws + 1) * sizeof *run);
    XmlDraw mine_box = {0};
    int nrun = 0, adding = 1;
    for (int k = 0; k < 3; k++)
        mine_box.lo[k] = LONG_MAX, mine_box.hi[k] = LONG_MIN; /* empty */
    for (int i = 0; i <= x->ndraws; i++) {
        const XmlDraw *d = i < x->ndraws ? &x->draws[i] : NULL;
        const int mine = d && d->mk == mk;
        const int other = d && !mine && takes_over(x, i, mk, &mine_box);
        if (mine)
            cover(&mine_box, d);
        if (nrun && (!d || (mine && !adding) || (other && adding))) {
            ShapeExpr *u = union_of(loc, run, nrun);
            s = !s ? u : ast_shape_op(loc, adding ? '+' : '-', s, u);
            nrun = 0;
        }
        if (mine || other) {
            adding = mine;
            run[nrun++] = !mine ? draw_shape(x, d) : i == which ? own : draw_shape(x, d);
        }
    }
    free(run);
    if (s && s->depth > AST_MAX_DEPTH - 2) { /* thousands of alternations: walks would overflow
                                               (2 levels kept for within_domain's cut) */
        diag_error(loc, "the drawings of mk %d and the later drawings of other mks that take "
                        "nodes over from them alternate more than %d times",
                   mk, (AST_MAX_DEPTH - 2) / 2);
        return NULL;
    }
    return s;
}

/* Where a shape is cut on side `side` of the domain (2a: below, 2a + 1: above along axis a).
 * GenCase has no node beyond the domain, and on its node lattice the cut lies half a
 * spacing past the first or last node.  A free-drawn cylinder's lattice is its own
 * (freedraw_cylinder), with layers that may fall on those planes: GenCase keeps its
 * particles inside [pointmin, pointmax], so it is cut there (a millionth of a spacing out). */
static double cut_plane(const XmlCtx *x, int side, int free)
{
    const int a = side / 2;
    const double past = free ? 1e-6 * x->dp : 0.5 * x->dp;
    if (side % 2)
        return (free ? x->pmax[a] : x->pmin[a] + (double)x->nodes[a] * x->dp) + past;
    return x->pmin[a] - past;
}

/* The slab beyond the cut on side `side` covering what of [lo, hi] lies there. */
static ShapeExpr *slab(const XmlCtx *x, int side, int free, const double lo[3],
                       const double hi[3], SrcLoc loc)
{
    const int a = side / 2;
    double from[3], to[3];
    for (int k = 0; k < 3; k++) {
        const int flat = x->dim == 2 && k == 1; /* boxes of a 2D case span y = 0 only */
        from[k] = flat ? 0.0 : xml_snap(lo[k] - x->dp, 1e-9 * x->dp);
        to[k] = flat ? 0.0 : xml_snap(hi[k] + x->dp, 1e-9 * x->dp);
    }
    const double plane = xml_snap(cut_plane(x, side, free), 1e-12 * x->dp);
    if (side % 2)
        from[a] = plane;
    else
        to[a] = plane;
    NamedCall call = {ast_strdup("box"), loc, {0}};
    ast_push_setting(&call.args, ast_setting(loc, "from", vec3(loc, from)));
    ast_push_setting(&call.args, ast_setting(loc, "to", vec3(loc, to)));
    return ast_shape_prim(call);
}

/* s less what of mk's drawings lies beyond the domain (a box's nodes are clipped already,
 * xml_geometry.c): s - (slab + slab ...), one slab per side some drawing reaches past.
 * free: mk is one free-drawn cylinder, grown by `grow` (freedraw_cylinder). */
static ShapeExpr *within_domain(const XmlCtx *x, int mk, ShapeExpr *s, int free, double grow,
                                SrcLoc loc)
{
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    int beyond = 0;
    for (int i = 0; i < x->ndraws; i++) {
        const XmlDraw *d = &x->draws[i];
        if (d->mk != mk || d->kind == XD_BOX)
            continue;
        for (int a = 0; a < 3; a++) {
            if (x->dim == 2 && a == 1)
                continue; /* (the plane of the case) */
            const double dlo = d->reach[0][a] - grow, dhi = d->reach[1][a] + grow;
            const int below = dlo < cut_plane(x, 2 * a, free);
            const int above = dhi > cut_plane(x, 2 * a + 1, free);
            beyond |= below << 2 * a | above << (2 * a + 1);
            lo[a] = fmin(lo[a], dlo);
            hi[a] = fmax(hi[a], dhi);
        }
    }
    if (!s || !beyond)
        return s;
    ShapeExpr *cut[6];
    int n = 0;
    for (int side = 0; side < 6; side++)
        if (beyond >> side & 1)
            cut[n++] = slab(x, side, free, lo, hi, loc);
    return ast_shape_op(loc, '-', s, union_of(loc, cut, n));
}

ShapeExpr *xml_mk_shape(const XmlCtx *x, int mk, SrcLoc loc)
{
    return within_domain(x, mk, combine(x, mk, loc, -1, NULL), 0, 0.0, loc);
}

int xml_mk_boxes_only(const XmlCtx *x, int mk)
{
    for (int i = 0; i < x->ndraws; i++)
        if (x->draws[i].mk == mk && x->draws[i].kind != XD_BOX)
            return 0;
    return 1;
}

/* The axis (0..2) a cylinder is parallel to, or -1 for an oblique one. */
static int cylinder_axis(const XmlDraw *d)
{
    double u[3], len = 0;
    for (int a = 0; a < 3; a++) {
        u[a] = d->p[1][a] - d->p[0][a];
        len = fmax(len, fabs(u[a]));
    }
    int axis = -1;
    for (int a = 0; a < 3; a++)
        if (fabs(u[a]) > 1e-12 * len) {
            if (axis >= 0)
                return -1;
            axis = a;
        }
    return axis;
}

/* GenCase's free drawing of a cylinder as sphc models it (the header comment): the grown
 * cylinder and the lattice corner. */
static ShapeExpr *freedraw_cylinder(const XmlCtx *x, const XmlDraw *d, int axis,
                                    double corner[3])
{
    double e = x->dp / sqrt(2.0), a[3], b[3], len = fabs(d->p[1][axis] - d->p[0][axis]);
    for (int k = 0; k < 3; k++) {
        double w = k == axis && len > 0 ? (d->p[1][k] - d->p[0][k]) / len : 0.0;
        a[k] = xml_snap(d->p[0][k] - e * w, 1e-12 * x->dp);
        b[k] = xml_snap(d->p[1][k] + e * w, 1e-12 * x->dp);
        corner[k] = xml_snap(k == axis ? d->p[0][k] - 0.5 * x->dp : d->p[0][k], 1e-12 * x->dp);
    }
    return cylinder_shape(a, b, xml_snap(d->r + e, 1e-12 * x->dp), d->loc);
}

/* GenCase's nodes as cell centres: a cell corner at pointmin - dp/2. */
static void node_corner(const XmlCtx *x, double corner[3])
{
    for (int a = 0; a < 3; a++)
        corner[a] = xml_snap(x->pmin[a] - 0.5 * x->dp, 1e-9 * x->dp);
}

ShapeExpr *xml_mk_body_shape(const XmlCtx *x, int mk, SrcLoc loc, int *has_corner,
                             double corner[3])
{
    int nown = 0, nboxes = 0, free_cyl = -1;
    for (int i = 0; i < x->ndraws; i++)
        if (x->draws[i].mk == mk) {
            nown++;
            nboxes += x->draws[i].kind == XD_BOX;
            if (x->draws[i].kind == XD_CYLINDER && x->draws[i].freedraw && free_cyl < 0)
                free_cyl = i;
        }
    *has_corner = 0;
    if (!x->opt.fill_gencase) {
        if (nboxes && nboxes < nown) {
            *has_corner = 1;
            node_corner(x, corner);
        }
        return xml_mk_shape(x, mk, loc);
    }
    if (free_cyl >= 0) {
        const XmlDraw *d = &x->draws[free_cyl];
        int axis = cylinder_axis(d);
        if (nown > 1) {
            diag_error(d->loc, "<drawcylinder>: with --xml-fill=gencase, a cylinder drawn in free "
                               "drawing mode (<setfrdrawmode auto=\"true\"/>) must be the only "
                               "drawing of its mk (%d)", mk);
            return NULL;
        }
        if (axis >= 0) {
            *has_corner = 1;
            ShapeExpr *grown = freedraw_cylinder(x, d, axis, corner);
            return within_domain(x, mk, combine(x, mk, loc, free_cyl, grown), 1,
                                 x->dp / sqrt(2.0), loc);
        }
        diag_warning(d->loc, "<drawcylinder>: with --xml-fill=gencase, sphc models free drawing "
                             "for cylinders along x, y or z only; this one is filled with "
                             "GenCase's lattice nodes");
    }
    if (nboxes < nown) {
        *has_corner = 1;
        node_corner(x, corner);
    }
    return xml_mk_shape(x, mk, loc);
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
