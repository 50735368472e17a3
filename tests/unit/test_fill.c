/* test_fill.c — region membership/distance and lattice filling (counts, volumes, order). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "geom/fill.h"
#include "geom/region.h"

#define PI 3.14159265358979323846

static int failures = 0;

/* Prints one check and counts it when it fails. */
static void check(int ok, const char *what)
{
    printf("%-4s %s\n", ok ? "ok" : "FAIL", what);
    failures += !ok;
}

/* Fills prims (n of them) and returns the count; *X set. */
static int fill(const sph_shape *prims, int np, int dim, double dx, double y, double **X)
{
    sph_region r = { .prims = prims, .n = np };
    return sph_fill_region(&r, dim, dx, y, X);
}

/* Exact box counts, including the 0.2 / 0.25e-3 = 800 rounding case and a 2D box with
 * a.y == b.y. */
static void test_box_counts(void)
{
    char what[200];
    double *X;
    sph_shape b2 = { SPH_BOX, { 0, 0, 0 }, { 0.2, 0, 0.02 }, 0, 0, NULL, NULL, 0 };
    int n = fill(&b2, 1, 2, 0.25e-3, 0.0, &X);
    double xmin = HUGE_VAL, xmax = -HUGE_VAL;
    for (int i = 0; i < n; i++) {
        xmin = fmin(xmin, X[2 * i]);
        xmax = fmax(xmax, X[2 * i]);
    }
    snprintf(what, sizeof what, "2D box 0.2 x 0.02, dx 0.25e-3: %d particles (expected 800*80 = "
             "64000), x in [%.6g, %.6g]", n, xmin, xmax);
    check(n == 64000 && fabs(xmin - 0.125e-3) < 1e-12 && fabs(xmax - 0.199875) < 1e-12, what);
    free(X);
    sph_shape b2b = { SPH_BOX, { -2e-3, 0, 0 }, { 200e-3, 0, 20e-3 }, 0, 0, NULL, NULL, 0 };
    n = fill(&b2b, 1, 2, 1e-3, 0.0, &X);
    snprintf(what, sizeof what, "2D box [-2e-3, 0.2] x [0, 0.02], dx 1e-3: %d (expected 4040)", n);
    check(n == 4040, what);
    free(X);
    sph_shape b3 = { SPH_BOX, { 0, 0, 0 }, { 0.2, 0.01, 0.02 }, 0, 0, NULL, NULL, 0 };
    n = fill(&b3, 1, 3, 1e-3, 0.0, &X);
    snprintf(what, sizeof what, "3D box 0.2 x 0.01 x 0.02, dx 1e-3: %d (expected 40000)", n);
    check(n == 40000, what);
    free(X);
}

/* N dx^dim vs the true volume (within 2%, 20 particles across). */
static void check_volume(const char *name, const sph_shape *p, int np, int dim, double dx,
                         double exact)
{
    char what[200];
    double *X;
    int n = fill(p, np, dim, dx, 0.0, &X);
    double v = n * pow(dx, dim), e = fabs(v / exact - 1.0);
    snprintf(what, sizeof what, "%s: N = %d, N dx^%d = %.5g vs %.5g (rel. error %.2e < 2e-2)",
             name, n, dim, v, exact, e);
    check(e < 2e-2, what);
    free(X);
}

/* Spheres and cylinders in 3D and their 2D versions. */
static void test_volumes(void)
{
    sph_shape sph = { SPH_SPHERE, { 0.3, -0.2, 0.1 }, { 0, 0, 0 }, 1.0, 0, NULL, NULL, 0 };
    check_volume("3D sphere r 1, dx 0.1", &sph, 1, 3, 0.1, 4.0 / 3.0 * PI);
    sph_shape cx = { SPH_CYLINDER, { 0, 0, 0 }, { 3, 0, 0 }, 1.0, 0, NULL, NULL, 0 };
    check_volume("3D cylinder along x, r 1, L 3", &cx, 1, 3, 0.1, PI * 3);
    sph_shape co = { SPH_CYLINDER, { 0, 0, 0 }, { 1, 2, 2 }, 1.0, 0, NULL, NULL, 0 };
    check_volume("3D oblique cylinder r 1, L 3", &co, 1, 3, 0.1, PI * 3);
    check_volume("2D sphere -> disc r 1", &sph, 1, 2, 0.1, PI);
    sph_shape cy = { SPH_CYLINDER, { 0.5, -1, 0.5 }, { 0.5, 1, 0.5 }, 1.0, 0, NULL, NULL, 0 };
    check_volume("2D cylinder along y -> disc r 1", &cy, 1, 2, 0.1, PI);
    sph_shape cr = { SPH_CYLINDER, { 0, 0, 0.5 }, { 2, 0, 0.5 }, 0.5, 0, NULL, NULL, 0 };
    double *X;
    int n = fill(&cr, 1, 2, 0.1, 0.0, &X);
    char what[200];
    snprintf(what, sizeof what, "2D cylinder along x (r 0.5, L 2) -> rectangle: %d (expected 200)", n);
    check(n == 200, what);
    free(X);
}

/* Box minus sphere and a union of overlapping boxes. */
static void test_csg(void)
{
    char what[200];
    double *X, dx = 0.1, dmin = HUGE_VAL;
    sph_shape d[2] = { { SPH_BOX, { -1, -1, -1 }, { 1, 1, 1 }, 0, 0, NULL, NULL, 0 },
                       { SPH_SPHERE, { 0, 0, 0 }, { 0, 0, 0 }, 0.5, 1, NULL, NULL, 0 } };
    int n = fill(d, 2, 3, dx, 0.0, &X), inball = 0;
    for (int a = 0; a < 20; a++)  /* lattice points of the box inside the ball */
        for (int b = 0; b < 20; b++)
            for (int c = 0; c < 20; c++) {
                double x = -1 + (a + .5) * dx, y = -1 + (b + .5) * dx, z = -1 + (c + .5) * dx;
                inball += x * x + y * y + z * z <= 0.25;
            }
    for (int i = 0; i < n; i++)
        dmin = fmin(dmin, sqrt(X[3 * i] * X[3 * i] + X[3 * i + 1] * X[3 * i + 1] +
                               X[3 * i + 2] * X[3 * i + 2]));
    double v = n * dx * dx * dx, exact = 8.0 - 4.0 / 3.0 * PI * 0.125;
    snprintf(what, sizeof what, "box [-1,1]^3 minus sphere r 0.5: %d = 8000 - %d, closest to centre "
             "%.4f > 0.5, volume %.4f vs %.4f", n, inball, dmin, v, exact);
    check(n == 8000 - inball && dmin > 0.5 && fabs(v / exact - 1) < 2e-2, what);
    free(X);
    sph_shape u[2] = { { SPH_BOX, { 0, 0, 0 }, { 1, 0, 1 }, 0, 0, NULL, NULL, 0 },
                       { SPH_BOX, { 0.5, 0, 0.5 }, { 1.5, 0, 1.5 }, 0, 0, NULL, NULL, 0 } };
    n = fill(u, 2, 2, dx, 0.0, &X);
    snprintf(what, sizeof what, "2D union of overlapping unit boxes: %d (expected 175)", n);
    check(n == 175, what);
    free(X);
    sph_shape only = { SPH_SPHERE, { 0, 0, 0 }, { 0, 0, 0 }, 1.0, 1, NULL, NULL, 0 };
    n = fill(&only, 1, 3, dx, 0.0, &X);
    check(n == 0 && X == NULL, "region with only a subtracted primitive: 0 particles");
}

/* Documented order: tiles (16 in 2D, 8 in 3D) x fastest, inside a tile x fastest. */
static void test_order(void)
{
    char what[200];
    double *X, dx = 0.5;
    sph_shape b = { SPH_BOX, { 0, 0, 0 }, { 20, 7, 12 }, 0, 0, NULL, NULL, 0 };
    int ok = 1;
    for (int dim = 2; dim <= 3; dim++) {
        int n = fill(&b, 1, dim, dx, 3.0, &X), T = dim == 2 ? 16 : 8;
        long nk[3] = { 40, dim == 2 ? 24 : 14, 24 }, nt[3], prev = -1;
        for (int c = 0; c < dim; c++)
            nt[c] = (nk[c] + T - 1) / T;
        for (int i = 0; i < n; i++) {
            long tile = 0, local = 0;
            for (int c = dim - 1; c >= 0; c--) {
                long k = lround(X[i * dim + c] / dx - 0.5);
                tile = tile * nt[c] + k / T;
                local = local * T + k % T;
            }
            long key = tile * (dim == 2 ? T * T : T * T * T) + local;
            ok = ok && key > prev;
            prev = key;
        }
        long expect = dim == 2 ? 40 * 24 : 40 * 14 * 24;
        snprintf(what, sizeof what, "%dD fill order: %d particles (expected %ld), tile order strictly "
                 "increasing", dim, n, expect);
        check(ok && n == expect, what);
        free(X);
    }
}

/* Region membership and distances of single primitives and a difference. */
static void test_region(void)
{
    char what[200];
    sph_shape box = { SPH_BOX, { 0, 0, 0 }, { 1, 1, 1 }, 0, 0, NULL, NULL, 0 };
    sph_shape cyl = { SPH_CYLINDER, { 0, 0, 0 }, { 0, 0, 2 }, 0.5, 0, NULL, NULL, 0 };
    sph_shape d[2] = { box, { SPH_SPHERE, { 1, 1, 1 }, { 0, 0, 0 }, 0.5, 1, NULL, NULL, 0 } };
    sph_region rb = { .prims = &box, .n = 1 }, rc = { .prims = &cyl, .n = 1 };
    sph_region rd = { .prims = d, .n = 2 };
    double p1[3] = { 2, 2, 2 }, p2[3] = { 0.5, 0.5, 0.5 }, p3[3] = { 1.5, 0, 3 };
    double p4[3] = { 0.25, 0, 1 }, p5[3] = { 0.95, 0.95, 0.95 }, p6[3] = { 0, 0, 2 };
    double e = fabs(sph_region_distance(&rb, p1) - sqrt(3.0)) + sph_region_distance(&rb, p2) +
               fabs(sph_region_distance(&rc, p3) - sqrt(2.0)) + sph_region_distance(&rc, p4);
    int in = sph_region_contains(&rb, p2) && !sph_region_contains(&rb, p1) &&
             sph_region_contains(&rc, p4) && sph_region_contains(&rc, p6) &&
             !sph_region_contains(&rd, p5) && sph_region_contains(&rd, p2);
    double dd = sph_region_distance(&rd, p5), dexp = 0.5 - sqrt(3 * 0.05 * 0.05);
    snprintf(what, sizeof what, "region: box/cylinder distances (error %.1e), membership, difference "
             "distance %.4f (exact %.4f)", e, dd, dexp);
    check(e < 1e-14 && in && fabs(dd - dexp) < 1e-12, what);
}

/* Lattices: cells centred on a bounding box that does not span whole cells, and cells
 * aligned to a given corner with lattice nodes on the faces counted as inside. */
static void test_lattice(void)
{
    char what[240];
    double *X;
    /* r = 3.2, L = 32.4, dx = 0.5: 13 cells across (axis on a node: 129 per layer, the
     * lattice points with i^2 + j^2 <= 6.4^2) and 65 layers; cells from the bounding box
     * minimum would put 131 in a layer (N dx^3 2.1 % above the volume). */
    sph_shape bar = { SPH_CYLINDER, { 0, 0, 0 }, { 0, 0, 32.4e-3 }, 3.2e-3, 0, NULL, NULL, 0 };
    int n = fill(&bar, 1, 3, 0.5e-3, 0.0, &X), on_axis = 0;
    for (int i = 0; i < n; i++)
        on_axis += fabs(X[3 * i]) < 1e-12 && fabs(X[3 * i + 1]) < 1e-12;
    double v = n * 0.125e-9, exact = PI * 3.2e-3 * 3.2e-3 * 32.4e-3;
    snprintf(what, sizeof what, "cylinder r 3.2 L 32.4 dx 0.5 (centred cells): %d (expected 129 x "
             "65 = 8385, %d on the axis), N dx^3 %.4f of the volume", n, on_axis, v / exact);
    check(n == 8385 && on_axis == 65 && fabs(v / exact - 1) < 1e-2, what);
    free(X);
    /* Unit cube, cells with a corner at -0.05: the nodes 0, 0.1, ..., 1 (11 per axis), those on
     * the faces included. */
    sph_shape cube = { SPH_BOX, { 0, 0, 0 }, { 1, 1, 1 }, 0, 0, NULL, NULL, 0 };
    sph_region r = { .prims = &cube, .n = 1, .has_corner = 1, .corner = { -0.05, -0.05, -0.05 } };
    n = sph_fill_region(&r, 3, 0.1, 0.0, &X);
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int i = 0; i < 3 * n; i++)
        lo = fmin(lo, X[i]), hi = fmax(hi, X[i]);
    snprintf(what, sizeof what, "unit cube, lattice corner -0.05, dx 0.1: %d nodes (expected "
             "11^3 = 1331) from %.3g to %.3g", n, lo, hi);
    check(n == 1331 && fabs(lo) < 1e-12 && fabs(hi - 1) < 1e-12, what);
    free(X);
    r.corner[0] = r.corner[1] = r.corner[2] = 0.0;
    n = sph_fill_region(&r, 3, 0.1, 0.0, &X);
    snprintf(what, sizeof what, "unit cube, lattice corner 0: %d (expected 1000)", n);
    check(n == 1000, what);
    free(X);
}

/* A lattice beyond 2e9 points is refused (-1, with a message) without filling it, also when
 * one axis alone exceeds what a long counts; an empty region gives 0. */
static void test_too_large(void)
{
    char what[200];
    double *X = NULL;
    sph_shape cube = { SPH_BOX, { 0, 0, 0 }, { 1, 1, 1 }, 0, 0, NULL, NULL, 0 };
    int n = fill(&cube, 1, 3, 1e-4, 0.0, &X);
    snprintf(what, sizeof what, "unit cube at dx 1e-4 (1e12 points): %d (expected -1)", n);
    check(n == -1 && !X, what);
    sph_shape bar = { SPH_BOX, { 0, 0, 0 }, { 1, 0, 1e-30 }, 0, 0, NULL, NULL, 0 };
    n = fill(&bar, 1, 2, 1e-25, 0.0, &X);
    snprintf(what, sizeof what, "2D bar 1 x 1e-30 at dx 1e-25 (1e25 points along x): %d "
             "(expected -1)", n);
    check(n == -1 && !X, what);
    n = fill(&cube, 0, 3, 0.1, 0.0, &X);
    snprintf(what, sizeof what, "a region of no shape: %d (expected 0)", n);
    check(n == 0, what);
}

int main(void)
{
    test_region();
    test_lattice();
    test_box_counts();
    test_volumes();
    test_csg();
    test_order();
    test_too_large();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
