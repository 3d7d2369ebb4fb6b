/* test_pair_style.c - adding a pair style (src/pair/pair_style.h): the worked
 * example of README.md, "Pair styles", registered here and run through the
 * walk (with and without Lees-Edwards shear, at every instruction-set
 * level), the virial by part, the pair energy and the m = 0 assembly, each
 * against an all-pairs sum of the same formulas written out below. And the
 * registry: the built-in styles by name, a name taken twice refused.
 *
 * The example: a Morse pair (Morse 1929) with the DPD thermostat of Groot &
 * Warren (w_R = 1 - r/rc, w_D = w_R^2),
 *   V(r) = D [e^{-2 alpha (r - r0)} - 2 e^{-alpha (r - r0)}] - V(rc),
 *   F_ij = [2 alpha D (x^2 - x) - gamma w_D e.v_ij + sigma w_R theta / sqrt(dt)] e_ij,
 *   x = e^{-alpha (r - r0)},
 * with D, alpha, r0 in PairParams.coef.
 *
 * Tolerances: each force is a sum of some 40 pair terms, each of a few tens of
 * roundings in either code (the exp's within 1 ulp): 64 eps times the sum of
 * the absolute values of the terms. */
#include "testutil.h"
#include "system.h"
#include "box.h"
#include "neighbor.h"
#include "forces.h"
#include "overdamped.h"
#include "random.h"
#include "simd.h"

/* ---- the style: one file in src/pair/ would hold exactly this ------------- */
/* (README.md, "Pair styles", shows this block as it is) */
#include "pair_walk.h"

/* F_ij = [2 alpha D (x^2 - x) - gamma w^2 e.v_ij + sigma w theta / sqrt(dt)] e_ij,
 * x = exp(-alpha (r - r0)), w = 1 - r/rc; D, alpha, r0 in coef */
static inline __attribute__((always_inline))
void morse_pair(const PairParams *p, const PairIn *in, PairOut *out, int record)
{
    const double D = p->coef[0], alpha = p->coef[1], r0 = p->coef[2];
    const double x = exp(-alpha * (in->r - r0)), w = 1.0 - in->r / p->rc;
    const double edv = in->e[0] * in->dv[0] + in->e[1] * in->dv[1] + in->e[2] * in->dv[2];
    const double fc = 2.0 * alpha * D * (x * x - x), fd = -p->gamma * w * w * edv;
    const double fr = p->sigma * w * in->noise[0] * in->inv_sqrt_dt;
    for (int a = 0; a < 3; a++) out->F[a] = (fc + fd + fr) * in->e[a];
    if (record) {   /* a measurement step: the parts along e_ij and the energy, V(rc) = 0 */
        const double xc = exp(-alpha * (p->rc - r0));
        out->mag[PART_CONSERVATIVE] = fc; out->mag[PART_DISSIPATIVE] = fd; out->mag[PART_RANDOM] = fr;
        out->energy = D * (x * x - 2.0 * x) - D * (xc * xc - 2.0 * xc);
    }
}
static const PairEvaluator morse_evaluator = {.nvar = 1, .central = 1, .pair = morse_pair};
PAIR_STYLE_WALKS(morse, morse_evaluator)   /* morse_walk_plain, morse_walk_shear */

static void morse_one(const PairParams *p, const PairIn *in, PairOut *out) { morse_pair(p, in, out, 1); }
/* m = 0: F_ij = (fcr - g e.v_ij) e_ij */
static void morse_overdamped(const PairParams *p, double r, double theta, double inv_sqrt_dt, double *fcr, double *g)
{
    const double D = p->coef[0], alpha = p->coef[1], r0 = p->coef[2];
    const double x = exp(-alpha * (r - r0)), w = 1.0 - r / p->rc;
    *fcr = 2.0 * alpha * D * (x * x - x) + p->sigma * w * theta * inv_sqrt_dt;
    *g = p->gamma * w * w;
}
const PairStyle morse_style = {
    .name = "morse", .nvar = 1, .central = 1, .walk = {morse_walk_plain, morse_walk_shear},
    .one = morse_one, .overdamped = morse_overdamped,
};
/* ---- end of the style ----------------------------------------------------- */

static const double D0 = 2.0, ALPHA = 3.0, R0 = 0.7, GAMMA = 4.5, RC = 1.0;

static void registered(void **state)
{
    (void)state;
    CHECK_TRUE(pair_style_find("dpd") && pair_style_find("pan2008"), "the built-in styles are not registered");
    CHECK_TRUE(pair_style_find("morse") == NULL, "morse registered before the test registers it");
    assert_int_equal(pair_style_register(&morse_style), 0);
    CHECK_TRUE(pair_style_find("morse") == &morse_style, "morse not found after its registration");
    CHECK_TRUE(pair_style_register(&morse_style) == -1, "a name registered twice");
    /* a System without its own style gets the one that serves it */
    System s;
    memset(&s, 0, sizeof s);
    CHECK_TRUE(pair_style_of(&s) == pair_style_find("dpd"), "a scene without rotation is not standard DPD");
    s.rotation = 1;
    CHECK_TRUE(pair_style_of(&s) == pair_style_find("pan2008"), "a rotation scene is not Pan 2008");
    s.pair_style = &morse_style;
    CHECK_TRUE(pair_style_of(&s) == &morse_style, "a System's own style is not used");
}

/* n particles at random in a periodic (rate = 0) or sheared box, one type with
 * the Morse style, random velocities, kBT = 1 (the random force on). */
static void morse_system(System *s, int n, const double L[3], double rate, double offset, uint64_t seed)
{
    memset(s, 0, sizeof *s);
    assert_int_equal(system_alloc(s, n), 0);
    box_init(&s->box, 3, L, rate);
    s->box.le_offset = offset;
    s->ntypes = 1;
    snprintf(s->types[0].name, sizeof s->types[0].name, "m");
    s->types[0].mass = 1.0;
    s->types[0].body_force_flip_axis = -1;
    s->kBT = 1.0; s->dt = 0.01; s->lambda = 0.5; s->seed = 77; s->step = 5;
    PairParams p = {.active = 1, .gamma = GAMMA, .s = 2.0, .rc = RC, .coef = {D0, ALPHA, R0}};
    system_set_pair(s, 0, 0, p);
    s->pair_style = pair_style_find("morse");
    CHECK_TRUE(s->pair_style != NULL, "morse is not registered");
    uint64_t st = seed;
    for (int i = 0; i < n; i++) {
        s->id[i] = (uint32_t)i;
        for (int a = 0; a < 3; a++) {
            s->x[3 * i + a] = L[a] * tu_uniform(&st);
            s->v[3 * i + a] = s->v_pred[3 * i + a] = 2.0 * tu_uniform(&st) - 1.0;
        }
    }
}

/* All pairs, minimum image (with j's image velocity): the Morse forces by
 * particle id, the virial by part, the energy and each particle's error scale. */
static void morse_all_pairs(const System *s, double *F, double *scale, double W[PAIR_PARTS][9], double *E,
                            double *Wscale)
{
    const int n = s->n;
    memset(F, 0, 3 * (size_t)n * sizeof(double));
    memset(scale, 0, (size_t)n * sizeof(double));
    memset(W, 0, PAIR_PARTS * 9 * sizeof(double));
    *E = 0.0; *Wscale = 0.0;
    const double sigma = sqrt(2.0 * GAMMA * s->kBT), xc = exp(-ALPHA * (RC - R0));
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            double d[3] = {s->x[3 * i] - s->x[3 * j], s->x[3 * i + 1] - s->x[3 * j + 1], s->x[3 * i + 2] - s->x[3 * j + 2]};
            double dvx = s->v_pred[3 * i] - s->v_pred[3 * j];
            box_min_image(&s->box, d, &dvx);
            const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (r >= RC || r < PAIR_R_EPSILON) continue;
            const double dv[3] = {dvx, s->v_pred[3 * i + 1] - s->v_pred[3 * j + 1], s->v_pred[3 * i + 2] - s->v_pred[3 * j + 2]};
            const double e[3] = {d[0] / r, d[1] / r, d[2] / r};
            const double x = exp(-ALPHA * (r - R0)), w = 1.0 - r / RC;
            const double part[3] = {2.0 * ALPHA * D0 * (x * x - x), -GAMMA * w * w * (e[0] * dv[0] + e[1] * dv[1] + e[2] * dv[2]),
                                    sigma * w * rng_pair_normal(s->seed, s->step, s->id[i], s->id[j]) / sqrt(s->dt)};
            const double mag = fabs(part[0]) + fabs(part[1]) + fabs(part[2]);
            const int ki = (int)s->id[i], kj = (int)s->id[j];   /* by id: the list sorts the particles */
            for (int a = 0; a < 3; a++) {
                const double fa = (part[0] + part[1] + part[2]) * e[a];
                F[3 * ki + a] += fa;
                F[3 * kj + a] -= fa;
            }
            scale[ki] += mag; scale[kj] += mag;
            for (int q = 0; q < PAIR_PARTS; q++)
                for (int k = 0; k < 9; k++) W[q][k] += d[k / 3] * part[q] * e[k % 3];
            *Wscale += r * mag;
            *E += D0 * (x * x - 2.0 * x) - D0 * (xc * xc - 2.0 * xc);
        }
}

/* The walk, its virial and the energy against all pairs, periodic and sheared,
 * at every level the CPU has (the style has no accelerators: on AVX-512 the
 * walk's candidate pass is vectorised, the pairs go through morse_pair). */
static void morse_walk_virial_energy(void **state)
{
    (void)state;
    const double L[3] = {5.0, 5.5, 6.0};
    const int n = 500;
    double *F = malloc(3 * (size_t)n * sizeof(double)), *scale = malloc((size_t)n * sizeof(double));
    assert_non_null(F); assert_non_null(scale);
    const int best = simd_cap(-1);
    for (int sheared = 0; sheared <= 1; sheared++) {
        System s;
        morse_system(&s, n, L, sheared ? 0.6 : 0.0, sheared ? 3.3 : 0.0, 41 + (uint64_t)sheared);
        NeighborList nl;
        ForceWork fw;
        assert_int_equal(neighbor_init(&nl, &s, 0.3), 0);
        assert_int_equal(neighbor_build(&nl, &s), 0);
        assert_int_equal(forces_init(&fw, &s, 0), 0);
        double W[PAIR_PARTS][9], E, Wscale;
        morse_all_pairs(&s, F, scale, W, &E, &Wscale);
        for (int level = 0; level <= 2; level++) {
            if (simd_cap(level) != level) continue;
            PairVirial pv = {.bin_axis = -1};
            forces_compute(&s, &nl, &fw, &pv);
            double worst = 0.0;
            for (int i = 0; i < n; i++) {
                const int k = (int)s.id[i];
                for (int a = 0; a < 3; a++) {
                    const double tol = 64.0 * DBL_EPSILON * scale[k];
                    char what[96];
                    snprintf(what, sizeof what, "shear %d, level %d: F_%c of particle %d", sheared, level, "xyz"[a], k);
                    CHECK_ABS(what, s.f[3 * i + a], F[3 * k + a], tol);
                    worst = fmax(worst, fabs(s.f[3 * i + a] - F[3 * k + a]));
                }
            }
            for (int q = 0; q < PAIR_PARTS; q++)
                for (int c = 0; c < 9; c++) {
                    char what[96];
                    snprintf(what, sizeof what, "shear %d, level %d: virial part %d, W_%c%c", sheared, level, q, "xyz"[c / 3], "xyz"[c % 3]);
                    CHECK_ABS(what, pv.W[q][c / 3][c % 3], W[q][c], 64.0 * DBL_EPSILON * Wscale);
                }
            CHECK_ABS("pair energy", pv.epot, E, 64.0 * DBL_EPSILON * Wscale);
            CHECK_TRUE(fabs(pv.W[PART_RANDOM][0][0]) > 1.0 && fabs(E) > 1.0, "no random virial or no energy: vacuous");
            printf("morse, shear %d, level %d: %zu pairs listed, largest force difference %.2g, energy %.6g\n",
                   sheared, level, neighbor_pairs(&nl), worst, pv.epot);
        }
        forces_free(&fw);
        neighbor_free(&nl);
        system_free(&s);
    }
    simd_cap(best);
    free(F); free(scale);
}

/* The m = 0 assembly with the style: f - A v at the particles' velocities is
 * each particle's pair force (the friction is linear in v), so it equals the
 * all-pairs sum (Phan-Thien et al. 2016 eqs 15-18), periodic and sheared. */
static void morse_overdamped_assembly(void **state)
{
    (void)state;
    const double L[3] = {5.0, 5.5, 6.0};
    const int n = 500;
    double *F = malloc(3 * (size_t)n * sizeof(double)), *scale = malloc((size_t)n * sizeof(double));
    assert_non_null(F); assert_non_null(scale);
    for (int sheared = 0; sheared <= 1; sheared++) {
        System s;
        morse_system(&s, n, L, sheared ? 0.6 : 0.0, sheared ? 3.3 : 0.0, 51 + (uint64_t)sheared);
        memcpy(s.v, s.v_pred, 3 * (size_t)n * sizeof(double));
        NeighborList nl;
        assert_int_equal(neighbor_init(&nl, &s, 0.3), 0);
        assert_int_equal(neighbor_build(&nl, &s), 0);
        double W[PAIR_PARTS][9], E, Wscale;
        morse_all_pairs(&s, F, scale, W, &E, &Wscale);
        OdSystem od;
        od_init(&od);
        assert_int_equal(od_assemble(&od, &s, &nl), 0);
        double *v = malloc(3 * (size_t)n * sizeof(double)), *Av = malloc(3 * (size_t)n * sizeof(double));
        assert_non_null(v); assert_non_null(Av);
        od_gather(&od, &s, v);
        od_matvec(&od, v, Av);
        for (int r = 0; r < od.nm; r++) {
            const int i = od.part_of[r], k = (int)s.id[i];
            for (int a = 0; a < 3; a++) {
                char what[96];
                snprintf(what, sizeof what, "shear %d: (f - A v)_%c of particle %d", sheared, "xyz"[a], k);
                /* A v forms the friction through e e^T blocks: another order of roundings */
                CHECK_ABS(what, od.f[3 * r + a] - Av[3 * r + a], F[3 * k + a], 256.0 * DBL_EPSILON * scale[k]);
            }
        }
        free(v); free(Av);
        od_free(&od);
        neighbor_free(&nl);
        system_free(&s);
    }
    free(F); free(scale);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(registered),
        cmocka_unit_test(morse_walk_virial_energy),
        cmocka_unit_test(morse_overdamped_assembly),
    };
    return cmocka_run_group_tests_name("pair_style", tests, NULL, NULL);
}
