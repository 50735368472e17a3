/* mesh_query.c — inside test and distance for a closed surface (mesh.h).
 *
 * A bounding-volume hierarchy over the triangles: each node's box holds its triangles;
 * nodes are split at the median of the triangle centres along the longest side of the box
 * until at most 4 triangles are left.
 *
 * Inside: the ray from p along +z is crossed an odd number of times (mesh_ray.c decides
 * crossings through edges and vertices consistently), or p lies on a triangle it meets
 * (height within 1e-12 of the surface's size).  Only nodes whose box spans p in x and y and
 * reaches above it are visited.  The parity rule counts a cavity as outside.
 *
 * Distance: the nearest triangle (closest point on a triangle, as in Ericson, Real-Time
 * Collision Detection, 5.1.5), visiting nodes nearest first and skipping those whose box is
 * further than the best so far (or than the caller's limit). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"

typedef struct {
    const sph_mesh *m;
    double *centre;     /* 3 per triangle */
    int axis;
} builder;

static void triangle_box(const sph_mesh *m, int k, double lo[3], double hi[3])
{
    for (int d = 0; d < 3; d++) {
        lo[d] = HUGE_VAL;
        hi[d] = -HUGE_VAL;
        for (int c = 0; c < 3; c++) {
            double x = m->v[3 * m->t[3 * k + c] + d];
            lo[d] = fmin(lo[d], x);
            hi[d] = fmax(hi[d], x);
        }
    }
}

/* Partially sorts order[lo..hi) so that the median (by centre along axis) is at mid. */
static void select_median(const builder *b, int *order, int lo, int hi, int mid)
{
    while (hi - lo > 1) {
        double pivot = b->centre[3 * order[(lo + hi) / 2] + b->axis];
        int i = lo, j = hi - 1;
        while (i <= j) {
            while (b->centre[3 * order[i] + b->axis] < pivot)
                i++;
            while (b->centre[3 * order[j] + b->axis] > pivot)
                j--;
            if (i <= j) {
                int s = order[i];
                order[i++] = order[j];
                order[j--] = s;
            }
        }
        if (mid <= j)
            hi = j + 1;
        else if (mid >= i)
            lo = i;
        else
            return;
    }
}

static int build(sph_mesh *m, builder *b, int first, int count)
{
    int id = m->nnodes++;
    sph_mesh_node *n = &m->nodes[id];
    for (int d = 0; d < 3; d++) {
        n->lo[d] = HUGE_VAL;
        n->hi[d] = -HUGE_VAL;
    }
    for (int i = first; i < first + count; i++) {
        double lo[3], hi[3];
        triangle_box(m, m->order[i], lo, hi);
        for (int d = 0; d < 3; d++) {
            n->lo[d] = fmin(n->lo[d], lo[d]);
            n->hi[d] = fmax(n->hi[d], hi[d]);
        }
    }
    n->first = first;
    n->count = count;
    n->left = n->right = -1;
    if (count <= 4)
        return id;
    b->axis = 0;
    for (int d = 1; d < 3; d++)
        if (n->hi[d] - n->lo[d] > n->hi[b->axis] - n->lo[b->axis])
            b->axis = d;
    int half = count / 2;
    select_median(b, m->order, first, first + count, first + half);
    n->count = 0;
    int left = build(m, b, first, half);
    int right = build(m, b, first + half, count - half);
    m->nodes[id].left = left; /* m->nodes does not move: allocated for all nodes */
    m->nodes[id].right = right;
    return id;
}

void sph_mesh_index(sph_mesh *m)
{
    if (m->nodes)
        return;
    builder b = {m, malloc((size_t)m->nt * 3 * sizeof(double)), 0};
    m->order = malloc((size_t)m->nt * sizeof *m->order);
    for (int k = 0; k < m->nt; k++) {
        m->order[k] = k;
        for (int d = 0; d < 3; d++)
            b.centre[3 * k + d] = (m->v[3 * m->t[3 * k] + d] + m->v[3 * m->t[3 * k + 1] + d] +
                                   m->v[3 * m->t[3 * k + 2] + d]) / 3.0;
    }
    m->nodes = malloc((size_t)(2 * m->nt + 1) * sizeof *m->nodes);
    m->nnodes = 0;
    build(m, &b, 0, m->nt);
    free(b.centre);
}

/* ------------------------------------------------------------------ inside */

int sph_mesh_inside(const sph_mesh *m, const double p[3])
{
    double size = 0, tol;
    for (int d = 0; d < 3; d++)
        size = fmax(size, m->hi[d] - m->lo[d]);
    tol = 1e-12 * size;
    if (p[0] < m->lo[0] || p[0] > m->hi[0] || p[1] < m->lo[1] || p[1] > m->hi[1] ||
        p[2] < m->lo[2] - tol || p[2] > m->hi[2] + tol)
        return 0;
    int stack[128], top = 0, crossings = 0;
    stack[top++] = 0;
    while (top) {
        const sph_mesh_node *n = &m->nodes[stack[--top]];
        if (p[0] < n->lo[0] || p[0] > n->hi[0] || p[1] < n->lo[1] || p[1] > n->hi[1] ||
            n->hi[2] < p[2] - tol)
            continue;
        if (n->count == 0) {
            stack[top++] = n->left;
            stack[top++] = n->right;
            continue;
        }
        for (int i = n->first; i < n->first + n->count; i++) {
            double z;
            if (!sph_mesh_ray_hits(m, m->order[i], p, &z))
                continue;
            if (fabs(z - p[2]) <= tol)
                return 1; /* on the surface */
            crossings += z > p[2];
        }
    }
    return crossings % 2;
}

/* ------------------------------------------------------------------ distance */

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Squared distance from p to triangle k. */
static double triangle_distance2(const sph_mesh *m, int k, const double p[3])
{
    const double *a = m->v + 3 * m->t[3 * k], *b = m->v + 3 * m->t[3 * k + 1],
                 *c = m->v + 3 * m->t[3 * k + 2];
    double ab[3], ac[3], ap[3], q[3];
    for (int d = 0; d < 3; d++)
        ab[d] = b[d] - a[d], ac[d] = c[d] - a[d], ap[d] = p[d] - a[d];
    double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) {
        memcpy(q, a, sizeof q);
    } else {
        double bp[3], cp[3];
        for (int d = 0; d < 3; d++)
            bp[d] = p[d] - b[d], cp[d] = p[d] - c[d];
        double d3 = dot(ab, bp), d4 = dot(ac, bp), d5 = dot(ab, cp), d6 = dot(ac, cp);
        double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
        if (d3 >= 0 && d4 <= d3) {
            memcpy(q, b, sizeof q);
        } else if (d6 >= 0 && d5 <= d6) {
            memcpy(q, c, sizeof q);
        } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            double v = d1 / (d1 - d3);
            for (int d = 0; d < 3; d++)
                q[d] = a[d] + v * ab[d];
        } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            double w = d2 / (d2 - d6);
            for (int d = 0; d < 3; d++)
                q[d] = a[d] + w * ac[d];
        } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
            double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            for (int d = 0; d < 3; d++)
                q[d] = b[d] + w * (c[d] - b[d]);
        } else {
            double den = 1.0 / (va + vb + vc), v = vb * den, w = vc * den;
            for (int d = 0; d < 3; d++)
                q[d] = a[d] + v * ab[d] + w * ac[d];
        }
    }
    double r2 = 0;
    for (int d = 0; d < 3; d++)
        r2 += (p[d] - q[d]) * (p[d] - q[d]);
    return r2;
}

static double box_distance2(const sph_mesh_node *n, const double p[3])
{
    double r2 = 0;
    for (int d = 0; d < 3; d++) {
        double e = fmax(n->lo[d] - p[d], p[d] - n->hi[d]);
        if (e > 0)
            r2 += e * e;
    }
    return r2;
}

double sph_mesh_distance(const sph_mesh *m, const double p[3], double limit)
{
    double best = limit * limit;
    int stack[128], top = 0;
    stack[top++] = 0;
    while (top) {
        const sph_mesh_node *n = &m->nodes[stack[--top]];
        if (box_distance2(n, p) >= best)
            continue;
        if (n->count) {
            for (int i = n->first; i < n->first + n->count; i++)
                best = fmin(best, triangle_distance2(m, m->order[i], p));
            continue;
        }
        double dl = box_distance2(&m->nodes[n->left], p);
        double dr = box_distance2(&m->nodes[n->right], p);
        stack[top++] = dl < dr ? n->right : n->left; /* the nearer child is visited first */
        stack[top++] = dl < dr ? n->left : n->right;
    }
    return sqrt(best);
}
