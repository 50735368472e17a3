/* test_derivative.c — the scalar graph's symbolic derivatives (compiler/ir/derivative.c)
 * against central finite differences of the graph's own values at random points, for every
 * node kind the material laws build, and exact identities: d det F / dF = cof F,
 * d tr(pos(A)^2) / dA = 2 pos(A) (spectral.c, the adjoint of the eigen-split). */
#include <math.h>
#include <stdio.h>

#include "ir/scalar.h"
#include "ir/spectral.h"
#include "lang/builtins.h"
#include "unit_check.h"

static double point[9]; /* the inputs x[0..8] */

static double input(const char *name, int index, void *ctx)
{
    (void)name, (void)ctx;
    return point[index];
}

static double value_at(const SGraph *g, int y, const double *x, int nx)
{
    double v[8192];
    for (int k = 0; k < nx; k++)
        point[k] = x[k];
    sg_eval(g, y, input, NULL, NULL, v);
    return v[y];
}

/* The largest relative difference between dy/dx from the graph and central differences. */
static double fd_error(SGraph *g, int y, const int *x, int nx, const double *at)
{
    int d[9];
    if (sg_derivatives(g, y, x, nx, d))
        return INFINITY;
    int last = y;
    for (int k = 0; k < nx; k++)
        last = d[k] > last ? d[k] : last;
    double v[8192], err = 0;
    for (int k = 0; k < nx; k++)
        point[k] = at[k];
    sg_eval(g, last, input, NULL, NULL, v);
    for (int k = 0; k < nx; k++) {
        double xp[9], xm[9];
        const double h = 1e-5 * fmax(1.0, fabs(at[k]));
        for (int q = 0; q < nx; q++)
            xp[q] = xm[q] = at[q];
        xp[k] += h, xm[k] -= h;
        const double fd = (value_at(g, y, xp, nx) - value_at(g, y, xm, nx)) / (2 * h);
        err = fmax(err, fabs(v[d[k]] - fd) / fmax(1.0, fabs(fd)));
    }
    return err;
}

/* ---------------------------------------------------------------- pos and neg (eq. 13-16)
 *
 * A symmetric tensor of six inputs x[0..5] = a00, a01, a02, a11, a12, a22 (in 2D, plane
 * strain, three: axx, axz, azz), its positive part as law.c lowers it (an SN_EXT routine of
 * the upper triangle), neg(A) = A - pos(A), and scalars of them. */

typedef struct {
    int A[9], P[9], N[9]; /* A, pos(A), neg(A), row-major nodes */
} Split;

static Split split(SGraph *g, const int *x, int dim)
{
    static const int sym3[9] = {0, 1, 2, 1, 3, 4, 2, 4, 5};
    Split s;
    const int zero = sg_const(g, 0.0);
    if (dim == 3) {
        for (int k = 0; k < 9; k++)
            s.A[k] = x[sym3[k]];
        const int ext = sg_ext(g, SPECTRAL_POS3, s.A, 9, 9);
        for (int k = 0; k < 9; k++)
            s.P[k] = sg_part(g, ext, k);
    } else {
        for (int k = 0; k < 9; k++)
            s.A[k] = s.P[k] = zero;
        s.A[0] = x[0], s.A[2] = s.A[6] = x[1], s.A[8] = x[2];
        const int ext = sg_ext(g, SPECTRAL_POS2, x, 3, 3);
        s.P[0] = sg_part(g, ext, 0), s.P[2] = s.P[6] = sg_part(g, ext, 1);
        s.P[8] = sg_part(g, ext, 2);
    }
    for (int k = 0; k < 9; k++)
        s.N[k] = sg_binary(g, SN_SUB, s.A[k], s.P[k]);
    return s;
}

/* tr(X Y) */
static int trace_product(SGraph *g, const int *X, const int *Y)
{
    int acc = sg_const(g, 0.0);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            acc = sg_binary(g, SN_ADD, acc, sg_binary(g, SN_MUL, X[3 * i + k], Y[3 * k + i]));
    return acc;
}

/* A fixed tensor W, not symmetric (nor diagonal in any eigenbasis of A). */
static const double W[9] = {0.7, -1.3, 0.4, 2.1, -0.2, 0.9, -0.6, 1.7, 1.1};

/* W with the plane-strain structure (no y coupling), still not symmetric. */
static const double WP[9] = {0.7, 0, 0.4, 0, -0.2, 0, -0.6, 0, 1.1};

static int scalar_of_split(SGraph *g, const Split *s, int which)
{
    int w[9];
    switch (which) {
    case 4:                                        /* tr(WP pos(A)) */
    case 5:                                        /* tr(WP neg(A)) */
        for (int k = 0; k < 9; k++)
            w[k] = sg_const(g, WP[k]);
        return trace_product(g, w, which == 4 ? s->P : s->N);
    case 0: return trace_product(g, s->P, s->P);  /* tr(pos(A)^2) */
    case 1: return trace_product(g, s->N, s->N);  /* tr(neg(A)^2) */
    case 2:                                        /* tr(W pos(A)) */
        for (int k = 0; k < 9; k++)
            w[k] = sg_const(g, W[k]);
        return trace_product(g, w, s->P);
    default:                                       /* tr(W neg(A)) + tr(pos(A)^2) tr(A) */
        for (int k = 0; k < 9; k++)
            w[k] = sg_const(g, W[k]);
        return sg_binary(g, SN_ADD, trace_product(g, w, s->N),
                         sg_binary(g, SN_MUL, trace_product(g, s->P, s->P),
                                   sg_binary(g, SN_ADD, sg_binary(g, SN_ADD, s->A[0], s->A[4]),
                                             s->A[8])));
    }
}

/* A random rotation (a random unit quaternion). */
static void random_rotation(double R[9])
{
    double q[4], n = 0;
    for (int k = 0; k < 4; k++)
        q[k] = urand() - 0.5, n += q[k] * q[k];
    n = sqrt(n);
    const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                         2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    for (int k = 0; k < 9; k++)
        R[k] = r[k];
}

/* A random symmetric tensor with distinct eigenvalues, at least 0.1 apart and from zero,
 * of the signs given (signs[k] = +1 or -1), as the inputs of split (6 in 3D, 3 in 2D). */
static void random_symmetric(int dim, const int *signs, double *x)
{
    double l[3], R[9], A[9];
    for (int k = 0; k < dim; k++)
        for (int again = 1; again;) {
            l[k] = signs[k] * (0.1 + 1.4 * urand());
            again = 0;
            for (int j = 0; j < k; j++)
                again |= fabs(l[k] - l[j]) < 0.1;
        }
    if (dim == 2) { /* the x-z plane: a rotation by an angle */
        const double a = 6.283185307179586 * urand(), c = cos(a), s = sin(a);
        x[0] = c * c * l[0] + s * s * l[1];
        x[1] = c * s * (l[0] - l[1]);
        x[2] = s * s * l[0] + c * c * l[1];
        return;
    }
    random_rotation(R);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            A[3 * i + j] = 0;
            for (int k = 0; k < 3; k++)
                A[3 * i + j] += R[3 * i + k] * l[k] * R[3 * j + k];
        }
    const double u[6] = {A[0], A[1], A[2], A[4], A[5], A[8]};
    for (int k = 0; k < 6; k++)
        x[k] = u[k];
}

/* The worst central-difference error of scalar `which` of the split over 100 random tensors
 * whose eigenvalues have the signs of `pattern` (0: both signs, 1: all positive, 2: all
 * negative). */
static double split_fd_error(int dim, int which, int pattern)
{
    static const int signs[3][3] = {{1, -1, 1}, {1, 1, 1}, {-1, -1, -1}};
    int sg[3] = {signs[pattern][0], signs[pattern][1], signs[pattern][2]};
    double worst = 0;
    for (int trial = 0; trial < 100; trial++) {
        if (pattern == 0 && dim == 3 && trial % 2) /* two negative, one positive */
            sg[0] = -1, sg[2] = 1;
        else if (pattern == 0)
            sg[0] = 1, sg[2] = dim == 3 ? 1 : -1;
        if (pattern == 0 && dim == 2)
            sg[1] = -1;
        SGraph g;
        sg_init(&g);
        const int n = dim == 3 ? 6 : 3;
        int x[6];
        for (int k = 0; k < n; k++)
            x[k] = sg_input(&g, "x", k);
        Split s = split(&g, x, dim);
        const int y = scalar_of_split(&g, &s, which);
        double at[6];
        random_symmetric(dim, sg, at);
        worst = fmax(worst, fd_error(&g, y, x, n, at));
        sg_free(&g);
    }
    return worst;
}

/* max |d tr(P^2)/dA - 2 X| / max |X|, X = pos(A) (which 0) or neg(A) (which 1), over 100
 * random tensors of both signs: an off-diagonal input stands for two entries, 4 X_ij. */
static double split_identity_error(int dim, int which)
{
    double worst = 0;
    for (int trial = 0; trial < 100; trial++) {
        SGraph g;
        sg_init(&g);
        const int n = dim == 3 ? 6 : 3;
        int x[6], d[6];
        for (int k = 0; k < n; k++)
            x[k] = sg_input(&g, "x", k);
        Split s = split(&g, x, dim);
        const int y = scalar_of_split(&g, &s, which);
        if (sg_derivatives(&g, y, x, n, d)) {
            sg_free(&g);
            return INFINITY;
        }
        const int sg3[3] = {1, trial % 2 ? 1 : -1, -1};
        random_symmetric(dim, sg3, point);
        double v[8192];
        sg_eval(&g, g.n - 1, input, NULL, NULL, v);
        static const int entry3[6] = {0, 1, 2, 4, 5, 8}, entry2[3] = {0, 2, 8};
        const int *X = which ? s.N : s.P;
        double scale = 0, err = 0;
        for (int k = 0; k < n; k++) {
            const int e = dim == 3 ? entry3[k] : entry2[k];
            const double expect = (e % 4 ? 4 : 2) * v[X[e]];
            scale = fmax(scale, fabs(v[X[e]]));
            err = fmax(err, fabs(v[d[k]] - expect));
        }
        worst = fmax(worst, err / scale);
        sg_free(&g);
    }
    return worst;
}

/* The plane-strain constants (a01 = a11 = a12 = 0) put for inputs 1, 3, 4 of a 3D split. */
static int plane_input(const SNode *n, void *ctx)
{
    SGraph *g = ctx;
    const int k = (int)n->v;
    return k == 1 || k == 3 || k == 4 ? sg_const(g, 0.0) : -1;
}

/* The derivative of tr(WP pos(A)), tr(WP neg(A)), tr(W pos(A)) taken in 3D, then folded
 * for a plane-strain A (pos, and its adjoint where the output's adjoint has the plane
 * structure too, become the 2D closed forms as sg_part folds them), against the one taken in
 * 2D: max relative difference over 150 random tensors. */
static double plane_fold_error(void)
{
    double worst = 0;
    for (int trial = 0; trial < 150; trial++) {
        static const int scalars[3] = {4, 5, 2};
        const int which = scalars[trial % 3];
        SGraph g;
        sg_init(&g);
        int x[6], d3[6], d2[3], f3[6];
        for (int k = 0; k < 6; k++)
            x[k] = sg_input(&g, "x", k);
        Split s3 = split(&g, x, 3);
        if (sg_derivatives(&g, scalar_of_split(&g, &s3, which), x, 6, d3))
            worst = INFINITY;
        sg_substitute(&g, d3, 6, plane_input, &g, f3);
        int y[3] = {sg_input(&g, "y", 0), sg_input(&g, "y", 1), sg_input(&g, "y", 2)};
        Split s2 = split(&g, y, 2);
        if (sg_derivatives(&g, scalar_of_split(&g, &s2, which), y, 3, d2))
            worst = INFINITY;
        const int sg3[3] = {1, -1, 1};
        double at[3], v[8192];
        random_symmetric(2, sg3, at);
        const double x3[6] = {at[0], 0, at[1], 0, 0, at[2]};
        for (int k = 0; k < 6; k++) /* "x" and "y" read the same point: x[k], y[k] */
            point[k] = x3[k];
        sg_eval(&g, g.n - 1, input, NULL, NULL, v);
        const double three[3] = {v[f3[0]], v[f3[2]], v[f3[5]]};
        for (int k = 0; k < 3; k++)
            point[k] = at[k];
        sg_eval(&g, g.n - 1, input, NULL, NULL, v);
        for (int k = 0; k < 3; k++)
            worst = fmax(worst, fabs(three[k] - v[d2[k]]) / fmax(1.0, fabs(v[d2[k]])));
        sg_free(&g);
    }
    return worst;
}

static void spectral_checks(void)
{
    static const char *const what[] = {"tr(pos(A)^2)", "tr(neg(A)^2)", "tr(W pos(A))",
                                       "tr(W neg(A)) + tr(pos(A)^2) tr(A)"};
    static const char *const signs[] = {"both signs", "positive", "negative"};
    for (int dim = 3; dim >= 2; dim--)
        for (int which = 0; which < 4; which++)
            for (int pattern = 0; pattern < 3; pattern++) {
                char name[128];
                snprintf(name, sizeof name, "%dD d %s / dA vs central differences, %s", dim,
                         what[which], signs[pattern]);
                const double e = split_fd_error(dim, which, pattern);
                check(e < 1e-7, name, e, 1e-7);
            }
    for (int dim = 3; dim >= 2; dim--) {
        char name[96];
        double e = split_identity_error(dim, 0);
        snprintf(name, sizeof name, "%dD d tr(pos(A)^2) / dA = 2 pos(A) (relative)", dim);
        check(e < 1e-13, name, e, 1e-13);
        e = split_identity_error(dim, 1);
        snprintf(name, sizeof name, "%dD d tr(neg(A)^2) / dA = 2 neg(A) (relative)", dim);
        check(e < 1e-13, name, e, 1e-13);
    }
    const double e = plane_fold_error();
    check(e < 1e-13, "3D derivative folded for plane strain = the 2D one", e, 1e-13);
    /* no second derivative: an adjoint routine has no rule, nor a routine sphc does not know */
    SGraph g;
    sg_init(&g);
    int x[6], d[6];
    for (int k = 0; k < 6; k++)
        x[k] = sg_input(&g, "x", k);
    Split s = split(&g, x, 3);
    const int y = trace_product(&g, s.P, s.P);
    sg_derivatives(&g, y, x, 6, d);
    check(sg_derivatives(&g, d[1], x, 6, d) == -1, "a second derivative of pos is refused", 0, 0);
    const int other = sg_ext(&g, "sph_unknown", x, 6, 2);
    int d1[1];
    check(sg_derivatives(&g, sg_part(&g, other, 1), x, 1, d1) == -1,
          "a routine without a rule is refused", 0, 0);
    sg_free(&g);
}

typedef int (*Build)(SGraph *g, int a, int b);

static int b_add(SGraph *g, int a, int b) { return sg_binary(g, SN_ADD, a, b); }
static int b_sub(SGraph *g, int a, int b) { return sg_binary(g, SN_SUB, a, b); }
static int b_mul(SGraph *g, int a, int b) { return sg_binary(g, SN_MUL, a, b); }
static int b_div(SGraph *g, int a, int b) { return sg_binary(g, SN_DIV, a, b); }
static int b_neg(SGraph *g, int a, int b) { return sg_binary(g, SN_MUL, sg_unary(g, SN_NEG, a), b); }
static int b_pow(SGraph *g, int a, int b) { return sg_binary(g, SN_POW, a, b); }
static int b_powc(SGraph *g, int a, int b) { return sg_binary(g, SN_MUL, sg_binary(g, SN_POW, a, sg_const(g, -2.0 / 3)), b); }
static int b_min(SGraph *g, int a, int b) { return sg_binary(g, SN_MIN, a, b); }
static int b_max(SGraph *g, int a, int b) { return sg_binary(g, SN_MAX, a, b); }
static int b_sel(SGraph *g, int a, int b)
{
    return sg_select(g, sg_binary(g, SN_LT, a, b), sg_binary(g, SN_MUL, a, a), sg_binary(g, SN_MUL, a, b));
}

/* The folding of factors as the graph is built: x + x is 2 x, and k (c x) is (k c) x where k
 * or c is a power of two; each gives the unfolded arithmetic's number to the last bit, here
 * at random x and factors c (the unfolded value computed in C, operation by operation). */
static void factor_checks(void)
{
    int folded = 1, wrong = 0;
    for (int trial = 0; trial < 1000; trial++) {
        SGraph g;
        sg_init(&g);
        const int x = sg_input(&g, "x", 0);
        const double c = 1e-3 + 1e4 * urand(), xv = 2 * urand() - 1;
        const int cx = sg_binary(&g, SN_MUL, sg_const(&g, c), x);
        const int twice = sg_binary(&g, SN_ADD, cx, cx);           /* 2 (c x) */
        const int y = sg_binary(&g, SN_MUL, sg_const(&g, 0.5), twice); /* 0.5 (2 (c x)) */
        const int z = sg_binary(&g, SN_MUL, sg_const(&g, 0.25), sg_binary(&g, SN_MUL,
                                sg_const(&g, c), sg_binary(&g, SN_ADD, x, x)));
        folded &= y == cx && g.nodes[twice].op == SN_MUL;
        const double cxv = c * xv;
        wrong += value_at(&g, twice, &xv, 1) != cxv + cxv;
        wrong += value_at(&g, y, &xv, 1) != 0.5 * (cxv + cxv);
        wrong += value_at(&g, z, &xv, 1) != 0.25 * (c * (xv + xv));
        sg_free(&g);
    }
    check(folded, "0.5 (c x + c x) folds to the node c x; x + x to a product", 0, 0);
    check(wrong == 0, "folded factors give the unfolded numbers to the last bit (1000 x)",
          wrong, 0);
}

int main(void)
{
    factor_checks();
    static const struct { const char *name; Build build; } ops[] = {
        {"a + b", b_add}, {"a - b", b_sub}, {"a b", b_mul}, {"a / b", b_div},
        {"(-a) b", b_neg}, {"a ^ b", b_pow}, {"a ^ (-2/3) b", b_powc}, {"min(a, b)", b_min},
        {"max(a, b)", b_max}, {"if(a < b, a a, a b)", b_sel},
    };
    for (size_t k = 0; k < sizeof ops / sizeof ops[0]; k++) {
        double worst = 0;
        for (int trial = 0; trial < 50; trial++) {
            SGraph g;
            sg_init(&g);
            int x[2] = {sg_input(&g, "x", 0), sg_input(&g, "x", 1)};
            int y = ops[k].build(&g, x[0], x[1]);
            double at[2] = {0.2 + 2 * urand(), 0.2 + 2 * urand()};
            if (fabs(at[0] - at[1]) < 1e-3) /* not at a kink of min, max, if */
                at[1] += 0.01;
            worst = fmax(worst, fd_error(&g, y, x, 2, at));
            sg_free(&g);
        }
        char what[96];
        snprintf(what, sizeof what, "d/da, d/db of %s vs central differences", ops[k].name);
        check(worst < 1e-7, what, worst, 1e-7);
    }
    for (int f = 0; f < NBUILTIN_FUNCTIONS; f++) {
        if (BUILTIN_FUNCTION[f].form != BF_CALL)
            continue;
        double worst = 0;
        for (int trial = 0; trial < 50; trial++) {
            SGraph g;
            sg_init(&g);
            int x[1] = {sg_input(&g, "x", 0)};
            int y = sg_call(&g, f, sg_binary(&g, SN_MUL, x[0], x[0])); /* f(x^2): the chain */
            /* x^2 < 1.21: away from tan's pole; asin's and acos's below 0.72, inside their
             * domain and away from its ends */
            const int inside = f == BI_asin || f == BI_acos;
            double at[1] = {0.3 + (inside ? 0.55 : 0.8) * urand()};
            worst = fmax(worst, fd_error(&g, y, x, 1, at));
            sg_free(&g);
        }
        char what[96];
        snprintf(what, sizeof what, "d %s(x^2) / dx vs central differences",
                 BUILTIN_FUNCTION[f].name);
        check(worst < 1e-7, what, worst, 1e-7);
    }
    /* d det F / dF = cof F exactly: det by cofactors of the first row, nine inputs */
    SGraph g;
    sg_init(&g);
    int F[9], cof[9], d[9];
    for (int k = 0; k < 9; k++)
        F[k] = sg_input(&g, "F", k);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r * 3 + c] = sg_binary(&g, SN_SUB, sg_binary(&g, SN_MUL, F[r1 * 3 + c1], F[r2 * 3 + c2]),
                                       sg_binary(&g, SN_MUL, F[r1 * 3 + c2], F[r2 * 3 + c1]));
        }
    int det = sg_const(&g, 0);
    for (int c = 0; c < 3; c++)
        det = sg_binary(&g, SN_ADD, det, sg_binary(&g, SN_MUL, F[c], cof[c]));
    sg_derivatives(&g, det, F, 9, d);
    double worst = 0, v[8192];
    for (int trial = 0; trial < 20; trial++) {
        for (int k = 0; k < 9; k++)
            point[k] = (k % 4 == 0) + 0.3 * (urand() - 0.5);
        sg_eval(&g, g.n - 1, input, NULL, NULL, v);
        for (int k = 0; k < 9; k++)
            worst = fmax(worst, fabs(v[d[k]] - v[cof[k]]));
    }
    check(worst == 0 || worst < 1e-15, "d det F / dF = cof F", worst, 1e-15);
    sg_free(&g);
    spectral_checks();
    printf("%s\n", failures ? "FAILED" : "all checks passed");
    return failures ? 1 : 0;
}
