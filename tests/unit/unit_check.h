/* unit_check.h — what the unit tests share: one line per check (ok/FAIL, what, the value and
 * its limit) with a count of failures, and a reproducible uniform random number. */
#ifndef SPH_UNIT_CHECK_H
#define SPH_UNIT_CHECK_H

#include <stdint.h>
#include <stdio.h>

static int failures = 0;

/* Prints one check and counts it when it fails. */
static void check(int ok, const char *what, double value, double limit)
{
    printf("%-4s %-62s %.3e (limit %.1e)\n", ok ? "ok" : "FAIL", what, value, limit);
    failures += !ok;
}

static uint64_t lcg_state = 12345u;

/* Uniform in [0, 1) from a 64-bit LCG (Knuth's MMIX constants), the top 53 bits. */
static inline double urand(void)
{
    lcg_state = lcg_state * 6364136223846793005u + 1442695040888963407u;
    return (double)(lcg_state >> 11) * 0x1.0p-53;
}

#endif
