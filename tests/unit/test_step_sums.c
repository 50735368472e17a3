/* A body's step sums (runtime/scene/step_sums.h): the table's members read and written in
 * its order, the initial values, and the CPU's SPH_STEP_SUM_OVER, which must give the same
 * bits on any number of threads (stripe by stripe, then in stripe order). */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/body.h"
#include "scene/step_sums.h"
#include "unit_check.h"

/* Every row's member, written through sph_step_sums_set, reads back at its index. */
static void round_trip(void)
{
    sph_body b;
    memset(&b, 0, sizeof b);
    double x[SPH_STEP_NSUMS], y[SPH_STEP_NSUMS];
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        x[k] = 1.5 + k;
    sph_step_sums_set(&b, x);
    sph_step_sums_get(&b, y);
    int same = 1;
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        same &= x[k] == y[k];
    check(same, "the step sums set and read back in the table's order", same, 1);
    check(b.vmax2 == x[SPH_STEP_SUM_vmax2] && b.lam2min == x[SPH_STEP_SUM_lam2min] &&
              b.visc_dissipated == x[SPH_STEP_SUM_visc_dissipated],
          "the members are the rows of their indices", b.lam2min, x[SPH_STEP_SUM_lam2min]);
    check(sph_step_sum_initial(SPH_STEP_SUM_lam2min) == 1.0 &&
              sph_step_sum_reduce(SPH_STEP_SUM_lam2min) == SPH_REDUCE_MIN,
          "the smallest stretch: a minimum, 1 before the first step",
          sph_step_sum_initial(SPH_STEP_SUM_lam2min), 1.0);
}

/* visc_rate := the sum over the particles of a value of very different magnitudes, on 1, 2
 * and 3 threads; the sum in stripe order as reference. */
static void sum_over(void)
{
    enum { N = 10007, STRIPES = 24 };
    sph_body b;
    memset(&b, 0, sizeof b);
    int stripe[STRIPES + 1];
    double stripe_sum[STRIPES], *v = malloc(N * sizeof *v);
    for (int s = 0; s <= STRIPES; s++)
        stripe[s] = (int)((long)N * s / STRIPES);
    for (int i = 0; i < N; i++)
        v[i] = (urand() - 0.3) * pow(10, 12 * urand() - 6);
    b.n = b.nown = N, b.nstripes = STRIPES, b.stripe = stripe, b.stripe_sum = stripe_sum;
    b.v = v;
    double ref = 0;
    for (int s = 0; s < STRIPES; s++) {
        double x = 0;
        for (int i = stripe[s]; i < stripe[s + 1]; i++)
            x += v[i] * v[i] - v[i];
        ref += x;
    }
    for (int threads = 1; threads <= 3; threads++) {
        omp_set_num_threads(threads);
        b.visc_rate = NAN;
        SPH_STEP_SUM_OVER(&b, visc_rate, i, b.v[i] * b.v[i] - b.v[i]);
        char what[80];
        snprintf(what, sizeof what, "SPH_STEP_SUM_OVER on %d thread%s: the stripes' order", threads,
                 threads > 1 ? "s" : "");
        check(b.visc_rate == ref, what, b.visc_rate - ref, 0);
    }
    free(v);
}

int main(void)
{
    round_trip();
    sum_over();
    return failures ? 1 : 0;
}
