/* cc.c — the last stage: the generated source written to a file and built by the target's
 * compiler (cc for the CPU, mpicc for the CPU with --mpi, nvcc for CUDA) against the
 * runtime. */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "util/diag.h"
#include "driver.h"
#include "emit/emit.h"

/* ------------------------------------------------------------------ stopped by a signal */

/* sphc stopped by SIGINT, SIGTERM or SIGHUP while it writes the source or the compiler runs:
 * the temporary folder and the source in it are removed, the compiler gets the signal too
 * (a SIGTERM sent to sphc alone would leave it running) and is waited for, and sphc then
 * ends by the signal, as it would have without a handler.  A signal the caller ignores
 * (nohup, a background job) stays ignored. */
static const int STOP_SIGNALS[] = {SIGINT, SIGTERM, SIGHUP};
enum { NSTOP = sizeof STOP_SIGNALS / sizeof STOP_SIGNALS[0] };

static char tmp_dir[4096], tmp_src[4200]; /* the temporary folder and its source */
static volatile sig_atomic_t tmp_made;     /* tmp_dir exists and is sphc's to remove */
static volatile sig_atomic_t compiler_pid; /* the compiler running, or 0 */

/* Only async-signal-safe calls. */
static void on_stop_signal(int sig)
{
    if (tmp_made) {
        unlink(tmp_src);
        rmdir(tmp_dir);
    }
    for (int k = 0; k < NSTOP; k++) /* a second signal ends sphc at once */
        signal(STOP_SIGNALS[k], SIG_DFL);
    const pid_t pid = compiler_pid;
    if (pid > 0) {
        kill(pid, sig);
        while (waitpid(pid, NULL, 0) < 0 && errno == EINTR)
            ;
    }
    raise(sig);
}

static void catch_stop_signals(void)
{
    for (int k = 0; k < NSTOP; k++) {
        struct sigaction old, sa;
        if (sigaction(STOP_SIGNALS[k], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_stop_signal;
        sigemptyset(&sa.sa_mask);
        for (int j = 0; j < NSTOP; j++)
            sigaddset(&sa.sa_mask, STOP_SIGNALS[j]);
        sigaction(STOP_SIGNALS[k], &sa, NULL);
    }
}

/* The stop signals held back (the mask before in *old), and let through again. */
static void hold_stop_signals(sigset_t *old)
{
    sigset_t set;
    sigemptyset(&set);
    for (int k = 0; k < NSTOP; k++)
        sigaddset(&set, STOP_SIGNALS[k]);
    sigprocmask(SIG_BLOCK, &set, old);
}

static void release_stop_signals(const sigset_t *old)
{
    sigprocmask(SIG_SETMASK, old, NULL);
}

/* The temporary folder removed (its source first), no longer the handler's. */
static void remove_tmp(void)
{
    if (!tmp_made)
        return;
    tmp_made = 0;
    remove(tmp_src);
    rmdir(tmp_dir);
}

/* The folder for the generated source: TMPDIR's (or /tmp's) sphc-XXXXXX, in tmp_dir.
 * Returns 0, or -1 after an error. */
static int make_tmp(void)
{
    const char *base = getenv("TMPDIR");
    if (!base || !*base)
        base = "/tmp";
    if (snprintf(tmp_dir, sizeof tmp_dir, "%s/sphc-XXXXXX", base) >= (int)sizeof tmp_dir) {
        diag_fatal_noloc("cannot create a temporary folder: TMPDIR is too long");
        return -1;
    }
    catch_stop_signals();
    sigset_t old;
    hold_stop_signals(&old); /* made and marked as one step */
    const int made = mkdtemp(tmp_dir) != NULL;
    const int err = errno;
    tmp_src[0] = 0;
    tmp_made = made;
    release_stop_signals(&old);
    if (!made) {
        diag_fatal_noloc("cannot create a temporary folder in %s: %s", base, strerror(err));
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ the compiler */

static int run_command(char *const argv[])
{
    sigset_t old;
    hold_stop_signals(&old); /* the pid known to the handler before a signal */
    pid_t pid = fork();
    if (pid == 0) {
        for (int k = 0; k < NSTOP; k++) /* not sphc's handler: the signal's own action */
            if (signal(STOP_SIGNALS[k], SIG_DFL) == SIG_IGN)
                signal(STOP_SIGNALS[k], SIG_IGN);
        release_stop_signals(&old);
        execvp(argv[0], argv);
        fprintf(stderr, "sphc: error: cannot run '%s': %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    compiler_pid = pid > 0 ? pid : 0;
    release_stop_signals(&old);
    if (pid < 0)
        return -1;
    int status, r;
    while ((r = waitpid(pid, &status, 0)) < 0 && errno == EINTR)
        ;
    compiler_pid = 0;
    if (r < 0)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static int write_source(const Plan *plan, const Options *o, const Paths *paths,
                        const char *file)
{
    FILE *f = fopen(file, "w");
    if (!f) {
        diag_fatal_noloc("cannot write '%s': %s", file, strerror(errno));
        return -1;
    }
    int r = emit_program(plan, o->target, o->mpi, paths->templates, f);
    if (fclose(f) != 0)
        r = -1;
    return r;
}

/* Program `name` in the first folder of PATH that has it executable (in buf); NULL when
 * none has.  A name with a slash is that file itself, as execvp takes it. */
static const char *find_on_path(const char *name, char *buf, size_t size)
{
    if (strchr(name, '/')) {
        snprintf(buf, size, "%s", name);
        return access(buf, X_OK) == 0 ? buf : NULL;
    }
    const char *path = getenv("PATH");
    while (path && *path) {
        const char *end = strchr(path, ':');
        size_t n = end ? (size_t)(end - path) : strlen(path);
        snprintf(buf, size, "%.*s/%s", (int)n, path, name);
        if (n && access(buf, X_OK) == 0)
            return buf;
        path = end ? end + 1 : NULL;
    }
    return NULL;
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
    return find_on_path("nvcc", buf, size);
}

/* An MPI compiler wrapper: $VAR, else `name` (in buf); NULL after reporting when it is not
 * there, so that the user reads what to install rather than execvp's "cannot run". */
static const char *find_mpi_wrapper(const char *var, const char *name, char *buf, size_t size)
{
    const char *wrapper = getenv(var);
    if (!wrapper || !*wrapper)
        wrapper = name;
    if (find_on_path(wrapper, buf, size))
        return buf;
    diag_fatal_noloc("--mpi needs %s (an MPI library: scripts/deps installs Open MPI), which "
                     "is not on PATH", wrapper);
    return NULL;
}

/* The CPU target's C compiler with MPI (mpicc), and the CUDA target's host compiler (mpicxx,
 * nvcc's -ccbin: it compiles the host code and links with MPI's libraries). */
static const char *find_mpicc(char *buf, size_t size)
{
    return find_mpi_wrapper("MPICC", "mpicc", buf, size);
}

static const char *find_mpicxx(char *buf, size_t size)
{
    return find_mpi_wrapper("MPICXX", "mpicxx", buf, size);
}

/* The processes' runtime (runtime/mpi/, sph_mpi_main), in the folder of libsphrt.a. */
#define MPI_RUNTIME "libsphrt_mpi.a"

/* What a build for many processes needs beyond the CPU target's, checked before anything is
 * written: -1 after reporting. */
static int mpi_ready(const Model *m, const Options *o, const Paths *paths)
{
    /* libsphrt_mpi is built on the double runtime only (there is no libsphrt_mpi_single) */
    if (m->single) {
        diag_fatal_noloc("--mpi with `precision single` is not supported yet");
        return -1;
    }
    if (o->emit_only) /* the source alone needs neither MPI nor its runtime */
        return 0;
    char buf[4200];
    if (!(o->target == TARGET_CUDA ? find_mpicxx(buf, sizeof buf) : find_mpicc(buf, sizeof buf)))
        return -1;
    /* built only where cmake found an MPI library when sphc was built */
    snprintf(buf, sizeof buf, "%s/" MPI_RUNTIME, paths->lib);
    if (access(buf, R_OK)) {
        diag_fatal_noloc("sphc was built without MPI (" MPI_RUNTIME " is missing in %s): install "
                         "an MPI library (scripts/deps) and build sphc again", paths->lib);
        return -1;
    }
    return 0;
}

/* The CUDA target: nvcc builds model.cu with runtime/sph_cuda.h and links the host runtime. */
static int compile_cuda(const Plan *plan, const Options *o, const char *src, const char *lib,
                        const char *inc, const char *exe)
{
    const Model *m = plan->model;
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
    char host[4096], mpilib[4200];
    char *argv[24];
    int n = 0;
    argv[n++] = nvcc;
    if (o->mpi) { /* MPI's C++ wrapper as nvcc's host compiler, and the processes' runtime */
        find_mpicxx(host, sizeof host);
        argv[n++] = "-ccbin";
        argv[n++] = host;
    }
    static const char *const flags[] = {"-std=c++20", "--extended-lambda", "-O3", NULL};
    for (const char *const *f = flags; *f; f++)
        argv[n++] = (char *)*f;
    argv[n++] = arch;
    /* a law in pieces: each device function compiled on its own (ptxas's time over a whole
     * program grows faster than its functions' number: 3000 chained lets, 390 s, 53 s so) */
    if (emit_law_in_pieces(plan, TARGET_CUDA))
        argv[n++] = "-rdc=true";
    argv[n++] = "-Xcompiler";
    argv[n++] = "-fopenmp,-Wall,-Wextra";
    argv[n++] = (char *)inc;
    argv[n++] = (char *)src;
    if (o->mpi) {
        snprintf(mpilib, sizeof mpilib, "%.*s/" MPI_RUNTIME, (int)(strrchr(lib, '/') - lib), lib);
        argv[n++] = mpilib;
    }
    argv[n++] = (char *)lib;
    argv[n++] = "-lgomp";
    argv[n++] = "-lm";
    argv[n++] = "-o";
    argv[n++] = (char *)exe;
    argv[n] = NULL;
    return run_command(argv);
}

/* The CPU target: cc (or $CC) builds model.c with OpenMP and links the runtime; with --mpi,
 * mpicc (or $MPICC: the C compiler with MPI's headers and libraries) builds it and links the
 * processes' runtime too, before libsphrt.a, whose functions it calls (mpi_ready checked both).
 * -ffp-contract=fast: let a*b+c become one fused multiply-add (ISO C mode turns that off by
 * default); -fno-math-errno: math functions need not set errno, so they inline. */
static int compile_c(const Plan *plan, const Options *o, const char *src, const char *lib,
                     const char *inc, const char *exe)
{
    (void)plan;
    char compiler[4096], mpilib[4200];
    const char *cc = getenv("CC");
    if (o->mpi)
        find_mpicc(compiler, sizeof compiler);
    else
        snprintf(compiler, sizeof compiler, "%s", cc && *cc ? cc : "cc");
    char *argv[24];
    int n = 0;
    argv[n++] = compiler;
    /* -fno-trapping-math: the program never reads or traps floating-point exceptions, so the
     * compiler may evaluate both sides of a select (a division, a comparison) where only one
     * is used, which vectorising the stress pass needs on a machine without AVX-512 masks */
    static const char *const flags[] = {"-std=c11",        "-O3",
                                        "-march=native",    "-ffp-contract=fast",
                                        "-fno-math-errno",  "-fno-trapping-math",
                                        "-fopenmp",         "-Wall",
                                        "-Wextra",          NULL};
    for (const char *const *f = flags; *f; f++)
        argv[n++] = (char *)*f;
    if (o->no_simd) { /* scalar code: no loop vectorised, no statements packed into vectors */
        argv[n++] = "-fno-tree-vectorize";
        argv[n++] = "-fno-tree-slp-vectorize";
    }
    argv[n++] = (char *)inc;
    argv[n++] = (char *)src;
    if (o->mpi) { /* lib is DIR/libsphrt.a (build_program) */
        snprintf(mpilib, sizeof mpilib, "%.*s/" MPI_RUNTIME, (int)(strrchr(lib, '/') - lib), lib);
        argv[n++] = mpilib;
    }
    argv[n++] = (char *)lib;
    argv[n++] = "-lm";
    argv[n++] = "-o";
    argv[n++] = (char *)exe;
    argv[n] = NULL;
    return run_command(argv);
}

/* Each target's compiler, and its name in the message when it fails. */
static const struct {
    int (*compile)(const Plan *plan, const Options *o, const char *src, const char *lib,
                   const char *inc, const char *exe);
    const char *name;
} COMPILERS[] = {
    [TARGET_CPU] = {compile_c, "the C compiler"},
    [TARGET_CUDA] = {compile_cuda, "nvcc"},
};

/* A clamp by images runs on one process (its images are found among a process's own
 * particles, run/clamp.c): an error at its line for --mpi, 1; 0 otherwise. */
static int clamp_many_processes(const Options *o, SrcLoc loc)
{
    if (!o->mpi)
        return 0;
    diag_error(loc, "a body's 'clamp' runs on one process; --mpi needs a velocity condition "
                    "instead");
    return 1;
}

int build_program(const Plan *plan, const Options *o, const Paths *paths)
{
    const Model *m = plan->model;
    for (int i = 0; i < m->nbodies; i++)
        if (m->bodies[i].has_clamp && clamp_many_processes(o, m->bodies[i].clamp_loc))
            return -1;
    if (o->mpi && mpi_ready(m, o, paths))
        return -1;
    char dir[4096];
    if (o->emit_dir) {
        snprintf(dir, sizeof dir, "%s", o->emit_dir);
        mkdir(dir, 0777);
    } else {
        if (make_tmp())
            return -1;
        snprintf(dir, sizeof dir, "%s", tmp_dir);
    }
    char src[4200], lib[4200], inc[4200];
    snprintf(src, sizeof src, "%s/%s.%s", dir, m->name, target_suffix(o->target));
    if (!o->emit_dir) { /* whole before the handler reads it (a signal sees "" or src) */
        sigset_t old;
        hold_stop_signals(&old);
        memcpy(tmp_src, src, sizeof src);
        release_stop_signals(&old);
    }
    snprintf(lib, sizeof lib, "%s/libsphrt%s.a", paths->lib, m->single ? "_single" : "");
    snprintf(inc, sizeof inc, "-I%s", paths->include);
    if (write_source(plan, o, paths, src)) {
        remove_tmp();
        return -1;
    }
    if (o->emit_only) {
        printf("sphc: wrote %s\n", src);
        return 0;
    }
    const char *exe = o->output ? o->output : m->name;
    int rc = COMPILERS[o->target].compile(plan, o, src, lib, inc, exe);
    remove_tmp();
    if (rc != 0) {
        diag_fatal_noloc("%s failed on the generated code (exit %d); rerun with --emit-c DIR to "
                         "inspect it", COMPILERS[o->target].name, rc);
        return -1;
    }
    printf("sphc: built %s%s (%s%s)%s%s\n", strchr(exe, '/') ? "" : "./", exe,
           target_name(o->target), o->mpi ? ", MPI" : "", o->emit_dir ? ", its source in " : "",
           o->emit_dir ? src : "");
    return 0;
}
