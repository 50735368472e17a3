/* profile.h — where the time of a run goes (the program's --profile; profile.c).  The CPU
 * target's step calls its passes through SPH_PASS(fn, (args)) (a body's: SPH_BODY_PASS), and the
 * set-up times its stages
 * with SPH_TIMED(name, statement): when profiling is on, the wall time of the call is added to
 * its entry (found once per call site) in the phase the run is in; otherwise it costs one
 * test.  The CUDA target's SPH_PASS is the bare call: its kernels are timed on the device
 * (cuda/launch.h).  io/profile_report.h reports the entries. */
#ifndef SPHRT_CORE_PROFILE_H
#define SPHRT_CORE_PROFILE_H

#include "clock.h"
#include "defs.h"

SPH_C_BEGIN

enum { SPH_PHASE_STEPS, SPH_PHASE_CHECKS, SPH_PHASE_SETUP }; /* sph_profile_phase */
extern int sph_profile_on, sph_profile_phase;
int sph_profile_slot(const char *pass);
/* The entry "BODY_PASS" of a body's pass (SPH_BODY_PASS): bodies that run the same code
 * (sphc's shared code) keep an entry each. */
int sph_profile_body_slot(const char *body, const char *pass);
/* The entry of `pass` in the phase the run is in, kept in *at for the next call. */
int sph_profile_slot_at(int *at, const char *pass);
void sph_profile_add(int slot, double seconds);

/* The entries so far, in the order they were first timed (*n of them, at most
 * SPH_PROFILE_MAX: a few per body, a few for the scene). */
#define SPH_PROFILE_MAX 128
typedef struct {
    const char *name;
    int phase;
    double seconds;
    long calls;
} sph_profile_entry;
const sph_profile_entry *sph_profile_entries(int *n);

SPH_C_END

/* The statement timed into the entry `slot` (an expression, evaluated only when profiling). */
#define SPH_TIMED_INTO(slot, statement)                                                        \
    do {                                                                                       \
        if (sph_profile_on) {                                                                  \
            const int slot_ = (slot);                                                          \
            const double t0_ = sph_wall_time();                                                \
            statement;                                                                         \
            sph_profile_add(slot_, sph_wall_time() - t0_);                                     \
        } else {                                                                               \
            statement;                                                                         \
        }                                                                                      \
    } while (0)
#define SPH_TIMED(name, statement)                                                             \
    do {                                                                                       \
        static int at_ = -1; /* (the call site's entry, found once per phase) */               \
        SPH_TIMED_INTO(sph_profile_slot_at(&at_, name), statement);                            \
    } while (0)
#define SPH_PASS(fn, args) SPH_TIMED(#fn, fn args)
/* A pass of body b (a sph_body *), timed as "NAME_PASS" with NAME the body's own: the same
 * function may run several bodies (sphc runs bodies of the same code by one body's
 * functions), each with its entry. */
#define SPH_BODY_PASS(b, pass, call)                                                           \
    SPH_TIMED_INTO(sph_profile_body_slot((b)->desc->name, pass), call)

#endif
