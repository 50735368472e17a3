/* fracture.c — measured quantities of phase-field fracture: the fracture energy of a body,
 *
 *   E_f = sum_i V_i Gc ((1 - s_i)^2 / (4 eps0) + eps0 |grad s|_i^2),
 *
 * the crack-surface functional of the phase-field model (section 2.2); for a straight crack
 * it tends to Gc times the crack length (2D, per unit thickness) or area (3D).  |grad s|^2
 * is taken in the form that matches the SPH Laplacian of eq. 62, lap_i = sum_j c_ij (s_i -
 * s_j):  |grad s|_i^2 = -1/2 sum_j c_ij (s_i - s_j)^2, since sum_i V |grad s|^2 = -sum_i V
 * s_i lap_i for that operator.  The phase field's discrete steady state then minimises this
 * discrete energy exactly, and the steep gradient next to a crack is not smoothed away as
 * a kernel-averaged gradient would do.  Called at output times only. */
#include <stdlib.h>

#include "measure.h"
#include "par/par.h"
#include "scene/body.h"
#include "scene/body_desc.h"

double sph_fracture_energy(const sph_body *b)
{
    const sph_fracture_desc *f = b->desc->fracture;
    if (!f || !b->s)
        return 0.0;
    double *g2 = calloc((size_t)b->n, sizeof(double));
    if (!g2)
        return 0.0;
    if (b->xb_start) { /* on many processes: the halo's phase field as the last step left it */
        const sph_field field = SPH_FIELD(b->s, 1);
        b->par->post((sph_body *)b, &field, 1);
        b->par->wait((sph_body *)b, &field, 1);
    }
    for (int i = 0; i < b->nown; i++) /* each pair once; ltab holds c_ij (< 0) */
        for (int p = b->hb_start[i]; p < b->hb_start[i + 1]; p++) {
            const int j = b->hb[p];
            const double d = b->s[i] - b->s[j], e = -0.5 * b->ltab[b->hb_k[p]] * d * d;
            g2[i] += e;
            g2[j] += e;
        }
    for (int i = 0; b->xb_start && i < b->nown; i++) /* pairs with the halo: i's share */
        for (int p = b->xb_start[i]; p < b->xb_start[i + 1]; p++) {
            const double d = b->s[i] - b->s[b->xb[p]];
            g2[i] += -0.5 * b->ltab[b->xb_k[p]] * d * d;
        }
    double sum = 0;
    for (int i = 0; i < b->nown; i++) {
        const double d = 1.0 - b->s[i];
        sum += d * d / (4 * f->eps0) + f->eps0 * g2[i];
    }
    free(g2);
    return f->Gc * b->vol * sum;
}
