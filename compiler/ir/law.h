/* law.h — material laws lowered to the scalar graph. */
#ifndef SPHC_LAW_H
#define SPHC_LAW_H

#include "model/model.h"
#include "scalar.h"

#define LAW_MAX_SLOTS 48   /* per-particle state values of one law (a tensor takes 9) */
#define LAW_MAX_STATES 16
#define LAW_MAX_RARE 8     /* conditions of `if` blocks without `else` kept (law_fast) */

/* A state variable of a law: slots offset .. offset+size-1 of the particle's state. */
typedef struct {
    const char *name;
    int offset, size;   /* size 1 (scalar) or 9 (tensor, row-major) */
} LawState;

typedef struct {
    int S[9];   /* second Piola–Kirchhoff stress, row-major 3×3 */
    int psi;    /* strain energy density */
    int has_tension;
    int Sp[9];  /* its tensile part S+ (eq. 17, 31), from the law's `tension` block (written,
                 * or derived from psi+) */
    int psip;   /* the tensile energy psi+ (eq. 11, 20) */
    int Sd[9];  /* degraded by the phase field s: S = s^2 S+ + S- (eq. 18) */
    int psid;   /* psi = s^2 psi+ + psi- (eq. 7) */
    LawState states[LAW_MAX_STATES];
    int nstates;
    int nslots;                  /* state values per particle */
    double init[LAW_MAX_SLOTS];  /* their initial values */
    int next[LAW_MAX_SLOTS];     /* their values at the end of the law (graph nodes) */
    int dissipation;             /* 1 + the slot of the dissipated energy density; 0: none */
    int temperature;             /* 1 + the slot of the temperature [K]; 0: none */
    int viscous_heat;            /* 1 + the slot the artificial viscosity's heat [J/m^3] is
                                  * added to (`viscousheat`); 0: none */
    int has_wavespeed;           /* the law gives the particle's wave speed now: */
    int wavespeed;               /* its node [m/s] (`wavespeed`) */
    double heat_capacity;        /* its specific heat [J/(kg K)] (NaN: symbolic parameters) */
    int rare[LAW_MAX_RARE];      /* the conditions of the law's `if` blocks without `else`
                                  * (not nested, not in the tension block): a return map's
                                  * `if f > 0 { ... }`, which most particles do not take */
    int nrare;
} LawRoots;

/* The law as if none of its rare `if` blocks (r->rare) were taken: fast gets r's results
 * rebuilt with those conditions put to 0 (folded: the blocks' work is gone), *flag a node
 * that is nonzero where one of them holds after all (evaluated along that path: where it is
 * 0, fast's results are r's).  Returns 0, or -1 when the law has no such block. */
int law_fast(SGraph *g, const LawRoots *r, LawRoots *fast, int *flag);

/* Evaluate `law` for a body b of dimension dim, with its parameter values and reference
 * density (b NULL: symbolic).  The `tension` block is evaluated only when tension is set
 * (bodies with fracture).  Returns 0, or -1 after reporting errors. */
int law_build(SGraph *g, const Model *m, const MaterialDef *law, const BodyModel *b, int dim,
              int tension, LawRoots *out);
/* Whether the law's results (S, psi, the state's end values, the tension block's) read the
 * graph input named input (LAW_INPUT_DT): its material function then takes it. */
int law_reads(const SGraph *g, const LawRoots *r, const char *input);

/* A law that writes its stress (or its tension block's S+) and its energy: both evaluated
 * in 3D with parameter values params at a few sample deformations, and a warning at the
 * `stress` statement where S differs from F^-1 dpsi/dF (S+ from psi+'s) by more than
 * round-off; a law with state is differentiated at its returned state.  Returns the number
 * of warnings (law_verify.c). */
int law_verify(const Model *m, const BodyModel *b);
/* An error, at the law's `energy` (or `stress`, or the tension block's) statement, when the
 * law g, r built for body b gives an energy, a stress or a state that is not finite at F = I
 * or at a small deformation near it (where every particle starts), with a note where the
 * first value that is not finite is computed.  Returns 0, or -1 after the error. */
int law_verify_finite(const BodyModel *b, const SGraph *g, const LawRoots *r);
/* A warning, at the body, when its law's small-strain shear or bulk modulus is not the
 * body's (the sound speed of eq. 59 follows the body's), an error when they are not finite;
 * returns the number of diagnostics. */
int law_verify_moduli(const Model *m, const BodyModel *b);
/* The wave speed law g, r gives (its `wavespeed`) at F = I, at its state's initial values:
 * where it exceeds the body's c0, the compression bound takes it from the first step on
 * (lower.c, lam2_rest); NaN for a law without one. */
double law_wavespeed_at_rest(const SGraph *g, const LawRoots *r);

/* Check a law's statements symbolically (its parameters unknown, in 3D, with its tension
 * block): the checker's test of every material law.  Returns 0, or -1 after reporting. */
int law_check(const Model *m, const MaterialDef *law);

/* The law's graph inputs, named as the parameters of the emitted material function:
 * F[k] (row-major), the phase field s of a degraded law, the state slots st[k]. */
#define LAW_INPUT_F "F"
#define LAW_INPUT_S "s"
#define LAW_INPUT_STATE "st"
/* The step of the law's update: the time since its last evaluation (a scalar argument). */
#define LAW_INPUT_DT "dt"
/* dF/dt (Fd[k], row-major): the corrected gradient of the velocity. */
#define LAW_INPUT_FDOT "Fd"
/* The variables of an energy given as psi(C) or psi(E), replaced by F's before emission. */
#define LAW_INPUT_C "C"
#define LAW_INPUT_E "E"

#endif
