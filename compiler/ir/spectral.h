/* spectral.h — the runtime's spectral routines (runtime/sph_tensor.h) as the scalar graph
 * knows them: their names, their values (for the graph's reference interpreter) and the
 * routines of their derivatives (for reverse accumulation).  pos(A), the positive part of a
 * symmetric tensor (eq. 13-16), is an SN_EXT node of one of these; neg(A) = A - pos(A) needs
 * none.  Numbers and names only: the graph (scalar.h) builds on these, not the reverse. */
#ifndef SPHC_SPECTRAL_H
#define SPHC_SPECTRAL_H

/* pos of a 3x3 tensor: 9 inputs (row-major; the upper triangle mirrored), 9 outputs. */
#define SPECTRAL_POS3 "sph_sym_pos3"
/* pos of a plane-strain tensor: inputs and outputs {xx, xz, zz}. */
#define SPECTRAL_POS2 "sph_sym_pos2"
/* Their adjoints: the inputs followed by the adjoints of the outputs; out: the adjoints of
 * the inputs (Daleckii-Krein, sph_tensor.h). */
#define SPECTRAL_POS3_ADJOINT "sph_sym_pos3_adjoint"
#define SPECTRAL_POS2_ADJOINT "sph_sym_pos2_adjoint"

/* The outputs (out[0 .. nout-1]) of routine name at argument values args; -1 for a routine
 * the compiler does not know (its outputs are then NaN). */
int spectral_eval(const char *name, const double *args, int nargs, double *out);

/* The routine that gives the adjoints of routine name's arguments (nargs of them) from the
 * adjoints of its outputs, called with the arguments followed by those adjoints (derivative.c
 * builds it into the graph); NULL for a routine without one (an adjoint routine itself: no
 * second derivatives) or one the compiler does not know. */
const char *spectral_adjoint_of(const char *name, int nargs);

#endif
