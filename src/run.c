/* run.c - the time loop, provenance and the outputs of a run. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <errno.h>
#include <unistd.h>
#include <sys/stat.h>
#include <sys/resource.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "run.h"
#include "scene.h"
#include "setup.h"
#include "neighbor.h"
#include "forces.h"
#include "integrator.h"
#include "measure.h"
#include "output.h"
#include "timers.h"
#include "overdamped.h"
#include "checkpoint.h"
#include <signal.h>
#include "rotation.h"

#ifndef DPD_GIT
#define DPD_GIT "unknown"
#endif
#ifndef DPD_CFLAGS
#define DPD_CFLAGS "unknown"
#endif

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

typedef struct {
    double wall0, cpu0, timers[T_COUNT];
    double prod_wall0;        /* wall clock when production started */
    double prod_cpu0;         /* process CPU time then (< 0: unknown, a resumed run) */
    long long steps_done;
    int threads;
    long builds;
    long long resumed_at;     /* the step a resumed run continued from (-1: not resumed) */
} RunStats;

static void provenance_text(char **buf, size_t *len, const RunOptions *opt, const System *s,
                            const RunStats *st)
{
    FILE *m = open_memstream(buf, len);
    if (!m) return;
    char host[256] = "unknown";
    gethostname(host, sizeof host - 1);
    time_t now = time(NULL);
    char date[64];
    strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    fprintf(m, "key\tvalue\n");
    fprintf(m, "git_commit\t%s\n", DPD_GIT);
    fprintf(m, "compiler\t%s\n", __VERSION__);
    fprintf(m, "flags\t%s\n", DPD_CFLAGS);
    fprintf(m, "threads\t%d\n", st->threads);
    {   /* how idle threads wait (tools/lib/omp.sh): it changes the speed, never the numbers */
        const char *wp = getenv("OMP_WAIT_POLICY"), *sc = getenv("GOMP_SPINCOUNT");
        fprintf(m, "omp_wait\tOMP_WAIT_POLICY=%s GOMP_SPINCOUNT=%s\n", wp ? wp : "", sc ? sc : "");
    }
    fprintf(m, "seed\t%u\n", s->seed);
    if (st->resumed_at >= 0) fprintf(m, "resumed_at_step\t%lld\n", st->resumed_at);
    fprintf(m, "cpu_seconds\t%.3f\n", cpu_now() - st->cpu0);
    fprintf(m, "wall_seconds\t%.3f\n", wall_now() - st->wall0);
    fprintf(m, "peak_rss_kb\t%ld\n", ru.ru_maxrss);
    fprintf(m, "date\t%s\n", date);
    fprintf(m, "host\t%s\n", host);
    fprintf(m, "scene\t%s\n", opt->scene);
    fprintf(m, "command\t%s\n", opt->command_line ? opt->command_line : "");
    fclose(m);
}

static int write_h5(Output *o, const RunOptions *opt, Scene *sc, const System *s,
                    const Measure *m, const RunStats *st, const char *prov, const char *summary,
                    long long first_step)
{
    int rc = 0;
    rc |= output_attr_text(o, "/results", "summary_tsv", summary);
    char *text = scene_text(sc);
    rc |= output_attr_text(o, "/parameters", "scene", text ? text : "");
    free(text);
    rc |= output_attr_text(o, "/parameters", "scene_file", opt->scene);
    for (int k = 0; k < opt->noverrides; k++) {
        char name[32];
        snprintf(name, sizeof name, "set_%d", k);
        rc |= output_attr_text(o, "/parameters", name, opt->overrides[k]);
    }
    /* provenance: one attribute per key */
    char *copy = strdup(prov), *save = NULL;
    for (char *line = strtok_r(copy, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
        char *tab = strchr(line, '\t');
        if (!tab || strncmp(line, "key\t", 4) == 0) continue;
        *tab = '\0';
        rc |= output_attr_text(o, "/provenance", line, tab + 1);
    }
    free(copy);
    for (int k = 0; k < T_COUNT; k++) rc |= output_attr_double(o, "/timers", TIMER_NAMES[k], st->timers[k]);
    rc |= output_series(o, "temperature", m->temperature.v, m->temperature.n, first_step, m->every, s->dt);
    rc |= output_series(o, "pressure", m->pressure.v, m->pressure.n, first_step, m->every, s->dt);
    static const char *parts[STRESS_PARTS] = {"kinetic", "conservative", "dissipative", "random"};
    for (int p = 0; p < STRESS_PARTS; p++) {
        char name[64];
        snprintf(name, sizeof name, "pressure_yx_%s", parts[p]);
        rc |= output_series(o, name, m->P[p][3].v, m->P[p][3].n, first_step, m->every, s->dt);
    }
    /* torque and drag on frozen types, sample by sample: their correlation time checks the blocking */
    if (s->rotation)
        for (int t = 0; t < s->ntypes; t++) {
            if (!s->types[t].frozen) continue;
            for (int d = 0; d < 3; d++) {
                char name[96];
                snprintf(name, sizeof name, "torque_on_%s_%c", s->types[t].name, "xyz"[d]);
                rc |= output_series(o, name, m->frozen_torque[t][d].v, m->frozen_torque[t][d].n, first_step, m->every, s->dt);
                snprintf(name, sizeof name, "drag_on_%s_%c", s->types[t].name, "xyz"[d]);
                rc |= output_series(o, name, m->frozen_drag[t][d].v, m->frozen_drag[t][d].n, first_step, m->every, s->dt);
            }
        }
    double *fin = checkpoint_final_state(s);
    rc |= fin ? output_table(o, "/results/final_state", fin, s->n, 10, FINAL_STATE_COLUMNS) : -1;
    free(fin);
    static const char *tables[] = {"profile", "rdf", "msd", "tcaf", "tcaf_eta"};
    for (int k = 0; k < 5; k++) {
        char f[1100], path[64];
        snprintf(f, sizeof f, "%s/%s.tsv", opt->outdir, tables[k]);
        snprintf(path, sizeof path, "/results/%s", tables[k]);
        if (access(f, R_OK) == 0) rc |= output_tsv(o, path, f);
    }
    return rc;
}

/* Solver statistics of the m = 0 runs, one entry per step. */
typedef struct {
    Series iterations, residual, seconds, true_error;
    Series cpu_seconds;       /* process CPU time of assembly + solve (robust to a shared machine) */
    long long unconverged;
    double *sol, *ref;        /* packed solution and reference (3 n each) */
} SolverStats;

/* One step of the m = 0 dynamics: v from A v = f at the current positions
 * (eqs 15-18, noise of this step), then r += v dt (eq. 28); frozen particles
 * move at their wall velocity. Returns -1 if the solve did not converge and
 * the scene does not allow it. */
static int overdamped_step(System *s, NeighborList *nl, OdSystem *od, const RunConfig *rc,
                           SolverStats *ss)
{
    const int record = (long long)s->step >= rc->equilibration;   /* production steps only */
    const double t0 = wall_now(), c0 = cpu_now();
    if (od_assemble(od, s, nl)) return -2;
    if (rc->bonds) bonds_rhs(rc->bonds, s, od);                    /* eqs 50-51 into eq. 18 */
    OdResult r = od_solve(od, s, (OdSolver)rc->od_solver, (OdStop)rc->od_stop, rc->od_tol, rc->od_max_iter);
    if (record) {
        series_push(&ss->iterations, r.iterations);
        series_push(&ss->residual, r.rel_residual);
        series_push(&ss->seconds, wall_now() - t0);
        series_push(&ss->cpu_seconds, cpu_now() - c0);
    }
    if (!r.converged) {
        ss->unconverged++;
        if (!rc->od_allow_unconverged) {
            static const char *names[] = {"scheme1", "scheme2_paper", "scheme2_consistent", "pcg", "pcg_2level"};
            fprintf(stderr, "dpd: the %s solve did not converge at step %llu: %d iterations, change %g, "
                    "relative residual %g (tolerance %g); raise overdamped.max_iterations or set "
                    "overdamped.allow_unconverged = true\n", names[rc->od_solver],
                    (unsigned long long)s->step, r.iterations, r.change, r.rel_residual, rc->od_tol);
            return -1;
        }
    }
    if (record && rc->od_reference_tol > 0.0) {
        /* true error: distance to a tight PCG solve started from this solution */
        od_gather(od, s, ss->sol);
        memcpy(ss->ref, ss->sol, 3 * (size_t)od->nm * sizeof(double));
        if (rc->od_reference_own && rc->od_solver == OD_SCHEME2_PAPER)   /* its own fixed point */
            od_scheme2_paper_fixed_point(od, ss->ref, rc->od_reference_tol);
        else
            od_solve_vec(od, ss->ref, OD_PCG, OD_STOP_RESIDUAL, rc->od_reference_tol, 100 * od->nm + 1000);
        double num = 0.0, den = 0.0;
        for (int k = 0; k < 3 * od->nm; k++) {
            num += (ss->sol[k] - ss->ref[k]) * (ss->sol[k] - ss->ref[k]);
            den += ss->ref[k] * ss->ref[k];
        }
        series_push(&ss->true_error, den > 0 ? sqrt(num / den) : sqrt(num));
    }
    memcpy(s->v_pred, s->v, 3 * (size_t)s->n * sizeof(double));
    return 0;
}

/* Specular walls: mirror a mobile particle that crossed a confining plane. */
static void confine(System *s, const RunConfig *rc)
{
    const int a = rc->confine_axis;
    if (!MOD_ON(a >= 0)) return;
    #pragma omp parallel for schedule(static)
    for (int i = 0; i < s->n; i++) {
        if (s->types[s->type[i]].frozen) continue;
        double *x = s->x + 3 * i, *v = s->v + 3 * i, *vp = s->v_pred + 3 * i;
        if (x[a] < rc->confine_lo) { x[a] = 2.0 * rc->confine_lo - x[a]; v[a] = -v[a]; vp[a] = -vp[a]; }
        else if (x[a] > rc->confine_hi) { x[a] = 2.0 * rc->confine_hi - x[a]; v[a] = -v[a]; vp[a] = -vp[a]; }
    }
}

static void overdamped_move(System *s)
{
    const double dt = s->dt;
    integrate_advance_offset(s);
    int bad = 0;
    #pragma omp parallel for schedule(static) reduction(+:bad)
    for (int i = 0; i < s->n; i++) {
        double *x = s->x + 3 * i, *v = s->v + 3 * i;
        for (int d = 0; d < 3; d++) x[d] += dt * v[d];   /* eq. 28 */
        bad += box_wrap(&s->box, x, s->img + 3 * i, &v[0], &s->v_pred[3 * i]);
    }
    s->nonfinite = bad;   /* the run stops */
    s->step++;
    s->time += dt;
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

/* What ran away: quantity, value and the limit it broke. */
typedef struct {
    char what[64];
    double value, limit;
} Instability;

/* After a step whose particle loops counted a non-finite position or velocity
 * (s->nonfinite): the first non-finite position (velocities: the checks of
 * check_stable). Returns 1 if there is one. */
static int find_nonfinite_position(const System *s, Instability *u)
{
    for (int i = 0; i < s->n; i++)
        for (int d = 0; d < 3; d++) {
            const double x = s->x[3 * i + d];
            if (isfinite(x)) continue;
            snprintf(u->what, sizeof u->what, "position %c of particle %u", "xyz"[d], s->id[i]);
            u->value = x;
            u->limit = s->box.L[d];   /* positions are wrapped into [0, L) */
            return 1;
        }
    return 0;
}

/* Blow-up detection. Returns 1 if the state is sound; else *u names the
 * quantity that ran away, its value and the limit it broke. Checks: the kinetic
 * (and rotational) temperature against max_temperature_ratio x kBT (inertial
 * runs), and in every run the largest displacement per step of a mobile
 * particle against half the smallest box side (beyond it the minimum image
 * and the pair forces lose their meaning; m = 0 runs have no temperature), and
 * after a step that made a position or velocity non-finite, that value. */
static int check_stable(const System *s, const RunConfig *rc, Instability *u)
{
    const double kT = s->kBT > 0 ? s->kBT : 1.0;
    if (!rc->overdamped) {
        snprintf(u->what, sizeof u->what, "kinetic temperature");
        u->value = system_kinetic_temperature(s);
        u->limit = rc->max_temperature_ratio * kT;
        if (!isfinite(u->value) || u->value > u->limit) return 0;
        if (MOD_ROTATION(s)) {   /* spins can blow up first (too small an inertia for the step) */
            snprintf(u->what, sizeof u->what, "rotational temperature");
            u->value = rotation_temperature(s);
            if (!isfinite(u->value) || u->value > u->limit) return 0;
        }
    }
    double v2max = 0.0, lmin = INFINITY;
    for (int i = 0; i < s->n; i++) {
        if (MOD_FROZEN(&s->types[s->type[i]])) continue;
        const double *v = s->v + 3 * i;
        const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (!(v2 <= v2max)) v2max = v2;   /* NaN propagates */
    }
    for (int d = 0; d < s->box.dim; d++) lmin = fmin(lmin, s->box.L[d]);
    snprintf(u->what, sizeof u->what, "largest displacement per step");
    u->value = sqrt(v2max) * s->dt;
    u->limit = 0.5 * lmin;
    if (!isfinite(u->value) || u->value > u->limit) return 0;
    return !(s->nonfinite && find_nonfinite_position(s, u));
}

/* The stability check; if it fails, the message (step, quantity, value, a
 * smaller dt) and the reason in INCOMPLETE. Returns 0, or 3 (unstable). */
static int stop_if_unstable(const System *s, const RunConfig *rc, const RunOptions *opt, int show)
{
    Instability u;
    if (check_stable(s, rc, &u)) return 0;
    if (show) fputc('\n', stderr);
    char why[512];
    snprintf(why, sizeof why, "unstable at step %llu (t = %g): %s %g is %s (limit %g); reduce dt "
             "(now %g), e.g. to %g\n", (unsigned long long)s->step, s->time, u.what, u.value,
             isfinite(u.value) ? "too high" : "not finite", u.limit, s->dt, 0.5 * s->dt);
    fprintf(stderr, "dpd: %s", why);
    fprintf(stderr, "dpd: the output written so far is kept; '%s' is marked incomplete (INCOMPLETE)\n",
            opt->outdir);
    write_file_atomic(opt->outdir, "INCOMPLETE", why, strlen(why));   /* the reason, for the record */
    return 3;
}

/* SIGINT and SIGTERM: finish the step, write a checkpoint, stop incomplete. */
static volatile sig_atomic_t stop_signal = 0;
static void on_stop_signal(int sig) { stop_signal = sig; }

static int save_checkpoint(const RunOptions *opt, uint64_t hash, const System *s, const NeighborList *nl,
                           const Measure *m, CheckpointExtra *cx, const RunStats *st, long long equilibration,
                           Output *out)
{
    char err[1400];
    /* the frames so far are closed in complete segment files first */
    if (output_segment_commit(out)) {
        fprintf(stderr, "dpd: closing the trajectory segment in '%s' failed (disk full?)\n", opt->outdir);
        return -1;
    }
    cx->trajectory_segments = out->nseg;
    cx->trajectory_frames = out->frames;
    cx->cpu_used = cpu_now() - st->cpu0;
    cx->wall_used = wall_now() - st->wall0;
    cx->prod_wall_used = (long long)s->step > equilibration ? wall_now() - st->prod_wall0 : 0.0;
    cx->steps_done = st->steps_done;
    if (checkpoint_write(opt->outdir, hash, s, nl, m, cx, err, sizeof err)) {
        fprintf(stderr, "dpd: %s\n", err);
        return -1;
    }
    return 0;
}

int run_scene(const RunOptions *opt)
{
#ifdef _OPENMP
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
#endif
    Scene sc;
    System s;
    Measure m;
    RunConfig rc = {0};
    if (scene_load(&sc, opt->scene, opt->overrides, opt->noverrides) || setup_from_scene(&sc, &s, &m, &rc)) {
        fprintf(stderr, "dpd: %s\n", sc.error);
        colloid_free(rc.colloids);
        bonds_free(rc.bonds);
        scene_free(&sc);
        return 2;
    }
    if (opt->dry_run) {   /* the size of the run, for planning (tools/plan) */
        printf("particles\t%d\nequilibration\t%lld\nsteps\t%lld\noverdamped\t%d\n", s.n,
               (long long)rc.equilibration, (long long)rc.steps, rc.overdamped ? 1 : 0);
        colloid_free(rc.colloids);
        bonds_free(rc.bonds);
        system_free(&s);
        scene_free(&sc);
        return 0;
    }
#ifdef _OPENMP
    /* the m = 0 solvers are serial: extra threads would only spin between the
     * short parallel loops (doubling the CPU time, and far worse on a busy
     * machine); --threads still overrides */
    if (rc.overdamped && opt->threads <= 0) omp_set_num_threads(1);
#endif
    if (mkdir_p(opt->outdir)) {
        fprintf(stderr, "dpd: cannot create or write the output directory '%s': %s\n", opt->outdir, strerror(errno));
        system_free(&s); scene_free(&sc);
        return 4;
    }
    char marker[1100];
    snprintf(marker, sizeof marker, "%s/INCOMPLETE", opt->outdir);
    if (write_file_atomic(opt->outdir, "INCOMPLETE", "run started\n", 12)) {
        fprintf(stderr, "dpd: cannot write in '%s': %s\n", opt->outdir, strerror(errno));
        system_free(&s); scene_free(&sc);
        return 4;
    }
    RunStats st = {.wall0 = wall_now(), .cpu0 = cpu_now(), .threads = threads_in_use(), .resumed_at = -1};
    NeighborList nl;
    ForceWork fw;
    Output out;
    int status = 0, wrote_summary = 0;
    if (neighbor_init(&nl, &s, rc.skin) || forces_init(&fw, &s, m.prof_on ? m.prof_bins : 0)
        || measure_init(&m, &s) || neighbor_build(&nl, &s)) {
        fprintf(stderr, "dpd: out of memory\n");
        return 4;
    }
    if (output_open(&out, opt->outdir, &s, rc.trajectory_every > 0)) {
        fprintf(stderr, "dpd: cannot create the HDF5 file in '%s' (disk full or not writable?)\n", opt->outdir);
        measure_free(&m); forces_free(&fw); neighbor_free(&nl); system_free(&s); scene_free(&sc);
        return 4;
    }
    if (rc.colloids && m.tcaf.on && m.tcaf.p.include_bodies)   /* the bodies' momentum joins the TCAF */
        tcaf_set_bodies(&m.tcaf, &s, rc.colloids->ncol, rc.colloids->R, rc.colloids->V, rc.colloids->p.mass);
    if (rc.colloids) m.colloids = rc.colloids;   /* the bodies' momentum flux joins the stress */
    double *wbin = m.prof_on ? calloc((size_t)m.prof_bins * PAIR_PARTS * 9, sizeof(double)) : NULL;
    PairVirial pv = {.bin_axis = m.prof_axis, .nbins = m.prof_on ? m.prof_bins : 0, .Wbin = wbin};
    const long long total = rc.equilibration + rc.steps;
    const int show = !opt->quiet && isatty(2);
    OdSystem od;
    SolverStats ss = {0};
    od_init(&od);
    ss.sol = calloc(3 * (size_t)s.n + 1, sizeof(double));
    ss.ref = calloc(3 * (size_t)s.n + 1, sizeof(double));
    if (!ss.sol || !ss.ref) { fprintf(stderr, "dpd: out of memory\n"); return 4; }
    double vwall[DPD_MAX_TYPES][3];
    for (int t = 0; t < s.ntypes; t++) memcpy(vwall[t], s.types[t].wall_velocity, sizeof vwall[t]);
    const int walls_later = MOD_ON(rc.walls_start_at_production && rc.equilibration > 0);
    /* checkpoints: the scene as run identifies them */
    char *scene_txt = scene_text(&sc);
    const uint64_t scene_hash = checkpoint_hash(scene_txt ? scene_txt : "", scene_txt ? strlen(scene_txt) : 0, 0);
    free(scene_txt);
    CheckpointExtra cx = {.timers = st.timers, .ntimers = T_COUNT, .nsolver = 4,
                          .solver = {&ss.iterations, &ss.residual, &ss.seconds, &ss.true_error},
                          .solver_cpu = rc.overdamped ? &ss.cpu_seconds : NULL,
                          .unconverged = &ss.unconverged, .bonds = rc.bonds, .colloids = rc.colloids,
                          .threads = st.threads, .trajectory = rc.trajectory_every > 0};
    int resumed = 0;
    if (opt->resume) {
        char err[1400];
        const int r = checkpoint_read(opt->outdir, scene_hash, &s, &nl, &m, &cx, err, sizeof err);
        if (r < 0) { fprintf(stderr, "dpd: %s\n", err); status = 2; }
        else if (r == 0 && output_segments_resume(&out, cx.trajectory_segments, cx.trajectory_frames, err, sizeof err)) {
            fprintf(stderr, "dpd: %s\n", err);
            status = 2;
        } else if (r == 0) {
            resumed = 1;
            st.resumed_at = (long long)s.step;
            st.cpu0 = cpu_now() - cx.cpu_used;
            st.wall0 = wall_now() - cx.wall_used;
            st.prod_wall0 = wall_now() - cx.prod_wall_used;
            st.steps_done = cx.steps_done;
            if (!opt->quiet) fprintf(stderr, "dpd: resuming %s at step %llu\n", opt->outdir, (unsigned long long)s.step);
            cx.threads = st.threads;
        }
    }
    if (!resumed && status == 0) {   /* a fresh run: trajectory segments of an earlier one go */
        char err[1400];
        if (output_segments_resume(&out, 0, 0, err, sizeof err)) { fprintf(stderr, "dpd: %s\n", err); status = 2; }
    }
    /* walls that start with the production run: still at rest before it */
    if (walls_later) set_walls_moving(&s, (const double (*)[3])vwall, resumed && s.step > (uint64_t)rc.equilibration);
    if (resumed || status) {
        /* forces, v_pred and the m = 0 velocities of this step come from the checkpoint */
    } else if (MOD_ON(rc.overdamped)) {
        int r = overdamped_step(&s, &nl, &od, &rc, &ss);
        if (r) { status = r == -2 ? 4 : 3; }
    } else {
        forces_compute(&s, &nl, &fw, NULL);
        if (MOD_ON(rc.bonds)) bonds_forces(rc.bonds, &s, NULL);
        if (MOD_ON(rc.colloids)) colloid_step(rc.colloids, &s, NULL);   /* particles start on their sites */
    }
    if (!resumed) st.prod_wall0 = rc.equilibration == 0 ? wall_now() : 0.0;
    st.prod_cpu0 = resumed ? -1.0 : cpu_now();
    struct sigaction sa = {.sa_handler = on_stop_signal}, old_int, old_term;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    stop_signal = 0;
    double last_checkpoint = wall_now();
    for (long long k = (long long)s.step; k < total && status == 0; k++) {
        if (k == rc.equilibration) { st.prod_wall0 = wall_now(); if (st.prod_cpu0 >= 0) st.prod_cpu0 = cpu_now(); }
        if (walls_later && k == rc.equilibration) set_walls_moving(&s, (const double (*)[3])vwall, 1);
        double t0 = wall_now(), t1, t2, t3, t4;
        long long prod;
        int want;
        if (MOD_ON(rc.overdamped)) {
            /* the velocities of step k are known: sample them, then move (eq. 28) */
            prod = (long long)s.step - rc.equilibration;
            want = prod >= 0 && measure_wants_virial(&m, prod);
            if (want) forces_compute(&s, &nl, &fw, &pv);   /* virial of the solved state */
            if (want && rc.bonds) bonds_forces(rc.bonds, &s, &pv);   /* spring virial */
            if (prod >= 0) measure_sample(&m, &s, &nl, want ? &pv : NULL, prod);
            if (prod >= 0 && rc.bonds) bonds_sample(rc.bonds, &s, prod);
            overdamped_move(&s);
            confine(&s, &rc);
            if (s.nonfinite && (status = stop_if_unstable(&s, &rc, opt, show))) break;   /* before it spreads */
            t1 = wall_now();
            if (neighbor_update(&nl, &s) < 0) { fprintf(stderr, "dpd: out of memory\n"); status = 4; break; }
            t2 = wall_now();
            int r = overdamped_step(&s, &nl, &od, &rc, &ss);
            if (r) { status = r == -2 ? 4 : 3; break; }
            t3 = t4 = wall_now();
            prod = -1;   /* sampled above */
            want = 0;
        } else {
            double doff = integrate_predict(&s);
            neighbor_note_shear(&nl, doff);
            confine(&s, &rc);
            if (s.nonfinite && (status = stop_if_unstable(&s, &rc, opt, show))) break;   /* before it spreads */
            t1 = wall_now();
            if (neighbor_update(&nl, &s) < 0) { fprintf(stderr, "dpd: out of memory\n"); status = 4; break; }
            t2 = wall_now();
            prod = (long long)s.step - rc.equilibration;
            want = prod >= 0 && measure_wants_virial(&m, prod);
            forces_compute(&s, &nl, &fw, want ? &pv : NULL);
            if (MOD_ON(rc.bonds)) { bonds_forces(rc.bonds, &s, want ? &pv : NULL); bonds_sample(rc.bonds, &s, prod); }
            if (MOD_ON(rc.colloids)) { rc.colloids->record = prod >= 0; colloid_step(rc.colloids, &s, want ? &pv : NULL); }   /* eq. 30 */
            t3 = wall_now();
            integrate_correct(&s);
            t4 = wall_now();
        }
        if (prod >= 0) measure_sample(&m, &s, &nl, want ? &pv : NULL, prod);
        /* every 10 steps; every step for spins (they can run away within a few steps) and at m = 0 (the
         * check costs nothing beside the solve, and a runaway would otherwise first show as a failed solve);
         * at once after a step that made a velocity non-finite (integrate_correct counts them) */
        if ((s.step % 10 == 0 || want || MOD_ROTATION(&s) || MOD_ON(rc.overdamped) || s.nonfinite)
            && (status = stop_if_unstable(&s, &rc, opt, show)))
            break;
        double t5 = wall_now();
        if (rc.trajectory_every > 0 && s.step % rc.trajectory_every == 0 && output_frame(&out, &s)) {
            fprintf(stderr, "dpd: writing the trajectory failed at step %llu\n", (unsigned long long)s.step);
            status = 4;
            break;
        }
        double t6 = wall_now();
        st.timers[T_INTEGRATE] += (t1 - t0) + (t4 - t3);
        st.timers[T_NEIGHBOR] += t2 - t1;
        st.timers[T_FORCE] += t3 - t2;
        st.timers[T_MEASURE] += t5 - t4;
        st.timers[T_OUTPUT] += t6 - t5;
        st.steps_done++;
        if (show) progress(k + 1, total, st.wall0, k + 1 == total);
        /* a checkpoint holds every sampled series, so it grows with the run (hundreds of MB in long
         * runs): the wall-clock floor keeps its rewriting a small share of the run */
        if (stop_signal || (opt->checkpoint_every > 0 && (long long)s.step % opt->checkpoint_every == 0 && k + 1 < total
                            && wall_now() - last_checkpoint >= opt->checkpoint_wall)) {
            if (save_checkpoint(opt, scene_hash, &s, &nl, &m, &cx, &st, rc.equilibration, &out)) { status = 4; break; }
            last_checkpoint = wall_now();
            if (stop_signal) {
                if (show) fputc('\n', stderr);
                fprintf(stderr, "dpd: stopped by signal %d at step %llu; checkpoint written, the run is incomplete "
                        "(continue with --resume)\n", (int)stop_signal, (unsigned long long)s.step);
                status = 128 + stop_signal;
                break;
            }
        }
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    st.builds = nl.builds;
    if (status == 0) {
        char *sum = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&sum, &len);
        fprintf(f, "quantity\tvalue\tstderr\n");
        if (measure_write(&m, &s, f, opt->outdir)) status = 4;
        if (rc.colloids) colloid_write(rc.colloids, &s, f, m.nblocks);
        if (rc.bonds && bonds_write(rc.bonds, &s, f, opt->outdir)) status = 4;
        const double wall = wall_now() - st.wall0;
        fprintf(f, "particles\t%d\t0\n", s.n);
        fprintf(f, "steps\t%lld\t0\n", total);
        fprintf(f, "cpu_seconds\t%.3f\t0\n", cpu_now() - st.cpu0);
        fprintf(f, "wall_seconds\t%.3f\t0\n", wall);
        fprintf(f, "particle_steps_per_second\t%.6g\t0\n", (double)s.n * total / (wall > 0 ? wall : 1e-9));
        const double pwall = wall_now() - st.prod_wall0;
        fprintf(f, "production_particle_steps_per_second\t%.6g\t0\n",
                rc.steps > 0 ? (double)s.n * rc.steps / (pwall > 0 ? pwall : 1e-9) : 0.0);
        /* the same per CPU second of the process: for one thread, far less
         * sensitive than wall time to other jobs on a shared machine */
        const double pcpu = cpu_now() - st.prod_cpu0;
        if (st.prod_cpu0 >= 0 && rc.steps > 0 && pcpu > 0)
            fprintf(f, "production_particle_steps_per_second_cpu\t%.6g\t0\n", (double)s.n * rc.steps / pcpu);
        struct rusage ru;
        getrusage(RUSAGE_SELF, &ru);
        fprintf(f, "peak_memory_bytes_per_particle\t%.6g\t0\n", ru.ru_maxrss * 1024.0 / s.n);
        for (int t = 0; t < T_COUNT; t++) fprintf(f, "time_%s_seconds\t%.4f\t0\n", TIMER_NAMES[t], st.timers[t]);
        fprintf(f, "neighbor_builds\t%ld\t0\n", st.builds);
        if (rc.overdamped) {
            /* per-step solver record for plots; cpu_seconds last (plots read true_rel_error as column 5) */
            char path[1100];
            snprintf(path, sizeof path, "%s/solver.tsv", opt->outdir);
            FILE *sf = fopen(path, "w");
            if (sf) {
                fprintf(sf, "step\titerations\trel_residual\tseconds%s\tcpu_seconds\n", ss.true_error.n ? "\ttrue_rel_error" : "");
                for (size_t k = 0; k < ss.iterations.n; k++) {
                    fprintf(sf, "%zu\t%g\t%.4g\t%.4g", k, ss.iterations.v[k], ss.residual.v[k], ss.seconds.v[k]);
                    if (ss.true_error.n) fprintf(sf, "\t%.4g", ss.true_error.v[k]);
                    fprintf(sf, "\t%.4g\n", k < ss.cpu_seconds.n ? ss.cpu_seconds.v[k] : NAN);
                }
                if (fclose(sf)) status = 4;
            } else status = 4;
            double v, se;
            series_stats(&ss.iterations, m.nblocks, &v, &se);
            fprintf(f, "solver_iterations\t%.10g\t%.4g\n", v, se);
            series_stats(&ss.residual, m.nblocks, &v, &se);
            fprintf(f, "solver_rel_residual\t%.10g\t%.4g\n", v, se);
            series_stats(&ss.seconds, m.nblocks, &v, &se);
            fprintf(f, "solver_seconds_per_step\t%.10g\t%.4g\n", v, se);
            series_stats(&ss.cpu_seconds, m.nblocks, &v, &se);
            fprintf(f, "solver_cpu_seconds_per_step\t%.10g\t%.4g\n", v, se);
            fprintf(f, "solver_unconverged_steps\t%lld\t0\n", ss.unconverged);
            if (ss.true_error.n > 0) {
                series_stats(&ss.true_error, m.nblocks, &v, &se);
                fprintf(f, "solver_true_rel_error\t%.10g\t%.4g\n", v, se);
            }
        }
        fclose(f);
        char *prov = NULL;
        size_t plen = 0;
        provenance_text(&prov, &plen, opt, &s, &st);
        wrote_summary = status == 0;
        if (status == 0 && write_file_atomic(opt->outdir, "summary.tsv", sum, len)) status = 4;
        if (status == 0 && write_file_atomic(opt->outdir, "provenance.tsv", prov, plen)) status = 4;
        if (status == 0 && output_segments_merge(&out, &s)) status = 4;   /* the trajectory */
        /* the step of the first sample: production step 0, which the inertial loop first
         * reaches after a step, so never when there is no equilibration */
        const long long first = rc.equilibration + (rc.equilibration == 0 && !rc.overdamped ? m.every : 0);
        if (status == 0 && write_h5(&out, opt, &sc, &s, &m, &st, prov, sum, first)) status = 4;
        free(sum);
        free(prov);
        if (status == 4) fprintf(stderr, "dpd: writing the results in '%s' failed\n", opt->outdir);
    }
    if (output_close(&out, status == 0) && status == 0) {
        fprintf(stderr, "dpd: closing %s failed (disk full?)\n", out.path);
        status = 4;
    }
    if (status != 0 && wrote_summary) {
        /* a failed run leaves no summary that looks like a result (INCOMPLETE stays too) */
        char f[1100];
        snprintf(f, sizeof f, "%s/summary.tsv", opt->outdir);
        unlink(f);
        snprintf(f, sizeof f, "%s/provenance.tsv", opt->outdir);
        unlink(f);
    }
    if (status == 0) {
        unlink(marker);
        char ck[1100];
        snprintf(ck, sizeof ck, "%s/%s", opt->outdir, CHECKPOINT_FILE);
        unlink(ck);   /* the run is complete: nothing to resume */
        output_segments_remove(&out);   /* their frames are in run.h5 */
    }
    free(wbin);
    od_free(&od);
    series_free(&ss.iterations); series_free(&ss.residual); series_free(&ss.seconds);
    series_free(&ss.true_error); series_free(&ss.cpu_seconds); free(ss.sol); free(ss.ref);
    measure_free(&m);
    colloid_free(rc.colloids);
    bonds_free(rc.bonds);
    forces_free(&fw);
    neighbor_free(&nl);
    system_free(&s);
    scene_free(&sc);
    return status;
}
