/* main.h — the entry points of a generated program (run.c; mpi/par_mpi.c). */
#ifndef SPHRT_RUN_MAIN_H
#define SPHRT_RUN_MAIN_H

#include "core/defs.h"
#include "par/par.h"
#include "scene/model.h"

SPH_C_BEGIN

/* Entry point of a generated program; sph_mpi_main that of one built with sphc --mpi, on
 * every process of the run (libsphrt_mpi). */
int sph_main(const sph_model *m, int argc, char **argv);
int sph_mpi_main(const sph_model *m, int argc, char **argv);
/* sph_main for the processes par (run.c). */
int sph_main_par(const sph_model *m, int argc, char **argv, const sph_par *par);

SPH_C_END

#endif
