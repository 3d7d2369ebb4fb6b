/* test_threads.c - the trajectory does not depend on the number of OpenMP
 * threads: the pair noise depends only on (seed, step, ids), the neighbour
 * list is concatenated in particle order and the forces are summed over
 * FORCE_CHUNKS fixed chunks in a fixed order (the TCAF current over TCAF_CHUNKS).
 * So runs with 1, 2 and 3 threads
 * must agree bit for bit (no tolerance). A small sheared system exercises the
 * Lees-Edwards boundaries and the binned stress; run.h5 stores frames in id
 * order, so rows are compared directly (equivalent to sorting by id). */
#include "runutil.h"

static const char *SCENE =
    "dimension = 3;\n"
    "box = [6.0, 6.0, 6.0];\n"
    "dt = 0.01;\n"
    "seed = 4242;\n"
    "steps = 100;\n"
    "shear_rate = 0.3;\n"
    "types = ( { name = \"w\"; density = 3.0; } );\n"
    "pairs = ( { types = [\"w\", \"w\"]; a = 25.0; gamma = 4.5; } );\n"
    "output = { trajectory_every = 100; };\n"
    "measure = { every = 10; blocks = 5; profile = { axis = \"y\"; bins = 6; }; };\n";

static char dir[512];

static int setup(void **state)
{
    (void)state;
    make_tmpdir(dir, sizeof dir, "threads");
    char scene[600];
    snprintf(scene, sizeof scene, "%s/scene.cfg", dir);
    write_text(scene, SCENE);
    for (int t = 1; t <= 3; t++) {
        char out[600];
        snprintf(out, sizeof out, "%s/out%d", dir, t);
        const int rc = run_quiet(scene, out, t);
        if (rc != 0) { fprintf(stderr, "run with %d threads: status %d\n", t, rc); return -1; }
    }
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    rm_rf(dir);
    return 0;
}

static void compare_dataset(const char *dset, hid_t type, size_t elsize)
{
    char f1[700];
    snprintf(f1, sizeof f1, "%s/out1/run.h5", dir);
    int n1 = 0;
    void *a = h5_last_frame(f1, dset, type, elsize, &n1);
    CHECK_TRUE(a != NULL, "cannot read %s from %s", dset, f1);
    CHECK_TRUE(n1 == 648, "%s: %d particles, want 648", dset, n1);
    for (int t = 2; t <= 3; t++) {
        char ft[700];
        snprintf(ft, sizeof ft, "%s/out%d/run.h5", dir, t);
        int nt = 0;
        void *b = h5_last_frame(ft, dset, type, elsize, &nt);
        CHECK_TRUE(b != NULL && nt == n1, "cannot read %s from %s", dset, ft);
        if (memcmp(a, b, (size_t)n1 * 3 * elsize) != 0) {
            for (int k = 0; k < 3 * n1; k++)
                if (memcmp((char *)a + k * elsize, (char *)b + k * elsize, elsize)) {
                    if (elsize == sizeof(double))
                        fail_msg("%s differs between 1 and %d threads: particle %d component %d: %.17g vs %.17g",
                                 dset, t, k / 3, k % 3, ((double *)a)[k], ((double *)b)[k]);
                    fail_msg("%s differs between 1 and %d threads at particle %d component %d", dset, t, k / 3, k % 3);
                }
        }
        free(b);
    }
    free(a);
}

static void positions_bitwise(void **state) { (void)state; compare_dataset("/particles/all/position/value", H5T_NATIVE_DOUBLE, sizeof(double)); }
static void velocities_bitwise(void **state) { (void)state; compare_dataset("/particles/all/velocity/value", H5T_NATIVE_DOUBLE, sizeof(double)); }
static void images_equal(void **state) { (void)state; compare_dataset("/particles/all/image/value", H5T_NATIVE_INT, sizeof(int)); }

/* The frame really is at step 100 and the particles moved (not a trivial pass). */
static void frame_is_final_and_moved(void **state)
{
    (void)state;
    char f1[700];
    snprintf(f1, sizeof f1, "%s/out1/run.h5", dir);
    hid_t f = H5Fopen(f1, H5F_ACC_RDONLY, H5P_DEFAULT);
    assert_true(f >= 0);
    hid_t d = H5Dopen2(f, "/particles/all/position/step", H5P_DEFAULT);
    assert_true(d >= 0);
    long long step[4] = {0};
    hid_t sp = H5Dget_space(d);
    hsize_t dims[2];
    H5Sget_simple_extent_dims(sp, dims, NULL);
    CHECK_TRUE(dims[0] == 1, "%llu frames, want 1", (unsigned long long)dims[0]);
    H5Dread(d, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, step);
    CHECK_TRUE(step[0] == 100, "frame at step %lld, want 100", step[0]);
    H5Sclose(sp); H5Dclose(d); H5Fclose(f);
    int n = 0;
    int *img = h5_last_frame(f1, "/particles/all/image/value", H5T_NATIVE_INT, sizeof(int), &n);
    assert_non_null(img);
    int crossed_y = 0;
    for (int i = 0; i < n; i++) crossed_y += img[3 * i + 1] != 0;
    CHECK_TRUE(crossed_y > 0, "no particle crossed the sheared boundary: Lees-Edwards not exercised");
    free(img);
}

/* Measured averages (virial, binned stress) agree as well. */
static void summaries_equal(void **state)
{
    (void)state;
    static const char *keys[] = {"temperature", "pressure", "stress_xy", "viscosity", "potential_energy_per_particle"};
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
        double v1 = NAN, e1 = NAN;
        char d1[600];
        snprintf(d1, sizeof d1, "%s/out1", dir);
        CHECK_TRUE(summary_get(d1, keys[k], &v1, &e1) == 0, "summary.tsv: no %s", keys[k]);
        for (int t = 2; t <= 3; t++) {
            double v = NAN, e = NAN;
            char dt[600];
            snprintf(dt, sizeof dt, "%s/out%d", dir, t);
            CHECK_TRUE(summary_get(dt, keys[k], &v, &e) == 0, "summary.tsv (%d threads): no %s", t, keys[k]);
            CHECK_TRUE(v == v1 && (e == e1 || (isnan(e) && isnan(e1))),
                       "%s: %.10g +- %.3g with 1 thread, %.10g +- %.3g with %d", keys[k], v1, e1, v, e, t);
        }
    }
    char p1[1400], p2[1400];
    snprintf(p1, sizeof p1, "cmp -s %s/out1/profile.tsv %s/out2/profile.tsv", dir, dir);
    snprintf(p2, sizeof p2, "cmp -s %s/out1/profile.tsv %s/out3/profile.tsv", dir, dir);
    CHECK_TRUE(system(p1) == 0 && system(p2) == 0, "profile.tsv (binned IK stress) differs between thread counts");
}

/* The TCAF current J(k) (eq. 23) is summed over fixed particle chunks in a
 * fixed order: its tables do not depend on the thread count either. */
static const char *TCAF_SCENE =
    "dimension = 3;\n"
    "box = [5.0, 5.0, 5.0];\n"
    "dt = 0.01;\n"
    "seed = 17;\n"
    "equilibration = 20;\n"
    "steps = 400;\n"
    "types = ( { name = \"w\"; density = 3.0; } );\n"
    "pairs = ( { types = [\"w\", \"w\"]; a = 25.0; gamma = 4.5; } );\n"
    "measure = { every = 5; blocks = 4;\n"
    "  tcaf = { every = 2; window = 80; origin_every = 10; n2max = 5; fit_min = 0.3; }; };\n";

static void tcaf_tables_equal(void **state)
{
    (void)state;
    char scene[600], out[2][600], cmd[2600];
    snprintf(scene, sizeof scene, "%s/tcaf.cfg", dir);
    write_text(scene, TCAF_SCENE);
    for (int t = 1; t <= 2; t++) {
        snprintf(out[t - 1], sizeof out[t - 1], "%s/tcaf%d", dir, t);
        CHECK_TRUE(run_quiet(scene, out[t - 1], t) == 0, "TCAF run with %d threads failed", t);
    }
    /* the summary rows carry 10 digits (the tables fewer): a per-thread
     * partial sum shows there, in eta(k) and its fits */
    for (int t = 0; t < 2; t++) {
        snprintf(cmd, sizeof cmd, "grep '^tcaf' %s/summary.tsv > %s/tcaf-rows.tsv", out[t], out[t]);
        CHECK_TRUE(system(cmd) == 0, "no tcaf rows in %s/summary.tsv", out[t]);
    }
    static const char *tables[] = {"tcaf-rows.tsv", "tcaf.tsv", "tcaf_eta.tsv", "tcaf_extrapolation.tsv"};
    for (size_t k = 0; k < sizeof tables / sizeof tables[0]; k++) {
        snprintf(cmd, sizeof cmd, "cmp -s %s/%s %s/%s", out[0], tables[k], out[1], tables[k]);
        CHECK_TRUE(system(cmd) == 0, "%s differs between 1 and 2 threads", tables[k]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(frame_is_final_and_moved),
        cmocka_unit_test(positions_bitwise),
        cmocka_unit_test(velocities_bitwise),
        cmocka_unit_test(images_equal),
        cmocka_unit_test(summaries_equal),
        cmocka_unit_test(tcaf_tables_equal),
    };
    return cmocka_run_group_tests_name("threads", tests, setup, teardown);
}
