/* options.c — the command line of a generated program.
 *
 *   --out DIR  --threads N  --end T  --every T  --frames T  --checkpoint T  --restart FILE
 *   --overwrite  --quiet  --progress T  --summary T  --profile  --partition N  --no-stencil
 *   --whole-law
 *   --help | -h
 *
 * Options with a value also accept the spelling --opt=value; each may be given once (a
 * second value is refused rather than silently taking the place of the first). */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "options.h"

typedef enum {
    OPT_OUT, OPT_THREADS, OPT_END, OPT_EVERY, OPT_FRAMES, OPT_CHECKPOINT, OPT_RESTART,
    OPT_OVERWRITE, OPT_QUIET, OPT_PROGRESS, OPT_SUMMARY, OPT_PROFILE, OPT_PARTITION,
    OPT_NO_STENCIL, OPT_WHOLE_LAW, OPT_FIXED_THREADS, OPT_HELP,
    NOPT_IDS
} opt_id;

typedef struct {
    const char *name;
    opt_id id;
    int has_value;
} opt_info;

static const opt_info OPTIONS[] = {
    {"--out", OPT_OUT, 1},     {"--threads", OPT_THREADS, 1}, {"--end", OPT_END, 1},
    {"--every", OPT_EVERY, 1}, {"--frames", OPT_FRAMES, 1},   {"--checkpoint", OPT_CHECKPOINT, 1},
    {"--restart", OPT_RESTART, 1}, {"--overwrite", OPT_OVERWRITE, 0},
    {"--quiet", OPT_QUIET, 0},     {"--progress", OPT_PROGRESS, 1},
    {"--summary", OPT_SUMMARY, 1},
    {"--profile", OPT_PROFILE, 0}, {"--partition", OPT_PARTITION, 1},
    {"--no-stencil", OPT_NO_STENCIL, 0}, {"--whole-law", OPT_WHOLE_LAW, 0},
    {"--fixed-threads", OPT_FIXED_THREADS, 0},
    {"--help", OPT_HELP, 0},       {"-h", OPT_HELP, 0},
};
#define NOPTIONS (int)(sizeof OPTIONS / sizeof OPTIONS[0])

static const char *program_name(int argc, char **argv, const char *model)
{
    if (argc < 1 || !argv[0] || !argv[0][0])
        return model;
    const char *slash = strrchr(argv[0], '/');
    return slash ? slash + 1 : argv[0];
}

static void usage(FILE *f, const char *prog, const char *model)
{
    fprintf(f,
            "usage: %s [options]\n"
            "Runs the SPH model %s.\n"
            "\n"
            "options:\n"
            "  --out DIR     output folder (default: %s_out)\n"
            "  --threads N   the most OpenMP threads the steps run on, at most 4 per core\n"
            "                (default: OpenMP's count); fewer while other programs hold\n"
            "                the cores, and said at the end\n"
            "  --fixed-threads  the thread count throughout, never fewer (a benchmark's)\n"
            "  --end T       end time in seconds (default: the model's)\n"
            "  --every T     output interval in seconds (default: the model's)\n"
            "  --frames T    interval of the particle files (default: every output; the\n"
            "                energies and measurements are written at every output; at\n"
            "                most 10^5 frames up to the end time)\n"
            "  --checkpoint T  write the state to DIR/checkpoint.bin every T seconds of\n"
            "                simulated time (at output times) and at the end of the run\n"
            "  --restart FILE  resume the run of FILE, a checkpoint of this model, in its\n"
            "                folder (unless --out is given) to the end time\n"
            "  --overwrite   replace the outputs of an earlier run in the output folder\n"
            "                (without it such a folder is refused)\n"
            "  --quiet       no progress lines\n"
            "  --progress T  a progress line every T seconds when the output is not a\n"
            "                terminal (a log; default 10, 0: none)\n"
            "  --summary T   while running, write summary.json and summary.html again at\n"
            "                an output at most every T seconds (default 5, 0: every output)\n"
            "  --profile     the time each pass of the step takes, printed at the end and\n"
            "                written to summary.json\n"
            "  --partition N  report how each body would be decomposed for N processes\n"
            "                (particles and halo per part) and exit, without running\n"
            "  --no-stencil  every pair through the neighbour lists, none through the\n"
            "                lattice stencil (2D) or the offset blocks (3D) (the same\n"
            "                sums, in another order: a check)\n"
            "  --whole-law   every particle through its whole material law: no fast path\n"
            "                that leaves out a return map for particles that do not yield\n"
            "                (the same stresses: a check)\n"
            "  -h, --help    show this help and exit\n"
            "Each option may be given once.\n",
            prog, model, model);
}

/* Prints "PROG: error: MSG ARG" and the usage to stderr; returns -1. */
static int fail(const char *prog, const char *model, const char *msg, const char *arg)
{
    fprintf(stderr, "%s: error: %s%s\n", prog, msg, arg);
    usage(stderr, prog, model);
    return -1;
}

/* The option arg names, or NULL; *inline_value is set to the text after '=', if any. */
static const opt_info *find_option(const char *arg, const char **inline_value)
{
    for (int k = 0; k < NOPTIONS; k++) {
        size_t len = strlen(OPTIONS[k].name);
        if (strncmp(arg, OPTIONS[k].name, len) != 0)
            continue;
        if (arg[len] == '\0') {
            *inline_value = NULL;
            return &OPTIONS[k];
        }
        if (arg[len] == '=' && arg[1] == '-') {
            *inline_value = arg + len + 1;
            return &OPTIONS[k];
        }
    }
    return NULL;
}

/* A positive integer / finite positive number; 0 on success. */
static int parse_positive_int(const char *s, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end || errno || v <= 0 || v > 1000000)
        return -1;
    *out = (int)v;
    return 0;
}

static int parse_double(const char *s, double *out, double lowest, int with_lowest)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end || errno || !isfinite(v) || v < lowest || (v == lowest && !with_lowest))
        return -1;
    *out = v;
    return 0;
}

static int parse_positive_double(const char *s, double *out)
{
    return parse_double(s, out, 0, 0);
}

/* Stores the value of option id; 0 on success, -1 (message printed) otherwise. */
static int set_value(sph_options *o, opt_id id, const char *name, const char *value,
                     const char *prog, const char *model)
{
    int bad = 0;
    switch (id) {
    case OPT_OUT:
        bad = value[0] == '\0';
        o->out_dir = value;
        break;
    case OPT_THREADS: bad = parse_positive_int(value, &o->threads); break;
    case OPT_PARTITION: bad = parse_positive_int(value, &o->partition); break;
    case OPT_END:     bad = parse_positive_double(value, &o->t_end); break;
    case OPT_EVERY:   bad = parse_positive_double(value, &o->t_out); break;
    case OPT_FRAMES:  bad = parse_positive_double(value, &o->t_frames); break;
    case OPT_CHECKPOINT: bad = parse_positive_double(value, &o->t_checkpoint); break;
    case OPT_PROGRESS: bad = parse_double(value, &o->progress, 0, 1); break;
    case OPT_SUMMARY: bad = parse_double(value, &o->summary, 0, 1); break;
    case OPT_RESTART:
        bad = value[0] == '\0';
        o->restart = value;
        break;
    default: break;
    }
    if (!bad)
        return 0;
    fprintf(stderr, "%s: error: invalid value '%s' for %s%s\n", prog, value, name,
            id == OPT_OUT || id == OPT_RESTART ? ""
            : id == OPT_THREADS                ? " (expected a positive integer)"
            : id == OPT_PROGRESS || id == OPT_SUMMARY ? " (expected seconds, 0 or more)"
                                               : " (expected a positive number)");
    usage(stderr, prog, model);
    return -1;
}

/* An option with a value given a second time (given[id] holds its first value): refused, with
 * both values, since either could be the one meant (-1); otherwise its value is noted (0). */
static int given_twice(const char **given, const opt_info *opt, const char *value,
                       const char *prog, const char *model)
{
    const char *first = given[opt->id];
    if (!first) {
        given[opt->id] = value;
        return 0;
    }
    fprintf(stderr, "%s: error: %s given twice ('%s', then '%s'): give it once\n", prog,
            opt->name, first, value);
    usage(stderr, prog, model);
    return -1;
}

/* "<model>_out".  The string is kept for the life of the program and reused while the
 * model name stays the same. */
static const char *default_out_dir(const char *model)
{
    static char *dir = NULL;
    size_t len = strlen(model);
    if (dir && strncmp(dir, model, len) == 0 && strcmp(dir + len, "_out") == 0)
        return dir;
    char *s = malloc(len + 5);
    if (!s)
        return "sph_out";
    memcpy(s, model, len);
    memcpy(s + len, "_out", 5);
    dir = s; /* an earlier string may still be in use by an earlier sph_options */
    return dir;
}

/* The folder of a file ("." for a bare name), kept for the life of the program (an earlier
 * one may still be in use by an earlier sph_options). */
static const char *folder_of(const char *file)
{
    const char *slash = strrchr(file, '/');
    if (!slash)
        return ".";
    const size_t len = slash == file ? 1 : (size_t)(slash - file);
    char *dir = malloc(len + 1);
    if (!dir)
        return ".";
    memcpy(dir, file, len);
    dir[len] = '\0';
    return dir;
}

int sph_parse_options(sph_options *o, const char *model_name, int argc, char **argv)
{
    const char *model = model_name && model_name[0] ? model_name : "sph";
    const char *prog = program_name(argc, argv, model);
    *o = (sph_options){.out_dir = NULL, .threads = 0, .t_end = -1, .t_out = -1, .t_frames = -1,
                       .t_checkpoint = -1, .restart = NULL, .quiet = 0, .profile = 0,
                       .overwrite = 0, .progress = 10, .summary = 5};
    const char *given[NOPT_IDS] = {NULL}; /* each option's value, once given */
    for (int i = 1; i < argc; i++) {
        const char *value;
        const opt_info *opt = find_option(argv[i], &value);
        if (!opt)
            return fail(prog, model, argv[i][0] == '-' ? "unknown option " :
                                     "unexpected argument ", argv[i]);
        if (opt->id == OPT_HELP && !value) {
            usage(stdout, prog, model);
            return 1;
        }
        if (!opt->has_value) {
            if (value)
                return fail(prog, model, "option takes no value: ", argv[i]);
            if (opt->id == OPT_QUIET)
                o->quiet = 1;
            else if (opt->id == OPT_OVERWRITE)
                o->overwrite = 1;
            else if (opt->id == OPT_NO_STENCIL)
                o->no_stencil = 1;
            else if (opt->id == OPT_FIXED_THREADS)
                o->fixed_threads = 1;
            else if (opt->id == OPT_WHOLE_LAW)
                o->whole_law = 1;
            else
                o->profile = 1;
            continue;
        }
        const char *next_value;
        if (!value && (i + 1 >= argc || find_option(argv[i + 1], &next_value)))
            return fail(prog, model, "missing value for ", opt->name);
        value = value ? value : argv[++i];
        if (given_twice(given, opt, value, prog, model) ||
            set_value(o, opt->id, opt->name, value, prog, model))
            return -1;
    }
    if (o->restart && o->overwrite) /* (it would remove the files it continues) */
        return fail(prog, model, "--overwrite with --restart: a resumed run continues the "
                                 "files of its folder", "");
    if (!o->out_dir)
        o->out_dir = o->restart ? folder_of(o->restart) : default_out_dir(model);
    return 0;
}
