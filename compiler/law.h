/* law.h — material laws lowered to the scalar graph. */
#ifndef SPHC_LAW_H
#define SPHC_LAW_H

#include "model.h"
#include "scalar.h"

typedef struct {
    int S[9];   /* second Piola–Kirchhoff stress, row-major 3×3 */
    int psi;    /* strain energy density */
    int has_tension;
    int Sp[9];  /* its tensile part S+ (eq. 17, 31), from the law's `tension` block */
    int psip;   /* the tensile energy psi+ (eq. 11, 20) */
    int Sd[9];  /* degraded by the phase field s (input 9): S = s^2 S+ + S- (eq. 18) */
    int psid;   /* psi = s^2 psi+ + psi- (eq. 7) */
} LawRoots;

/* Evaluate `law` for a body of dimension dim with parameter values params (NULL:
 * symbolic).  The `tension` block is evaluated only when tension is set (bodies with
 * fracture).  Returns 0, or -1 after reporting errors. */
int law_build(SGraph *g, const Model *m, const MaterialDef *law, const double *params, int dim,
              int tension, LawRoots *out);

/* The graph input that holds the phase field s in a degraded law (F is inputs 0-8). */
#define LAW_INPUT_S 9

#endif
