/* plan.h — the lowered kernel plan of each body: which features its code needs.
 * Computed once from the checked model (lower.c); the emitters only read it. */
#ifndef SPHC_PLAN_H
#define SPHC_PLAN_H

#include "ir/law.h"
#include "check/model.h"

typedef struct {
    int viscosity;      /* beta1 or beta2 nonzero */
    int beta2;          /* the quadratic term of eq. 58 */
    int hourglass;      /* hourglass control penalty */
    int gravity;        /* nonzero body force */
    int velocity_bcs;   /* any velocity BC */
    int force_bcs;      /* any force BC */
    int symplectic;
    int fracture;       /* phase-field fracture (eq. 6-9, 61-63) */
    int restrict_phase; /* a lower bound on its phase field */
    int crush;          /* the time step's bound on compression (timestep auto or stretch) */
    int measure;        /* measurement planes */
    int bc_fns;         /* BCs with a value function: those with an in-plane component */
    int nstate;         /* state values per particle of its law (plasticity); 0: none */
    SGraph law;         /* the material law, constants folded, for this body's dimension */
    LawRoots roots;
} BodyPlan;

/* Returns 0, or -1 after reporting. plans has m->nbodies entries. */
int lower_model(const Model *m, BodyPlan *plans);

#endif
