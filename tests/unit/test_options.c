/* test_options.c — command-line parsing of generated programs: defaults, both option
 * spellings, --help, and the rejection of bad input with an error and the usage. */
#define _POSIX_C_SOURCE 200809L
#include "run/options.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int failures = 0;

#define CHECK(cond, ...)                                   \
    do {                                                   \
        if (!(cond)) {                                     \
            printf("  FAIL (%s:%d): ", __FILE__, __LINE__); \
            printf(__VA_ARGS__);                           \
            printf("\n");                                  \
            failures++;                                    \
        }                                                  \
    } while (0)

#define MAX_ARGS 16

/* Parses the NULL-terminated argument list (argv[0] = "./beam", model "beam") with
 * stdout and stderr captured into out/err (each up to size-1 bytes). */
static int parse(sph_options *o, const char *const *args, char *out, char *err, size_t size)
{
    char *argv[MAX_ARGS + 2] = {"./beam"};
    int argc = 1;
    for (; args[argc - 1] && argc <= MAX_ARGS; argc++)
        argv[argc] = (char *)args[argc - 1];
    argv[argc] = NULL;

    FILE *fo = tmpfile(), *fe = tmpfile();
    fflush(stdout);
    fflush(stderr);
    int saved_out = dup(1), saved_err = dup(2);
    dup2(fileno(fo), 1);
    dup2(fileno(fe), 2);
    int rc = sph_parse_options(o, "beam", argc, argv);
    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    close(saved_out);
    close(saved_err);

    FILE *files[2] = {fo, fe};
    char *bufs[2] = {out, err};
    for (int k = 0; k < 2; k++) {
        rewind(files[k]);
        size_t got = fread(bufs[k], 1, size - 1, files[k]);
        bufs[k][got] = '\0';
        fclose(files[k]);
    }
    return rc;
}

static char out[4096], err[4096];

static void test_defaults(void)
{
    printf("defaults without arguments\n");
    sph_options o;
    const char *args[] = {NULL};
    CHECK(parse(&o, args, out, err, sizeof out) == 0, "returns 0");
    CHECK(o.out_dir && strcmp(o.out_dir, "beam_out") == 0, "out_dir beam_out, got %s",
          o.out_dir ? o.out_dir : "(null)");
    CHECK(o.threads == 0 && o.t_end == -1 && o.t_out == -1 && o.t_frames == -1 && o.quiet == 0,
          "other defaults");
    CHECK(o.fixed_threads == 0, "the thread count a maximum by default");
    CHECK(out[0] == '\0' && err[0] == '\0', "nothing printed");
}

static void test_separate_values(void)
{
    printf("--out DIR --threads N --end T --every T --frames T --quiet\n");
    sph_options o;
    const char *args[] = {"--out", "res/a", "--threads", "4", "--end", "0.5",
                          "--every", "1e-3", "--frames", "0.1", "--quiet", NULL};
    CHECK(parse(&o, args, out, err, sizeof out) == 0, "returns 0 (stderr: %s)", err);
    CHECK(strcmp(o.out_dir, "res/a") == 0, "out_dir");
    CHECK(o.threads == 4, "threads 4");
    CHECK(o.t_end == 0.5, "t_end 0.5");
    CHECK(o.t_out == 1e-3, "t_out 1e-3");
    CHECK(o.t_frames == 0.1, "t_frames 0.1");
    CHECK(o.quiet == 1, "quiet");
    const char *fixed[] = {"--threads", "2", "--fixed-threads", NULL};
    CHECK(parse(&o, fixed, out, err, sizeof out) == 0 && o.threads == 2 && o.fixed_threads == 1,
          "--fixed-threads (stderr: %s)", err);
}

static void test_checkpoints(void)
{
    printf("--checkpoint T --restart FILE: the output folder is FILE's unless --out is given\n");
    sph_options o;
    const char *args[] = {"--checkpoint", "0.5", "--restart", "runs/a/checkpoint.bin", NULL};
    CHECK(parse(&o, args, out, err, sizeof out) == 0, "returns 0 (stderr: %s)", err);
    CHECK(o.t_checkpoint == 0.5, "t_checkpoint 0.5");
    CHECK(o.restart && strcmp(o.restart, "runs/a/checkpoint.bin") == 0, "restart");
    CHECK(strcmp(o.out_dir, "runs/a") == 0, "out_dir runs/a, got %s", o.out_dir);
    const char *bare[] = {"--restart=checkpoint.bin", NULL};
    CHECK(parse(&o, bare, out, err, sizeof out) == 0 && strcmp(o.out_dir, ".") == 0,
          "a bare file name: out_dir ., got %s", o.out_dir);
    const char *root[] = {"--restart", "/checkpoint.bin", NULL};
    CHECK(parse(&o, root, out, err, sizeof out) == 0 && strcmp(o.out_dir, "/") == 0,
          "a file in /: out_dir /, got %s", o.out_dir);
    const char *given[] = {"--restart", "a/checkpoint.bin", "--out", "b", NULL};
    CHECK(parse(&o, given, out, err, sizeof out) == 0 && strcmp(o.out_dir, "b") == 0,
          "--out given: out_dir b, got %s", o.out_dir);
    const char *none[] = {NULL};
    CHECK(parse(&o, none, out, err, sizeof out) == 0 && o.t_checkpoint == -1 && !o.restart,
          "defaults: no checkpoints, no restart");
}

static void test_outputs(void)
{
    printf("--overwrite, --progress T (0: none; default 10 s)\n");
    sph_options o;
    const char *args[] = {"--overwrite", "--progress", "0.5", NULL};
    CHECK(parse(&o, args, out, err, sizeof out) == 0, "returns 0 (stderr: %s)", err);
    CHECK(o.overwrite == 1 && o.progress == 0.5, "overwrite, progress 0.5");
    const char *none[] = {"--progress=0", NULL};
    CHECK(parse(&o, none, out, err, sizeof out) == 0 && o.progress == 0 && !o.overwrite,
          "--progress=0; no --overwrite");
    const char *defaults[] = {NULL};
    CHECK(parse(&o, defaults, out, err, sizeof out) == 0 && o.progress == 10,
          "progress 10 by default");
    CHECK(o.summary == 5, "summary every 5 s by default, got %g", o.summary);
    const char *every[] = {"--summary", "0", NULL};
    CHECK(parse(&o, every, out, err, sizeof out) == 0 && o.summary == 0, "--summary 0");
    const char *negative[] = {"--summary", "-1", NULL};
    CHECK(parse(&o, negative, out, err, sizeof out) < 0, "--summary -1 refused");
}

static void test_equals_spelling(void)
{
    printf("--opt=value spellings\n");
    sph_options o;
    const char *args[] = {"--threads=8", "--end=2", "--every=0.25", "--out=x=y", NULL};
    CHECK(parse(&o, args, out, err, sizeof out) == 0, "returns 0 (stderr: %s)", err);
    CHECK(strcmp(o.out_dir, "x=y") == 0, "out_dir x=y, got %s", o.out_dir);
    CHECK(o.threads == 8 && o.t_end == 2 && o.t_out == 0.25 && o.quiet == 0, "values");
}

static void test_given_twice(void)
{
    printf("an option with a value given twice is refused, naming it and both values\n");
    static const char *const cases[][5] = {
        {"--end", "1", "--end", "2"},       {"--out=a", "--out", "b"},
        {"--every", "1e-3", "--every=1e-3"}, {"--threads", "2", "--quiet", "--threads=4"},
        {"--restart", "a/checkpoint.bin", "--restart", "b/checkpoint.bin"},
        {"--frames", "0.1", "--frames", "0.2"}, {"--checkpoint=1", "--checkpoint=2"},
        {"--progress", "0", "--progress", "5"}, {"--partition", "2", "--partition", "3"},
    };
    static const char *const names[] = {"--end",     "--out",      "--every",
                                        "--threads", "--restart",  "--frames",
                                        "--checkpoint", "--progress", "--partition"};
    for (int c = 0; c < (int)(sizeof cases / sizeof cases[0]); c++) {
        sph_options o;
        const char *args[6] = {cases[c][0], cases[c][1], cases[c][2], cases[c][3], cases[c][4],
                               NULL};
        char want[64];
        snprintf(want, sizeof want, "beam: error: %s given twice (", names[c]);
        CHECK(parse(&o, args, out, err, sizeof out) == -1, "%s twice returns -1", names[c]);
        CHECK(strncmp(err, want, strlen(want)) == 0 && strstr(err, "): give it once\n"),
              "%s twice: '%s...', got: %.*s", names[c], want, (int)strcspn(err, "\n"), err);
    }
    sph_options o;
    const char *end[] = {"--end", "0.5", "--end=0.7", NULL};
    parse(&o, end, out, err, sizeof out);
    const char *both = "beam: error: --end given twice ('0.5', then '0.7'): give it once\n";
    CHECK(strncmp(err, both, strlen(both)) == 0, "both values named, got: %.*s",
          (int)strcspn(err, "\n"), err);
    const char *flags[] = {"--quiet", "--quiet", "--overwrite", "--overwrite", NULL};
    CHECK(parse(&o, flags, out, err, sizeof out) == 0 && o.quiet && o.overwrite,
          "a flag given twice is harmless (stderr: %s)", err);
}

static void test_help(void)
{
    printf("--help and -h print the usage to stdout and return 1\n");
    const char *spellings[] = {"--help", "-h"};
    for (int k = 0; k < 2; k++) {
        sph_options o;
        const char *args[] = {"--threads", "2", spellings[k], "--bogus", NULL};
        CHECK(parse(&o, args, out, err, sizeof out) == 1, "%s returns 1", spellings[k]);
        CHECK(strncmp(out, "usage: beam [options]", 21) == 0, "%s: usage on stdout",
              spellings[k]);
        CHECK(strstr(out, "--every T") && strstr(out, "beam_out"), "usage lists options");
        CHECK(err[0] == '\0', "%s: nothing on stderr", spellings[k]);
    }
}

/* Each list must be rejected with "beam: error: ..." and the usage on stderr. */
static void test_errors(void)
{
    printf("bad input: error message + usage on stderr, returns -1\n");
    static const char *const cases[][4] = {
        {"--bogus"},           {"-x"},                 {"results"},
        {"--threads"},         {"--out"},              {"--end"},
        {"--every", "--quiet"}, {"--threads", "0"},    {"--threads", "-2"},
        {"--threads", "abc"},  {"--threads", "4x"},    {"--threads=2.5"},
        {"--end", "-1"},       {"--end", "0"},         {"--end", "nan"},
        {"--end", "inf"},      {"--end", "1e400"},     {"--every="},
        {"--frames", "0"},     {"--frames", "-1"},
        {"--out="},            {"--quiet=1"},          {"--help=1"},
        {"--outdir", "x"},     {"--end", "1s"},        {"-hx"},
        {"--checkpoint", "0"}, {"--checkpoint"},       {"--restart="},
        {"--progress", "-1"},  {"--progress"},         {"--overwrite=1"},
        {"--restart", "a/checkpoint.bin", "--overwrite"},
    };
    int ncases = (int)(sizeof cases / sizeof cases[0]);
    for (int c = 0; c < ncases; c++) {
        sph_options o;
        const char *args[5] = {cases[c][0], cases[c][1], cases[c][2], cases[c][3], NULL};
        int rc = parse(&o, args, out, err, sizeof out);
        CHECK(rc == -1, "'%s %s' returns -1, got %d", args[0], args[1] ? args[1] : "", rc);
        CHECK(strncmp(err, "beam: error: ", 13) == 0 && strstr(err, "\nusage: beam"),
              "'%s': error and usage on stderr, got: %s", args[0], err);
        CHECK(out[0] == '\0', "'%s': nothing on stdout", args[0]);
    }
    printf("  %d bad inputs rejected; e.g.\n%.*s\n", ncases, (int)strcspn(err, "\n"), err);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    test_defaults();
    test_separate_values();
    test_checkpoints();
    test_outputs();
    test_equals_spelling();
    test_given_twice();
    test_help();
    test_errors();
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "ok", failures);
    return failures != 0;
}
