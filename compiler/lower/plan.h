/* plan.h — the third stage's product: the lowered kernel plan of each body, which features
 * its code needs and its material law as a folded scalar graph.  Computed once from the
 * checked model (lower.c); the emitters only read it. */
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

/* The plan of a whole scene. */
typedef struct {
    const Model *model;
    BodyPlan *bodies;   /* model->nbodies plans */
    int nbodies;
    int contact;        /* contact between the bodies (model_has_contact) */
    int fracture;       /* some body has phase-field fracture */
} Plan;

/* Returns 0, or -1 after reporting (and freeing what it built). */
int lower_model(const Model *m, Plan *plan);
void plan_free(Plan *plan);

/* Print the plan (sphc --dump=plan): each body's features and its law's graph. */
void plan_dump(const Plan *plan, FILE *out);

#endif
