/* test_bonds.c - massless 2D spring colloids (Phan-Thien et al. 2016, eqs
 * 50-51) in the m = 0 system.
 *
 * Error model / derived values:
 *  - spring forces are pairwise opposite: their sum over a colloid vanishes to
 *    round-off, |sum| <= 8 eps H |r - r_bar|.
 *  - an isolated colloid without noise (kBT = 0) relaxes to an equilateral
 *    triangle whose sides balance the DPD repulsion of its own particles and
 *    the springs: a (1 - r*) = H (r* - r_bar), r* = (a + H r_bar) / (a + H).
 *  - linearised about r*, the stiffness of every spring is (H + a) e e^T (the
 *    transverse stiffness is the net force / r = 0) and its friction in A is
 *    gamma w_D(r*) e e^T: both have the same bond structure, so every shape
 *    mode relaxes at lambda = (H + a) / (gamma w_D(r*)) and Euler (eq. 28) is
 *    stable for dt < 2 / lambda (at H = 1000: 0.00758). */
#include "testutil.h"
#include "runutil.h"
#include "system.h"
#include "box.h"
#include "neighbor.h"
#include "forces.h"
#include "overdamped.h"
#include "bonds.h"
#include "measure_field.h"

#define A_REP 18.5
#define GAMMA 4.5
#define H_SPRING 1000.0
#define SIDE 0.25

typedef struct {
    System s;
    NeighborList nl;
    OdSystem od;
    Bonds b;
} Col;

/* One colloid (type 1, particles 0-2) of side `side0` centred at (3, 3) and
 * nsolv solvent particles (type 0) at random, 6 x 6 box, kBT as given. */
static void make_col(Col *c, double side0, double a_intra, int nsolv, double kBT, uint64_t seed)
{
    memset(c, 0, sizeof *c);
    System *s = &c->s;
    const int n = 3 + nsolv;
    assert_int_equal(system_alloc(s, n), 0);
    const double L[3] = {6.0, 6.0, 0.0};
    box_init(&s->box, 2, L, 0.0);
    s->ntypes = 2;
    snprintf(s->types[0].name, sizeof s->types[0].name, "solvent");
    snprintf(s->types[1].name, sizeof s->types[1].name, "colloid");
    for (int t = 0; t < 2; t++) { s->types[t].mass = 0.0; s->types[t].body_force_flip_axis = -1; }
    s->kBT = kBT;
    s->dt = 0.005;
    s->seed = 77;
    PairParams p = {.active = 1, .a = A_REP, .gamma = GAMMA, .s = 0.5, .rc = 1.0};
    system_set_pair(s, 0, 0, p);
    system_set_pair(s, 0, 1, p);
    p.a = a_intra;
    system_set_pair(s, 1, 1, p);
    const double R = side0 / sqrt(3.0);
    uint64_t st = seed;
    for (int i = 0; i < n; i++) {
        s->id[i] = (uint32_t)i;
        s->type[i] = i < 3 ? 1 : 0;
        if (i < 3) {
            const double phi = 0.3 + i * 2.0 * M_PI / 3.0;
            s->x[3 * i] = 3.0 + R * cos(phi);
            s->x[3 * i + 1] = 3.0 + R * sin(phi);
        } else {
            s->x[3 * i] = 6.0 * tu_uniform(&st);
            s->x[3 * i + 1] = 6.0 * tu_uniform(&st);
        }
    }
    c->b.p.type = 1;
    c->b.p.ncol = 1;
    c->b.p.side = SIDE;
    c->b.p.H = H_SPRING;
    c->b.ids = calloc(3, sizeof(uint32_t));
    c->b.index = calloc((size_t)n + 1, sizeof(int));
    assert_non_null(c->b.ids);
    assert_non_null(c->b.index);
    for (int k = 0; k < 3; k++) c->b.ids[k] = (uint32_t)k;
    assert_int_equal(neighbor_init(&c->nl, s, 0.3), 0);
    assert_int_equal(neighbor_build(&c->nl, s), 0);
    od_init(&c->od);
}

/* array index of particle id (the neighbour build sorts the arrays) */
static int at(const Col *c, int id)
{
    for (int i = 0; i < c->s.n; i++) if ((int)c->s.id[i] == id) return i;
    fail_msg("no particle with id %d", id);
    return -1;
}

static void free_col(Col *c)
{
    free(c->b.ids);
    free(c->b.index);
    od_free(&c->od);
    neighbor_free(&c->nl);
    system_free(&c->s);
}

/* One m = 0 step: A v = f with the springs in f (eqs 15-18, 50-51), then eq. 28.
 * The isolated test colloid lies well inside the box: no minimum image needed. */
static void od_step(Col *c)
{
    System *s = &c->s;
    assert_int_equal(neighbor_update(&c->nl, s) < 0, 0);
    assert_int_equal(od_assemble(&c->od, s, &c->nl), 0);
    bonds_rhs(&c->b, s, &c->od);
    if (c->od.fnorm < 1e-9) {
        /* at rest (no noise, forces balanced to round-off): v = 0 solves A v = f;
         * a relative stopping rule on |f| ~ 1e-15 would chase round-off */
        memset(s->v, 0, 3 * (size_t)s->n * sizeof(double));
    } else {
        /* near rest the residual of the 3-particle system (singular for
         * rigid motions) stalls near 1e-7 relative: not checked here; the
         * shape and stability checks below measure the outcome */
        od_solve(&c->od, s, OD_PCG, OD_STOP_RESIDUAL, 1e-12, 200);
    }
    if (s->n == 3) {
        /* an isolated colloid: A is blind to rigid rotations as well as
         * translations; keep the solution without them (minimum norm) */
        double cx = 0, cy = 0, L = 0, I = 0;
        for (int i = 0; i < 3; i++) { cx += s->x[3 * i] / 3; cy += s->x[3 * i + 1] / 3; }
        for (int i = 0; i < 3; i++) {
            const double rx = s->x[3 * i] - cx, ry = s->x[3 * i + 1] - cy;
            L += rx * s->v[3 * i + 1] - ry * s->v[3 * i];
            I += rx * rx + ry * ry;
        }
        for (int i = 0; i < 3; i++) {
            s->v[3 * i] += L / I * (s->x[3 * i + 1] - cy);
            s->v[3 * i + 1] -= L / I * (s->x[3 * i] - cx);
        }
    }
    for (int i = 0; i < s->n; i++) {
        for (int d = 0; d < 2; d++) s->x[3 * i + d] += s->dt * s->v[3 * i + d];
        box_wrap(&s->box, s->x + 3 * i, s->img + 3 * i, NULL, NULL);
    }
    s->step++;
}

static double side_of(const Col *c, int p, int q)
{
    p = at(c, p); q = at(c, q);
    double d[3] = {c->s.x[3 * p] - c->s.x[3 * q], c->s.x[3 * p + 1] - c->s.x[3 * q + 1], 0.0};
    box_min_image(&c->s.box, d, NULL);
    return sqrt(d[0] * d[0] + d[1] * d[1]);
}

/* largest deviation of the three sides from r */
static double shape_error(const Col *c, double r)
{
    return fmax(fabs(side_of(c, 0, 1) - r), fmax(fabs(side_of(c, 1, 2) - r), fabs(side_of(c, 2, 0) - r)));
}

static void spring_forces_sum_to_zero_per_colloid(void **state)
{
    (void)state;
    Col c;
    make_col(&c, SIDE, A_REP, 20, 1.0, 5);
    uint64_t st = 11;
    for (int k = 0; k < 3; k++)            /* deform the triangle */
        for (int d = 0; d < 2; d++) c.s.x[3 * at(&c, k) + d] += 0.1 * (tu_uniform(&st) - 0.5);
    memset(c.s.f, 0, 3 * (size_t)c.s.n * sizeof(double));
    PairVirial pv = {0};
    bonds_forces(&c.b, &c.s, &pv);
    double F[2] = {0, 0}, T = 0.0, fmax_ = 0.0;
    for (int id = 0; id < 3; id++) {
        const int k = at(&c, id);
        F[0] += c.s.f[3 * k]; F[1] += c.s.f[3 * k + 1];
        T += (c.s.x[3 * k] - 3.0) * c.s.f[3 * k + 1] - (c.s.x[3 * k + 1] - 3.0) * c.s.f[3 * k];
        fmax_ = fmax(fmax_, hypot(c.s.f[3 * k], c.s.f[3 * k + 1]));
    }
    CHECK_TRUE(fmax_ > 1.0, "the deformed colloid carries spring forces (largest %g)", fmax_);
    CHECK_ABS("sum of spring forces on the colloid, x", F[0], 0.0, 8 * DBL_EPSILON * fmax_);
    CHECK_ABS("sum of spring forces on the colloid, y", F[1], 0.0, 8 * DBL_EPSILON * fmax_);
    CHECK_ABS("torque of the spring forces about a point", T, 0.0, 64 * DBL_EPSILON * fmax_);
    for (int i = 0; i < c.s.n; i++)
        if (c.s.id[i] >= 3) CHECK_ABS("no spring force on a solvent particle", hypot(c.s.f[3 * i], c.s.f[3 * i + 1]), 0.0, 0.0);
    /* the virial is sum over springs of r_ab F_ab, symmetric (central forces) */
    double W[2][2] = {{0, 0}, {0, 0}};
    const int P[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (int k = 0; k < 3; k++) {
        const int i = at(&c, P[k][0]), j = at(&c, P[k][1]);
        double d[3] = {c.s.x[3 * i] - c.s.x[3 * j], c.s.x[3 * i + 1] - c.s.x[3 * j + 1], 0.0}, f[3];
        bonds_spring(H_SPRING, SIDE, d, f);
        for (int a = 0; a < 2; a++) for (int e = 0; e < 2; e++) W[a][e] += d[a] * f[e];
    }
    for (int a = 0; a < 2; a++)
        for (int e = 0; e < 2; e++) CHECK_REL("spring virial in the conservative part", pv.W[PART_CONSERVATIVE][a][e], W[a][e], 1e-12);
    CHECK_ABS("spring virial symmetric", pv.W[PART_CONSERVATIVE][0][1], pv.W[PART_CONSERVATIVE][1][0], 1e-12 * fabs(W[0][0]));
    free_col(&c);
}

static void colloid_at_rest_keeps_its_shape(void **state)
{
    (void)state;
    /* without repulsion inside the colloid: the reference triangle is a rest state */
    Col c;
    make_col(&c, SIDE, 0.0, 0, 0.0, 1);
    for (int step = 0; step < 500; step++) od_step(&c);
    CHECK_ABS("sides after 500 steps, no intra-colloid repulsion", shape_error(&c, SIDE), 0.0, 1e-12);
    free_col(&c);
    /* with the repulsion of eq. 50's DPD terms: relaxes to r* = (a + H r_bar) / (a + H), stays equilateral */
    make_col(&c, SIDE, A_REP, 0, 0.0, 1);
    const double rstar = (A_REP + H_SPRING * SIDE) / (A_REP + H_SPRING);
    for (int step = 0; step < 500; step++) od_step(&c);
    CHECK_ABS("sides relax to r* = (a + H r_bar) / (a + H)", shape_error(&c, rstar), 0.0, 1e-8);
    free_col(&c);
}

/* Perturbed isolated colloid (kBT = 0) over nsteps: does the shape error shrink? */
static int stable_at(double dt, int nsteps)
{
    Col c;
    const double rstar = (A_REP + H_SPRING * SIDE) / (A_REP + H_SPRING);
    make_col(&c, rstar, A_REP, 0, 0.0, 1);
    c.s.dt = dt;
    c.s.x[3 * at(&c, 0)] += 1e-6;
    const double e0 = shape_error(&c, rstar);
    double e1 = e0;
    for (int k = 0; k < nsteps && e1 < 1e-3; k++) {   /* stop a growing mode before it blows up */
        od_step(&c);
        e1 = shape_error(&c, rstar);
    }
    free_col(&c);
    return isfinite(e1) && e1 < e0;
}

static void largest_stable_dt_at_H1000(void **state)
{
    (void)state;
    const double rstar = (A_REP + H_SPRING * SIDE) / (A_REP + H_SPRING);
    const double dt_pred = 2.0 * GAMMA * sqrt(1.0 - rstar) / (H_SPRING + A_REP);   /* 2 / lambda */
    double lo = 0.5 * dt_pred, hi = 1.5 * dt_pred;
    CHECK_TRUE(stable_at(lo, 300) && !stable_at(hi, 300), "bracket [%g, %g] of the stability limit", lo, hi);
    for (int it = 0; it < 10; it++) {
        const double mid = 0.5 * (lo + hi);
        if (stable_at(mid, 300)) lo = mid; else hi = mid;
    }
    print_message("isolated colloid, H = 1000: largest stable dt measured %.6f (unstable from %.6f), "
                  "predicted 2 gamma w_D(r*) / (H + a) = %.6f\n", lo, hi, dt_pred);
    CHECK_REL("largest stable dt against 2 / lambda", 0.5 * (lo + hi), dt_pred, 0.01);
    CHECK_TRUE(stable_at(0.005, 300), "the paper's dt = 0.005 is stable at H = 1000");
}

static void coincident_particles_give_no_nan(void **state)
{
    (void)state;
    Col c;
    make_col(&c, SIDE, A_REP, 30, 1.0, 9);
    const int p0 = at(&c, 0), p1 = at(&c, 1), p3 = at(&c, 3);
    c.s.x[3 * p1] = c.s.x[3 * p0]; c.s.x[3 * p1 + 1] = c.s.x[3 * p0 + 1];   /* two constituents on top of each other */
    c.s.x[3 * p3] = c.s.x[3 * p0]; c.s.x[3 * p3 + 1] = c.s.x[3 * p0 + 1];   /* and a solvent particle too */
    double d[3] = {0, 0, 0}, F[3];
    bonds_spring(H_SPRING, SIDE, d, F);
    CHECK_TRUE(F[0] == 0.0 && F[1] == 0.0, "r = 0: no direction, no spring force (got %g, %g)", F[0], F[1]);
    memset(c.s.f, 0, 3 * (size_t)c.s.n * sizeof(double));
    bonds_forces(&c.b, &c.s, NULL);
    for (int k = 0; k < 3 * c.s.n; k++) CHECK_TRUE(isfinite(c.s.f[k]), "force component %d not finite", k);
    for (int step = 0; step < 20; step++) od_step(&c);
    for (int k = 0; k < 3 * c.s.n; k++) {
        CHECK_TRUE(isfinite(c.s.v[k]), "velocity component %d not finite after coincident start", k);
        CHECK_TRUE(isfinite(c.s.x[k]), "position component %d not finite after coincident start", k);
    }
    free_col(&c);
}

/* A colloid started on top of a frozen body (the 4-particle cylinder of
 * fig06 centred on the colloid centre, one frozen particle exactly on a
 * constituent) in the n = 4 fluid: the r = 0 pair has no direction and is
 * skipped, every other pair repels, and the m = 0 system (pinned by the frozen
 * particles) stays solvable. Expected: bounded velocities at every step, the
 * body at rest, and after t = 2 the colloid centre farther from the body centre
 * than 0.15, the sum of the colloid's circumradius (0.144) and the half
 * diagonal of the cylinder square (0.071) less a margin of 0.07 (half the
 * fluid's exclusion distance measured by fig06 is 0.18). */
static void colloid_on_a_frozen_body_is_pushed_out(void **state)
{
    (void)state;
    Col c;
    make_col(&c, SIDE, A_REP, 140, 1.0, 21);   /* n = 4, the paper's density: a dilute m = 0 fluid has particles with almost no friction */
    System *s = &c.s;
    /* four of the solvent particles become the frozen cylinder (type 2) */
    s->ntypes = 3;
    snprintf(s->types[2].name, sizeof s->types[2].name, "cylinder");
    s->types[2].frozen = 1;
    s->types[2].body_force_flip_axis = -1;
    PairParams p = {.active = 1, .a = A_REP, .gamma = GAMMA, .s = 0.5, .rc = 1.0};
    system_set_pair(s, 0, 2, p);
    system_set_pair(s, 1, 2, p);
    PairParams off = {.active = 0, .rc = 1.0};
    system_set_pair(s, 2, 2, off);
    const double corner[4][2] = {{2.95, 2.95}, {3.05, 2.95}, {2.95, 3.05}, {3.05, 3.05}};
    const int c0 = at(&c, 0);
    for (int k = 0; k < 4; k++) {
        const int i = at(&c, 3 + k);
        s->type[i] = 2;
        s->x[3 * i] = corner[k][0];
        s->x[3 * i + 1] = corner[k][1];
    }
    const int f0 = at(&c, 3);
    s->x[3 * f0] = s->x[3 * c0];            /* a frozen particle exactly on a constituent: r = 0 */
    s->x[3 * f0 + 1] = s->x[3 * c0 + 1];
    s->n_frozen = 4;
    assert_int_equal(neighbor_build(&c.nl, s), 0);
    int blown = -1;
    for (int step = 0; step < 400 && blown < 0; step++) {
        od_step(&c);
        for (int k = 0; k < 3 * s->n; k++)
            if (!(fabs(s->v[k]) < 1e3)) { blown = step; break; }   /* also catches NaN */
    }
    CHECK_TRUE(blown < 0, "the run stayed bounded (|v| >= 1e3 at step %d)", blown);
    double cx = 0.0, cy = 0.0;
    for (int k = 0; k < 3; k++) { cx += s->x[3 * at(&c, k)] / 3.0; cy += s->x[3 * at(&c, k) + 1] / 3.0; }
    for (int k = 0; k < 3 * s->n; k++) CHECK_TRUE(isfinite(s->x[k]) && isfinite(s->v[k]), "component %d not finite", k);
    const double dist = hypot(cx - 3.0, cy - 3.0);
    print_message("colloid started on the cylinder: centre %.3f from the body centre after t = 2\n", dist);
    CHECK_TRUE(dist > 0.15, "the colloid left the frozen body (centre distance %.3f > 0.15)", dist);
    for (int k = 0; k < 4; k++) {   /* the body did not move */
        const int i = at(&c, 3 + k);
        CHECK_TRUE(s->v[3 * i] == 0.0 && s->v[3 * i + 1] == 0.0, "frozen particle %d has velocity", k);
    }
    free_col(&c);
}

/* A colloid of m = 1 particles alone in a sheared box (nothing else, no
 * thermostat: a = gamma = 0, the springs are the only force) drifts at v = (0.3, 1.0) through the
 * y boundary again and again while the springs keep it together. Its centre
 * is its centre of mass, which the springs do not move: in the infinite
 * sheared system it travels in a straight line, so the centre MSD of
 * colloid_msd.tsv is |v|^2 t^2 = 1.09 t^2 at every lag (to its 8 printed
 * digits). With x + img L the centre jumps by the offset at each crossing. */
static void sheared_colloid_centre_moves_straight(void **state)
{
    (void)state;
    const char *text =
        "dimension = 2;\n"
        "box = [4.0, 4.0];\n"
        "kBT = 1.0;\n"
        "dt = 0.005;\n"
        "seed = 52;\n"
        "equilibration = 0;\n"
        "steps = 4000;\n"
        "shear_rate = 1.0;\n"
        "max_temperature_ratio = 1e6;\n"   /* a free particle falls behind the flow it crosses */
        "types = ( { name = \"colloid\"; count = 3; velocity = [0.3, 1.0]; } );\n"
        "pairs = ( { types = [\"colloid\", \"colloid\"]; a = 0.0; gamma = 0.0; rc = 1.0; } );\n"
        "colloids2d = { type = \"colloid\"; count = 1; side = 0.25; H = 1000.0; every = 10; msd_window = 1000; };\n"
        "measure = { every = 10; };\n";
    char dir[512], out[600], path[700];
    const int rc = run_scene_text("bonds-shear", text, dir, sizeof dir, out, sizeof out);
    snprintf(path, sizeof path, "%s/colloid_msd.tsv", out);
    FILE *f = fopen(path, "r");
    int rows = 0;
    double worst = 0.0;
    if (f) {
        char line[256];
        double t, msd;
        while (fgets(line, sizeof line, f))
            if (sscanf(line, "%lf\t%lf", &t, &msd) == 2) {
                rows++;
                worst = fmax(worst, fabs(msd / (t * t) / 1.09 - 1.0));
            }
        fclose(f);
    }
    rm_rf(dir);
    CHECK_TRUE(rc == 0 && rows == 100, "status %d, %d rows of colloid_msd.tsv", rc, rows);
    CHECK_ABS("sheared free colloid: largest |msd / (|v|^2 t^2) - 1| over the lags", worst, 0.0, 1e-6);
}

/* The two radii of eq. 48, colloid_radius (colloids2d.around, about the
 * colloid centres) and exclusion_radius (measure.around, about a point), are
 * the lower edge of the first bin where g reaches the threshold, with one
 * error rule: the jackknife variance over blocks plus the dq^2 / 12 of a
 * uniform bin (the radius is only known to a bin). An ideal solvent (no
 * interaction with anything) fills the first bin (dq = 0.2: 0.5 particles per
 * sample, 20 samples per block) in every block: both radii are 0 with a zero
 * jackknife variance, so both errors must be dq / sqrt(12) exactly. */
static void around_radii_share_one_error_rule(void **state)
{
    (void)state;
    const char *text =
        "dimension = 2;\n"
        "box = [6.0, 6.0];\n"
        "kBT = 1.0;\n"
        "dt = 0.01;\n"
        "seed = 53;\n"
        "equilibration = 0;\n"
        "steps = 2000;\n"
        "types = ( { name = \"solvent\"; count = 144; }, { name = \"colloid\"; count = 3; } );\n"
        "pairs = ( { types = [\"solvent\", \"solvent\"]; a = 0.0; gamma = 0.0; interact = false; },\n"
        "          { types = [\"solvent\", \"colloid\"]; a = 0.0; gamma = 0.0; interact = false; },\n"
        "          { types = [\"colloid\", \"colloid\"]; a = 0.0; gamma = 0.0; rc = 1.0; } );\n"
        "colloids2d = { type = \"colloid\"; count = 1; side = 0.25; H = 1000.0; every = 10; msd_window = 100;\n"
        "               around = { type = \"solvent\"; dq = 0.2; qmax = 2.0; }; };\n"
        "measure = { every = 10; blocks = 10;\n"
        "            around = { centre = [3.0, 3.0]; type = \"solvent\"; dq = 0.2; qmax = 2.0; }; };\n";
    char dir[512], out[600];
    const int rc = run_scene_text("around-rule", text, dir, sizeof dir, out, sizeof out);
    double ac = NAN, ac_se = NAN, ae = NAN, ae_se = NAN;
    const int got = summary_get(out, "colloid_radius", &ac, &ac_se) | summary_get(out, "exclusion_radius", &ae, &ae_se);
    rm_rf(dir);
    CHECK_TRUE(rc == 0 && got == 0, "status %d, radii in summary.tsv: %s", rc, got ? "no" : "yes");
    CHECK_ABS("exclusion_radius of an ideal solvent", ae, 0.0, 0.0);
    CHECK_ABS("colloid_radius of an ideal solvent", ac, 0.0, 0.0);
    CHECK_REL("exclusion_radius error: dq / sqrt(12)", ae_se, 0.2 / sqrt(12.0), 1e-3);
    CHECK_REL("colloid_radius error: dq / sqrt(12)", ac_se, 0.2 / sqrt(12.0), 1e-3);
}

/* around_write, the rule both radii use, on a hand-made histogram with a
 * nonzero jackknife: 2D, dq = 1, density 1/pi (shells hold 1, 3, 5 particles
 * at g = 1), threshold 0.45, three blocks of one sample each with counts
 * (0, 0, 5), (0, 3, 5), (1, 3, 5). All blocks: g = 1/3, 2/3 -> radius 1.
 * Leaving out each block: g0 = 1/2, 1/2, 0 (then g1 = 1/2) -> radii 0, 0, 1;
 * jackknife variance (2/3) sum (r - 1/3)^2 = 4/9, plus 1/12: se = sqrt(19)/6. */
static void around_write_rule_by_hand(void **state)
{
    (void)state;
    const double hist[9] = {0, 0, 5, 0, 3, 5, 1, 3, 5};
    const long long samples[3] = {1, 1, 1};
    const AroundHist a = {.hist = hist, .samples = samples, .nblocks = 3, .bins = 3, .dim = 2,
                          .dq = 1.0, .density = 1.0 / M_PI, .threshold = 0.45};
    char line[256], name[64];
    FILE *sum = tmpfile(), *t = tmpfile();
    assert_non_null(sum);
    assert_non_null(t);
    const int rc = around_write(&a, t, sum, "radius");
    rewind(sum);
    double r = NAN, se = NAN;
    const int got = fgets(line, sizeof line, sum) && sscanf(line, "%63[^\t]\t%lf\t%lf", name, &r, &se) == 3;
    fclose(sum);
    rewind(t);
    int rows = 0;
    while (fgets(line, sizeof line, t)) rows++;
    fclose(t);
    CHECK_TRUE(rc == 0 && got && !strcmp(name, "radius") && rows == 4, "status %d, row read %d, table rows %d", rc, got, rows);
    CHECK_ABS("radius", r, 1.0, 0.0);
    CHECK_REL("error: jackknife plus dq^2 / 12", se, sqrt(19.0) / 6.0, 1e-3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spring_forces_sum_to_zero_per_colloid),
        cmocka_unit_test(colloid_at_rest_keeps_its_shape),
        cmocka_unit_test(largest_stable_dt_at_H1000),
        cmocka_unit_test(coincident_particles_give_no_nan),
        cmocka_unit_test(colloid_on_a_frozen_body_is_pushed_out),
        cmocka_unit_test(sheared_colloid_centre_moves_straight),
        cmocka_unit_test(around_radii_share_one_error_rule),
        cmocka_unit_test(around_write_rule_by_hand),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
