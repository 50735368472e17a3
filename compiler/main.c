/* main.c — sphc: the stages in order, each handing a plain data structure to the next
 * (docs/architecture.md):
 *
 *   load   (driver/load.c: front/ parses a .sph model, xml/ imports a .xml case)  -> Program
 *   check  (check/)                                                                -> Model
 *   lower  (lower/: per-body features, the material law as a folded graph, ir/)    -> Plan
 *   emit   (emit/: the plan as C for the CPU or CUDA for the GPU)                  -> source
 *   cc     (driver/cc.c: cc or nvcc against the runtime)                           -> program
 *
 * --dump=ast|model|plan prints a stage's product and stops; --to-sph prints the syntax tree
 * as an .sph model (to convert an XML case); --check stops after lowering.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check/check.h"
#include "driver/driver.h"
#include "front/sph_print.h"
#include "lower/plan.h"
#include "util/diag.h"

/* The file's stem, "cases/my-beam.sph" -> "my-beam": the program's name.  Characters other
 * than letters, digits and . _ + - (which the generated code would have to quote) become
 * '_', with a note saying so. */
static char *stem(const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    char *s = strdup(base);
    char *dot = strrchr(s, '.');
    if (dot && dot != s)
        *dot = 0;
    int changed = 0;
    for (char *c = s; *c; c++)
        if (!isalnum((unsigned char)*c) && !strchr("._+-", *c)) {
            *c = '_';
            changed = 1;
        }
    if (changed)
        fprintf(stderr, "sphc: note: the program is named '%s' (characters other than letters, "
                        "digits and . _ + - became '_')\n", s);
    return s;
}

static void print_sph(const Options *o, const Program *prog)
{
    printf("# %s, converted by sphc --to-sph\n", o->input);
    if (prog->comment) { /* the case's own comments */
        printf("#\n");
        sph_print_comment(prog->comment, stdout);
    }
    printf("\n");
    sph_print_program(prog, stdout);
}

int main(int argc, char **argv)
{
    Options o;
    if (parse_options(argc, argv, &o))
        return 2;
    Paths paths;
    if (find_paths(argv[0], &paths))
        return 1;

    Program prog = {0};
    if (load_program(o.input, &paths, &o.xml, &prog))
        return 1;
    if (o.dump && !strcmp(o.dump, "ast")) {
        ast_dump(&prog, stdout);
        return 0;
    }

    Model m;
    m.name = stem(o.output ? o.output : o.input);
    if (check_program(&prog, &m))
        return 1;
    if (o.dump && !strcmp(o.dump, "model")) {
        model_dump(&m, stdout);
        return 0;
    }
    if (o.to_sph && !o.dump) {
        print_sph(&o, &prog);
        return 0;
    }

    Plan plan; /* --check lowers too: a law that folds to a non-finite value with a body's
                * parameters is an error of the model */
    m.no_simd = o.no_simd;
    if (lower_model(&m, &plan))
        return 1;
    if (o.target == TARGET_CUDA &&
        plan_laws_beyond(&plan, LAW_MAX_OPERATIONS_CUDA, " on the CUDA target")) {
        plan_free(&plan);
        return 1;
    }
    if (o.dump) {
        plan_dump(&plan, stdout);
        return 0;
    }
    if (o.check_only) {
        plan_free(&plan);
        return 0;
    }

    int rc = build_program(&plan, &o, &paths) ? 1 : 0;
    plan_free(&plan);
    return rc;
}
