/* exit_codes.h — the exit codes of a generated program (README): a declared expectation
 * failed, bad options, the run went unstable, set-up or output failed, a CUDA call or kernel
 * failed, a signal stopped a run with checkpoints (after writing one), or one without. */
#ifndef SPHRT_CORE_EXIT_CODES_H
#define SPHRT_CORE_EXIT_CODES_H

enum {
    SPH_EXIT_EXPECT = 1, SPH_EXIT_OPTIONS = 2, SPH_EXIT_UNSTABLE = 3, SPH_EXIT_SETUP = 4,
    SPH_EXIT_CUDA = 5, SPH_EXIT_STOPPED = 6, SPH_EXIT_SIGNALLED = 7
};

#endif
