/* peak.c — this machine's ceilings for the roofline of the passes (bench/roofline/run):
 *   - the peak double-precision multiply-add rate of one core and of all the threads of
 *     OpenMP's team: 12 independent chains x = x * a + b in vectors of 8, 4 and 2 doubles
 *     and in scalars (each chain waits on its own last result, 12 of them in flight hide
 *     the multiply-add's latency), GFLOP/s counting a multiply-add as 2 operations;
 *   - the triad a[i] = b[i] + s * c[i] over three arrays of 2^25 doubles (768 MB, far past
 *     the caches), GB/s counting 24 bytes an element (two loads, one store) and, as the
 *     memory moves them, 32 (the store's line is read first: write-allocate); and the same
 *     over arrays that fit the second- and third-level caches (the passes' data do).
 * Each figure is the best of several repeats (the run the machine's other work disturbed
 * least).  Build:  cc -std=c11 -O3 -march=native -ffp-contract=fast -fopenmp -Wall -Wextra
 *                  -o peak peak.c
 * Run:    ./peak [THREADS]   (THREADS: the second team's size, default 2)
 * Prints one line a figure, then the same as one JSON object on the last line. */
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>

#define CHAINS 12
#define FMA_ITERS 20000000L /* per chain and repeat: 12 chains, about 0.1 s at 8 wide */
#define REPEATS 7
#define TRIAD_N (1L << 25)
#define L2_N (1L << 14)
#define L3_N (1L << 19)

typedef double v8 __attribute__((vector_size(64)));
typedef double v4 __attribute__((vector_size(32)));
typedef double v2 __attribute__((vector_size(16)));

static double now(void)
{
    return omp_get_wtime();
}

/* 12 chains of W lanes, n multiply-adds each; returns their sum so that nothing is dead.
 * x * a + b with a < 1 converges to b / (1 - a): no overflow, no denormals. */
/* GCC's basic-block vectoriser would merge the narrow chains into wider vectors (12 scalar
 * chains into one vector of 8 and one of 4): not for these. */
#if defined(__GNUC__) && !defined(__clang__)
#define AS_WRITTEN __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define AS_WRITTEN
#endif

#define CHAIN_KERNEL(NAME, T, W)                                                            \
    AS_WRITTEN static double NAME(long n, double seed)                                      \
    {                                                                                       \
        T x[CHAINS], a, b;                                                                  \
        for (int l = 0; l < W; l++) {                                                       \
            a[l] = 0.999999;                                                                \
            b[l] = 1e-6 * seed;                                                             \
        }                                                                                   \
        for (int k = 0; k < CHAINS; k++)                                                    \
            for (int l = 0; l < W; l++)                                                     \
                x[k][l] = seed + k + 0.1 * l;                                               \
        for (long i = 0; i < n; i++)                                                        \
            for (int k = 0; k < CHAINS; k++)                                                \
                x[k] = x[k] * a + b;                                                        \
        double s = 0;                                                                       \
        for (int k = 0; k < CHAINS; k++)                                                    \
            for (int l = 0; l < W; l++)                                                     \
                s += x[k][l];                                                               \
        return s;                                                                           \
    }

CHAIN_KERNEL(chains8, v8, 8)
CHAIN_KERNEL(chains4, v4, 4)
CHAIN_KERNEL(chains2, v2, 2)

AS_WRITTEN static double chains1(long n, double seed)
{
    double x[CHAINS], a = 0.999999, b = 1e-6 * seed;
    for (int k = 0; k < CHAINS; k++)
        x[k] = seed + k;
    for (long i = 0; i < n; i++)
        for (int k = 0; k < CHAINS; k++)
            x[k] = x[k] * a + b;
    double s = 0;
    for (int k = 0; k < CHAINS; k++)
        s += x[k];
    return s;
}

static double sink; /* keeps the chains' results */

/* GFLOP/s of chains of width w on a team of t threads, the best of REPEATS */
static double fma_rate(int w, int t)
{
    long n = FMA_ITERS * 8 / w;
    double best = 0;
    for (int r = 0; r < REPEATS; r++) {
        double s = 0, t0 = now();
#pragma omp parallel num_threads(t) reduction(+ : s)
        {
            double seed = 1.0 + omp_get_thread_num();
            s += w == 8 ? chains8(n, seed) : w == 4 ? chains4(n, seed)
                 : w == 2 ? chains2(n, seed) : chains1(n, seed);
        }
        double dt = now() - t0;
        sink += s;
        double rate = 2.0 * CHAINS * w * (double)n * t / dt * 1e-9;
        if (rate > best)
            best = rate;
    }
    return best;
}

/* triad's GB/s at 24 bytes an element over n elements on a team of t threads, the best of
 * REPEATS, each of `passes` sweeps (small arrays: many, so that a repeat lasts some ms).  The
 * arrays are first touched by the same static schedule, so each thread's pages are its own. */
static double triad(double *a, const double *b, const double *c, long n, int passes, int t)
{
    double best = 0;
    for (int r = 0; r < REPEATS; r++) {
        double t0 = now();
#pragma omp parallel num_threads(t)
        for (int p = 0; p < passes; p++) {
            const double s = 3.0 + 1e-9 * p; /* (a sweep unlike the last) */
#pragma omp for simd schedule(static)
            for (long i = 0; i < n; i++)
                a[i] = b[i] + s * c[i];
        }
        double dt = now() - t0;
        sink += a[r];
        double rate = 24.0 * (double)n * passes / dt * 1e-9;
        if (rate > best)
            best = rate;
    }
    return best;
}

int main(int argc, char **argv)
{
    int team = argc > 1 ? atoi(argv[1]) : 2;
    if (team < 1)
        team = 1;
    static const int widths[] = {8, 4, 2, 1};
    double f1[4], ft[4];
    for (int k = 0; k < 4; k++) {
        f1[k] = fma_rate(widths[k], 1);
        ft[k] = fma_rate(widths[k], team);
    }
    double *a = malloc(TRIAD_N * sizeof *a), *b = malloc(TRIAD_N * sizeof *b),
           *c = malloc(TRIAD_N * sizeof *c);
    if (!a || !b || !c) {
        fprintf(stderr, "peak: no memory for the triad's arrays\n");
        return 1;
    }
#pragma omp parallel for num_threads(team) schedule(static)
    for (long i = 0; i < TRIAD_N; i++) {
        a[i] = 0;
        b[i] = 1.0 + (double)(i & 7);
        c[i] = 0.5;
    }
    double tr1 = triad(a, b, c, TRIAD_N, 1, 1), trt = triad(a, b, c, TRIAD_N, 1, team);
    /* the same within the caches: 3 x 128 kB (the second level, 1 MB a core here) and
     * 3 x 4 MB (the third, 32 MB shared here); the lscpu of another machine may want others */
    double l2_1 = triad(a, b, c, L2_N, 4000, 1), l2_t = triad(a, b, c, L2_N, 4000, team);
    double l3_1 = triad(a, b, c, L3_N, 100, 1), l3_t = triad(a, b, c, L3_N, 100, team);
    for (int k = 0; k < 4; k++)
        printf("fma %d-wide      1 thread  %7.1f GFLOP/s   %d threads %7.1f GFLOP/s\n",
               widths[k], f1[k], team, ft[k]);
    printf("triad 24 B/elem 1 thread  %7.1f GB/s      %d threads %7.1f GB/s\n", tr1, team, trt);
    printf("triad 32 B/elem 1 thread  %7.1f GB/s      %d threads %7.1f GB/s\n",
           tr1 * 32 / 24, team, trt * 32 / 24);
    printf("triad in L2 (384 kB) 1 thread %7.1f GB/s  %d threads %7.1f GB/s\n", l2_1, team, l2_t);
    printf("triad in L3 (12 MB)  1 thread %7.1f GB/s  %d threads %7.1f GB/s\n", l3_1, team, l3_t);
    printf("{\"threads\": %d, \"fma_gflops_1\": {\"8\": %.2f, \"4\": %.2f, \"2\": %.2f, "
           "\"1\": %.2f}, \"fma_gflops_team\": {\"8\": %.2f, \"4\": %.2f, \"2\": %.2f, "
           "\"1\": %.2f}, \"triad_gbs_1\": %.2f, \"triad_gbs_team\": %.2f, "
           "\"triad_wa_gbs_1\": %.2f, \"triad_wa_gbs_team\": %.2f, \"triad_l2_gbs_1\": %.2f, "
           "\"triad_l2_gbs_team\": %.2f, \"triad_l3_gbs_1\": %.2f, \"triad_l3_gbs_team\": %.2f}\n",
           team, f1[0], f1[1], f1[2], f1[3], ft[0], ft[1], ft[2], ft[3], tr1, trt,
           tr1 * 32 / 24, trt * 32 / 24, l2_1, l2_t, l3_1, l3_t);
    if (sink == 42.0) /* never: the results are used */
        printf("%g\n", sink);
    free(a);
    free(b);
    free(c);
    return 0;
}
