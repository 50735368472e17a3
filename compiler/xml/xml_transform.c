/* xml_transform.c — GenCase's transformation of the drawings: <move>, <rotate>,
 * <rotateline>, <scale>, <matrixreset>, <matrixsave>, <matrixload>.
 *
 * GenCase keeps one affine matrix M and draws every shape through it.  Each command
 * multiplies M on the right by its own matrix (M = M T), so of
 *
 *     <move x="1" y="0" z="0"/> <rotate ang="90" x="0" y="0" z="1"/> <drawbox>...
 *
 * the box is rotated first and then moved, as in OpenGL.  GenCase turns by -ang about the
 * axis (right-hand rule): <rotate ang="90" x="0" y="0" z="1"/> takes the point (1, 0, 0)
 * to (0, -1, 0).  <rotate ang x y z> turns about the line through the origin along
 * (x, y, z), <rotateline ang> about the line through its two <point>s.  <matrixsave/> pushes
 * M, <matrixload/> pops it, <matrixreset/> sets it to the identity.  xml_geometry.c maps
 * each drawing through M onto the sph shapes. */
#include <math.h>
#include <string.h>

#include "util/diag.h"
#include "geom/mesh.h"
#include "xml_internal.h"

/* Nesting of <matrixsave/> without <matrixload/>: far beyond any case, and finite. */
#define MAX_SAVED 256

void xml_matrix_identity(XmlMatrix *m)
{
    memset(m, 0, sizeof *m);
    for (int r = 0; r < 3; r++)
        m->a[r][r] = 1.0;
}

int xml_matrix_is_identity(const XmlMatrix *m)
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
            if (m->a[r][c] != (r == c ? 1.0 : 0.0))
                return 0;
    return 1;
}

void xml_matrix_point(const XmlMatrix *m, const double p[3], double out[3])
{
    double q[3];
    for (int r = 0; r < 3; r++)
        q[r] = m->a[r][0] * p[0] + m->a[r][1] * p[1] + m->a[r][2] * p[2] + m->a[r][3];
    memcpy(out, q, sizeof q);
}

/* Entries below this fraction of the largest are round-off of a turn by a multiple of 90
 * degrees (cos 90 = 6e-17), not a tilt. */
#define TILT_EPS 1e-12

static double largest_entry(const XmlMatrix *m)
{
    double big = 0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            big = fmax(big, fabs(m->a[r][c]));
    return big;
}

/* m = m t: t applies to a point first.  The round-off of turns by multiples of 90 degrees
 * is set to 0, so that such turns keep the axes exactly (a box a box, a 2D case's plane its
 * plane). */
static void right_multiply(XmlMatrix *m, const XmlMatrix *t)
{
    XmlMatrix o;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++) {
            double v = c == 3 ? m->a[r][3] : 0.0;
            for (int k = 0; k < 3; k++)
                v += m->a[r][k] * t->a[k][c];
            o.a[r][c] = v;
        }
    const double tol = TILT_EPS * largest_entry(&o);
    for (int r = 0; r < 3 && isfinite(tol); r++) /* (an overflow is reported, not hidden) */
        for (int c = 0; c < 3; c++)
            if (fabs(o.a[r][c]) <= tol)
                o.a[r][c] = 0.0;
    *m = o;
}

/* The rotation by -deg degrees about the line through p along v (Rodrigues' formula), the
 * sense GenCase turns in. */
static void rotation(double deg, const double p[3], const double v[3], XmlMatrix *t)
{
    const double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const double u[3] = {v[0] / len, v[1] / len, v[2] / len};
    const double th = -deg * (3.14159265358979323846 / 180.0), c = cos(th), s = sin(th);
    const double k[3][3] = {{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}};
    for (int r = 0; r < 3; r++) {
        for (int col = 0; col < 3; col++)
            t->a[r][col] = (r == col ? c : 0.0) + s * k[r][col] + (1.0 - c) * u[r] * u[col];
    }
    for (int r = 0; r < 3; r++) /* about p: x -> R (x - p) + p */
        t->a[r][3] = p[r] - (t->a[r][0] * p[0] + t->a[r][1] * p[1] + t->a[r][2] * p[2]);
}

/* The attributes names[0..2] of a command with the attributes attrs and no children. */
static int read_three(XmlCtx *x, const xmlNode *n, const char *const *attrs,
                      const char *const names[3], double v[3])
{
    static const char *const none[] = {NULL};
    int bad = xml_check_attrs(x, n, attrs) != 0;
    bad |= xml_check_children(x, n, none) != 0;
    for (int k = 0; k < 3; k++)
        bad |= xml_number(x, n, names[k], 1, &v[k]) != 1;
    return bad ? -1 : 0;
}

static int read_xyz(XmlCtx *x, const xmlNode *n, const char *const *attrs, double v[3])
{
    static const char *const xyz[] = {"x", "y", "z"};
    return read_three(x, n, attrs, xyz, v);
}

/* An error (-1) when the axis v of a turn has no direction. */
static int zero_axis(const XmlCtx *x, const xmlNode *n, const double v[3])
{
    if (v[0] != 0 || v[1] != 0 || v[2] != 0)
        return 0;
    diag_error(xml_loc(x, n), "<%s>: the axis of rotation has zero length", xml_name(n));
    return -1;
}

/* <rotate ang x y z/>: about the line through the origin along (x, y, z). */
static int rotate(XmlCtx *x, const xmlNode *n, XmlMatrix *t)
{
    static const char *const attrs[] = {"ang", "x", "y", "z", NULL};
    static const double origin[3] = {0, 0, 0};
    double v[3], deg;
    if (read_xyz(x, n, attrs, v) || xml_number(x, n, "ang", 1, &deg) != 1 || zero_axis(x, n, v))
        return -1;
    rotation(deg, origin, v, t);
    return 0;
}

/* <rotateline ang> with two <point>s: about the line through them. */
static int rotateline(XmlCtx *x, const xmlNode *n, XmlMatrix *t)
{
    static const char *const attrs[] = {"ang", NULL};
    static const char *const kids[] = {"point", NULL};
    double v[3], deg;
    int np, bad = xml_check_attrs(x, n, attrs) != 0;
    bad |= xml_check_children(x, n, kids) != 0;
    bad |= xml_number(x, n, "ang", 1, &deg) != 1;
    const double *p = xml_points(x, n, 1, &np);
    if (bad || !p)
        return -1;
    if (np != 2) {
        diag_error(xml_loc(x, n), "<rotateline> needs two <point>s (its axis), got %d", np);
        return -1;
    }
    for (int a = 0; a < 3; a++)
        v[a] = p[3 + a] - p[a];
    if (zero_axis(x, n, v))
        return -1;
    rotation(deg, p, v, t);
    return 0;
}

/* <move x y z/> (and a surface file's <drawmove>): by (x, y, z). */
static int move(XmlCtx *x, const xmlNode *n, XmlMatrix *t)
{
    static const char *const attrs[] = {"x", "y", "z", NULL};
    double d[3];
    if (read_xyz(x, n, attrs, d))
        return -1;
    for (int a = 0; a < 3; a++)
        t->a[a][3] = d[a];
    return 0;
}

/* <scale x y z/> (and a surface file's <drawscale>): along each axis, about the origin; none
 * may be 0. */
static int scale(XmlCtx *x, const xmlNode *n, XmlMatrix *t)
{
    static const char *const attrs[] = {"x", "y", "z", NULL};
    double s[3];
    if (read_xyz(x, n, attrs, s))
        return -1;
    for (int a = 0; a < 3; a++) {
        if (s[a] == 0) {
            diag_error(xml_loc(x, n), "<%s>: %c = 0 flattens %s", xml_name(n), "xyz"[a],
                       xml_is(n, "scale") ? "every drawing" : "the surface");
            return -1;
        }
        t->a[a][a] = s[a];
    }
    return 0;
}

/* A command without attributes or children. */
static int no_arguments(XmlCtx *x, const xmlNode *n)
{
    static const char *const none[] = {NULL};
    return xml_check_attrs(x, n, none) || xml_check_children(x, n, none) ? -1 : 0;
}

/* <matrixreset/>, <matrixsave/> (push M), <matrixload/> (pop it). */
static int matrix_stack(XmlCtx *x, const xmlNode *n)
{
    if (no_arguments(x, n))
        return -1;
    if (xml_is(n, "matrixreset")) {
        xml_matrix_identity(&x->matrix);
        return 0;
    }
    if (xml_is(n, "matrixsave")) {
        if (x->nsaved == MAX_SAVED) {
            diag_error(xml_loc(x, n), "<matrixsave>: more than %d matrices saved and not loaded",
                       MAX_SAVED);
            return -1;
        }
        x->saved = ast_room(x->saved, (size_t)x->nsaved, sizeof *x->saved);
        x->saved[x->nsaved++] = x->matrix;
        return 0;
    }
    if (!x->nsaved) {
        diag_error(xml_loc(x, n), "<matrixload>: no matrix was saved (<matrixsave/>) to load");
        return -1;
    }
    x->matrix = x->saved[--x->nsaved];
    return 0;
}

/* 0 when m is finite and flattens nothing, else -1 after reporting n. */
static int usable(const XmlCtx *x, const xmlNode *n, const XmlMatrix *m)
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 4; c++)
            if (!isfinite(m->a[r][c])) {
                diag_error(xml_loc(x, n), "<%s>: the transformation it makes has an entry "
                                          "that is not a finite number", xml_name(n));
                return -1;
            }
    double xf[12];
    xml_matrix_columns(m, xf);
    const double det = sph_mesh_map_det(xf);
    if (det == 0) { /* (a scale of 1e-13 beside 1 is round-off to the snapping above) */
        diag_error(xml_loc(x, n), "<%s>: the transformation it makes flattens the drawings",
                   xml_name(n));
        return -1;
    }
    if (!isfinite(det)) {
        diag_error(xml_loc(x, n), "<%s>: the transformation it makes is too large (its "
                                  "determinant is not a finite number)", xml_name(n));
        return -1;
    }
    return 0;
}

int xml_transform_command(XmlCtx *x, const xmlNode *n)
{
    if (xml_is(n, "matrixreset") || xml_is(n, "matrixsave") || xml_is(n, "matrixload"))
        return matrix_stack(x, n);
    XmlMatrix t;
    xml_matrix_identity(&t);
    int rc;
    if (xml_is(n, "move"))
        rc = move(x, n, &t);
    else if (xml_is(n, "rotate"))
        rc = rotate(x, n, &t);
    else if (xml_is(n, "rotateline"))
        rc = rotateline(x, n, &t);
    else if (xml_is(n, "scale"))
        rc = scale(x, n, &t);
    else
        return 1;
    if (rc)
        return -1;
    right_multiply(&x->matrix, &t);
    return usable(x, n, &x->matrix);
}

/* ------------------------------------------------------------------ a surface file's own */

/* <drawrotate angx angy angz/>: only all three 0 (GenCase's order of the three turns and
 * their sense are not documented). */
static int file_rotate(XmlCtx *x, const xmlNode *c)
{
    static const char *const attrs[] = {"angx", "angy", "angz", NULL};
    double v[3];
    int bad = read_three(x, c, attrs, attrs, v);
    if (bad || (v[0] == 0 && v[1] == 0 && v[2] == 0))
        return bad;
    diag_error(xml_loc(x, c), "<drawrotate> with an angle other than 0 is not supported (in "
                              "which order and sense GenCase turns by the three angles is not "
                              "documented): turn the surface with <rotate> before the drawing");
    return -1;
}

int xml_file_transform(XmlCtx *x, const xmlNode *n, XmlMatrix *map)
{
    static const char *const kids[] = {"drawscale", "drawmove", "drawrotate", NULL};
    XmlMatrix scale_t, move_t;
    xml_matrix_identity(&scale_t);
    xml_matrix_identity(&move_t);
    *map = x->matrix;
    if (xml_check_children(x, n, kids))
        return -1;
    int bad = 0, seen[3] = {0, 0, 0};
    for (xmlNode *c = xml_first(n); c; c = xml_next(c)) {
        const int k = xml_is(c, "drawscale") ? 0 : xml_is(c, "drawmove") ? 1 : 2;
        if (seen[k]++) {
            diag_error(xml_loc(x, c), "<%s> is given twice in <%s>", xml_name(c), xml_name(n));
            bad = 1;
        } else if (k == 2)
            bad |= file_rotate(x, c) != 0;
        else
            bad |= (k == 0 ? scale(x, c, &scale_t) : move(x, c, &move_t)) != 0;
    }
    if (bad)
        return -1;
    if (!xml_matrix_is_identity(&scale_t) && !xml_matrix_is_identity(&move_t)) {
        diag_error(xml_loc(x, n), "<%s> with both <drawscale> and <drawmove> is not supported "
                                  "(whether GenCase moves before or after it scales is not "
                                  "documented): give the move and the scale as <move> and "
                                  "<scale> before the drawing, in the order meant",
                   xml_name(n));
        return -1;
    }
    right_multiply(map, &move_t); /* (one of the two is the identity) */
    right_multiply(map, &scale_t);
    return usable(x, n, map);
}

/* ------------------------------------------------------------------ what M keeps */

/* (right_multiply has set the round-off of quarter turns to 0: the zeros are exact.) */
int xml_matrix_keeps_axes(const XmlMatrix *m)
{
    for (int r = 0; r < 3; r++)
        if ((m->a[r][0] != 0) + (m->a[r][1] != 0) + (m->a[r][2] != 0) != 1)
            return 0;
    return 1;
}

double xml_matrix_similarity(const XmlMatrix *m)
{
    /* M's linear part L is s Q (Q orthogonal) when L^T L = s^2 I. */
    double g[3][3], s2 = 0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            g[i][j] = 0;
            for (int k = 0; k < 3; k++)
                g[i][j] += m->a[k][i] * m->a[k][j];
        }
    s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (fabs(g[i][j] - (i == j ? s2 : 0.0)) > 1e-9 * s2)
                return 0.0;
    return sqrt(s2);
}

int xml_matrix_keeps_y(const XmlMatrix *m)
{
    return m->a[1][0] == 0 && m->a[1][2] == 0 && m->a[0][1] == 0 && m->a[2][1] == 0;
}

void xml_matrix_points(const XmlMatrix *m, double *pts, int n)
{
    for (int k = 0; k < n; k++)
        xml_matrix_point(m, pts + 3 * k, pts + 3 * k);
}

void xml_matrix_columns(const XmlMatrix *m, double xf[12])
{
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 3; r++)
            xf[3 * c + r] = m->a[r][c];
}
