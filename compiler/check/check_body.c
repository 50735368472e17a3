/* check_body.c — checking a body: its shape, material, settings, boundary conditions and
 * measurement planes. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check_body.h"
#include "check_expr.h"
#include "check_fracture.h"
#include "law_require.h"
#include "quad.h"
#include "seen_settings.h"
#include "model/admissible.h"
#include "model/elastic.h"
#include "lang/bc_kinds.h"
#include "util/diag.h"
#include "util/source.h"
#include "geom/mesh.h"
#include "core/limits.h"

/* ------------------------------------------------------------------ shapes */

static const Setting *find_arg(const NamedCall *c, const char *key)
{
    return ast_find_setting(&c->args, key);
}

/* Every argument must be one of `allowed`, given once, with one value (or, when several is
 * set, one or more): a string for `file`, numbers or vectors otherwise. */
static int check_arg_names(const NamedCall *c, const char *const *allowed, int nallowed,
                           int several)
{
    int bad = 0;
    for (int i = 0; i < c->args.n; i++) {
        const Setting *s = &c->args.items[i];
        int is_file = strcmp(s->key, "file") == 0;
        if (s->text && !is_file) {
            diag_error(s->loc, "argument '%s' of %s() takes a number, not a string", s->key,
                       c->name);
            bad = 1;
            continue;
        }
        if (is_file && !s->text) {
            diag_error(s->loc, "argument 'file' of %s() takes a file name in quotes", c->name);
            bad = 1;
            continue;
        }
        int ok = 0;
        for (int k = 0; k < nallowed; k++)
            ok |= strcmp(s->key, allowed[k]) == 0;
        if (!ok) {
            diag_error(s->loc, "unknown argument '%s' of %s()", s->key, c->name);
            bad = 1;
        }
        for (int j = 0; j < i; j++)
            if (strcmp(c->args.items[j].key, s->key) == 0) {
                diag_error(s->loc, "argument '%s' of %s() given twice", s->key, c->name);
                bad = 1;
            }
        if (s->text ? s->nvalues > 0 : !several && s->nvalues != 1) {
            diag_error(s->loc, "argument '%s' takes one value", s->key);
            bad = 1;
        }
    }
    return bad ? -1 : 0;
}

static int need_vec(const Model *m, const NamedCall *c, const char *key, double out[3])
{
    const Setting *s = find_arg(c, key);
    if (!s) {
        diag_error(c->loc, "%s() needs '%s'", c->name, key);
        return -1;
    }
    return check_vec3(m, s->values[0], key, out);
}

static int need_positive(const Model *m, const NamedCall *c, const char *key, double *out)
{
    const Setting *s = find_arg(c, key);
    if (!s) {
        diag_error(c->loc, "%s() needs '%s'", c->name, key);
        return -1;
    }
    if (check_const_expr(m, s->values[0], key, out))
        return -1;
    if (!(*out > 0)) {
        diag_error(s->values[0]->loc, "%s must be positive (got %g)", key, *out);
        return -1;
    }
    return 0;
}

static int check_box(const Model *m, const NamedCall *c, ShapePrim *p)
{
    static const char *const args[] = {"from", "to", "size"};
    if (check_arg_names(c, args, 3, 0))
        return -1;
    p->kind = SHAPE_BOX;
    if (need_vec(m, c, "from", p->a))
        return -1;
    int has_to = find_arg(c, "to") != NULL, has_size = find_arg(c, "size") != NULL;
    if (has_to == has_size) {
        diag_error(c->loc, "box() needs either 'to' or 'size'");
        return -1;
    }
    if (need_vec(m, c, has_to ? "to" : "size", p->b))
        return -1;
    for (int k = 0; k < 3; k++) {
        if (has_size)
            p->b[k] += p->a[k];
        if (p->b[k] < p->a[k]) {
            diag_error(c->loc, "box() extent is negative along %c", "xyz"[k]);
            return -1;
        }
    }
    return 0;
}

/* The map that moves a surface (sph_mesh_load_moved: the columns of its matrix, then the
 * translation) from `scale s`, or `matrix [row 1] [row 2] [row 3]`, and `move [b]`; p->pts
 * stays NULL when none is given. */
static int surface_map(const Model *m, const NamedCall *c, ShapePrim *p)
{
    const Setting *scale = find_arg(c, "scale"), *matrix = find_arg(c, "matrix");
    const Setting *move = find_arg(c, "move");
    double a[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, b[3] = {0, 0, 0};
    if (!scale && !matrix && !move)
        return 0;
    if (scale && matrix) {
        diag_error(matrix->loc, "surface() takes 'scale' or 'matrix', not both");
        return -1;
    }
    if ((scale && scale->nvalues != 1) || (move && move->nvalues != 1)) {
        diag_error((scale && scale->nvalues != 1 ? scale : move)->loc, "argument '%s' takes one "
                   "value", scale && scale->nvalues != 1 ? "scale" : "move");
        return -1;
    }
    if (matrix && matrix->nvalues != 3) {
        diag_error(matrix->loc, "argument 'matrix' takes the matrix's 3 rows (got %d)",
                   matrix->nvalues);
        return -1;
    }
    double sc = 1.0;
    if (scale && check_const_expr(m, scale->values[0], "scale", &sc))
        return -1;
    for (int r = 0; r < 3; r++) {
        if (matrix && check_vec3(m, matrix->values[r], "matrix", a[r]))
            return -1;
        a[r][r] *= sc;
    }
    if (move && check_vec3(m, move->values[0], "move", b))
        return -1;
    p->pts = ast_alloc(12 * sizeof *p->pts);
    p->npts = 4;
    for (int col = 0; col < 3; col++)
        for (int r = 0; r < 3; r++)
            p->pts[3 * col + r] = a[r][col];
    memcpy(p->pts + 9, b, sizeof b);
    const double det = sph_mesh_map_det(p->pts);
    if (!(fabs(det) > 0) || !isfinite(det)) {
        diag_error((matrix ? matrix : scale)->loc, "the %s %s the surface (its determinant is "
                   "%g)", matrix ? "matrix" : "scale", isfinite(det) ? "flattens" : "is too large for",
                   det);
        return -1;
    }
    return 0;
}

/* surface(file "name" [scale s | matrix [r1] [r2] [r3]] [move [b]]): the closed surface in a
 * VTK or STL file (runtime/geom/mesh.h), each point x of it moved to A x + b (A = s I or the
 * matrix), read and checked now and read again by the program, which gets its absolute
 * path. */
static int check_surface(const Model *m, const NamedCall *c, ShapePrim *p)
{
    static const char *const args[] = {"file", "scale", "matrix", "move"};
    p->kind = SHAPE_SURFACE;
    if (check_arg_names(c, args, 4, 1) || surface_map(m, c, p))
        return -1;
    const Setting *s = find_arg(c, "file");
    if (!s) {
        diag_error(c->loc, "surface() needs 'file', the name of a VTK or STL file");
        return -1;
    }
    char *path = source_beside(s->loc.file, s->text), err[1024], full[PATH_MAX];
    sph_mesh mesh;
    if (sph_mesh_load_moved(path, p->pts, &mesh, err, sizeof err)) {
        diag_error(s->loc, "%s", err);
        free(path);
        return -1;
    }
    for (int k = 0; k < 3; k++) {
        p->a[k] = mesh.lo[k];
        p->b[k] = mesh.hi[k];
    }
    p->volume = mesh.volume;
    p->file = realpath(path, full) ? strdup(full) : strdup(path);
    sph_mesh_free(&mesh);
    free(path);
    return 0;
}

/* The corners given after key (3 coordinates each) into p->pts from p->npts on. */
static int corners(const Model *m, const Setting *s, ShapePrim *p)
{
    for (int k = 0; k < s->nvalues; k++)
        if (check_vec3(m, s->values[k], s->key, p->pts + 3 * p->npts++))
            return -1;
    return 0;
}

/* prism(base [p1] [p2] .. top [q1] [q2] ..) and pyramid(apex [a] base [p1] [p2] ..), the
 * solids of GenCase's <drawprism> and <drawpyramid>: their surface (runtime/geom/mesh_solid.c)
 * is built and checked now, and again by the program from the same corners. */
static int check_solid(const Model *m, const NamedCall *c, ShapePrim *p)
{
    static const char *const prism_args[] = {"base", "top"}, *const pyramid_args[] = {"apex",
                                                                                     "base"};
    const int prism = strcmp(c->name, "prism") == 0;
    const char *const *args = prism ? prism_args : pyramid_args;
    p->kind = prism ? SHAPE_PRISM : SHAPE_PYRAMID;
    if (check_arg_names(c, args, 2, 1))
        return -1;
    const Setting *s0 = find_arg(c, args[0]), *s1 = find_arg(c, args[1]);
    if (!s0 || !s1) {
        diag_error(c->loc, "%s() needs '%s'", c->name, args[s0 ? 1 : 0]);
        return -1;
    }
    const Setting *base = prism ? s0 : s1;
    if (!prism && s0->nvalues != 1) {
        diag_error(s0->loc, "argument 'apex' takes one value");
        return -1;
    }
    if (base->nvalues < 3) {
        diag_error(base->loc, "the base of a %s needs at least 3 corners (got %d)", c->name,
                   base->nvalues);
        return -1;
    }
    if (prism && s1->nvalues != s0->nvalues) {
        diag_error(s1->loc, "the top has %d corners and the base %d: a prism joins corner k "
                   "of its base to corner k of its top", s1->nvalues, s0->nvalues);
        return -1;
    }
    p->pts = ast_alloc((size_t)(s0->nvalues + s1->nvalues) * 3 * sizeof *p->pts);
    if (corners(m, s0, p) || corners(m, s1, p))
        return -1;
    sph_mesh mesh;
    char err[1024];
    if (sph_mesh_solid(prism ? SPH_SOLID_PRISM : SPH_SOLID_PYRAMID, p->pts, p->npts, &mesh, err,
                       sizeof err)) {
        diag_error(c->loc, "%s", err);
        return -1;
    }
    for (int k = 0; k < 3; k++) {
        p->a[k] = mesh.lo[k];
        p->b[k] = mesh.hi[k];
    }
    p->volume = mesh.volume;
    sph_mesh_free(&mesh);
    return 0;
}

static int check_prim(const Model *m, const NamedCall *c, ShapePrim *p)
{
    memset(p, 0, sizeof *p);
    if (strcmp(c->name, "box") == 0)
        return check_box(m, c, p);
    if (strcmp(c->name, "cylinder") == 0) {
        static const char *const args[] = {"from", "to", "radius"};
        p->kind = SHAPE_CYLINDER;
        if (check_arg_names(c, args, 3, 0) || need_vec(m, c, "from", p->a) ||
            need_vec(m, c, "to", p->b) || need_positive(m, c, "radius", &p->r))
            return -1;
        return 0;
    }
    if (strcmp(c->name, "sphere") == 0) {
        static const char *const args[] = {"center", "radius"};
        p->kind = SHAPE_SPHERE;
        if (check_arg_names(c, args, 2, 0) || need_vec(m, c, "center", p->a) ||
            need_positive(m, c, "radius", &p->r))
            return -1;
        return 0;
    }
    if (strcmp(c->name, "surface") == 0)
        return check_surface(m, c, p);
    if (strcmp(c->name, "prism") == 0 || strcmp(c->name, "pyramid") == 0)
        return check_solid(m, c, p);
    diag_error(c->loc, "unknown shape '%s' (expected box, cylinder, sphere, surface, prism or "
               "pyramid)", c->name);
    return -1;
}

static void push_prim(Region *r, ShapePrim p)
{
    r->prims = ast_room(r->prims, (size_t)r->n, sizeof *r->prims); /* 50 000 drawings, say */
    r->prims[r->n++] = p;
}

/* Whether s is primitives joined by + only: a - (b + c) is (a - b) - c, in order. */
static int unions_only(const ShapeExpr *s)
{
    return s->op == 0 || (s->op == '+' && unions_only(s->lhs) && unions_only(s->rhs));
}

/* Flatten a shape tree into an ordered list: union adds, difference subtracts. */
static int flatten(const Model *m, const ShapeExpr *s, int subtract, Region *r)
{
    if (s->op == 0) {
        ShapePrim p;
        if (check_prim(m, &s->prim, &p))
            return -1;
        p.subtract = subtract;
        push_prim(r, p);
        return 0;
    }
    if (flatten(m, s->lhs, subtract, r))
        return -1;
    if (s->op == '-' && !unions_only(s->rhs)) {
        diag_error(s->rhs->loc, "only a shape or a union of shapes can be subtracted (write "
                                "a - b - c or a - (b + c))");
        return -1;
    }
    if (s->op == '+' && !unions_only(s->rhs)) { /* a + (b - c) is not (a + b) - c */
        diag_error(s->rhs->loc, "only a shape or a union of shapes can be added (write "
                                "a + b - c to cut c from both, or put the difference first)");
        return -1;
    }
    return flatten(m, s->rhs, s->op == '-' ? 1 : subtract, r);
}

static int check_region(const Model *m, const ShapeExpr *s, Region *r)
{
    memset(r, 0, sizeof *r);
    if (flatten(m, s, 0, r))
        return -1;
    if (r->prims[0].subtract) {
        diag_error(s->loc, "a shape cannot start with a subtraction");
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ material */

static const MaterialDef *find_law(const Model *m, const char *name)
{
    for (int i = 0; i < m->nlaws; i++)
        if (strcmp(m->laws[i]->name, name) == 0)
            return m->laws[i];
    return NULL;
}

/* Law parameters that are elastic constants, derived from the body's pair. */
static int elastic_param(const BodyModel *b, const char *name, double *out)
{
    if (!strcmp(name, "lambda")) *out = b->lambda;
    else if (!strcmp(name, "mu")) *out = b->mu;
    else if (!strcmp(name, "E")) *out = b->E;
    else if (!strcmp(name, "nu")) *out = b->nu;
    else if (!strcmp(name, "K")) *out = b->K;
    else if (!strcmp(name, "rho")) *out = b->rho0;
    else return 0;
    return 1;
}

/* One named argument of a material use: density, an elastic constant, or a law parameter. */
static int material_arg(const Model *m, const Setting *s, ElasticInput *el, BodyModel *b,
                        const MaterialDef *law, int *has_density)
{
    double v;
    if (s->text) {
        diag_error(s->loc, "argument '%s' takes a number, not a string", s->key);
        return -1;
    }
    if (s->nvalues != 1) {
        diag_error(s->loc, "argument '%s' takes one value", s->key);
        return -1;
    }
    if (check_const_expr(m, s->values[0], s->key, &v))
        return -1;
    const char *k = s->key;
    if (!strcmp(k, "density")) {
        if (check_admissible(s->values[0]->loc, "density", Q_DENSITY, v))
            return -1;
        b->rho0 = v;
        *has_density = 1;
    } else if (!strcmp(k, "young")) el->has_E = 1, el->E = v;
    else if (!strcmp(k, "poisson")) el->has_nu = 1, el->nu = v;
    else if (!strcmp(k, "lambda")) el->has_lambda = 1, el->lambda = v;
    else if (!strcmp(k, "shear") || !strcmp(k, "mu")) el->has_mu = 1, el->mu = v;
    else if (!strcmp(k, "bulk") || !strcmp(k, "K")) el->has_K = 1, el->K = v;
    else {
        for (int i = 0; i < law->nparams; i++)
            if (!strcmp(law->params[i], k)) {
                b->law_args[i] = v;
                return 0;
            }
        diag_error(s->loc, "material '%s' has no parameter '%s'", law->name, k);
        return -1;
    }
    return 0;
}

static int check_material_use(const Model *m, const NamedCall *c, BodyModel *b)
{
    const MaterialDef *law = find_law(m, c->name);
    if (!law) {
        diag_error(c->loc, "unknown material '%s' (is an 'import' missing?)", c->name);
        return -1;
    }
    b->law = law;
    b->law_args = calloc((size_t)law->nparams + 1, sizeof(double));
    for (int i = 0; i < law->nparams; i++)
        b->law_args[i] = NAN;
    ElasticInput el = {0};
    int has_density = 0, bad = 0;
    for (int i = 0; i < c->args.n; i++)
        bad |= material_arg(m, &c->args.items[i], &el, b, law, &has_density);
    if (bad)
        return -1;
    if (!has_density) {
        diag_error(c->loc, "material '%s' needs 'density'", law->name);
        return -1;
    }
    if (elastic_complete(&el, c->loc, b))
        return -1;
    for (int i = 0; i < law->nparams; i++) {
        if (elastic_param(b, law->params[i], &b->law_args[i]))
            continue;
        if (isnan(b->law_args[i])) {
            diag_error(c->loc, "material '%s' needs parameter '%s'", law->name,
                       law->params[i]);
            bad = 1;
        }
    }
    return bad ? -1 : 0;
}

/* ------------------------------------------------------------------ settings */

/* The one constant value of setting s, whose value is `what` (for the error). */
static int one_value(const Model *m, const Setting *s, const char *what, double *out)
{
    if (s->nvalues != 1) {
        diag_error(s->loc, "'%s' takes one value, %s", s->key, what);
        return -1;
    }
    return check_const_expr(m, s->values[0], s->key, out);
}

static int check_viscosity(const Model *m, const Setting *s, BodyModel *b)
{
    if (s->nvalues < 1 || s->nvalues > 2) {
        diag_error(s->loc, "'viscosity' takes beta1 and optionally beta2");
        return -1;
    }
    if (check_const_expr(m, s->values[0], "beta1", &b->beta1))
        return -1;
    b->beta2 = 0;
    if (s->nvalues == 2 && check_const_expr(m, s->values[1], "beta2", &b->beta2))
        return -1;
    const char *why = inadmissible(Q_VISCOSITY, b->beta1);
    why = why ? why : inadmissible(Q_VISCOSITY, b->beta2);
    if (why)
        diag_error(s->loc, "artificial viscosity coefficients %s", why);
    return why ? -1 : 0;
}

/* plane y0 (2D): the plane y = y0 in which the body's shapes are cut. */
static int check_plane(const Model *m, const Setting *s, BodyModel *b)
{
    if (one_value(m, s, "the y of the plane in which a 2D body's shapes are cut", &b->plane))
        return -1;
    if (m->dim != 2) {
        diag_error(s->loc, "'plane' is for 2D models, whose bodies lie in a plane y = const");
        return -1;
    }
    b->has_plane = 1;
    b->plane_loc = s->values[0]->loc;
    return 0;
}

/* `clamp P, N`: a point of the clamped plane and its normal, pointing into the body (in 2D
 * in the x-z plane); the normal is stored as a unit vector. */
static int check_clamp(const Model *m, const Setting *s, BodyModel *b)
{
    if (s->nvalues != 2) {
        diag_error(s->loc, "'clamp' takes a point of the clamped plane and the plane's normal "
                           "into the body: clamp [x, y, z], [nx, ny, nz]");
        return -1;
    }
    if (check_vec3(m, s->values[0], "the clamp's point", b->clamp_p) ||
        check_vec3(m, s->values[1], "the clamp's normal", b->clamp_n))
        return -1;
    if (m->dim == 2 && b->clamp_n[1] != 0) {
        diag_error(s->values[1]->loc, "a 2D body's clamp has its normal in the x-z plane "
                                      "(got y component %g)", b->clamp_n[1]);
        return -1;
    }
    const double n = sqrt(b->clamp_n[0] * b->clamp_n[0] + b->clamp_n[1] * b->clamp_n[1] +
                          b->clamp_n[2] * b->clamp_n[2]);
    if (!(n > 0) || !isfinite(n)) {
        diag_error(s->values[1]->loc, "the clamp's normal must be a nonzero vector");
        return -1;
    }
    for (int c = 0; c < 3; c++)
        b->clamp_n[c] /= n;
    b->has_clamp = 1;
    b->clamp_loc = s->loc;
    return 0;
}

/* The plane of a 2D body with `plane` must cut every surface, prism and pyramid of it (the
 * others take any plane). */
static int plane_cuts(const BodyModel *b)
{
    for (int k = 0; b->has_plane && k < b->region.n; k++) {
        const ShapePrim *s = &b->region.prims[k];
        const int cut = s->kind == SHAPE_SURFACE || s->kind == SHAPE_PRISM ||
                        s->kind == SHAPE_PYRAMID;
        if (!cut || (b->plane >= s->a[1] && b->plane <= s->b[1]))
            continue;
        diag_error(b->plane_loc, "the plane y = %g misses the body's %s, which spans y from %g "
                                 "to %g", b->plane, s->kind == SHAPE_SURFACE ? "surface"
                                 : s->kind == SHAPE_PRISM ? "prism" : "pyramid",
                   s->a[1], s->b[1]);
        return -1;
    }
    return 0;
}

/* The settings with members of their own (SET_OWN in model/body_settings.h), each with its
 * check. */
static const struct {
    const char *key;
    int (*check)(const Model *m, const Setting *s, BodyModel *b);
} OWN_SETTINGS[] = {
    {"viscosity", check_viscosity},
    {"plane", check_plane},
    {"clamp", check_clamp},
};

/* Setting s of row `row` of the table (model/body_settings.h) into body b. */
static int check_table_setting(const Model *m, const Setting *s, const BodySetting *row,
                               BodyModel *b)
{
    double v, *out = body_setting_number(b, row);
    switch (row->form) {
    case SET_INT:
        if (one_value(m, s, row->what, &v))
            return -1;
        if (inadmissible(Q_COUNT, v)) {
            diag_error(s->values[0]->loc, "'%s' %s (got %g)", s->key, inadmissible(Q_COUNT, v),
                       v);
            return -1;
        }
        *body_setting_int(b, row) = (int)v;
        return 0;
    case SET_NUMBER:
        if (one_value(m, s, row->what, out))
            return -1;
        return check_admissible(s->values[0]->loc, row->what, row->rule, *out);
    case SET_POINT:
        if (s->nvalues != 1) {
            diag_error(s->loc, "'%s' takes one point, %s", s->key, row->what);
            return -1;
        }
        if (check_vec3(m, s->values[0], s->key, out))
            return -1;
        *body_setting_given(b, row) = 1;
        return 0;
    case SET_OWN:
        for (size_t k = 0; k < sizeof OWN_SETTINGS / sizeof *OWN_SETTINGS; k++)
            if (!strcmp(s->key, OWN_SETTINGS[k].key))
                return OWN_SETTINGS[k].check(m, s, b);
        break;
    }
    diag_error(s->loc, "internal error: body setting '%s' has no check", s->key);
    return -1;
}

static int check_setting(const Model *m, const Setting *s, BodyModel *b)
{
    const BodySetting *row = body_setting_find(s->key);
    if (row)
        return check_table_setting(m, s, row, b);
    char expected[256] = "";
    for (int k = 0; k < BODY_NSETTINGS; k++) /* `restrict` is read with the fracture */
        snprintf(expected + strlen(expected), sizeof expected - strlen(expected), "%s, ",
                 BODY_SETTING_ROWS[k].keyword);
    expected[strlen(expected) - 2] = 0;
    diag_error(s->loc, "unknown body setting '%s' (expected %s or restrict)", s->key, expected);
    return -1;
}

/* ------------------------------------------------------------------ BCs, measures */

static int check_window(const Model *m, const BcDecl *d, BcModel *bc)
{
    bc->t0 = -INFINITY;
    bc->t1 = INFINITY;
    bc->has_window = d->t_from || d->t_to;
    if (d->t_from && check_const_expr(m, d->t_from, "start time", &bc->t0))
        return -1;
    if (d->t_to && check_const_expr(m, d->t_to, "end time", &bc->t1))
        return -1;
    if (bc->t1 < bc->t0) {
        diag_error(d->loc, "boundary condition ends (t = %g) before it starts (t = %g)",
                   bc->t1, bc->t0);
        return -1;
    }
    return 0;
}

static int check_bc(const Model *m, const BcDecl *d, BcModel *bc)
{
    memset(bc, 0, sizeof *bc);
    bc->kind = d->kind;
    bc->comps = d->comps;
    bc->value = d->value;
    bc->loc = d->loc;
    if (m->dim == 2 && (d->comps & 2)) {
        /* Plane strain: y is out of plane.  Prescribing it is allowed only as zero-motion
         * statements that users copy from 3D models; the value is ignored. */
        if (BC_KIND[d->kind].pass == BC_FORCE) {
            diag_error(d->comps_loc, "a force along y is not possible in a 2D (x-z) model");
            return -1;
        }
        bc->comps &= ~2;
    }
    ExprScope s = {m, NULL, 0, 1, 1, "a boundary condition"};
    int bad = check_scalar_expr(&s, d->value, 1);
    bad |= check_window(m, d, bc);
    if (d->near) {
        bc->has_near = 1;
        bad |= check_region(m, d->near, &bc->near);
    }
    return bad ? -1 : 0;
}

static int check_measure(const Model *m, const MeasureDecl *d, MeasureModel *ms)
{
    ms->name = d->name;
    ms->loc = d->loc;
    int bad = 0;
    for (int k = 0; k < 4; k++)
        bad |= check_vec3(m, d->points[k], "a plane corner", ms->p[k]);
    return bad || quad_spans(ms->p, d->loc, "measurement plane") ? -1 : 0;
}

/* ------------------------------------------------------------------ the body */

static int check_item(Model *m, const BodyItem *it, BodyModel *b, int *nshape, int *nmat)
{
    switch (it->kind) {
    case BI_SHAPE:
        if ((*nshape)++) {
            diag_error(it->loc, "body '%s' has more than one shape (combine them with + and -)",
                       b->name);
            return -1;
        }
        return check_region(m, it->shape, &b->region);
    case BI_MATERIAL:
        if ((*nmat)++) {
            diag_error(it->loc, "body '%s' has more than one material", b->name);
            return -1;
        }
        if (check_material_use(m, &it->material, b))
            return -1;
        return law_require_body(m, b, it->loc); /* with the elastic constants derived */
    case BI_SETTING:
        if (!strcmp(it->setting.key, "restrict"))
            return check_fracture_item(m, it, &b->fracture);
        return check_setting(m, &it->setting, b);
    case BI_BC:
        return check_bc(m, &it->bc, &b->bcs[b->nbcs++]);
    case BI_MEASURE:
        for (int i = 0; i < b->nmeasures; i++)
            if (!strcmp(b->measures[i].name, it->measure.name)) {
                diag_error(it->loc, "measurement '%s' defined twice", it->measure.name);
                return -1;
            }
        return check_measure(m, &it->measure, &b->measures[b->nmeasures++]);
    case BI_NOTCH:
    case BI_FRACTURE:
        return check_fracture_item(m, it, &b->fracture);
    }
    return -1;
}

/* The box around primitive p (a cylinder's and a surface's conservatively). */
static void prim_box(const ShapePrim *p, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        const double r = p->kind == SHAPE_CYLINDER || p->kind == SHAPE_SPHERE ? p->r : 0;
        const double b = p->kind == SHAPE_SPHERE ? p->a[k] : p->b[k];
        lo[k] = fmin(p->a[k], b) - r;
        hi[k] = fmax(p->a[k], b) + r;
    }
}

/* A body must be wider than its particle spacing along each of its axes (the others would
 * be one particle or none, without the neighbours the kernel correction needs), and a
 * shape subtracted must not take all of it: both would only be found, or found with the
 * wrong reason, when the program fills the body.  0, or -1 after reporting at loc. */
static int region_fits(const Model *m, const BodyModel *b, SrcLoc loc)
{
    const double dx = m->dp / b->refine;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < b->region.n; k++) {
        double plo[3], phi[3];
        if (b->region.prims[k].subtract)
            continue;
        prim_box(&b->region.prims[k], plo, phi);
        for (int c = 0; c < 3; c++)
            lo[c] = fmin(lo[c], plo[c]), hi[c] = fmax(hi[c], phi[c]);
    }
    double cells = 1; /* the lattice points of the box around the body */
    for (int c = 0; c < 3; c++)
        if (!(m->dim == 2 && c == 1))
            cells *= (hi[c] - lo[c]) / dx + 1;
    if (!(cells <= SPH_MAX_LATTICE_POINTS)) {
        diag_error(loc, "body '%s' spans %s%.3g lattice points of its spacing %g, more than the "
                        "%.0e a program fills (make dp larger or refine smaller)",
                   b->name, isfinite(cells) ? "some " : "more than ",
                   isfinite(cells) ? cells : DBL_MAX, dx, SPH_MAX_LATTICE_POINTS);
        return -1;
    }
    for (int c = 0; c < 3; c++) {
        if (m->dim == 2 && c == 1) /* the x-z plane */
            continue;
        if (hi[c] - lo[c] < dx) {
            diag_error(loc, "body '%s' is %g m across along %c, less than its particle spacing "
                            "%g: it would be one particle thick at most (make dp smaller or "
                            "refine larger)", b->name, hi[c] - lo[c], "xyz"[c], dx);
            return -1;
        }
    }
    int last_added = -1; /* the shapes apply in order: one added after a cut fills again */
    for (int k = 0; k < b->region.n; k++)
        if (!b->region.prims[k].subtract)
            last_added = k;
    for (int k = last_added + 1; k < b->region.n; k++) {
        const ShapePrim *p = &b->region.prims[k];
        int covers = p->kind == SHAPE_BOX;
        for (int c = 0; covers && c < 3; c++)
            covers = (m->dim == 2 && c == 1) ||
                     (fmin(p->a[c], p->b[c]) <= lo[c] && fmax(p->a[c], p->b[c]) >= hi[c]);
        if (covers) {
            diag_error(loc, "body '%s' is empty: the box subtracted as its shape's part %d "
                            "covers all of the rest", b->name, k + 1);
            return -1;
        }
    }
    return 0;
}

int check_body(Model *m, const BodyDecl *d, BodyModel *b)
{
    memset(b, 0, sizeof *b);
    b->name = d->name;
    b->loc = d->loc;
    body_settings_default(b);
    b->bcs = calloc((size_t)d->n + 1, sizeof *b->bcs);
    b->measures = calloc((size_t)d->n + 1, sizeof *b->measures);
    int nshape = 0, nmat = 0, bad = 0;
    SeenSettings seen = {0};
    char where[300];
    snprintf(where, sizeof where, "body '%s'", d->name);
    for (int i = 0; i < d->n; i++) {
        const BodyItem *it = &d->items[i];
        if (it->kind == BI_SETTING && setting_once(&seen, &it->setting, where)) {
            bad = 1;
            continue;
        }
        bad |= check_item(m, it, b, &nshape, &nmat) != 0;
    }
    seen_settings_free(&seen);
    if (!nshape) {
        diag_error(d->loc, "body '%s' has no shape", d->name);
        bad = 1;
    }
    if (!nmat) {
        diag_error(d->loc, "body '%s' has no material", d->name);
        bad = 1;
    }
    if (!bad && b->soundspeed > 0) /* after the material, which sets eq. 59's */
        b->c0 = b->soundspeed;
    for (int i = 0; !bad && i < d->n; i++)
        if (d->items[i].kind == BI_SHAPE)
            bad |= region_fits(m, b, d->items[i].loc) != 0;
    if (!bad)
        bad |= check_fracture_body(b, d) != 0 || plane_cuts(b) != 0;
    return bad ? -1 : 0;
}
