/* compat.h — the output files SoliDualSPHysics writes, for models imported from its XML case
 * files (sph_model.compat_outputs; docs/xml.md lists the columns). */
#ifndef SPHRT_COMPAT_H
#define SPHRT_COMPAT_H

#include "csv.h"
#include "scene/model.h"

typedef struct {
    sph_csv energies;     /* DeformStruc_Energies.csv */
    sph_csv *planes;      /* MeasuringPlData_MK<mk>_PL<k>.csv, one per measurement plane */
    int nplanes, nbodies, dim;
    unsigned char *fracture; /* per body: it has a fracture energy column */
} sph_compat;

/* Opens the files in dir with their header lines; 0, or -1 after reporting. */
int sph_compat_open(sph_compat *c, const sph_model *m, const char *dir);
/* One energy row, given as the row of energies.csv: e[0] = t, strain and kinetic energy of
 * every body, then the fracture energy of every body with fracture (and the total, unused).
 * Written as SoliDualSPHysics orders it: per body strain, kinetic[, fracture]. */
int sph_compat_energies(sph_compat *c, const double *e);
/* One row of plane q (counted over all bodies in order): r = t, ux uy uz, fx fy fz. */
int sph_compat_plane(sph_compat *c, int q, const double r[7]);
void sph_compat_close(sph_compat *c);

/* The mk of body i: N for a body named mkN (as the XML importer names them), else i + 1. */
int sph_compat_mk(const sph_model *m, int i);

#endif
