/* select.c — choosing particles by geometry in the reference configuration (select.h).
 *
 * Near: distance to the region (region.c, 2D: x-z version of the region at y = y_plane)
 * <= dx (1 + 1e-9).
 *
 * Plane: the quad p[0..3] (corners in order).  Its normal is Newell's (robust for slightly
 * non-planar quads).  A particle is kept when its distance to the quad's plane is
 * <= tol = dx/2 + 1e-9 dx and its projection q onto the plane lies inside the quad (one of
 * the triangles p0 p1 p2, p0 p2 p3) or within tol of one of its edges (the quad grown by
 * dx/2, with rounded corners).  In 2D corners and particles are projected onto the x-z
 * plane (y = 0): a quad perpendicular to that plane becomes a segment (collinear corners),
 * and then, as for any degenerate quad without a normal, particles within tol of its edges,
 * i.e. of the segment, are kept; a quad lying in the x-z plane keeps the particles inside it
 * or within tol of its edges.
 */
#include <math.h>
#include <stdlib.h>

#include "region.h"
#include "select.h"

/* 3D point of particle i (2D: (x, y, z) with the given y). */
static void particle_point(const double *X, int dim, int i, double y, double p[3])
{
    const double *x = X + (size_t)i * dim;
    p[0] = x[0];
    p[1] = dim == 2 ? y : x[1];
    p[2] = dim == 2 ? x[1] : x[2];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void sub3(const double a[3], const double b[3], double o[3])
{
    for (int k = 0; k < 3; k++)
        o[k] = a[k] - b[k];
}

static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Distance from q to the segment a-b. */
static double segment_distance(const double q[3], const double a[3], const double b[3])
{
    double ab[3], aq[3], t = 0.0, d[3];
    sub3(b, a, ab);
    sub3(q, a, aq);
    double l2 = dot3(ab, ab);
    if (l2 > 0.0)
        t = fmin(1.0, fmax(0.0, dot3(aq, ab) / l2));
    for (int k = 0; k < 3; k++)
        d[k] = aq[k] - t * ab[k];
    return sqrt(dot3(d, d));
}

/* 1 when q (in the triangle's plane) lies in the non-degenerate triangle a b c. */
static int in_triangle(const double q[3], const double a[3], const double b[3],
                       const double c[3])
{
    const double *v[3] = { a, b, c };
    double e1[3], e2[3], nt[3];
    sub3(b, a, e1);
    sub3(c, a, e2);
    cross3(e1, e2, nt);
    if (dot3(nt, nt) == 0.0)
        return 0;
    for (int k = 0; k < 3; k++) {
        double e[3], w[3], x[3];
        sub3(v[(k + 1) % 3], v[k], e);
        sub3(q, v[k], w);
        cross3(e, w, x);
        if (dot3(x, nt) < 0.0)
            return 0;
    }
    return 1;
}

/* The measured quad: corners, unit normal (has_normal 0 for a degenerate quad). */
typedef struct {
    double c[4][3], n[3];
    int has_normal;
    double tol;
} quad;

/* Sets up the quad (2D: corners projected onto y = 0). */
static void quad_init(quad *Q, const double p[4][3], int dim, double dx)
{
    double span2 = 0.0;
    for (int k = 0; k < 4; k++)
        for (int a = 0; a < 3; a++)
            Q->c[k][a] = dim == 2 && a == 1 ? 0.0 : p[k][a];
    for (int a = 0; a < 3; a++)
        Q->n[a] = 0.0;
    for (int k = 0; k < 4; k++) {  /* Newell: sum of (p_k - p_0) x (p_k+1 - p_0) */
        double x[3], e[3], u[3], v[3];
        sub3(Q->c[k], Q->c[0], u);
        sub3(Q->c[(k + 1) % 4], Q->c[0], v);
        cross3(u, v, x);
        sub3(v, u, e);
        span2 = fmax(span2, dot3(e, e));
        for (int a = 0; a < 3; a++)
            Q->n[a] += x[a];
    }
    double nn = sqrt(dot3(Q->n, Q->n));
    Q->has_normal = nn > 1e-9 * span2 && nn > 0.0; /* nn = 2 area */
    for (int a = 0; a < 3; a++)
        Q->n[a] = Q->has_normal ? Q->n[a] / nn : 0.0;
    Q->tol = dx * (0.5 + 1e-9);
}

/* 1 when point x is cut by the quad (see the header comment). */
static int quad_cuts(const quad *Q, const double x[3])
{
    double q[3] = { x[0], x[1], x[2] };
    if (Q->has_normal) {
        double d[3];
        sub3(x, Q->c[0], d);
        double s = dot3(d, Q->n);
        if (fabs(s) > Q->tol)
            return 0;
        for (int a = 0; a < 3; a++)
            q[a] = x[a] - s * Q->n[a];
        if (in_triangle(q, Q->c[0], Q->c[1], Q->c[2]) || in_triangle(q, Q->c[0], Q->c[2], Q->c[3]))
            return 1;
    }
    for (int k = 0; k < 4; k++)
        if (segment_distance(q, Q->c[k], Q->c[(k + 1) % 4]) <= Q->tol)
            return 1;
    return 0;
}

/* Keeps the marked entries of flag (n) as an index list. */
static int compact(const unsigned char *flag, int n, int **idx)
{
    int m = 0;
    for (int i = 0; i < n; i++)
        m += flag[i];
    *idx = m > 0 ? malloc((size_t)m * sizeof **idx) : NULL;
    if (m > 0 && !*idx)
        return 0;
    for (int i = 0, k = 0; i < n; i++)
        if (flag[i])
            (*idx)[k++] = i;
    return m;
}

int sph_select_near(const double *X, int n, int dim, double y_plane, double dx,
                    const sph_region *r, int **idx)
{
    unsigned char *flag = malloc((size_t)(n > 0 ? n : 1));
    *idx = NULL;
    if (!flag)
        return 0;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        double p[3];
        particle_point(X, dim, i, y_plane, p);
        flag[i] = (unsigned char)(sph_region_distance_dim(r, dim, p) <= dx * (1.0 + 1e-9));
    }
    int m = compact(flag, n, idx);
    free(flag);
    return m;
}

int sph_select_plane(const double *X, int n, int dim, double dx, const double p[4][3],
                     int **idx)
{
    quad Q;
    unsigned char *flag = malloc((size_t)(n > 0 ? n : 1));
    *idx = NULL;
    if (!flag)
        return 0;
    quad_init(&Q, p, dim, dx);
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        double x[3];
        particle_point(X, dim, i, 0.0, x);
        flag[i] = (unsigned char)quad_cuts(&Q, x);
    }
    int m = compact(flag, n, idx);
    free(flag);
    return m;
}
