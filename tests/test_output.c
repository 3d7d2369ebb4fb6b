/* test_output.c - the HDF5 output releases every handle on every path: a run
 * whose k-th HDF5 group creation fails (k = 1, 2, ...: output_open's header and
 * trajectory groups, the segment files, run.h5's results) ends with no HDF5
 * file or object left open, as a complete run does. H5Gcreate2 is wrapped at
 * link time (tests.mk: -Wl,--wrap=H5Gcreate2 for this test only). */
#include "runutil.h"

hid_t __real_H5Gcreate2(hid_t loc, const char *name, hid_t lcpl, hid_t gcpl, hid_t gapl);
static int calls, fail_at;   /* fail the fail_at-th call (0: never) */

hid_t __wrap_H5Gcreate2(hid_t loc, const char *name, hid_t lcpl, hid_t gcpl, hid_t gapl)
{
    if (++calls == fail_at) return -1;
    return __real_H5Gcreate2(loc, name, lcpl, gcpl, gapl);
}

static const char *SCENE =
    "dimension = 3; box = [5.0, 5.0, 5.0]; dt = 0.01; steps = 20; seed = 3;\n"
    "types = ( { name = \"w\"; density = 3.0; } );\n"
    "pairs = ( { types = [\"w\", \"w\"]; a = 25.0; gamma = 4.5; } );\n"
    "output = { trajectory_every = 5; };\n";

static ssize_t open_ids(void) { return H5Fget_obj_count((hid_t)H5F_OBJ_ALL, H5F_OBJ_ALL); }

/* With no failure: status 0 and nothing left open; then each call failing in turn. */
static void every_failure_closes_the_files(void **state)
{
    (void)state;
    char dir[512], out[700];
    calls = 0;
    fail_at = 0;
    assert_int_equal(run_scene_text("output", SCENE, dir, sizeof dir, out, sizeof out), 0);
    const int total = calls;
    CHECK_TRUE(total >= 3, "a run creates %d groups, want at least 3", total);
    CHECK_TRUE(open_ids() == 0, "complete run: %zd HDF5 ids left open", open_ids());
    rm_rf(dir);
    int bad = 0;
    for (int k = 1; k <= total; k++) {
        calls = 0;
        fail_at = k;
        const int st = run_scene_text("output", SCENE, dir, sizeof dir, out, sizeof out);
        const ssize_t left = open_ids();
        if (st != 4 || left != 0) {
            fprintf(stderr, "group creation %d of %d failed: status %d (want 4), %zd HDF5 ids left open (want 0)\n",
                    k, total, st, left);
            bad++;
            H5close();   /* the next run starts from a clean library */
        }
        rm_rf(dir);
    }
    fail_at = 0;
    CHECK_TRUE(bad == 0, "%d of %d failure paths left a wrong status or HDF5 ids open", bad, total);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_failure_closes_the_files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
