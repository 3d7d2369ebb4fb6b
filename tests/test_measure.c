/* test_measure.c - the writers of src/measure/measure.c against more blocks than their
 * per-block arrays hold (issue 24, bug 4c): the scene validator allows at most
 * 1000 blocks, but a caller that bypasses it must get an error, not a read past
 * an array or silently dropped blocks. */
#include "testutil.h"
#include <unistd.h>
#include "measure.h"

enum { NBLOCKS = 1100, BINS = 2 };   /* more blocks than the arrays (1024 before issue 24) */

/* 64 particles on a cubic lattice in a box of side 4. */
static void lattice(System *s)
{
    memset(s, 0, sizeof *s);
    const double L[3] = {4.0, 4.0, 4.0};
    box_init(&s->box, 3, L, 0.0);
    assert_int_equal(system_alloc(s, 64), 0);
    s->ntypes = 1;
    snprintf(s->types[0].name, sizeof s->types[0].name, "w");
    s->types[0].mass = 1.0;
    s->kBT = 1.0;
    s->dt = 0.01;
    for (int i = 0; i < s->n; i++) {
        s->id[i] = (uint32_t)i;
        s->x[3 * i] = i % 4 + 0.5; s->x[3 * i + 1] = i / 4 % 4 + 0.5; s->x[3 * i + 2] = i / 16 + 0.5;
    }
}

/* A profile with a sample in every one of NBLOCKS blocks: measure_write fails. */
static void profile_with_too_many_blocks_is_refused(void **state)
{
    (void)state;
    System s; lattice(&s);
    Measure m;
    memset(&m, 0, sizeof m);
    m.every = 1; m.nblocks = NBLOCKS; m.prof_on = 1; m.prof_axis = 1; m.prof_bins = BINS;
    assert_int_equal(measure_init(&m, &s), 0);
    for (int k = 0; k < NBLOCKS; k++) {
        m.prof_samples[k] = 1;
        for (int b = 0; b < BINS; b++) {
            double *q = m.prof + ((size_t)k * BINS + b) * PROF_Q;
            q[0] = 32.0; q[1] = 32.0;   /* particles and mass of the bin */
        }
    }
    char dir[] = "/tmp/dpd-test-measure-XXXXXX";
    assert_non_null(mkdtemp(dir));
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    const int rc = measure_write(&m, &s, f, dir);
    fclose(f);
    free(buf);
    char path[128];
    snprintf(path, sizeof path, "%s/profile.tsv", dir);
    unlink(path);
    rmdir(dir);
    CHECK_TRUE(rc != 0, "measure_write of %d blocks returned %d: it must refuse more blocks than it holds",
               NBLOCKS, rc);
    measure_free(&m);
    system_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(profile_with_too_many_blocks_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
