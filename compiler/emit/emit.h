/* emit.h — the fourth stage: a plan as the source of a program for a target, model.c for the
 * CPU (OpenMP) or model.cu for an NVIDIA GPU (CUDA).  The targets share the program's
 * structure and differ by a table (emit_target.c). */
#ifndef SPHC_EMIT_H
#define SPHC_EMIT_H

#include <stdio.h>

#include "lower/plan.h"

typedef enum { TARGET_CPU, TARGET_CUDA } Target;

/* The target called `name` ("cpu", "cuda") in *t: 0, or -1 when there is none. */
int target_named(const char *name, Target *t);
/* The generated file's suffix: "c" or "cu". */
const char *target_suffix(Target t);
/* Its name, as --target takes it. */
const char *target_name(Target t);

/* Write the whole generated program for target t, for many processes (MPI) when mpi is set;
 * templates_dir holds the templates.  Returns 0, or -1 after reporting. */
int emit_program(const Plan *plan, Target t, int mpi, const char *templates_dir, FILE *out);
/* Whether a body's material law is printed in pieces for target t (lower/graph_print.h). */
int emit_law_in_pieces(const Plan *plan, Target t);

#endif
