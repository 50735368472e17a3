/* profile_report.h — the profile of a run (core/profile.h's entries) reported: in
 * summary.json and as the table the program prints (profile_report.c). */
#ifndef SPHRT_IO_PROFILE_REPORT_H
#define SPHRT_IO_PROFILE_REPORT_H

#include <stdio.h>

#include "json.h"

/* The profile (profile.c): the passes' times in summary.json ("profile"), and as a table. */
void sph_profile_json(sph_json *j);
typedef struct {
    double setup, steps, checks, outputs; /* the run's timers, in seconds */
} sph_profile_times;
void sph_profile_print(FILE *f, const char *model, long steps, const sph_profile_times *t);

#endif
