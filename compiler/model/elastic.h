/* elastic.h — a body's isotropic elastic constants completed from any accepted pair (both
 * front ends: the checker's material use and the XML importer's cards). */
#ifndef SPHC_ELASTIC_H
#define SPHC_ELASTIC_H

#include "model.h"

/* The constants given, from the named arguments of a material use. */
typedef struct {
    int has_E, has_nu, has_lambda, has_mu, has_K;
    double E, nu, lambda, mu, K;
} ElasticInput;

/* All five constants of b and its sound speed c0 (eq. 59) from a pair, each admissible:
 * 0, or -1 after reporting at loc. */
int elastic_complete(const ElasticInput *in, SrcLoc loc, BodyModel *b);
/* Lame's lambda and mu of a pair in dim dimensions: mu = E / (2 (1 + nu)),
 * lambda = E nu / ((1 + nu)(1 - (dim - 1) nu)) or K - 2 mu / dim.  dim 3 is the sph
 * language's reading; dim 2 that of 2D elasticity (SoliDualSPHysics' 2D cases). */
void elastic_lame(const ElasticInput *in, int dim, double *lambda, double *mu);
/* The reference sound speed, eq. 59: c0 = sqrt((K + 4 mu / 3) / rho0). */
double elastic_sound_speed(double K, double mu, double rho0);

#endif
