/* run_context.h - the state of one run, shared by its phases: run.c (init,
 * resume, the step loop, cleanup), run_output.c (summary, provenance, HDF5)
 * and stability.c (the blow-up check). Private to the app layer. */
#ifndef DPD_RUN_CONTEXT_H
#define DPD_RUN_CONTEXT_H

#include <stdint.h>
#include "run.h"
#include "scene.h"
#include "setup.h"
#include "neighbor.h"
#include "forces.h"
#include "measure.h"
#include "output.h"
#include "timers.h"
#include "overdamped.h"
#include "checkpoint.h"

typedef struct {
    double wall0, cpu0, timers[T_COUNT];
    double prod_wall0;        /* wall clock when production started */
    double prod_cpu0;         /* process CPU time then (< 0: unknown, a resumed run) */
    long long steps_done;
    int threads;
    long builds;
    long long resumed_at;     /* the step a resumed run continued from (-1: not resumed) */
} RunStats;

typedef struct {
    const RunOptions *opt;
    Scene sc;
    System s;
    Measure m;
    RunConfig rc;
    NeighborList nl;
    ForceWork fw;
    Output out;
    PairVirial pv;            /* the virial of measurement steps (its slabs in pv.Wbin) */
    OdSystem od;              /* m = 0 runs: the velocity system, its solver and statistics */
    OdStats ods_stats;
    RunStats st;
    CheckpointExtra cx;
    uint64_t scene_hash;      /* identifies the checkpoints of this scene as run */
    double vwall[DPD_MAX_TYPES][3];
    int walls_later;          /* frozen particles start moving with the production run */
    int show;                 /* progress on a terminal */
    int resumed;
    int virial_step;          /* the last inertial step computed the virial (a measurement step) */
    int loaded, set_up, opened;   /* what run_free releases: scene, system and buffers, output */
    int wrote_summary;        /* summary.tsv written: removed again if the run then fails */
    int lock;                 /* the output directory's lock (dirlock.h; -1: none) */
    double *thermal_cells;    /* the stability check's sums per cell (stability.c), 5 per cell */
    size_t thermal_ncells;
} Run;

/* run_output.c: summary.tsv, provenance.tsv, solver.tsv, the trajectory and
 * run.h5 of a completed run. Returns 0 or 4 (I/O failure). */
int run_write_results(Run *r);

/* stability.c: the blow-up check after a step; if it fails, the message (step,
 * quantity, value, a smaller dt) and the reason in INCOMPLETE. Returns 0, or
 * 3 (unstable). spins_only: the rotational temperature alone (the steps
 * between the full checks of a rotation scene). */
int run_stop_if_unstable(const Run *r, int spins_only);
/* stability.c: the cells of the thermal temperature for cells of side >= cut. */
size_t run_thermal_cells(const System *s, double cut);

#endif
