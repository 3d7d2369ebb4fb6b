/* main.c - the dpd command line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include "run.h"
#include "params.h"
#include "linefit.h"
#include "lengthscale.h"
#include "poiseuille.h"
#include "transverse_relaxation.h"
#include "checkpoint.h"
#include <sys/stat.h>

#ifndef DPD_GIT
#define DPD_GIT "unknown"
#endif

static void usage(FILE *f)
{
    fprintf(f,
        "dpd - dissipative particle dynamics for the reproducibility package\n"
        "\n"
        "usage:\n"
        "  dpd run SCENE [--set key=value ...] [--out DIR] [--threads N] [--quiet]\n"
        "          [--checkpoint-every N [--checkpoint-wall S]] [--resume] [--dry-run]\n"
        "      run a libconfig scene; --set overrides any key (e.g. --set pairs.[0].a=6.5,\n"
        "      --set measure.profile.bins=40); results go to DIR (default: out/);\n"
        "      --checkpoint-every N writes DIR/checkpoint.dpd every N steps (SIGINT and\n"
        "      SIGTERM write one too), with --checkpoint-wall S not sooner than S wall\n"
        "      seconds after the last one; --resume continues from it, bit for bit;\n"
        "      --dry-run sets the scene up and prints its particles and steps (the cost\n"
        "      of a run is about particles x steps), writing nothing\n"
        "  dpd checkpoint-info DIR|FILE\n"
        "      the step, time, particle count and format of a run's checkpoint (DIR/checkpoint.dpd),\n"
        "      its checksum verified, as quantity/value rows: how far an interrupted run got\n"
        "  dpd params --eta ETA --Sc SC [--dim 3] [--n 4] [--rc 1.5] [--m 1] [--kBT 1]\n"
        "      s and gamma that impose a viscosity and a Schmidt number (Mai-Duy et al.\n"
        "      2019, eqs 14-21), as quantity/value/stderr rows\n"
        "  dpd fit-line TABLE --x COL --y COL --se COL [--range LO:HI] [--origin]\n"
        "      weighted straight-line fit (GSL) of a result table, e.g. a velocity profile\n"
        "  dpd tcaf-fit TCAF_TSV --rho R --box L [--model exp|two-mode|integral] [--fit-min F]\n"
        "               [--kmax 2] [--order 1] [--table FILE] [--curves FILE] [--summary FILE]\n"
        "      eta(k) of every shell of a run's tcaf.tsv and its k -> 0 limit: eq. 28's single\n"
        "      exponential, a slow mode beside a damped oscillation (eta from the slow mode),\n"
        "      or rho / (k^2 integral C/C0 dt); errors propagated from the per-lag errors.\n"
        "      --model two-mode,integral: both from one fit; --summary, --table and --curves\n"
        "      then name a file per model with %m (the model's name)\n"
        "  dpd wavelengths [--box 15] [--n 4] [--p 6] [--kmin 3] [--kmax 13]\n"
        "      phi of k^3 colloids of p particles among n L^3 solvent particles and the\n"
        "      cube (eq. 31) and sphere (eq. 32) length scales (Mai-Duy et al. 2019, Table 1)\n"
        "  dpd fit-poiseuille PROFILE.tsv --force G [--column vx] [--blocks]\n"
        "      viscosity from a reverse Poiseuille profile, parabola per half (GSL);\n"
        "      --blocks: PROFILE is a profile_blocks.tsv, fitted per block, error from\n"
        "      the blocks' scatter\n"
        "  dpd --help | --version\n"
        "\n"
        "exit status: 0 success, 1 usage, 2 bad scene, 3 unstable run, 4 I/O failure,\n"
        "  128 + signal: stopped by SIGINT/SIGTERM (checkpoint written, run incomplete)\n");
}

static int cmd_params(int argc, char **argv)
{
    double eta = -1, Sc = -1, n = 4, rc = 1.5, m = 1, kBT = 1;
    int dim = 3;
    for (int k = 0; k < argc; k++) {
        if (k + 1 >= argc) { fprintf(stderr, "dpd params: %s needs a value\n", argv[k]); return 1; }
        const char *o = argv[k];
        char *end;
        double v = strtod(argv[++k], &end);
        if (*end) { fprintf(stderr, "dpd params: %s: '%s' is not a number\n", o, argv[k]); return 1; }
        if (!strcmp(o, "--eta")) eta = v;
        else if (!strcmp(o, "--Sc")) Sc = v;
        else if (!strcmp(o, "--n")) n = v;
        else if (!strcmp(o, "--rc")) rc = v;
        else if (!strcmp(o, "--m")) m = v;
        else if (!strcmp(o, "--kBT")) kBT = v;
        else if (!strcmp(o, "--dim")) dim = (int)v;
        else { fprintf(stderr, "dpd params: unknown option %s\n", o); return 1; }
    }
    if (eta <= 0 || Sc <= 0 || n <= 0 || rc <= 0 || m <= 0 || kBT <= 0 || (dim != 2 && dim != 3)) {
        fprintf(stderr, "dpd params: need --eta > 0 and --Sc > 0 (and n, rc, m, kBT > 0, dim 2 or 3)\n");
        return 1;
    }
    ImposedParams p = params_from_eta_sc(dim, eta, Sc, m, kBT, n, rc);
    printf("quantity\tvalue\tstderr\n");
    printf("s_%dd\t%.10g\t0\n", dim, p.s);
    printf("gamma_%dd\t%.10g\t0\n", dim, p.gamma);
    printf("C_%dd\t%.10g\t0\n", dim, p.C);
    printf("eta_max_%dd\t%.10g\t0\n", dim, p.eta_max);
    printf("Sc_min_%dd\t%.10g\t0\n", dim, p.Sc_min);
    if (!p.valid) {
        fprintf(stderr, "dpd params: s = %g <= 0: eta must be below %g (eq. %d) or Sc above %g (eq. %d)\n",
                p.s, p.eta_max, dim == 3 ? 16 : 20, p.Sc_min, dim == 3 ? 17 : 21);
        return 2;
    }
    return 0;
}

/* dpd checkpoint-info DIR|FILE: what the checkpoint says of itself (checkpoint.h CheckpointInfo).
 * 0, 1 (usage) or 2 (no checkpoint there, or not a sound one). */
static int cmd_checkpoint_info(int argc, char **argv)
{
    if (argc != 1) { fprintf(stderr, "dpd checkpoint-info: need one run directory or checkpoint file\n"); return 1; }
    char path[4200];
    struct stat st;
    if (stat(argv[0], &st) == 0 && S_ISDIR(st.st_mode)) snprintf(path, sizeof path, "%s/%s", argv[0], CHECKPOINT_FILE);
    else snprintf(path, sizeof path, "%s", argv[0]);
    CheckpointInfo ci;
    char err[1400];
    if (checkpoint_info(path, &ci, err, sizeof err)) { fprintf(stderr, "dpd checkpoint-info: %s\n", err); return 2; }
    printf("quantity\tvalue\n");
    printf("step\t%llu\n", (unsigned long long)ci.step);
    printf("time\t%.10g\n", ci.time);
    printf("particles\t%u\n", (unsigned)ci.particles);
    printf("format\t%u\n", (unsigned)ci.version);
    return 0;
}

/* The options of dpd run that take a value. */
static int takes_value(const char *a)
{
    static const char *const with_value[] = {"--set", "--out", "--threads", "--checkpoint-every", "--checkpoint-wall"};
    for (size_t k = 0; k < sizeof with_value / sizeof with_value[0]; k++)
        if (!strcmp(a, with_value[k])) return 1;
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) { usage(stderr); return 1; }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) { usage(stdout); return 0; }
    if (!strcmp(argv[1], "--version")) { printf("dpd %s\n", DPD_GIT); return 0; }
    if (!strcmp(argv[1], "params")) return cmd_params(argc - 2, argv + 2);
    if (!strcmp(argv[1], "fit-line")) return cmd_fit_line(argc - 2, argv + 2);
    if (!strcmp(argv[1], "wavelengths")) return cmd_wavelengths(argc - 2, argv + 2);
    if (!strcmp(argv[1], "tcaf-fit")) return cmd_tcaf_fit(argc - 2, argv + 2);
    if (!strcmp(argv[1], "fit-poiseuille")) return poiseuille_command(argc - 2, argv + 2);
    if (!strcmp(argv[1], "checkpoint-info")) return cmd_checkpoint_info(argc - 2, argv + 2);
    if (strcmp(argv[1], "run")) { fprintf(stderr, "dpd: unknown command '%s'\n", argv[1]); usage(stderr); return 1; }
    RunOptions opt = {.outdir = "out"};
    int rc = 1;
    char **sets = calloc((size_t)argc, sizeof *sets);
    size_t cl = 1;
    for (int k = 0; k < argc; k++) cl += strlen(argv[k]) + 1;
    char *cmdline = calloc(cl, 1);
    if (!sets || !cmdline) return 4;
    for (int k = 0; k < argc; k++) { strcat(cmdline, argv[k]); if (k + 1 < argc) strcat(cmdline, " "); }
    opt.command_line = cmdline;
    for (int k = 2; k < argc; k++) {
        const char *a = argv[k];
        if (takes_value(a) && k + 1 < argc && !strncmp(argv[k + 1], "--", 2)) {
            /* "--out --quiet": the option is not the value (it would become a directory named --quiet) */
            fprintf(stderr, "dpd run: %s needs a value, not the option '%s'\n", a, argv[k + 1]);
            goto done;
        }
        if (!strcmp(a, "--set") || !strcmp(a, "--out") || !strcmp(a, "--threads")) {
            if (k + 1 >= argc) { fprintf(stderr, "dpd run: %s needs a value\n", a); goto done; }
            const char *v = argv[++k];
            if (!strcmp(a, "--set")) sets[opt.noverrides++] = (char *)v;
            else if (!strcmp(a, "--out")) opt.outdir = v;
            else {
                char *end;
                long t = strtol(v, &end, 10);
                if (*end || t < 1 || t > 1024) { fprintf(stderr, "dpd run: --threads %s: allowed 1 to 1024\n", v); goto done; }
                opt.threads = (int)t;
            }
        } else if (!strcmp(a, "--checkpoint-every")) {
            char *end;
            if (k + 1 >= argc) { fprintf(stderr, "dpd run: %s needs a value\n", a); goto done; }
            const char *v = argv[++k];
            errno = 0;
            long long c = strtoll(v, &end, 10);
            if (*end || end == v || c < 1 || errno == ERANGE) { fprintf(stderr, "dpd run: --checkpoint-every %s: allowed 1 to 9223372036854775807 steps\n", v); goto done; }
            opt.checkpoint_every = c;
        } else if (!strcmp(a, "--checkpoint-wall")) {
            char *end;
            if (k + 1 >= argc) { fprintf(stderr, "dpd run: %s needs a value\n", a); goto done; }
            const char *v = argv[++k];
            double w = strtod(v, &end);
            if (*end || end == v || !(w >= 0 && w <= 1e7)) { fprintf(stderr, "dpd run: --checkpoint-wall %s: allowed 0 to 1e7 seconds\n", v); goto done; }
            opt.checkpoint_wall = w;
        } else if (!strcmp(a, "--resume")) opt.resume = 1;
        else if (!strcmp(a, "--dry-run")) opt.dry_run = 1;
        else if (!strncmp(a, "--set=", 6)) sets[opt.noverrides++] = (char *)a + 6;
        else if (!strcmp(a, "--quiet")) opt.quiet = 1;
        else if (a[0] == '-' && a[1]) { fprintf(stderr, "dpd run: unknown option %s\n", a); usage(stderr); goto done; }
        else if (!opt.scene) opt.scene = a;
        else { fprintf(stderr, "dpd run: more than one scene given ('%s', '%s')\n", opt.scene, a); goto done; }
    }
    if (!opt.scene) { fprintf(stderr, "dpd run: no scene file given\n"); usage(stderr); goto done; }
    opt.overrides = sets;
    rc = run_scene(&opt);
done:
    free(sets);
    free(cmdline);
    return rc;
}
