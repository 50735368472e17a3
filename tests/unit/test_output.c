/* test_output.c — the output writers: .vtu files are read back and their XML header,
 * appended blocks and values checked; .pvd, CSV and JSON files are compared with the
 * expected text; sph_mkdirs creates nested folders. */
#define _POSIX_C_SOURCE 200809L
#include "io/csv.h"
#include "io/fsutil.h"
#include "io/json.h"
#include "io/vtu.h"
#include "scene/body.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int failures = 0;

#define CHECK(cond, ...)                                   \
    do {                                                   \
        if (!(cond)) {                                     \
            printf("  FAIL (%s:%d): ", __FILE__, __LINE__); \
            printf(__VA_ARGS__);                           \
            printf("\n");                                  \
            failures++;                                    \
        }                                                  \
    } while (0)

static char tmpdir[64];

static char *path_in_tmp(const char *name)
{
    static char buf[4][256];
    static int k = 0;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", tmpdir, name);
    return buf[k];
}

/* Whole file, NUL-terminated; *size gets its length. */
static char *read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)len + 1);
    size_t got = fread(buf, 1, (size_t)len, f);
    fclose(f);
    buf[got] = '\0';
    if (size)
        *size = got;
    return buf;
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* ------------------------------------------------------------------ vtu reader */

typedef struct {
    char *data;
    size_t size;
    size_t header_len;    /* XML before the binary data */
    size_t base;          /* first byte after '_' */
} vtu_file;

typedef struct {
    const char *name;
    int ncomp;
    size_t elsize;
} vtu_array;

static const vtu_array VTU_ARRAYS[] = {
    {"displacement", 3, 8}, {"velocity", 3, 8}, {"cauchy_stress", 6, 8},
    {"sigma_vm", 1, 8},     {"J", 1, 8},        {"strain_energy", 1, 8},
    {"Points", 3, 8},       {"connectivity", 1, 8}, {"offsets", 1, 8}, {"types", 1, 1},
};
#define NVTU_ARRAYS (int)(sizeof VTU_ARRAYS / sizeof VTU_ARRAYS[0])

static int load_vtu(const char *path, vtu_file *v)
{
    v->data = read_file(path, &v->size);
    if (!v->data)
        return -1;
    char *app = strstr(v->data, "<AppendedData encoding=\"raw\">");
    char *us = app ? strchr(app, '_') : NULL;
    if (!us)
        return -1;
    v->header_len = (size_t)(app - v->data);
    v->base = (size_t)(us - v->data) + 1;
    return 0;
}

/* Offset attribute of DataArray `name` (in the XML header), or -1. */
static long array_offset(const vtu_file *v, const char *name)
{
    char key[64];
    snprintf(key, sizeof key, "Name=\"%s\"", name);
    char *p = strstr(v->data, key);
    if (!p || (size_t)(p - v->data) > v->header_len)
        return -1;
    char *end = strchr(p, '>');
    char *off = strstr(p, "offset=\"");
    if (!off || off > end)
        return -1;
    return strtol(off + 8, NULL, 10);
}

/* Values of array `name`: a pointer into the file after the block's byte count. */
static const char *array_data(const vtu_file *v, const char *name, uint64_t *bytes)
{
    long off = array_offset(v, name);
    if (off < 0 || v->base + (size_t)off + 8 > v->size)
        return NULL;
    memcpy(bytes, v->data + v->base + off, 8);
    return v->data + v->base + off + 8;
}

static double get_f64(const vtu_file *v, const char *name, int index)
{
    uint64_t bytes;
    const char *p = array_data(v, name, &bytes);
    double x = NAN;
    if (p && (size_t)(index + 1) * 8 <= bytes)
        memcpy(&x, p + (size_t)index * 8, 8);
    return x;
}

static int64_t get_i64(const vtu_file *v, const char *name, int index)
{
    uint64_t bytes;
    const char *p = array_data(v, name, &bytes);
    int64_t x = -999;
    if (p && (size_t)(index + 1) * 8 <= bytes)
        memcpy(&x, p + (size_t)index * 8, 8);
    return x;
}

/* Header attributes, block sizes, contiguity of the blocks and the file's tail. */
static void check_vtu_structure(const vtu_file *v, int n, double t)
{
    char attr[96];
    snprintf(attr, sizeof attr, "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">", n, n);
    CHECK(strstr(v->data, attr) != NULL, "header has %s", attr);
    CHECK(strstr(v->data, "byte_order=\"LittleEndian\" header_type=\"UInt64\"") != NULL,
          "byte order and header type");
    char *tv = strstr(v->data, "Name=\"TimeValue\"");
    CHECK(tv && strtod(strchr(tv, '>') + 1, NULL) == t, "TimeValue %g", t);
    uint64_t expect_off = 0;
    for (int a = 0; a < NVTU_ARRAYS; a++) {
        long off = array_offset(v, VTU_ARRAYS[a].name);
        uint64_t bytes = 0;
        array_data(v, VTU_ARRAYS[a].name, &bytes);
        uint64_t want = (uint64_t)n * VTU_ARRAYS[a].ncomp * VTU_ARRAYS[a].elsize;
        CHECK(off == (long)expect_off, "%s offset %ld, expected %llu", VTU_ARRAYS[a].name, off,
              (unsigned long long)expect_off);
        CHECK(bytes == want, "%s block has %llu bytes, expected %llu", VTU_ARRAYS[a].name,
              (unsigned long long)bytes, (unsigned long long)want);
        expect_off += 8 + want;
    }
    const char *tail = "\n  </AppendedData>\n</VTKFile>\n";
    CHECK(v->base + expect_off + strlen(tail) == v->size &&
              memcmp(v->data + v->base + expect_off, tail, strlen(tail)) == 0,
          "blocks end where </AppendedData> starts");
}

static void check_cells(const vtu_file *v, int n)
{
    uint64_t bytes;
    const uint8_t *types = (const uint8_t *)array_data(v, "types", &bytes);
    for (int i = 0; i < n; i++) {
        CHECK(get_i64(v, "connectivity", i) == i, "connectivity[%d]", i);
        CHECK(get_i64(v, "offsets", i) == i + 1, "offsets[%d]", i);
        CHECK(types && types[i] == 1, "types[%d] == VTK_VERTEX", i);
    }
}

static int near(double a, double b) { return fabs(a - b) <= 1e-12 * (1 + fabs(b)); }

/* ------------------------------------------------------------------ vtu tests */

static void test_vtu_2d(void)
{
    printf("vtu: 2D body (x-z plane, y = y_plane), stress, J, energy\n");
    double X[] = {0.0, 1.0, 0.5, 2.0, 1.0, 3.0};
    double u[] = {0.1, -0.2, 0.0, 0.0, 0.3, 0.4};
    double vel[] = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
    double F[27] = {1.1, 0, 0, 0, 1, 0, 0, 0, 0.9,   1, 0.2, 0, 0, 1, 0, 0, 0, 1,
                    2, 0, 0, 0, 1, 0, 0, 0, 1};
    double sigma[18] = {100, 0, 0, 0, 0, 0,   0, 0, 0, 10, 0, 0,   1, 2, 3, 4, 5, 6};
    double psi[] = {0.5, 1.5, 2.5};
    sph_body b = {.n = 3, .nown = 3, .dim = 2, .y_plane = 0.25, .X = X, .u = u, .v = vel,
                  .F = F, .sigma = sigma, .psi = psi};
    const char *path = path_in_tmp("body2d_0000.vtu");
    CHECK(sph_write_vtu(path, &b, 0.125) == 0, "sph_write_vtu returns 0");
    vtu_file v;
    if (load_vtu(path, &v) != 0) {
        CHECK(0, "cannot read back %s", path);
        return;
    }
    check_vtu_structure(&v, 3, 0.125);
    check_cells(&v, 3);
    CHECK(get_f64(&v, "Points", 0) == X[0] + u[0] && get_f64(&v, "Points", 1) == 0.25 &&
              get_f64(&v, "Points", 2) == X[1] + u[1], "first point (0.1, 0.25, 0.8)");
    CHECK(get_f64(&v, "Points", 6) == X[4] + u[4] && get_f64(&v, "Points", 8) == X[5] + u[5],
          "third point (1.3, 0.25, 3.4)");
    CHECK(get_f64(&v, "displacement", 0) == 0.1 && get_f64(&v, "displacement", 1) == 0 &&
              get_f64(&v, "displacement", 2) == -0.2, "displacement (ux, 0, uz)");
    CHECK(get_f64(&v, "velocity", 3) == 3 && get_f64(&v, "velocity", 4) == 0 &&
              get_f64(&v, "velocity", 5) == 4, "velocity of particle 1");
    for (int c = 0; c < 18; c++)
        CHECK(get_f64(&v, "cauchy_stress", c) == sigma[c], "cauchy_stress[%d]", c);
    CHECK(near(get_f64(&v, "sigma_vm", 0), 100), "von Mises of uniaxial 100 is 100");
    CHECK(near(get_f64(&v, "sigma_vm", 1), 10 * sqrt(3.0)), "von Mises of shear 10");
    CHECK(near(get_f64(&v, "sigma_vm", 2), sqrt(3.0 + 3.0 * 77)), "von Mises, general");
    CHECK(near(get_f64(&v, "J", 0), 0.99), "J = det diag(1.1, 1, 0.9)");
    CHECK(near(get_f64(&v, "J", 1), 1.0), "J of a shear");
    CHECK(near(get_f64(&v, "J", 2), 2.0), "J of a stretch");
    CHECK(get_f64(&v, "strain_energy", 2) == 2.5, "strain_energy");
    free(v.data);
}

static void test_vtu_3d(void)
{
    printf("vtu: 3D body without F, sigma, psi (J = 1, zeros)\n");
    double X[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    double u[] = {0.5, 0.25, -1, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    double vel[12] = {0};
    sph_body b = {.n = 4, .nown = 4, .dim = 3, .X = X, .u = u, .v = vel};
    const char *path = path_in_tmp("body3d_0001.vtu");
    CHECK(sph_write_vtu(path, &b, 2.5) == 0, "sph_write_vtu returns 0");
    vtu_file v;
    if (load_vtu(path, &v) != 0) {
        CHECK(0, "cannot read back %s", path);
        return;
    }
    check_vtu_structure(&v, 4, 2.5);
    check_cells(&v, 4);
    CHECK(get_f64(&v, "Points", 0) == 1.5 && get_f64(&v, "Points", 1) == 2.25 &&
              get_f64(&v, "Points", 2) == 2.0, "first point (1.5, 2.25, 2)");
    CHECK(get_f64(&v, "Points", 11) == 13, "last point z");
    for (int i = 0; i < 4; i++) {
        CHECK(get_f64(&v, "J", i) == 1.0, "J[%d] = 1 without F", i);
        CHECK(get_f64(&v, "sigma_vm", i) == 0.0, "sigma_vm[%d] = 0 without sigma", i);
        CHECK(get_f64(&v, "strain_energy", i) == 0.0, "strain_energy[%d] = 0", i);
        CHECK(get_f64(&v, "cauchy_stress", i * 6 + 3) == 0.0, "stress[%d] = 0", i);
    }
    free(v.data);
}

/* The components' names of the multi-component arrays, ParaView's: X Y Z for the vectors and
 * points, XX YY ZZ XY YZ XZ for the stress (the order body->sigma holds); none for scalars. */
static const char *const VECTOR_NAMES =
    "NumberOfComponents=\"3\" ComponentName0=\"X\" ComponentName1=\"Y\" ComponentName2=\"Z\"";
static const char *const TENSOR_NAMES =
    "NumberOfComponents=\"6\" ComponentName0=\"XX\" ComponentName1=\"YY\" "
    "ComponentName2=\"ZZ\" ComponentName3=\"XY\" ComponentName4=\"YZ\" ComponentName5=\"XZ\"";

static void check_component_names(const char *text, const char *tag, const char *file)
{
    static const char *const vectors[] = {"displacement", "velocity", "Points"};
    char want[512];
    for (int k = 0; k < 3; k++) {
        snprintf(want, sizeof want, "<%s type=\"Float64\" Name=\"%s\" %s", tag, vectors[k],
                 VECTOR_NAMES);
        CHECK(strstr(text, want) != NULL, "%s: %s names X Y Z", file, vectors[k]);
    }
    snprintf(want, sizeof want, "<%s type=\"Float64\" Name=\"cauchy_stress\" %s", tag,
             TENSOR_NAMES);
    CHECK(strstr(text, want) != NULL, "%s: cauchy_stress names XX YY ZZ XY YZ XZ", file);
    const char *vm = strstr(text, "Name=\"sigma_vm\"");
    CHECK(vm && !memchr(vm, 'C', (size_t)(strchr(vm, '>') - vm)), "%s: sigma_vm, a scalar, "
          "names no component", file);
}

static void test_vtu_components(void)
{
    printf("vtu, pvtu: ParaView's names of the components\n");
    double X[] = {0, 0, 0, 1, 0, 0}, zero[6] = {0};
    int64_t gid[] = {7, 3};
    sph_body b = {.n = 2, .nown = 2, .dim = 3, .X = X, .u = zero, .v = zero, .gid = gid};
    const char *path = path_in_tmp("names_0000.vtu");
    CHECK(sph_write_vtu(path, &b, 0) == 0, "sph_write_vtu returns 0");
    vtu_file v;
    if (load_vtu(path, &v) == 0) {
        v.data[v.header_len] = '\0'; /* (the XML header only) */
        check_component_names(v.data, "DataArray", path);
        free(v.data);
    } else {
        CHECK(0, "cannot read back %s", path);
    }
    const char *pieces[] = {"names_0000_p0.vtu", "names_0000_p1.vtu"};
    path = path_in_tmp("names_0000.pvtu");
    CHECK(sph_write_pvtu(path, &b, pieces, 2) == 0, "sph_write_pvtu returns 0");
    char *text = read_file(path, NULL);
    if (text) {
        check_component_names(text, "PDataArray", path);
        CHECK(strstr(text, "<Piece Source=\"names_0000_p1.vtu\"/>") != NULL, "pieces listed");
        free(text);
    } else {
        CHECK(0, "cannot read back %s", path);
    }
}

static void test_vtu_empty_and_error(void)
{
    printf("vtu: empty body; unwritable path fails (error message expected)\n");
    sph_body b = {.n = 0, .nown = 0, .dim = 3};
    const char *path = path_in_tmp("empty.vtu");
    CHECK(sph_write_vtu(path, &b, 0) == 0, "empty body written");
    vtu_file v;
    if (load_vtu(path, &v) == 0) {
        check_vtu_structure(&v, 0, 0);
        free(v.data);
    } else {
        CHECK(0, "cannot read back %s", path);
    }
    CHECK(sph_write_vtu(path_in_tmp("missing/dir/x.vtu"), &b, 0) == -1,
          "writing into a missing folder returns -1");
}

/* ------------------------------------------------------------------ other writers */

static void check_file(const char *path, const char *expected, const char *what)
{
    char *text = read_file(path, NULL);
    CHECK(text && strcmp(text, expected) == 0, "%s content:\n%s\nexpected:\n%s", what,
          text ? text : "(unreadable)", expected);
    free(text);
}

static void test_pvd(void)
{
    printf("pvd: collection of two files, attribute escaping, rewrite\n");
    const char *files[] = {"beam_0000.vtu", "a&b\"<c>.vtu"};
    double times[] = {0.0, 0.125};
    const char *path = path_in_tmp("beam.pvd");
    CHECK(sph_write_pvd(path, files, times, 1) == 0, "first pvd written");
    CHECK(sph_write_pvd(path, files, times, 2) == 0, "pvd rewritten");
    check_file(path,
               "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "  <Collection>\n"
               "    <DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"beam_0000.vtu\"/>\n"
               "    <DataSet timestep=\"0.125\" group=\"\" part=\"0\""
               " file=\"a&amp;b&quot;&lt;c&gt;.vtu\"/>\n"
               "  </Collection>\n</VTKFile>\n",
               "pvd");
    CHECK(access(path_in_tmp("beam.pvd.tmp"), F_OK) != 0, "no temporary file left");
}

static void test_csv(void)
{
    printf("csv: header and rows, %%.10g, readable before close (1 error expected)\n");
    const char *cols[] = {"t", "ux", "fz"};
    const char *path = path_in_tmp("series.csv");
    sph_csv c;
    CHECK(sph_csv_open(&c, path, cols, 3) == 0, "csv opened");
    double r1[] = {0, 1e-7, -2.5}, r2[] = {0.1, 1.0 / 3.0, 1234567890.0};
    CHECK(sph_csv_row(&c, r1) == 0 && sph_csv_row(&c, r2) == 0, "rows written");
    check_file(path, "t,ux,fz\n0,1e-07,-2.5\n0.1,0.3333333333,1234567890\n",
               "csv (flushed, still open)");
    sph_csv_close(&c);
    CHECK(c.f == NULL, "closed");
    CHECK(sph_csv_open(&c, path_in_tmp("nope/x.csv"), cols, 3) == -1, "bad path fails");

    sph_csv_table t; /* read back: the names, and the numbers as printed */
    CHECK(sph_csv_read(path, &t, 100) == 0 && t.ncols == 3 && t.nrows == 2, "csv read back");
    CHECK(t.ncols == 3 && !strcmp(t.names[0], "t") && !strcmp(t.names[2], "fz"), "its names");
    CHECK(t.nrows == 2 && t.v[1] == 1e-7 && t.v[4] == 0.3333333333 && t.v[5] == 1234567890.0,
          "its numbers");
    sph_csv_table_free(&t);
    /* a long series thinned to at most 4 rows and the last: rows 0, 8, 16 of 0..19, and 19 */
    static const char *const names[] = {"time"};
    t = (sph_csv_table){.ncols = 1, .names = (char **)names};
    for (int k = 0; k < 20; k++) {
        const double row = k;
        sph_csv_table_add(&t, &row, 4);
    }
    CHECK(t.nrows == 4 && t.stride == 8 && t.total == 20 && t.v[0] == 0 && t.v[1] == 8 &&
          t.v[2] == 16 && t.v[3] == 19, "a long series thinned");
    free(t.v);
    CHECK(sph_csv_read(path_in_tmp("nope/x.csv"), &t, 100) == -1 && t.nrows == 0, "no file: -1");
}

static void write_json_sample(const char *path)
{
    sph_json j;
    CHECK(sph_json_open(&j, path) == 0, "json opened");
    sph_json_str(&j, "model", "say \"hi\"\\\n\t\x01");
    sph_json_num(&j, "third", 1.0 / 3.0);
    sph_json_num(&j, "tenth", 0.1);
    sph_json_num(&j, "big", 1e300);
    sph_json_num(&j, "whole", 42.0);
    sph_json_num(&j, "nan", NAN);
    sph_json_num(&j, "inf", -INFINITY);
    sph_json_int(&j, "steps", 123456789012L);
    sph_json_bool(&j, "ok", 1);
    sph_json_str(&j, "none", NULL);
    sph_json_key_object(&j, "empty");
    sph_json_end_object(&j);
    sph_json_key_array(&j, "checks");
    sph_json_key_object(&j, NULL);
    sph_json_bool(&j, "passed", 0);
    sph_json_end_object(&j);
    sph_json_num(&j, NULL, 2.5);
    sph_json_end_array(&j);
    CHECK(sph_json_close(&j) == 0, "json closed");
}

static void test_json(void)
{
    printf("json: escaping, numbers, null, nesting, arrays of objects (1 error expected)\n");
    const char *path = path_in_tmp("summary.json");
    write_json_sample(path);
    check_file(path,
               "{\n"
               "  \"model\": \"say \\\"hi\\\"\\\\\\n\\t\\u0001\",\n"
               "  \"third\": 0.3333333333333333,\n"
               "  \"tenth\": 0.1,\n"
               "  \"big\": 1e+300,\n"
               "  \"whole\": 42,\n"
               "  \"nan\": null,\n"
               "  \"inf\": null,\n"
               "  \"steps\": 123456789012,\n"
               "  \"ok\": true,\n"
               "  \"none\": null,\n"
               "  \"empty\": {},\n"
               "  \"checks\": [\n"
               "    {\n"
               "      \"passed\": false\n"
               "    },\n"
               "    2.5\n"
               "  ]\n"
               "}\n",
               "summary.json");
    char *text = read_file(path, NULL);
    char *third = text ? strstr(text, "\"third\": ") : NULL;
    CHECK(third && strtod(third + 9, NULL) == 1.0 / 3.0, "1/3 reads back exactly");
    free(text);

    sph_json bad;
    CHECK(sph_json_open(&bad, path_in_tmp("nope/summary.json")) == -1, "bad path fails");
    sph_json_key_object(&bad, "x");
    sph_json_num(&bad, "y", 1);
    sph_json_end_object(&bad);
    CHECK(sph_json_close(&bad) == -1, "writes after a failed open are ignored");
}

static void test_mkdirs(void)
{
    printf("mkdirs: nested folders, existing folder, a file in the way (2 errors expected)\n");
    CHECK(sph_mkdirs(path_in_tmp("a/b//c/")) == 0 && is_dir(path_in_tmp("a/b/c")),
          "a/b/c created");
    CHECK(sph_mkdirs(path_in_tmp("a/b")) == 0, "existing folder is fine");
    FILE *f = fopen(path_in_tmp("file"), "w");
    if (f)
        fclose(f);
    CHECK(sph_mkdirs(path_in_tmp("file/sub")) == -1, "a file in the way fails");
    CHECK(sph_mkdirs(path_in_tmp("file")) == -1, "an existing file fails");
}

static void remove_tree(const char *dir)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("  (could not remove %s)\n", dir);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0); /* keep checks and expected error messages in order */
    snprintf(tmpdir, sizeof tmpdir, "/tmp/sphrt_output_XXXXXX");
    if (!mkdtemp(tmpdir)) {
        perror("mkdtemp");
        return 1;
    }
    test_vtu_2d();
    test_vtu_3d();
    test_vtu_components();
    test_vtu_empty_and_error();
    test_pvd();
    test_csv();
    test_json();
    test_mkdirs();
    if (failures == 0)
        remove_tree(tmpdir);
    else
        printf("files kept in %s\n", tmpdir);
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "ok", failures);
    return failures != 0;
}
