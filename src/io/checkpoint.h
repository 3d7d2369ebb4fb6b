/* checkpoint.h - the whole state of a run at the end of a step, so that a
 * resumed run continues bit for bit: particles in their current (cell-sorted)
 * order with x, v, f, v_pred, image counters, ids and types; step, time and
 * the Lees-Edwards offset; the neighbour list as built (pair order and the
 * reference positions of its rebuild test), so the resumed run rebuilds at
 * the same steps and sums the forces in the same order; every measurement
 * accumulator (series, profile and RDF blocks, MSD origins and curves); the
 * m = 0 solver statistics with its CPU time per step (the solver's warm start
 * is v); the timers;
 * in rotation scenes the angular velocities, their prediction and the torques;
 * the rigid bodies of 3D spring colloids (centre, velocity, quaternion,
 * angular momentum, last reactions) with their extension record; the TCAF
 * time origins in flight and its accumulators; how many trajectory segment
 * files (output.h) were complete and their checksums. Format version 5 (checkpoint.c).
 * One binary file DIR/checkpoint.dpd, written to a temporary name, fsynced
 * and renamed; a 64-bit FNV-1a checksum over the content and a hash of the
 * scene as run reject a truncated file or one of another scene. */
#ifndef DPD_CHECKPOINT_H
#define DPD_CHECKPOINT_H

#include <stdint.h>
#include "system.h"
#include "neighbor.h"
#include "measure.h"
#include "blockavg.h"

#define CHECKPOINT_FILE "checkpoint.dpd"

/* Run-loop state outside System, NeighborList and Measure. */
typedef struct {
    double *timers;           /* ntimers wall-clock sums per phase */
    int ntimers;
    double cpu_used, wall_used, prod_wall_used;   /* before this process */
    long long steps_done;
    Series *solver[4];        /* the m = 0 solver series (nsolver of them) */
    int nsolver;
    Series *solver_cpu;       /* m = 0 scenes: the solver's CPU time per step (format 4); else NULL */
    long long *unconverged;
    struct Bonds *bonds;      /* 2D spring colloids' records (bonds.h), NULL if none */
    struct Colloids *colloids;   /* 3D spring colloids' rigid bodies (colloid.h), NULL if none */
    int threads;              /* threads of the run (the TCAF current is summed per thread) */
    int trajectory;           /* the scene writes a trajectory */
    int trajectory_segments;  /* trajectory segment files complete at this checkpoint (output.h) */
    long long trajectory_frames;   /* frames in them */
    uint64_t *trajectory_sums;     /* their checksums (format 5; writing: the Output's, reading: malloc'd) */
} CheckpointExtra;

uint64_t checkpoint_hash(const void *data, size_t len, uint64_t h);   /* FNV-1a; h = 0 to start */

/* Returns 0, or -1 with err set (nothing replaced: the previous checkpoint stays). */
int checkpoint_write(const char *dir, uint64_t scene_hash, const System *s, const NeighborList *nl,
                     const Measure *m, const CheckpointExtra *x, char *err, size_t errlen);
/* Returns 0 (state restored), 1 (no checkpoint in dir) or -1 with err set.
 * s, nl and m must be set up from the same scene (sizes are checked). */
int checkpoint_read(const char *dir, uint64_t scene_hash, System *s, NeighborList *nl,
                    Measure *m, CheckpointExtra *x, char *err, size_t errlen);

/* What a checkpoint file says of itself, without the scene it was written for: its format version,
 * particle count, and the step and time at which it was written (for progress reports: dpd
 * checkpoint-info, tools/in-flight). Its checksum is verified. 0, or -1 with err set (no such file,
 * not a dpd checkpoint, truncated, corrupt). */
typedef struct { uint32_t version, particles; uint64_t step; double time; } CheckpointInfo;
int checkpoint_info(const char *path, CheckpointInfo *ci, char *err, size_t errlen);

/* The final state by stable id, one row per particle: id, x, y, z (wrapped),
 * image counters, vx, vy, vz (10 columns, malloc'd; NULL if out of memory).
 * Stored in run.h5 as /results/final_state, so that two runs can be compared
 * bit for bit (h5diff) whatever their particle order. */
#define FINAL_STATE_COLUMNS "id\tx\ty\tz\timg_x\timg_y\timg_z\tvx\tvy\tvz"
double *checkpoint_final_state(const System *s);

#endif
