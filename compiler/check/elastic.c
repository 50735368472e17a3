/* elastic.c — completing isotropic elastic constants from any accepted pair.
 *
 * Accepted pairs: young/poisson (E, nu), lambda/shear, bulk/shear (K, mu).  The bulk
 * modulus is the 3D one, K = lambda + 2 mu / 3, in plane strain too (plane strain is a
 * 3D state).  All five constants are derived and checked for physical admissibility. */
#include <math.h>

#include "check.h"
#include "util/diag.h"

static void from_E_nu(BodyModel *b, double E, double nu)
{
    b->E = E;
    b->nu = nu;
    b->mu = E / (2.0 * (1.0 + nu));
    b->lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    b->K = E / (3.0 * (1.0 - 2.0 * nu));
}

static void from_lambda_mu(BodyModel *b, double lambda, double mu)
{
    b->lambda = lambda;
    b->mu = mu;
    b->K = lambda + 2.0 * mu / 3.0;
    b->E = mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
    b->nu = lambda / (2.0 * (lambda + mu));
}

static int count_given(const ElasticInput *in)
{
    return in->has_E + in->has_nu + in->has_lambda + in->has_mu + in->has_K;
}

static int derive(const ElasticInput *in, SrcLoc loc, BodyModel *b)
{
    if (count_given(in) != 2) {
        diag_error(loc, "give exactly two elastic constants: young and poisson, lambda and "
                        "shear, or bulk and shear (%d given)",
                   count_given(in));
        return -1;
    }
    if (in->has_E && in->has_nu) {
        if (!(in->E > 0)) {
            diag_error(loc, "young's modulus must be positive (got %g)", in->E);
            return -1;
        }
        if (!(in->nu > -1.0 && in->nu < 0.5)) {
            diag_error(loc, "poisson's ratio must lie in (-1, 0.5) (got %g)", in->nu);
            return -1;
        }
        from_E_nu(b, in->E, in->nu);
        return 0;
    }
    if (in->has_mu && !(in->mu > 0)) {
        diag_error(loc, "shear modulus must be positive (got %g)", in->mu);
        return -1;
    }
    if (in->has_lambda && in->has_mu) {
        from_lambda_mu(b, in->lambda, in->mu);
        return 0;
    }
    if (in->has_K && in->has_mu) {
        if (!(in->K > 0)) {
            diag_error(loc, "bulk modulus must be positive (got %g)", in->K);
            return -1;
        }
        from_lambda_mu(b, in->K - 2.0 * in->mu / 3.0, in->mu);
        return 0;
    }
    diag_error(loc, "unsupported pair of elastic constants: give young and poisson, lambda "
                    "and shear, or bulk and shear");
    return -1;
}

int elastic_complete(const ElasticInput *in, SrcLoc loc, BodyModel *b)
{
    if (derive(in, loc, b))
        return -1;
    if (!(b->nu > -1.0 && b->nu < 0.5) || !(b->K > 0) || !(b->mu > 0)) {
        diag_error(loc, "elastic constants are not admissible (E = %g, nu = %g, K = %g, "
                        "mu = %g): need mu > 0, K > 0, -1 < nu < 0.5",
                   b->E, b->nu, b->K, b->mu);
        return -1;
    }
    /* Reference sound speed, eq. 59: c0 = sqrt((K + 4 mu / 3) / rho0). */
    b->c0 = sqrt((b->K + 4.0 * b->mu / 3.0) / b->rho0);
    return 0;
}
