/* options.c — sphc's command line:
 *
 *   sphc [-o NAME] [--target cpu|cuda] [--mpi] [--emit-c DIR] [--dump=ast|model|plan]
 *        [--check] [--strict] [--to-sph] [--xml-elastic2d=3d|sdsph]
 *        [--xml-fill=volume|gencase] FILE
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "driver.h"

static void usage(FILE *f)
{
    fputs("usage: sphc [-o NAME] [--target cpu|cuda] [--cuda-arch A] [--mpi] [--emit-c DIR]\n"
          "            [--dump=ast|model|plan]\n"
          "            [--check] [--strict] [--to-sph] [--xml-elastic2d=3d|sdsph]\n"
          "            [--xml-fill=volume|gencase] FILE\n"
          "Compiles a model (FILE.sph, or a SoliDualSPHysics case FILE.xml) into an\n"
          "executable (named after FILE unless -o is given).\n"
          "  -o NAME          name of the executable\n"
          "  --target T       cpu (OpenMP, default) or cuda (nvcc from PATH or $CUDA_HOME)\n"
          "  --cuda-arch A    nvcc -arch for the cuda target (default: native when a GPU is\n"
          "                   present, else sm_90)\n"
          "  --mpi            build for many processes (MPI): mpirun -np N ./model runs the model\n"
          "                   on N processes; without mpirun it runs as one (docs/mpi.md)\n"
          "  --no-simd        a CPU program of scalar code: no pair pass by the lattice\n"
          "                   stencil or offset blocks, no loop over particles vectorised (to\n"
          "                   compare with the vector code; docs/performance.md)\n"
          "  --emit-c DIR     keep the generated C source in DIR\n"
          "  --dump=STAGE     print the syntax tree, checked model or kernel plan and stop\n"
          "  --emit-only      with --emit-c: write the C source without compiling it\n"
          "  --check          check the model only\n"
          "  --strict         make warnings errors (a law's stress that is not its energy's\n"
          "                   derivative, a cfl above 1, ...): the exit status is non-zero\n"
          "  --to-sph         check the model and print it as an .sph model (to convert an\n"
          "                   XML case once: sphc --to-sph Case_Def.xml > case.sph)\n"
          "  --xml-elastic2d=3d|sdsph\n"
          "                   elastic constants of a 2D XML case: 3D constants (default) or,\n"
          "                   as SoliDualSPHysics reads them, those of 2D elasticity (u_bulk =\n"
          "                   lambda + mu); see docs/xml.md\n"
          "  --xml-fill=volume|gencase\n"
          "                   particles of an XML case's cylinders and surfaces: cell centres\n"
          "                   inside the shape, which keep its volume (default), or where\n"
          "                   GenCase puts them; see docs/xml.md\n"
          "  --version        print the version\n",
          f);
}

/* "--NAME=VALUE" or "--NAME VALUE" (then *i moves past VALUE): the value, or NULL. */
static const char *option_value(const char *arg, const char *name, const char *next, int *i)
{
    size_t n = strlen(name);
    if (strncmp(arg, name, n))
        return NULL;
    if (arg[n] == '=')
        return arg + n + 1;
    if (arg[n] == '\0' && next) {
        (*i)++;
        return next;
    }
    return NULL;
}

/* One of two values a and b for option name: 0 for a, 1 for b, -1 after reporting. */
static int choice(const char *name, const char *v, const char *a, const char *b)
{
    if (!strcmp(v, a) || !strcmp(v, b))
        return !strcmp(v, b);
    diag_fatal_noloc("unknown value '%s' for %s (expected %s or %s)", v, name, a, b);
    return -1;
}

/* The options that choose how an XML case is read (docs/xml.md). */
static int xml_option(Options *o, const char *arg, const char *next, int *i)
{
    const char *v;
    int c;
    if ((v = option_value(arg, "--xml-elastic2d", next, i))) {
        if ((c = choice("--xml-elastic2d", v, "3d", "sdsph")) < 0)
            return -1;
        o->xml.elastic2d_sdsph = c;
    } else if ((v = option_value(arg, "--xml-fill", next, i))) {
        if ((c = choice("--xml-fill", v, "volume", "gencase")) < 0)
            return -1;
        o->xml.fill_gencase = c;
    } else {
        diag_fatal_noloc("unknown option '%s' (see sphc --help)", arg);
        return -1;
    }
    o->xml_options_given = 1;
    return 0;
}

int parse_options(int argc, char **argv, Options *o)
{
    memset(o, 0, sizeof *o);
    const char *target = "cpu";
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            exit(0);
        } else if (!strcmp(a, "--version")) {
            printf("sphc %s\n", SPHC_VERSION);
            exit(0);
        } else if (!strcmp(a, "-o") && i + 1 < argc) {
            o->output = argv[++i];
        } else if (!strcmp(a, "--target") && i + 1 < argc) {
            target = argv[++i];
        } else if (!strncmp(a, "--target=", 9)) {
            target = a + 9;
        } else if (!strcmp(a, "--cuda-arch") && i + 1 < argc) {
            o->cuda_arch = argv[++i];
        } else if (!strncmp(a, "--cuda-arch=", 12)) {
            o->cuda_arch = a + 12;
        } else if (!strcmp(a, "--mpi")) {
            o->mpi = 1;
        } else if (!strcmp(a, "--no-simd")) {
            o->no_simd = 1;
        } else if (!strcmp(a, "--emit-c") && i + 1 < argc) {
            o->emit_dir = argv[++i];
        } else if (!strncmp(a, "--emit-c=", 9)) {
            o->emit_dir = a + 9;
        } else if (!strncmp(a, "--dump=", 7)) {
            o->dump = a + 7;
        } else if (!strcmp(a, "--emit-only")) {
            o->emit_only = 1;
        } else if (!strcmp(a, "--check")) {
            o->check_only = 1;
        } else if (!strcmp(a, "--strict")) {
            diag_set_strict(1); /* from the first stage on: every warning is an error */
        } else if (!strcmp(a, "--to-sph")) {
            o->to_sph = 1;
        } else if (!strncmp(a, "--xml-", 6)) {
            if (xml_option(o, a, i + 1 < argc ? argv[i + 1] : NULL, &i))
                return -1;
        } else if (a[0] == '-' && a[1]) {
            diag_fatal_noloc("unknown option '%s' (see sphc --help)", a);
            return -1;
        } else if (o->input) {
            diag_fatal_noloc("more than one model file given ('%s' and '%s')", o->input, a);
            return -1;
        } else {
            o->input = a;
        }
    }
    if (!o->input) {
        usage(stderr);
        return -1;
    }
    if (target_named(target, &o->target)) {
        diag_fatal_noloc("unknown target '%s' (expected cpu or cuda)", target);
        return -1;
    }
    if (o->no_simd && o->target == TARGET_CUDA) {
        diag_fatal_noloc("--no-simd is for the cpu target (a CUDA device runs its threads in "
                         "warps whatever the code)");
        return -1;
    }
    if (o->emit_only && !o->emit_dir) {
        diag_fatal_noloc("--emit-only needs --emit-c DIR");
        return -1;
    }
    if (o->xml_options_given && !xml_is_case_file(o->input)) {
        diag_fatal_noloc("the --xml-* options apply to SoliDualSPHysics case files (.xml), not "
                         "to '%s'", o->input);
        return -1;
    }
    if (o->dump && strcmp(o->dump, "ast") && strcmp(o->dump, "model") && strcmp(o->dump, "plan")) {
        diag_fatal_noloc("unknown stage '%s' for --dump (expected ast, model or plan)", o->dump);
        return -1;
    }
    return 0;
}
