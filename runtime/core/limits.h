/* limits.h — limits the compiler checks and the program enforces, written once. */
#ifndef SPH_LIMITS_H
#define SPH_LIMITS_H

/* The lattice points of the box around a body that the filling visits (fill.c): a body
 * spanning more is refused, by sphc --check and by the program's set-up. */
#define SPH_MAX_LATTICE_POINTS 2e9

#endif
