/* table.h — a reference solution's table read at a time (expect.c), for the expectations
 * of generated code that compare with one. */
#ifndef SPHRT_RUN_TABLE_H
#define SPHRT_RUN_TABLE_H

#include "core/defs.h"

SPH_C_BEGIN

/* A table of n rows (t strictly increasing) at x, linearly interpolated; NaN outside
 * [t[0], t[n-1]] (reference solutions read from CSV files). */
double sph_table_interp(const double *t, const double *v, int n, double x);

SPH_C_END

#endif
