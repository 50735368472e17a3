/* contact_law.h — the contact force of one particle pair (the law is described at the top of
 * contact.c), and the search's cell of a coordinate.  One source for both targets: contact.c
 * and contact_search.c call them on the CPU and cuda/contact.h on the device (SPH_HD:
 * __host__ __device__ under nvcc). */
#ifndef SPHRT_CONTACT_LAW_H
#define SPHRT_CONTACT_LAW_H

#include <math.h>

#include "core/defs.h"

/* The law of a pair of bodies. */
typedef struct {
    double dc;     /* contact distance */
    double k;      /* stiffness of F_e */
    double zeta;   /* damping ratio */
    double mu;     /* friction coefficient */
    double mstar;  /* reduced mass of a particle pair */
    double w2ref;  /* omega^2 at an overlap of 0.1 dc */
} sph_pair_law;

/* The cell coordinate of x on a grid of cells `cell` wide.  A coordinate that is not finite
 * or beyond 2^62 cells (a run going unstable, which the monitor stops at its next check) goes
 * to the last cell on its side instead of a conversion that C leaves undefined. */
SPH_HD static inline long long sph_contact_cell_of(double x, double cell)
{
    const double q = floor(x / cell), lim = 0x1p62;
    return q < lim ? (q > -lim ? (long long)q : -(long long)lim) : (long long)lim;
}

/* F_e ~ delta^hertz: 3/2 in 3D (Hertz), 1 in 2D (linear). */
SPH_HD static inline double sph_contact_hertz(int dim) { return dim == 3 ? 1.5 : 1.0; }

/* How close two particles of different bodies at distance r are: level less their gap
 * r - dc, 0 when the gap is level or more.  level is half the search's skin, within which
 * both targets see every pair (the CPU's candidates: contact_search.h; the device's cells). */
SPH_HD static inline double sph_contact_closeness(double r, double dc, double level)
{
    return fmax(0.0, level - (r - dc));
}

/* The force f on particle i (position xi, velocity vi) from particle j of another body, in
 * D dimensions; adds half the pair's stored energy to *stored and half its dissipated power
 * to *power (each pair is seen from both sides), raises *w2 to the pair's omega^2 and *close
 * to its closeness (for `level`).  The same arithmetic from both sides makes the two forces
 * exactly opposite. */
SPH_HD static inline void sph_contact_pair(const sph_pair_law *L, int D, const double *xi,
                                           const double *xj, const double *vi, const double *vj,
                                           double dt, double level, double f[3], double *stored,
                                           double *power, double *w2, double *close)
{
    double n[3] = {0, 0, 0}, dv[3] = {0, 0, 0}, r2 = 0;
    f[0] = f[1] = f[2] = 0;
    for (int k = 0; k < D; k++) {
        n[k] = xi[k] - xj[k];
        dv[k] = vi[k] - vj[k];
        r2 += n[k] * n[k];
    }
    const double r = sqrt(r2);
    *close = fmax(*close, sph_contact_closeness(r, L->dc, level));
    if (!(r2 < L->dc * L->dc) || r2 == 0)
        return;
    const double delta = L->dc - r;
    double vn = 0;
    for (int k = 0; k < D; k++) {
        n[k] /= r;
        vn += dv[k] * n[k];
    }
    const double root = D == 3 ? sqrt(delta) : 1.0;
    const double fe = L->k * delta * root, kt = sph_contact_hertz(D) * L->k * root;
    const double damp = 2 * L->zeta * sqrt(L->mstar * kt);
    const double fn = fmax(0.0, fe - damp * vn);
    double vt[3], vt2 = 0;
    for (int k = 0; k < D; k++) {
        vt[k] = dv[k] - vn * n[k];
        vt2 += vt[k] * vt[k];
    }
    const double vtn = sqrt(vt2), ft = vtn > 0 ? fmin(L->mu * fn, L->mstar * vtn / dt) : 0;
    for (int k = 0; k < D; k++)
        f[k] = fn * n[k] - (vtn > 0 ? ft * vt[k] / vtn : 0);
    *stored += 0.5 * L->k * delta * delta * root / (sph_contact_hertz(D) + 1);
    *power += 0.5 * ((fe - fn) * vn + ft * vtn); /* work of damping and friction */
    *w2 = fmax(*w2, kt / L->mstar);
}

/* The contact's sums of a step, in this order on the device (cuda/contact.h; the
 * first four are zeroed before each step's pairs): the stored energy, the largest omega^2 of
 * a pair in contact, the closeness of the closest pair (below), the dissipated power; then
 * the dissipated energy so far and the closeness's level (constants of the scene). */
enum {
    SPH_CSUM_STORED, SPH_CSUM_W2, SPH_CSUM_CLOSE, SPH_CSUM_POWER, SPH_CSUM_DISSIPATED,
    SPH_CSUM_LEVEL, SPH_NCSUM
};

/* Whether a pair is in contact (close >= level: a gap of 0 or less) or may touch before the
 * next step ends, counted from where the last step's pairs were measured: within the last
 * step dt_last and the next one, `step`, two particles close at most by twice the largest
 * speed and acceleration, times a margin of 2.  A reach beyond the level: near. */
SPH_HD static inline int sph_contact_near(double close, double level, double vmax2,
                                          double amax2, double dt_last, double step)
{
    const double t = dt_last + step;
    const double reach = 4 * (sqrt(vmax2) * t + sqrt(amax2) * t * t);
    return !(reach < level) || close >= level || level - close < reach;
}

/* The contact's bound on the step, 1/omega (before eq. 64's C_CFL): omega^2 of the pairs in
 * contact, and near contact at least the laws' reference w2ref (an overlap of 0.1 dc: a Hertz
 * contact that has just begun is soft, and stiffens within the step). */
SPH_HD static inline double sph_contact_bound(double w2, double w2ref, int near)
{
    const double w = near ? fmax(w2, w2ref) : w2;
    return w > 0 ? 1.0 / sqrt(w) : INFINITY;
}

#endif
