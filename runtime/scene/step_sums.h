/* step_sums.h — a body's step sums, one table (SPH_STEP_SUMS): the numbers the generated passes
 * reduce over a body's particles at every step (the time step's bounds, the artificial
 * viscosity's power and energy).  Each row is read by everything that keeps such a number: the
 * member of sph_body (body.h), its initial value (run/setup.c), its slot of the device's sums
 * and the copies between host and device (cuda/sums.h, cuda/transfer.h), the exchange between
 * processes (run/sim.c), the checkpoint (io/checkpoint.c) and, where it is one, its column of
 * energies.csv (run/run.c).  The passes that compute a row are the templates'. */
#ifndef SPHRT_SCENE_STEP_SUMS_H
#define SPHRT_SCENE_STEP_SUMS_H

#include "core/defs.h"

/* How a row's values combine: over the particles, over the device's blocks and over the
 * processes of a run.
 *   SPH_REDUCE_MAX  the largest: the scene's, which the processes agree on before every time
 *                   step (run/sim.c), so each holds it
 *   SPH_REDUCE_MIN  the smallest, the same way; the device holds the largest reciprocal (its
 *                   reductions take maxima of non-negative numbers, SPH_FOR_MAX3), 0 for
 *                   none: the row's initial value
 *   SPH_REDUCE_ADD  the sum: each process holds its own particles' share, added up where it is
 *                   read (energies.csv's rows, a checkpoint) */
enum { SPH_REDUCE_MAX, SPH_REDUCE_MIN, SPH_REDUCE_ADD };

/* X(member, SLOT, reduce, initial, saved, column, kind, when), one row per step sum:
 *   member   its double in sph_body, which the CPU's passes write (b->member)
 *   SLOT     its slot of the device's sums, b->red[SPH_RED_<SLOT>] (cuda/sums.h)
 *   reduce   SPH_REDUCE_MAX, _MIN or _ADD (above)
 *   initial  its value before the first step
 *   saved    1: a number of the checkpoint's record <body>.sums, which holds the saved rows in
 *            this order (a maximum or minimum the scene's, restored on every process; a sum
 *            the processes' total, restored on process 0); 0: not kept, the initial value on
 *            a restart (a sum the next step makes anew before it is read)
 *   column   its column of energies.csv, <body>_<column>, after the body's other ones
 *            (run/run.c); NULL: none
 *   kind     the total of energies.csv the column joins: HELD or DISSIPATED (run/run.c)
 *   when     whether a body has the column: an expression of its description d (const
 *            sph_body_desc *) and the model m (const sph_model *), in parentheses if it holds
 *            a comma; 0 for a row that is no column
 * A row that is no column only bounds or feeds others; one column of a sum and its rate
 * (visc_dissipated += visc_rate dt) take a row each. */
#define SPH_STEP_SUMS(X)                                                                         \
    /* the largest |v|^2 and |a|^2 over free components, eq. 65-66 (the update) */               \
    X(vmax2, VMAX2, SPH_REDUCE_MAX, 0.0, 1, NULL, HELD, 0)                                       \
    X(amax2, AMAX2, SPH_REDUCE_MAX, 0.0, 1, NULL, HELD, 0)                                       \
    /* the smallest squared principal stretch, the time step's bound on compression where the   \
     * body tracks it (desc->crush: the stress pass's lam2, reduced by the update) */           \
    X(lam2min, CRUSH, SPH_REDUCE_MIN, 1.0, 1, NULL, HELD, 0)                                     \
    /* artificial viscosity (eq. 57-60): the rate at which it dissipates energy (the momentum   \
     * pass) and the energy it has dissipated (templates/body_sums.c) */                         \
    X(visc_rate, VISC_RATE, SPH_REDUCE_ADD, 0.0, 1, NULL, HELD, 0)                               \
    X(visc_dissipated, VISC_DISSIPATED, SPH_REDUCE_ADD, 0.0, 1, "viscous", DISSIPATED, d->viscous)

/* The rows' indices, SPH_STEP_SUM_<member> (the table's order), and their count. */
enum {
#define SPH_STEP_SUM_INDEX(member, ...) SPH_STEP_SUM_##member,
    SPH_STEP_SUMS(SPH_STEP_SUM_INDEX)
#undef SPH_STEP_SUM_INDEX
    SPH_STEP_NSUMS
};

/* Row k's reduce, initial and saved (functions, so that the device's code reads them too). */
SPH_HD static inline int sph_step_sum_reduce(int k)
{
    switch (k) {
#define SPH_STEP_SUM_CASE(member, SLOT, reduce, ...) case SPH_STEP_SUM_##member: return reduce;
        SPH_STEP_SUMS(SPH_STEP_SUM_CASE)
#undef SPH_STEP_SUM_CASE
    }
    return SPH_REDUCE_ADD;
}

SPH_HD static inline double sph_step_sum_initial(int k)
{
    switch (k) {
#define SPH_STEP_SUM_CASE(member, SLOT, reduce, initial, ...) \
    case SPH_STEP_SUM_##member: return initial;
        SPH_STEP_SUMS(SPH_STEP_SUM_CASE)
#undef SPH_STEP_SUM_CASE
    }
    return 0;
}

SPH_HD static inline int sph_step_sum_saved(int k)
{
    switch (k) {
#define SPH_STEP_SUM_CASE(member, SLOT, reduce, initial, saved, ...) \
    case SPH_STEP_SUM_##member: return saved;
        SPH_STEP_SUMS(SPH_STEP_SUM_CASE)
#undef SPH_STEP_SUM_CASE
    }
    return 0;
}

/* The words in which templates/body_sums.c computes step sums once for both targets (the
 * CUDA target's are cuda/sums.h's):
 *   SPH_STEP_SUM(b, member)  body b's step sum where its passes keep it, an lvalue: the CPU's
 *                            b->member, the device's slot of b->red (which holds a minimum as
 *                            its reciprocal: read maxima and sums there)
 *   SPH_STEP_ONCE({ ... })   statements on those, once (on the device one thread, in stream
 *                            order after the passes before it)
 *   SPH_STEP_SUM_OVER(b, member, i, expr)
 *                            sum member (SPH_REDUCE_ADD) := expr summed over b's own particles
 *                            i, in a pass of its own; on the CPU stripe by stripe, then in
 *                            stripe order, so that the bits are the same on any number of
 *                            threads (as the momentum pass's viscous power) */
#ifndef SPH_STEP_SUM_DEFINED
#define SPH_STEP_SUM(b, member) ((b)->member)
#define SPH_STEP_ONCE(...) do __VA_ARGS__ while (0)
#define SPH_STEP_SUM_OVER(b, member, i, ...)                                 \
    do {                                                                     \
        sph_body *const sb_ = (b);                                           \
        _Pragma("omp parallel for schedule(static)")                         \
        for (int s_ = 0; s_ < sb_->nstripes; s_++) {                         \
            double x_ = 0;                                                   \
            for (int i = sb_->stripe[s_]; i < sb_->stripe[s_ + 1]; i++)      \
                x_ += (__VA_ARGS__);                                         \
            sb_->stripe_sum[s_] = x_;                                        \
        }                                                                    \
        double sum_ = 0;                                                     \
        for (int s_ = 0; s_ < sb_->nstripes; s_++)                           \
            sum_ += sb_->stripe_sum[s_];                                     \
        sb_->member = sum_;                                                  \
    } while (0)
#endif

#endif
