/* reference_csv.h — a reference solution's rows read from a CSV file (reference_csv.c). */
#ifndef SPHC_REFERENCE_CSV_H
#define SPHC_REFERENCE_CSV_H

#include "util/source.h"

/* The (t, value) rows of the file at path into *t, *v (*n of them); errors at loc. */
int reference_csv_read(const char *path, SrcLoc loc, double **t, double **v, int *n);

#endif
