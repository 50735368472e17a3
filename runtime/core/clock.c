/* clock.c — the wall clock, the process's CPU time and the machine's idle time (clock.h). */
#include <stdio.h>
#include <time.h>
#include <unistd.h>

#include "clock.h"

double sph_wall_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double sph_cpu_time(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double sph_idle_time(void)
{
    /* Linux: the first line of /proc/stat, "cpu user nice system idle iowait ...", in ticks
     * of 1/sysconf(_SC_CLK_TCK) s, summed over the cores */
    FILE *f = fopen("/proc/stat", "r");
    if (!f)
        return -1;
    unsigned long long user, nice, sys, idle, iowait;
    const int n = fscanf(f, "cpu %llu %llu %llu %llu %llu", &user, &nice, &sys, &idle, &iowait);
    fclose(f);
    const long tick = sysconf(_SC_CLK_TCK);
    return n == 5 && tick > 0 ? (double)(idle + iowait) / (double)tick : -1;
}
