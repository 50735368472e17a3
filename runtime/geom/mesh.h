/* mesh.h — closed triangle surfaces for the `surface(file "...")` shape (SPH_MESH).
 *
 *   mesh_read.c   reading legacy VTK polydata (ASCII or BINARY) and STL (ASCII or binary)
 *   mesh_check.c  the closed-surface check, consistent outward orientation, volume
 *   mesh_ray.c    the crossing of a triangle by a vertical ray (robust on edges and vertices)
 *   mesh_query.c  bounding-volume hierarchy, inside test, distance to the surface
 *   mesh_solid.c  the surface of a prism or pyramid given by its corners
 *   mesh_cache.c  loading each file once per run (sph_mesh_get)
 *
 * The compiler uses mesh_read.c, mesh_check.c and mesh_ray.c to check a surface when it
 * compiles the model; the runtime loads it again when the program runs. */
#ifndef SPHRT_MESH_H
#define SPHRT_MESH_H

#include <stddef.h>

/* A node of the bounding-volume hierarchy: a leaf holds triangles order[first ..
 * first + count - 1]; an inner node (count == 0) its children left and right. */
typedef struct {
    double lo[3], hi[3];
    int left, right, first, count;
} sph_mesh_node;

typedef struct {
    char *file;          /* the path it was read from */
    int nv, nt;
    double *v;           /* nv * 3 vertex coordinates */
    int *t;              /* nt * 3 vertex indices; after sph_mesh_close oriented outwards */
    double lo[3], hi[3]; /* bounding box */
    double volume;       /* enclosed volume (divergence theorem), after sph_mesh_close */
    double eps;          /* 1e-6 of the largest coordinate: how well the file (often in single
                          * precision) places the surface; sph_mesh_close */
    int ncomponents;     /* connected pieces of the surface */
    sph_mesh_node *nodes;/* the hierarchy (sph_mesh_index); NULL before */
    int *order;
    int nnodes;
} sph_mesh;

/* Reads a legacy VTK file (DATASET POLYDATA: POLYGONS, TRIANGLE_STRIPS; POINTS float or
 * double; ASCII or BINARY; version 5 OFFSETS/CONNECTIVITY too) or an STL file (ASCII or
 * binary, recognised by content).  Polygons are split into fans from their first vertex;
 * vertices with equal coordinates are merged.  Returns 0, or -1 with a message naming the
 * file in err. */
int sph_mesh_read(const char *path, sph_mesh *m, char *err, size_t len);

/* Checks that the surface is closed (every edge shared by exactly two triangles) and
 * orientable, orients every piece outwards (the boundary of a cavity inwards) and computes
 * the volume and bounding box.  Returns 0, or -1 with a message naming the file in err. */
int sph_mesh_close(sph_mesh *m, char *err, size_t len);

/* sph_mesh_read and sph_mesh_close. */
int sph_mesh_load(const char *path, sph_mesh *m, char *err, size_t len);
/* The same with every vertex moved by the affine map xf (NULL: none), 4 vectors of 3: the
 * images of the unit vectors along x, y and z (the columns of its matrix), then the
 * translation.  A map that mirrors the surface is fine: sph_mesh_close orients it. */
int sph_mesh_load_moved(const char *path, const double *xf, sph_mesh *m, char *err,
                        size_t len);
/* The determinant of the map xf's matrix (its volume ratio; 0: it flattens). */
double sph_mesh_map_det(const double *xf);
void sph_mesh_free(sph_mesh *m);

/* mesh_ray.c: whether the ray from p along +z crosses triangle k, at height *z.  Points of
 * the triangle's edges and vertices are decided as for p moved by (e, e^2, 0), e -> 0, the
 * same way for every triangle, so a ray through an edge or vertex shared by several
 * triangles crosses the surface the right number of times. */
int sph_mesh_ray_hits(const sph_mesh *m, int k, const double p[3], double *z);

/* mesh_query.c: the hierarchy (built once; required by the queries below). */
void sph_mesh_index(sph_mesh *m);
/* 1 when p lies inside the closed surface or on it (within 1e-12 of its size). */
int sph_mesh_inside(const sph_mesh *m, const double p[3]);
/* Distance from p to the surface, or `limit` when it is larger than that. */
double sph_mesh_distance(const sph_mesh *m, const double p[3], double limit);

/* mesh_solid.c: the surface of a prism (pts: the base's corners, then the top's, as many)
 * or a pyramid (pts: the apex, then the base's corners), npts points of 3 coordinates,
 * closed and checked as by sph_mesh_close.  Returns 0, or -1 with a message in err. */
typedef enum { SPH_SOLID_PRISM, SPH_SOLID_PYRAMID } sph_solid_kind;
enum { SPH_SOLID_MAX_CORNERS = 1000 }; /* per polygon */
int sph_mesh_solid(sph_solid_kind kind, const double *pts, int npts, sph_mesh *m, char *err,
                   size_t len);

/* mesh_cache.c: at most this many surfaces in a run (the compiler checks a model against
 * it): unmoved surfaces of one file count once, every moved one, prism and pyramid once. */
enum { SPH_MESH_MAX = 4096 };
/* The surface in file moved by xf (NULL: as it is; sph_mesh_load_moved),
 * loaded, checked and indexed on first use (thread safe); prints the error and exits with
 * status 4 (set-up failed) when it cannot be.  A map is known by its address. */
const sph_mesh *sph_mesh_get(const char *file, const double *xf);
/* The same for the solid of npts corners pts, known by the address of its corners. */
const sph_mesh *sph_mesh_get_solid(sph_solid_kind kind, const double *pts, int npts);

#endif
