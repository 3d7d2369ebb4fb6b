/* overdamped.h - velocity solve of strongly overdamped (m = 0) DPD
 * (Phan-Thien, Mai-Duy, Khoo & Duong-Hong 2016, "Strongly overdamped
 * dissipative particle dynamics for fluid-solid systems", sections 2-3).
 *
 * With m = 0 the momentum equation of every mobile particle i is a force
 * balance (eq. 14). Collecting the unknown velocities of the Ns mobile
 * particles gives the sparse symmetric linear system A v = f (eq. 15) with
 * dim x dim blocks (eqs 16-18):
 *   A_ii = sum_{j, all}    gamma w_D e_ij e_ij^T
 *   A_ij = -gamma w_D e_ij e_ij^T                     (j mobile)
 *   f_i  = sum_j a w_C e_ij + sum_j sigma w_R theta_ij e_ij / sqrt(dt)
 *          + body force of i + sum_{j frozen} gamma w_D e_ij e_ij^T v_j
 * (noise discretised as theta / sqrt(dt); under Lees-Edwards shear the known
 * velocity offset of a sheared image is moved to f as well).
 * A is a weighted graph Laplacian plus the couplings to frozen particles:
 * symmetric positive semi-definite, definite when the frozen particles pin
 * every rigid translation of the fluid.
 *
 * Storage: block CSR over the mobile particles, rows in particle order; per row
 * its diagonal block (and inverse) and the off-diagonal blocks of the pairs
 * listed under that row in the Verlet half list, so every pair is stored once
 * and A_ji = A_ij^T = A_ij by construction. Blocks are 3x3 row-major and
 * vectors 3 doubles per row even in 2D (z unused, kept zero).
 *
 * Solvers (all start from the current s->v of the mobile particles):
 *   OD_SCHEME1            block Jacobi / Picard, eqs 23-26
 *   OD_SCHEME2_PAPER      Scheme 2 as published: centre-of-mass frame (eq. 35,
 *                         right side shifted by -F~/Ns, eq. 45) plus Wielandt
 *                         deflation (eqs 41-46). Its fixed point has zero mean
 *                         fluid velocity and is NOT the solution of A v = f
 *                         whenever the frozen particles carry a net reaction
 *                         (e.g. a body force drives fluid past them).
 *   OD_SCHEME2_CONSISTENT Jacobi sweep + uniform velocity correction that
 *                         zeroes the net residual force on the fluid (a
 *                         two-level method whose coarse space is the rigid
 *                         translation); converges to the solution of A v = f.
 *   OD_PCG                conjugate gradients, block-Jacobi preconditioner.
 *   OD_PCG_2LEVEL         conjugate gradients, additive two-level
 *                         preconditioner: block Jacobi plus an exact solve on
 *                         a coarse space of piecewise-constant velocities over
 *                         square cells of side 2 rc (aggregation), which
 *                         removes the slow long-wavelength (shear) modes.
 * Stopping rules: OD_STOP_CHANGE, eq. 27: |v^l - v^{l-1}| < tol |v^l|;
 *                 OD_STOP_RESIDUAL: |f - A v| < tol |f|.
 */
#ifndef DPD_OVERDAMPED_H
#define DPD_OVERDAMPED_H

#include <stdio.h>
#include "system.h"
#include "neighbor.h"
#include "blockavg.h"
#include "table.h"

typedef enum {
    OD_SCHEME1 = 0,
    OD_SCHEME2_PAPER = 1,
    OD_SCHEME2_CONSISTENT = 2,
    OD_PCG = 3,
    OD_PCG_2LEVEL = 4         /* PCG, block Jacobi + aggregation coarse space */
} OdSolver;

typedef enum {
    OD_STOP_CHANGE = 0,       /* eq. 27 */
    OD_STOP_RESIDUAL = 1
} OdStop;

typedef struct {
    int dim;
    int n;                    /* particles of the System at assembly */
    int nm;                   /* mobile particles = rows (Ns of the paper) */
    int *row_of;              /* n: row of particle i, -1 if frozen */
    int *part_of;             /* nm: particle of each row */
    double *diag;             /* nm x 9: A_ii */
    double *dinv;             /* nm x 9: A_ii^{-1} (pseudo-inverse if singular) */
    int *ostart;              /* nm + 1: off-diagonal blocks of row r are ostart[r] .. ostart[r+1] */
    int *ocol;                /* column (row index of the partner) of each block */
    double *oblk;             /* 9 per block: A_rc = A_cr */
    double *f;                /* nm x 3: right side, eq. 18 */
    double *wrow;             /* nm x 9: frozen couplings of each row, sum_{j frozen} gamma w_D e e^T */
    double wall[9];           /* sum of wrow over rows = 1^T A 1 (per block) */
    double wall_inv[9];       /* its inverse (pseudo-inverse if singular) */
    double fbody[3];          /* sum of the body forces in f */
    int s2_exclude_body;      /* OD_SCHEME2_PAPER: 1 = F~ without body forces (eq. 31 verbatim);
                               * 0 (default) = F~ is the fluid's whole net force */
    double fnorm;             /* |f| */
    int n_singular;           /* rows whose diagonal block is singular (e.g. one neighbour) */
    size_t cap_rows, cap_blk; /* allocated sizes */
    double *work;             /* 6 x n x 3 scratch: slots 0-3 solvers, 4 od_solve */
    /* two-level preconditioner (OD_PCG_2LEVEL), built on demand per assembly */
    int *agg;                 /* nm: coarse cell of each row */
    int ncoarse;              /* coarse unknowns = cells x dim */
    double *coarse;           /* ncoarse^2: Cholesky factor of P^T A P */
    size_t cap_coarse;
    int coarse_ok;            /* factor valid for the current assembly */
} OdSystem;

typedef struct {
    int iterations;           /* sweeps / CG iterations done */
    int matvecs;              /* applications of A (or of its off-diagonal part) */
    double change;            /* final |v^l - v^{l-1}| / |v^l| (PCG under the residual rule: NaN after a breakdown, where it is not computed) */
    double rel_residual;      /* final |f - A v| / |f| */
    int converged;            /* 1 if the stopping rule was met within max_iter */
} OdResult;

void od_init(OdSystem *od);
void od_free(OdSystem *od);

/* Build A and f (eqs 16, 18) from the current positions, frozen velocities in
 * s->v, noise of step s->step. Returns 0, or -1 on allocation failure. */
int od_assemble(OdSystem *od, const System *s, const NeighborList *nl);

/* Solve A v = f with the chosen scheme, warm-started from s->v; writes the
 * solution into s->v for mobile particles (frozen ones untouched). */
OdResult od_solve(OdSystem *od, System *s, OdSolver solver, OdStop stop,
                  double tol, int max_iter);

/* Same on a packed vector v (nm x 3), in place; v holds the warm start. */
OdResult od_solve_vec(OdSystem *od, double *v, OdSolver solver, OdStop stop,
                      double tol, int max_iter);

/* Fixed point of the published Scheme 2 (A v = f - 1 F~/Ns with zero mean
 * fluid velocity), by dim + 1 PCG solves to residual tol; v (nm x 3) holds
 * the warm start for A^{-1} f and receives the result. 0, or -1 (no frozen
 * contact, or out of memory). */
int od_scheme2_paper_fixed_point(OdSystem *od, double *v, double tol);

/* y = A v on packed vectors (nm x 3). */
void od_matvec(const OdSystem *od, const double *v, double *y);

/* |f - A v| / |f| (|f - A v| if f = 0). */
double od_residual(const OdSystem *od, const double *v);

/* Pack / unpack the mobile velocities of s (nm x 3). */
void od_gather(const OdSystem *od, const System *s, double *v);
void od_scatter(const OdSystem *od, System *s, const double *v);

/* ------------------------------------------------------ the m = 0 step */

/* The solver a scene asks for (setup.c reads it). */
typedef struct {
    OdSolver solver;
    OdStop stop;
    double tol;
    int max_iter;
    int allow_unconverged;    /* a step whose solve did not converge is kept */
    double reference_tol;     /* > 0: also solve by PCG to this residual and record the true error */
    int reference_own;        /* published Scheme 2: error against its own fixed point, not A v = f */
} OdSettings;

/* Solver statistics of the production steps, one entry per step. */
typedef struct {
    Series iterations, residual, seconds, true_error;
    Series cpu_seconds;       /* process CPU time of assembly + solve (robust to a shared machine) */
    long long unconverged;
    double *sol, *ref;        /* packed solution and reference (3 n each) */
} OdStats;

/* Scratch for n particles; 0, or -1 if out of memory. */
int  od_stats_init(OdStats *st, int n);
void od_stats_free(OdStats *st);

/* The velocities of the step from A v = f, assembled by od_assemble (eqs
 * 15-18, noise of this step; springs may have added to f since), then
 * v_pred = v. record: a production step (statistics kept); t0, c0: wall and
 * CPU time when the assembly started. Returns 0, or -1 if the solve did not
 * converge and the scene does not allow it (the message printed). */
int od_step_solve(OdSystem *od, System *s, const OdSettings *set, OdStats *st, int record,
                  double t0, double c0);

/* r += v dt (eq. 28) for every particle (frozen ones at their wall
 * velocity), the Lees-Edwards offset on, the wrap; s->nonfinite counts the
 * positions made non-finite. */
void od_move(System *s);

/* The table solver.tsv (per step, handed to io/: table.h) and the solver_* rows
 * of the summary. 0, or -1 (out of memory). */
int od_stats_write(const OdStats *st, FILE *summary, Tables *ts, int nblocks);

#endif
