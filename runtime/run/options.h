/* options.h — the command line of a generated program (options.c). */
#ifndef SPHRT_RUN_OPTIONS_H
#define SPHRT_RUN_OPTIONS_H

/* Command-line options of a generated program. */
typedef struct {
    const char *out_dir;  /* --out DIR (default "<model>_out") */
    int threads;          /* --threads N (0 = OpenMP default): the most the steps run on */
    int fixed_threads;    /* --fixed-threads: that count throughout, never fewer */
    int partition;        /* --partition N: report the decomposition and exit (0: run) */
    double t_end;         /* --end T   (< 0: model's) */
    double t_out;         /* --every T (< 0: model's) */
    double t_frames;      /* --frames T: particle files every T (< 0: every output) */
    double t_checkpoint;  /* --checkpoint T: the state every T (< 0: none) */
    const char *restart;  /* --restart FILE: resume from this checkpoint (NULL: none) */
    int quiet;            /* --quiet */
    int profile;          /* --profile: the time of each pass of the step */
    int no_stencil;       /* --no-stencil: no lattice stencil in the pair passes */
    int whole_law;        /* --whole-law: no fast path of the material laws */
    int overwrite;        /* --overwrite: replace the outputs of an earlier run in out_dir */
    double progress;      /* --progress T: a progress line every T s in a log (0: none) */
    double summary;       /* --summary T: summary.json and .html again at an output at most
                           * every T s of wall time while running (0: every output) */
} sph_options;
/* Parses argv; prints usage and returns -1 on a bad option (the caller exits 2);
 * returns 1 after printing --help, 0 otherwise. */
int sph_parse_options(sph_options *o, const char *model_name, int argc, char **argv);

#endif
