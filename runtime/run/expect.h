/* expect.h — a model's expectations evaluated from the recorded time series (expect.c). */
#ifndef SPHRT_RUN_EXPECT_H
#define SPHRT_RUN_EXPECT_H

#include <stddef.h>

#include "measure.h"
#include "io/json.h"
#include "io/report.h"
#include "scene/model.h"

/* Evaluate the model's expectations; writes them into the summary and prints a
 * line each.  Returns the number of failed expectations. */
typedef struct {
    sph_series *measures;   /* per (body, measure): rows ux uy uz fx fy fz */
    int *measure_base;      /* index of body b's first measure in `measures` */
    sph_series energy;      /* rows: total strain, total kinetic */
} sph_record;
/* errors (if not NULL, len bytes) receives "period 1.91 %, energy 0.0059 %", one entry per
 * expectation, for the program's final line; out (if not NULL, m->nexpects entries) the
 * results, for the report page. */
/* The mid-line (max + min) / 2 of column q of s, half its range, and the first time it
 * crosses the mid-line (as the period is measured): 1 rising there, -1 falling, 0 never
 * (t0 NAN).  The report page draws the sinusoid of an expected period from them. */
int sph_expect_phase(const sph_series *s, int q, double *mid, double *amplitude, double *t0);
int sph_expect_evaluate(const sph_model *m, const sph_record *r, sph_json *j, int quiet,
                        char *errors, size_t len, sph_report_expect *out);

#endif
