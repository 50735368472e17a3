/* vtu.h — ParaView particle files (vtu.c): a body's .vtu or, on many processes, .pvtu, and
 * the .pvd collections that list them.  0 on success, -1 on an I/O error (reported). */
#ifndef SPHRT_IO_VTU_H
#define SPHRT_IO_VTU_H

#include "scene/body.h"

/* One VTK XML UnstructuredGrid (.vtu) file of a body's particles (VTK_VERTEX cells), binary
 * "raw" appended data with UInt64 headers, Float64 values.  Points are the current positions
 * X+u in 3D (2D: y = body->y_plane).  Point data: "displacement" (3), "velocity" (3),
 * "cauchy_stress" (6 components xx yy zz xy yz zx, from body->sigma), "sigma_vm" (von Mises),
 * "J" (det F), "strain_energy" (psi); with fracture also
 * "phase_field" (s) and "history" (H, eq. 8).  Multi-component arrays name their components
 * as ParaView does: X Y Z for vectors and points, XX YY ZZ XY YZ XZ for the stress.
 * docs/outputs.md describes every array. */
int sph_write_vtu(const char *path, const sph_body *b, double t);

/* The frame of a body on many processes: a .pvtu file listing the pieces, one .vtu file of
 * each process's own particles (relative to the .pvtu), with the arrays body b's have. */
int sph_write_pvtu(const char *path, const sph_body *b, const char *const *pieces, int npieces);

/* A ParaView collection (.pvd) listing files[k] (relative to the pvd) at times[k]. */
int sph_write_pvd(const char *path, const char *const *files, const double *times, int n);

#endif
