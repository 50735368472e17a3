/* body.h — a body's particles as the passes work on them (sph_body): the reference and
 * current state, the pair lists and offset tables, the CPU's stencil and offset blocks, the
 * device's full lists, fracture, selections and the passes' step sums (step_sums.h). */
#ifndef SPHRT_SCENE_BODY_H
#define SPHRT_SCENE_BODY_H

#include <stdint.h>
#include <stdio.h>

#include "body_desc.h"
#include "pass_types.h"
#include "step_sums.h"
#include "core/defs.h"

SPH_C_BEGIN

struct sph_par;
typedef struct sph_body sph_body;

/* One task of a block of the gradient pass's offset blocks (offset_blocks.c): particle
 * i0 + l of the block, for each lane l in the mask key & 255, has the pair with particle
 * i0 + l + off at offset table entry key >> 8. */
#define SPH_OB_LANES 8
enum { SPH_MB_Q = 0, SPH_MB_CV = 9, SPH_MB_CS = 18, SPH_MB_V = 19, SPH_MB_A = 22, SPH_MB_ROWS = 25 };
typedef struct {
    int off;
    unsigned key;
} sph_ob_task;

struct sph_body {
    const sph_body_desc *desc;
    int n, dim;
    /* Runs on many processes (docs/mpi.md): this process's own particles are 0 .. nown - 1,
     * its halo (particles of other processes within the kernel support of its own, whose
     * values the exchanges bring) nown .. n - 1.  On one process nown = n.  Particle loops
     * run over the own particles, the pair passes over the pairs of own particles. */
    int nown;
    int64_t *gid;         /* n global ids (lattice ids, partition.h); NULL on one process */
    int *halo_part;       /* n - nown: the process each halo particle belongs to */
    /* Pairs of an own particle i with halo particles: xb_start[i] .. xb_start[i + 1] - 1,
     * neighbour xb[p], offset table entry xb_k[p] (as i sees the pair).  A process computes
     * them for its own particle only; the other process computes the same pair for its own.
     * NULL on one process. */
    int *xb_start, *xb, *xb_k;
    const struct sph_par *par; /* the processes of the run (one, or MPI's) */
    void *halo;                /* the halo exchange's plan (the MPI runtime's) */
    void *halo_dev;            /* device targets: the plan's lists and buffers on the device */
    double dx, h, vol, mass, rho0, c0, y_plane;

    double *X;          /* n*dim reference positions */
    double *u, *v, *a;  /* n*dim displacement, velocity, acceleration */
    double *F;          /* n*9 deformation gradient (3×3) */
    int want_F;         /* whether the next stress pass stores F: only where something reads it
                         * after the step (sph_sim_advance), unless the body's code reads it
                         * every step (the plan's F_EVERY_STEP) */
    double *L;          /* n*dim*dim correction */
    sph_real *Q;        /* P·L (first Piola–Kirchhoff times correction), SPH_TENSOR */
    sph_real *Cv;       /* cof(F) = J F^-T for artificial viscosity, SPH_TENSOR */
    sph_real *Cs;       /* 1 / cof(F)'s largest singular value (sph_viscous_scale) */
    double *psi;        /* n strain energy density */
    double *vq;         /* n the artificial viscosity's heating rate per unit mass: half of
                           each of the particle's pairs' f_visc . (v_j - v_i), the momentum
                           pass's (desc->vheat; NULL without) */
    double *sigma;      /* n*6 Cauchy stress, filled at output */
    double *work;       /* n*dim scratch for integrators (symplectic: v at n) */
    uint8_t *fix;       /* n bit masks: bit k = component k has a prescribed velocity */
    uint8_t *rare_hint; /* laws with state, at each CPU stress block's first particle: steps
                         * left that take the whole law (templates/body_forces.c, RARE) */

    int *nb_start, *nb;   /* CSR neighbour lists, both directions (set-up only; freed) */
    int *nb_k;            /* per pair: entry of the offset tables (set-up only; freed) */
    sph_real *wtab;       /* ntab*SPH_ROW(dim): V_j grad W for each distinct offset (0-padded) */
    sph_real *gtab;       /* ntab: G_ij = gtab * (v_i - v_j) . w_ij  (eq. 60) */
    sph_real *htab;       /* ntab: V W(r0) / (rho0 r0^2), for the hourglass penalty */
    int ntab;
    /* Half lists (j > i only) for the passes that visit each pair once and add its share
     * to both particles.  Particles are cut into stripes of consecutive indices, in
     * ncolours colours (stripe s's: s mod ncolours), each at least the largest j - i over
     * ncolours - 1 long, so a pair of stripe s touches only stripes s .. s + ncolours - 1:
     * the stripes of one colour can run in parallel, then those of the next, without two
     * threads ever writing the same particle (mostly two colours, even and odd stripes). */
    int *hb_start, *hb, *hb_k;
    int *stripe;          /* nstripes + 1 particle indices */
    int nstripes, ncolours;
    double *stripe_sum;   /* nstripes: a sum over each stripe's pairs (the viscous power)
                           * or particles (SPH_STEP_SUM_OVER), added up in stripe order after
                           * the pass: the same bits on any number of threads */
    /* The lattice stencil (stencil.c; CPU only).  Where particles sit on a lattice, most
     * have the same half list relative to their own index: neighbours i + st_o[q] at offset
     * table entries st_k[q], q < st_m.  A particle whose pairs are exactly those and their
     * mirror images (i - st_o[q], the same entries as i - st_o[q] sees them), none with the
     * halo, belongs to one of the runs [st_run[2r], st_run[2r + 1]) of consecutive such
     * particles (ascending, r < nruns).  The pair passes do a run offset by offset, the
     * same pair of many particles in one vector instruction; the stress pass takes the run
     * particles' gradient sums from the stencil.  st_m = 0, nruns = 0: none (off a lattice,
     * or the program's --no-stencil). */
    int st_m, *st_k, *st_o;
    int nruns, *st_run;
    /* With a stencil, the gradient pass's lists: the particles it still visits (rest[c],
     * ascending, c < nrest: those not in a run, and run particles with a neighbour that is
     * not), each with the pairs it must add (rest_start[c] .. rest_start[c + 1] - 1,
     * neighbour rest_j, entry rest_k): a particle not in a run its whole half list, a run
     * particle its pairs with particles not in a run.  The momentum pass reads them for the
     * particles not in a run.  Compact, so that the passes do not load the half lists'
     * cache lines for a few particles apiece (they took a sixth of crack branching's step).
     * NULL without a stencil. */
    int nrest, *rest, *rest_start, *rest_j, *rest_k;
    /* The gradient pass's offset blocks (offset_blocks.c; 3D, CPU only): block B, the
     * SPH_OB_LANES own particles from SPH_OB_LANES B on, sums its particles' own pairs by the
     * tasks ob[ob_start[B] .. ob_start[B + 1] - 1] (sph_ob_task), reading u by component from
     * ob_u (row r from ob_u + r ob_stride, particle i at ob_pad + i), and v from ob_v alike
     * where the law reads a rate (the velocity's gradient; NULL otherwise); ob_pairs: the
     * pairs, in both directions, that the tasks' lanes hold.  nob = 0, NULL: none (the half
     * lists sum the pairs). */
    int nob, *ob_start, ob_pad, ob_stride;
    sph_ob_task *ob;
    double *ob_u, *ob_v;
    long ob_pairs;
    /* The momentum pass's offset blocks (offset_blocks.c; 3D, CPU only), over the half lists:
     * stripe s's blocks mb_stripe[s] .. mb_stripe[s + 1] - 1, block B the up to
     * SPH_OB_LANES particles from mb_i0[B] (within the stripe), its tasks
     * mb[mb_start[B] .. mb_start[B + 1] - 1].  mb_soa: SPH_MB_ROWS rows of mb_stride doubles,
     * particle i at mb_pad + i: Q and cof F entry (r, c) in rows 3 r + c and 9 + 3 r + c, Cs,
     * v and the pass's sums (SPH_MB_*).  mb_pairs: the pairs the lanes hold.  NULL, nmb = 0:
     * none. */
    int nmb, *mb_start, *mb_i0, *mb_stripe, mb_pad, mb_stride;
    sph_ob_task *mb;
    double *mb_soa;
    long mb_pairs;
    sph_real *A;          /* n*SPH_TENSOR_SIZE(dim): sum_j (u_j - u_i) (x) w_ij, the pair part of
                           * eq. 53, row by row, rows padded like wtab (CPU only) */
    /* The corrected gradient exact for quadratic fields (desc->quadratic; pairs/quadratic.h;
     * CPU only, NULL otherwise).  qtab: ntab*SPH_QR(dim), the pair weight's monomial part
     * -V_j (dW/dr / r) q(X_j - X_i) for each offset table entry (the same both ways, padded
     * with zeros); Mq: n*SPH_QM(dim)^2, each particle's inverse moment matrix; Aq:
     * n*dim*SPH_QR(dim), row by row, the gradient pass's sum_j (u_j - u_i) (x) qtab, then the
     * fit's second-derivative coefficients; Qq: n*SPH_QN(dim)*SPH_ROW(dim), column by column
     * like Q, the stress's share the momentum pass contracts with qtab
     * (templates/body_quadratic.c). */
    sph_real *qtab, *Aq, *Qq;
    double *Mq;
    /* A clamp by mirror images (desc->clamp; run/clamp.c): particle image[k] behind the
     * plane moves with minus particle image_of[k]'s displacement, k < nimages. */
    int nimages, *image, *image_of;
    /* Full lists (both directions) for device targets, whose threads each sum their own
     * particle's pairs, stored slot by slot: pair s of particle i (s < fb_count[i]) is
     * fb[s*n + i], so the threads of a warp read consecutive words.  fb_k is the offset table
     * entry k of the pair as the half list holds it, or ~k for the reversed pair
     * (w_ji = -w_ij).  On a lattice every offset has its own slot, the same for all
     * particles (where a particle lacks that neighbour, near a surface or a notch, the slot
     * holds a particle near i + the offset, sph_hole, and the zero table entry ntab the
     * device tables end with), so a warp's threads at one slot read j = i + const,
     * consecutive words; off a lattice each particle's pairs are packed and sorted by entry.
     * Where every pair of a body lies at i + its slot's offset (a box), fb and fb_k are NULL
     * and fb_mask holds the pairs: bit s & 31 of fb_mask[(s >> 5)*n + i] says whether
     * particle i has slot s's neighbour i + fb_off[s], of table entry fb_slotk[s] (sph_slot,
     * cuda/slots.h).  NULL on the CPU. */
    int *fb_count, *fb, *fb_k;
    unsigned *fb_mask;
    int *fb_off, *fb_slotk;
    /* Device targets: u and v by component (us[r*n + i]), as the pair passes read their
     * neighbours' (sph_cuda_components, cuda/components.h).  NULL on the CPU. */
    double *us, *vs;
    /* Device targets: the step sums below as the device sums them (SPH_RED_* of
     * cuda/sums.h), read back once per step.  NULL on the CPU. */
    double *red;

    double *state;        /* n*nstate state of the material law (NULL without state) */
    sph_real *Ad;         /* n D x D, rows like A's: sum_j V_j (v_j - v_i) (x) grad W_ij (a law
                           * that reads the rate of F; NULL otherwise) */
    double *Fd;           /* n*9 its rate dF/dt = Ad L^T, as the last stress pass left it */
    double law_dt;        /* the time since the law's last evaluation (a law that reads dt:
                           * the step sets it before the stress pass, from sph_sim.dt_prev) */

    /* Phase-field fracture (NULL unless the body has fracture). */
    double *s, *sd, *sdd; /* n phase field (1 intact, 0 broken), ds/dt, d2s/dt2 */
    double *H;            /* n history field: the largest psi+ so far (eq. 8) */
    double *lap;          /* n Laplacian of s (eq. 62), summed by the gradient pass */
    double *sd_n;         /* n symplectic: ds/dt at the start of the step */
    sph_real *ltab;       /* ntab: 2 V dW/dr / r, so lap_i = sum_j ltab (s_i - s_j) */
    long npairs;          /* neighbour relations, both directions (2 x the half lists) */

    int **bc_list;      /* per BC with `near`: particle indices */
    int *bc_count;
    int **ms_list;      /* per measure: particle indices */
    int *ms_count;

    /* the time step's bound on compression (desc->crush): each particle's squared smallest
     * principal stretch from the last stress pass (their minimum: lam2min, below) */
    double *lam2;
    /* the step sums the generated passes write, one double each (vmax2, amax2, lam2min,
     * visc_rate, visc_dissipated, ...): the rows of step_sums.h */
#define SPH_STEP_SUM_MEMBER(member, ...) double member;
    SPH_STEP_SUMS(SPH_STEP_SUM_MEMBER)
#undef SPH_STEP_SUM_MEMBER
};

/* Body b's step sums into x, in the table's order (step_sums.h). */
static inline void sph_step_sums_get(const sph_body *b, double x[SPH_STEP_NSUMS])
{
#define SPH_STEP_SUM_GET(member, ...) x[SPH_STEP_SUM_##member] = b->member;
    SPH_STEP_SUMS(SPH_STEP_SUM_GET)
#undef SPH_STEP_SUM_GET
}

/* Body b's step sums from x, in the table's order. */
static inline void sph_step_sums_set(sph_body *b, const double x[SPH_STEP_NSUMS])
{
#define SPH_STEP_SUM_SET(member, ...) b->member = x[SPH_STEP_SUM_##member];
    SPH_STEP_SUMS(SPH_STEP_SUM_SET)
#undef SPH_STEP_SUM_SET
}

/* Particle i's reference position for a message: "x = X, z = Z" (2D, the x-z plane) or
 * "x = X, y = Y, z = Z" (3D), into buf; returns what snprintf returns. */
static inline int sph_reference_position(const sph_body *b, int i, char *buf, size_t len)
{
    const double *x = b->X + (size_t)i * b->dim;
    if (b->dim == 3)
        return snprintf(buf, len, "x = %g, y = %g, z = %g", x[0], x[1], x[2]);
    return snprintf(buf, len, "x = %g, z = %g", x[0], x[1]);
}

/* The first k < n with a[k stride] >= v (n when none): a binary search of ascending values. */
static inline int sph_first_at_least(const int *a, int n, int stride, int v)
{
    int lo = 0, hi = n;
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (a[(size_t)mid * stride] >= v)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* The first of body b's stencil runs that ends after particle i (b->nruns when none does):
 * where a pass over particles i .. finds its runs. */
static inline int sph_run_after(const sph_body *b, int i)
{
    return sph_first_at_least(b->st_run + 1, b->nruns, 2, i + 1);
}

/* The first of body b's rest particles (above) at or after particle i (b->nrest when none). */
static inline int sph_rest_after(const sph_body *b, int i)
{
    return sph_first_at_least(b->rest, b->nrest, 1, i);
}

SPH_C_END

#endif
