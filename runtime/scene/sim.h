/* sim.h — a simulation: the scene's bodies, its clock and the processes it runs on
 * (sph_sim; run/sim.h steps it). */
#ifndef SPHRT_SCENE_SIM_H
#define SPHRT_SCENE_SIM_H

#include "body.h"
#include "model.h"

typedef struct sph_contact sph_contact;
typedef struct sph_par sph_par;

/* What set a time step (run/time_step.h, sph_dt_bound_of): a body's eq. 65 on the sound
 * speed and its speed (the CFL bound), eq. 66 on its acceleration, eq. 65 under the factor
 * of its compression (timestep auto), the stiffest contact, the scene's fixed step.  The
 * names, in this order, are SPH_DT_BOUND_NAMES. */
typedef enum {
    SPH_DT_SPEED, SPH_DT_ACCELERATION, SPH_DT_COMPRESSION, SPH_DT_CONTACT, SPH_DT_FIXED,
    SPH_DT_NBOUNDS
} sph_dt_bound;
#define SPH_DT_BOUND_NAMES {"speed", "acceleration", "compression", "contact", "fixed"}

struct sph_sim {
    const sph_model *m;
    sph_body *bodies;
    int nbodies;
    double t, dt;
    double dt_prev;        /* the step before the one being taken (0 before the first) */
    long step;
    int threads;
    sph_contact *contact;  /* contact state (contact.c); NULL until the first contact pass */
    double dt_factor;      /* the smallest factor on eq. 65 of any body at the last
                              sph_sim_stable_dt (timestep auto or stretch; 1 otherwise) */
    const sph_par *par;    /* the processes of the run (sph_par_one unless under MPI) */
    /* what set the time step of the last sph_sim_stable_dt: the bound, and the body whose
     * bound it was (-1: the contact or the fixed step) */
    sph_dt_bound dt_bound;
    int dt_body;
    /* the steps sph_sim_advance took, by the bound that set each, and by the body whose
     * bound it was (nbodies; a device target's clock counts its own, cuda/advance.h) */
    long dt_bound_steps[SPH_DT_NBOUNDS];
    long *dt_body_steps;
};

#endif
