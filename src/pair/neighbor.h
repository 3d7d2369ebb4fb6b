/* neighbor.h - linked cells and a Verlet half list (Verlet 1967) with a skin.
 * Every build also sorts the particles by cell so that neighbours are close in
 * memory. Lees-Edwards: the cells across the sheared y boundary are chosen from
 * the current image offset, and the list is rebuilt when twice the largest
 * displacement plus the change of offset exceeds the skin. */
#ifndef DPD_NEIGHBOR_H
#define DPD_NEIGHBOR_H

#include <stddef.h>
#include <limits.h>
#include "system.h"

#define NL_MAX_THREADS 64   /* threads of the counting sort */
#define NL_MAX_CHUNKS 128   /* ranges of the list build */

typedef struct {
    double skin, cutoff;      /* cutoff = rc_max + skin */
    int nc[3];                /* cells per dimension (nc[2] = 1 in 2D) */
    double cw[3];             /* cell width */
    int brute_force;          /* box too small for cells: all pairs */
    int per_cutoff;           /* cells per cutoff length, R = 1 or 2 */
    int *cell_start;          /* ncells + 1 */
    int *tmpl_start;          /* without shear: cell c's stencil segments are tmpl[tmpl_start[c] ..] */
    void *tmpl;               /* (neighbor.c's Segment, made at the first build) */
    int *cell_of, *perm;
    int *tcount;              /* per-thread cell counts of the sort (ncells x threads) */
    int tcount_threads;
    int *start;               /* n + 1: pairs of i are nbr[start[i] .. start[i+1]) */
    int *nbr;
    size_t cap;
    double *x_ref;            /* positions at the last build (3 n) */
    int *img_ref;             /* y image counter at the last build */
    double offset_moved;      /* Lees-Edwards offset travelled since the build */
    double *scratch;          /* 3 n doubles for permutations */
    long builds;
    int n;
    /* per-chunk build buffers */
    int *tbuf[NL_MAX_CHUNKS];
    size_t tcap[NL_MAX_CHUNKS], tlen[NL_MAX_CHUNKS];
    int nchunks_used;
} NeighborList;

/* The most cells a list has (its cell indices are int). */
#define NEIGHBOR_MAX_CELLS ((size_t)INT_MAX - 1)
/* neighbor_init's status for a box with more cells of side >= cutoff than that. */
#define NEIGHBOR_TOO_MANY_CELLS (-2)

/* 0, -1 (out of memory) or NEIGHBOR_TOO_MANY_CELLS. */
int  neighbor_init(NeighborList *nl, const System *s, double skin);
void neighbor_free(NeighborList *nl);
/* Rebuild if needed (returns 1 if it rebuilt; particles may be reordered). */
int  neighbor_update(NeighborList *nl, System *s);
int  neighbor_build(NeighborList *nl, System *s);
void neighbor_note_shear(NeighborList *nl, double offset_increment);
size_t neighbor_pairs(const NeighborList *nl);

#endif
