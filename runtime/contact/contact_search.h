/* contact_search.h — candidate contact pairs in the current configuration.
 *
 * The particles of every body get one global index (body by body).  Candidates are the
 * pairs of particles of different bodies closer than their contact distance plus a skin;
 * they are found with a hashed cell list and kept until some particle has moved more than
 * a quarter of the skin since, so between two rebuilds every pair within half a skin of
 * contact is a candidate (no pair comes into contact unseen, and the closest pair's
 * closeness, contact_law.h, is exact). */
#ifndef SPHRT_CONTACT_SEARCH_H
#define SPHRT_CONTACT_SEARCH_H

typedef struct {
    int n, dim, nbodies;
    const int *body;       /* n: body of each particle */
    const double *dc;      /* nbodies^2: contact distance of a pair of bodies */
    double skin;
    double *x0;            /* n*dim positions at the last rebuild */
    int *start, *nb;       /* candidates of each particle (CSR over the global index, both
                              directions) */
    int *active, nactive;  /* the particles that have candidates */
    long builds;           /* rebuilds so far */
    int built;
} sph_csearch;

/* Brings the candidates up to date with positions x (n*dim): rebuilds when a particle has
 * moved more than skin/4 since the last rebuild.  Returns 1 when it rebuilt. */
int sph_csearch_update(sph_csearch *c, const double *x);
/* Whether candidates built are out of date once the farthest particle has moved sqrt(moved2)
 * since their rebuild: more than a quarter of the skin (the test of sph_csearch_update). */
static inline int sph_csearch_stale(const sph_csearch *c, double moved2)
{
    return moved2 > 0.0625 * c->skin * c->skin;
}
/* The candidates built at positions x0, as the last rebuild at x0 made them (a resumed run's,
 * from its checkpoint). */
void sph_csearch_build_at(sph_csearch *c, const double *x0);
void sph_csearch_free(sph_csearch *c);
/* Another set of n particles of bodies body[] (a run on many processes, whose partners from
 * other processes change): the next update builds the candidates anew. */
void sph_csearch_reset(sph_csearch *c, int n, const int *body);

#endif
