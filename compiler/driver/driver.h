/* driver.h — the driver's own work around the stages: the command line, where sphc's files
 * are, loading a model with its imports (the first stage) and building the generated source
 * with the target's compiler (the last). */
#ifndef SPHC_DRIVER_H
#define SPHC_DRIVER_H

#include "model/model.h"
#include "emit/emit.h"
#include "front/ast.h"
#include "lower/plan.h"
#include "xml/xml.h"

typedef struct {
    const char *input;
    const char *output;    /* -o */
    Target target;         /* --target cpu | cuda */
    const char *cuda_arch; /* --cuda-arch: nvcc's -arch (NULL: native with a GPU, else sm_90) */
    int mpi;               /* --mpi: a program for many processes (docs/mpi.md) */
    int no_simd;           /* --no-simd: a CPU program without vectors across particles */
    const char *emit_dir;  /* --emit-c */
    const char *dump;      /* ast | model | plan */
    int check_only;
    int emit_only;         /* --emit-only: write the C source (to --emit-c DIR) and stop */
    int to_sph;            /* --to-sph: print the model as .sph and stop */
    XmlOptions xml;        /* --xml-*: how an XML case is read */
    int xml_options_given; /* some --xml-* option was given (an error for a .sph model) */
} Options;

typedef struct {
    char templates[4096];
    char stdlib[4096];
    char include[4096];
    char lib[4096];        /* folder holding libsphrt.a */
} Paths;

/* The command line (options.c); -1 after reporting, and exits for --help and --version. */
int parse_options(int argc, char **argv, Options *o);

/* Installed layout (<prefix>/bin/sphc with <prefix>/share/sphc and <prefix>/lib) first,
 * then the source and build trees sphc was built from; SPHC_HOME overrides both. */
int find_paths(const char *argv0, Paths *p);

/* Parse the model (a .sph file, or a SoliDualSPHysics .xml case through the importer, read
 * with the options xml) and every module it imports (stdlib/NAME.sph or NAME.sph beside it). */
int load_program(const char *path, const Paths *paths, const XmlOptions *xml, Program *prog);

/* Emit the plan's program for o->target, compile and link the executable. */
int build_program(const Plan *plan, const Options *o, const Paths *paths);

#endif
