/* test_notch.c — notch quads: segment/quad cases (through, beside, in the plane, ending on
 * it, rim and shared diagonal, tilted and non-planar quads) and the removal of crossing
 * pairs from 2D and 3D lattice neighbour lists, compared with independent brute force. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <omp.h>
#include "pairs/neighbours.h"
#include "pairs/notch.h"

static int failures = 0;

/* Prints one check and counts it when it fails. */
static void check(int ok, const char *what)
{
    printf("%-4s %s\n", ok ? "ok" : "FAIL", what);
    failures += !ok;
}

/* Deterministic uniform random numbers in [0, 1). */
static double rnd(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* A lattice of m points per axis, spacing dx, cell-centred at (k + 1/2) dx. */
static double *lattice_points(int m, int dim, double dx, int *n)
{
    *n = dim == 2 ? m * m : m * m * m;
    double *X = malloc((size_t)*n * dim * sizeof *X);
    for (int i = 0; i < *n; i++)
        for (int k = 0, t = i; k < dim; k++, t /= m)
            X[i * dim + k] = (t % m + 0.5) * dx;
    return X;
}

/* Segment p-q against quad Q both ways; -1 when the two directions disagree. */
static int crosses(const double p[3], const double q[3], const double Q[4][3])
{
    int a = sph_segment_crosses_quad(p, q, Q), b = sph_segment_crosses_quad(q, p, Q);
    return a == b ? a : -1;
}

/* One segment case: expected answer, with the quad's corners in both orders. */
static void seg_case(const char *what, double px, double py, double pz, double qx, double qy,
                     double qz, const double Q[4][3], int expect)
{
    const double p[3] = { px, py, pz }, q[3] = { qx, qy, qz };
    const double R[4][3] = { { Q[3][0], Q[3][1], Q[3][2] }, { Q[2][0], Q[2][1], Q[2][2] },
                             { Q[1][0], Q[1][1], Q[1][2] }, { Q[0][0], Q[0][1], Q[0][2] } };
    int a = crosses(p, q, Q), b = crosses(p, q, R);
    char line[200];
    snprintf(line, sizeof line, "segment: %s: %d, corners reversed %d (expected %d)", what, a, b,
             expect);
    check(a == expect && b == expect, line);
}

/* Fixed segment cases against the unit square at z = 0 and a quad with a lifted corner. */
static void test_segment_cases(void)
{
    static const double S[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
    seg_case("through the middle", 0.3, 0.6, -1, 0.3, 0.6, 1, S, 1);
    seg_case("oblique, meets the plane inside", -0.5, 0.5, -1, 1.5, 0.5, 1, S, 1);
    seg_case("beside the quad", 1.5, 0.5, -1, 1.5, 0.5, 1, S, 0);
    seg_case("oblique, meets the plane beside", 0.5, 0.5, -1, 2.5, 0.5, 1, S, 0);
    seg_case("stops short of the plane", 0.5, 0.5, -1, 0.5, 0.5, -0.1, S, 0);
    seg_case("parallel, in the plane", -1, 0.5, 0, 2, 0.5, 0, S, 0);
    seg_case("parallel, inside the quad", 0.2, 0.2, 0, 0.8, 0.7, 0, S, 0);
    seg_case("parallel, above the plane", -1, 0.5, 0.1, 2, 0.5, 0.1, S, 0);
    seg_case("ends on the plane inside, from below", 0.5, 0.5, -1, 0.5, 0.5, 0, S, 1);
    seg_case("ends on the plane inside, from above", 0.5, 0.5, 1, 0.5, 0.5, 0, S, 0);
    seg_case("ends on the plane beside, from below", 2, 0.5, -1, 2, 0.5, 0, S, 0);
    seg_case("ends 1e-13 below the plane, from above", 0.5, 0.5, 1, 0.5, 0.5, -1e-13, S, 0);
    seg_case("ends 1e-6 below the plane, from above", 0.5, 0.5, 1, 0.5, 0.5, -1e-6, S, 1);
    seg_case("on the shared diagonal p1-p3", 0.5, 0.5, -1, 0.5, 0.5, 1, S, 1);
    seg_case("on the diagonal, oblique", 0.2, 0.4, -1, 0.6, 0.4, 1, S, 1);
    seg_case("1e-15 beside the diagonal", 0.3 + 1e-15, 0.3, -1, 0.3 + 1e-15, 0.3, 1, S, 1);
    seg_case("1e-15 beside the diagonal, other side", 0.3, 0.3 + 1e-15, -1, 0.3, 0.3 + 1e-15,
             1, S, 1);
    seg_case("on the rim x = 1", 1, 0.5, -1, 1, 0.5, 1, S, 1);
    seg_case("on the corner p3", 1, 1, -1, 1, 1, 1, S, 1);
    seg_case("on the corner p2 (end of no diagonal)", 1, 0, -1, 1, 0, 1, S, 1);
    seg_case("1e-6 outside the rim", 1 + 1e-6, 0.5, -1, 1 + 1e-6, 0.5, 1, S, 0);
    seg_case("coincident ends", 0.5, 0.5, 0, 0.5, 0.5, 0, S, 0);

    /* p3 lifted to z = 0.2: triangle p1p2p3 is z = 0.2 y, triangle p1p3p4 is z = 0.2 x. */
    static const double F[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0.2 }, { 0, 1, 0 } };
    seg_case("non-planar: through triangle p1p2p3", 0.8, 0.2, -1, 0.8, 0.2, 1, F, 1);
    seg_case("non-planar: through triangle p1p3p4", 0.2, 0.8, -1, 0.2, 0.8, 1, F, 1);
    seg_case("non-planar: through the fold", 0.5, 0.5, -1, 0.5, 0.5, 1, F, 1);
    seg_case("non-planar: stops below the sheet (z 0.05 < 0.1)", 0.9, 0.5, -1, 0.9, 0.5, 0.05,
             F, 0);
    seg_case("non-planar: ends above the sheet (z 0.15 > 0.1)", 0.9, 0.5, -1, 0.9, 0.5, 0.15,
             F, 1);

    static const double D[4][3] = { { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 }, { 3, 3, 3 } };
    seg_case("degenerate quad (a line)", 1, 1, 0, 1, 1, 2, D, 0);
}

/* A rectangle c + a u + b v (|a| <= ha, |b| <= hb), normal w = u x v, for brute force. */
typedef struct {
    double c[3], u[3], v[3], w[3], ha, hb;
} rect;

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* A rectangle rotated by angles (yaw about z, then pitch about the rotated x axis). */
static rect rect_make(const double c[3], double ha, double hb, double yaw, double pitch)
{
    rect r = { .ha = ha, .hb = hb };
    double cy = cos(yaw), sy = sin(yaw), cp = cos(pitch), sp = sin(pitch);
    double u[3] = { cy, sy, 0 }, v[3] = { -sy * cp, cy * cp, sp };
    for (int k = 0; k < 3; k++) {
        r.c[k] = c[k];
        r.u[k] = u[k];
        r.v[k] = v[k];
    }
    r.w[0] = u[1] * v[2] - u[2] * v[1];
    r.w[1] = u[2] * v[0] - u[0] * v[2];
    r.w[2] = u[0] * v[1] - u[1] * v[0];
    return r;
}

/* The rectangle's corners, in order around it. */
static void rect_corners(const rect *r, double Q[4][3])
{
    static const double sa[4] = { -1, 1, 1, -1 }, sb[4] = { -1, -1, 1, 1 };
    for (int k = 0; k < 4; k++)
        for (int m = 0; m < 3; m++)
            Q[k][m] = r->c[m] + sa[k] * r->ha * r->u[m] + sb[k] * r->hb * r->v[m];
}

/* Brute force: p and q on different sides of the plane (w >= 0 up), meeting it inside.
 * *margin gets the smallest distance of a deciding quantity to its threshold. */
static int rect_crossed(const rect *r, const double p[3], const double q[3], double *margin)
{
    double dp[3], dq[3];
    for (int k = 0; k < 3; k++) {
        dp[k] = p[k] - r->c[k];
        dq[k] = q[k] - r->c[k];
    }
    double wp = dot3(dp, r->w), wq = dot3(dq, r->w);
    if ((wp >= 0) == (wq >= 0))
        return 0;
    *margin = fmin(*margin, fmin(fabs(wp), fabs(wq)));
    double s = wp / (wp - wq), x[3];
    for (int k = 0; k < 3; k++)
        x[k] = dp[k] + s * (dq[k] - dp[k]);
    double a = dot3(x, r->u), b = dot3(x, r->v);
    *margin = fmin(*margin, fmin(fabs(fabs(a) - r->ha), fabs(fabs(b) - r->hb)));
    return fabs(a) <= r->ha && fabs(b) <= r->hb;
}

/* Random segments against tilted rectangles, crossing points spread over and around them. */
static void test_segment_random(void)
{
    unsigned long long seed = 7;
    int bad = 0, ncross = 0, ntests = 0;
    double margin = HUGE_VAL;
    for (int t = 0; t < 20; t++) {
        double c[3] = { rnd(&seed) - 0.5, rnd(&seed) - 0.5, rnd(&seed) - 0.5 };
        rect r = rect_make(c, 0.2 + rnd(&seed), 0.2 + rnd(&seed), 6.3 * rnd(&seed),
                           3.1 * rnd(&seed) - 1.55);
        double Q[4][3];
        rect_corners(&r, Q);
        for (int k = 0; k < 2000; k++) {
            double a = (2.4 * rnd(&seed) - 1.2) * r.ha, b = (2.4 * rnd(&seed) - 1.2) * r.hb;
            double d[3] = { rnd(&seed) - 0.5, rnd(&seed) - 0.5, rnd(&seed) - 0.5 };
            double s0 = -0.1 - rnd(&seed), s1 = 1.1 * rnd(&seed) - 0.1, p[3], q[3];
            for (int m = 0; m < 3; m++) {
                double x = r.c[m] + a * r.u[m] + b * r.v[m], dir = r.w[m] + d[m];
                p[m] = x + s0 * dir;
                q[m] = x + s1 * dir;
            }
            int want = rect_crossed(&r, p, q, &margin), got = crosses(p, q, Q);
            bad += got != want;
            ncross += want;
            ntests++;
        }
    }
    char what[200];
    snprintf(what, sizeof what, "segment: %d random segments vs 20 tilted rectangles == brute "
             "force (%d cross; %d wrong; smallest margin %.1e)", ntests, ncross, bad, margin);
    check(bad == 0 && ncross > ntests / 5 && ncross < ntests * 4 / 5, what);
}

/* ------------------------------------------------------------------ neighbour lists */

/* Which pairs a brute-force computation cuts (positions as stored, 2D (x, z) or 3D). */
typedef int (*brute_fn)(const void *ctx, const double *xi, const double *xj);

/* 2D notch planes z = z0 (z >= z0 up) from x = x0 to x1; the quads span y_plane. */
typedef struct {
    double z0, x0, x1;
} plane2;

static int brute2(const void *ctx, const double *xi, const double *xj)
{
    const plane2 *p = ctx;
    if ((xi[1] >= p->z0) == (xj[1] >= p->z0))
        return 0;
    double x = xi[0] + (p->z0 - xi[1]) / (xj[1] - xi[1]) * (xj[0] - xi[0]);
    return x >= p->x0 && x <= p->x1;
}

/* 2D: the notch z = 10 and a vertical one, x = 15 (x >= 15 up), from z = -1 to 8. */
static int brute2_two(const void *ctx, const double *xi, const double *xj)
{
    (void)ctx;
    const plane2 a = { 10, -1, 10.5 };
    if (brute2(&a, xi, xj))
        return 1;
    if ((xi[0] >= 15) == (xj[0] >= 15))
        return 0;
    double z = xi[1] + (15 - xi[0]) / (xj[0] - xi[0]) * (xj[1] - xi[1]);
    return z >= -1 && z <= 8;
}

typedef struct {
    const rect *r;
    double margin;
} brute3_ctx;

static int brute3(const void *ctx, const double *xi, const double *xj)
{
    brute3_ctx *c = (brute3_ctx *)ctx;
    return rect_crossed(c->r, xi, xj, &c->margin);
}

/* 1 when every list excludes i and (i, j) implies (j, i). */
static int symmetric(const int *st, const int *nb, int n)
{
    for (int i = 0; i < n; i++)
        for (int p = st[i]; p < st[i + 1]; p++) {
            int j = nb[p], found = 0;
            if (j == i)
                return 0;
            for (int q = st[j]; q < st[j + 1]; q++)
                found |= nb[q] == i;
            if (!found)
                return 0;
        }
    return 1;
}

/* Counts of a comparison of the cut lists with brute force. */
typedef struct {
    long before, after, returned; /* list entries */
    long brute;                   /* entries brute force cuts */
    long wrong;                   /* entries kept or cut against brute force */
    int sym;
} cut_result;

/* Builds the lattice lists, cuts them and compares them, entry by entry, with the original
 * lists minus the pairs brute force cuts. */
static cut_result cut_and_compare(const double *X, int n, int dim, double y_plane,
                                  double radius, double dx, const double (*quads)[4][3],
                                  int nquads, brute_fn brute, const void *ctx)
{
    int *st, *nb;
    cut_result r = { 0 };
    sph_neighbours(X, n, dim, radius, 0, dx, &st, &nb);
    int *st0 = malloc(((size_t)n + 1) * sizeof *st0), *nb0 = malloc((size_t)st[n] * sizeof *nb0);
    memcpy(st0, st, ((size_t)n + 1) * sizeof *st);
    memcpy(nb0, nb, (size_t)st[n] * sizeof *nb);
    r.before = st0[n];
    r.returned = sph_drop_notch_pairs(X, n, dim, y_plane, st, nb, quads, nquads, NULL);
    r.after = st[n];
    for (int i = 0; i < n; i++) {
        int k = st[i];
        for (int p = st0[i]; p < st0[i + 1]; p++) {
            int j = nb0[p], cut = brute(ctx, X + (size_t)i * dim, X + (size_t)j * dim);
            r.brute += cut;
            int kept = k < st[i + 1] && nb[k] == j;
            k += kept;
            r.wrong += kept == cut;
        }
        r.wrong += st[i + 1] - k; /* entries that were never in the list */
    }
    r.sym = symmetric(st, nb, n);
    free(st); free(nb); free(st0); free(nb0);
    return r;
}

/* Prints and checks one comparison. */
static void report(const char *name, cut_result r, long expect_cut)
{
    char what[300];
    snprintf(what, sizeof what, "%s: %ld -> %ld entries (returned %ld), %ld cut (%ld pairs), "
             "brute force %ld, %ld wrong, symmetric %d", name, r.before, r.after, r.returned,
             r.before - r.after, (r.before - r.after) / 2, r.brute, r.wrong, r.sym);
    int ok = r.wrong == 0 && r.sym && r.returned == r.after && r.before - r.after == r.brute;
    if (expect_cut >= 0)
        ok = ok && r.brute == expect_cut;
    else
        ok = ok && r.brute > 0;
    check(ok, what);
}

/* Pairs of the 2D lattice that cross z = z0 beside the notch, at x > x1 (kept). */
static long beside_pairs(const double *X, int n, double radius, double dx, plane2 p)
{
    int *st, *nb;
    long c = 0;
    sph_neighbours(X, n, 2, radius, 0, dx, &st, &nb);
    for (int i = 0; i < n; i++)
        for (int k = st[i]; k < st[i + 1]; k++) {
            const double *a = X + 2 * i, *b = X + 2 * nb[k];
            if ((a[1] >= p.z0) == (b[1] >= p.z0))
                continue;
            c += a[0] + (p.z0 - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) > p.x1;
        }
    free(st);
    free(nb);
    return c;
}

/* 2D block 20 x 20, dx = 1, h = sqrt(2) dx, radius 2h: the notch z = 10 from x = -1 to 10.5
 * (between rows), the same on a particle row (z = 10.5), out of the plane y = y_plane, and
 * with a second notch. */
static void test_lists_2d(void)
{
    int n;
    double dx = 1.0, radius = 2 * sqrt(2.0) * dx, *X = lattice_points(20, 2, dx, &n);
    static const double N1[1][4][3] = {
        { { -1, -1, 10 }, { 10.5, -1, 10 }, { 10.5, 1, 10 }, { -1, 1, 10 } } };
    /* Crossing z = 10: rows 9.5-10.5 (dz = 1) and 8.5-10.5, 9.5-11.5 (dz = 2), |dx| <= 2 each:
     * 3 x 94 = 282 pairs.  With x = k + 1/2 the crossing is at k_i + 1/2 + t (k_j - k_i), t = 1/2,
     * 3/4, 1/4: 51 + 50 + 50 = 151 pairs cross at x <= 10.5 (cut), 131 beside (kept). */
    plane2 p = { 10, -1, 10.5 };
    cut_result r = cut_and_compare(X, n, 2, 0.0, radius, dx, N1, 1, brute2, &p);
    report("2D 20x20, notch z = 10, x in [-1, 10.5]", r, 2 * 151);
    char what[200];
    long beside = beside_pairs(X, n, radius, dx, p);
    snprintf(what, sizeof what, "2D: %ld pairs cross z = 10 beside the notch (x > 10.5), "
             "kept", beside / 2);
    check(beside == 2 * 131 && r.wrong == 0, what);

    static const double N2[1][4][3] = {
        { { -1, -1, 10.5 }, { 10.5, -1, 10.5 }, { 10.5, 1, 10.5 }, { -1, 1, 10.5 } } };
    plane2 p2 = { 10.5, -1, 10.5 };
    r = cut_and_compare(X, n, 2, 0.0, radius, dx, N2, 1, brute2, &p2);
    report("2D 20x20, notch on the row z = 10.5 (on the plane = above)", r, -1);

    r = cut_and_compare(X, n, 2, 2.0, radius, dx, N1, 1, brute2, &p);
    snprintf(what, sizeof what, "2D: y_plane = 2 outside the notch's y span: %ld -> %ld entries",
             r.before, r.after);
    check(r.before == r.after && r.returned == r.after, what);

    static const double N3[2][4][3] = {
        { { -1, -1, 10 }, { 10.5, -1, 10 }, { 10.5, 1, 10 }, { -1, 1, 10 } },
        { { 15, -1, -1 }, { 15, 1, -1 }, { 15, 1, 8 }, { 15, -1, 8 } } };
    r = cut_and_compare(X, n, 2, 0.0, radius, dx, N3, 2, brute2_two, NULL);
    report("2D 20x20, two notches (z = 10 and x = 15)", r, -1);
    free(X);
}

/* 3D block 12^3, h = sqrt(3) dx, radius 2h, a tilted rectangle inside it (segments pass it on
 * every side); corners in both orders. */
static void test_lists_3d(void)
{
    int n;
    double dx = 1.0, radius = 2 * sqrt(3.0) * dx, *X = lattice_points(12, 3, dx, &n);
    const double c[3] = { 6.1, 5.93, 6.27 };
    rect rc = rect_make(c, 3.7, 2.6, 0.37, 0.61);
    double Q[2][4][3];
    rect_corners(&rc, Q[0]);
    for (int k = 0; k < 4; k++)
        memcpy(Q[1][k], Q[0][3 - k], sizeof Q[1][k]);
    brute3_ctx ctx = { &rc, HUGE_VAL };
    cut_result r = cut_and_compare(X, n, 3, 0.0, radius, dx, (const double (*)[4][3])Q, 1,
                                   brute3, &ctx);
    report("3D 12^3, tilted rectangle", r, -1);
    cut_result s = cut_and_compare(X, n, 3, 0.0, radius, dx, (const double (*)[4][3])Q + 1, 1,
                                   brute3, &ctx);
    report("3D 12^3, tilted rectangle, corners reversed", s, r.brute);
    char what[200];
    snprintf(what, sizeof what, "3D: brute-force decisions are clear (smallest margin %.2e)",
             ctx.margin);
    check(ctx.margin > 1e-6, what);
    free(X);
}

/* A 3D lattice of 64000 particles with a notch through its middle (timing reported). */
static void test_timing(void)
{
    int n, m = 40, *st, *nb;
    double dx = 1.0, *X = lattice_points(m, 3, dx, &n), t0 = omp_get_wtime();
    sph_neighbours(X, n, 3, 2 * sqrt(3.0) * dx, 0, dx, &st, &nb);
    double t1 = omp_get_wtime();
    long before = st[n];
    static const double N[1][4][3] = {
        { { -1, -1, 20 }, { 20.2, -1, 20 }, { 20.2, 41, 20 }, { -1, 41, 20 } } };
    long after = sph_drop_notch_pairs(X, n, 3, 0.0, st, nb, N, 1, NULL);
    double t2 = omp_get_wtime();
    plane2 p = { 20, -1, 20.2 };
    long brute = 0;
    int *s2, *n2;
    sph_neighbours(X, n, 3, 2 * sqrt(3.0) * dx, 0, dx, &s2, &n2);
    for (int i = 0; i < n; i++)
        for (int k = s2[i]; k < s2[i + 1]; k++) {
            const double *a = X + 3 * i, *b = X + 3 * n2[k];
            double xa[2] = { a[0], a[2] }, xb[2] = { b[0], b[2] };
            brute += brute2(&p, xa, xb);
        }
    char what[200];
    snprintf(what, sizeof what, "timing: 3D lattice %d particles, %ld entries, %ld cut (brute "
             "force %ld); search %.3f s, cut %.3f s on %d threads", n, before, before - after,
             brute, t1 - t0, t2 - t1, omp_get_max_threads());
    check(before - after == brute && brute > 0, what);
    free(X); free(st); free(nb); free(s2); free(n2);
}

int main(void)
{
    test_segment_cases();
    test_segment_random();
    test_lists_2d();
    test_lists_3d();
    test_timing();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
