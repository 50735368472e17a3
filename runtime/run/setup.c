/* setup.c — building a body: particles from its region, neighbour lists and corrected
 * kernel gradients in the reference configuration (total Lagrangian: done once), the
 * particle selections of its boundary conditions and measurements, and its arrays. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "setup.h"
#include "core/alloc.h"
#include "core/exit_codes.h"
#include "core/kernel.h"
#include "core/message.h"
#include "core/profile.h"
#include "geom/fill.h"
#include "geom/select.h"
#include "pairs/gradients.h"
#include "pairs/neighbours.h"
#include "pairs/notch.h"
#include "pairs/offset_blocks.h"
#include "pairs/quadratic.h"
#include "pairs/stencil.h"
#include "run/clamp.h"
#include "run/particle_order.h"
#include "par/par.h"
#include "scene/body.h"
#include "scene/body_desc.h"
#include "scene/model.h"
#include "scene/pass_types.h"
#include "scene/point.h"
#include "scene/step_sums.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static void *zalloc(size_t n, size_t size)
{
    return sph_alloc_setup(n * size, 1); /* (huge pages for large arrays: core/alloc.c) */
}

/* zalloc on a cache line: the pair passes read A, Q, Cv and wtab a short vector at a time
 * (templates/body_forces.c), which then never straddles two lines. */
static void *zalloc_lines(size_t n, size_t size)
{
    const size_t line = 64, bytes = ((n ? n * size : 1) + line - 1) / line * line;
    void *p = aligned_alloc(line, bytes);
    if (!p) {
        sph_error("out of memory");
        exit(SPH_EXIT_SETUP);
    }
    return memset(p, 0, bytes);
}

int sph_fast_law_off;

static void allocate(sph_body *b)
{
    size_t n = (size_t)b->n, D = (size_t)b->dim;
    b->u = zalloc(n * D, sizeof(double));
    b->v = zalloc(n * D, sizeof(double));
    b->a = zalloc(n * D, sizeof(double));
    b->work = zalloc(n * D, sizeof(double));
    b->F = zalloc(n * 9, sizeof(double));
    for (size_t i = 0; i < n; i++)
        b->F[9 * i] = b->F[9 * i + 4] = b->F[9 * i + 8] = 1.0;
    b->want_F = 1;
    b->Q = zalloc_lines(n * SPH_TENSOR_SIZE(D), sizeof *b->Q);
    b->A = zalloc_lines(n * SPH_TENSOR_SIZE(D), sizeof *b->A);
    b->Cv = zalloc_lines(n * SPH_TENSOR_SIZE(D), sizeof *b->Cv);
    b->Cs = zalloc(n, sizeof *b->Cs);
    if (b->desc->fdot) {
        b->Ad = zalloc_lines(n * SPH_TENSOR_SIZE(D), sizeof *b->Ad);
        b->Fd = zalloc(n * 9, sizeof(double));
    }
    if (b->desc->quadratic) {
        b->Aq = zalloc_lines(n * D * SPH_QR(D), sizeof *b->Aq);
        b->Qq = zalloc_lines(n * SPH_QN(D) * SPH_ROW(D), sizeof *b->Qq);
    }
    b->psi = zalloc(n, sizeof(double));
    if (b->desc->vheat) /* (each momentum pass writes it whole) */
        b->vq = zalloc(n, sizeof(double));
    b->sigma = zalloc(n * 6, sizeof(double));
    b->fix = zalloc(n, 1);
    /* a law whose wave speed at rest exceeds c0 bounds the first step as the later ones */
    const double rest = b->desc->lam2_rest > 0 ? b->desc->lam2_rest : 1.0;
    double sums[SPH_STEP_NSUMS]; /* (the step sums before the first step) */
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        sums[k] = k == SPH_STEP_SUM_lam2min ? rest : sph_step_sum_initial(k);
    sph_step_sums_set(b, sums);
    if (b->desc->crush) {
        b->lam2 = zalloc(n, sizeof(double));
        for (size_t i = 0; i < n; i++)
            b->lam2[i] = rest;
    }
    const int ns = b->desc->nstate;
    if (ns > 0) {
        b->state = zalloc(n * (size_t)ns, sizeof(double));
        b->rare_hint = zalloc(n, 1);
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < ns; k++)
                b->state[i * (size_t)ns + (size_t)k] = b->desc->state_init[k];
    }
    if (!b->desc->fracture)
        return;
    b->s = zalloc(n, sizeof(double));
    for (size_t i = 0; i < n; i++)
        b->s[i] = 1.0; /* intact */
    b->sd = zalloc(n, sizeof(double));
    b->sdd = zalloc(n, sizeof(double));
    b->H = zalloc(n, sizeof(double));
    b->lap = zalloc(n, sizeof(double));
    b->sd_n = zalloc(n, sizeof(double));
}

/* Pairs at exactly the support radius have a zero kernel gradient and contribute nothing to
 * any pass; removing them saves a sixth of the pair work on a lattice (24 -> 20 in 2D).
 * Pairs whose gradient is below 1e-14 of the kernel's largest go too: they lie at the
 * support radius up to the rounding of their distance (the gradient there is of the order
 * of that rounding squared or cubed), less than a pair sum's rounding, and whether the
 * search kept such a pair depended on that rounding, particle by particle, so that the
 * particles of one lattice had different neighbour lists (no lattice stencil, stencil.c).
 * In single precision the bound is 1e-30 of the largest: in float the gradient underflows,
 * and the viscosity factor of eq. 60 (about 1/|w|) would overflow.  The gradients are
 * recomputed (sph_pair_gradient) rather than kept from sph_gradients: 24 bytes a pair in
 * 3D, most of the set-up's memory. */
static int silent_pair(const sph_body *b, int i, int p, sph_kernel_kind kernel, double tiny)
{
    double w[3];
    int silent = 1;
    sph_pair_gradient(b->X, b->dim, i, b->nb[p], kernel, b->h, b->vol, w);
    for (int c = 0; c < b->dim; c++)
        silent &= fabs(w[c]) <= tiny;
    return silent;
}

static void drop_silent_pairs(sph_body *b, sph_kernel_kind kernel)
{
    const int D = b->dim, n = b->nown; /* (the rows of own particles) */
    /* the kernel's largest V |dW/dr| over its support, sampled finely: a bound on any pair's
     * gradient, the same on every process, without a pass over the pairs (which took as
     * long as the one below) */
    double wmax = 0;
    for (int k = 1; k <= 1000; k++) {
        const double r = 2.0 * b->h * k / 1000;
        wmax = fmax(wmax, fabs(sph_kernel_dwdr_over_r(kernel, D, r, b->h) * r));
    }
    const double tiny = (sizeof(sph_real) < sizeof(double) ? 1e-30 : 1e-14) * b->vol * wmax;
    int *start = zalloc((size_t)n + 1, sizeof(int));
#pragma omp parallel for schedule(dynamic, 1024)
    for (int i = 0; i < n; i++) { /* the pairs each particle keeps (silent ones marked -1) */
        int c = 0;
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++)
            if (silent_pair(b, i, p, kernel, tiny))
                b->nb[p] = -1;
            else
                c++;
        start[i + 1] = c;
    }
    for (int i = 0; i < n; i++)
        start[i + 1] += start[i];
    int *nb = zalloc((size_t)start[n] + 1, sizeof(int));
#pragma omp parallel for schedule(dynamic, 1024)
    for (int i = 0; i < n; i++) {
        int q = start[i];
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++)
            if (b->nb[p] >= 0)
                nb[q++] = b->nb[p];
    }
    free(b->nb_start), free(b->nb);
    b->nb_start = start, b->nb = nb;
    b->npairs = start[n];
}

#define KEY_BASE 121 /* offsets of up to 60 spacings a component */

/* The integer lattice offset X_i - X_j of pair p = (i, nb[p]) in spacings, component k in
 * off[k]; 0 when it is not a whole number of spacings (to 1e-6 dx) or too long. */
static int pair_offset(const sph_body *b, int i, int p, long *off)
{
    for (int k = 0; k < b->dim; k++) {
        const double dX = b->X[(size_t)i * b->dim + k] - b->X[(size_t)b->nb[p] * b->dim + k];
        const double q = dX / b->dx, r = nearbyint(q);
        if (fabs(q - r) > 1e-6 || fabs(r) > KEY_BASE / 2)
            return 0;
        off[k] = (long)r;
    }
    return 1;
}

/* Lattice offsets packed as keys: components in [-60, 60] in base KEY_BASE as the pairs are
 * scanned, then re-packed in base 2 reach + 1 once the longest component, reach, is known,
 * so that the keys number some hundreds. */
static long repack_key(long key, int dim, long reach)
{
    long digit[3], out = 0;
    for (int k = dim - 1; k >= 0; k--, key /= KEY_BASE)
        digit[k] = key % KEY_BASE - KEY_BASE / 2;
    for (int k = 0; k < dim; k++)
        out = out * (2 * reach + 1) + digit[k] + reach;
    return out;
}

/* Table entry k from pair p = (i, nb[p]). */
static void table_entry(sph_body *b, int k, int i, long p, sph_kernel_kind kernel)
{
    const int D = b->dim;
    double dX[3], w[3], r2 = 0;
    for (int c = 0; c < D; c++) {
        dX[c] = b->X[(size_t)i * D + c] - b->X[(size_t)b->nb[p] * D + c];
        r2 += dX[c] * dX[c];
    }
    const double f = sph_pair_w(kernel, D, b->h, b->vol, dX, w); /* (core/kernel.h) */
    for (int c = 0; c < D; c++)
        b->wtab[(size_t)k * SPH_ROW(D) + c] = (sph_real)w[c];
    b->gtab[k] = (sph_real)sph_viscosity_factor(D, b->h, dX, w); /* eq. 60 */
    b->htab[k] = (sph_real)(b->vol * sph_kernel_w(kernel, D, sqrt(r2), b->h) / (b->rho0 * r2));
    if (b->ltab) /* eq. 62: 2 V_j (r0 . grad W) / r0^2 = 2 V dW/dr / r */
        b->ltab[k] = (sph_real)(2 * f);
    if (b->qtab) { /* the pair weight's monomials (pairs/quadratic.h; even in dX) */
        double q[SPH_QN3];
        sph_quad_monomials(D, dX, q);
        for (int c = 0; c < SPH_QN(D); c++)
            b->qtab[(size_t)k * SPH_QR(D) + c] = (sph_real)(-f * q[c]);
    }
}

/* The number of particles a selection holds on all processes. */
static double selected(const sph_body *b, int count)
{
    double n = count;
    b->par->sum(&n, 1);
    return n;
}

/* The quadratic gradient's moments (pairs/quadratic.h): M_i^{-1} per particle, which takes the
 * linear correction's place, L = I (the stress pass's F = I + A L then reads the fit's
 * gradient from A: templates/body_quadratic.c).  Particles with too few neighbours for a
 * quadratic fit keep their L inside M_i^{-1}; the set-up says how many. */
static void quadratic_moments(sph_body *b, sph_kernel_kind kernel)
{
    const int D = b->dim;
    const int nlinear = sph_quadratic_moments(b->X, b->nown, D, b->nb_start, b->nb, kernel, b->h,
                                              b->vol, b->L, &b->Mq);
    for (int i = 0; i < b->nown; i++)
        for (int k = 0; k < D * D; k++)
            b->L[(size_t)i * D * D + k] = k % (D + 1) == 0 ? 1.0 : 0.0;
    const double count[2] = {selected(b, nlinear), selected(b, b->nown)}; /* (all processes) */
    if (count[0] > 0 && b->par->rank == 0)
        sph_note("body '%s': %.0f of %.0f particles have too few neighbours for the quadratic "
                 "gradient and keep the linear one", b->desc->name, count[0], count[1]);
}

/* Per-pair tables (see sphrt.h): one entry per distinct lattice offset, or one per pair
 * when the particles are not on one lattice.  Whether they are, and the longest offset, are
 * found in parallel; the entries are numbered in pair order (so the tables do not depend on
 * the thread count), through a table of all offsets up to the longest (a few hundred; one
 * of every offset a key could have, 8 MB to fill, took most of a small body's set-up), and
 * on a lattice each is computed once, from the first pair that has it. */
static void offset_tables(sph_body *b, sph_kernel_kind kernel)
{
    const int D = b->dim;
    const long np = b->npairs;
    b->nb_k = zalloc((size_t)np, sizeof(int));
    /* on a lattice, the largest offset component sizes the keys' range: some hundreds */
    long reach = 0;
    int lattice = 1;
#pragma omp parallel for schedule(dynamic, 1024) reduction(max : reach) reduction(&& : lattice)
    for (int i = 0; i < b->nown; i++)
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++) {
            long off[3], key = 0;
            if (!pair_offset(b, i, p, off)) {
                lattice = 0;
                continue;
            }
            for (int k = 0; k < D; k++) {
                reach = labs(off[k]) > reach ? labs(off[k]) : reach;
                key = key * KEY_BASE + off[k] + KEY_BASE / 2;
            }
            b->nb_k[p] = (int)key; /* below 121^3 */
        }
    int ntab = 0, *slot = NULL, *first_i = NULL;
    long *first_p = NULL;
    if (lattice) {
        long nslots = 1;
        for (int k = 0; k < D; k++)
            nslots *= 2 * reach + 1;
        slot = malloc(sizeof(int) * (size_t)nslots);
        first_i = malloc(sizeof(int) * (size_t)nslots);
        first_p = malloc(sizeof(long) * (size_t)nslots);
        for (long s = 0; s < nslots; s++)
            slot[s] = -1;
#pragma omp parallel for schedule(dynamic, 1024)
        for (int i = 0; i < b->nown; i++)
            for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++)
                b->nb_k[p] = (int)repack_key(b->nb_k[p], D, reach);
        for (int i = 0; i < b->nown; i++) /* numbered in pair order */
            for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++) {
                int *k = &slot[b->nb_k[p]];
                if (*k < 0)
                    first_i[ntab] = i, first_p[ntab] = p, *k = ntab++;
                b->nb_k[p] = *k;
            }
    } else
        ntab = (int)np;
    b->ntab = ntab;
    b->wtab = zalloc_lines((size_t)ntab * SPH_ROW(D), sizeof *b->wtab);
    b->gtab = zalloc((size_t)ntab, sizeof *b->gtab);
    b->htab = zalloc((size_t)ntab, sizeof *b->htab);
    if (b->desc->fracture)
        b->ltab = zalloc((size_t)ntab, sizeof *b->ltab);
    if (b->desc->quadratic)
        b->qtab = zalloc_lines((size_t)ntab * SPH_QR(D), sizeof *b->qtab);
    if (lattice) {
        for (int k = 0; k < ntab; k++)
            table_entry(b, k, first_i[k], first_p[k], kernel);
        free(slot), free(first_i), free(first_p);
        return;
    }
#pragma omp parallel for schedule(dynamic, 1024)
    for (int i = 0; i < b->nown; i++)
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++) {
            b->nb_k[p] = p;
            table_entry(b, p, i, p, kernel);
        }
}

/* Half lists (j > i) and the stripes of consecutive particles they are processed in
 * (see scene/body.h). */
static void half_lists(sph_body *b)
{
    const int n = b->nown; /* pairs of own particles; with a halo, those with it apart */
    b->hb_start = zalloc((size_t)n + 1, sizeof(int));
    if (b->nown < b->n)
        b->xb_start = zalloc((size_t)n + 1, sizeof(int));
    int reach = 1;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) { /* counts, then their running sum */
        int c = 0, x = 0;
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++) {
            c += b->nb[p] > i && b->nb[p] < n;
            x += b->nb[p] >= n;
        }
        b->hb_start[i + 1] = c;
        if (b->xb_start)
            b->xb_start[i + 1] = x;
    }
    for (int i = 0; i < n; i++) {
        b->hb_start[i + 1] += b->hb_start[i];
        if (b->xb_start)
            b->xb_start[i + 1] += b->xb_start[i];
    }
    const size_t q = (size_t)b->hb_start[n];
    b->hb = zalloc(q, sizeof(int));
    b->hb_k = zalloc(q, sizeof(int));
    if (b->xb_start) {
        b->xb = zalloc((size_t)b->xb_start[n] + 1, sizeof(int));
        b->xb_k = zalloc((size_t)b->xb_start[n] + 1, sizeof(int));
    }
#pragma omp parallel for schedule(static) reduction(max : reach)
    for (int i = 0; i < n; i++) {
        int at = b->hb_start[i], xat = b->xb_start ? b->xb_start[i] : 0;
        for (int p = b->nb_start[i]; p < b->nb_start[i + 1]; p++)
            if (b->nb[p] >= n) {
                b->xb[xat] = b->nb[p];
                b->xb_k[xat++] = b->nb_k[p];
            } else if (b->nb[p] > i) {
                b->hb[at] = b->nb[p];
                b->hb_k[at++] = b->nb_k[p];
                reach = b->nb[p] - i > reach ? b->nb[p] - i : reach;
            }
    }
    /* The passes use only the half lists; the full ones are not kept. */
    free(b->nb_start), free(b->nb), free(b->nb_k);
    b->nb_start = b->nb = b->nb_k = NULL;
    /* Stripes in C colours (stripe s's colour: s mod C), each at least reach / (C - 1)
     * particles long: a pair of stripe s then touches stripes s .. s + C - 1 only, and the
     * stripes of a colour never share a particle.  Two colours where that gives 4 stripes
     * or more; else more colours, for a body whose reach is over a quarter of it (the
     * Taylor bar, its particles along its axis fastest: particle_order.c), up to 8; else one
     * stripe, run serially.  A multiple of 2C stripes (of 4C from 4C on), so that each
     * colour's split evenly among 2 threads (and 4), which a pass of few stripes feels: with
     * 27 stripes, one of two threads idled through a seventh of the odd colour.  The counts
     * depend on the body alone, never on the threads: the order of the sums, and so their
     * bits, are the same on any number of threads. */
    int ns = 1, nc = 1;
    for (int c = 2; c <= 8 && ns == 1; c++) {
        const int most = n / ((reach + c - 2) / (c - 1));
        if (most >= 2 * c)
            ns = most < 4 * c ? 2 * c : most / (4 * c) * (4 * c), nc = c;
    }
    b->ncolours = nc;
    b->nstripes = ns;
    b->stripe = zalloc((size_t)ns + 1, sizeof(int));
    b->stripe_sum = zalloc((size_t)ns, sizeof(double));
    for (int s = 0; s <= ns; s++)
        b->stripe[s] = (int)((long)n * s / ns);
}

/* Whether value (a BC's or a restrict's expression) gives a value, rather than skip, at any
 * of n particles (list, or all when list is NULL) at five times from 0 to t_end.  A selection
 * that holds nothing (a window narrower than the spacing: 0.4 mm wide at dx = 1 mm) would
 * otherwise do nothing silently.  The displacement is zero here, so a selection by
 * displacement counts as empty until it moves; the callers only warn. */
static int selects_any(const sph_body *b, int (*value)(const struct sph_pt *, double *),
                       const int *list, int n, double t_end)
{
    double any = 0; /* (on many processes: on any of them) */
    for (int q = 0; q <= 4 && !any; q++)
        for (int c = 0; c < n && !any; c++) {
            sph_pt p;
            double val;
            sph_point(b, list ? list[c] : c, b->dim, 0.25 * q * t_end, 0, &p);
            any = value(&p, &val);
        }
    b->par->max(&any, 1);
    return any > 0;
}

/* A boundary condition whose time window opens at or after the run's end never acts (a step
 * acts when its middle lies in the window, and the last one's middle is before the end):
 * reported, like one that selects no particle.  1 when so. */
static int window_after_end(const sph_body *b, const sph_bc_desc *bc, double t_end)
{
    if (!(bc->t0 >= t_end))
        return 0;
    if (b->par->rank == 0)
        fprintf(stderr, "%s: warning: %s of body '%s' never acts: its window opens at t = %g s, "
                        "at or after the run's end time %g s (the model's `end`, or --end)\n",
                bc->where, bc->what, b->desc->name, bc->t0, t_end);
    return 1;
}

static void selections(sph_body *b, const sph_body_desc *d, double t_end)
{
    b->bc_list = zalloc((size_t)d->nbcs, sizeof(int *));
    b->bc_count = zalloc((size_t)d->nbcs, sizeof(int));
    for (int k = 0; k < d->nbcs; k++) {
        const sph_bc_desc *bc = &d->bcs[k];
        const int never = window_after_end(b, bc, t_end);
        if (bc->has_near) {
            b->bc_count[k] = sph_select_near(b->X, b->nown, b->dim, b->y_plane, b->dx,
                                             &bc->near, &b->bc_list[k]);
            if (selected(b, b->bc_count[k]) == 0) {
                if (b->par->rank == 0 && !never)
                    fprintf(stderr, "%s: warning: %s of body '%s' acts on no particle: none lies "
                                "within dx = %g m of its `near` shape\n",
                        bc->where, bc->what, d->name, b->dx);
                continue;
            }
        }
        if (bc->value && !never &&
            !selects_any(b, bc->value, bc->has_near ? b->bc_list[k] : NULL,
                         bc->has_near ? b->bc_count[k] : b->nown, t_end) &&
            b->par->rank == 0)
            fprintf(stderr, "%s: warning: %s of body '%s' acts on no particle: its expression "
                            "skips every particle%s at t = 0, T/4, T/2, 3T/4 and T (the end "
                            "time); is the selection narrower than the spacing dx = %g m?\n",
                    bc->where, bc->what, d->name, bc->has_near ? " near its shape" : "", b->dx);
    }
    b->ms_list = zalloc((size_t)d->nmeasures, sizeof(int *));
    b->ms_count = zalloc((size_t)d->nmeasures, sizeof(int));
    for (int k = 0; k < d->nmeasures; k++) {
        b->ms_count[k] = sph_select_plane(b->X, b->nown, b->dim, b->dx, d->measures[k].p,
                                          &b->ms_list[k]);
        if (selected(b, b->ms_count[k]) == 0 && b->par->rank == 0)
            sph_warning("measurement '%s' of body '%s' selects no particle",
                        d->measures[k].name, d->name);
    }
}

/* Cuts the pairs across the body's notches; a notch that cuts no pair (outside the body, or
 * along a plane of particles that no pair crosses) is reported. */
static void cut_notches(sph_body *b, const sph_fracture_desc *f)
{
    int *cuts = zalloc((size_t)f->nnotches, sizeof(int));
    b->npairs = sph_drop_notch_pairs(b->X, b->nown, b->dim, b->y_plane, b->nb_start, b->nb,
                                     (const double(*)[4][3])f->notches, f->nnotches, cuts);
    for (int k = 0; k < f->nnotches; k++)
        if (selected(b, cuts[k]) == 0 && b->par->rank == 0)
            fprintf(stderr, "%s: warning: the notch of body '%s' cuts no pair of particles: no "
                            "pair of neighbours crosses it (does it lie outside the body?)\n",
                    f->notch_where ? f->notch_where[k] : "sph", b->desc->name);
    free(cuts);
}

/* A `restrict` that bounds no particle at t = 0, T/4, T/2, 3T/4 and T is reported, like a
 * boundary condition that acts on none. */
static void check_restrict(const sph_body *b, const sph_fracture_desc *f, double t_end)
{
    if (!f->restrict_value || selects_any(b, f->restrict_value, NULL, b->nown, t_end) ||
        b->par->rank != 0)
        return;
    fprintf(stderr, "%s: warning: the restrict of body '%s' bounds no particle: its expression "
                    "skips every particle at t = 0, T/4, T/2, 3T/4 and T (the end time); is the "
                    "selection narrower than the spacing dx = %g m?\n",
            f->restrict_where, b->desc->name, b->dx);
}

/* The memory a run may use, in bytes (0 when unknown): the machine's, or the process's
 * address-space limit (ulimit -v) when that is smaller; *what names which. */
static double memory_limit(const char **what)
{
    const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    double mem = pages > 0 && size > 0 ? (double)pages * (double)size : 0.0;
    struct rlimit lim;
    *what = "this machine's";
    if (getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY &&
        (mem == 0.0 || (double)lim.rlim_cur < mem)) {
        mem = (double)lim.rlim_cur;
        *what = "the process's limit (ulimit -v) of";
    }
    return mem;
}

/* Refuses a body of `count` particles whose pair lists cannot be held: clearly more than 2^31
 * pairs (int offsets; the search counts them exactly when it is close) or more memory than
 * the machine has, instead of a search that runs for minutes and then fails or is killed.
 * Asked by the fill once it has counted the particles, before it allocates them
 * (refuse_count), and again before the neighbour search (on many processes with the halo).
 * A particle has about as many neighbours as lattice points lie within 2h (a sphere or a
 * disc of radius 2h / dx: 174 in 3D and 13 in 2D at coefh 1, a few more than interior
 * particles have), and the run needs at most some 12 bytes per neighbour (the
 * lists while the set-up builds the half lists from them; a 3D lattice's offset blocks add
 * about 1.4, 8 bytes a task of some 6 pairs) and 1 KB per particle (the plate at dp 1 mm,
 * 242 400 particles of 157 neighbours: estimated 0.70 GB, measured 0.48 GB at its peak
 * before the offset blocks; 1.26 GB when the set-up kept every pair's kernel gradient). */
static int check_size(const sph_body *b, long count)
{
    const double r = 2.0 * b->h / b->dx, n = (double)count;
    const double per = b->dim == 3 ? 4.0 / 3.0 * M_PI * r * r * r : M_PI * r * r;
    const char *what;
    const double bytes = n * (12.0 * per + 1024.0), mem = memory_limit(&what);
    if (n * per > 1.25 * 0x7fffffffL) {
        sph_error("body '%s' would have some %.3g neighbour pairs (%ld particles "
                  "with about %.0f neighbours each), more than 2^31: raise dp or lower "
                  "refine or coefh", b->desc->name, n * per, count, per);
        return -1;
    }
    if (mem > 0 && bytes > mem) {
        sph_error("body '%s' would need some %.3g GB of memory (%ld particles "
                  "with about %.0f neighbours each), more than %s %.3g GB: raise dp or "
                  "lower refine or coefh", b->desc->name, bytes / 1e9, count, per, what,
                  mem / 1e9);
        return -1;
    }
    return 0;
}

/* check_size as the fill's check of its count, before the particles are allocated: a body
 * of 3e8 particles is refused in the time it takes to count them, not after filling 7 GB. */
static int refuse_count(long n, void *body)
{
    return check_size(body, n) != 0;
}

/* Particles whose neighbours do not span the body's dimensions (too few of them, or all in
 * a line) leave the kernel correction singular: gradients there would be wrong, and a
 * particle alone moves without resistance.  Where no notch cut the pairs, that is a body too
 * thin or too small for its spacing, refused before the run; next to a notch it is the cut
 * itself (L = I there, as before). */
static int too_few_neighbours(const sph_body *b, const sph_body_desc *d, int nsingular,
                              int first)
{
    if (d->fracture && d->fracture->nnotches)
        return 0;
    char at[96];
    sph_reference_position(b, first, at, sizeof at);
    sph_error("body '%s': %d of its %d particles have too few neighbours for the kernel "
              "correction (the %d of particle %d at %s do not span %d dimensions): the body is "
              "too small or too thin for its spacing %g; make the spacing smaller (dp, refine) "
              "or the kernel wider (coefh)",
              d->name, nsingular, b->n, b->nb_start[first + 1] - b->nb_start[first], first, at,
              b->dim, b->dx);
    return -1;
}

/* The body's particles: the whole body on one process; on many, this process's own part
 * and its halo (docs/mpi.md).  0, or -1 after a message (on every process alike). */
static int fill(sph_body *b, const sph_body_desc *d, const sph_model *m)
{
    const sph_par *par = b->par;
    int bad = 0;
    if (par->size == 1) {
        SPH_TIMED("set-up: filling the shapes",
                  bad = sph_fill_region_checked(&d->region, m->dim, b->dx, d->y_plane,
                                                refuse_count, b, &b->X));
        b->n = b->nown = bad < 0 ? 0 : bad;
    } else {
        sph_part_fill pf;
        SPH_TIMED("set-up: filling the shapes",
                  bad = sph_fill_part(&d->region, m->dim, b->dx, d->y_plane, 2.0 * b->h,
                                      d->nbsrange, par->rank, par->size, refuse_count, b, &pf));
        b->n = pf.n, b->nown = pf.nown, b->X = pf.X, b->gid = pf.gid, b->halo_part = pf.halo_part;
    }
    if (par->agree(bad == SPH_FILL_REFUSED)) /* (too large: refuse_count has said so) */
        return -1;
    bad = bad < 0;
    if (par->agree(bad)) {
        sph_error("body '%s' cannot be filled with particles of spacing %g", d->name, b->dx);
        return -1;
    }
    double count[2] = {b->nown, b->nown > 0 ? 1 : 0}; /* particles, processes holding some */
    par->sum(count, 2);
    if (count[0] == 0) {
        sph_error("body '%s' has no particles (its shape is smaller than the "
                  "particle spacing %g)", d->name, b->dx);
        return -1;
    }
    if (count[1] < par->size) {
        sph_error("body '%s' has %.0f particles, too few to give each of the %d processes "
                  "some (%.0f hold none): run it on fewer processes", d->name, count[0],
                  par->size, par->size - count[1]);
        return -1;
    }
    return 0;
}

int sph_body_setup(sph_body *b, const sph_body_desc *d, const sph_model *m, double t_end,
                   const sph_par *par)
{
    memset(b, 0, sizeof *b);
    b->desc = d;
    b->par = par;
    b->dim = m->dim;
    b->dx = m->dp / d->refine;
    b->h = m->coefh * sqrt((double)m->dim) * b->dx; /* h = coefh sqrt(dim) dx */
    b->vol = pow(b->dx, m->dim);                    /* 2D: unit thickness */
    b->rho0 = d->rho0;
    b->mass = b->rho0 * b->vol;
    b->c0 = d->c0;
    b->y_plane = d->y_plane;
    if (fill(b, d, m))
        return -1;
    if (par->agree(check_size(b, b->n))) /* (with the halo, on many processes) */
        return -1;
    SPH_TIMED("set-up: particle order", sph_order_particles(b));
    if (d->clamp && sph_clamp_setup(b))
        return -1;
    SPH_TIMED("set-up: neighbour search",
              sph_neighbours(b->X, b->n, b->dim, 2.0 * b->h, d->nbsrange, b->dx, &b->nb_start,
                             &b->nb));
    b->npairs = b->nb_start[b->nown];
    if (d->fracture && d->fracture->nnotches) /* before the gradients: L sees the cut */
        SPH_TIMED("set-up: notches", cut_notches(b, d->fracture));
    int nsingular = 0, first = -1;
    SPH_TIMED("set-up: kernel gradients and L",
              nsingular = sph_gradients(b->X, b->nown, b->dim, b->nb_start, b->nb, m->kernel,
                                        b->h, b->vol, NULL, &b->L, &first));
    if (par->agree(nsingular && too_few_neighbours(b, d, nsingular, first)))
        return -1;
    SPH_TIMED("set-up: silent pairs", drop_silent_pairs(b, m->kernel));
    SPH_TIMED("set-up: offset tables", offset_tables(b, m->kernel));
    if (d->quadratic)
        SPH_TIMED("set-up: quadratic moments", quadratic_moments(b, m->kernel));
    SPH_TIMED("set-up: offset blocks", sph_offset_blocks_setup(b));
    SPH_TIMED("set-up: half lists and stripes", half_lists(b));
    SPH_TIMED("set-up: momentum blocks", sph_momentum_blocks_setup(b));
    if (!d->quadratic) /* (its runs sum the linear moments of u only) */
        SPH_TIMED("set-up: lattice stencil", sph_stencil_setup(b));
    SPH_TIMED("set-up: arrays", allocate(b));
    SPH_TIMED("set-up: BC and plane selections", selections(b, d, t_end));
    if (d->fracture)
        check_restrict(b, d->fracture, t_end);
    return 0;
}

void sph_body_free(sph_body *b)
{
    if (b->par)
        b->par->body_free(b);
    free(b->gid), free(b->halo_part), free(b->xb_start), free(b->xb), free(b->xb_k);
    for (int k = 0; k < b->desc->nbcs; k++)
        free(b->bc_list[k]);
    for (int k = 0; k < b->desc->nmeasures; k++)
        free(b->ms_list[k]);
    free(b->bc_list), free(b->bc_count), free(b->ms_list), free(b->ms_count);
    free(b->X), free(b->u), free(b->v), free(b->a), free(b->work), free(b->F), free(b->L);
    free(b->Q), free(b->Cv), free(b->Cs), free(b->lam2), free(b->psi), free(b->vq), free(b->sigma), free(b->fix),
        free(b->rare_hint);
    free(b->nb_start), free(b->nb), free(b->nb_k), free(b->wtab), free(b->gtab), free(b->htab);
    free(b->hb_start), free(b->hb), free(b->hb_k), free(b->stripe), free(b->stripe_sum), free(b->A);
    free(b->s), free(b->sd), free(b->sdd), free(b->H), free(b->lap), free(b->sd_n);
    free(b->ltab), free(b->state), free(b->qtab), free(b->Aq), free(b->Qq), free(b->Mq);
    free(b->Ad), free(b->Fd);
    free(b->image), free(b->image_of);
    free(b->st_k), free(b->st_o), free(b->st_run);
    free(b->rest), free(b->rest_start), free(b->rest_j), free(b->rest_k);
    free(b->ob_start), free(b->ob), free(b->ob_u), free(b->ob_v);
    free(b->mb_start), free(b->mb_i0), free(b->mb_stripe), free(b->mb), free(b->mb_soa);
}
