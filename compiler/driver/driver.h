/* driver.h — locating sphc's files, loading a model with its imports, building it. */
#ifndef SPHC_DRIVER_H
#define SPHC_DRIVER_H

#include "front/ast.h"
#include "check/model.h"
#include "xml/xml.h"

typedef struct {
    const char *input;
    const char *output;    /* -o */
    const char *target;    /* cpu | cuda */
    const char *cuda_arch; /* --cuda-arch: nvcc's -arch (NULL: native with a GPU, else sm_90) */
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

/* Installed layout (<prefix>/bin/sphc with <prefix>/share/sphc and <prefix>/lib) first,
 * then the source and build trees sphc was built from; SPHC_HOME overrides both. */
int find_paths(const char *argv0, Paths *p);

/* Parse the model (a .sph file, or a SoliDualSPHysics .xml case through the importer, read
 * with the options xml) and every module it imports (stdlib/NAME.sph or NAME.sph beside it). */
int load_program(const char *path, const Paths *paths, const XmlOptions *xml, Program *prog);

/* Emit C, compile and link the executable. */
int build_program(const Model *m, const Options *o, const Paths *paths);

#endif
