/* spectral.h — the runtime's spectral routines (runtime/sph_tensor.h) as the scalar graph
 * knows them: their names, their values (for the graph's reference interpreter) and their
 * derivatives (for reverse accumulation).  pos(A), the positive part of a symmetric tensor
 * (eq. 13-16), is an SN_EXT node of one of these; neg(A) = A - pos(A) needs none. */
#ifndef SPHC_SPECTRAL_H
#define SPHC_SPECTRAL_H

#include "scalar.h"

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

/* The derivative of SN_EXT node ext in reverse accumulation: given the adjoints of its
 * outputs (bar[k], a node, or -1 where output k has none), the adjoints of its arguments
 * (into arg_bar[k], a node) as graph nodes.  Returns 0, or -1 for a routine without a rule
 * (an adjoint routine itself: no second derivatives). */
int spectral_adjoint(SGraph *g, int ext, const int *bar, int *arg_bar);

/* Output k of routine ext folded where its arguments allow: the 3D positive part (and its
 * adjoint) of a plane-strain tensor (no y coupling, yy zero) is the 2D closed form's, with
 * zeros in the y row and column.  Returns the node, or -1 (sg_part keeps the part). */
int spectral_fold_part(SGraph *g, int ext, int k);

#endif
