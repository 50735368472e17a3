/* vtu.c — ParaView output: one VTK XML UnstructuredGrid (.vtu) file per body and output
 * time, and the .pvd collection that lists them.
 *
 * The .vtu file holds the particles as VTK_VERTEX cells.  All arrays are stored as raw
 * binary in <AppendedData>: each block is a UInt64 byte count followed by the values,
 * and each DataArray's `offset` is the position of its block after the leading '_'.
 *
 * Both files are written beside their name and renamed over it once complete
 * (sph_open_whole): ParaView, or a run killed while writing, never sees a part of one. */

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fsutil.h"
#include "vtu.h"
#include "core/defs.h"
#include "core/message.h"
#include "scene/body.h"
#include "scene/body_desc.h"

#define VTK_VERTEX 1

/* The arrays of a .vtu file, in the order their blocks are appended. */
typedef enum {
    A_DISPLACEMENT, A_VELOCITY, A_STRESS, A_VON_MISES, A_J, A_ENERGY,
    A_PHASE, A_HISTORY, /* bodies with fracture only */
    A_GID,              /* runs on many processes only: the particles' global ids */
    A_POINTS, A_CONNECTIVITY, A_OFFSETS, A_TYPES, A_COUNT
} array_id;

typedef struct {
    const char *name;
    const char *type;  /* VTK type name */
    int ncomp;
    size_t size;       /* bytes per component */
    const char *const *comp; /* ncomp > 1: the components' names, in the order written */
} array_info;

/* ParaView's component names: a vector's x y z, and a symmetric tensor's six components in
 * the order ParaView reads them (XX YY ZZ XY YZ XZ), which is the order body->sigma holds
 * (xx yy zz xy yz zx; zx = xz). */
static const char *const VECTOR[3] = {"X", "Y", "Z"};
static const char *const SYMTENSOR[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};

static const array_info ARRAYS[A_COUNT] = {
    [A_DISPLACEMENT] = {"displacement", "Float64", 3, sizeof(double), VECTOR},
    [A_VELOCITY]     = {"velocity", "Float64", 3, sizeof(double), VECTOR},
    [A_STRESS]       = {"cauchy_stress", "Float64", 6, sizeof(double), SYMTENSOR},
    [A_VON_MISES]    = {"sigma_vm", "Float64", 1, sizeof(double)},
    [A_J]            = {"J", "Float64", 1, sizeof(double)},
    [A_ENERGY]       = {"strain_energy", "Float64", 1, sizeof(double)},
    [A_PHASE]        = {"phase_field", "Float64", 1, sizeof(double)},
    [A_HISTORY]      = {"history", "Float64", 1, sizeof(double)},
    [A_GID]          = {"global_id", "Int64", 1, sizeof(int64_t)},
    [A_POINTS]       = {"Points", "Float64", 3, sizeof(double), VECTOR},
    [A_CONNECTIVITY] = {"connectivity", "Int64", 1, sizeof(int64_t)},
    [A_OFFSETS]      = {"offsets", "Int64", 1, sizeof(int64_t)},
    [A_TYPES]        = {"types", "UInt8", 1, sizeof(uint8_t)},
};

static int write_error(const char *path, int err)
{
    sph_error("cannot write %s: %s", path, strerror(err));
    return -1;
}

/* The byte order of this machine, which is the order the raw blocks are written in. */
static const char *host_byte_order(void)
{
    const uint16_t one = 1;
    return *(const uint8_t *)&one ? "LittleEndian" : "BigEndian";
}

static size_t block_bytes(array_id a, size_t n)
{
    return n * (size_t)ARRAYS[a].ncomp * ARRAYS[a].size;
}

/* ------------------------------------------------------------------ array values */

/* Expand a compact per-particle vector (dim components, NULL = zero) to 3D. */
static void fill_vec3(const sph_body *b, const double *v, double *out)
{
    memset(out, 0, (size_t)b->nown * 3 * sizeof(double));
    if (!v)
        return;
    for (int i = 0; i < b->nown; i++)
        for (int k = 0; k < b->dim; k++)
            out[i * 3 + sph_axis(b->dim, k)] = v[(size_t)i * b->dim + k];
}

/* Current positions X + u; 2D bodies lie in the plane y = y_plane. */
static void fill_points(const sph_body *b, double *out)
{
    fill_vec3(b, b->X, out);
    if (b->u) {
        for (int i = 0; i < b->nown; i++)
            for (int k = 0; k < b->dim; k++)
                out[i * 3 + sph_axis(b->dim, k)] += b->u[(size_t)i * b->dim + k];
    }
    if (b->dim == 2)
        for (int i = 0; i < b->nown; i++)
            out[i * 3 + 1] = b->y_plane;
}

static void fill_stress(const sph_body *b, double *out)
{
    size_t bytes = (size_t)b->nown * 6 * sizeof(double);
    if (b->sigma)
        memcpy(out, b->sigma, bytes);
    else
        memset(out, 0, bytes);
}

/* Von Mises equivalent stress of s = (xx yy zz xy yz zx). */
static double von_mises(const double *s)
{
    double d1 = s[0] - s[1], d2 = s[1] - s[2], d3 = s[2] - s[0];
    double shear = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
    return sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + 3.0 * shear);
}

static void fill_von_mises(const sph_body *b, double *out)
{
    for (int i = 0; i < b->nown; i++)
        out[i] = b->sigma ? von_mises(b->sigma + (size_t)i * 6) : 0.0;
}

static double det3(const double *F)
{
    return F[0] * (F[4] * F[8] - F[5] * F[7])
         - F[1] * (F[3] * F[8] - F[5] * F[6])
         + F[2] * (F[3] * F[7] - F[4] * F[6]);
}

static void fill_jacobian(const sph_body *b, double *out)
{
    for (int i = 0; i < b->nown; i++)
        out[i] = b->F ? det3(b->F + (size_t)i * 9) : 1.0;
}

static void fill_energy(const sph_body *b, double *out)
{
    for (int i = 0; i < b->nown; i++)
        out[i] = b->psi ? b->psi[i] : 0.0;
}

static int present(array_id a, const sph_body *b)
{
    if (a == A_GID)
        return b->gid != NULL;
    return (a != A_PHASE && a != A_HISTORY) || b->s;
}

static void fill_scalar(const sph_body *b, const double *x, double *out)
{
    for (int i = 0; i < b->nown; i++)
        out[i] = x[i];
}

/* One cell per particle: connectivity i, offset i+1, type VTK_VERTEX. */
static void fill_cells(array_id a, int n, void *buf)
{
    int64_t *ids = buf;
    uint8_t *types = buf;
    for (int i = 0; i < n; i++) {
        if (a == A_TYPES)
            types[i] = VTK_VERTEX;
        else
            ids[i] = a == A_OFFSETS ? (int64_t)i + 1 : (int64_t)i;
    }
}

static void fill_array(array_id a, const sph_body *b, void *buf)
{
    switch (a) {
    case A_DISPLACEMENT: fill_vec3(b, b->u, buf); break;
    case A_VELOCITY:     fill_vec3(b, b->v, buf); break;
    case A_STRESS:       fill_stress(b, buf); break;
    case A_VON_MISES:    fill_von_mises(b, buf); break;
    case A_J:            fill_jacobian(b, buf); break;
    case A_ENERGY:       fill_energy(b, buf); break;
    case A_PHASE:        fill_scalar(b, b->s, buf); break;
    case A_HISTORY:      fill_scalar(b, b->H, buf); break;
    case A_GID:          memcpy(buf, b->gid, block_bytes(A_GID, (size_t)b->nown)); break;
    case A_POINTS:       fill_points(b, buf); break;
    default:             fill_cells(a, b->nown, buf); break;
    }
}

/* ------------------------------------------------------------------ XML structure */

/* NumberOfComponents and the components' names of a multi-component array. */
static void write_components(FILE *f, array_id a)
{
    if (ARRAYS[a].ncomp <= 1)
        return;
    fprintf(f, " NumberOfComponents=\"%d\"", ARRAYS[a].ncomp);
    for (int c = 0; ARRAYS[a].comp && c < ARRAYS[a].ncomp; c++)
        fprintf(f, " ComponentName%d=\"%s\"", c, ARRAYS[a].comp[c]);
}

static void write_data_array(FILE *f, array_id a, uint64_t offset, const char *indent)
{
    fprintf(f, "%s<DataArray type=\"%s\" Name=\"%s\"", indent, ARRAYS[a].type, ARRAYS[a].name);
    write_components(f, a);
    fprintf(f, " format=\"appended\" offset=\"%llu\"/>\n", (unsigned long long)offset);
}

/* The law's scalar state variables (e.g. the equivalent plastic strain `ep`), written as
 * point data after the fixed arrays, named as in the law. */
static int state_output(const sph_body *b, int k)
{
    const sph_body_desc *d = b->desc;
    return d && d->state_names && k < d->nstate && d->state_names[k];
}

/* Everything before the binary data; offsets follow the order of ARRAYS, then the state. */
static void write_header(FILE *f, const sph_body *b, double t)
{
    const char *in = "        ";
    uint64_t off[A_COUNT], pos = 0;
    for (int a = 0; a < A_COUNT; a++) {
        off[a] = pos;
        if (present((array_id)a, b))
            pos += sizeof(uint64_t) + block_bytes((array_id)a, (size_t)b->nown);
    }
    const uint64_t state_bytes = sizeof(uint64_t) + (uint64_t)b->nown * sizeof(double);
    fprintf(f, "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"%s\""
               " header_type=\"UInt64\">\n  <UnstructuredGrid>\n"
               "    <FieldData>\n      <DataArray type=\"Float64\" Name=\"TimeValue\""
               " NumberOfTuples=\"1\" format=\"ascii\">%.17g</DataArray>\n    </FieldData>\n"
               "    <Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n"
               "      <PointData Scalars=\"sigma_vm\" Vectors=\"displacement\">\n",
            host_byte_order(), t, b->nown, b->nown);
    for (int a = A_DISPLACEMENT; a <= A_GID; a++)
        if (present((array_id)a, b))
            write_data_array(f, (array_id)a, off[a], in);
    for (int k = 0; b->desc && k < b->desc->nstate; k++)
        if (state_output(b, k)) {
            fprintf(f, "%s<DataArray type=\"Float64\" Name=\"%s\" format=\"appended\" "
                       "offset=\"%llu\"/>\n",
                    in, b->desc->state_names[k], (unsigned long long)pos);
            pos += state_bytes;
        }
    fprintf(f, "      </PointData>\n      <Points>\n");
    write_data_array(f, A_POINTS, off[A_POINTS], in);
    fprintf(f, "      </Points>\n      <Cells>\n");
    for (int a = A_CONNECTIVITY; a <= A_TYPES; a++)
        write_data_array(f, (array_id)a, off[a], in);
    fprintf(f, "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
               "  <AppendedData encoding=\"raw\">\n   _");
}

/* The appended blocks, each built in buf (large enough for the biggest one).  Stops at
 * the first failed write; the error stays recorded in ferror(f). */
static void write_blocks(FILE *f, const sph_body *b, void *buf)
{
    for (int a = 0; a < A_COUNT; a++) {
        if (!present((array_id)a, b))
            continue;
        uint64_t bytes = block_bytes((array_id)a, (size_t)b->nown);
        fill_array((array_id)a, b, buf);
        if (fwrite(&bytes, sizeof bytes, 1, f) != 1)
            return;
        if (bytes && fwrite(buf, 1, (size_t)bytes, f) != bytes)
            return;
    }
    for (int k = 0; b->desc && k < b->desc->nstate; k++) {
        if (!state_output(b, k))
            continue;
        double *v = buf;
        const int ns = b->desc->nstate;
        for (int i = 0; i < b->nown; i++)
            v[i] = b->state[(size_t)i * ns + k];
        uint64_t bytes = (uint64_t)b->nown * sizeof(double);
        if (fwrite(&bytes, sizeof bytes, 1, f) != 1 || (bytes && fwrite(buf, 1, bytes, f) != bytes))
            return;
    }
}

int sph_write_vtu(const char *path, const sph_body *b, double t)
{
    size_t n = b->nown > 0 ? (size_t)b->nown : 0;
    void *buf = malloc(block_bytes(A_STRESS, n) + 1);
    if (!buf)
        return write_error(path, ENOMEM);
    FILE *f = sph_open_whole(path);
    if (!f) {
        int err = errno;
        free(buf);
        return write_error(path, err);
    }
    errno = 0;
    write_header(f, b, t);
    write_blocks(f, b, buf);
    fputs("\n  </AppendedData>\n</VTKFile>\n", f);
    int err = sph_close_whole(f, path);
    free(buf);
    return err ? write_error(path, err) : 0;
}

/* ------------------------------------------------------------------ collection */

/* A string as the value of an XML attribute. */
static void write_xml_attr(FILE *f, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&':  fputs("&amp;", f); break;
        case '<':  fputs("&lt;", f); break;
        case '>':  fputs("&gt;", f); break;
        case '"':  fputs("&quot;", f); break;
        default:   fputc(*s, f); break;
        }
    }
}

static void write_collection(FILE *f, const char *const *files, const double *times, int n)
{
    fprintf(f, "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"%s\">\n"
               "  <Collection>\n", host_byte_order());
    for (int k = 0; k < n; k++) {
        fprintf(f, "    <DataSet timestep=\"%.10g\" group=\"\" part=\"0\" file=\"", times[k]);
        write_xml_attr(f, files[k]);
        fprintf(f, "\"/>\n");
    }
    fprintf(f, "  </Collection>\n</VTKFile>\n");
}

/* The collection is rewritten at every output. */
int sph_write_pvd(const char *path, const char *const *files, const double *times, int n)
{
    FILE *f = sph_open_whole(path);
    if (!f)
        return write_error(path, errno);
    errno = 0;
    write_collection(f, files, times, n);
    const int err = sph_close_whole(f, path);
    return err ? write_error(path, err) : 0;
}

/* ------------------------------------------------------------------ pieces of many processes */

int sph_write_pvtu(const char *path, const sph_body *b, const char *const *pieces, int npieces)
{
    FILE *f = sph_open_whole(path);
    if (!f)
        return write_error(path, errno);
    errno = 0;
    const char *in = "      ";
    fprintf(f, "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"%s\""
               " header_type=\"UInt64\">\n  <PUnstructuredGrid GhostLevel=\"0\">\n"
               "    <PPointData Scalars=\"sigma_vm\" Vectors=\"displacement\">\n",
            host_byte_order());
    for (int a = A_DISPLACEMENT; a <= A_GID; a++) /* (the arrays of the pieces, write_header) */
        if (present((array_id)a, b)) {
            fprintf(f, "%s<PDataArray type=\"%s\" Name=\"%s\"", in, ARRAYS[a].type,
                    ARRAYS[a].name);
            write_components(f, (array_id)a);
            fputs("/>\n", f);
        }
    for (int k = 0; b->desc && k < b->desc->nstate; k++)
        if (state_output(b, k))
            fprintf(f, "%s<PDataArray type=\"Float64\" Name=\"%s\"/>\n", in,
                    b->desc->state_names[k]);
    fprintf(f, "    </PPointData>\n    <PPoints>\n%s<PDataArray type=\"Float64\" Name=\"Points\"",
            in);
    write_components(f, A_POINTS);
    fputs("/>\n    </PPoints>\n", f);
    for (int k = 0; k < npieces; k++) {
        fputs("    <Piece Source=\"", f);
        write_xml_attr(f, pieces[k]);
        fputs("\"/>\n", f);
    }
    fputs("  </PUnstructuredGrid>\n</VTKFile>\n", f);
    const int err = sph_close_whole(f, path);
    return err ? write_error(path, err) : 0;
}
