/* contact.h — contact between the particles of different bodies (contact.c): the CPU's
 * contact pass, the contact's bound on the time step and its energies, and its state for
 * checkpoints. */
#ifndef SPHRT_CONTACT_CONTACT_H
#define SPHRT_CONTACT_CONTACT_H

#include <stddef.h>

#include "core/defs.h"
#include "scene/sim.h"

SPH_C_BEGIN

/* Contact (m->contact set; contact.c).  The contact pass adds every body's contact
 * accelerations to its `a`, from the current positions X + u and velocities v; generated
 * steps call it after the bodies' force passes and before their updates.  dt is the step's
 * length (friction stops a pair's sliding at most within one step). */
void sph_contact_forces(sph_sim *s, double dt);
/* The contact's bound on the time step, sqrt(m_pair / k) of the stiffest contact (before eq. 64's
 * C_CFL), for a step of `step` (the bodies' own): the pairs in contact, and the laws'
 * reference stiffness while a pair is in contact or may touch before the step ends
 * (contact_law.h, sph_contact_near); INFINITY without contact or far from it. */
double sph_contact_dt(const sph_sim *s, double step);
/* The energy stored in the contacts now and the energy the contacts' damping and friction
 * have dissipated so far (both 0 without contact). */
void sph_contact_energies(const sph_sim *s, double *stored, double *dissipated);
/* The largest omega^2 of the contacts of the last contact pass (0 without contact). */
double sph_contact_w2max(const sph_sim *s);
/* Frees the contact state (sph_sim_free calls it). */
void sph_contact_free(sph_sim *s);

/* Particles of two bodies closer than their contact distance where the run starts (before
 * its first step; collective on many processes): a warning for each pair of bodies, and
 * their contacts' stored energy at the start in the contact's sums (energies.csv). */
void sph_contact_overlaps(sph_sim *s);
/* The contact state of a scene with contact (pair laws, search); idempotent. */
void sph_contact_init(sph_sim *s);
/* For checkpoints: 1 with the contact's sums (stored, dissipated, the largest
 * omega^2, the closest pair's closeness) and the positions its candidates were last built
 * at (*nx0 values, 0 before the first build); 0 in a scene without contact. */
int sph_contact_checkpoint(const sph_sim *s, double sums[4], const double **x0, size_t *nx0);
/* The contact as a checkpoint left it: its sums, and its candidates built again at x0 (nx0
 * values; 0: not built yet).  -1 after reporting when nx0 is not the scene's size. */
int sph_contact_restore(sph_sim *s, const double sums[4], const double *x0, size_t nx0);

SPH_C_END

#endif
