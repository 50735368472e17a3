/* check.h — tiny assertion helpers for the physics tests: print what is checked, with the
 * numbers, and count failures. */
#ifndef SPH_TEST_CHECK_H
#define SPH_TEST_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_failures;

/* |got - want| <= tol, reported with a label. */
static void check_close(const char *what, double got, double want, double tol)
{
    int ok = fabs(got - want) <= tol;
    printf("%-58s got %-14.8g want %-14.8g tol %-9.2g %s\n", what, got, want, tol, ok ? "ok" : "FAIL");
    check_failures += !ok;
}

#ifdef SPHRT_H
/* The largest |entry| of a body's P L (Q): its stress, for tests of stress-free motions. */
static double check_max_stress(const sph_body *b)
{
    double q = 0;
    for (long i = 0; i < (long)b->n * b->dim * b->dim; i++)
        q = fmax(q, fabs(b->Q[i]));
    return q;
}
#endif

static int check_result(void)
{
    printf(check_failures ? "%d check(s) FAILED\n" : "all checks passed\n", check_failures);
    return check_failures ? 1 : 0;
}

#endif
