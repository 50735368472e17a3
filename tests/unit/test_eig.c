/* test_eig.c — symmetric 3×3 eigen-decomposition and positive/negative parts (sph_tensor.h):
 * reconstruction, orthonormality, eigenvalues of R diag(d) Rᵀ (repeated, zero, graded, nearly
 * repeated), the tension/compression split and the 2D closed form against the 3D one. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <time.h>
#include "sph_tensor.h"
#include "unit_check.h"

/* ---------------------------------------------------------------- helpers */

static double srand1(void) { return 2.0 * urand() - 1.0; } /* uniform in [-1, 1) */

/* A random rotation from a random unit quaternion. */
static void random_rotation(double R[9])
{
    double w, x, y, z, n;
    do {
        w = srand1(), x = srand1(), y = srand1(), z = srand1();
        n = w * w + x * x + y * y + z * z;
    } while (n < 1e-2 || n > 1.0);
    n = 1.0 / sqrt(n);
    w *= n, x *= n, y *= n, z *= n;
    double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                   2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                   2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    for (int k = 0; k < 9; k++)
        R[k] = r[k];
}

/* A = R diag(d) Rᵀ, made exactly symmetric. */
static void compose(const double R[9], const double d[3], double A[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double s = 0.0;
            for (int k = 0; k < 3; k++)
                s += R[3 * i + k] * d[k] * R[3 * j + k];
            A[3 * i + j] = A[3 * j + i] = s;
        }
}

/* Frobenius norm of A − B (B = NULL: of A), scaled so that no square under- or overflows. */
static double fdist(const double A[9], const double B[9])
{
    double m = 0.0, s = 0.0, e[9];
    for (int k = 0; k < 9; k++)
        e[k] = A[k] - (B ? B[k] : 0.0), m = fmax(m, fabs(e[k]));
    if (m == 0.0)
        return 0.0;
    for (int k = 0; k < 9; k++)
        s += (e[k] / m) * (e[k] / m);
    return m * sqrt(s);
}

static double fnorm(const double A[9]) { return fdist(A, NULL); }

static int all_finite(const double *a, int n)
{
    for (int k = 0; k < n; k++)
        if (!isfinite(a[k]))
            return 0;
    return 1;
}

static void sort3_desc(double d[3])
{
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2 - i; j++)
            if (d[j] < d[j + 1]) {
                double t = d[j];
                d[j] = d[j + 1];
                d[j + 1] = t;
            }
}

/* A random symmetric matrix, entries uniform in [-1, 1] times 10^[-8, 8]. */
static void random_sym(double A[9])
{
    double s = pow(10.0, 16.0 * urand() - 8.0);
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++)
            A[3 * i + j] = A[3 * j + i] = s * srand1();
}

/* Errors of one decomposition: reconstruction and eigenvalue order (relative to |A|) and
 * orthonormality |QᵀQ − I|max. */
typedef struct {
    double recon, ortho, order;
    int finite;
} EigErr;

static EigErr eig_errors(const double A[9], const double lam[3], const double Q[9])
{
    EigErr e = {0.0, 0.0, 0.0, all_finite(lam, 3) && all_finite(Q, 9)};
    double B[9], nA = fnorm(A);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0.0, g = 0.0;
            for (int k = 0; k < 3; k++) {
                s += Q[3 * i + k] * lam[k] * Q[3 * j + k];
                g += Q[3 * k + i] * Q[3 * k + j];
            }
            B[3 * i + j] = s;
            e.ortho = fmax(e.ortho, fabs(g - (i == j)));
        }
    e.recon = nA > 0.0 ? fdist(A, B) / nA : fnorm(B);
    e.order = fmax(fmax(lam[1] - lam[0], lam[2] - lam[1]), 0.0) / (nA > 0.0 ? nA : 1.0);
    return e;
}

/* ---------------------------------------------------------------- eigen-decomposition */

#define TOL 1e-12

/* Random symmetric matrices of random scale. */
static void test_eig_random(void)
{
    double recon = 0.0, ortho = 0.0, order = 0.0;
    int finite = 1;
    for (int n = 0; n < 4000; n++) {
        double A[9], lam[3], Q[9];
        random_sym(A);
        sph_sym_eig3(A, lam, Q);
        EigErr e = eig_errors(A, lam, Q);
        recon = fmax(recon, e.recon), ortho = fmax(ortho, e.ortho), order = fmax(order, e.order);
        finite &= e.finite;
    }
    check(finite && recon < TOL, "eig3 random (4000): max |A - Q L Qt| / |A|", recon, TOL);
    check(finite && ortho < TOL, "eig3 random: max |Qt Q - I|", ortho, TOL);
    check(order == 0.0, "eig3 random: eigenvalues descending (violation)", order, 0.0);
}

/* d for family f: generic, d1 = d2, triple, zero, graded 1e-12 : 1 : 1e12, nearly
 * repeated 1 and 1 + 1e-14, one zero, two zeros; random signs and scale. */
static const char *family_name[] = {"generic",        "d1 = d2",        "d1 = d2 = d3",
                                    "d = 0",          "{1e-12,1,1e12}", "{1, 1+1e-14, x}",
                                    "{x, y, 0}",      "{x, 0, 0}"};
enum { NFAMILY = 8 };

static void family_d(int f, double d[3])
{
    double s = pow(10.0, 12.0 * urand() - 6.0);
    double x = s * srand1(), y = s * srand1(), z = s * srand1();
    double sg = srand1() < 0.0 ? -1.0 : 1.0;
    switch (f) {
    case 0: d[0] = x, d[1] = y, d[2] = z; break;
    case 1: d[0] = x, d[1] = x, d[2] = y; break;
    case 2: d[0] = d[1] = d[2] = x; break;
    case 3: d[0] = d[1] = d[2] = 0.0; break;
    case 4: d[0] = sg * 1e-12 * s, d[1] = (srand1() < 0 ? -s : s), d[2] = sg * 1e12 * s; break;
    case 5: d[0] = s, d[1] = s * (1.0 + 1e-14), d[2] = x; break;
    case 6: d[0] = x, d[1] = y, d[2] = 0.0; break;
    default: d[0] = x, d[1] = d[2] = 0.0; break;
    }
    /* a random permutation, so that repeated values are not always in the same slots */
    int p = (int)(3.0 * urand());
    double t = d[0];
    d[0] = d[p], d[p] = t;
}

/* R diag(d) Rᵀ with known eigenvalues, for each family. */
static void test_eig_families(void)
{
    char what[100];
    for (int f = 0; f < NFAMILY; f++) {
        double recon = 0.0, ortho = 0.0, lamerr = 0.0, order = 0.0;
        int finite = 1;
        for (int n = 0; n < 1000; n++) {
            double R[9], d[3], A[9], lam[3], Q[9];
            random_rotation(R);
            family_d(f, d);
            compose(R, d, A);
            sph_sym_eig3(A, lam, Q);
            EigErr e = eig_errors(A, lam, Q);
            recon = fmax(recon, e.recon), ortho = fmax(ortho, e.ortho);
            order = fmax(order, e.order);
            finite &= e.finite;
            sort3_desc(d);
            double dmax = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
            for (int k = 0; k < 3; k++)
                lamerr = fmax(lamerr, fabs(lam[k] - d[k]) / (dmax > 0.0 ? dmax : 1.0));
        }
        double worst = fmax(fmax(recon, ortho), lamerr);
        snprintf(what, sizeof what, "eig3 R diag(d) Rt, %s: recon/ortho/|lam-d| max",
                 family_name[f]);
        check(finite && worst < TOL && order == 0.0, what, worst, TOL);
    }
}

/* The zero matrix and c I: finite, exact eigenvalues, Q = I. */
static void test_eig_special(void)
{
    const double cs[] = {0.0, 1.0, -3.5, 1e-300, -1e300, 4.9e-324, 2.5e-3};
    double err = 0.0;
    int finite = 1;
    for (unsigned n = 0; n < sizeof cs / sizeof cs[0]; n++) {
        double A[9] = {cs[n], 0, 0, 0, cs[n], 0, 0, 0, cs[n]}, lam[3], Q[9];
        sph_sym_eig3(A, lam, Q);
        finite &= all_finite(lam, 3) && all_finite(Q, 9);
        for (int k = 0; k < 3; k++)
            err = fmax(err, fabs(lam[k] - cs[n]) / (cs[n] != 0.0 ? fabs(cs[n]) : 1.0));
        for (int k = 0; k < 9; k++)
            err = fmax(err, fabs(Q[k] - (k % 4 == 0)));
    }
    check(finite && err == 0.0, "eig3 of 0 and c I (c down to subnormal): lam = c, Q = I", err,
          0.0);
    /* Tiny and huge matrices: the scaling keeps squares from under- or overflowing. */
    double worst = 0.0;
    finite = 1;
    for (int n = 0; n < 200; n++) {
        double A[9], lam[3], Q[9], s = n % 2 ? 1e-300 : 1e300;
        for (int i = 0; i < 3; i++)
            for (int j = i; j < 3; j++)
                A[3 * i + j] = A[3 * j + i] = s * srand1();
        sph_sym_eig3(A, lam, Q);
        EigErr e = eig_errors(A, lam, Q);
        worst = fmax(worst, fmax(e.recon, e.ortho));
        finite &= e.finite;
    }
    check(finite && worst < TOL, "eig3 of matrices with entries ~1e-300 / 1e300: recon, ortho",
          worst, TOL);
}

/* ---------------------------------------------------------------- positive part (3D) */

/* Ap, An = −pos(−A) computed independently; checks Ap + An = A, Ap ⪰ 0, An ⪯ 0, Ap : An = 0,
 * and (when R, d are given) Ap = R diag(max(d, 0)) Rᵀ. Returns the worst relative error. */
static double split_errors(const double A[9], const double R[9], const double d[3], int *finite)
{
    double mA[9], Ap[9], An[9], S[9], lam[3], Q[9], nA = fnorm(A);
    for (int k = 0; k < 9; k++)
        mA[k] = -A[k];
    sph_sym_pos3(A, Ap);
    sph_sym_pos3(mA, An);
    for (int k = 0; k < 9; k++)
        An[k] = -An[k], S[k] = Ap[k] + An[k];
    *finite &= all_finite(Ap, 9) && all_finite(An, 9);
    if (nA == 0.0)
        return fnorm(Ap) + fnorm(An);
    double e = fdist(S, A) / nA, dot = 0.0;
    sph_sym_eig3(Ap, lam, Q);
    e = fmax(e, -lam[2] / nA); /* Ap positive semidefinite */
    sph_sym_eig3(An, lam, Q);
    e = fmax(e, lam[0] / nA); /* An negative semidefinite */
    for (int k = 0; k < 9; k++)
        dot += Ap[k] * An[k];
    e = fmax(e, fabs(dot) / (nA * nA)); /* Ap : An = 0 */
    if (R) {
        double dp[3] = {fmax(d[0], 0.0), fmax(d[1], 0.0), fmax(d[2], 0.0)}, P[9];
        compose(R, dp, P);
        e = fmax(e, fdist(P, Ap) / nA);
    }
    return e;
}

static void test_pos3(void)
{
    char what[100];
    double worst = 0.0;
    int finite = 1;
    for (int n = 0; n < 4000; n++) {
        double A[9];
        random_sym(A);
        worst = fmax(worst, split_errors(A, NULL, NULL, &finite));
    }
    check(finite && worst < TOL, "pos3 random (4000): Ap+An=A, Ap>=0, An<=0, Ap:An=0", worst, TOL);
    for (int f = 0; f < NFAMILY; f++) {
        worst = 0.0;
        for (int n = 0; n < 1000; n++) {
            double R[9], d[3], A[9];
            random_rotation(R);
            family_d(f, d);
            compose(R, d, A);
            worst = fmax(worst, split_errors(A, R, d, &finite));
        }
        snprintf(what, sizeof what, "pos3 %s: split checks and Ap = R max(d,0) Rt", family_name[f]);
        check(finite && worst < TOL, what, worst, TOL);
    }
    /* SPD: Ap = A exactly; negative definite: Ap = 0 exactly (fast paths). */
    double spd = 0.0, nd = 0.0;
    for (int n = 0; n < 1000; n++) {
        double R[9], d[3] = {urand() + 1e-3, urand() + 1e-3, urand() + 1e-3}, A[9], mA[9], Ap[9];
        random_rotation(R);
        compose(R, d, A);
        sph_sym_pos3(A, Ap);
        spd = fmax(spd, fdist(A, Ap) / fnorm(A));
        for (int k = 0; k < 9; k++)
            mA[k] = -A[k];
        sph_sym_pos3(mA, Ap);
        nd = fmax(nd, fnorm(Ap));
    }
    check(spd == 0.0, "pos3 SPD: |Ap - A| / |A| (exact)", spd, 0.0);
    check(nd == 0.0, "pos3 negative definite: |Ap| (exact)", nd, 0.0);
    /* R diag(2, -1, -1) Rᵀ: Ap = 2 q1 q1ᵀ with q1 the first column of R. */
    double e = 0.0;
    for (int n = 0; n < 1000; n++) {
        double R[9], d[3] = {2, -1, -1}, A[9], Ap[9], P[9];
        random_rotation(R);
        compose(R, d, A);
        sph_sym_pos3(A, Ap);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                P[3 * i + j] = 2.0 * R[3 * i] * R[3 * j];
        e = fmax(e, fdist(P, Ap) / fnorm(A));
    }
    check(e < TOL, "pos3 R diag(2,-1,-1) Rt: |Ap - 2 q1 q1t| / |A|", e, TOL);
    /* zero and c I */
    const double cs[] = {0.0, 1.0, -1.0, 1e-300, -1e300, 4.9e-324};
    e = 0.0;
    finite = 1;
    for (unsigned n = 0; n < sizeof cs / sizeof cs[0]; n++) {
        double c = cs[n], A[9] = {c, 0, 0, 0, c, 0, 0, 0, c}, Ap[9];
        sph_sym_pos3(A, Ap);
        finite &= all_finite(Ap, 9);
        for (int k = 0; k < 9; k++)
            e = fmax(e, fabs(Ap[k] - (k % 4 == 0 ? fmax(c, 0.0) : 0.0)));
    }
    check(finite && e == 0.0, "pos3 of 0 and c I: finite, Ap = max(c,0) I (exact)", e, 0.0);
}

/* ---------------------------------------------------------------- positive part (2D) */

/* pos2 against pos3 on the tensor embedded in the x–z plane (y row and column zero). */
static double pos2_vs_pos3(double axx, double axz, double azz, int *finite)
{
    double A[9] = {axx, 0, axz, 0, 0, 0, axz, 0, azz}, Ap[9], p[3];
    sph_sym_pos3(A, Ap);
    sph_sym_pos2(axx, axz, azz, p);
    *finite &= all_finite(p, 3);
    double n = fnorm(A), e = fabs(Ap[1]) + fabs(Ap[3]) + fabs(Ap[4]) + fabs(Ap[5]) + fabs(Ap[7]);
    e += fabs(p[0] - Ap[0]) + fabs(p[1] - Ap[2]) + fabs(p[1] - Ap[6]) + fabs(p[2] - Ap[8]);
    return n > 0.0 ? e / n : e + fabs(p[0]) + fabs(p[1]) + fabs(p[2]);
}

static void test_pos2(void)
{
    double worst = 0.0;
    int finite = 1;
    for (int n = 0; n < 4000; n++) {
        double s = pow(10.0, 16.0 * urand() - 8.0);
        worst = fmax(worst, pos2_vs_pos3(s * srand1(), s * srand1(), s * srand1(), &finite));
    }
    check(finite && worst < TOL, "pos2 vs pos3 embedded, random (4000)", worst, TOL);
    /* Where the squares of the entries over- or underflow (|A| ~ 1e150 and beyond, 1e-150 and
     * below), mixed signs mostly: pos2 scales its radius by a power of two. */
    worst = 0.0;
    for (int n = 0; n < 2000; n++) {
        double s = pow(10.0, (n % 2 ? 1.0 : -1.0) * (150.0 + 150.0 * urand()));
        worst = fmax(worst, pos2_vs_pos3(s * srand1(), s * srand1(), s * srand1(), &finite));
    }
    check(finite && worst < TOL, "pos2 vs pos3 at |A| 1e150..1e300 and 1e-300..1e-150", worst, TOL);
    /* Repeated eigenvalues, zero, one zero eigenvalue, graded, rotated diag(a, -a). */
    const double cs[] = {0.0, 1.0, -1.0, 1e-300, -1e300, 4.9e-324, 3e-3};
    worst = 0.0;
    for (unsigned n = 0; n < sizeof cs / sizeof cs[0]; n++) {
        double p[3], c = cs[n];
        sph_sym_pos2(c, 0.0, c, p);
        finite &= all_finite(p, 3);
        worst = fmax(worst, fabs(p[0] - fmax(c, 0.0)) + fabs(p[1]) + fabs(p[2] - fmax(c, 0.0)));
        worst = fmax(worst, pos2_vs_pos3(c, 0.0, c, &finite));
    }
    check(finite && worst == 0.0, "pos2 of 0 and c I: Ap = max(c,0) I (exact), = pos3", worst, 0.0);
    worst = 0.0;
    for (int n = 0; n < 2000; n++) {
        double th = 3.14159265358979 * urand(), c = cos(th), s = sin(th);
        double sc = pow(10.0, 12.0 * urand() - 6.0), d1 = sc * srand1();
        double d2 = n % 4 == 0 ? d1 : n % 4 == 1 ? 0.0 : n % 4 == 2 ? -d1 : 1e-12 * sc;
        double axx = c * c * d1 + s * s * d2, azz = s * s * d1 + c * c * d2;
        double axz = c * s * (d1 - d2);
        double p[3], p1 = fmax(d1, 0.0), p2 = fmax(d2, 0.0);
        double ex[3] = {c * c * p1 + s * s * p2, c * s * (p1 - p2), s * s * p1 + c * c * p2};
        sph_sym_pos2(axx, axz, azz, p);
        double nA = fmax(fabs(d1), fabs(d2));
        double e = fabs(p[0] - ex[0]) + fabs(p[1] - ex[1]) + fabs(p[2] - ex[2]);
        worst = fmax(worst, nA > 0.0 ? e / nA : e);
        worst = fmax(worst, pos2_vs_pos3(axx, axz, azz, &finite));
    }
    check(finite && worst < TOL, "pos2 rotated diag(d1,d2), d2 = d1, 0, -d1, ~0: exact, = pos3",
          worst, TOL);
}

/* ---------------------------------------------------------------- timing (informative) */

static double now_s(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

enum { NT = 1024, TRIALS = 20 };
static double tA[NT][9];
static volatile double sink; /* keeps the timed results alive */

/* ns per call of sph_sym_pos3 over the matrices in tA (best of TRIALS: the machine may be
 * shared). */
static double time_pos3(void)
{
    double best = 1e30, Ap[9];
    for (int trial = 0; trial < TRIALS; trial++) {
        double t0 = now_s(), acc = 0.0;
        for (int r = 0; r < 10; r++)
            for (int n = 0; n < NT; n++) {
                sph_sym_pos3(tA[n], Ap);
                acc += Ap[0] + Ap[5];
            }
        best = fmin(best, (now_s() - t0) * 1e9 / (10.0 * NT));
        sink += acc;
    }
    return best;
}

/* ns per call of sph_sym_pos2 on {tA[n][0], tA[n][1], tA[n][2]}. */
static double time_pos2(void)
{
    double best = 1e30, p[3];
    for (int trial = 0; trial < TRIALS; trial++) {
        double t0 = now_s(), acc = 0.0;
        for (int r = 0; r < 100; r++)
            for (int n = 0; n < NT; n++) {
                sph_sym_pos2(tA[n][0], tA[n][1], tA[n][2], p);
                acc += p[0] + p[1] + p[2];
            }
        best = fmin(best, (now_s() - t0) * 1e9 / (100.0 * NT));
        sink += acc;
    }
    return best;
}

static void timing(void)
{
    for (int n = 0; n < NT; n++)
        random_sym(tA[n]);
    printf("info pos3, random symmetric (mostly mixed signs): %.1f ns/call\n", time_pos3());
    printf("info pos2, random symmetric (mostly mixed signs): %.1f ns/call\n", time_pos2());
    for (int n = 0; n < NT; n++) { /* strain-like: uniaxial tension with Poisson contraction */
        double R[9], e = 1e-3 * (0.5 + urand()), d[3] = {e, -0.3 * e, -0.3 * e};
        random_rotation(R);
        compose(R, d, tA[n]);
    }
    printf("info pos3, rotated diag(e, -0.3e, -0.3e): %.1f ns/call\n", time_pos3());
    for (int n = 0; n < NT; n++) {
        double R[9], d[3] = {urand() + 1e-3, urand() + 1e-3, urand() + 1e-3};
        random_rotation(R);
        compose(R, d, tA[n]);
    }
    printf("info pos3, SPD (fast path after the eigenvalues): %.1f ns/call\n", time_pos3());
    printf("info (timings are informative only, never a pass/fail condition)\n");
}

int main(void)
{
    test_eig_random();
    test_eig_families();
    test_eig_special();
    test_pos3();
    test_pos2();
    timing();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
