/* expect.c — evaluating a model's expectations from the recorded time series: period and
 * amplitude of a measured quantity, conservation of energy, and the error against a
 * reference solution (max and relative L2 over the output times). */
#include <math.h>
#include <stdio.h>

#include "expect.h"
#include "measure.h"
#include "table.h"
#include "io/json.h"
#include "scene/model.h"

static double column(const sph_series *s, int row, int col)
{
    return s->val[(size_t)row * (size_t)s->width + (size_t)col];
}

static void min_max(const sph_series *s, int q, double *lo, double *hi)
{
    *lo = INFINITY, *hi = -INFINITY;
    for (int i = 0; i < s->n; i++) {
        double v = column(s, i, q);
        *lo = fmin(*lo, v), *hi = fmax(*hi, v);
    }
}

/* Period from the crossings of the mid-line (max + min) / 2, linearly interpolated:
 * two crossings are half a period apart.  NAN when fewer than two crossings. */
static double period(const sph_series *s, int q)
{
    double lo, hi;
    min_max(s, q, &lo, &hi);
    const double mid = 0.5 * (lo + hi);
    double first = NAN, last = NAN;
    int crossings = 0;
    for (int i = 1; i < s->n; i++) {
        double a = column(s, i - 1, q) - mid, b = column(s, i, q) - mid;
        if ((a < 0 && b >= 0) || (a > 0 && b <= 0)) {
            double tc = s->t[i - 1] + (s->t[i] - s->t[i - 1]) * a / (a - b);
            if (crossings++ == 0)
                first = tc;
            last = tc;
        }
    }
    return crossings >= 2 ? 2.0 * (last - first) / (crossings - 1) : NAN;
}

int sph_expect_phase(const sph_series *s, int q, double *mid, double *amplitude, double *t0)
{
    double lo, hi;
    min_max(s, q, &lo, &hi);
    *mid = 0.5 * (lo + hi), *amplitude = 0.5 * (hi - lo), *t0 = NAN;
    for (int i = 1; i < s->n; i++) { /* (the first crossing, as period() finds it) */
        const double a = column(s, i - 1, q) - *mid, b = column(s, i, q) - *mid;
        if ((a < 0 && b >= 0) || (a > 0 && b <= 0)) {
            *t0 = s->t[i - 1] + (s->t[i] - s->t[i - 1]) * a / (a - b);
            return a < 0 ? 1 : -1;
        }
    }
    return 0;
}

static double energy_drift(const sph_series *e)
{
    if (e->n == 0)
        return NAN;
    const double e0 = column(e, 0, 0) + column(e, 0, 1);
    double worst = 0;
    for (int i = 0; i < e->n; i++)
        worst = fmax(worst, fabs(column(e, i, 0) + column(e, i, 1) - e0));
    return e0 > 0 ? worst / e0 : NAN;
}

double sph_table_interp(const double *t, const double *v, int n, double x)
{
    if (!(x >= t[0] && x <= t[n - 1]))
        return NAN;
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        *(t[mid] <= x ? &lo : &hi) = mid;
    }
    const double w = (x - t[lo]) / (t[hi] - t[lo]);
    return (1 - w) * v[lo] + w * v[hi];
}

/* Max and relative L2 error over the output times where the reference has a value (a
 * table covers only its own time range); NaN when it has none. */
static void reference_error(const sph_series *s, int q, double (*ref)(double), double *max_abs,
                            double *rel_l2)
{
    double num = 0, den = 0;
    int used = 0;
    *max_abs = 0;
    for (int i = 0; i < s->n; i++) {
        double r = ref(s->t[i]), d = column(s, i, q) - r;
        if (!isfinite(r))
            continue;
        *max_abs = fmax(*max_abs, fabs(d));
        num += d * d, den += r * r;
        used++;
    }
    if (!used)
        *max_abs = NAN;
    *rel_l2 = !used ? NAN : den > 0 ? sqrt(num / den) : sqrt(num);
}

static const char *const KIND[] = {"period", "amplitude", "energy", "reference"};

/* Why an expectation has no error (it is NaN), for its line: what the run did not record. */
static const char *no_error_reason(const sph_expect_desc *x)
{
    switch (x->kind) {
    case SPH_EXPECT_PERIOD:
        return "no period: the quantity crossed its mid-line fewer than twice in the outputs "
               "(run longer, or output more often)";
    case SPH_EXPECT_ENERGY:
        return "no energy drift: the initial energy is zero";
    case SPH_EXPECT_REFERENCE:
        return "no error: the reference has no finite value at any output time";
    default:
        return "no error: the quantity is not finite";
    }
}

int sph_expect_evaluate(const sph_model *m, const sph_record *r, sph_json *j, int quiet,
                        char *errors, size_t len, sph_report_expect *out)
{
    size_t used = 0;
    if (errors && len)
        errors[0] = 0;
    int failed = 0;
    sph_json_key_array(j, "expectations");
    for (int k = 0; k < m->nexpects; k++) {
        const sph_expect_desc *x = &m->expects[k];
        const sph_series *s = x->kind == SPH_EXPECT_ENERGY
                                  ? NULL
                                  : &r->measures[r->measure_base[x->body] + x->measure];
        double value = NAN, error = NAN, max_abs = NAN;
        if (x->kind == SPH_EXPECT_PERIOD) {
            value = period(s, x->quantity);
        } else if (x->kind == SPH_EXPECT_AMPLITUDE) {
            double lo, hi;
            min_max(s, x->quantity, &lo, &hi);
            value = 0.5 * (hi - lo);
        }
        if (x->kind == SPH_EXPECT_PERIOD || x->kind == SPH_EXPECT_AMPLITUDE)
            error = fabs(value - x->value) / fabs(x->value);
        else if (x->kind == SPH_EXPECT_ENERGY)
            error = value = energy_drift(&r->energy);
        else
            reference_error(s, x->quantity, x->reference, &max_abs, &error);
        int pass = x->tolerance < 0 || (isfinite(error) && error <= x->tolerance);
        failed += !pass;
        sph_json_key_object(j, NULL);
        sph_json_str(j, "kind", KIND[x->kind]);
        sph_json_str(j, "model", x->text);
        sph_json_num(j, "value", value);
        if (x->kind == SPH_EXPECT_PERIOD || x->kind == SPH_EXPECT_AMPLITUDE)
            sph_json_num(j, "expected", x->value);
        if (x->kind == SPH_EXPECT_REFERENCE)
            sph_json_num(j, "max_abs_error", max_abs);
        sph_json_num(j, "relative_error", error);
        if (x->tolerance >= 0)
            sph_json_num(j, "tolerance", x->tolerance);
        sph_json_bool(j, "pass", pass);
        sph_json_end_object(j);
        if (out)
            out[k] = (sph_report_expect){
                KIND[x->kind], x->text, value,
                x->kind == SPH_EXPECT_PERIOD || x->kind == SPH_EXPECT_AMPLITUDE ? x->value : NAN,
                max_abs, error, x->tolerance, pass};
        if (errors && used < len)
            used += (size_t)(isfinite(error)
                                 ? snprintf(errors + used, len - used, "%s%s %.3g %%",
                                            used ? ", " : "", KIND[x->kind], 100.0 * error)
                                 : snprintf(errors + used, len - used, "%s%s none",
                                            used ? ", " : "", KIND[x->kind]));
        if ((!quiet || !pass) && !isfinite(error))
            fprintf(pass ? stdout : stderr, "%s: %s%s\n", x->text, no_error_reason(x),
                    x->tolerance >= 0 ? " (FAILED)" : "");
        else if (!quiet || !pass)
            fprintf(pass ? stdout : stderr, "%s: relative error %.3g %%%s\n", x->text,
                    100.0 * error, x->tolerance >= 0 ? (pass ? " (ok)" : " (FAILED)") : "");
    }
    sph_json_end_array(j);
    return failed;
}
