/* test_solid.c — prisms and pyramids given by their corners (runtime/geom/mesh_solid.c) and
 * their fill.
 *
 * Closed forms: an L-shaped prism (a base that is not convex) of volume 4 x 2 = 8, filled
 * at dx 0.1 with exactly 8000 cell centres (its faces lie on cell faces); a frustum of
 * square sides 2 and 1, height 1 (a prism whose top is not a translate of its base),
 * volume (4 + 1 + 2)/3; a pyramid over a pentagon that is not convex (area 3),
 * height 1.5, volume 1.5; a pyramid over a rectangle with corners in the middle of two
 * edges (volume 2); GenCase's slope, a triangle given as four corners, one repeated
 * (area 4.75, 2 deep: 9.5), with inside and outside points and a distance.  Refused, with
 * what is wrong: a base whose edges cross (a bow tie, a pentagram), a base with all corners on a line, a prism with
 * an odd number of corners, a pyramid of two base corners, a polygon of 1001 corners (1000
 * are built: a pyramid over the regular 1000-gon, volume (m/2) sin(2 pi/m) / 3). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/fill.h"
#include "geom/mesh.h"
#include "geom/region.h"

static int failures = 0;

static void check(int ok, const char *what)
{
    printf("%-4s %s\n", ok ? "ok" : "FAIL", what);
    failures += !ok;
}

/* Builds the solid and checks its volume against the exact one. */
static void check_volume(sph_solid_kind kind, const double *pts, int n, double exact,
                         const char *what)
{
    char err[512], msg[768];
    sph_mesh m;
    const int rc = sph_mesh_solid(kind, pts, n, &m, err, sizeof err);
    snprintf(msg, sizeof msg, "%s: %s, volume %.15g (exact %.15g)", what, rc ? err : "built",
             rc ? 0.0 : m.volume, exact);
    check(rc == 0 && fabs(m.volume / exact - 1) < 1e-12, msg);
    if (!rc)
        sph_mesh_free(&m);
}

/* Building the solid fails with a message that contains `expect`. */
static void check_refused(sph_solid_kind kind, const double *pts, int n, const char *expect,
                          const char *what)
{
    char err[512] = "", msg[768];
    sph_mesh m;
    const int rc = sph_mesh_solid(kind, pts, n, &m, err, sizeof err);
    snprintf(msg, sizeof msg, "%s: refused (\"%s\")", what, rc ? err : "accepted");
    check(rc != 0 && strstr(err, expect) != NULL, msg);
    if (!rc)
        sph_mesh_free(&m);
}

static const double L_PRISM[] = { /* the L in the x-z plane at y = 0, then at y = 2 */
    0, 0, 0, 3, 0, 0, 3, 0, 1, 1, 0, 1, 1, 0, 2, 0, 0, 2,
    0, 2, 0, 3, 2, 0, 3, 2, 1, 1, 2, 1, 1, 2, 2, 0, 2, 2};

static void test_l_prism(void)
{
    check_volume(SPH_SOLID_PRISM, L_PRISM, 12, 8.0, "L-shaped prism");
    sph_shape s = {SPH_PRISM, {0, 0, 0}, {3, 2, 2}, 0, 0, NULL, L_PRISM, 12};
    sph_region r = {.prims = &s, .n = 1};
    double *X;
    const int n = sph_fill_region(&r, 3, 0.1, 0.0, &X);
    char what[200];
    snprintf(what, sizeof what, "L-shaped prism filled at dx 0.1: %d (expected 8000)", n);
    check(n == 8000, what);
    free(X);
    const double notch[3] = {2, 1, 1.5}, leg[3] = {0.5, 1, 1.5}, foot[3] = {2.5, 1, 0.5};
    const double above[3] = {2, 1, 1.25};
    const double d = sph_region_distance(&r, above);
    snprintf(what, sizeof what, "L-shaped prism: inside and outside tests, distance %.15g "
             "from the notch (0.25)", d);
    check(!sph_region_contains(&r, notch) && sph_region_contains(&r, leg) &&
              sph_region_contains(&r, foot) && fabs(d - 0.25) < 1e-12,
          what);
}

static void test_frustum(void)
{
    const double f[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0,
                        0.5, 0.5, 1, 1.5, 0.5, 1, 1.5, 1.5, 1, 0.5, 1.5, 1};
    check_volume(SPH_SOLID_PRISM, f, 8, 7.0 / 3.0, "frustum (a prism, top side 1, base 2)");
}

static void test_pyramid(void)
{
    /* the square [0,2]^2 less the triangle (2,2) (1,1) (0,2): area 4 - 1 = 3 */
    const double p[] = {1, 1, 1.5, /* apex */
                        0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 1, 0, 0, 2, 0};
    check_volume(SPH_SOLID_PYRAMID, p, 6, 3.0 * 1.5 / 3.0,
                 "pyramid over a pentagon that is not convex");
    /* the rectangle [0,2] x [0,1] with a corner in the middle of two of its edges */
    const double q[] = {1, 0.5, 3, /* apex */
                        0, 0, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 0, 1, 0};
    check_volume(SPH_SOLID_PYRAMID, q, 7, 2.0 * 3.0 / 3.0,
                 "pyramid over a rectangle with corners on its edges");
}

static void test_gencase_slope(void)
{
    const double s[] = {19, -1, 1, 9, -1, 0, -0.5, -1, 0, -0.5, -1, 0,
                        19, 1, 1,  9, 1, 0,  -0.5, 1, 0,  -0.5, 1, 0};
    check_volume(SPH_SOLID_PRISM, s, 8, 9.5, "GenCase's slope (a corner given twice)");
    sph_shape sh = {SPH_PRISM, {-0.5, -1, 0}, {19, 1, 1}, 0, 0, NULL, s, 8};
    sph_region r = {.prims = &sh, .n = 1};
    const double in[3] = {9, 0, 0.2}, out[3] = {9, 0, 0.8}, under[3] = {5, 0, -0.5};
    const double d = sph_region_distance(&r, under);
    char what[200];
    snprintf(what, sizeof what, "GenCase's slope: inside and outside tests, distance %.15g "
             "below it (0.5)", d);
    check(sph_region_contains(&r, in) && !sph_region_contains(&r, out) &&
              fabs(d - 0.5) < 1e-12,
          what);
}

static void test_refused(void)
{
    const double bowtie[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                             0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
    check_refused(SPH_SOLID_PRISM, bowtie, 8, "not a simple polygon", "prism, base a bow tie");
    const double star[] = {0, 0, 1, /* apex, then a pentagram: every other corner of a pentagon */
                           1, 0, 0, -0.809017, 0.587785, 0, 0.309017, -0.951057, 0,
                           0.309017, 0.951057, 0, -0.809017, -0.587785, 0};
    check_refused(SPH_SOLID_PYRAMID, star, 6, "not a simple polygon", "pyramid over a pentagram");
    const double line[] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
    check_refused(SPH_SOLID_PYRAMID, line, 5, "not a simple polygon",
                  "pyramid, base corners on a line");
    const double tri_line[] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 2, 0, 0};
    check_refused(SPH_SOLID_PYRAMID, tri_line, 4, "no volume",
                  "pyramid, base of 3 corners on a line");
    check_refused(SPH_SOLID_PRISM, L_PRISM, 7, "two polygons", "prism of 7 corners");
    check_refused(SPH_SOLID_PYRAMID, L_PRISM, 3, "at least 3", "pyramid of 2 base corners");
    for (int m = SPH_SOLID_MAX_CORNERS; m <= SPH_SOLID_MAX_CORNERS + 1; m++) {
        /* a pyramid of height 1 over the regular polygon of m corners in the unit circle */
        const double pi = 3.14159265358979323846;
        double *fan = malloc((size_t)(m + 1) * 3 * sizeof *fan);
        fan[0] = 0, fan[1] = 0, fan[2] = 1;
        for (int k = 0; k < m; k++) {
            fan[3 * (k + 1)] = cos(2 * pi * k / m);
            fan[3 * (k + 1) + 1] = sin(2 * pi * k / m);
            fan[3 * (k + 1) + 2] = 0;
        }
        if (m > SPH_SOLID_MAX_CORNERS)
            check_refused(SPH_SOLID_PYRAMID, fan, m + 1, "more than 1000 corners",
                          "pyramid over 1001 corners");
        else
            check_volume(SPH_SOLID_PYRAMID, fan, m + 1, 0.5 * m * sin(2 * pi / m) / 3,
                         "pyramid over a regular polygon of 1000 corners");
        free(fan);
    }
}

int main(void)
{
    test_l_prism();
    test_frustum();
    test_pyramid();
    test_gencase_slope();
    test_refused();
    if (failures)
        printf("%d check(s) failed\n", failures);
    return failures != 0;
}
