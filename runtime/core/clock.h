/* clock.h — the wall clock, the process's CPU time and the machine's idle time (clock.c),
 * for the profile, the progress line, the thread team and the summary. */
#ifndef SPHRT_CORE_CLOCK_H
#define SPHRT_CORE_CLOCK_H

#include "defs.h"

SPH_C_BEGIN

double sph_wall_time(void); /* the wall clock in seconds, monotonic */
double sph_cpu_time(void);  /* the CPU time of the process's threads, seconds */
double sph_idle_time(void); /* the machine's idle seconds summed over its cores, or -1 */

SPH_C_END

#endif
