/* run.h - one simulation from a scene file to its output directory. */
#ifndef DPD_RUN_H
#define DPD_RUN_H

typedef struct {
    const char *scene;
    char **overrides;
    int noverrides;
    const char *outdir;
    int threads;              /* 0: OpenMP default */
    const char *command_line;
    int quiet;
    long long checkpoint_every;   /* > 0: write DIR/checkpoint.dpd every this many steps */
    double checkpoint_wall;       /* ... but not sooner than this many wall seconds after the last one */
    int resume;                   /* continue from DIR/checkpoint.dpd if there is one */
    int dry_run;                  /* validate and set up the scene, print its size, run nothing */
} RunOptions;

/* Exit status: 0 success, 2 bad input, 3 unstable run, 4 I/O failure,
 * 128 + signal after SIGINT or SIGTERM (checkpoint written, run incomplete). */
int run_scene(const RunOptions *opt);

#endif
