/* test_mesh.c — closed surfaces from VTK and STL files (runtime/geom/mesh.h) and their fill.
 *
 * Closed forms: a unit cube (volume 1) written as ASCII STL with some triangles reversed,
 * as ASCII and BINARY VTK with quads; an octahedron |x| + |y| + |z| <= 1 (volume 4/3) whose
 * edges and vertices lie on lattice lines, filled on the nodes k dx: the centred octahedral
 * number (2n + 1)(2n^2 + 2n + 3)/3 of them, n = 1/dx, only when every ray through an edge
 * or a vertex is counted right; a subdivided icosahedron as binary STL (volume of the
 * polyhedron from its triangles).  The four-point-bending beams of the paper
 * (cases/xml/Shape_{90,60,45}Lambda.vtk, binary VTK, inconsistently oriented) enclose
 * (80 x 20 - 9) mm^2 x 10 mm = 1.591e-5 m^3 (a notch of 2 x 3 mm under a triangle of 2 x 3
 * mm, sheared for 60 and 45 degrees); a cube with a face missing is refused, naming its
 * file. */
#define _XOPEN_SOURCE 700
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "geom/fill.h"
#include "geom/mesh.h"
#include "geom/region.h"

static int failures = 0;
static char tmpdir[64];

static void check(int ok, const char *what)
{
    printf("%-4s %s\n", ok ? "ok" : "FAIL", what);
    failures += !ok;
}

static const char *tmp(const char *name)
{
    static char buf[4][256];
    static int k = 0;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, name);
    return buf[k];
}

/* ------------------------------------------------------------------ writing test files */

/* The unit cube: 8 corners, 6 quads (outward). */
static const double CUBE_V[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
static const int CUBE_Q[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};

/* ASCII STL of the cube; faces[f] = 0 leaves face f out; odd triangles of the first three
 * faces reversed. */
static void write_cube_stl(const char *path, const int *faces)
{
    FILE *f = fopen(path, "w");
    fprintf(f, "solid cube\n");
    for (int q = 0; q < 6; q++) {
        if (!faces[q])
            continue;
        for (int h = 0; h < 2; h++) {
            int t[3] = {CUBE_Q[q][0], CUBE_Q[q][1 + h], CUBE_Q[q][2 + h]};
            if (q < 3 && h == 1) {
                int s = t[1];
                t[1] = t[2];
                t[2] = s;
            }
            fprintf(f, "  facet normal 0 0 0\n    outer loop\n");
            for (int c = 0; c < 3; c++)
                fprintf(f, "      vertex %g %g %g\n", CUBE_V[t[c]][0], CUBE_V[t[c]][1],
                        CUBE_V[t[c]][2]);
            fprintf(f, "    endloop\n  endfacet\n");
        }
    }
    fprintf(f, "endsolid cube\n");
    fclose(f);
}

static void put_be32(FILE *f, uint32_t u)
{
    unsigned char b[4] = {(unsigned char)(u >> 24), (unsigned char)(u >> 16),
                          (unsigned char)(u >> 8), (unsigned char)u};
    fwrite(b, 1, 4, f);
}

static void put_be_float(FILE *f, float x)
{
    uint32_t u;
    memcpy(&u, &x, 4);
    put_be32(f, u);
}

/* The cube as legacy VTK polydata with quads, ASCII or BINARY. */
static void write_cube_vtk(const char *path, int binary)
{
    FILE *f = fopen(path, "wb");
    fprintf(f, "# vtk DataFile Version 3.0\ncube\n%s\nDATASET POLYDATA\nPOINTS 8 float\n",
            binary ? "BINARY" : "ASCII");
    for (int i = 0; i < 8; i++)
        for (int c = 0; c < 3; c++) {
            if (binary)
                put_be_float(f, (float)CUBE_V[i][c]);
            else
                fprintf(f, "%g%c", CUBE_V[i][c], c == 2 ? '\n' : ' ');
        }
    fprintf(f, "%sPOLYGONS 6 30\n", binary ? "\n" : "");
    for (int q = 0; q < 6; q++) {
        if (binary)
            put_be32(f, 4);
        else
            fprintf(f, "4");
        for (int c = 0; c < 4; c++) {
            if (binary)
                put_be32(f, (uint32_t)CUBE_Q[q][c]);
            else
                fprintf(f, " %d", CUBE_Q[q][c]);
        }
        if (!binary)
            fprintf(f, "\n");
    }
    fprintf(f, "%sCELL_DATA 6\n", binary ? "\n" : "");
    fclose(f);
}

/* The octahedron |x| + |y| + |z| <= 1 as ASCII VTK (triangles, some reversed). */
static void write_octahedron_vtk(const char *path)
{
    FILE *f = fopen(path, "w");
    fprintf(f, "# vtk DataFile Version 3.0\noctahedron\nASCII\nDATASET POLYDATA\n"
               "POINTS 6 double\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
               "POLYGONS 8 32\n");
    int n = 0;
    for (int sx = 0; sx < 2; sx++)
        for (int sy = 0; sy < 2; sy++)
            for (int sz = 0; sz < 2; sz++)
                fprintf(f, "3 %d %d %d\n", sx, 2 + sy, 4 + sz), n++;
    fclose(f);
}

/* A unit sphere approximated by a subdivided icosahedron, as binary STL (little-endian). */
typedef struct {
    double (*v)[3];
    int nv;
    int (*t)[3];
    int nt;
} trimesh;

static int midpoint(trimesh *m, int a, int b)
{
    double p[3], r = 0;
    for (int c = 0; c < 3; c++)
        p[c] = 0.5 * (m->v[a][c] + m->v[b][c]), r += p[c] * p[c];
    r = sqrt(r);
    for (int i = 0; i < m->nv; i++)
        if (fabs(m->v[i][0] - p[0] / r) + fabs(m->v[i][1] - p[1] / r) +
                fabs(m->v[i][2] - p[2] / r) < 1e-12)
            return i;
    for (int c = 0; c < 3; c++)
        m->v[m->nv][c] = p[c] / r;
    return m->nv++;
}

static void icosphere(trimesh *m, int levels)
{
    const double g = (1 + sqrt(5.0)) / 2;
    const double v0[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                              {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                              {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    const int t0[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                           {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                           {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                           {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    int maxt = 20 << (2 * levels);
    m->v = malloc((size_t)maxt * sizeof *m->v);
    m->t = malloc((size_t)maxt * sizeof *m->t);
    m->nv = 12;
    m->nt = 20;
    for (int i = 0; i < 12; i++)
        for (int c = 0; c < 3; c++)
            m->v[i][c] = v0[i][c] / sqrt(1 + g * g);
    memcpy(m->t, t0, sizeof t0);
    for (int l = 0; l < levels; l++) {
        int (*t)[3] = malloc((size_t)maxt * sizeof *t), nt = 0;
        for (int k = 0; k < m->nt; k++) {
            int a = m->t[k][0], b = m->t[k][1], c = m->t[k][2];
            int ab = midpoint(m, a, b), bc = midpoint(m, b, c), ca = midpoint(m, c, a);
            int q[4][3] = {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}};
            memcpy(t[nt], q, sizeof q);
            nt += 4;
        }
        free(m->t);
        m->t = t;
        m->nt = nt;
    }
}

static void put_le_float(FILE *f, float x)
{
    unsigned char b[4];
    uint32_t u;
    memcpy(&u, &x, 4);
    for (int k = 0; k < 4; k++)
        b[k] = (unsigned char)(u >> (8 * k));
    fwrite(b, 1, 4, f);
}

/* Writes m as binary STL and returns the volume of the polyhedron of its float vertices. */
static double write_stl_binary(const char *path, const trimesh *m)
{
    FILE *f = fopen(path, "wb");
    char header[80] = "binary STL written by test_mesh";
    fwrite(header, 1, 80, f);
    unsigned char n[4] = {(unsigned char)m->nt, (unsigned char)(m->nt >> 8),
                          (unsigned char)(m->nt >> 16), (unsigned char)(m->nt >> 24)};
    fwrite(n, 1, 4, f);
    double vol = 0;
    for (int k = 0; k < m->nt; k++) {
        float p[3][3];
        for (int c = 0; c < 3; c++)
            for (int d = 0; d < 3; d++)
                p[c][d] = (float)m->v[m->t[k][c]][d];
        for (int d = 0; d < 3; d++)
            put_le_float(f, 0.0f);
        for (int c = 0; c < 3; c++)
            for (int d = 0; d < 3; d++)
                put_le_float(f, p[c][d]);
        fwrite("\0\0", 1, 2, f);
        vol += ((double)p[0][0] * ((double)p[1][1] * p[2][2] - (double)p[1][2] * p[2][1]) -
                (double)p[0][1] * ((double)p[1][0] * p[2][2] - (double)p[1][2] * p[2][0]) +
                (double)p[0][2] * ((double)p[1][0] * p[2][1] - (double)p[1][1] * p[2][0])) / 6;
    }
    fclose(f);
    return vol;
}

/* ------------------------------------------------------------------ checks */

/* Fills the surface in file (one mesh primitive) with lattice spacing dx. */
static int fill_mesh(const char *file, double dx, int has_corner, double corner, double **X)
{
    sph_shape s = {SPH_MESH, {0, 0, 0}, {0, 0, 0}, 0, 0, file, NULL, 0};
    sph_region r = {.prims = &s, .n = 1, .has_corner = has_corner,
                    .corner = {corner, corner, corner}};
    return sph_fill_region(&r, 3, dx, 0.0, X);
}

static void check_load(const char *file, double volume, const char *what)
{
    char err[512], msg[768];
    sph_mesh m;
    int rc = sph_mesh_load(file, &m, err, sizeof err);
    snprintf(msg, sizeof msg, "%s: %s, volume %.10g (exact %.10g)", what,
             rc ? err : "loaded", rc ? 0.0 : m.volume, volume);
    check(rc == 0 && fabs(m.volume / volume - 1) < 1e-12, msg);
    if (!rc)
        sph_mesh_free(&m);
}

static void test_cube(void)
{
    const int all[6] = {1, 1, 1, 1, 1, 1};
    write_cube_stl(tmp("cube.stl"), all);
    write_cube_vtk(tmp("cube_ascii.vtk"), 0);
    write_cube_vtk(tmp("cube_binary.vtk"), 1);
    check_load(tmp("cube.stl"), 1.0, "ASCII STL cube, three triangles reversed");
    check_load(tmp("cube_ascii.vtk"), 1.0, "ASCII VTK cube of quads");
    check_load(tmp("cube_binary.vtk"), 1.0, "BINARY VTK cube of quads");
    double *X;
    int n = fill_mesh(tmp("cube.stl"), 0.05, 0, 0, &X);
    char what[200];
    snprintf(what, sizeof what, "cube filled at dx 0.05: %d (expected 20^3 = 8000)", n);
    check(n == 8000, what);
    free(X);
    sph_shape s = {SPH_MESH, {0, 0, 0}, {0, 0, 0}, 0, 0, tmp("cube_binary.vtk"), NULL, 0};
    sph_region r = {.prims = &s, .n = 1};
    double out[3] = {0.5, 0.5, 2}, in[3] = {0.25, 0.5, 0.75}, edge[3] = {2, 2, 0.5};
    double d1 = sph_region_distance(&r, out), d2 = sph_region_distance(&r, edge);
    snprintf(what, sizeof what, "cube: distances %.15g (1) and %.15g (sqrt 2), inside test",
             d1, d2);
    check(fabs(d1 - 1) < 1e-12 && fabs(d2 - sqrt(2.0)) < 1e-12 && sph_region_contains(&r, in) &&
              !sph_region_contains(&r, out), what);
}

/* The cube in the layout of VTK 5 (OFFSETS, CONNECTIVITY); the unit tetrahedron as one
 * triangle strip 0 1 2 3 0 1 (volume 1/6). */
static void test_vtk_layouts(void)
{
    FILE *f = fopen(tmp("cube5.vtk"), "w");
    fprintf(f, "# vtk DataFile Version 5.1\ncube\nASCII\nDATASET POLYDATA\nPOINTS 8 float\n");
    for (int i = 0; i < 8; i++)
        fprintf(f, "%g %g %g\n", CUBE_V[i][0], CUBE_V[i][1], CUBE_V[i][2]);
    fprintf(f, "POLYGONS 7 24\nOFFSETS vtktypeint64\n0 4 8 12 16 20 24\n"
               "CONNECTIVITY vtktypeint64\n");
    for (int q = 0; q < 6; q++)
        fprintf(f, "%d %d %d %d\n", CUBE_Q[q][0], CUBE_Q[q][1], CUBE_Q[q][2], CUBE_Q[q][3]);
    fclose(f);
    check_load(tmp("cube5.vtk"), 1.0, "ASCII VTK 5.1 cube (OFFSETS, CONNECTIVITY)");
    f = fopen(tmp("tetra.vtk"), "w");
    fprintf(f, "# vtk DataFile Version 3.0\ntetrahedron\nASCII\nDATASET POLYDATA\n"
               "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
               "TRIANGLE_STRIPS 1 7\n6 0 1 2 3 0 1\n");
    fclose(f);
    check_load(tmp("tetra.vtk"), 1.0 / 6.0, "ASCII VTK tetrahedron as a triangle strip");
}

static void test_octahedron(void)
{
    write_octahedron_vtk(tmp("octahedron.vtk"));
    check_load(tmp("octahedron.vtk"), 4.0 / 3.0, "ASCII VTK octahedron, inconsistent triangles");
    double dx = 0.05, *X;
    int nn = 20, n = fill_mesh(tmp("octahedron.vtk"), dx, 1, -0.5 * dx, &X);
    int expected = (2 * nn + 1) * (2 * nn * nn + 2 * nn + 3) / 3;
    char what[240];
    snprintf(what, sizeof what, "octahedron on the nodes k dx (rays through its edges and "
             "vertices): %d (expected %d, faces included)", n, expected);
    check(n == expected, what);
    free(X);
    n = fill_mesh(tmp("octahedron.vtk"), dx, 0, 0, &X);
    double v = n * dx * dx * dx;
    snprintf(what, sizeof what, "octahedron, cell centres: N dx^3 = %.4f (4/3 within 2 %%)", v);
    check(fabs(v / (4.0 / 3.0) - 1) < 2e-2, what);
    free(X);
}

static void test_icosphere(void)
{
    trimesh m;
    icosphere(&m, 3);
    double vol = write_stl_binary(tmp("sphere.stl"), &m);
    char what[240];
    snprintf(what, sizeof what, "binary STL icosphere (%d triangles)", m.nt);
    check_load(tmp("sphere.stl"), vol, what);
    double dx = 0.05, *X;
    int n = fill_mesh(tmp("sphere.stl"), dx, 0, 0, &X);
    double v = n * dx * dx * dx;
    snprintf(what, sizeof what, "icosphere filled at dx 0.05: N dx^3 = %.4f vs %.4f (2 %%)", v,
             vol);
    check(fabs(v / vol - 1) < 2e-2, what);
    free(X);
    free(m.v);
    free(m.t);
}

static void test_beams(void)
{
    static const char *const names[] = {"Shape_90Lambda.vtk", "Shape_60Lambda.vtk",
                                        "Shape_45Lambda.vtk"};
    const double exact = (80e-3 * 20e-3 - 9e-6) * 10e-3;
    for (int k = 0; k < 3; k++) {
        char path[1024], what[300];
        snprintf(path, sizeof path, "%s/cases/xml/%s", SPH_SOURCE_DIR, names[k]);
        sph_mesh m;
        char err[512];
        if (sph_mesh_load(path, &m, err, sizeof err)) {
            check(0, err);
            continue;
        }
        double div = 0; /* the divergence theorem once more, about the origin */
        for (int t = 0; t < m.nt; t++) {
            const double *a = m.v + 3 * m.t[3 * t], *b = m.v + 3 * m.t[3 * t + 1],
                         *c = m.v + 3 * m.t[3 * t + 2];
            div += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
        }
        double dx = 0.5e-3, *X;
        int n = fill_mesh(path, dx, 0, 0, &X);
        double v = n * dx * dx * dx;
        snprintf(what, sizeof what, "%s: %d triangles, enclosed volume %.6g (divergence %.6g, "
                 "exact %.6g); %d particles of 0.5 mm, N dx^3 = %.6g (2 %%)", names[k], m.nt,
                 m.volume, div, exact, n, v);
        check(fabs(div / exact - 1) < 1e-6 && fabs(m.volume / div - 1) < 1e-12 &&
                  fabs(v / div - 1) < 2e-2, what);
        free(X);
        sph_mesh_free(&m);
    }
}

static void test_refused(void)
{
    const int five[6] = {1, 1, 1, 1, 1, 0};
    const char *path = tmp("open_cube.stl");
    write_cube_stl(path, five);
    sph_mesh m;
    char err[512], what[700];
    int rc = sph_mesh_load(path, &m, err, sizeof err);
    snprintf(what, sizeof what, "cube without a face refused: %s", rc ? err : "(loaded)");
    check(rc != 0 && strstr(err, path) && strstr(err, "not closed") && strstr(err, "4 edges"),
          what);
    rc = sph_mesh_load(tmp("missing.vtk"), &m, err, sizeof err);
    snprintf(what, sizeof what, "missing file refused: %s", rc ? err : "(loaded)");
    check(rc != 0 && strstr(err, "missing.vtk"), what);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    snprintf(tmpdir, sizeof tmpdir, "/tmp/sphrt_mesh_XXXXXX");
    if (!mkdtemp(tmpdir)) {
        perror("mkdtemp");
        return 1;
    }
    test_cube();
    test_vtk_layouts();
    test_octahedron();
    test_icosphere();
    test_beams();
    test_refused();
    const char *files[] = {"cube.stl", "cube_ascii.vtk", "cube_binary.vtk", "cube5.vtk",
                           "tetra.vtk", "octahedron.vtk", "sphere.stl", "open_cube.stl"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++)
        remove(tmp(files[k]));
    rmdir(tmpdir);
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
