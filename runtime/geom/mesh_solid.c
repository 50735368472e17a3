/* mesh_solid.c — the closed surface of a prism or a pyramid given by its corners (mesh.h).
 *
 * A prism has a base polygon p_0 .. p_{m-1} and a top polygon q_0 .. q_{m-1}, corner k of
 * the one joined to corner k of the other (GenCase's <drawprism>: the first half of the
 * points, then the second); a pyramid has an apex and a base polygon (<drawpyramid>: the
 * apex first).  The polygons need not be convex, nor the top a translate of the base (a
 * frustum is a prism); each must be simple (its edges do not cross).
 *
 * Corners with equal coordinates are one vertex, so a polygon may repeat a corner (GenCase
 * cases do, to give a triangle and a quadrilateral the same number of points): a repeated
 * corner drops out of its polygon, and a side whose corners coincide drops out of the
 * sides.  Each polygon is cut into triangles by ear clipping in its own plane (the normal
 * of Newell's method), each side (p_k, p_k+1, q_k+1, q_k) into two triangles; the result
 * goes through sph_mesh_close like a surface read from a file, which orients it and checks
 * that it is closed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"

/* The index of the vertex at p, added when new (equal coordinates). */
static int vertex(sph_mesh *m, const double p[3])
{
    for (int i = 0; i < m->nv; i++)
        if (m->v[3 * i] == p[0] && m->v[3 * i + 1] == p[1] && m->v[3 * i + 2] == p[2])
            return i;
    memcpy(m->v + 3 * m->nv, p, 3 * sizeof(double));
    return m->nv++;
}

static void triangle(sph_mesh *m, int a, int b, int c)
{
    if (a == b || b == c || c == a)
        return; /* a side whose corners coincide */
    int *t = m->t + 3 * m->nt++;
    t[0] = a, t[1] = b, t[2] = c;
}

/* Vertex k projected on the plane of normal nrm, along its largest component. */
static void project(const sph_mesh *m, const double nrm[3], int k, double out[2])
{
    const int drop = fabs(nrm[0]) >= fabs(nrm[1]) && fabs(nrm[0]) >= fabs(nrm[2]) ? 0
                     : fabs(nrm[1]) >= fabs(nrm[2])                               ? 1
                                                                                   : 2;
    const double *p = m->v + 3 * k;
    const int u = (drop + 1) % 3, w = (drop + 2) % 3;
    /* keep the orientation: (u, w) is right-handed about the dropped axis; flip with the
     * normal's sign so that a counter-clockwise polygon stays counter-clockwise */
    out[0] = p[u];
    out[1] = nrm[drop] < 0 ? -p[w] : p[w];
}

static double cross2(const double a[2], const double b[2], const double c[2])
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Whether p lies in triangle abc (counter-clockwise), its edges included. */
static int in_triangle(const double a[2], const double b[2], const double c[2],
                       const double p[2])
{
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

/* Whether two edges of the projected polygon xy[0..n) that share no corner cross (ear
 * clipping alone can cut a star into triangles). */
static int edges_cross(double (*xy)[2], int n)
{
    for (int k = 0; k < n; k++)
        for (int l = k + 2; l < n; l++) {
            if (k == 0 && l == n - 1)
                continue; /* adjacent through corner 0 */
            const double *a = xy[k], *b = xy[(k + 1) % n], *c = xy[l], *d = xy[(l + 1) % n];
            if (cross2(a, b, c) * cross2(a, b, d) < 0 && cross2(c, d, a) * cross2(c, d, b) < 0)
                return 1;
        }
    return 0;
}

/* Triangles of the simple polygon poly[0..n) (vertex indices, no two consecutive equal) by
 * ear clipping.  Returns -1 when its edges cross or no ear can be found (corners on a
 * line). */
static int clip_ears(sph_mesh *m, const int *poly, int n)
{
    double nrm[3] = {0, 0, 0}; /* Newell's normal: the polygon's area vector, doubled */
    for (int k = 0; k < n; k++) {
        const double *p = m->v + 3 * poly[k], *q = m->v + 3 * poly[(k + 1) % n];
        nrm[0] += (p[1] - q[1]) * (p[2] + q[2]);
        nrm[1] += (p[2] - q[2]) * (p[0] + q[0]);
        nrm[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    double (*xy)[2] = malloc((size_t)n * sizeof *xy);
    for (int k = 0; k < n; k++)
        project(m, nrm, poly[k], xy[k]);
    int *at = malloc((size_t)n * sizeof *at); /* the remaining corners, as indices into xy */
    for (int k = 0; k < n; k++)
        at[k] = k;
    int left = n, rc = edges_cross(xy, n) ? -1 : 0;
    while (rc == 0 && left > 3) {
        int ear = -1;
        for (int k = 0; k < left && ear < 0; k++) {
            const int a = at[(k + left - 1) % left], b = at[k], c = at[(k + 1) % left];
            if (cross2(xy[a], xy[b], xy[c]) <= 0)
                continue; /* a reflex or straight corner is no ear */
            int empty = 1;
            for (int j = 0; j < left && empty; j++) {
                const int q = at[j];
                if (q != a && q != b && q != c && in_triangle(xy[a], xy[b], xy[c], xy[q]))
                    empty = 0;
            }
            if (empty)
                ear = k;
        }
        if (ear < 0) {
            rc = -1;
            break;
        }
        triangle(m, poly[at[(ear + left - 1) % left]], poly[at[ear]], poly[at[(ear + 1) % left]]);
        memmove(at + ear, at + ear + 1, (size_t)(left - ear - 1) * sizeof *at);
        left--;
    }
    if (rc == 0)
        triangle(m, poly[at[0]], poly[at[1]], poly[at[2]]);
    free(xy), free(at);
    return rc;
}

/* Polygon corners[0..n) as vertex indices without repeats in a row (the last against the
 * first too); returns how many remain. */
static int polygon(sph_mesh *m, const double *corners, int n, int *out)
{
    int k = 0;
    for (int i = 0; i < n; i++) {
        const int v = vertex(m, corners + 3 * i);
        if (k == 0 || out[k - 1] != v)
            out[k++] = v;
    }
    while (k > 1 && out[k - 1] == out[0])
        k--;
    return k;
}

static int fail(char *err, size_t len, const char *what, const char *msg)
{
    snprintf(err, len, "%s: %s", what, msg);
    return -1;
}

int sph_mesh_solid(sph_solid_kind kind, const double *pts, int npts, sph_mesh *m, char *err,
                   size_t len)
{
    const char *what = kind == SPH_SOLID_PRISM ? "prism" : "pyramid";
    const int m_corners = kind == SPH_SOLID_PRISM ? npts / 2 : npts - 1;
    memset(m, 0, sizeof *m);
    if (m_corners < 3 || (kind == SPH_SOLID_PRISM && npts % 2))
        return fail(err, len, what, kind == SPH_SOLID_PRISM
                                        ? "needs two polygons of the same number of corners, "
                                          "at least 3 each"
                                        : "needs an apex and at least 3 corners of its base");
    if (m_corners > SPH_SOLID_MAX_CORNERS) /* ear clipping takes up to m^3 steps */
        return fail(err, len, what, "has more than 1000 corners in a polygon (give such a "
                                    "shape as a surface file)");
    for (int k = 0; k < 3 * npts; k++) /* (a NaN would never equal a vertex kept) */
        if (!isfinite(pts[k]))
            return fail(err, len, what, "a corner's coordinate is not a finite number");
    m->file = strdup(what);
    m->v = malloc((size_t)npts * 3 * sizeof *m->v);
    m->t = malloc((size_t)(4 * npts + 8) * 3 * sizeof *m->t);
    int *base = malloc((size_t)npts * sizeof *base), *top = malloc((size_t)npts * sizeof *top);
    const double *bp = kind == SPH_SOLID_PRISM ? pts : pts + 3;
    int nb = polygon(m, bp, m_corners, base), nt = 0, rc = 0;
    if (nb < 3)
        rc = fail(err, len, what, "its base has fewer than 3 distinct corners");
    else if (clip_ears(m, base, nb))
        rc = fail(err, len, what, "its base is not a simple polygon (its edges cross, or "
                                  "its corners lie on a line)");
    if (!rc && kind == SPH_SOLID_PRISM) {
        nt = polygon(m, pts + 3 * m_corners, m_corners, top);
        if (nt < 3)
            rc = fail(err, len, what, "its top has fewer than 3 distinct corners");
        else if (clip_ears(m, top, nt))
            rc = fail(err, len, what, "its top is not a simple polygon (its edges cross, or "
                                      "its corners lie on a line)");
        for (int k = 0; !rc && k < m_corners; k++) { /* the sides, corner k to corner k */
            const int k1 = (k + 1) % m_corners;
            const int a = vertex(m, bp + 3 * k), b = vertex(m, bp + 3 * k1);
            const int c = vertex(m, pts + 3 * (m_corners + k1)),
                      d = vertex(m, pts + 3 * (m_corners + k));
            triangle(m, a, b, c);
            triangle(m, a, c, d);
        }
    } else if (!rc) {
        const int apex = vertex(m, pts);
        for (int k = 0; k < nb; k++)
            triangle(m, base[k], base[(k + 1) % nb], apex);
    }
    free(base), free(top);
    if (!rc && sph_mesh_close(m, err, len)) /* (it refuses a surface of no volume too) */
        rc = -1;
    if (rc)
        sph_mesh_free(m);
    return rc;
}
