/* driver.c — locating sphc's files, loading a model with its imports, building it. */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "util/diag.h"
#include "driver.h"
#include "emit/emit.h"
#include "xml/xml.h"

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static int installed_paths(const char *argv0, Paths *p)
{
    char exe[2048];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) {
        if (!realpath(argv0, exe))
            return 0;
    } else {
        exe[n] = 0;
    }
    char *slash = strrchr(exe, '/');
    if (!slash)
        return 0;
    *slash = 0; /* <prefix>/bin */
    char probe[2200];
    snprintf(probe, sizeof probe, "%s/../%s/templates/body_forces.c", exe, SPHC_INSTALL_DATADIR);
    if (!exists(probe))
        return 0;
    snprintf(p->templates, sizeof p->templates, "%s/../%s/templates", exe, SPHC_INSTALL_DATADIR);
    snprintf(p->stdlib, sizeof p->stdlib, "%s/../%s/stdlib", exe, SPHC_INSTALL_DATADIR);
    snprintf(p->include, sizeof p->include, "%s/../%s/include", exe, SPHC_INSTALL_DATADIR);
    snprintf(p->lib, sizeof p->lib, "%s/../%s", exe, SPHC_INSTALL_LIBDIR);
    return 1;
}

int find_paths(const char *argv0, Paths *p)
{
    const char *home = getenv("SPHC_HOME");
    if (home && *home) {
        snprintf(p->templates, sizeof p->templates, "%s/share/sphc/templates", home);
        snprintf(p->stdlib, sizeof p->stdlib, "%s/share/sphc/stdlib", home);
        snprintf(p->include, sizeof p->include, "%s/share/sphc/include", home);
        snprintf(p->lib, sizeof p->lib, "%s/lib", home);
    } else if (!installed_paths(argv0, p)) {
        snprintf(p->templates, sizeof p->templates, "%s/templates", SPHC_SOURCE_DIR);
        snprintf(p->stdlib, sizeof p->stdlib, "%s/stdlib", SPHC_SOURCE_DIR);
        snprintf(p->include, sizeof p->include, "%s/runtime", SPHC_SOURCE_DIR);
        snprintf(p->lib, sizeof p->lib, "%s", SPHC_BUILD_LIBDIR);
    }
    char probe[4200];
    snprintf(probe, sizeof probe, "%s/body_forces.c", p->templates);
    if (!exists(probe)) {
        diag_fatal_noloc("cannot find sphc's templates (looked in %s); set SPHC_HOME to the "
                         "installation prefix",
                         p->templates);
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ imports */

static int already_loaded(char **loaded, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(loaded[i], name))
            return 1;
    return 0;
}

static int import_module(const Item *it, const char *model_dir, const Paths *paths, Program *prog)
{
    char path[8192];
    snprintf(path, sizeof path, "%s/%s.sph", model_dir, it->name);
    if (!exists(path))
        snprintf(path, sizeof path, "%s/%s.sph", paths->stdlib, it->name);
    if (!exists(path)) {
        diag_error(it->loc, "cannot find module '%s' (looked beside the model and in %s)",
                   it->name, paths->stdlib);
        return 1;
    }
    return parse_file(strdup(path), prog);
}

int load_program(const char *path, const Paths *paths, const XmlOptions *xml, Program *prog)
{
    prog->file = path;
    int errors = xml_is_case_file(path) ? xml_import(path, xml, prog) : parse_file(path, prog);
    char *dir = strdup(path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = 0;
    else
        strcpy(dir, ".");
    char **loaded = NULL;
    int nloaded = 0;
    /* Imported files may import more: prog->n grows while we scan.  An XML case imports
     * the material laws it uses, which are found like any module. */
    for (int i = 0; i < prog->n && !errors; i++) {
        const Item *it = &prog->items[i];
        if (it->kind != IT_IMPORT || already_loaded(loaded, nloaded, it->name))
            continue;
        loaded = realloc(loaded, (size_t)(nloaded + 1) * sizeof *loaded);
        loaded[nloaded++] = it->name;
        Item copy = *it; /* parse_file may move prog->items */
        errors += import_module(&copy, dir, paths, prog);
    }
    free(loaded);
    free(dir);
    return errors || diag_error_count() ? -1 : 0;
}

/* ------------------------------------------------------------------ building */

static int run_command(char *const argv[])
{
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        execvp(argv[0], argv);
        fprintf(stderr, "sphc: error: cannot run '%s': %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    int status;
    if (waitpid(pid, &status, 0) < 0)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static int write_source(const Model *m, const Paths *paths, const char *file)
{
    FILE *f = fopen(file, "w");
    if (!f) {
        diag_fatal_noloc("cannot write '%s': %s", file, strerror(errno));
        return -1;
    }
    const int cuda = strstr(file, ".cu") && file[strlen(file) - 1] == 'u';
    int r = cuda ? emit_cuda_program(m, paths->templates, f) : emit_c_program(m, paths->templates, f);
    if (fclose(f) != 0)
        r = -1;
    return r;
}

/* nvcc: $CUDA_HOME/bin/nvcc, else the first on PATH; NULL when there is none. */
static const char *find_nvcc(char *buf, size_t size)
{
    const char *home = getenv("CUDA_HOME");
    if (home && *home) {
        snprintf(buf, size, "%s/bin/nvcc", home);
        if (access(buf, X_OK) == 0)
            return buf;
    }
    const char *path = getenv("PATH");
    while (path && *path) {
        const char *end = strchr(path, ':');
        size_t n = end ? (size_t)(end - path) : strlen(path);
        snprintf(buf, size, "%.*s/nvcc", (int)n, path);
        if (n && access(buf, X_OK) == 0)
            return buf;
        path = end ? end + 1 : NULL;
    }
    return NULL;
}

/* The CUDA target: nvcc builds model.cu with runtime/sph_cuda.h and links the host runtime. */
static int compile_cuda(const Model *m, const Options *o, const char *src, const char *lib,
                        const char *inc, const char *exe)
{
    char nvcc[4096], arch[256];
    if (!find_nvcc(nvcc, sizeof nvcc)) {
        diag_fatal_noloc("--target cuda needs nvcc, which is neither in $CUDA_HOME/bin nor on "
                         "PATH (install the CUDA toolkit, or use --target cpu)");
        return -1;
    }
    const char *a = o->cuda_arch;
    if (!a) {
        a = access("/dev/nvidiactl", F_OK) == 0 ? "native" : "sm_90";
        if (strcmp(a, "native"))
            fprintf(stderr, "sphc: note: no GPU found on this machine; building %s for sm_90 "
                            "(--cuda-arch to choose)\n", m->name);
    }
    snprintf(arch, sizeof arch, "-arch=%s", a);
    char *argv[] = {nvcc, "-std=c++20", "--extended-lambda", "-O3", arch,
                    "-Xcompiler", "-fopenmp,-Wall,-Wextra", (char *)inc, (char *)src, (char *)lib,
                    "-lgomp", "-lm", "-o", (char *)exe, NULL};
    return run_command(argv);
}

int build_program(const Model *m, const Options *o, const Paths *paths)
{
    const int cuda = !strcmp(o->target, "cuda");
    char dir[4096];
    if (o->emit_dir) {
        snprintf(dir, sizeof dir, "%s", o->emit_dir);
        mkdir(dir, 0777);
    } else {
        snprintf(dir, sizeof dir, "/tmp/sphc-XXXXXX");
        if (!mkdtemp(dir)) {
            diag_fatal_noloc("cannot create a temporary folder: %s", strerror(errno));
            return -1;
        }
    }
    char src[4200], lib[4200], inc[4200];
    snprintf(src, sizeof src, "%s/%s.%s", dir, m->name, cuda ? "cu" : "c");
    snprintf(lib, sizeof lib, "%s/libsphrt%s.a", paths->lib, m->single ? "_single" : "");
    snprintf(inc, sizeof inc, "-I%s", paths->include);
    if (write_source(m, paths, src))
        return -1;
    if (o->emit_only)
        return 0;
    const char *cc = getenv("CC");
    const char *exe = o->output ? o->output : m->name;
    if (cuda) {
        int rc = compile_cuda(m, o, src, lib, inc, exe);
        if (!o->emit_dir) {
            remove(src);
            rmdir(dir);
        }
        if (rc != 0)
            diag_fatal_noloc("nvcc failed on the generated code (exit %d); rerun with --emit-c "
                             "DIR to inspect it", rc);
        return rc != 0 ? -1 : 0;
    }
    /* -ffp-contract=fast: let a*b+c become one fused multiply-add (ISO C mode turns that
     * off by default); -fno-math-errno: math functions need not set errno, so they inline. */
    char *argv[] = {(char *)(cc && *cc ? cc : "cc"), "-std=c11", "-O3", "-march=native",
                    "-ffp-contract=fast", "-fno-math-errno", "-fopenmp", "-Wall", "-Wextra",
                    inc, src, lib, "-lm", "-o", (char *)exe, NULL};
    int rc = run_command(argv);
    if (!o->emit_dir) {
        remove(src);
        rmdir(dir);
    }
    if (rc != 0) {
        diag_fatal_noloc("the C compiler failed on the generated code (exit %d); rerun with "
                         "--emit-c DIR to inspect it",
                         rc);
        return -1;
    }
    return 0;
}
