/* partition_report.h — the program's --partition N (partition_report.c). */
#ifndef SPHRT_RUN_PARTITION_REPORT_H
#define SPHRT_RUN_PARTITION_REPORT_H

#include "scene/model.h"

/* --partition N, each body's decomposition for N processes printed
 * (particles and halo per part); 0, or -1 after a message. */
int sph_partition_report(const sph_model *m, int nparts);

#endif
