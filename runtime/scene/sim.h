/* sim.h — a simulation: the scene's bodies, its clock and the processes it runs on
 * (sph_sim; run/sim.h steps it). */
#ifndef SPHRT_SCENE_SIM_H
#define SPHRT_SCENE_SIM_H

#include "body.h"
#include "model.h"

typedef struct sph_contact sph_contact;
typedef struct sph_par sph_par;

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
};

#endif
