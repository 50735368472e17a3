/* measure.h — what a run measures of a body (measure.c, fracture.c): its energies,
 * measurement planes, and the time series they are recorded in. */
#ifndef SPHRT_RUN_MEASURE_H
#define SPHRT_RUN_MEASURE_H

#include "core/defs.h"
#include "scene/body.h"

SPH_C_BEGIN

/* Energies of a body: strain (sum V psi) and kinetic (sum m |v|^2 / 2). */
void sph_body_energies(const sph_body *b, double *strain, double *kinetic);
/* The same with the kinetic energy at the middle of the last step, of length dt (0: as
 * sph_body_energies), the velocity (v_n + v_n+1) / 2 = v - dt/2 a on the free components:
 * in time with the strain energy of the stress pass at the step's start (Verlet) or its
 * middle (symplectic), so that their sum is a free elastic body's energy to O(dt^2), where
 * with v it swings by O(dt) as energy moves between them (energies.csv; a free cube
 * compressed and rebounding at cfl 0.2: 0.5 % against 11 %). */
void sph_body_energies_at(const sph_body *b, double dt, double *strain, double *kinetic);
/* Fracture energy of a body: sum V Gc ((1 - s)^2 / (4 eps0) + eps0 |grad s|^2); 0 without
 * fracture. */
double sph_fracture_energy(const sph_body *b);
/* Energy a body has dissipated in its material law (plastic work): sum V w; 0 without. */
double sph_dissipated_energy(const sph_body *b);
/* The heat a body's law has put into its particles (a law with a temperature T of specific
 * heat c): sum m c (T - T at the start); 0 without. */
double sph_thermal_energy(const sph_body *b);

/* A growable time series of one measured quantity set. */
typedef struct {
    double *t;
    double *val;   /* n rows of `width` values */
    int n, cap, width;
} sph_series;
void sph_series_push(sph_series *s, double t, const double *row);

/* Mean displacement (3) and total force (3, sum m a) over measurement k of body b. */
void sph_measure(const sph_body *b, int k, double out[6]);

SPH_C_END

#endif
