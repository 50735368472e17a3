/* fuzz_run.c — one fuzz input through sphc's stages (fuzz_run.h).
 *
 * Each input is written to <tmp>/input.sph or input.xml in a folder made once per process
 * (in /dev/shm when there is one), beside links to the surface and CSV files the cases and
 * tests name, so that a mutated case still finds them.  The stages run as main.c runs them;
 * the error limit of diag.c longjmps back here instead of exiting.  Afterwards the source
 * cache (util/source.c) and the scanner's names are forgotten and every block the stages
 * left allocated is freed (fuzz_alloc.c), so a long run's memory stays flat. */
#include <dirent.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check/check.h"
#include "driver/driver.h"
#include "front/sph_print.h"
#include "fuzz_alloc.h"
#include "fuzz_run.h"
#include "lower/plan.h"
#include "util/diag.h"
#include "util/source.h"

/* fuzz_alloc.h renames the allocator for the compiler's sources; here it is the system's. */
#undef malloc
#undef calloc
#undef realloc
#undef free
#undef strdup
#undef strndup

static char dir[4096];
static Paths paths;
static FILE *devnull;
static jmp_buf stop_env;

static void stop(void)
{
    longjmp(stop_env, 1);
}

static void remove_dir(void)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    char path[8192];
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            unlink(path);
        }
    closedir(d);
    rmdir(dir);
}

static int has_suffix(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && !strcmp(s + n - k, suffix);
}

/* Links in dir to the data files of a source folder: surfaces and reference solutions. */
static void link_data(const char *folder)
{
    char src[4096];
    snprintf(src, sizeof src, "%s/%s", SPHC_SOURCE_DIR, folder);
    DIR *d = opendir(src);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (!has_suffix(e->d_name, ".vtk") && !has_suffix(e->d_name, ".stl")
            && !has_suffix(e->d_name, ".csv"))
            continue;
        char from[8192], to[8192];
        snprintf(from, sizeof from, "%s/%s", src, e->d_name);
        snprintf(to, sizeof to, "%s/%s", dir, e->d_name);
        if (access(to, F_OK) != 0) /* the first of two files of one name wins */
            (void)symlink(from, to);
    }
    closedir(d);
}

static void init(void)
{
    const char *base = getenv("TMPDIR");
    struct stat st;
    if (stat("/dev/shm", &st) == 0 && S_ISDIR(st.st_mode) && access("/dev/shm", W_OK) == 0)
        base = "/dev/shm";
    snprintf(dir, sizeof dir, "%s/sphc-fuzz-XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(dir)) {
        perror("sphc fuzz: mkdtemp");
        abort();
    }
    atexit(remove_dir);
    static const char *const data_folders[] = {"cases", "cases/xml", "tests/xml/good",
                                               "tests/xml/bad", "tests/physics"};
    for (size_t i = 0; i < sizeof data_folders / sizeof *data_folders; i++)
        link_data(data_folders[i]);
    snprintf(paths.templates, sizeof paths.templates, "%s/templates", SPHC_SOURCE_DIR);
    snprintf(paths.stdlib, sizeof paths.stdlib, "%s/stdlib", SPHC_SOURCE_DIR);
    snprintf(paths.include, sizeof paths.include, "%s/runtime", SPHC_SOURCE_DIR);
    snprintf(paths.lib, sizeof paths.lib, "%s", ".");
    devnull = fopen("/dev/null", "w");
    if (!devnull)
        abort();
    diag_set_stop(stop);
}

/* The stages after loading, as main.c runs them, and every printer of their products. */
static void check_and_lower(const Program *prog)
{
    Model m;
    memset(&m, 0, sizeof m);
    m.name = "input";
    if (check_program(prog, &m))
        return;
    ast_dump(prog, devnull);
    model_dump(&m, devnull);
    sph_print_program(prog, devnull);
    Plan plan;
    if (lower_model(&m, &plan))
        return;
    plan_dump(&plan, devnull);
    emit_program(&plan, TARGET_CPU, 0, paths.templates, devnull);
    emit_program(&plan, TARGET_CPU, 1, paths.templates, devnull); /* sphc --mpi */
    emit_program(&plan, TARGET_CUDA, 0, paths.templates, devnull);
    plan_free(&plan);
}

/* One reading of the model file; the error limit jumps back here. */
static void run_once(const char *path, const XmlOptions *xml)
{
    diag_reset();
    if (setjmp(stop_env) == 0) {
        Program prog;
        memset(&prog, 0, sizeof prog);
        if (load_program(path, &paths, xml, &prog) == 0)
            check_and_lower(&prog);
    }
    source_forget();
    lex_forget_names();
    sphc_fuzz_release();
}

int fuzz_run(const uint8_t *data, size_t size, const char *ext)
{
    if (!devnull)
        init();
    char path[4200];
    snprintf(path, sizeof path, "%s/input.%s", dir, ext);
    FILE *f = fopen(path, "wb");
    if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f)) {
        perror("sphc fuzz: writing the input");
        abort();
    }
    XmlOptions xml = {0, 0};
    run_once(path, &xml);
    if (!strcmp(ext, "xml") && diag_error_count() == 0) {
        XmlOptions other = {1, 1};
        run_once(path, &other);
    }
    return 0;
}
