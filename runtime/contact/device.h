/* device.h — the CPU's contact for device targets, which compute contact themselves
 * (cuda/contact.h): the pair laws of a scene, the state the device computed handed back, and
 * on many processes the partners of other processes (contact.c, contact_partners.c). */
#ifndef SPHRT_CONTACT_DEVICE_H
#define SPHRT_CONTACT_DEVICE_H

#include "contact_law.h"
#include "core/defs.h"
#include "par/par.h"
#include "scene/sim.h"

/* The pair laws of scene s, nbodies x nbodies (made on the first call), and the state the device
 * computed, handed back for sph_contact_dt and sph_contact_energies. */
SPH_C_BEGIN
const sph_pair_law *sph_contact_laws(sph_sim *s);
void sph_contact_set(sph_sim *s, double stored, double dissipated, double w2max, double close);
/* The level of the contact's closeness (sph_contact_closeness): half the search's skin. */
double sph_contact_level(const sph_sim *s);
/* The closeness of the closest pair at the last step (the level before the first). */
double sph_contact_close(const sph_sim *s);
/* On many processes (contact_partners.c): the particles of other processes within `reach` of
 * the box of this process's n particles (bodies body[], positions x, velocities v; D values
 * each) of another body, as records of 1 + 2 D doubles (body, position, velocity) in
 * *partners (malloc'd; free it); returns how many.  Collective. */
int sph_contact_partners(const sph_par *par, int D, int nbodies, int n, const int *body,
                         const double *x, const double *v, double reach, double **partners);
SPH_C_END

#endif
