/* elastic.c — completing isotropic elastic constants from any accepted pair.
 *
 * Accepted pairs: young/poisson (E, nu), lambda/shear, bulk/shear (K, mu).  The bulk
 * modulus is the 3D one, K = lambda + 2 mu / 3, in plane strain too (plane strain is a
 * 3D state).  All five constants are derived and checked for physical admissibility
 * (admissible.h). */
#include <math.h>

#include "admissible.h"
#include "elastic.h"
#include "util/diag.h"

void elastic_lame(const ElasticInput *in, int dim, double *lambda, double *mu)
{
    if (in->has_E && in->has_nu) {
        *mu = in->E / (2.0 * (1.0 + in->nu));
        *lambda = in->E * in->nu / ((1.0 + in->nu) * (1.0 - (dim - 1) * in->nu));
        return;
    }
    *mu = in->mu;
    *lambda = in->has_K ? in->K - 2.0 * in->mu / dim : in->lambda;
}

double elastic_sound_speed(double K, double mu, double rho0)
{
    return sqrt((K + 4.0 * mu / 3.0) / rho0);
}

/* E, nu and K from lambda and mu (the pair E, nu keeps its own values). */
static void from_lame(const ElasticInput *in, BodyModel *b)
{
    const double lambda = b->lambda, mu = b->mu;
    if (in->has_E && in->has_nu) {
        b->E = in->E;
        b->nu = in->nu;
        b->K = in->E / (3.0 * (1.0 - 2.0 * in->nu));
        return;
    }
    b->K = lambda + 2.0 * mu / 3.0;
    b->E = mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
    b->nu = lambda / (2.0 * (lambda + mu));
}

static int count_given(const ElasticInput *in)
{
    return in->has_E + in->has_nu + in->has_lambda + in->has_mu + in->has_K;
}

/* The given constants: a pair, each admissible. */
static int given(const ElasticInput *in, SrcLoc loc)
{
    if (count_given(in) != 2) {
        diag_error(loc, "give exactly two elastic constants: young and poisson, lambda and "
                        "shear, or bulk and shear (%d given)",
                   count_given(in));
        return -1;
    }
    if (in->has_E && in->has_nu)
        return check_admissible(loc, "young's modulus", Q_YOUNG, in->E) ||
               check_admissible(loc, "poisson's ratio", Q_POISSON, in->nu) ? -1 : 0;
    if (in->has_mu && check_admissible(loc, "shear modulus", Q_SHEAR, in->mu))
        return -1;
    if (in->has_lambda && in->has_mu)
        return 0;
    if (in->has_K && in->has_mu)
        return check_admissible(loc, "bulk modulus", Q_BULK, in->K);
    diag_error(loc, "unsupported pair of elastic constants: give young and poisson, lambda "
                    "and shear, or bulk and shear");
    return -1;
}

int elastic_complete(const ElasticInput *in, SrcLoc loc, BodyModel *b)
{
    if (given(in, loc))
        return -1;
    elastic_lame(in, 3, &b->lambda, &b->mu);
    from_lame(in, b);
    if (inadmissible(Q_POISSON, b->nu) || inadmissible(Q_BULK, b->K) ||
        inadmissible(Q_SHEAR, b->mu)) {
        diag_error(loc, "elastic constants are not admissible (E = %g, nu = %g, K = %g, "
                        "mu = %g): need mu > 0, K > 0, -1 < nu < 0.5",
                   b->E, b->nu, b->K, b->mu);
        return -1;
    }
    b->c0 = elastic_sound_speed(b->K, b->mu, b->rho0);
    return 0;
}
