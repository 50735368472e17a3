/* test_kernel.c — kernel normalisation, continuity, support and derivative checks. */
#include <math.h>
#include <stdio.h>
#include "core/kernel.h"
#include "unit_check.h"

static const char *kname(sph_kernel_kind k) { return k == SPH_CUBIC ? "cubic" : "wendland"; }

/* sum over a lattice of spacing dx of W dx^dim (lattice through the kernel centre). */
static double lattice_sum(sph_kernel_kind k, int dim, double h, double dx)
{
    int m = (int)ceil(2.0 * h / dx) + 1;
    double s = 0.0;
    for (int a = -m; a <= m; a++)
        for (int b = -m; b <= m; b++)
            for (int c = (dim == 3 ? -m : 0); c <= (dim == 3 ? m : 0); c++)
                s += sph_kernel_w(k, dim, dx * sqrt((double)(a * a + b * b + c * c)), h);
    return s * pow(dx, dim);
}

/* Normalisation on a fine lattice, also at an offset lattice-unrelated h. */
static void test_normalisation(sph_kernel_kind k, int dim)
{
    char what[100];
    double h = 1.3, dx = h / (dim == 2 ? 20.0 : 12.0);
    double s = lattice_sum(k, dim, h, dx);
    snprintf(what, sizeof what, "%s %dD: |sum W dx^%d - 1| (h/dx = %.0f)", kname(k), dim, dim,
             h / dx);
    check(fabs(s - 1.0) < 1e-3, what, fabs(s - 1.0), 1e-3);
    dx = h / sqrt((double)dim); /* the production spacing, h = sqrt(dim) dx */
    s = lattice_sum(k, dim, h, dx);
    snprintf(what, sizeof what, "%s %dD: |sum W dx^%d - 1| at h = sqrt(%d) dx (report)", kname(k),
             dim, dim, dim);
    check(fabs(s - 1.0) < 2e-2, what, fabs(s - 1.0), 2e-2);
}

/* Support: W(2h) = 0, dW(2h) = 0, W just inside 2h tiny; W > 0 inside. */
static void test_support(sph_kernel_kind k, int dim)
{
    char what[100];
    double h = 0.7, w2 = sph_kernel_w(k, dim, 2.0 * h, h);
    double d2 = sph_kernel_dwdr_over_r(k, dim, 2.0 * h, h);
    double w0 = sph_kernel_w(k, dim, 0.0, h);
    double wi = sph_kernel_w(k, dim, 2.0 * h * (1 - 1e-6), h);
    snprintf(what, sizeof what, "%s %dD: |W(2h)| + |dW(2h)| and W(2h-) / W(0)", kname(k), dim);
    check(w2 == 0.0 && d2 == 0.0 && wi / w0 < 1e-12 && wi > 0.0, what, wi / w0, 1e-12);
}

/* dW/dr from dwdr_over_r vs a central finite difference of W, over the whole support. */
static void test_derivative(sph_kernel_kind k, int dim)
{
    char what[100];
    double h = 0.9, e = 1e-6 * h, err = 0.0, scale = 0.0;
    for (int s = 1; s < 400; s++) {
        double r = 2.0 * h * s / 400.0;
        double fd = (sph_kernel_w(k, dim, r + e, h) - sph_kernel_w(k, dim, r - e, h)) / (2 * e);
        double an = sph_kernel_dwdr_over_r(k, dim, r, h) * r;
        err = fmax(err, fabs(fd - an));
        scale = fmax(scale, fabs(an));
    }
    snprintf(what, sizeof what, "%s %dD: max |dW/dr - FD| / max |dW/dr|", kname(k), dim);
    check(err / scale < 1e-6, what, err / scale, 1e-6);
    double d0 = sph_kernel_dwdr_over_r(k, dim, 0.0, h);
    double d1 = sph_kernel_dwdr_over_r(k, dim, 1e-8 * h, h);
    snprintf(what, sizeof what, "%s %dD: dW/dr/r at r=0 finite, = limit (rel. diff)", kname(k), dim);
    check(isfinite(d0) && d0 < 0.0 && fabs(d0 - d1) <= 1e-6 * fabs(d0), what,
          fabs(d0 - d1) / fabs(d0), 1e-6);
}

/* Cubic spline: W and dW/dr continuous at q = 1. */
static void test_cubic_q1(int dim)
{
    char what[100];
    double h = 1.1, e = 1e-10;
    double wl = sph_kernel_w(SPH_CUBIC, dim, h * (1 - e), h);
    double wr = sph_kernel_w(SPH_CUBIC, dim, h * (1 + e), h);
    double dl = sph_kernel_dwdr_over_r(SPH_CUBIC, dim, h * (1 - e), h);
    double dr = sph_kernel_dwdr_over_r(SPH_CUBIC, dim, h * (1 + e), h);
    snprintf(what, sizeof what, "cubic %dD: jump of W at q=1 (relative)", dim);
    check(fabs(wl - wr) < 1e-8 * wl, what, fabs(wl - wr) / wl, 1e-8);
    snprintf(what, sizeof what, "cubic %dD: jump of dW/dr at q=1 (relative)", dim);
    check(fabs(dl - dr) < 1e-8 * fabs(dl), what, fabs(dl - dr) / fabs(dl), 1e-8);
}

/* Known values: W(0) = aD for Wendland, aD for cubic. */
static void test_values(void)
{
    double h = 2.0, pi = 3.14159265358979323846;
    double e1 = fabs(sph_kernel_w(SPH_WENDLAND, 2, 0.0, h) - 7.0 / (4 * pi * h * h));
    double e2 = fabs(sph_kernel_w(SPH_WENDLAND, 3, 0.0, h) - 21.0 / (16 * pi * h * h * h));
    double e3 = fabs(sph_kernel_w(SPH_CUBIC, 2, 0.0, h) - 10.0 / (7 * pi * h * h));
    double e4 = fabs(sph_kernel_w(SPH_CUBIC, 3, 0.0, h) - 1.0 / (pi * h * h * h));
    double e5 = fabs(sph_kernel_w(SPH_CUBIC, 3, 1.5 * h, h) - 0.25 * 0.125 / (pi * h * h * h));
    double e = fmax(fmax(e1, e2), fmax(fmax(e3, e4), e5));
    check(e < 1e-15, "W(0) = aD (both kernels, 2D/3D), cubic W(1.5h)", e, 1e-15);
}

int main(void)
{
    for (int dim = 2; dim <= 3; dim++) {
        for (int k = 0; k < 2; k++) {
            test_normalisation((sph_kernel_kind)k, dim);
            test_support((sph_kernel_kind)k, dim);
            test_derivative((sph_kernel_kind)k, dim);
        }
        test_cubic_q1(dim);
    }
    test_values();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
