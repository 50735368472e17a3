/* region.h — regions: unions and differences of boxes, cylinders, spheres, closed surfaces,
 * prisms and pyramids (region.c), as the scene describes a body's and a boundary condition's
 * shape. */
#ifndef SPHRT_GEOM_REGION_H
#define SPHRT_GEOM_REGION_H

#include "core/defs.h"

SPH_C_BEGIN

typedef enum { SPH_BOX, SPH_CYLINDER, SPH_SPHERE, SPH_MESH, SPH_PRISM, SPH_PYRAMID } sph_shape_kind;

typedef struct {
    sph_shape_kind kind;
    double a[3]; /* box: min corner   cylinder: axis start   sphere: centre */
    double b[3]; /* box: max corner   cylinder: axis end                    */
    double r;    /* cylinder, sphere: radius                                */
    int subtract;/* 1: this primitive is removed from the union of the previous ones */
    const char *file; /* mesh: a closed surface, VTK or STL (mesh.h); loaded at first use */
    const double *pts;/* prism: the base's corners, then the top's; pyramid: the apex, then */
    int npts;         /* the base's corners (npts points, mesh.h); its surface built at first use;
                       * mesh: NULL, or the map that moves the file's surface (4 points:
                       * sph_mesh_load_moved) */
} sph_shape;

typedef struct {
    const sph_shape *prims;
    int n;
    int has_corner;   /* 1: the fill lattice has a cell corner at `corner` */
    double corner[3];
} sph_region;

/* 1 when point p (3D) lies in the region (union/difference of its primitives). */
int sph_region_contains(const sph_region *r, const double p[3]);
/* Distance from p to the region (0 inside). */
double sph_region_distance(const sph_region *r, const double p[3]);

/* Regions tested in the body's dimension (2D: in the x-z plane, y ignored). */
int sph_region_contains_dim(const sph_region *r, int dim, const double p[3]);
/* The same, counting points within tol of a primitive as on it (fill.c: tol = 1e-9 dx). */
int sph_region_contains_tol_dim(const sph_region *r, int dim, const double p[3], double tol);
double sph_region_distance_dim(const sph_region *r, int dim, const double p[3]);
int sph_region_bbox_dim(const sph_region *r, int dim, double lo[3], double hi[3]);

SPH_C_END

#endif
