/* notch.c — cutting the neighbour pairs that cross a notch quad (notch.h).
 *
 * A quad p1 p2 p3 p4 is the two triangles p1p2p3 and p1p3p4, which share the diagonal p1-p3
 * (a non-planar quad is a surface folded along it, without a gap).  A segment crosses a
 * triangle when
 *   1. its ends lie on different sides of the triangle's plane: a point is "up" when its
 *      signed distance d = n·(x - p1) >= -tol, "down" otherwise, with tol = 1e-9 times the
 *      diagonal of the quad's bounding box, and
 *   2. the point where it meets the plane, p + t (q - p) with t = d_p / (d_p - d_q), lies in
 *      the closed triangle: all three barycentric coordinates >= -1e-9, so a crossing on the
 *      rim or on the shared diagonal is never missed.
 * The unit normal n of both triangles is oriented along the quad's Newell normal N, itself
 * oriented so that its largest component is positive; the corners' order does not matter.
 *
 * Touching rule (why "on the plane" counts as up).  A particle exactly on the notch plane is
 * ambiguous.  Counting only strict crossings would let a row of particles on the plane link
 * both faces, bridging the notch; counting every touch would cut that row off from both
 * sides.  Giving it to one side keeps the partition clean: a pair in the plane is never cut,
 * a pair from below to the plane is cut where it meets the quad, one from above is not.
 * With the usual placement (the plane between two particle rows) the question never arises.
 *
 * Symmetry: the segment's ends are ordered lexicographically before the test, so (i, j) and
 * (j, i) give bitwise the same answer and the lists stay symmetric.
 *
 * Cost: pairs are first tested against the bounding box of all quads (grown by tol), then
 * against each quad's box, so away from the notches a pair costs one load of X_j and a few
 * comparisons.  The first pass (parallel) only counts the cut pairs of every particle; the
 * second compacts the lists, re-testing only the lists that lose pairs, and moves nothing
 * before the first one.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "notch.h"
#include "core/exit_codes.h"
#include "core/message.h"

#define NOTCH_TOL 1e-9

typedef struct {
    double a[3], e1[3], e2[3];  /* vertex p1 and the edges to the other two vertices */
    double n[3];                /* unit normal, oriented up */
    double d00, d01, d11, inv;  /* Gram matrix of e1, e2 and 1 / its determinant */
    int ok;                     /* 0: degenerate (no area), never crossed */
} notch_tri;

typedef struct {
    notch_tri t[2];
    double lo[3], hi[3];        /* bounding box grown by tol */
    double tol;                 /* distance counted as "on the plane" */
    int index;                  /* its place in the caller's list of quads */
} notch_quad;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* malloc that ends the program with a message when memory runs out. */
static void *xmalloc(size_t size)
{
    void *p = malloc(size ? size : 1);
    if (!p) {
        sph_error("out of memory cutting notch pairs (%zu bytes)", size);
        exit(SPH_EXIT_SETUP);
    }
    return p;
}

/* Triangle a b c with its normal oriented along up (the quad's oriented Newell normal). */
static void tri_prepare(notch_tri *t, const double a[3], const double b[3], const double c[3],
                        const double up[3])
{
    for (int k = 0; k < 3; k++) {
        t->a[k] = a[k];
        t->e1[k] = b[k] - a[k];
        t->e2[k] = c[k] - a[k];
    }
    t->d00 = dot3(t->e1, t->e1);
    t->d01 = dot3(t->e1, t->e2);
    t->d11 = dot3(t->e2, t->e2);
    double det = t->d00 * t->d11 - t->d01 * t->d01;
    cross3(t->e1, t->e2, t->n);
    double len = sqrt(dot3(t->n, t->n));
    t->ok = det > 1e-24 * t->d00 * t->d11 && len > 0.0;
    if (!t->ok)
        return;
    t->inv = 1.0 / det;
    double s = dot3(t->n, up) < 0.0 ? -1.0 / len : 1.0 / len;
    for (int k = 0; k < 3; k++)
        t->n[k] *= s;
}

/* Splits quad p into its two triangles, orients them and sets the grown bounding box.
 * Returns 0 when the quad has no area. */
static int quad_prepare(notch_quad *q, const double p[4][3])
{
    double N[3] = { 0, 0, 0 }, c[3];
    for (int k = 0; k < 4; k++) {
        cross3(p[k], p[(k + 1) % 4], c);
        for (int m = 0; m < 3; m++)
            N[m] += c[m];
    }
    int big = 0;
    for (int m = 1; m < 3; m++)
        if (fabs(N[m]) > fabs(N[big]))
            big = m;
    if (N[big] < 0.0)
        for (int m = 0; m < 3; m++)
            N[m] = -N[m];
    double diag = 0.0;
    for (int m = 0; m < 3; m++) {
        q->lo[m] = fmin(fmin(p[0][m], p[1][m]), fmin(p[2][m], p[3][m]));
        q->hi[m] = fmax(fmax(p[0][m], p[1][m]), fmax(p[2][m], p[3][m]));
        diag += (q->hi[m] - q->lo[m]) * (q->hi[m] - q->lo[m]);
    }
    q->tol = NOTCH_TOL * sqrt(diag);
    for (int m = 0; m < 3; m++) {
        q->lo[m] -= q->tol;
        q->hi[m] += q->tol;
    }
    tri_prepare(&q->t[0], p[0], p[1], p[2], N);
    tri_prepare(&q->t[1], p[0], p[2], p[3], N);
    return q->t[0].ok || q->t[1].ok;
}

/* 1 when the box of segment a-b overlaps the box lo-hi. */
static int boxes_overlap(const double a[3], const double b[3], const double lo[3],
                         const double hi[3])
{
    for (int k = 0; k < 3; k++)
        if ((a[k] < lo[k] && b[k] < lo[k]) || (a[k] > hi[k] && b[k] > hi[k]))
            return 0;
    return 1;
}

/* Segment a-b (ordered) against one triangle. */
static int tri_crossed(const notch_tri *t, double tol, const double a[3], const double b[3])
{
    if (!t->ok)
        return 0;
    double ra[3], rb[3];
    for (int k = 0; k < 3; k++) {
        ra[k] = a[k] - t->a[k];
        rb[k] = b[k] - t->a[k];
    }
    double da = dot3(t->n, ra), db = dot3(t->n, rb);
    if ((da >= -tol) == (db >= -tol))
        return 0;                       /* same side (a pair in the plane: both up) */
    double s = da / (da - db), x[3];
    for (int k = 0; k < 3; k++)
        x[k] = ra[k] + s * (rb[k] - ra[k]);
    double d20 = dot3(x, t->e1), d21 = dot3(x, t->e2);
    double v = (t->d11 * d20 - t->d01 * d21) * t->inv;
    double w = (t->d00 * d21 - t->d01 * d20) * t->inv;
    return v >= -NOTCH_TOL && w >= -NOTCH_TOL && 1.0 - v - w >= -NOTCH_TOL;
}

/* Segment p-q against a prepared quad; p and q are ordered lexicographically first. */
static int quad_crossed(const notch_quad *Q, const double p[3], const double q[3])
{
    if (!boxes_overlap(p, q, Q->lo, Q->hi))
        return 0;
    const double *a = p, *b = q;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) {
            if (q[k] < p[k]) {
                a = q;
                b = p;
            }
            break;
        }
    return tri_crossed(&Q->t[0], Q->tol, a, b) || tri_crossed(&Q->t[1], Q->tol, a, b);
}

int sph_segment_crosses_quad(const double p[3], const double q[3], const double quad[4][3])
{
    notch_quad Q;
    if (!quad_prepare(&Q, quad))
        return 0;
    return quad_crossed(&Q, p, q);
}

/* ------------------------------------------------------------------ neighbour lists */

typedef struct {
    const double *X;
    int dim;
    double y_plane;
    const notch_quad *q;
    int nq;
    double lo[3], hi[3];        /* box of all quads */
} notch_set;

/* Particle i's reference position in 3D. */
static void point3(const notch_set *s, int i, double p[3])
{
    const double *x = s->X + (size_t)i * s->dim;
    if (s->dim == 3) {
        p[0] = x[0];
        p[1] = x[1];
        p[2] = x[2];
        return;
    }
    p[0] = x[0];
    p[1] = s->y_plane;
    p[2] = x[1];
}

/* 1 + the index of the first quad the pair (i at p, j) crosses; 0 when it crosses none. */
static int pair_cut(const notch_set *s, const double p[3], int j)
{
    double q[3];
    point3(s, j, q);
    if (!boxes_overlap(p, q, s->lo, s->hi))
        return 0;
    for (int k = 0; k < s->nq; k++)
        if (quad_crossed(&s->q[k], p, q))
            return 1 + s->q[k].index;
    return 0;
}

/* Number of i's pairs that cross a quad; hit[k] = 1 (hit not NULL) for each quad k one of
 * them crosses first. */
static int count_cut(const notch_set *s, int i, const int *start, const int *nb, int *hit)
{
    double p[3];
    int c = 0;
    point3(s, i, p);
    for (int k = start[i]; k < start[i + 1]; k++) {
        const int q = pair_cut(s, p, nb[k]);
        if (!q)
            continue;
        c++;
        if (hit) {
#pragma omp atomic write
            hit[q - 1] = 1;
        }
    }
    return c;
}

/* Prepares the quads that can cut a pair (with area; in 2D, reaching y_plane); returns
 * their number, 0 when none can. */
static int set_prepare(notch_set *s, notch_quad *q, const double (*quads)[4][3], int nquads)
{
    s->q = q;
    s->nq = 0;
    for (int k = 0; k < 3; k++) {
        s->lo[k] = HUGE_VAL;
        s->hi[k] = -HUGE_VAL;
    }
    for (int k = 0; k < nquads; k++) {
        notch_quad *Q = &q[s->nq];
        if (!quad_prepare(Q, quads[k]))
            continue;
        if (s->dim == 2 && (s->y_plane < Q->lo[1] || s->y_plane > Q->hi[1]))
            continue;
        for (int m = 0; m < 3; m++) {
            s->lo[m] = fmin(s->lo[m], Q->lo[m]);
            s->hi[m] = fmax(s->hi[m], Q->hi[m]);
        }
        Q->index = k;
        s->nq++;
    }
    return s->nq;
}

long sph_drop_notch_pairs(const double *X, int n, int dim, double y_plane, int *start, int *nb,
                          const double (*quads)[4][3], int nquads, int *quad_cuts)
{
    for (int k = 0; quad_cuts && k < nquads; k++)
        quad_cuts[k] = 0;
    if (n <= 0 || nquads <= 0)
        return n > 0 ? start[n] : 0;
    notch_set s = { .X = X, .dim = dim, .y_plane = y_plane };
    notch_quad *q = xmalloc((size_t)nquads * sizeof *q);
    if (!set_prepare(&s, q, quads, nquads)) {
        free(q);
        return start[n];
    }
    int *cut = xmalloc((size_t)n * sizeof *cut);
    long total = 0;
#pragma omp parallel for schedule(dynamic, 1024) reduction(+ : total)
    for (int i = 0; i < n; i++) {
        cut[i] = count_cut(&s, i, start, nb, quad_cuts);
        total += cut[i];
    }
    if (total == 0) {
        free(cut);
        free(q);
        return start[n];
    }
    int w = 0;
    for (int i = 0; i < n; i++) {
        int b = start[i], e = start[i + 1];
        start[i] = w;
        if (!cut[i]) {
            if (w != b)
                memmove(nb + w, nb + b, (size_t)(e - b) * sizeof *nb);
            w += e - b;
            continue;
        }
        double p[3];
        point3(&s, i, p);
        for (int k = b; k < e; k++)
            if (!pair_cut(&s, p, nb[k]))
                nb[w++] = nb[k];
    }
    start[n] = w;
    free(cut);
    free(q);
    return w;
}
