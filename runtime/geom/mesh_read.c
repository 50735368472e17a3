/* mesh_read.c — reading triangle surfaces: legacy VTK polydata and STL (mesh.h).
 *
 * VTK (a file starting "# vtk DataFile"): the header line, a title line, ASCII or BINARY,
 * DATASET POLYDATA, then sections up to POINT_DATA, CELL_DATA or FIELD: POINTS n float|double,
 * VERTICES and LINES (skipped), POLYGONS and TRIANGLE_STRIPS in the classic layout (n size,
 * then per cell its vertex count and vertices) or the layout of version 5 (OFFSETS and
 * CONNECTIVITY arrays).  BINARY data are big-endian and start after the newline that ends
 * the section's line.
 *
 * STL: binary when the size is 84 + 50 n with n the count at byte 80 (little-endian floats),
 * otherwise ASCII ("solid ... facet ... vertex x y z ... endsolid": every three `vertex`
 * lines make a triangle).
 *
 * Afterwards vertices with equal coordinates are merged (STL repeats them per triangle) and
 * triangles that use a vertex twice are dropped. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "core/regular_file.h"

typedef struct {
    const char *path;
    const unsigned char *s;
    size_t n, i;
    int binary;
    char *err;
    size_t errlen;
    /* what is being built */
    double *v;
    int nv, capv;
    int *t;
    int nt, capt;
} reader;

static int fail(reader *r, const char *fmt, ...)
{
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    snprintf(r->err, r->errlen, "%s: %s", r->path, msg);
    return -1;
}

static void push_vertex(reader *r, double x, double y, double z)
{
    if (r->nv == r->capv) {
        r->capv = r->capv ? 2 * r->capv : 256;
        r->v = realloc(r->v, (size_t)r->capv * 3 * sizeof *r->v);
    }
    r->v[3 * r->nv] = x, r->v[3 * r->nv + 1] = y, r->v[3 * r->nv + 2] = z;
    r->nv++;
}

static void push_triangle(reader *r, int a, int b, int c)
{
    if (r->nt == r->capt) {
        r->capt = r->capt ? 2 * r->capt : 256;
        r->t = realloc(r->t, (size_t)r->capt * 3 * sizeof *r->t);
    }
    r->t[3 * r->nt] = a, r->t[3 * r->nt + 1] = b, r->t[3 * r->nt + 2] = c;
    r->nt++;
}

/* ------------------------------------------------------------------ tokens and numbers */

static int is_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

/* The next whitespace-separated word (copied into w); 0 at the end of the text. */
static int word(reader *r, char *w, size_t len)
{
    while (r->i < r->n && is_space(r->s[r->i]))
        r->i++;
    size_t k = 0;
    while (r->i < r->n && !is_space(r->s[r->i])) {
        if (k + 1 < len)
            w[k++] = (char)r->s[r->i];
        r->i++;
    }
    w[k] = 0;
    return k > 0;
}

/* Moves past the end of the current line (where BINARY data start). */
static void end_of_line(reader *r)
{
    while (r->i < r->n && r->s[r->i] != '\n')
        r->i++;
    if (r->i < r->n)
        r->i++;
}

static int ascii_number(reader *r, double *out)
{
    char w[64], *end;
    if (!word(r, w, sizeof w))
        return -1;
    errno = 0;
    *out = strtod(w, &end);
    return *end || errno == ERANGE || !isfinite(*out) ? -1 : 0;
}

static uint64_t big_endian(const unsigned char *p, int bytes)
{
    uint64_t v = 0;
    for (int k = 0; k < bytes; k++)
        v = v << 8 | p[k];
    return v;
}

/* One value of a VTK data array of the given type: float, double, int, long (vtktypeint32,
 * vtktypeint64, ...). */
static int vtk_value(reader *r, int bytes, int is_float, double *out)
{
    if (!r->binary)
        return ascii_number(r, out);
    if (r->i + (size_t)bytes > r->n)
        return -1;
    uint64_t u = big_endian(r->s + r->i, bytes);
    r->i += (size_t)bytes;
    if (is_float && bytes == 4) {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, 4);
        *out = f;
    } else if (is_float) {
        double d;
        memcpy(&d, &u, 8);
        *out = d;
    } else if (bytes == 4) {
        *out = (double)(int32_t)(uint32_t)u;
    } else {
        *out = (double)(int64_t)u;
    }
    return 0;
}

/* Size and kind of a VTK type name; -1 when unknown. */
static int vtk_type(const char *name, int *is_float)
{
    static const struct { const char *name; int bytes, is_float; } types[] = {
        {"float", 4, 1}, {"double", 8, 1}, {"int", 4, 0}, {"long", 8, 0},
        {"vtktypeint32", 4, 0}, {"vtktypeint64", 8, 0}, {"vtkIdType", 8, 0},
        {"unsigned_int", 4, 0}, {"unsigned_long", 8, 0}};
    for (size_t k = 0; k < sizeof types / sizeof types[0]; k++)
        if (!strcmp(name, types[k].name)) {
            *is_float = types[k].is_float;
            return types[k].bytes;
        }
    return -1;
}

static int count_word(reader *r, long *out)
{
    char w[64], *end;
    if (!word(r, w, sizeof w))
        return -1;
    *out = strtol(w, &end, 10);
    return *end || *out < 0 || *out > 500000000L ? -1 : 0;
}

/* ------------------------------------------------------------------ VTK */

static int vtk_points(reader *r)
{
    long n;
    char type[64];
    int is_float;
    if (count_word(r, &n) || !word(r, type, sizeof type))
        return fail(r, "VTK: bad POINTS line");
    int bytes = vtk_type(type, &is_float);
    if (bytes < 0)
        return fail(r, "VTK: POINTS of type '%s' are not supported (float or double)", type);
    if (r->binary)
        end_of_line(r);
    for (long k = 0; k < n; k++) {
        double x[3];
        for (int c = 0; c < 3; c++)
            if (vtk_value(r, bytes, is_float, &x[c]))
                return fail(r, "VTK: the POINTS data end early or hold a value that is "
                               "not a finite number");
        push_vertex(r, x[0], x[1], x[2]);
    }
    return 0;
}

/* Adds cell ids[0..n-1] of a POLYGONS (fan) or TRIANGLE_STRIPS section. */
static int add_cell(reader *r, const double *ids, long n, int strip, long npoints)
{
    for (long k = 0; k < n; k++)
        if (ids[k] < 0 || ids[k] >= (double)npoints || ids[k] != floor(ids[k]))
            return fail(r, "VTK: a cell refers to a point that does not exist");
    for (long k = 2; k < n; k++) {
        int a = (int)ids[strip ? k - 2 : 0], b = (int)ids[k - 1], c = (int)ids[k];
        if (strip && k % 2 == 1) /* every second triangle of a strip is reversed */
            push_triangle(r, b, a, c);
        else
            push_triangle(r, a, b, c);
    }
    return 0;
}

/* Classic layout: ncells total, then per cell its vertex count and vertex ids. */
static int vtk_cells_classic(reader *r, long ncells, long total, int keep, int strip)
{
    double *ids = NULL;
    long cap = 0, used = 0;
    for (long c = 0; c < ncells; c++) {
        double cnt;
        if (vtk_value(r, 4, 0, &cnt) || !(cnt >= 0 && cnt <= 1e8))
            break;
        long m = (long)cnt;
        if (m > cap) {
            cap = m;
            ids = realloc(ids, (size_t)cap * sizeof *ids);
        }
        for (long k = 0; k < m; k++)
            if (vtk_value(r, 4, 0, &ids[k])) {
                free(ids);
                return fail(r, "VTK: the cell data end early");
            }
        used += m + 1;
        if (keep && add_cell(r, ids, m, strip, r->nv)) {
            free(ids);
            return -1;
        }
    }
    free(ids);
    if (used != total)
        return fail(r, "VTK: the cell data do not match their declared size");
    return 0;
}

/* Version 5 layout: OFFSETS type (n values), CONNECTIVITY type (m values). */
static int vtk_cells_offsets(reader *r, long noffsets, long nconn, int keep, int strip)
{
    char w[64], type[64];
    int is_float, bytes;
    double *off = malloc((size_t)(noffsets + 1) * sizeof *off);
    double *conn = malloc((size_t)(nconn + 1) * sizeof *conn);
    int bad = 0;
    for (int part = 0; part < 2 && !bad; part++) {
        long n = part ? nconn : noffsets;
        double *dst = part ? conn : off;
        if (!word(r, w, sizeof w) || strcmp(w, part ? "CONNECTIVITY" : "OFFSETS") ||
            !word(r, type, sizeof type) || (bytes = vtk_type(type, &is_float)) < 0 || is_float) {
            bad = fail(r, "VTK: expected %s with an integer type",
                       part ? "CONNECTIVITY" : "OFFSETS");
            break;
        }
        if (r->binary)
            end_of_line(r);
        for (long k = 0; k < n && !bad; k++)
            if (vtk_value(r, bytes, 0, &dst[k]))
                bad = fail(r, "VTK: the cell data end early");
    }
    for (long c = 0; c + 1 < noffsets && !bad; c++) {
        if (!(off[c] >= 0 && off[c] <= off[c + 1] && off[c + 1] <= (double)nconn)) {
            bad = fail(r, "VTK: bad OFFSETS");
            break;
        }
        long a = (long)off[c], b = (long)off[c + 1];
        if (keep)
            bad = add_cell(r, conn + a, b - a, strip, r->nv);
    }
    free(off);
    free(conn);
    return bad ? -1 : 0;
}

static int vtk_cells(reader *r, int keep, int strip)
{
    long a, b;
    if (count_word(r, &a) || count_word(r, &b))
        return fail(r, "VTK: bad cell section line");
    size_t at = r->i;
    char w[64];
    if (word(r, w, sizeof w) && !strcmp(w, "OFFSETS")) {
        r->i = at;
        return vtk_cells_offsets(r, a, b, keep, strip);
    }
    r->i = at;
    if (r->binary)
        end_of_line(r);
    return vtk_cells_classic(r, a, b, keep, strip);
}

static int read_vtk(reader *r)
{
    char w[64];
    end_of_line(r); /* # vtk DataFile Version x.y */
    end_of_line(r); /* title */
    if (!word(r, w, sizeof w) || (strcmp(w, "ASCII") && strcmp(w, "BINARY")))
        return fail(r, "VTK: expected ASCII or BINARY on the third line, got '%s'", w);
    r->binary = !strcmp(w, "BINARY");
    if (!word(r, w, sizeof w) || strcmp(w, "DATASET") || !word(r, w, sizeof w))
        return fail(r, "VTK: expected DATASET POLYDATA");
    if (strcmp(w, "POLYDATA"))
        return fail(r, "VTK: only DATASET POLYDATA is supported (this file holds %s)", w);
    while (word(r, w, sizeof w)) {
        int bad;
        if (!strcmp(w, "POINTS"))
            bad = vtk_points(r);
        else if (!strcmp(w, "POLYGONS") || !strcmp(w, "TRIANGLE_STRIPS"))
            bad = vtk_cells(r, 1, !strcmp(w, "TRIANGLE_STRIPS"));
        else if (!strcmp(w, "VERTICES") || !strcmp(w, "LINES"))
            bad = vtk_cells(r, 0, 0);
        else if (!strcmp(w, "POINT_DATA") || !strcmp(w, "CELL_DATA") || !strcmp(w, "FIELD") ||
                 !strcmp(w, "METADATA"))
            break;
        else
            return fail(r, "VTK: unexpected '%s'", w);
        if (bad)
            return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ STL */

static double little_float(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                 (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static int read_stl_binary(reader *r, long n)
{
    for (long k = 0; k < n; k++) {
        const unsigned char *f = r->s + 84 + 50 * k + 12; /* after the normal */
        for (int c = 0; c < 3; c++)
            push_vertex(r, little_float(f + 12 * c), little_float(f + 12 * c + 4),
                        little_float(f + 12 * c + 8));
        push_triangle(r, r->nv - 3, r->nv - 2, r->nv - 1);
    }
    return 0;
}

static int read_stl_ascii(reader *r)
{
    char w[64];
    int corners = 0;
    end_of_line(r); /* solid name */
    while (word(r, w, sizeof w)) {
        if (strcmp(w, "vertex"))
            continue;
        double x[3];
        for (int c = 0; c < 3; c++)
            if (ascii_number(r, &x[c]))
                return fail(r, "STL: a vertex needs three numbers");
        push_vertex(r, x[0], x[1], x[2]);
        if (++corners % 3 == 0)
            push_triangle(r, r->nv - 3, r->nv - 2, r->nv - 1);
    }
    if (corners % 3)
        return fail(r, "STL: the number of vertices is not a multiple of three");
    return 0;
}

static int read_stl(reader *r)
{
    if (r->n >= 84) {
        uint32_t n = (uint32_t)r->s[80] | (uint32_t)r->s[81] << 8 | (uint32_t)r->s[82] << 16 |
                     (uint32_t)r->s[83] << 24;
        if ((uint64_t)84 + 50 * (uint64_t)n == r->n)
            return read_stl_binary(r, (long)n);
    }
    size_t k = 0;
    while (k < r->n && is_space(r->s[k]))
        k++;
    if (r->n - k >= 5 && !memcmp(r->s + k, "solid", 5))
        return read_stl_ascii(r);
    return fail(r, "not a VTK or STL file (a legacy VTK file starts with '# vtk DataFile', an "
                   "ASCII STL file with 'solid', a binary STL file holds 84 + 50 n bytes)");
}

/* ------------------------------------------------------------------ merging vertices */

static const double *sort_v; /* qsort has no context argument; loading is serialised */

static int by_coords(const void *pa, const void *pb)
{
    const double *a = sort_v + 3 * *(const int *)pa, *b = sort_v + 3 * *(const int *)pb;
    for (int c = 0; c < 3; c++)
        if (a[c] != b[c])
            return a[c] < b[c] ? -1 : 1;
    return *(const int *)pa - *(const int *)pb;
}

/* Merges vertices with equal coordinates; drops triangles that use a vertex twice. */
static void weld(reader *r)
{
    int *perm = malloc((size_t)r->nv * sizeof *perm), *map = malloc((size_t)r->nv * sizeof *map);
    for (int k = 0; k < r->nv; k++)
        perm[k] = k;
    sort_v = r->v;
    qsort(perm, (size_t)r->nv, sizeof *perm, by_coords);
    double *v = malloc((size_t)r->nv * 3 * sizeof *v);
    int nv = 0;
    for (int k = 0; k < r->nv; k++) {
        const double *p = r->v + 3 * perm[k];
        if (nv == 0 || memcmp(v + 3 * (nv - 1), p, 3 * sizeof *p) != 0) {
            memcpy(v + 3 * nv, p, 3 * sizeof *p);
            nv++;
        }
        map[perm[k]] = nv - 1;
    }
    int nt = 0;
    for (int k = 0; k < r->nt; k++) {
        int a = map[r->t[3 * k]], b = map[r->t[3 * k + 1]], c = map[r->t[3 * k + 2]];
        if (a == b || b == c || c == a)
            continue;
        r->t[3 * nt] = a, r->t[3 * nt + 1] = b, r->t[3 * nt + 2] = c;
        nt++;
    }
    free(r->v);
    free(perm);
    free(map);
    r->v = v;
    r->nv = nv;
    r->nt = nt;
}

/* ------------------------------------------------------------------ the file */

static unsigned char *read_file(const char *path, size_t *n, char *err, size_t len)
{
    if (sph_not_regular_file(path)) {
        snprintf(err, len, "%s: not a regular file", path);
        return NULL;
    }
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, len, "%s: cannot open: %s", path, strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, got;
    unsigned char *buf = malloc(cap);
    *n = 0;
    while (buf && (got = fread(buf + *n, 1, cap - *n, f)) > 0) {
        *n += got;
        if (*n == cap)
            buf = realloc(buf, cap *= 2);
    }
    int bad = ferror(f) || !buf;
    fclose(f);
    if (bad) {
        snprintf(err, len, "%s: cannot read", path);
        free(buf);
        return NULL;
    }
    return buf;
}

int sph_mesh_read(const char *path, sph_mesh *m, char *err, size_t len)
{
    memset(m, 0, sizeof *m);
    reader r = {0};
    r.path = path;
    r.err = err;
    r.errlen = len;
    unsigned char *text = read_file(path, &r.n, err, len);
    if (!text)
        return -1;
    r.s = text;
    int bad = r.n >= 14 && !memcmp(text, "# vtk DataFile", 14) ? read_vtk(&r) : read_stl(&r);
    free(text);
    if (!bad && r.nt == 0)
        bad = fail(&r, "the file holds no triangles");
    for (long k = 0; !bad && k < 3 * (long)r.nv; k++)
        if (!isfinite(r.v[k]))
            bad = fail(&r, "vertex %ld has a coordinate that is not a finite number", k / 3);
    if (bad) {
        free(r.v);
        free(r.t);
        return -1;
    }
    weld(&r);
    m->file = strdup(path);
    m->v = r.v;
    m->nv = r.nv;
    m->t = r.t;
    m->nt = r.nt;
    return 0;
}

int sph_mesh_load(const char *path, sph_mesh *m, char *err, size_t len)
{
    return sph_mesh_load_moved(path, NULL, m, err, len);
}

double sph_mesh_map_det(const double *xf)
{
    const double *e1 = xf, *e2 = xf + 3, *e3 = xf + 6; /* the matrix's columns */
    return e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e2[0] * (e1[1] * e3[2] - e1[2] * e3[1]) +
           e3[0] * (e1[1] * e2[2] - e1[2] * e2[1]);
}

int sph_mesh_load_moved(const char *path, const double *xf, sph_mesh *m, char *err, size_t len)
{
    const double det = xf ? sph_mesh_map_det(xf) : 1.0;
    if (!(fabs(det) > 0)) {
        snprintf(err, len, "%s: the map that moves it flattens it", path);
        return -1;
    }
    if (!isfinite(det)) {
        snprintf(err, len, "%s: the map that moves it is too large (its determinant is not a "
                           "finite number)", path);
        return -1;
    }
    if (sph_mesh_read(path, m, err, len))
        return -1;
    for (int i = 0; xf && i < m->nv; i++) { /* x -> x e1' + y e2' + z e3' + b */
        double *v = m->v + 3 * i, q[3];
        for (int a = 0; a < 3; a++)
            q[a] = xf[a] * v[0] + xf[3 + a] * v[1] + xf[6 + a] * v[2] + xf[9 + a];
        v[0] = q[0], v[1] = q[1], v[2] = q[2];
    }
    if (sph_mesh_close(m, err, len)) {
        sph_mesh_free(m);
        return -1;
    }
    return 0;
}

void sph_mesh_free(sph_mesh *m)
{
    free(m->file);
    free(m->v);
    free(m->t);
    free(m->nodes);
    free(m->order);
    memset(m, 0, sizeof *m);
}
