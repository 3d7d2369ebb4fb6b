/* test_reference_forces.c - the simulator's forces, torques, virial by part
 * and energy against codes other than ours (issue 39, item 2): LAMMPS `pair
 * dpd` and `pair dpd/ext` (standard DPD, the general weight exponent, 2D, two
 * Lees-Edwards boxes with an offset, one beyond L_x / 2) and the paper's
 * equations of Pan et al. 2008 (eqs 1, 7, 13-15) evaluated in numpy, at kBT =
 * 0, for small fixed configurations with pairs near the cutoff, at small r,
 * coincident and across every face. The references, their conventions and
 * the error model are those of tests/reference/make-references.py, which
 * wrote the tests/reference/NAME.ref files.
 *
 * Tolerance: each reference value carries its error scale from that model
 * (separations within 8 eps L in each code, velocities within 4 eps of their
 * sizes, 32 eps per pair term, n eps for a sum of n terms, the
 * sensitivity of each pair to its separation); a value passes when within
 * 2^-52 x scale. The forces are compared at every instruction-set level the
 * CPU has (the vector evaluators of one-type batches, the Pan 2008 lanes),
 * on a step without and a step with the virial. */
#include "testutil.h"
#include "system.h"
#include "box.h"
#include "neighbor.h"
#include "forces.h"
#include "rotation.h"
#include "simd.h"

#define MAXP 128

typedef struct {
    char name[64];
    int dim, rotation, ntypes, n, npairs;
    double L[3], rate, offset;
    PairParams pair[DPD_MAX_TYPES][DPD_MAX_TYPES];
    int have_pair[DPD_MAX_TYPES][DPD_MAX_TYPES];
    int type[MAXP];
    double x[MAXP][3], v[MAXP][3], w[MAXP][3];
    double f[MAXP][3], fscale[MAXP], t[MAXP][3], tscale[MAXP];
    double W[PAIR_PARTS][9], Wscale, E, Escale;
    int have_force[MAXP], have_torque[MAXP];
} Ref;

static void ref_read(Ref *r, const char *name)
{
    char path[512], line[2048];
    const char *dir = getenv("DPD_REFERENCE_DIR") ? getenv("DPD_REFERENCE_DIR") : "tests/reference";
    snprintf(path, sizeof path, "%s/%s.ref", dir, name);
    FILE *f = fopen(path, "r");
    CHECK_TRUE(f != NULL, "cannot open %s (run from the repository top or set DPD_REFERENCE_DIR)", path);
    memset(r, 0, sizeof *r);
    snprintf(r->name, sizeof r->name, "%s", name);
    int lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char key[32];
        int k, ti, tj, used = 0;
        if (line[0] == '#' || sscanf(line, "%31s%n", key, &used) != 1) continue;
        const char *rest = line + used;
        int ok = 1;
        if (!strcmp(key, "dim")) ok = sscanf(rest, "%d", &r->dim) == 1;
        else if (!strcmp(key, "box")) ok = sscanf(rest, "%lf %lf %lf", &r->L[0], &r->L[1], &r->L[2]) == 3;
        else if (!strcmp(key, "shear")) ok = sscanf(rest, "%lf %lf", &r->rate, &r->offset) == 2;
        else if (!strcmp(key, "rotation")) ok = sscanf(rest, "%d", &r->rotation) == 1;
        else if (!strcmp(key, "types")) ok = sscanf(rest, "%d", &r->ntypes) == 1 && r->ntypes <= DPD_MAX_TYPES;
        else if (!strcmp(key, "particles")) ok = sscanf(rest, "%d", &r->n) == 1 && r->n <= MAXP;
        else if (!strcmp(key, "pairs")) ok = sscanf(rest, "%d", &r->npairs) == 1;
        else if (!strcmp(key, "pair")) {
            PairParams p = {.active = 1};
            ok = sscanf(rest, "%d %d %lf %lf %lf %lf %lf", &ti, &tj, &p.a, &p.gamma, &p.s, &p.rc, &p.gamma_shear) == 7
              && ti >= 0 && tj >= 0 && ti < DPD_MAX_TYPES && tj < DPD_MAX_TYPES;
            if (ok) { r->pair[ti][tj] = r->pair[tj][ti] = p; r->have_pair[ti][tj] = r->have_pair[tj][ti] = 1; }
        } else if (!strcmp(key, "p")) {
            int ty;
            double q[9];
            ok = sscanf(rest, "%d %d %lf %lf %lf %lf %lf %lf %lf %lf %lf", &k, &ty, &q[0], &q[1], &q[2], &q[3], &q[4],
                        &q[5], &q[6], &q[7], &q[8]) == 11 && k >= 0 && k < MAXP;
            if (ok) {
                r->type[k] = ty;
                for (int a = 0; a < 3; a++) { r->x[k][a] = q[a]; r->v[k][a] = q[3 + a]; r->w[k][a] = q[6 + a]; }
            }
        } else if (!strcmp(key, "force")) {
            double q[4];
            ok = sscanf(rest, "%d %lf %lf %lf %lf", &k, &q[0], &q[1], &q[2], &q[3]) == 5 && k >= 0 && k < MAXP;
            if (ok) { for (int a = 0; a < 3; a++) r->f[k][a] = q[a]; r->fscale[k] = q[3]; r->have_force[k] = 1; }
        } else if (!strcmp(key, "torque")) {
            double q[4];
            ok = sscanf(rest, "%d %lf %lf %lf %lf", &k, &q[0], &q[1], &q[2], &q[3]) == 5 && k >= 0 && k < MAXP;
            if (ok) { for (int a = 0; a < 3; a++) r->t[k][a] = q[a]; r->tscale[k] = q[3]; r->have_torque[k] = 1; }
        } else if (!strcmp(key, "virial")) {
            char part;
            double q[10];
            ok = sscanf(rest, " %c %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &part, &q[0], &q[1], &q[2], &q[3], &q[4],
                        &q[5], &q[6], &q[7], &q[8], &q[9]) == 11;
            const int pq = part == 'C' ? PART_CONSERVATIVE : part == 'D' ? PART_DISSIPATIVE : PART_RANDOM;
            if (ok) { for (int c = 0; c < 9; c++) r->W[pq][c] = q[c]; r->Wscale = q[9]; }
        } else if (!strcmp(key, "energy")) ok = sscanf(rest, "%lf %lf", &r->E, &r->Escale) == 2;
        else ok = 0;
        CHECK_TRUE(ok, "%s:%d: cannot read: %s", path, lineno, line);
    }
    fclose(f);
    CHECK_TRUE(r->n > 0 && r->dim >= 2 && r->ntypes > 0, "%s: no configuration", path);
    for (int k = 0; k < r->n; k++) CHECK_TRUE(r->have_force[k], "%s: no force of particle %d", path, k);
}

/* The reference's configuration as a System (kBT = 0: sigma = 0 in every
 * part), ids = the reference's indices. */
static void ref_system(const Ref *r, System *s)
{
    memset(s, 0, sizeof *s);
    assert_int_equal(system_alloc(s, r->n), 0);
    box_init(&s->box, r->dim, r->L, r->rate);
    s->box.le_offset = r->offset;
    s->ntypes = r->ntypes;
    for (int t = 0; t < r->ntypes; t++) {
        snprintf(s->types[t].name, sizeof s->types[t].name, "t%d", t);
        s->types[t].mass = 1.0;
        s->types[t].inertia = 0.1;
        s->types[t].body_force_flip_axis = -1;
    }
    s->kBT = 0.0; s->dt = 0.01; s->lambda = 0.5; s->seed = 5; s->step = 1;
    for (int a = 0; a < r->ntypes; a++)
        for (int b = a; b < r->ntypes; b++) {
            CHECK_TRUE(r->have_pair[a][b], "%s: no parameters of type pair (%d, %d)", r->name, a, b);
            system_set_pair(s, a, b, r->pair[a][b]);
        }
    for (int k = 0; k < r->n; k++) {
        s->id[k] = (uint32_t)k;
        s->type[k] = (uint8_t)r->type[k];
        for (int a = 0; a < 3; a++) { s->x[3 * k + a] = r->x[k][a]; s->v[3 * k + a] = s->v_pred[3 * k + a] = r->v[k][a]; }
    }
    if (r->rotation) {
        assert_int_equal(rotation_alloc(s), 0);
        for (int k = 0; k < r->n; k++)
            for (int a = 0; a < 3; a++) s->omega[3 * k + a] = s->omega_pred[3 * k + a] = r->w[k][a];
    }
}

/* the largest |difference| / tolerance seen in a case (printed: how close it came) */
static double worst;
static void note(double got, double want, double tol)
{
    if (tol > 0.0 && fabs(got - want) / tol > worst) worst = fabs(got - want) / tol;
}

/* Forces (and torques) by particle id against the reference, within eps x scale. */
static void compare_particles(const Ref *r, const System *s, const char *when)
{
    for (int i = 0; i < s->n; i++) {
        const int k = (int)s->id[i];
        for (int a = 0; a < 3; a++) {
            char what[160];
            snprintf(what, sizeof what, "%s, %s: F_%c of particle %d", r->name, when, "xyz"[a], k);
            CHECK_ABS(what, s->f[3 * i + a], r->f[k][a], DBL_EPSILON * r->fscale[k]);
            note(s->f[3 * i + a], r->f[k][a], DBL_EPSILON * r->fscale[k]);
            if (r->rotation) {
                snprintf(what, sizeof what, "%s, %s: T_%c of particle %d", r->name, when, "xyz"[a], k);
                CHECK_ABS(what, s->torque[3 * i + a], r->t[k][a], DBL_EPSILON * r->tscale[k]);
                note(s->torque[3 * i + a], r->t[k][a], DBL_EPSILON * r->tscale[k]);
            }
        }
    }
}

static void compare_reference(const char *name)
{
    static Ref r;
    ref_read(&r, name);
    System s;
    ref_system(&r, &s);
    NeighborList nl;
    ForceWork fw;
    assert_int_equal(neighbor_init(&nl, &s, 0.3), 0);
    assert_int_equal(neighbor_build(&nl, &s), 0);
    assert_int_equal(forces_init(&fw, &s, 0), 0);
    const int best = simd_cap(-1);
    int pairs_in_list = 0;
    worst = 0.0;
    for (int level = 0; level <= 2; level++) {
        if (simd_cap(level) != level) continue;
        char when[64];
        snprintf(when, sizeof when, "level %d, no virial", level);
        forces_compute(&s, &nl, &fw, NULL);
        compare_particles(&r, &s, when);
        PairVirial pv = {.bin_axis = -1};
        forces_compute(&s, &nl, &fw, &pv);
        snprintf(when, sizeof when, "level %d, with the virial", level);
        compare_particles(&r, &s, when);
        for (int q = 0; q < PAIR_PARTS; q++)
            for (int c = 0; c < 9; c++) {
                char what[160];
                snprintf(what, sizeof what, "%s, level %d: virial part %d, W_%c%c", name, level, q, "xyz"[c / 3], "xyz"[c % 3]);
                CHECK_ABS(what, pv.W[q][c / 3][c % 3], r.W[q][c], DBL_EPSILON * r.Wscale);
                note(pv.W[q][c / 3][c % 3], r.W[q][c], DBL_EPSILON * r.Wscale);
            }
        char what[160];
        snprintf(what, sizeof what, "%s, level %d: pair energy", name, level);
        CHECK_ABS(what, pv.epot, r.E, DBL_EPSILON * r.Escale);
        note(pv.epot, r.E, DBL_EPSILON * r.Escale);
        pairs_in_list = (int)neighbor_pairs(&nl);
    }
    simd_cap(best);
    /* the list holds every pair of the reference (and more, within rc + skin) */
    CHECK_TRUE(pairs_in_list >= r.npairs, "%s: %d listed pairs, the reference has %d in range", name, pairs_in_list, r.npairs);
    printf("%s: %d particles, %d pairs in range; the largest difference %.3g of its tolerance\n", name, r.n, r.npairs, worst);
    forces_free(&fw);
    neighbor_free(&nl);
    system_free(&s);
}

static void lammps_dpd(void **state) { (void)state; compare_reference("lammps-dpd"); }
static void lammps_dpd_ext_mai_duy(void **state) { (void)state; compare_reference("lammps-dpd-ext-mai-duy"); }
static void lammps_dpd_ext_exponents(void **state) { (void)state; compare_reference("lammps-dpd-ext-exponents"); }
static void lammps_dpd_2d(void **state) { (void)state; compare_reference("lammps-dpd-2d"); }
static void lammps_dpd_lees_edwards(void **state) { (void)state; compare_reference("lammps-dpd-lees-edwards"); }
static void lammps_dpd_ext_lees_edwards(void **state) { (void)state; compare_reference("lammps-dpd-ext-lees-edwards"); }
static void pan2008_eqs(void **state) { (void)state; compare_reference("pan2008"); }
static void pan2008_lees_edwards(void **state) { (void)state; compare_reference("pan2008-lees-edwards"); }

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lammps_dpd),
        cmocka_unit_test(lammps_dpd_ext_mai_duy),
        cmocka_unit_test(lammps_dpd_ext_exponents),
        cmocka_unit_test(lammps_dpd_2d),
        cmocka_unit_test(lammps_dpd_lees_edwards),
        cmocka_unit_test(lammps_dpd_ext_lees_edwards),
        cmocka_unit_test(pan2008_eqs),
        cmocka_unit_test(pan2008_lees_edwards),
    };
    return cmocka_run_group_tests_name("reference_forces", tests, NULL, NULL);
}
