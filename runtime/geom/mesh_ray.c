/* mesh_ray.c — does the ray from p along +z cross triangle k? (mesh.h)
 *
 * In the x-y projection, q = (p.x, p.y) is tested against the triangle's edges.  The test of
 * an edge is computed from its lower-numbered vertex u to its other vertex w,
 *     E(q) = (w.x - u.x)(q.y - u.y) - (w.y - u.y)(q.x - u.x),
 * whichever triangle asks, so the triangles that share an edge get bitwise the same number.
 * When E(q) is 0 (q on the edge's line, or on a vertex) the sign is the one E takes for q
 * moved by (e, e^2), e -> 0: sign(u.y - w.y), or sign(w.x - u.x) for an edge along x.  The
 * moved point lies strictly inside or outside every triangle, so a ray through an edge or a
 * vertex crosses each sheet of the surface exactly once.  A triangle seen edge-on (zero
 * projected area) is never crossed.  *z is the height of the triangle's plane above q. */
#include "mesh.h"

/* The sign of edge u-w (vertex numbers) at q, as seen from u to w. */
static int edge_sign(const double *v, int u, int w, const double q[2])
{
    int reverse = u > w;
    if (reverse) {
        int s = u;
        u = w;
        w = s;
    }
    const double *a = v + 3 * u, *b = v + 3 * w;
    double ex = b[0] - a[0], ey = b[1] - a[1];
    double e = ex * (q[1] - a[1]) - ey * (q[0] - a[0]);
    int s = e > 0 ? 1 : e < 0 ? -1 : ey < 0 ? 1 : ey > 0 ? -1 : ex > 0 ? 1 : ex < 0 ? -1 : 0;
    return reverse ? -s : s;
}

int sph_mesh_ray_hits(const sph_mesh *m, int k, const double p[3], double *z)
{
    const int *t = m->t + 3 * k;
    const double *a = m->v + 3 * t[0], *b = m->v + 3 * t[1], *c = m->v + 3 * t[2];
    double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                   (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                   (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    if (n[2] == 0.0)
        return 0;
    const double q[2] = {p[0], p[1]};
    int s0 = edge_sign(m->v, t[0], t[1], q), s1 = edge_sign(m->v, t[1], t[2], q);
    int s2 = edge_sign(m->v, t[2], t[0], q);
    if (s0 == 0 || s0 != s1 || s1 != s2)
        return 0;
    *z = a[2] - (n[0] * (q[0] - a[0]) + n[1] * (q[1] - a[1])) / n[2];
    return 1;
}
