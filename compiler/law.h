/* law.h — material laws lowered to the scalar graph. */
#ifndef SPHC_LAW_H
#define SPHC_LAW_H

#include "model.h"
#include "scalar.h"

typedef struct {
    int S[9];   /* second Piola–Kirchhoff stress, row-major 3×3 */
    int psi;    /* strain energy density */
} LawRoots;

/* Evaluate `law` for a body of dimension dim with parameter values params (NULL:
 * symbolic).  Returns 0, or -1 after reporting errors. */
int law_build(SGraph *g, const Model *m, const MaterialDef *law, const double *params, int dim,
              LawRoots *out);

#endif
