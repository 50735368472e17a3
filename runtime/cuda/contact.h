/* contact.h — contact between bodies on the device, for the CUDA target (included by the
 * model.cu of scenes with contact, through sph_cuda_contact.h).
 *
 * The pair law is the CPU's (contact/contact_law.h, one source).  The search differs:
 * instead of the CPU's candidate lists kept between rebuilds (contact/contact_search.c),
 * every step sorts all particles by the bucket of their cell on the device and looks for
 * partners in the 9 (2D) or 27 (3D) cells around each particle, cells as wide as the largest
 * contact distance; the sort is stable, so a bucket lists its particles by index and every sum has
 * a fixed order.  A step is then
 *   1. the current positions and velocities of all bodies into global arrays;
 *   2. each particle's bucket, the stable sort, the buckets' ranges;
 *   3. per particle, the sum of its contact forces over the particles of other bodies in
 *      reach (its own acceleration only: no two threads write the same particle), with the
 *      stored energy, dissipated power and largest omega^2 summed into c->sum;
 *   4. the contact accelerations added to each body's a.
 * sph_cuda_contact_to_host hands the sums to the host runtime (sph_contact_set), for the
 * time step and the energies.  On many processes (docs/mpi.md) the particles are this
 * process's own, then the partners other processes send for the step (sph_contact_partners,
 * through the host), and only the own particles' forces are summed. */
#ifndef SPHRT_CUDA_CONTACT_H
#define SPHRT_CUDA_CONTACT_H

#include <vector>

#include "target.h"
#include "check.h"
#include "device_clock.h"
#include "launch.h"
#include "loops.h"
#include "memory.h"
#include "contact/contact.h"
#include "contact/contact_law.h"
#include "contact/device.h"
#include "core/defs.h"
#include "par/par.h"
#include "scene/body.h"
#include "scene/pass_types.h"
#include "scene/sim.h"
#ifndef SPH_CUDA_EMULATE
#include <cub/device/device_radix_sort.cuh>
#else
#include <algorithm>
#endif

typedef struct {
    int n, dim, nbodies;
    int nown, cap;        /* the own particles (first), and the particles the arrays hold */
    int *base;            /* host, nbodies + 1: first global index of each body */
    int *hbody;           /* host, nown: body of each own particle (many processes) */
    int *body;            /* n: body of each global particle */
    double *mass;         /* nbodies: particle mass of each body */
    sph_pair_law *law;    /* nbodies^2 */
    double *x, *v, *acc;  /* n*dim: positions, velocities, contact accelerations */
    double cell;          /* cell side: the largest contact distance plus the skin */
    double level;         /* the closeness's level, half the skin (contact_law.h) */
    unsigned mask;        /* buckets - 1 (a power of two) */
    int bits;             /* log2 buckets: the sort's key bits */
    unsigned *key, *skey; /* n: bucket of each particle; sorted */
    int *idx, *order;     /* n: 0..n-1; the particles sorted by bucket */
    int *bstart, *bend;   /* buckets: range of each bucket in order */
    void *tmp;            /* the sort's scratch */
    size_t tmp_bytes;
    double *sum;          /* SPH_NCSUM (contact_law.h) */
    double w2ref;         /* the largest reference omega^2 of two bodies' law (contact.c) */
} sph_cuda_contact;

/* The cell of position x (D components; the third is 0 in 2D). */
SPH_HD static inline void sph_contact_cell(const double *x, int D, double cell, long long c[3])
{
    c[1] = c[2] = 0;
    for (int k = 0; k < D; k++)
        c[k] = sph_contact_cell_of(x[k], cell);
}

SPH_HD static inline unsigned sph_contact_bucket(const long long c[3], unsigned mask)
{
    unsigned long long h = (unsigned long long)c[0] * 73856093u ^
                           (unsigned long long)c[1] * 19349663u ^
                           (unsigned long long)c[2] * 83492791u;
    return (unsigned)((h ^ (h >> 29)) & mask);
}

/* Room for n particles in the arrays of the search (buckets: at least 2n, a power of two);
 * the own particles' bodies and indices are kept. */
static void sph_cuda_contact_reserve(sph_cuda_contact *c, int n)
{
    if (n <= c->cap)
        return;
    const int cap = c->cap ? n + n / 2 : n, D = c->dim;
    int *body = (int *)sph_dev_alloc((size_t)cap * sizeof(int));
    double *x = (double *)sph_dev_alloc((size_t)cap * D * sizeof(double));
    double *v = (double *)sph_dev_alloc((size_t)cap * D * sizeof(double));
    if (c->body) { /* (the own particles' bodies, and their positions of this step) */
        SPH_CUDA_CHECK(cudaMemcpy(body, c->body, (size_t)c->nown * sizeof(int),
                                  cudaMemcpyDeviceToDevice));
        SPH_CUDA_CHECK(cudaMemcpy(x, c->x, (size_t)c->nown * D * sizeof(double),
                                  cudaMemcpyDeviceToDevice));
        SPH_CUDA_CHECK(cudaMemcpy(v, c->v, (size_t)c->nown * D * sizeof(double),
                                  cudaMemcpyDeviceToDevice));
        for (void *p : {(void *)c->body, (void *)c->x, (void *)c->v, (void *)c->acc,
                        (void *)c->key, (void *)c->skey, (void *)c->idx, (void *)c->order,
                        (void *)c->bstart, c->tmp})
            if (p)
                SPH_CUDA_CHECK(cudaFree(p));
    }
    c->body = body, c->x = x, c->v = v;
    c->acc = (double *)sph_dev_alloc((size_t)cap * D * sizeof(double));
    size_t buckets = 1;
    c->bits = 0;
    while (buckets < 2 * (size_t)cap)
        buckets <<= 1, c->bits++;
    c->mask = (unsigned)(buckets - 1);
    c->key = (unsigned *)sph_dev_alloc((size_t)cap * sizeof(unsigned));
    c->skey = (unsigned *)sph_dev_alloc((size_t)cap * sizeof(unsigned));
    std::vector<int> idx((size_t)cap + 1);
    for (int g = 0; g < cap; g++)
        idx[g] = g;
    c->idx = (int *)sph_dev_copy(idx.data(), (size_t)cap * sizeof(int));
    c->order = (int *)sph_dev_alloc((size_t)cap * sizeof(int));
    c->bstart = (int *)sph_dev_alloc(2 * buckets * sizeof(int)); /* bend follows: one memset */
    c->bend = c->bstart + buckets;
    c->tmp = NULL, c->tmp_bytes = 0;
#ifndef SPH_CUDA_EMULATE
    SPH_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(NULL, c->tmp_bytes, c->key, c->skey, c->idx,
                                                   c->order, cap, 0, c->bits));
    c->tmp = sph_dev_alloc(c->tmp_bytes);
#endif
    c->cap = cap;
}

/* The device contact state of scene s: its pair laws, buckets and sums. */
static void sph_cuda_contact_init(sph_cuda_contact *c, sph_sim *s)
{
    const int nb = s->nbodies, D = s->m->dim;
    c->dim = D, c->nbodies = nb;
    c->base = (int *)calloc((size_t)nb + 1, sizeof(int));
    for (int i = 0; i < nb; i++)
        c->base[i + 1] = c->base[i] + s->bodies[i].nown;
    const int n = c->n = c->nown = c->base[nb];
    c->hbody = (int *)malloc(((size_t)n + 1) * sizeof(int));
    std::vector<double> mass((size_t)nb);
    for (int i = 0; i < nb; i++) {
        mass[i] = s->bodies[i].mass;
        for (int p = c->base[i]; p < c->base[i + 1]; p++)
            c->hbody[p] = i;
    }
    const sph_pair_law *law = sph_contact_laws(s);
    double dcmax = 0, dxmax = 0;
    c->w2ref = 0;
    for (int k = 0; k < nb * nb; k++) {
        dcmax = fmax(dcmax, law[k].dc);
        if (k / nb != k % nb) /* as sph_contact_dt */
            c->w2ref = fmax(c->w2ref, law[k].w2ref);
    }
    for (int i = 0; i < nb; i++)
        dxmax = fmax(dxmax, s->bodies[i].dx);
    /* Cells a skin wider than the largest contact distance, as the CPU's search's: every
     * pair within half a skin of contact is seen, so the closest pair's closeness is the
     * CPU's (contact.c) */
    const double skin = 0.5 * dxmax;
    c->cell = dcmax + skin;
    c->level = 0.5 * skin;
    c->mass = (double *)sph_dev_copy(mass.data(), (size_t)nb * sizeof(double));
    c->law = (sph_pair_law *)sph_dev_copy(law, (size_t)nb * nb * sizeof *law);
    c->cap = 0;
    c->body = NULL;
    sph_cuda_contact_reserve(c, n);
    SPH_CUDA_CHECK(cudaMemcpy(c->body, c->hbody, (size_t)n * sizeof(int), cudaMemcpyHostToDevice));
    double sum[SPH_NCSUM] = {0};
    sum[SPH_CSUM_CLOSE] = c->level; /* before the first step's pairs: as if touching */
    sum[SPH_CSUM_LEVEL] = c->level;
    c->sum = (double *)sph_dev_copy(sum, sizeof sum);
}

/* On many processes: the partners of this step from the other processes (through the host),
 * after the own particles; c->n becomes the own particles and the partners. */
static void sph_cuda_contact_partners(sph_cuda_contact *c, const sph_par *par)
{
    const int D = c->dim, nown = c->nown, rec = 1 + 2 * D;
    std::vector<double> x((size_t)nown * D + 1), v((size_t)nown * D + 1);
    SPH_CUDA_CHECK(cudaMemcpy(x.data(), c->x, (size_t)nown * D * sizeof(double),
                              cudaMemcpyDeviceToHost));
    SPH_CUDA_CHECK(cudaMemcpy(v.data(), c->v, (size_t)nown * D * sizeof(double),
                              cudaMemcpyDeviceToHost));
    double *in;
    const int total = sph_contact_partners(par, D, c->nbodies, nown, c->hbody, x.data(),
                                           v.data(), c->cell, &in);
    sph_cuda_contact_reserve(c, nown + total);
    std::vector<int> body((size_t)total + 1);
    std::vector<double> px((size_t)total * D + 1), pv((size_t)total * D + 1);
    for (int g = 0; g < total; g++) {
        const double *r = in + (size_t)g * rec;
        body[g] = (int)r[0];
        memcpy(&px[(size_t)g * D], r + 1, (size_t)D * sizeof(double));
        memcpy(&pv[(size_t)g * D], r + 1 + D, (size_t)D * sizeof(double));
    }
    free(in);
    SPH_CUDA_CHECK(cudaMemcpy(c->body + nown, body.data(), (size_t)total * sizeof(int),
                              cudaMemcpyHostToDevice));
    SPH_CUDA_CHECK(cudaMemcpy(c->x + (size_t)nown * D, px.data(),
                              (size_t)total * D * sizeof(double), cudaMemcpyHostToDevice));
    SPH_CUDA_CHECK(cudaMemcpy(c->v + (size_t)nown * D, pv.data(),
                              (size_t)total * D * sizeof(double), cudaMemcpyHostToDevice));
    c->n = nown + total;
}

/* Step 2: the particles sorted by bucket, and each bucket's range. */
static void sph_cuda_contact_sort(sph_cuda_contact *c)
{
    const int n = c->n, D = c->dim;
    const double *x = c->x, cell = c->cell;
    const unsigned mask = c->mask;
    unsigned *key = c->key, *skey = c->skey;
    int *order = c->order, *bstart = c->bstart, *bend = c->bend;
    SPH_FOR(g, n, {
        long long cg[3];
        sph_contact_cell(x + (size_t)g * D, D, cell, cg);
        key[g] = sph_contact_bucket(cg, mask);
    });
    sph_launch("the contact search's sort", [&] {
#ifndef SPH_CUDA_EMULATE
        SPH_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(c->tmp, c->tmp_bytes, key, skey, c->idx,
                                                       order, n, 0, c->bits));
#else
        for (int g = 0; g < n; g++)
            order[g] = g;
        std::stable_sort(order, order + n, [&](int a, int b) { return key[a] < key[b]; });
        for (int g = 0; g < n; g++)
            skey[g] = key[order[g]];
#endif
    });
    sph_launch("the contact search's buckets", [&] { /* bstart and bend */
        SPH_CUDA_CHECK(cudaMemset(bstart, 0, 2 * ((size_t)mask + 1) * sizeof(int)));
    });
    SPH_FOR(p, n, {
        const unsigned k = skey[p];
        if (p == 0 || skey[p - 1] != k)
            bstart[k] = p;
        if (p == n - 1 || skey[p + 1] != k)
            bend[k] = p + 1;
    });
}

/* Step 3: the contact acceleration of every particle (the pairs of contact_law.h). */
static void sph_cuda_contact_pairs(sph_cuda_contact *c, sph_time dt)
{
    const int D = c->dim, nb = c->nbodies;
    const double *x = c->x, *v = c->v, *mass = c->mass, cell = c->cell, level = c->level;
    const int *body = c->body, *order = c->order, *bstart = c->bstart, *bend = c->bend;
    const sph_pair_law *law = c->law;
    const unsigned mask = c->mask;
    double *acc = c->acc, *sum = c->sum;
    sph_cuda_zero(sum, SPH_CSUM_POWER + 1); /* stored, w2, close, power */
    SPH_FOR(g, c->nown, { /* (the partners' forces are their processes') */
        const int bg = body[g];
        const double *xg = x + (size_t)g * D;
        long long cg[3];
        sph_contact_cell(xg, D, cell, cg);
        double fi[3] = {0, 0, 0}, stored = 0, power = 0, w2 = 0, close = 0;
        const int span = D > 2; /* 2D: the third cell coordinate is always 0 */
        for (int o0 = -1; o0 <= 1; o0++)
            for (int o1 = -1; o1 <= 1; o1++)
                for (int o2 = -span; o2 <= span; o2++) {
                    const long long cj[3] = {cg[0] + o0, cg[1] + o1, cg[2] + o2};
                    const unsigned bk = sph_contact_bucket(cj, mask);
                    for (int p = bstart[bk]; p < bend[bk]; p++) {
                        const int j = order[p];
                        if (body[j] == bg)
                            continue;
                        long long ck[3];
                        sph_contact_cell(x + (size_t)j * D, D, cell, ck);
                        if (ck[0] != cj[0] || ck[1] != cj[1] || ck[2] != cj[2])
                            continue; /* another cell in the same bucket */
                        double f[3];
                        sph_contact_pair(&law[bg * nb + body[j]], D, xg, x + (size_t)j * D,
                                         v + (size_t)g * D, v + (size_t)j * D, dt, level, f,
                                         &stored, &power, &w2, &close);
                        for (int k = 0; k < D; k++)
                            fi[k] += f[k];
                    }
                }
        for (int k = 0; k < D; k++)
            acc[(size_t)g * D + k] = fi[k] / mass[bg];
        if (w2 > 0) { /* in contact: the few particles that touch add to the sums */
            atomicAdd(&sum[SPH_CSUM_STORED], stored);
            atomicAdd(&sum[SPH_CSUM_POWER], power);
            sph_atomic_max_pos(&sum[SPH_CSUM_W2], w2);
        }
        if (close > 0) /* near contact: the closest pair */
            sph_atomic_max_pos(&sum[SPH_CSUM_CLOSE], close);
    });
    SPH_ONCE({ sum[SPH_CSUM_DISSIPATED] += sum[SPH_CSUM_POWER] * dt; });
}

/* Contact between the bodies (device views dev[]) for a step of dt: adds to their a. */
static void sph_cuda_contact_forces(sph_cuda_contact *c, sph_body *const *dev, sph_time dt)
{
    const int D = c->dim;
    double *x = c->x, *v = c->v, *acc = c->acc;
    for (int i = 0; i < c->nbodies; i++) { /* step 1 */
        const sph_body *b = dev[i];
        const size_t base = (size_t)c->base[i] * D;
        SPH_FOR(p, b->nown, {
            for (int k = 0; k < D; k++) {
                x[base + (size_t)p * D + k] = b->X[(size_t)p * D + k] + b->u[(size_t)p * D + k];
                v[base + (size_t)p * D + k] = b->v[(size_t)p * D + k];
            }
        });
    }
    if (dev[0]->par && dev[0]->par->size > 1) {
        sph_cuda_contact_partners(c, dev[0]->par);
        x = c->x, v = c->v, acc = c->acc; /* (the arrays may have grown) */
    }
    sph_cuda_contact_sort(c);
    sph_cuda_contact_pairs(c, dt);
    for (int i = 0; i < c->nbodies; i++) { /* step 4 */
        const sph_body *b = dev[i];
        const size_t base = (size_t)c->base[i] * D;
        SPH_FOR(p, b->nown, {
            for (int k = 0; k < D; k++)
                b->a[(size_t)p * D + k] += acc[base + (size_t)p * D + k];
        });
    }
}

/* Where the device's clock finds the contact's sums of the step (SPH_CSUM_*: the largest
 * omega^2, the closest pair's closeness and its level). */
static const double *sph_cuda_contact_sums(const sph_cuda_contact *c)
{
    return c->sum;
}

/* The host runtime's contact sums onto the device (a run resumed from a checkpoint). */
static void sph_cuda_contact_from_host(sph_cuda_contact *c, const sph_sim *s)
{
    double sum[SPH_NCSUM] = {0};
    sph_contact_energies(s, &sum[SPH_CSUM_STORED], &sum[SPH_CSUM_DISSIPATED]);
    sum[SPH_CSUM_W2] = sph_contact_w2max(s);
    sum[SPH_CSUM_CLOSE] = sph_contact_close(s);
    sum[SPH_CSUM_LEVEL] = c->level;
    SPH_CUDA_CHECK(cudaMemcpy(c->sum, sum, sizeof sum, cudaMemcpyHostToDevice));
}

/* The device's contact sums into the host runtime (time step, energies). */
static void sph_cuda_contact_to_host(const sph_cuda_contact *c, sph_sim *s)
{
    double sum[SPH_NCSUM];
    SPH_CUDA_CHECK(cudaMemcpy(sum, c->sum, sizeof sum, cudaMemcpyDeviceToHost));
    sph_cuda_profile_collect(); /* (the host has waited) */
    if (s->par->size > 1) { /* the time step's: over all processes (energies: summed at outputs) */
        double most[2] = {sum[SPH_CSUM_W2], sum[SPH_CSUM_CLOSE]};
        s->par->max(most, 2);
        sum[SPH_CSUM_W2] = most[0], sum[SPH_CSUM_CLOSE] = most[1];
    }
    sph_contact_set(s, sum[SPH_CSUM_STORED], sum[SPH_CSUM_DISSIPATED], sum[SPH_CSUM_W2],
                    sum[SPH_CSUM_CLOSE]);
}

#endif
