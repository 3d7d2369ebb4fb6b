/* run_output.c - what a completed run writes: summary.tsv (every measured
 * quantity with its standard error, the run's cost), provenance.tsv (commit,
 * compiler, flags, threads, seed, CPU time), solver.tsv of m = 0 runs, the
 * trajectory and run.h5 (H5MD layout, tools/README.md). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/resource.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "run_context.h"

#ifndef DPD_GIT
#define DPD_GIT "unknown"
#endif
#ifndef DPD_CFLAGS
#define DPD_CFLAGS "unknown"
#endif

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

/* The run's cost rows of the summary: size, CPU and wall time, rates, memory,
 * time per phase, neighbour-list builds. */
static void summary_cost(FILE *f, const Run *r)
{
    const System *s = &r->s;
    const RunStats *st = &r->st;
    const long long total = r->rc.equilibration + r->rc.steps, steps = r->rc.steps;
    const double wall = wall_now() - st->wall0;
    fprintf(f, "particles\t%d\t0\n", s->n);
    fprintf(f, "steps\t%lld\t0\n", total);
    fprintf(f, "cpu_seconds\t%.3f\t0\n", cpu_now() - st->cpu0);
    fprintf(f, "wall_seconds\t%.3f\t0\n", wall);
    fprintf(f, "particle_steps_per_second\t%.6g\t0\n", (double)s->n * total / (wall > 0 ? wall : 1e-9));
    const double pwall = wall_now() - st->prod_wall0;
    fprintf(f, "production_particle_steps_per_second\t%.6g\t0\n",
            steps > 0 ? (double)s->n * steps / (pwall > 0 ? pwall : 1e-9) : 0.0);
    /* the same per CPU second of the process: for one thread, far less
     * sensitive than wall time to other jobs on a shared machine */
    const double pcpu = cpu_now() - st->prod_cpu0;
    if (st->prod_cpu0 >= 0 && steps > 0 && pcpu > 0)
        fprintf(f, "production_particle_steps_per_second_cpu\t%.6g\t0\n", (double)s->n * steps / pcpu);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    fprintf(f, "peak_memory_bytes_per_particle\t%.6g\t0\n", ru.ru_maxrss * 1024.0 / s->n);
    for (int t = 0; t < T_COUNT; t++) fprintf(f, "time_%s_seconds\t%.4f\t0\n", TIMER_NAMES[t], st->timers[t]);
    fprintf(f, "neighbor_builds\t%ld\t0\n", st->builds);
}

/* The summary text: the measurements, the bodies', the cost, the solver's; the
 * bodies' and the solver's tables into ts. */
static int summary_text(Run *r, char **sum, size_t *len, Tables *ts)
{
    int status = 0;
    FILE *f = open_memstream(sum, len);
    if (!f) return 4;
    fprintf(f, "quantity\tvalue\tstderr\n");
    /* a run whose production took no sample (steps = 0, an equilibration alone, or steps below
     * measure.every) measured nothing: its summary has the run's cost alone, not rows of nan */
    const int measured = r->m.temperature.n > 0;
    if (!measured)
        fprintf(stderr, "dpd: note: no sample was taken (steps = %lld, measure.every = %d): the summary "
                "has the run's cost and no measured quantity\n", r->rc.steps, r->m.every);
    if (measured && measure_write(&r->m, &r->s, f, r->opt->outdir)) status = 4;
    if (measured && r->rc.colloids) colloid_write(r->rc.colloids, &r->s, f, r->m.nblocks);
    if (measured && r->rc.bonds && bonds_write(r->rc.bonds, &r->s, f, ts)) status = 4;
    summary_cost(f, r);
    if (measured && r->rc.overdamped && od_stats_write(&r->ods_stats, f, ts, r->m.nblocks)) status = 4;
    return fclose(f) || status ? 4 : 0;
}

int run_write_results(Run *r)
{
    const RunOptions *opt = r->opt;
    char *sum = NULL, *prov = NULL;
    size_t len = 0, plen = 0;
    Tables ts = {0};
    int status = summary_text(r, &sum, &len, &ts);
    const char *failed = NULL;
    if (status == 0 && output_write_tables(opt->outdir, &ts, &failed)) {
        fprintf(stderr, "dpd: cannot write %s/%s\n", opt->outdir, failed);
        status = 4;
    }
    tables_free(&ts);
    provenance_text(&prov, &plen, opt, &r->s, &r->st);
    r->wrote_summary = status == 0;
    if (status == 0 && write_file_atomic(opt->outdir, "summary.tsv", sum, len)) status = 4;
    if (status == 0 && write_file_atomic(opt->outdir, "provenance.tsv", prov, plen)) status = 4;
    char err[1400];
    if (status == 0 && output_segments_merge(&r->out, &r->s, err, sizeof err)) {   /* the trajectory */
        fprintf(stderr, "dpd: %s\n", err);
        status = 4;
    }
    /* the step of the first sample: production step 0, which the inertial loop first
     * reaches after a step, so never when there is no equilibration */
    const long long first = r->rc.equilibration + (r->rc.equilibration == 0 && !r->rc.overdamped ? r->m.every : 0);
    if (status == 0 && write_h5(&r->out, opt, &r->sc, &r->s, &r->m, &r->st, prov, sum, first)) status = 4;
    free(sum);
    free(prov);
    if (status == 4) fprintf(stderr, "dpd: writing the results in '%s' failed\n", opt->outdir);
    return status;
}
