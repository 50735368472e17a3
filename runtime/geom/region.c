/* region.c — regions built from boxes, cylinders, spheres and closed surfaces.
 *
 * A region is evaluated left to right: a primitive with subtract = 0 is added to (united
 * with) what comes before it, one with subtract = 1 is removed from it.  Membership is
 * inclusive (points on a primitive's surface belong to it; so a point on the surface of a
 * subtracted primitive is removed).
 *
 * Primitives:
 *  - box: axis-aligned [min(a,b), max(a,b)] per axis;
 *  - cylinder: points within r of the segment a-b whose projection on the axis lies
 *    between a and b (flat caps).  A cylinder of zero length (a == b) is treated as a
 *    sphere of radius r around a (this is what a y-axis cylinder becomes in 2D);
 *  - sphere: centre a, radius r;
 *  - mesh: the inside of the closed surface in file (mesh.h; loaded on first use), on its
 *    surface included; its signed distance is the distance to the nearest triangle;
 *  - prism, pyramid: as a mesh, the surface built from the corners (mesh_solid.c).
 *
 * Distance: every primitive has an exact signed distance sd (negative inside); the region's
 * value is folded in order with the usual CSG rules, union s = min(s, sd) and difference
 * s = max(s, -sd), and the distance is max(s, 0).  This is exact for one primitive and for
 * unions; for differences it is the standard CSG approximation, a lower bound of the
 * true distance (it can underestimate it, e.g. inside a subtracted hole far from the rest),
 * and it is 0 exactly on the region.
 *
 * 2D (plane strain in x-z, dim == 2): every primitive is replaced by its x-z version placed
 * in the plane y = p[1] of the tested point: a box ignores its y extent (a box with
 * a.y == b.y still covers the plane), a sphere becomes the disc of radius r around (a.x, a.z),
 * a cylinder becomes the rectangle of half-width r around its x-z projected axis, or the disc
 * of radius r when the axis is along y (projected axis of zero length), and a mesh is cut by
 * the plane.
 * The *_dim functions below are exported for fill.c and select.c (declared in region.h).
 */
#include <math.h>

#include "mesh.h"
#include "region.h"

/* Signed distance to an axis-aligned box (exact). */
static double box_sd(const sph_shape *s, const double p[3])
{
    double out2 = 0.0, in = -HUGE_VAL;
    for (int k = 0; k < 3; k++) {
        double lo = fmin(s->a[k], s->b[k]), hi = fmax(s->a[k], s->b[k]);
        double e = fmax(lo - p[k], p[k] - hi);
        if (e > 0.0)
            out2 += e * e;
        in = fmax(in, e);
    }
    return out2 > 0.0 ? sqrt(out2) : fmin(in, 0.0);
}

/* Signed distance to a sphere of radius rad around c (exact). */
static double ball_sd(const double c[3], double rad, const double p[3])
{
    double d[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] };
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - rad;
}

/* Signed distance to a flat-capped cylinder (exact). */
static double cylinder_sd(const sph_shape *s, const double p[3])
{
    double ba[3], ap[3], len2 = 0.0, t = 0.0, rad2 = 0.0;
    for (int k = 0; k < 3; k++) {
        ba[k] = s->b[k] - s->a[k];
        ap[k] = p[k] - s->a[k];
        len2 += ba[k] * ba[k];
    }
    if (len2 == 0.0)
        return ball_sd(s->a, s->r, p);
    double len = sqrt(len2);
    for (int k = 0; k < 3; k++)
        t += ap[k] * ba[k] / len;
    for (int k = 0; k < 3; k++) {
        double d = ap[k] - t * ba[k] / len;
        rad2 += d * d;
    }
    double ea = fmax(-t, t - len), er = sqrt(rad2) - s->r;
    double oa = fmax(ea, 0.0), orad = fmax(er, 0.0);
    return sqrt(oa * oa + orad * orad) + fmin(fmax(ea, er), 0.0);
}

/* The x-z (2D) version of primitive s, placed in the plane y = y (see header comment). */
static sph_shape prim_in_plane(const sph_shape *s, double y)
{
    sph_shape o = *s;
    if (s->kind == SPH_BOX) {
        o.a[1] = -HUGE_VAL;
        o.b[1] = HUGE_VAL;
    } else if (s->kind == SPH_CYLINDER || s->kind == SPH_SPHERE) {
        o.a[1] = o.b[1] = y;
    }
    return o;
}

/* Primitive s as seen in dimension dim at a point with y coordinate y. */
static sph_shape prim_for_dim(const sph_shape *s, int dim, double y)
{
    return dim == 2 ? prim_in_plane(s, y) : *s;
}

/* The closed surface of a mesh, prism or pyramid; NULL for the other primitives. */
static const sph_mesh *prim_mesh(const sph_shape *s)
{
    switch (s->kind) {
    case SPH_MESH: return sph_mesh_get(s->file, s->pts);
    case SPH_PRISM: return sph_mesh_get_solid(SPH_SOLID_PRISM, s->pts, s->npts);
    case SPH_PYRAMID: return sph_mesh_get_solid(SPH_SOLID_PYRAMID, s->pts, s->npts);
    default: return NULL;
    }
}

/* Signed distance to one primitive. */
static double prim_sd(const sph_shape *s, const double p[3])
{
    switch (s->kind) {
    case SPH_BOX: return box_sd(s, p);
    case SPH_CYLINDER: return cylinder_sd(s, p);
    case SPH_SPHERE: return ball_sd(s->a, s->r, p);
    case SPH_MESH:
    case SPH_PRISM:
    case SPH_PYRAMID: {
        const sph_mesh *m = prim_mesh(s);
        double d = sph_mesh_distance(m, p, HUGE_VAL);
        return sph_mesh_inside(m, p) ? -d : d;
    }
    }
    return HUGE_VAL;
}

/* Whether p lies in primitive s or within tol of it (without a distance when inside).  A
 * mesh's surface is known to m->eps only (single-precision files): tol is at least that. */
static int prim_within(const sph_shape *s, const double p[3], double tol)
{
    const sph_mesh *m = prim_mesh(s);
    if (!m)
        return prim_sd(s, p) <= tol;
    if (sph_mesh_inside(m, p))
        return 1;
    tol = fmax(tol, m->eps);
    return tol > 0 && sph_mesh_distance(m, p, 2 * tol) <= tol;
}

/* Bounding box of one (already dimension-adjusted) primitive. */
static void prim_bbox(const sph_shape *s, double lo[3], double hi[3])
{
    double ba[3], len2 = 0.0;
    for (int k = 0; k < 3; k++) {
        ba[k] = s->b[k] - s->a[k];
        len2 += ba[k] * ba[k];
    }
    const sph_mesh *m = prim_mesh(s);
    for (int k = 0; k < 3; k++) {
        if (m) {
            lo[k] = m->lo[k];
            hi[k] = m->hi[k];
        } else if (s->kind == SPH_BOX) {
            lo[k] = fmin(s->a[k], s->b[k]);
            hi[k] = fmax(s->a[k], s->b[k]);
        } else if (s->kind == SPH_SPHERE || len2 == 0.0) {
            lo[k] = s->a[k] - s->r;
            hi[k] = s->a[k] + s->r;
        } else { /* the end discs' extent along k is r sqrt(1 - u_k^2) */
            double ext = s->r * sqrt(fmax(0.0, 1.0 - ba[k] * ba[k] / len2));
            lo[k] = fmin(s->a[k], s->b[k]) - ext;
            hi[k] = fmax(s->a[k], s->b[k]) + ext;
        }
    }
}

/* Membership in dimension dim (2: x-z plane version of every primitive); a point within
 * tol of a primitive counts as on it. */
int sph_region_contains_tol_dim(const sph_region *r, int dim, const double p[3], double tol)
{
    int in = 0;
    for (int i = 0; i < r->n; i++) {
        sph_shape s = prim_for_dim(&r->prims[i], dim, p[1]);
        int inside = prim_within(&s, p, tol);
        in = r->prims[i].subtract ? (in && !inside) : (in || inside);
    }
    return in;
}

int sph_region_contains_dim(const sph_region *r, int dim, const double p[3])
{
    return sph_region_contains_tol_dim(r, dim, p, 0.0);
}

/* Distance in dimension dim (see header comment for differences). */
double sph_region_distance_dim(const sph_region *r, int dim, const double p[3])
{
    if (sph_region_contains_dim(r, dim, p))
        return 0.0;
    double s = HUGE_VAL;
    for (int i = 0; i < r->n; i++) {
        sph_shape sh = prim_for_dim(&r->prims[i], dim, p[1]);
        double d = prim_sd(&sh, p);
        s = r->prims[i].subtract ? fmax(s, -d) : fmin(s, d);
    }
    return fmax(s, 0.0);
}

/* Bounding box of the union of the non-subtracted primitives; in 2D the y entries are
 * meaningless (infinite for boxes).  Returns 0 when there is no such primitive. */
int sph_region_bbox_dim(const sph_region *r, int dim, double lo[3], double hi[3])
{
    int any = 0;
    for (int k = 0; k < 3; k++) {
        lo[k] = HUGE_VAL;
        hi[k] = -HUGE_VAL;
    }
    for (int i = 0; i < r->n; i++) {
        if (r->prims[i].subtract)
            continue;
        double plo[3], phi[3];
        sph_shape s = prim_for_dim(&r->prims[i], dim, 0.0);
        prim_bbox(&s, plo, phi);
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], plo[k]);
            hi[k] = fmax(hi[k], phi[k]);
        }
        any = 1;
    }
    return any;
}

int sph_region_contains(const sph_region *r, const double p[3])
{
    return sph_region_contains_dim(r, 3, p);
}

double sph_region_distance(const sph_region *r, const double p[3])
{
    return sph_region_distance_dim(r, 3, p);
}
