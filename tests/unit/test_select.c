/* test_select.c — measurement planes and `near` selections on filled beams. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "geom/fill.h"
#include "geom/region.h"
#include "geom/select.h"

static int failures = 0;

/* Prints one check and counts it when it fails. */
static void check(int ok, const char *what)
{
    printf("%-4s %s\n", ok ? "ok" : "FAIL", what);
    failures += !ok;
}

/* 1 when component c of every selected particle equals v (to 1e-12). */
static int all_at(const double *X, int dim, const int *idx, int m, int c, double v)
{
    for (int k = 0; k < m; k++)
        if (fabs(X[idx[k] * dim + c] - v) > 1e-12)
            return 0;
    return 1;
}

/* 2D beam [0, 0.2] x [0, 0.02], dx 1e-3 (200 x 20 particles). */
static void test_2d(void)
{
    char what[200];
    double *X, dx = 1e-3;
    int *idx;
    sph_shape beam = { SPH_BOX, { 0, 0, 0 }, { 0.2, 0, 0.02 }, 0, 0, NULL, NULL, 0 };
    sph_region rb = { .prims = &beam, .n = 1 };
    int n = sph_fill_region(&rb, 2, dx, 0.0, &X);
    const double end[4][3] = { { 0.2, 0, 0 }, { 0.2, 1, 0 }, { 0.2, 1, 0.02 }, { 0.2, 0, 0.02 } };
    int m = sph_select_plane(X, n, 2, dx, end, &idx);
    snprintf(what, sizeof what, "2D plane at the free end x = 0.2: %d particles (expected one column "
             "of 20, all at x = 0.1995)", m);
    check(m == 20 && all_at(X, 2, idx, m, 0, 0.1995), what);
    free(idx);
    const double tip[4][3] = { { 0.2, 0, 9.5e-3 }, { 0.2, 1, 9.5e-3 }, { 0.2, 1, 10.5e-3 },
                               { 0.2, 0, 10.5e-3 } };
    m = sph_select_plane(X, n, 2, dx, tip, &idx);
    snprintf(what, sizeof what, "2D tip plane z in [9.5e-3, 10.5e-3] (the language example): %d "
             "(expected 2)", m);
    check(m == 2 && all_at(X, 2, idx, m, 0, 0.1995), what);
    free(idx);
    const double mid[4][3] = { { 0.1, 0, -1 }, { 0.1, 0, 1 }, { 0.1, 1, 1 }, { 0.1, 1, -1 } };
    m = sph_select_plane(X, n, 2, dx, mid, &idx);
    snprintf(what, sizeof what, "2D plane x = 0.1 (between columns): %d (expected 2 columns, 40)", m);
    check(m == 40, what);
    free(idx);
    sph_shape clamp = { SPH_BOX, { -2e-3, 0, 0 }, { 0, 0, 0.02 }, 0, 0, NULL, NULL, 0 };
    sph_region rc = { .prims = &clamp, .n = 1 };
    m = sph_select_near(X, n, 2, 0.0, dx, &rc, &idx);
    snprintf(what, sizeof what, "2D near box x in [-2e-3, 0] (a.y == b.y): %d (expected the first "
             "column, 20, at x = 0.0005)", m);
    check(m == 20 && all_at(X, 2, idx, m, 0, 0.0005), what);
    free(idx);
    sph_shape disc = { SPH_CYLINDER, { 0.1, -1, 0.025 }, { 0.1, 1, 0.025 }, 0.005, 0, NULL, NULL, 0 };
    sph_region rd = { .prims = &disc, .n = 1 };
    m = sph_select_near(X, n, 2, 0.0, dx, &rd, &idx);
    snprintf(what, sizeof what, "2D near a y-axis cylinder (disc r 5e-3 at z 0.025): %d (expected "
             "the 4 top-row particles with |x - 0.1| <= 1.5e-3)", m);
    check(m == 4 && all_at(X, 2, idx, m, 1, 0.0195), what);
    free(idx);
    free(X);
}

/* 3D beam [0, 0.2] x [0, 0.01] x [0, 0.02], dx 1e-3. */
static void test_3d(void)
{
    char what[200];
    double *X, dx = 1e-3;
    int *idx;
    sph_shape beam = { SPH_BOX, { 0, 0, 0 }, { 0.2, 0.01, 0.02 }, 0, 0, NULL, NULL, 0 };
    sph_region rb = { .prims = &beam, .n = 1 };
    int n = sph_fill_region(&rb, 3, dx, 0.0, &X);
    const double end[4][3] = { { 0.2, 0, 0 }, { 0.2, 0.01, 0 }, { 0.2, 0.01, 0.02 },
                               { 0.2, 0, 0.02 } };
    int m = sph_select_plane(X, n, 3, dx, end, &idx);
    snprintf(what, sizeof what, "3D plane at the free end: %d (expected 10 x 20 = 200 at x = 0.1995)", m);
    check(m == 200 && all_at(X, 3, idx, m, 0, 0.1995), what);
    free(idx);
    const double tip[4][3] = { { 0.2, 0, 9.5e-3 }, { 0.2, 1, 9.5e-3 }, { 0.2, 1, 10.5e-3 },
                               { 0.2, 0, 10.5e-3 } };
    m = sph_select_plane(X, n, 3, dx, tip, &idx);
    snprintf(what, sizeof what, "3D tip plane strip: %d (expected 2 rows x 10 = 20)", m);
    check(m == 20, what);
    free(idx);
    sph_shape clamp = { SPH_BOX, { -2e-3, -1, -1 }, { 0, 1, 1 }, 0, 0, NULL, NULL, 0 };
    sph_region rc = { .prims = &clamp, .n = 1 };
    m = sph_select_near(X, n, 3, 0.0, dx, &rc, &idx);
    snprintf(what, sizeof what, "3D near box x <= 0: %d (expected one layer, 200)", m);
    check(m == 200 && all_at(X, 3, idx, m, 0, 0.0005), what);
    free(idx);
    sph_shape ball = { SPH_SPHERE, { 0.1, 0.005, 0.0 }, { 0, 0, 0 }, 0.0, 0, NULL, NULL, 0 };
    sph_region rs = { .prims = &ball, .n = 1 };
    m = sph_select_near(X, n, 3, 0.0, 2 * dx, &rs, &idx);
    int expect = 0;
    for (int i = 0; i < n; i++)
        expect += sqrt(pow(X[3 * i] - 0.1, 2) + pow(X[3 * i + 1] - 0.005, 2) +
                       pow(X[3 * i + 2], 2)) <= 2 * dx;
    snprintf(what, sizeof what, "3D near a point on the bottom face (within 2 dx): %d (direct "
             "count %d)", m, expect);
    check(m == expect && m == 16, what);
    free(idx);
    free(X);
}

int main(void)
{
    test_2d();
    test_3d();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
