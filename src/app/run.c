/* run.c - one simulation: the run context (init, resume, the step loop,
 * the results, cleanup). The loop reads like the algorithm, as CoMD's
 * timestep(): an inertial step predicts (Groot & Warren 1997 eq. 16),
 * applies the constraints, updates the neighbours, computes the forces and
 * corrects; an m = 0 step (Phan-Thien et al. 2016) samples the solved state,
 * moves (eq. 28), applies the constraints, updates the neighbours and solves
 * for the next velocities (eqs 15-18). Then both measure, check stability,
 * write frames and checkpoints. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <errno.h>
#include <signal.h>
#include <unistd.h>
#include <sys/stat.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "run_context.h"
#include "integrator.h"
#include "dirlock.h"

static int mkdir_p(const char *dir)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", dir);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0775) && errno != EEXIST) return -1;
        *p = '/';
    }
    if (mkdir(buf, 0775) && errno != EEXIST) return -1;
    return access(buf, W_OK);
}

static int threads_in_use(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

static void progress(long long done, long long total, double t0, int force)
{
    static double last = 0.0;
    const double now = wall_now();
    if (!force && now - last < 1.0) return;
    last = now;
    const double rate = done / (now - t0 + 1e-12);
    const double eta = rate > 0 ? (total - done) / rate : 0.0;
    fprintf(stderr, "\rstep %lld/%lld  %.0f steps/s  ETA %02d:%02d:%02d ", done, total, rate,
            (int)(eta / 3600), (int)fmod(eta / 60, 60), (int)fmod(eta, 60));
    if (force) fputc('\n', stderr);
}

/* Start-up flows: frozen particles rest during equilibration and take their
 * wall velocity from production step 0 (walls_start_at_production). */
static void set_walls_moving(System *s, const double (*vwall)[3], int moving)
{
    for (int t = 0; t < s->ntypes; t++)
        if (s->types[t].frozen)
            for (int d = 0; d < 3; d++) s->types[t].wall_velocity[d] = moving ? vwall[t][d] : 0.0;
    for (int i = 0; i < s->n; i++)
        if (s->types[s->type[i]].frozen)
            for (int d = 0; d < 3; d++) s->v[3 * i + d] = s->v_pred[3 * i + d] = s->types[s->type[i]].wall_velocity[d];
}

/* ------------------------------------------------------------ the steps */

/* Forces of the current positions: pairs (and body forces), springs, rigid
 * colloids (eq. 30); pv != NULL: their virial too. prod: production step (< 0:
 * equilibration). */
static void compute_forces(Run *r, long long prod, PairVirial *pv)
{
    forces_compute(&r->s, &r->nl, &r->fw, pv);
    if (MOD_ON(r->rc.bonds)) { bonds_forces(r->rc.bonds, &r->s, pv); bonds_sample(r->rc.bonds, &r->s, prod); }
    if (MOD_ON(r->rc.colloids)) { r->rc.colloids->record = prod >= 0; colloid_step(r->rc.colloids, &r->s, pv); }
}

/* The m = 0 velocities of the current positions: A v = f (eqs 15-18), with
 * the springs' forces in f (eqs 50-51). 0, 3 (did not converge), 4 (memory). */
static int solve_velocities(Run *r)
{
    const int record = (long long)r->s.step >= r->rc.equilibration;   /* production steps only */
    const double t0 = wall_now(), c0 = cpu_now();
    if (od_assemble(&r->od, &r->s, &r->nl)) { fprintf(stderr, "dpd: out of memory\n"); return 4; }
    if (r->rc.bonds) bonds_rhs(r->rc.bonds, &r->s, &r->od);
    if (od_step_solve(&r->od, &r->s, &r->rc.od, &r->ods_stats, record, t0, c0) == 0) return 0;
    /* a solve that diverged within the step (a blow-up the stability check has not seen yet: the
     * velocities it left are what ran away) gets the blow-up's message and a smaller dt; otherwise
     * the solver's failure is the reason on record */
    if (run_stop_if_unstable(r, 0)) return 3;
    char why[160];
    snprintf(why, sizeof why, "the m = 0 solve did not converge at step %llu\n", (unsigned long long)r->s.step);
    write_file_atomic(r->opt->outdir, "INCOMPLETE", why, strlen(why));
    return 3;
}

/* After a move: the walls, the check for a non-finite position (before it
 * spreads), the neighbour list. 0, 3 or 4. */
static int after_move(Run *r, double *t)
{
    integrate_confine(&r->s, r->rc.confine_axis, r->rc.confine_lo, r->rc.confine_hi);
    int status = r->s.nonfinite ? run_stop_if_unstable(r, 0) : 0;
    if (status) return status;
    t[1] = wall_now();
    if (neighbor_update(&r->nl, &r->s) < 0) { fprintf(stderr, "dpd: out of memory\n"); return 4; }
    t[2] = wall_now();
    return 0;
}

/* One Groot-Warren step: predict, constraints, neighbours, forces, correct,
 * measure. t[0..4]: the phase times. */
static int step_inertial(Run *r, double *t)
{
    neighbor_note_shear(&r->nl, integrate_predict(&r->s));
    int status = after_move(r, t);
    if (status) return status;
    const long long prod = (long long)r->s.step - r->rc.equilibration;
    const int want = prod >= 0 && measure_wants_virial(&r->m, prod);
    r->virial_step = want;
    compute_forces(r, prod, want ? &r->pv : NULL);
    t[3] = wall_now();
    integrate_correct(&r->s);
    t[4] = wall_now();
    if (prod >= 0) measure_sample(&r->m, &r->s, &r->nl, want ? &r->pv : NULL, prod);
    return 0;
}

/* One m = 0 step: the velocities of step k are known, so sample them (with
 * the virial of the solved state), then move, constraints, neighbours and the
 * velocities of step k + 1. */
static int step_overdamped(Run *r, double *t)
{
    const long long prod = (long long)r->s.step - r->rc.equilibration;
    const int want = prod >= 0 && measure_wants_virial(&r->m, prod);
    if (want) forces_compute(&r->s, &r->nl, &r->fw, &r->pv);
    if (want && r->rc.bonds) bonds_forces(r->rc.bonds, &r->s, &r->pv);   /* spring virial */
    if (prod >= 0) measure_sample(&r->m, &r->s, &r->nl, want ? &r->pv : NULL, prod);
    if (prod >= 0 && r->rc.bonds) bonds_sample(r->rc.bonds, &r->s, prod);
    od_move(&r->s);
    int status = after_move(r, t);
    if (status) return status;
    status = solve_velocities(r);
    t[3] = t[4] = wall_now();
    return status;
}

/* ------------------------------------------------------ the run context */

/* The scene read and set up; 0 or 2 (bad input). */
static int run_load(Run *r)
{
    const RunOptions *opt = r->opt;
    r->loaded = 1;
    if (scene_load(&r->sc, opt->scene, opt->overrides, opt->noverrides) || setup_from_scene(&r->sc, &r->s, &r->m, &r->rc)) {
        fprintf(stderr, "dpd: %s\n", r->sc.error);
        return 2;
    }
    r->set_up = 1;
    return 0;
}

/* The output directory with its INCOMPLETE marker, the buffers, the first
 * neighbour list, the HDF5 file. 0 or 4. */
static int run_open(Run *r)
{
    const RunOptions *opt = r->opt;
    System *s = &r->s;
    if (mkdir_p(opt->outdir)) {
        fprintf(stderr, "dpd: cannot create or write the output directory '%s': %s\n", opt->outdir, strerror(errno));
        return 4;
    }
    /* one writer per directory (two would mix their files, and with HDF5_USE_FILE_LOCKING=FALSE
     * both could end with status 0) */
    char holder[600];
    r->lock = dirlock_take(opt->outdir, holder, sizeof holder);
    if (r->lock == -1) {
        fprintf(stderr, "dpd: '%s' is in use by another run: %s (lock %s/%s); wait for it to end, or stop it\n",
                opt->outdir, holder, opt->outdir, DIRLOCK_FILE);
        return 4;
    }
    if (r->lock == -2)
        fprintf(stderr, "dpd: warning: running without the output directory's lock (%s)\n", holder);
    /* an earlier result goes first (no byte of it may stay beside a run that fails; this also
     * frees its space for the marker); then the marker */
    if (output_remove_results(opt->outdir)) {
        fprintf(stderr, "dpd: cannot remove the earlier result in '%s': %s\n", opt->outdir, strerror(errno));
        return 4;
    }
    if (write_file_atomic(opt->outdir, "INCOMPLETE", "run started\n", 12)) {
        fprintf(stderr, "dpd: cannot write in '%s': %s\n", opt->outdir, strerror(errno));
        return 4;
    }
    r->st = (RunStats){.wall0 = wall_now(), .cpu0 = cpu_now(), .threads = threads_in_use(), .resumed_at = -1};
    const int nbins = r->m.prof_on ? r->m.prof_bins : 0;
    r->pv = (PairVirial){.bin_axis = r->m.prof_axis, .nbins = nbins};
    od_init(&r->od);
    if (neighbor_init(&r->nl, s, r->rc.skin) == NEIGHBOR_TOO_MANY_CELLS) {
        const Box *b = &s->box;
        const double cut = s->rc_max + r->rc.skin;
        double cells = 1.0;
        for (int d = 0; d < b->dim; d++) cells *= floor(b->L[d] / cut);
        fprintf(stderr, "dpd: %s: key 'box': the box %g x %g", opt->scene, b->L[0], b->L[1]);
        if (b->dim == 3) fprintf(stderr, " x %g", b->L[2]);
        fprintf(stderr, " needs %.3g neighbour cells of side >= the largest rc + skin = %g, more than the %zu "
                "a cell list indexes; use a smaller box (or fewer, larger cells would be needed)\n",
                cells, cut, NEIGHBOR_MAX_CELLS);
        return 2;
    }
    if (forces_init(&r->fw, s, nbins) || measure_init(&r->m, s)
        || neighbor_build(&r->nl, s) || od_stats_init(&r->ods_stats, s->n)
        || (nbins > 0 && !(r->pv.Wbin = calloc((size_t)nbins * PAIR_PARTS * 9, sizeof(double))))
        || (r->rc.max_thermal_ratio > 0.0 && !r->rc.overdamped
            && !(r->thermal_cells = malloc((r->thermal_ncells = run_thermal_cells(s, s->rc_max + r->rc.skin)) * 5 * sizeof(double))))) {
        fprintf(stderr, "dpd: out of memory\n");
        return 4;
    }
    if (output_open(&r->out, opt->outdir, s, r->rc.trajectory_every)) {
        fprintf(stderr, "dpd: cannot create the HDF5 file in '%s' (disk full or not writable?)\n", opt->outdir);
        return 4;
    }
    r->opened = 1;
    return 0;
}

/* The bodies join the measurements, the walls' velocities are kept for a
 * start-up flow, the checkpoint record is laid out. */
static void run_connect(Run *r)
{
    RunConfig *rc = &r->rc;
    System *s = &r->s;
    if (rc->colloids && r->m.tcaf.on && r->m.tcaf.p.include_bodies)   /* the bodies' momentum joins the TCAF */
        tcaf_set_bodies(&r->m.tcaf, s, rc->colloids->ncol, rc->colloids->R, rc->colloids->V, rc->colloids->p.mass);
    if (rc->colloids) r->m.colloids = rc->colloids;   /* the bodies' momentum flux joins the stress */
    for (int t = 0; t < s->ntypes; t++) memcpy(r->vwall[t], s->types[t].wall_velocity, sizeof r->vwall[t]);
    r->walls_later = MOD_ON(rc->walls_start_at_production && rc->equilibration > 0);
    char *scene_txt = scene_text(&r->sc);   /* the scene as run identifies its checkpoints */
    r->scene_hash = checkpoint_hash(scene_txt ? scene_txt : "", scene_txt ? strlen(scene_txt) : 0, 0);
    free(scene_txt);
    OdStats *ss = &r->ods_stats;
    r->cx = (CheckpointExtra){.timers = r->st.timers, .ntimers = T_COUNT, .nsolver = 4,
                              .solver = {&ss->iterations, &ss->residual, &ss->seconds, &ss->true_error},
                              .solver_cpu = rc->overdamped ? &ss->cpu_seconds : NULL,
                              .unconverged = &ss->unconverged, .bonds = rc->bonds, .colloids = rc->colloids,
                              .threads = r->st.threads, .trajectory = rc->trajectory_every > 0};
}

/* --resume: the state, series and clocks of the checkpoint, if there is one;
 * a fresh run removes the trajectory segments of an earlier one. 0 or 2. */
static int run_resume(Run *r)
{
    char err[1400];
    if (r->opt->resume) {
        const int k = checkpoint_read(r->opt->outdir, r->scene_hash, &r->s, &r->nl, &r->m, &r->cx, err, sizeof err);
        if (k < 0) { fprintf(stderr, "dpd: %s\n", err); return 2; }
        if (k == 0 && output_segments_resume(&r->out, r->cx.trajectory_segments, r->cx.trajectory_frames,
                                             r->cx.trajectory_sums, err, sizeof err)) {
            fprintf(stderr, "dpd: %s\n", err);
            return 2;
        }
        if (k == 0) {
            RunStats *st = &r->st;
            r->resumed = 1;
            st->resumed_at = (long long)r->s.step;
            st->cpu0 = cpu_now() - r->cx.cpu_used;
            st->wall0 = wall_now() - r->cx.wall_used;
            st->prod_wall0 = wall_now() - r->cx.prod_wall_used;
            st->steps_done = r->cx.steps_done;
            if (!r->opt->quiet) fprintf(stderr, "dpd: resuming %s at step %llu\n", r->opt->outdir, (unsigned long long)r->s.step);
            r->cx.threads = st->threads;
            return 0;
        }
    }
    if (output_segments_resume(&r->out, 0, 0, NULL, err, sizeof err)) { fprintf(stderr, "dpd: %s\n", err); return 2; }
    return 0;
}

/* Before the first step: the forces (or m = 0 velocities) of the initial
 * state, which a resumed run has from its checkpoint. 0, 3 or 4. */
static int run_start(Run *r)
{
    int status = 0;
    if (r->walls_later)   /* walls that start with the production run: still at rest before it */
        set_walls_moving(&r->s, (const double (*)[3])r->vwall, r->resumed && r->s.step > (uint64_t)r->rc.equilibration);
    if (r->resumed) {
        /* forces, v_pred and the m = 0 velocities of this step come from the checkpoint */
    } else if (MOD_ON(r->rc.overdamped)) {
        /* the first move uses these velocities: checked as every later solve is (a particle whose
         * neighbours start nearly on one line would otherwise jump unseen and leave them behind) */
        status = solve_velocities(r);
        if (!status) status = run_stop_if_unstable(r, 0);
    } else {
        compute_forces(r, -1, NULL);   /* colloid particles start on their sites */
    }
    if (!r->resumed) r->st.prod_wall0 = r->rc.equilibration == 0 ? wall_now() : 0.0;
    r->st.prod_cpu0 = r->resumed ? -1.0 : cpu_now();
    return status;
}
/* SIGINT and SIGTERM: finish the step, write a checkpoint, stop incomplete. */
static volatile sig_atomic_t stop_signal = 0;
static void on_stop_signal(int sig) { stop_signal = sig; }

static int save_checkpoint(Run *r)
{
    const RunOptions *opt = r->opt;
    const RunStats *st = &r->st;
    CheckpointExtra *cx = &r->cx;
    Output *out = &r->out;
    char err[1400];
    /* the frames so far are closed in complete segment files first */
    if (output_segment_commit(out)) {
        fprintf(stderr, "dpd: closing the trajectory segment in '%s' failed (disk full?)\n", opt->outdir);
        return -1;
    }
    cx->trajectory_segments = out->nseg;
    cx->trajectory_frames = out->frames;
    free(cx->trajectory_sums);   /* a resumed run's, read from its checkpoint: Output has them now */
    cx->trajectory_sums = out->seg_sum;
    cx->cpu_used = cpu_now() - st->cpu0;
    cx->wall_used = wall_now() - st->wall0;
    cx->prod_wall_used = (long long)r->s.step > r->rc.equilibration ? wall_now() - st->prod_wall0 : 0.0;
    cx->steps_done = st->steps_done;
    const int bad = checkpoint_write(opt->outdir, r->scene_hash, &r->s, &r->nl, &r->m, cx, err, sizeof err);
    cx->trajectory_sums = NULL;   /* the Output's */
    if (bad) {
        fprintf(stderr, "dpd: %s\n", err);
        return -1;
    }
    return 0;
}


/* After a step: the checkpoint when due, or on SIGINT/SIGTERM (then the run
 * stops incomplete). A checkpoint holds every sampled series, so it grows with
 * the run (hundreds of MB in long runs): the wall-clock floor keeps its
 * rewriting a small share of the run. 0, 4 or 128 + signal. */
static int checkpoint_if_due(Run *r, long long k, long long total, double *last)
{
    const RunOptions *opt = r->opt;
    if (!stop_signal && !(opt->checkpoint_every > 0 && (long long)r->s.step % opt->checkpoint_every == 0
                          && k + 1 < total && wall_now() - *last >= opt->checkpoint_wall))
        return 0;
    if (save_checkpoint(r)) return 4;
    *last = wall_now();
    if (!stop_signal) return 0;
    if (r->show) fputc('\n', stderr);
    fprintf(stderr, "dpd: stopped by signal %d at step %llu; checkpoint written, the run is incomplete "
            "(continue with --resume)\n", (int)stop_signal, (unsigned long long)r->s.step);
    return 128 + stop_signal;
}

/* Production starts at step k = equilibration: its clocks, its walls. */
static void production_starts(Run *r)
{
    r->st.prod_wall0 = wall_now();
    if (r->st.prod_cpu0 >= 0) r->st.prod_cpu0 = cpu_now();
    if (r->walls_later) set_walls_moving(&r->s, (const double (*)[3])r->vwall, 1);
}

/* The stability check every 10 steps, and at m = 0 on every step (the check
 * costs nothing beside the solve, and a runaway would otherwise first show as
 * a failed solve); at once after a step that made a velocity non-finite
 * (integrate_correct counts them) or computed the virial. Spins can run away
 * within a few steps: in between, their temperature alone on every step (the
 * translational checks every step were 1.7 % of the Pan 2008 fluid's run).
 * CHECK_NONE, CHECK_SPINS or CHECK_FULL. */
enum { CHECK_NONE, CHECK_SPINS, CHECK_FULL };
static int check_due(const Run *r)
{
    const System *s = &r->s;
    if (s->step % 10 == 0 || r->virial_step || MOD_ON(r->rc.overdamped) || s->nonfinite) return CHECK_FULL;
    return MOD_ROTATION(s) ? CHECK_SPINS : CHECK_NONE;
}

/* The step loop. 0, or the status that stopped it. */
static int run_loop(Run *r)
{
    const long long total = r->rc.equilibration + r->rc.steps;
    struct sigaction sa = {.sa_handler = on_stop_signal}, old_int, old_term;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    stop_signal = 0;
    double last_checkpoint = wall_now();
    int status = 0;
    for (long long k = (long long)r->s.step; k < total && status == 0; k++) {
        if (k == r->rc.equilibration) production_starts(r);
        double t[7];
        t[0] = wall_now();
        status = MOD_ON(r->rc.overdamped) ? step_overdamped(r, t) : step_inertial(r, t);
        const int check = status ? CHECK_NONE : check_due(r);
        if (status || (check != CHECK_NONE && (status = run_stop_if_unstable(r, check == CHECK_SPINS)))) break;
        t[5] = wall_now();
        if (r->rc.trajectory_every > 0 && r->s.step % r->rc.trajectory_every == 0 && output_frame(&r->out, &r->s)) {
            fprintf(stderr, "dpd: writing the trajectory failed at step %llu\n", (unsigned long long)r->s.step);
            status = 4;
            break;
        }
        t[6] = wall_now();
        RunStats *st = &r->st;
        st->timers[T_INTEGRATE] += (t[1] - t[0]) + (t[4] - t[3]);
        st->timers[T_NEIGHBOR] += t[2] - t[1];
        st->timers[T_FORCE] += t[3] - t[2];
        st->timers[T_MEASURE] += t[5] - t[4];
        st->timers[T_OUTPUT] += t[6] - t[5];
        st->steps_done++;
        if (r->show) progress(k + 1, total, st->wall0, k + 1 == total);
        status = checkpoint_if_due(r, k, total, &last_checkpoint);
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    r->st.builds = r->nl.builds;
    return status;
}

/* The end of a run, whatever its status: a failed run leaves no summary that
 * looks like a result (INCOMPLETE stays too); a complete one drops its
 * marker, checkpoint and segments (their frames are in run.h5). Then every
 * buffer is released. Returns status, or 4 if closing the output failed. */
static int run_finish(Run *r, int status)
{
    const char *dir = r->opt->outdir;
    char f[1100];
    if (r->opened && output_close(&r->out, status == 0) && status == 0) {
        fprintf(stderr, "dpd: closing %s failed (disk full?)\n", r->out.path);
        status = 4;
    }
    if (status != 0 && r->wrote_summary) {
        snprintf(f, sizeof f, "%s/summary.tsv", dir);
        unlink(f);
        snprintf(f, sizeof f, "%s/provenance.tsv", dir);
        unlink(f);
    }
    if (status == 0 && r->opened) {
        snprintf(f, sizeof f, "%s/INCOMPLETE", dir);
        unlink(f);
        snprintf(f, sizeof f, "%s/%s", dir, CHECKPOINT_FILE);
        unlink(f);   /* the run is complete: nothing to resume */
        output_segments_remove(&r->out);
    }
    dirlock_release(dir, r->lock);
    free(r->cx.trajectory_sums);
    free(r->thermal_cells);
    free(r->pv.Wbin);
    od_free(&r->od);
    od_stats_free(&r->ods_stats);
    if (r->set_up) measure_free(&r->m);
    colloid_free(r->rc.colloids);
    bonds_free(r->rc.bonds);
    forces_free(&r->fw);
    neighbor_free(&r->nl);
    system_free(&r->s);
    if (r->loaded) scene_free(&r->sc);
    return status;
}

/* The size of the run, for planning (tools/plan). */
static void print_plan(const Run *r)
{
    printf("particles\t%d\nequilibration\t%lld\nsteps\t%lld\noverdamped\t%d\n", r->s.n,
           (long long)r->rc.equilibration, (long long)r->rc.steps, r->rc.overdamped ? 1 : 0);
}

int run_scene(const RunOptions *opt)
{
#ifdef _OPENMP
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
#endif
    Run *r = calloc(1, sizeof *r);
    if (!r) { fprintf(stderr, "dpd: out of memory\n"); return 4; }
    r->opt = opt;
    r->lock = -1;
    r->show = !opt->quiet && isatty(2);
    int status = run_load(r);
    if (status == 0 && opt->dry_run) { print_plan(r); status = run_finish(r, 0); free(r); return status; }
#ifdef _OPENMP
    /* the m = 0 solvers are serial: extra threads would only spin between the
     * short parallel loops (doubling the CPU time, and far worse on a busy
     * machine); --threads still overrides */
    if (status == 0 && r->rc.overdamped && opt->threads <= 0) omp_set_num_threads(1);
#endif
    if (status == 0) status = run_open(r);
    if (status == 0) { run_connect(r); status = run_resume(r); }
    if (status == 0) status = run_start(r);
    if (status == 0) status = run_loop(r);
    if (status == 0) status = run_write_results(r);
    status = run_finish(r, status);
    free(r);
    return status;
}
