/* test_forces.c - pair forces, boundaries, neighbour lists and the
 * Irving-Kirkwood stress split. Error model used for the tolerances: every
 * floating-point operation rounds with relative error <= eps/2 (eps =
 * DBL_EPSILON = 2.2e-16); sums of K terms of magnitude <= M carry an absolute
 * error <= K eps M (worst case, usually ~sqrt(K) eps M). */
#include "testutil.h"
#ifdef _OPENMP
#include <omp.h>
#endif
#include "system.h"
#include "box.h"
#include "neighbor.h"
#include "forces.h"
#include "pairutil.h"
#include "integrator.h"
#include "overdamped.h"
#include "simd.h"
#include "pair_walk.h"

#define SKIN 0.3

/* One type, one pair entry, unit mass, kBT = 1. */
static void make_system(System *s, int dim, int n, const double L[3], double rate,
                        double a, double gamma, double sexp, double rc, uint64_t seed)
{
    memset(s, 0, sizeof *s);
    assert_int_equal(system_alloc(s, n), 0);
    box_init(&s->box, dim, L, rate);
    s->ntypes = 1;
    snprintf(s->types[0].name, sizeof s->types[0].name, "w");
    s->types[0].mass = 1.0;
    s->types[0].body_force_flip_axis = -1;
    s->kBT = 1.0;
    s->dt = 0.01;
    s->lambda = 0.5;
    s->seed = 1234;
    PairParams p = {.active = 1, .a = a, .gamma = gamma, .s = sexp, .rc = rc};
    system_set_pair(s, 0, 0, p);
    uint64_t st = seed;
    for (int i = 0; i < n; i++) {
        s->id[i] = (uint32_t)i;
        s->type[i] = 0;
        for (int d = 0; d < dim; d++) {
            s->x[3 * i + d] = tu_uniform(&st) * L[d];
            s->v[3 * i + d] = 2.0 * tu_uniform(&st) - 1.0;
        }
        s->v[3 * i] += box_stream_vx(&s->box, s->x[3 * i + 1]);
    }
    memcpy(s->v_pred, s->v, 3 * (size_t)n * sizeof(double));
}

/* ---------------------------------------------------------------- pair law */

/* Reference values computed independently with 40-digit decimal arithmetic
 * (python decimal) from eqs 2-7: fc = a (1 - r/rc), fd = -gamma (1-r/rc)^s e.v,
 * fr = sigma (1-r/rc)^(s/2) theta / sqrt(dt), a = 25, gamma = 4.5, rc = 1,
 * kBT = 1 (sigma = 3), e.v = -0.7, theta = 0.37, dt = 0.01. */
/* neighbour list, force work space and the first forces of a system */
static void first_forces(System *s, NeighborList *nl, ForceWork *fw)
{
    assert_int_equal(neighbor_init(nl, s, SKIN), 0);
    assert_int_equal(neighbor_build(nl, s), 0);
    assert_int_equal(forces_init(fw, s, 0), 0);
    forces_compute(s, nl, fw, NULL);
}

static void pair_magnitudes_hand_values(void **state)
{
    (void)state;
    System s;
    memset(&s, 0, sizeof s);
    s.kBT = 1.0;
    PairParams in = {.active = 1, .a = 25.0, .gamma = 4.5, .rc = 1.0, .sigma = 123.0};
    static const struct { double r, s, fc, fd, fr; } ref[] = {
        {0.3, 2.0, 1.75000000000000000e+01, 1.54350000000000009e+00, 7.76999999999999957e+00},
        {0.5, 0.5, 1.25000000000000000e+01, 2.22738636073762475e+00, 9.33395020931623165e+00},
        {0.8, 0.42, 5.00000000000000000e+00, 1.60229748853054610e+00, 7.91661049728141020e+00},
        {0.999, 1.0, 2.50000000000000014e-02, 3.15000000000000002e-03, 3.51012820278690130e-01},
    };
    for (size_t k = 0; k < sizeof ref / sizeof ref[0]; k++) {
        in.s = ref[k].s;
        system_set_pair(&s, 0, 0, in);
        const PairParams *p = &s.pair[0][0];
        double fc, fd, fr;
        dpd_pair_magnitudes(p, ref[k].r, -0.7, 0.37, 10.0, &fc, &fd, &fr);
        /* 1 - r/rc amplifies the representation error of r (eps/2 relative)
         * by r/(rc - r); pow and a few products add a few eps. */
        const double tol = 16.0 * DBL_EPSILON * (1.0 + ref[k].r / (1.0 - ref[k].r));
        char what[64];
        snprintf(what, sizeof what, "fc(r=%g, s=%g)", ref[k].r, ref[k].s);
        CHECK_REL(what, fc, ref[k].fc, tol);
        snprintf(what, sizeof what, "fd(r=%g, s=%g)", ref[k].r, ref[k].s);
        CHECK_REL(what, fd, ref[k].fd, tol);
        snprintf(what, sizeof what, "fr(r=%g, s=%g)", ref[k].r, ref[k].s);
        CHECK_REL(what, fr, ref[k].fr, tol);
    }
}

/* sigma is derived as sqrt(2 gamma kBT) (eq. 7), never taken from the input. */
static void sigma_is_derived(void **state)
{
    (void)state;
    System s;
    memset(&s, 0, sizeof s);
    const double kT[] = {1.0, 2.5}, g[] = {4.5, 6.97};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
            s.kBT = kT[a];
            PairParams p = {.active = 1, .a = 25.0, .gamma = g[b], .s = 2.0, .rc = 1.0, .sigma = 99.0};
            system_set_pair(&s, 1, 0, p);
            CHECK_REL("sigma[1][0]", s.pair[1][0].sigma, sqrt(2.0 * g[b] * kT[a]), 2 * DBL_EPSILON);
            CHECK_REL("sigma[0][1] (symmetric entry)", s.pair[0][1].sigma, sqrt(2.0 * g[b] * kT[a]), 2 * DBL_EPSILON);
        }
}

/* Two particles at a separation r along a skew direction; returns the force on
 * particle with id 0 after one forces_compute, and whether the pair was listed. */
static size_t two_particle_force(double r, double gamma, double f0[3], double f1[3])
{
    const double L[3] = {5.0, 5.0, 5.0};
    System s;
    make_system(&s, 3, 2, L, 0.0, 25.0, gamma, 2.0, 1.0, 7);
    const double e[3] = {0.48, 0.6, 0.64};   /* unit vector: 0.2304 + 0.36 + 0.4096 = 1 */
    for (int d = 0; d < 3; d++) {
        s.x[d] = 2.5;
        s.x[3 + d] = 2.5 + r * e[d];
        s.v[d] = s.v_pred[d] = 0.3 * (d + 1);
        s.v[3 + d] = s.v_pred[3 + d] = -0.2 * d;
    }
    NeighborList nl;
    ForceWork fw;
    first_forces(&s, &nl, &fw);
    const size_t np = neighbor_pairs(&nl);
    const int i0 = s.id[0] == 0 ? 0 : 1;
    memcpy(f0, s.f + 3 * i0, 3 * sizeof(double));
    memcpy(f1, s.f + 3 * (1 - i0), 3 * sizeof(double));
    forces_free(&fw);
    neighbor_free(&nl);
    system_free(&s);
    return np;
}

/* r = 0: no direction, the force must be exactly zero (and not NaN). Small r:
 * the conservative force tends to a e_ij, finite. */
static void zero_force_at_r0(void **state)
{
    (void)state;
    double f0[3], f1[3];
    assert_int_equal(two_particle_force(0.0, 4.5, f0, f1), 1);
    for (int d = 0; d < 3; d++) {
        CHECK_TRUE(f0[d] == 0.0 && f1[d] == 0.0, "r = 0: force component %d is %g, %g (want exactly 0)", d, f0[d], f1[d]);
    }
    /* gamma = 0 (so sigma = 0): only the conservative force a (1 - r) along
     * -e on particle 0 (it sits at -r e from particle 1). Positions near 2.5
     * carry an absolute error of eps, so r = 1e-6 has relative error
     * ~ 2.2e-16 / 1e-6 = 2.2e-10; the magnitude a (1 - r) is insensitive. */
    const double r = 1e-6;
    assert_int_equal(two_particle_force(r, 0.0, f0, f1), 1);
    const double mag = sqrt(f0[0] * f0[0] + f0[1] * f0[1] + f0[2] * f0[2]);
    CHECK_REL("|f| at r = 1e-6", mag, 25.0 * (1.0 - r), 1e-12);
    CHECK_ABS("f_x on particle 0 at r = 1e-6 (direction -e)", f0[0], -0.48 * 25.0 * (1.0 - r), 1e-8);
}

/* r >= rc: all three parts vanish, even though the pair is within the list
 * cutoff rc + skin (so the list holds it and the cutoff test is exercised). */
static void zero_force_beyond_rc(void **state)
{
    (void)state;
    const double rs[] = {1.0, 1.0 + 1e-12, 1.0001, 1.1, 1.25};
    for (size_t k = 0; k < sizeof rs / sizeof rs[0]; k++) {
        double f0[3], f1[3];
        const size_t np = two_particle_force(rs[k], 4.5, f0, f1);
        CHECK_TRUE(np == 1, "r = %.15g: pair not in the list (%zu pairs); the test would be vacuous", rs[k], np);
        for (int d = 0; d < 3; d++)
            CHECK_TRUE(f0[d] == 0.0 && f1[d] == 0.0, "r = %.15g >= rc: force %d is %g, %g (want exactly 0)",
                       rs[k], d, f0[d], f1[d]);
    }
    /* and just inside rc the force is not zero (the test has power) */
    double f0[3], f1[3];
    two_particle_force(0.999, 4.5, f0, f1);
    CHECK_TRUE(f0[0] != 0.0 || f0[1] != 0.0 || f0[2] != 0.0, "r = 0.999 < rc: force is zero");
}

/* ------------------------------------------------------------ conservation */

static void total_force_check(double rate, double offset)
{
    const double L[3] = {6.0, 6.0, 6.0};
    System s;
    make_system(&s, 3, 648, L, rate, 25.0, 4.5, 2.0, 1.0, 11);
    s.box.le_offset = offset;
    NeighborList nl;
    ForceWork fw;
    first_forces(&s, &nl, &fw);
    double sum[3] = {0, 0, 0}, abs_sum = 0.0;
    for (int i = 0; i < s.n; i++)
        for (int d = 0; d < 3; d++) { sum[d] += s.f[3 * i + d]; abs_sum += fabs(s.f[3 * i + d]); }
    CHECK_TRUE(abs_sum > 1.0, "forces vanish: sum |f| = %g", abs_sum);
    /* each pair adds +F to i and -F to j: the total is a sum of ~6000 exactly
     * cancelling terms, so only rounding remains, <= K eps max|f| << 1e-12 sum|f|. */
    for (int d = 0; d < 3; d++) {
        char what[64];
        snprintf(what, sizeof what, "sum f_%c (shear %g, offset %g)", "xyz"[d], rate, offset);
        CHECK_ABS(what, sum[d], 0.0, 1e-12 * abs_sum);
    }
    forces_free(&fw);
    neighbor_free(&nl);
    system_free(&s);
}

static void newton_third_law(void **state)
{
    (void)state;
    total_force_check(0.0, 0.0);
    total_force_check(0.3, 2.345);   /* pairs through the sliding boundary too */
}

/* A uniform flow is not heat: with a body force (momentum not conserved) the
 * kinetic temperature is that of the velocities relative to their centre of
 * mass over d (N - 1) degrees of freedom, so adding a drift changes it only
 * by rounding (relative 1e-12 allowed for sums of 648 terms of size ~30). */
static void drift_is_not_heat(void **state)
{
    (void)state;
    const double L[3] = {6.0, 6.0, 6.0};
    System s;
    make_system(&s, 3, 648, L, 0.0, 25.0, 4.5, 2.0, 1.0, 77);
    s.has_body_force = 1;
    double vcm[3] = {0, 0, 0}, sum = 0.0;
    for (int i = 0; i < s.n; i++) for (int d = 0; d < 3; d++) vcm[d] += s.v[3 * i + d] / s.n;
    for (int i = 0; i < s.n; i++)
        for (int d = 0; d < 3; d++) sum += (s.v[3 * i + d] - vcm[d]) * (s.v[3 * i + d] - vcm[d]);
    const double T0 = system_kinetic_temperature(&s);
    CHECK_REL("T of the peculiar velocities over 3 (N - 1)", T0, sum / (3.0 * (s.n - 1)), 1e-12);
    const double drift[3] = {5.0, -2.0, 1.0};
    for (int i = 0; i < s.n; i++) for (int d = 0; d < 3; d++) s.v[3 * i + d] += drift[d];
    CHECK_REL("T unchanged by a uniform drift of speed 5.5", system_kinetic_temperature(&s), T0, 1e-12);
    system_free(&s);
}

/* 200 steps of the Groot-Warren integrator, periodic box: total momentum is
 * constant. Per step the momentum changes by dt sum f (rounding only, see
 * above); 200 such steps and the final sum of 648 velocities stay far below
 * 1e-12 sum m |v|. */
static void momentum_conserved(void **state)
{
    (void)state;
    const double L[3] = {6.0, 6.0, 6.0};
    System s;
    make_system(&s, 3, 648, L, 0.0, 25.0, 4.5, 2.0, 1.0, 21);
    NeighborList nl;
    ForceWork fw;
    first_forces(&s, &nl, &fw);
    double p0[3] = {0, 0, 0};
    for (int i = 0; i < s.n; i++) for (int d = 0; d < 3; d++) p0[d] += s.v[3 * i + d];
    long builds0 = nl.builds;
    for (int k = 0; k < 200; k++) {
        neighbor_note_shear(&nl, integrate_predict(&s));
        assert_true(neighbor_update(&nl, &s) >= 0);
        forces_compute(&s, &nl, &fw, NULL);
        integrate_correct(&s);
    }
    double p[3] = {0, 0, 0}, scale = 0.0;
    for (int i = 0; i < s.n; i++)
        for (int d = 0; d < 3; d++) p[d] += s.v[3 * i + d];
    for (int i = 0; i < s.n; i++)
        scale += sqrt(s.v[3 * i] * s.v[3 * i] + s.v[3 * i + 1] * s.v[3 * i + 1] + s.v[3 * i + 2] * s.v[3 * i + 2]);
    CHECK_TRUE(nl.builds > builds0, "no neighbour rebuild in 200 steps: the test misses the reordering");
    for (int d = 0; d < 3; d++) {
        char what[64];
        snprintf(what, sizeof what, "P_%c after 200 steps", "xyz"[d]);
        CHECK_ABS(what, p[d], p0[d], 1e-12 * scale);
    }
    forces_free(&fw);
    neighbor_free(&nl);
    system_free(&s);
}

/* ------------------------------------------------------------ Lees-Edwards */

static void lees_edwards_min_image(void **state)
{
    (void)state;
    Box b;
    const double L[3] = {10.0, 8.0, 6.0};
    const double rate = 0.3, off = 2.7;
    box_init(&b, 3, L, rate);
    b.le_offset = off;
    /* i near y = Ly, j near y = 0: j's image above the box is at
     * (x_j + offset, y_j + Ly) and moves with vx_j + rate Ly. */
    const double xi[3] = {5.0, 7.8, 3.0}, xj[3] = {3.1, 0.1, 2.9};
    const double vxi = 0.4, vxj = -0.2;
    double d[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]}, dvx = vxi - vxj;
    box_min_image(&b, d, &dvx);
    CHECK_ABS("dx, j below i", d[0], xi[0] - (xj[0] + off), 1e-14);   /* 5 - 5.8 = -0.8 */
    CHECK_ABS("dy, j below i", d[1], xi[1] - (xj[1] + L[1]), 1e-14);
    CHECK_ABS("dz, j below i", d[2], 0.1, 1e-14);
    CHECK_ABS("dvx, j below i", dvx, vxi - (vxj + rate * L[1]), 1e-14);
    /* seen from j, i's image below the box is at x_i - offset, vx_i - rate Ly */
    double e[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]}, evx = vxj - vxi;
    box_min_image(&b, e, &evx);
    CHECK_ABS("dx, i seen from j", e[0], -d[0], 1e-14);
    CHECK_ABS("dy, i seen from j", e[1], -d[1], 1e-14);
    CHECK_ABS("dvx, i seen from j", evx, -dvx, 1e-14);
    /* the relative streaming velocity of the image equals rate * dy */
    double s[3] = {xi[0] - xj[0], xi[1] - xj[1], 0.0};
    double svx = box_stream_vx(&b, xi[1]) - box_stream_vx(&b, xj[1]);
    box_min_image(&b, s, &svx);
    CHECK_ABS("streaming dvx across the boundary = rate dy", svx, rate * s[1], 1e-14);
    /* x wrap after the shift: offset pushes dx past -Lx/2 */
    b.le_offset = 8.0;
    double w[3] = {1.0 - 9.5, 7.9 - 0.2, 0.0};
    box_min_image(&b, w, NULL);
    CHECK_ABS("dx wrapped after the shift", w[0], 1.0 - (9.5 + 8.0) + 2 * L[0], 1e-13);
}

static void lees_edwards_wrap(void **state)
{
    (void)state;
    Box b;
    const double L[3] = {10.0, 8.0, 6.0};
    const double rate = 0.3, off = 2.7, jump = rate * L[1];
    box_init(&b, 3, L, rate);
    b.le_offset = off;
    /* leaving through the top: x -= offset, vx -= rate Ly */
    double x[3] = {4.0, 8.05, 3.0}, vx = 1.0, vp = 0.5;
    int img[3] = {0, 0, 0};
    box_wrap(&b, x, img, &vx, &vp);
    CHECK_ABS("x after top exit", x[0], 4.0 - off, 1e-14);
    CHECK_ABS("y after top exit", x[1], 0.05, 1e-14);
    CHECK_ABS("vx after top exit", vx, 1.0 - jump, 1e-14);
    CHECK_ABS("v_pred x after top exit", vp, 0.5 - jump, 1e-14);
    CHECK_TRUE(img[1] == 1 && img[0] == 0, "images after top exit: %d %d", img[0], img[1]);
    /* the shift takes x below 0: wrapped into [0, Lx) with an x image */
    double y[3] = {1.0, 8.1, 3.0};
    int imy[3] = {0, 0, 0};
    box_wrap(&b, y, imy, NULL, NULL);
    CHECK_ABS("x after top exit and x wrap", y[0], 1.0 - off + L[0], 1e-14);
    CHECK_TRUE(imy[0] == -1 && imy[1] == 1, "images: %d %d", imy[0], imy[1]);
    /* leaving through the bottom: the opposite */
    double z[3] = {4.0, -0.1, 3.0}, vz = 1.0;
    int imz[3] = {0, 0, 0};
    box_wrap(&b, z, imz, &vz, NULL);
    CHECK_ABS("x after bottom exit", z[0], 4.0 + off, 1e-14);
    CHECK_ABS("y after bottom exit", z[1], 7.9, 1e-14);
    CHECK_ABS("vx after bottom exit", vz, 1.0 + jump, 1e-14);
    CHECK_TRUE(imz[1] == -1, "y image after bottom exit: %d", imz[1]);
    /* consistency: the separation and relative velocity to a neighbour near
     * the top are the same before and after wrapping */
    const double xj[3] = {3.5, 7.9, 3.1}, vj = 0.7;
    double p[3] = {4.2, 8.02, 3.0}, vpx = 1.3;
    int ip[3] = {0, 0, 0};
    double d0[3] = {p[0] - xj[0], p[1] - xj[1], p[2] - xj[2]}, dv0 = vpx - vj;
    box_min_image(&b, d0, &dv0);
    box_wrap(&b, p, ip, &vpx, NULL);
    double d1[3] = {p[0] - xj[0], p[1] - xj[1], p[2] - xj[2]}, dv1 = vpx - vj;
    box_min_image(&b, d1, &dv1);
    for (int k = 0; k < 3; k++) CHECK_ABS("separation invariant under wrap", d1[k], d0[k], 1e-13);
    CHECK_ABS("relative velocity invariant under wrap", dv1, dv0, 1e-13);
}


/* integrate_predict returns the change of the Lees-Edwards offset in one step,
 * rate Ly dt, also when the offset wraps through 0 or Lx (either sign of the
 * rate). neighbor_note_shear adds |change| to the distance budget of the
 * Verlet list, so a wrong value costs a spurious rebuild (or, if too small,
 * a missed one). Tolerance: the offset is reduced mod Lx (ulp(10) ~ 2e-15). */
static void le_offset_increment(void **state)
{
    (void)state;
    const double L[3] = {10.0, 8.0, 6.0};
    const double rates[] = {0.5, -0.5};
    const double starts[] = {5.0, 0.001, 10.0 - 0.001};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 3; b++) {
            System s;
            make_system(&s, 3, 1, L, rates[a], 25.0, 4.5, 2.0, 1.0, 61);
            s.box.le_offset = starts[b];
            const double doff = integrate_predict(&s);
            char what[96];
            snprintf(what, sizeof what, "offset change, rate %g, offset %g -> %g", rates[a], starts[b], s.box.le_offset);
            system_free(&s);
            CHECK_ABS(what, doff, rates[a] * L[1] * s.dt, 1e-12);
        }
}

/* A free particle (no force) in a sheared box crosses the y boundary again and
 * again while the offset wraps through L_x. Its unwrapped position
 * (box_unwrap: what the MSD, the centre of mass and the colloid centres use)
 * must be its straight line in the infinite sheared system, x0 + v0 t, v0 its
 * velocity in the box it started in: the image it moves into travels with it,
 * so its velocity in the primary box jumps by -+ rate L_y and its lab velocity
 * does not. x + img L alone jumps by the offset at every crossing.
 * Tolerance: 6000 steps of x += v dt (|x| < 300): 6000 x 300 eps ~ 4e-10. */
static void lees_edwards_unwrapped_continuous(void **state)
{
    (void)state;
    const double L[3] = {10.0, 8.0, 6.0};
    const double rates[] = {0.3, -0.45};
    const double v0[2][3] = {{0.7, 1.9, -0.4}, {-1.1, -2.3, 0.2}};
    for (int a = 0; a < 2; a++) {
        System s;
        make_system(&s, 3, 2, L, rates[a], 0.0, 0.0, 0.5, 1.0, 81);
        double x0[2][3];
        for (int i = 0; i < 2; i++)
            for (int d = 0; d < 3; d++) {
                s.x[3 * i + d] = x0[i][d] = (0.3 + 0.4 * i) * L[d];
                s.v[3 * i + d] = s.v_pred[3 * i + d] = v0[i][d];
            }
        int crossings = 0, wraps = 0, yimg[2] = {0, 0};
        double worst = 0.0, last_offset = s.box.le_offset;
        for (int k = 1; k <= 6000; k++) {
            integrate_predict(&s);   /* no force: the half kicks add nothing */
            wraps += fabs(s.box.le_offset - last_offset) > 0.5 * L[0];
            last_offset = s.box.le_offset;
            for (int i = 0; i < 2; i++) {
                crossings += s.img[3 * i + 1] != yimg[i];
                yimg[i] = s.img[3 * i + 1];
                double u[3];
                box_unwrap(&s.box, s.x + 3 * i, s.img + 3 * i, u);
                for (int d = 0; d < 3; d++) worst = fmax(worst, fabs(u[d] - (x0[i][d] + v0[i][d] * k * s.dt)));
            }
        }
        system_free(&s);
        char what[160];
        snprintf(what, sizeof what, "rate %g: %d crossings, %d offset wraps: largest |unwrapped - x0 - v0 t|",
                 rates[a], crossings, wraps);
        CHECK_TRUE(crossings >= 10 && wraps >= 5, "%s: too few to test", what);
        CHECK_ABS(what, worst, 0.0, 1e-9);
    }
}

/* A uniformly sheared state feels no dissipative force. Particles at
 * independent uniform positions (an ideal gas, g(r) = 1) move with the imposed
 * profile v_x = rate (y - L_y / 2) and nothing else; a = 0 and kBT = 0, so
 * every pair force is dissipative, -gamma w_D (e . v_ij) e, with v_ij =
 * rate (r_ij)_y x for every pair, across the sliding boundary too, where j's
 * image one row up moves with + rate L_y (Lees & Edwards 1972). The continuum
 * then says:
 *  - the mean dissipative force on a particle is zero: its neighbours lie
 *    uniformly around it and its F_x is odd in r_ij. This holds for the
 *    particles within rc of y = 0 and of y = L_y, whose pairs cross the
 *    boundary: without the image velocity they see neighbours moving
 *    rate L_y too fast or too slow and are dragged, each slab one way;
 *  - the dissipative virial is the viscous stress of the dissipative
 *    viscosity of an ideal gas (Groot & Warren 1997; Marsh, Backx & Ernst
 *    1997): <W_xy> = (N (N - 1) / 2 V) int d^3r (-gamma w_D rate x^2 y^2 / r^2)
 *    = -gamma rate (N (N - 1) / V) (2 pi / 15) int_0^rc r^4 w_D dr, which is
 *    -gamma rate (N (N - 1) / V) 2 pi / 1575 for w_D = (1 - r)^2, rc = 1 (the
 *    expectation over independent uniform positions is exact: the pair
 *    density of N points in a periodic box is N (N - 1) / V^2 within rc < L/2).
 * The m = 0 assembly (overdamped.c) gets the same check: f - A v at v = the
 * profile is each mobile particle's pair force.
 * R = 32 independent configurations, the offset spread over [0, L_x); each
 * mean over them within 5 of its standard errors (Student t, 31 degrees of
 * freedom: a false alarm of 2e-5 per check). */
static void sheared_state_feels_no_dissipative_force(void **state)
{
    (void)state;
    enum { R = 32 };
    const double L[3] = {6.0, 6.0, 6.0}, rate = 0.5, gamma = 4.5, rc = 1.0;
    const int n = 648;   /* rho = 3 */
    double low[R], high[R], Wxy[R], od_low[R], od_high[R];
    for (int c = 0; c < R; c++) {
        System s;
        make_system(&s, 3, n, L, rate, 0.0, gamma, 2.0, rc, 1000 + (uint64_t)c);
        s.kBT = 0.0;
        system_set_pair(&s, 0, 0, (PairParams){.active = 1, .a = 0.0, .gamma = gamma, .s = 2.0, .rc = rc});
        s.box.le_offset = fmod((c + 0.5) * 0.618034 * L[0], L[0]);
        for (int i = 0; i < n; i++) {
            s.v[3 * i] = s.v_pred[3 * i] = box_stream_vx(&s.box, s.x[3 * i + 1]);
            s.v[3 * i + 1] = s.v_pred[3 * i + 1] = s.v[3 * i + 2] = s.v_pred[3 * i + 2] = 0.0;
        }
        NeighborList nl;
        ForceWork fw;
        assert_int_equal(neighbor_init(&nl, &s, SKIN), 0);
        assert_int_equal(neighbor_build(&nl, &s), 0);
        assert_int_equal(forces_init(&fw, &s, 0), 0);
        PairVirial pv = {.bin_axis = -1};
        forces_compute(&s, &nl, &fw, &pv);
        /* the m = 0 system of the same state: r = f - A v */
        OdSystem od;
        od_init(&od);
        assert_int_equal(od_assemble(&od, &s, &nl), 0);
        assert_int_equal(od.nm, n);
        double *v = malloc(3 * (size_t)n * sizeof(double)), *Av = malloc(3 * (size_t)n * sizeof(double));
        assert_non_null(v); assert_non_null(Av);
        od_gather(&od, &s, v);
        od_matvec(&od, v, Av);
        double sum[4] = {0, 0, 0, 0};
        int cnt[2] = {0, 0};
        for (int i = 0; i < n; i++) {
            const double y = s.x[3 * i + 1];
            const int slab = y < rc ? 0 : y >= L[1] - rc ? 1 : -1;
            if (slab < 0) continue;
            const int r = od.row_of[i];
            sum[slab] += s.f[3 * i];
            sum[2 + slab] += od.f[3 * r] - Av[3 * r];
            cnt[slab]++;
        }
        CHECK_TRUE(cnt[0] > 50 && cnt[1] > 50, "configuration %d: slabs of %d and %d particles", c, cnt[0], cnt[1]);
        low[c] = sum[0] / cnt[0]; high[c] = sum[1] / cnt[1];
        od_low[c] = sum[2] / cnt[0]; od_high[c] = sum[3] / cnt[1];
        Wxy[c] = pv.W[PART_DISSIPATIVE][0][1];
        CHECK_TRUE(pv.W[PART_CONSERVATIVE][0][1] == 0.0 && pv.W[PART_RANDOM][0][1] == 0.0,
                   "a = 0 and kBT = 0, yet a conservative or random virial");
        free(v); free(Av);
        od_free(&od);
        forces_free(&fw);
        neighbor_free(&nl);
        system_free(&s);
    }
    const double V = L[0] * L[1] * L[2];
    const double W_cont = -gamma * rate * ((double)n * (n - 1) / V) * 2.0 * M_PI / 1575.0;
    const struct { const char *what; const double *x; double want; } checks[] = {
        {"mean F_x of the particles within rc of y = 0 (the walk)", low, 0.0},
        {"mean F_x of the particles within rc of y = L_y (the walk)", high, 0.0},
        {"mean F_x within rc of y = 0 (m = 0: f - A v)", od_low, 0.0},
        {"mean F_x within rc of y = L_y (m = 0: f - A v)", od_high, 0.0},
        {"dissipative virial W_xy against -gamma rate N (N - 1) / V 2 pi / 1575", Wxy, W_cont},
    };
    for (size_t k = 0; k < sizeof checks / sizeof checks[0]; k++) {
        double m = 0.0, q = 0.0;
        for (int c = 0; c < R; c++) m += checks[k].x[c] / R;
        for (int c = 0; c < R; c++) q += (checks[k].x[c] - m) * (checks[k].x[c] - m);
        const double se = sqrt(q / (R - 1) / R);
        printf("%s: %.5g +- %.2g (want %.5g)\n", checks[k].what, m, se, checks[k].want);
        CHECK_TRUE(se > 0.0, "%s: no spread over the configurations", checks[k].what);
        CHECK_ABS(checks[k].what, m, checks[k].want, 5.0 * se);
    }
}

/* ---------------------------------------------------------- neighbour list */

/* Every pair within rc (min image) is in the list exactly once, and every
 * listed pair is within the list cutoff. Returns the number of pairs within rc. */
static long check_list_complete(const System *s, const NeighborList *nl, double rc, const char *ctx)
{
    const int n = s->n;
    unsigned char *seen = calloc((size_t)n * n, 1);
    assert_non_null(seen);
    const double cut = nl->cutoff;
    for (int i = 0; i < n; i++)
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++) {
            const int j = nl->nbr[k];
            CHECK_TRUE(j >= 0 && j < n && j != i, "%s: bad neighbour %d of %d", ctx, j, i);
            const int lo = i < j ? i : j, hi = i < j ? j : i;
            CHECK_TRUE(!seen[(size_t)lo * n + hi], "%s: pair (%u, %u) listed twice", ctx, s->id[lo], s->id[hi]);
            seen[(size_t)lo * n + hi] = 1;
            double d[3] = {s->x[3 * i] - s->x[3 * j], s->x[3 * i + 1] - s->x[3 * j + 1], s->x[3 * i + 2] - s->x[3 * j + 2]};
            box_min_image(&s->box, d, NULL);
            const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            /* listed at a build, particles then moved by < skin/2 each */
            CHECK_TRUE(r < cut + nl->skin, "%s: listed pair (%u, %u) at r = %g beyond cutoff %g", ctx,
                       s->id[i], s->id[j], r, cut);
        }
    long within = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            double d[3] = {s->x[3 * i] - s->x[3 * j], s->x[3 * i + 1] - s->x[3 * j + 1], s->x[3 * i + 2] - s->x[3 * j + 2]};
            box_min_image(&s->box, d, NULL);
            const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if (r2 < rc * rc) {
                within++;
                CHECK_TRUE(seen[(size_t)i * n + j], "%s: pair (%u, %u) at r = %.6f < rc missing from the list "
                           "(y %.4f, %.4f; offset %.6f)", ctx, s->id[i], s->id[j], sqrt(r2),
                           s->x[3 * i + 1], s->x[3 * j + 1], s->box.le_offset);
            }
        }
    free(seen);
    return within;
}

static void neighbor_list_shear_vs_brute(void **state)
{
    (void)state;
    const double L[3] = {9.7, 8.3, 6.6};
    System s;
    make_system(&s, 3, 1594, L, 0.4, 25.0, 4.5, 2.0, 1.0, 31);
    NeighborList nl;
    assert_int_equal(neighbor_init(&nl, &s, SKIN), 0);
    CHECK_TRUE(!nl.brute_force, "cells not used (nc %d %d %d): the test would not exercise them", nl.nc[0], nl.nc[1], nl.nc[2]);
    const double cw = nl.cw[0];
    const double offsets[] = {0.0, cw, 2.0 * cw, 0.37, 1.234, 0.5 * L[0], L[0] - 0.01, L[0] - 1e-9, 3.0 * cw + 1e-9};
    for (size_t k = 0; k < sizeof offsets / sizeof offsets[0]; k++) {
        s.box.le_offset = offsets[k];
        assert_int_equal(neighbor_build(&nl, &s), 0);
        char ctx[64];
        snprintf(ctx, sizeof ctx, "3D offset %.10g", offsets[k]);
        long w = check_list_complete(&s, &nl, 1.0, ctx);
        CHECK_TRUE(w > 1000, "%s: only %ld pairs within rc", ctx, w);
    }
    neighbor_free(&nl);
    system_free(&s);
    /* 2D */
    const double L2[3] = {9.7, 8.3, 0.0};
    make_system(&s, 2, 242, L2, -0.4, 25.0, 4.5, 2.0, 1.0, 32);
    assert_int_equal(neighbor_init(&nl, &s, SKIN), 0);
    CHECK_TRUE(!nl.brute_force, "2D: cells not used");
    for (size_t k = 0; k < sizeof offsets / sizeof offsets[0]; k++) {
        s.box.le_offset = offsets[k];
        assert_int_equal(neighbor_build(&nl, &s), 0);
        char ctx[64];
        snprintf(ctx, sizeof ctx, "2D offset %.10g", offsets[k]);
        check_list_complete(&s, &nl, 1.0, ctx);
    }
    neighbor_free(&nl);
    system_free(&s);
}

/* Under shear the list must stay complete between rebuilds, as the offset
 * slides: after every neighbor_update every pair within rc is listed. */
static void neighbor_list_shear_dynamics(void **state)
{
    (void)state;
    const double L[3] = {8.3, 7.1, 5.4};
    System s;
    make_system(&s, 3, 955, L, 0.3, 25.0, 4.5, 2.0, 1.0, 41);
    NeighborList nl;
    ForceWork fw;
    first_forces(&s, &nl, &fw);
    int reused = 0;
    for (int k = 0; k < 80; k++) {
        neighbor_note_shear(&nl, integrate_predict(&s));
        const int rebuilt = neighbor_update(&nl, &s);
        assert_true(rebuilt >= 0);
        reused += rebuilt == 0;
        char ctx[64];
        snprintf(ctx, sizeof ctx, "step %d", k + 1);
        check_list_complete(&s, &nl, 1.0, ctx);
        forces_compute(&s, &nl, &fw, NULL);
        integrate_correct(&s);
    }
    CHECK_TRUE(reused > 10, "the list was rebuilt at nearly every step (%d reuses): the test has no power", reused);
    forces_free(&fw);
    neighbor_free(&nl);
    system_free(&s);
}

/* ------------------------------------------------------ Irving-Kirkwood */

/* One pair term over slabs, by hand: bins of width 2 along y (Ly = 8). */
static void ik_distribute_hand(void **state)
{
    (void)state;
    double t[9];
    for (int k = 0; k < 9; k++) t[k] = k + 1.0;
    double W[4 * 9];
    memset(W, 0, sizeof W);
    ik_distribute(W, 4, 1, 8.0, 2.5, 1.0, t);          /* segment [1.5, 2.5] */
    CHECK_ABS("bin 0 share", W[0 * 9 + 4], 0.5 * t[4], 1e-14);
    CHECK_ABS("bin 1 share", W[1 * 9 + 4], 0.5 * t[4], 1e-14);
    CHECK_ABS("bin 2 share", W[2 * 9 + 4], 0.0, 0.0);
    memset(W, 0, sizeof W);
    ik_distribute(W, 4, 1, 8.0, 0.3, 0.8, t);          /* segment [-0.5, 0.3]: wraps */
    CHECK_ABS("periodic: bin 3 share", W[3 * 9 + 0], 0.5 / 0.8 * t[0], 1e-14);
    CHECK_ABS("periodic: bin 0 share", W[0 * 9 + 0], 0.3 / 0.8 * t[0], 1e-14);
    memset(W, 0, sizeof W);
    ik_distribute(W, 4, 1, 8.0, 7.0, -0.5, t);         /* segment [7.0, 7.5]: j above */
    CHECK_ABS("j above: bin 3", W[3 * 9 + 8], t[8], 1e-14);
}

static void ik_bins_sum_to_virial(void **state)
{
    (void)state;
    const double L[3] = {6.0, 6.5, 7.0};
    System s;
    make_system(&s, 3, 819, L, 0.3, 25.0, 4.5, 0.42, 1.0, 51);
    s.box.le_offset = 1.1;
    NeighborList nl;
    assert_int_equal(neighbor_init(&nl, &s, SKIN), 0);
    assert_int_equal(neighbor_build(&nl, &s), 0);
    for (int axis = 0; axis < 3; axis++) {
        const int nbins = 7 + axis;
        ForceWork fw;
        assert_int_equal(forces_init(&fw, &s, nbins), 0);
        double *wbin = calloc((size_t)nbins * PAIR_PARTS * 9, sizeof(double));
        assert_non_null(wbin);
        PairVirial pv = {.bin_axis = axis, .nbins = nbins, .Wbin = wbin};
        forces_compute(&s, &nl, &fw, &pv);
        for (int q = 0; q < PAIR_PARTS; q++) {
            double norm = 0.0;
            for (int k = 0; k < 9; k++) norm += pv.W[q][k / 3][k % 3] * pv.W[q][k / 3][k % 3];
            norm = sqrt(norm);
            CHECK_TRUE(norm > 1.0, "part %d: virial norm %g, too small to test", q, norm);
            for (int k = 0; k < 9; k++) {
                double sum = 0.0;
                for (int b = 0; b < nbins; b++) sum += wbin[((size_t)q * nbins + b) * 9 + k];
                /* each pair term is split into fractions summing to 1 within a
                 * few eps; ~10^4 terms: error << 1e-10 of the tensor norm */
                char what[96];
                snprintf(what, sizeof what, "axis %c, part %d, component %d%d: sum of bins vs W",
                         "xyz"[axis], q, k / 3, k % 3);
                CHECK_ABS(what, sum, pv.W[q][k / 3][k % 3], 1e-10 * norm);
            }
        }
        /* the global conservative virial against an O(N^2) sum */
        if (axis == 0) {
            double Wc[9] = {0};
            for (int i = 0; i < s.n; i++)
                for (int j = i + 1; j < s.n; j++) {
                    double d[3] = {s.x[3 * i] - s.x[3 * j], s.x[3 * i + 1] - s.x[3 * j + 1], s.x[3 * i + 2] - s.x[3 * j + 2]};
                    box_min_image(&s.box, d, NULL);
                    const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                    if (r >= 1.0 || r < 1e-10) continue;
                    const double g = 25.0 * (1.0 - r) / r;
                    for (int k = 0; k < 9; k++) Wc[k] += d[k / 3] * d[k % 3] * g;
                }
            double norm = 0.0;
            for (int k = 0; k < 9; k++) norm += Wc[k] * Wc[k];
            norm = sqrt(norm);
            for (int k = 0; k < 9; k++)
                CHECK_ABS("conservative virial vs O(N^2) sum", pv.W[PART_CONSERVATIVE][k / 3][k % 3], Wc[k], 1e-10 * norm);
        }
        free(wbin);
        forces_free(&fw);
    }
    neighbor_free(&nl);
    system_free(&s);
}

/* ------------------------------------------------------ instruction sets */

/* The neighbour build's distance test (neighbor.c scan_segment_avx512) gives
 * the same list, and the candidate pass of the walk (pair_avx512.c range_avx512:
 * separations, folds and r^2 eight at a time) and the standard style's
 * one-type evaluator (pair_avx512.c dpd_one_type_avx512) the same forces, bit for bit,
 * as the scalar code at every level the CPU has: a box whose sides differ, so that every
 * fold is exercised; particles on the faces; a coincident pair (no force); a
 * dense cluster, whose lists are longer than a walk batch; a second type
 * pair with a shorter cutoff than the largest and a general exponent
 * (s = 0.42: w_R by batch, weight_pow_batch), with and without the virial
 * (the virial, the energy and the force on a frozen type the same bits too). */
static void same_forces_at_levels(int two_types, double sexp, double rc)
{
    printf("%s, s = %g, rc = %g\n", two_types ? "two types" : "one type", sexp, rc);
    const int best = simd_cap(-1);
    const double L[3] = {6.0, 6.5, 7.0};
    System s;
    make_system(&s, 3, 1500, L, 0.0, 25.0, 4.5, sexp, rc, 91);
    if (two_types) {
        s.ntypes = 2;
        snprintf(s.types[1].name, sizeof s.types[1].name, "u");
        s.types[1].mass = 1.0; s.types[1].body_force_flip_axis = -1;
        const PairParams same = s.pair[0][0];
        system_set_pair(&s, 0, 1, two_types == 3 ? same : (PairParams){.active = 1, .a = 20.0, .gamma = 3.0, .s = 0.42, .rc = 0.9});
        system_set_pair(&s, 1, 1, two_types == 3 ? same : (PairParams){.active = 1, .a = 15.0, .gamma = 6.0, .s = 1.0, .rc = 1.0});
    }
    uint64_t st = 7;
    /* two types: every fourth particle of type 1 (most walk batches mix the
     * types), or (two_types = 2) type 1 frozen on a slab x < 1.5, so that most
     * batches are of one type, some of the frozen one; or (3) that slab with
     * type 0's parameters, so that the batches that mix the types, frozen
     * particles with the others, go to the AVX-512 evaluator too */
    for (int i = 0; i < s.n; i++) s.type[i] = two_types >= 2 ? s.x[3 * i] < 1.5 : two_types && i % 4 == 0;
    if (two_types >= 2) s.types[1].frozen = 1;
    for (int i = 0; i < 300; i++)   /* the cluster: 300 particles in a ball of radius 0.4 at a corner */
        for (int d = 0; d < 3; d++) s.x[3 * i + d] = fmod(L[d] - 0.2 + 0.4 * tu_uniform(&st), L[d]);
    for (int d = 0; d < 3; d++) s.x[3 * 400 + d] = s.x[3 * 401 + d];   /* coincident */
    s.x[3 * 402] = 0.0; s.x[3 * 403] = nextafter(L[0], 0.0);           /* on the faces */
    s.x[3 * 404 + 1] = 0.0; s.x[3 * 405 + 2] = nextafter(L[2], 0.0);
    NeighborList nl;
    ForceWork fw;
    simd_cap(0);
    first_forces(&s, &nl, &fw);   /* the portable list, in the particles' cell order */
    for (int level = 1; level <= 2; level++) {
        if (simd_cap(level) != level) continue;
        NeighborList nl2;
        assert_int_equal(neighbor_init(&nl2, &s, SKIN), 0);
        assert_int_equal(neighbor_build(&nl2, &s), 0);   /* the same order: sorted already */
        const int same = memcmp(nl.start, nl2.start, ((size_t)s.n + 1) * sizeof(int)) == 0
                      && memcmp(nl.nbr, nl2.nbr, (size_t)nl.start[s.n] * sizeof(int)) == 0;
        CHECK_TRUE(same, "the neighbour list at level %d differs from the portable one", level);
        neighbor_free(&nl2);
    }
    int longest = 0;
    for (int i = 0; i < s.n; i++) longest = nl.start[i + 1] - nl.start[i] > longest ? nl.start[i + 1] - nl.start[i] : longest;
    CHECK_TRUE(longest > 256, "no list longer than a walk batch (longest %d)", longest);
    double *f0 = malloc(3 * (size_t)s.n * sizeof(double));
    assert_non_null(f0);
    simd_cap(0);
    forces_compute(&s, &nl, &fw, NULL);
    memcpy(f0, s.f, 3 * (size_t)s.n * sizeof(double));
    PairVirial pv = {.bin_axis = -1};
    forces_compute(&s, &nl, &fw, &pv);   /* with the virial */
    CHECK_TRUE(memcmp(f0, s.f, 3 * (size_t)s.n * sizeof(double)) == 0,
               "forces of a measurement step differ from those of a step without the virial");
    for (int level = 1; level <= 2; level++) {
        if (simd_cap(level) != level) { printf("level %d: not on this CPU\n", level); continue; }
        forces_compute(&s, &nl, &fw, NULL);
        CHECK_TRUE(memcmp(f0, s.f, 3 * (size_t)s.n * sizeof(double)) == 0,
                   "forces at level %d differ from the portable pass's bits", level);
        PairVirial pvl = {.bin_axis = -1};   /* a measurement step: virial, energy, force on the frozen type */
        forces_compute(&s, &nl, &fw, &pvl);
        CHECK_TRUE(memcmp(f0, s.f, 3 * (size_t)s.n * sizeof(double)) == 0 && memcmp(&pv, &pvl, sizeof pv) == 0,
                   "forces or virial of a measurement step at level %d differ from the portable pass's bits", level);
    }
    CHECK_TRUE(two_types < 2 || pv.frozen_force[1][0] != 0.0, "no force on the frozen type");
    simd_cap(best);
    free(f0);
    forces_free(&fw);
    neighbor_free(&nl);
    system_free(&s);
}

/* ... for two types (the scalar evaluator at every level; with the second
 * type on a slab, the AVX-512 evaluator on the batches of one type; with the
 * slab frozen and of the first type's parameters, on the batches that mix
 * them too), and for one type
 * with each case of w_R and rc = 1 and 1.5 (one type: the AVX-512 evaluator,
 * pair_avx512.c, and its two forms of r / rc) */
static void levels_same_forces(void **state)
{
    (void)state;
    same_forces_at_levels(1, 2.0, 1.0);
    same_forces_at_levels(2, 0.42, 1.0);
    same_forces_at_levels(3, 0.5, 1.0);
    const double sexp[] = {2.0, 1.0, 0.5, 0.42};
    for (int k = 0; k < 4; k++) same_forces_at_levels(0, sexp[k], 1.0);   /* r / rc as a product */
    same_forces_at_levels(0, 0.42, 1.5);                                   /* r / rc divided */
}

/* The walk's batch classifier (pair_walk.h batch_one_type) and the classes
 * system_set_pair derives: three types, the pairs (0, 0), (0, 1) and (1, 1)
 * of one set of parameters and type 2's pairs of others. A batch mixing
 * types 0 and 1 goes to the one-type kernels with those parameters; one
 * with a type-2 partner does not; a pair set apart later (a bit of its
 * gamma) splits the class; a batch without pairs takes its first particle's
 * own type pair. */
static void mixed_batches_of_one_parameter_set(void **state)
{
    (void)state;
    System s;
    memset(&s, 0, sizeof s);
    s.kBT = 1.0;
    s.ntypes = 3;
    const PairParams fluid = {.active = 1, .a = 25.0, .gamma = 4.5, .gamma_shear = 4.5, .s = 0.5, .rc = 1.0};
    for (int a = 0; a < 2; a++)
        for (int b = a; b < 2; b++) system_set_pair(&s, a, b, fluid);
    for (int a = 0; a < 3; a++) system_set_pair(&s, a, 2, (PairParams){.active = 1, .a = 25.0, .gamma = 3.5, .gamma_shear = 5.5, .s = 0.5, .rc = 1.0});
    assert_int_equal(system_alloc(&s, 6), 0);
    const uint8_t types[6] = {0, 1, 1, 0, 2, 0};
    memcpy(s.type, types, sizeof types);
    const int count[2] = {2, 1};
    const int near_same[3] = {1, 3, 2}, near_other[3] = {1, 4, 2};
    const PairParams *u = batch_one_type(&s, 0, 2, near_same, count);
    CHECK_TRUE(u != NULL && u->gamma == 4.5 && u->gamma_shear == 4.5,
               "a batch of types 0 and 1 (one parameter set) does not go to the one-type kernel");
    CHECK_TRUE(batch_one_type(&s, 0, 2, near_other, count) == NULL, "a batch with a type-2 partner goes to the one-type kernel");
    const int near_colloid[2] = {4, 4}, count_colloid[1] = {2};   /* particle 0 (type 0), both partners of type 2 */
    u = batch_one_type(&s, 0, 1, near_colloid, count_colloid);
    CHECK_TRUE(u != NULL && u->gamma == 3.5, "a type-0 particle with type-2 partners: not the (0, 2) parameters");
    CHECK_TRUE(s.pair_class[0][1] == s.pair_class[0][0] && s.pair_class[1][1] == s.pair_class[0][0]
               && s.pair_class[0][2] != s.pair_class[0][0] && s.pair_class[2][2] == s.pair_class[0][2],
               "pair classes (0,0) %d (0,1) %d (1,1) %d (0,2) %d (2,2) %d", s.pair_class[0][0], s.pair_class[0][1],
               s.pair_class[1][1], s.pair_class[0][2], s.pair_class[2][2]);
    PairParams apart = fluid;
    apart.gamma = nextafter(apart.gamma, 5.0);
    system_set_pair(&s, 0, 1, apart);
    CHECK_TRUE(batch_one_type(&s, 0, 2, near_same, count) == NULL, "a pair one bit apart still shares the class");
    CHECK_TRUE(s.pair_class[1][0] == s.pair_class[0][1] && s.pair_class[0][1] != s.pair_class[0][0], "the class of (0, 1) not split");
    const int none[2] = {0, 0};
    CHECK_TRUE(batch_one_type(&s, 4, 6, near_same, none) == &s.pair[2][2], "a batch without pairs: not its first type's pair");
    system_free(&s);
}

/* ------------------------------------------------------ w^p (weight_pow.h) */

static uint64_t wp_state = 88172645463325252ULL;
static double wp_uniform(void)
{
    wp_state ^= wp_state << 13; wp_state ^= wp_state >> 7; wp_state ^= wp_state << 17;
    return (double)(wp_state >> 11) * 0x1p-53;
}

/* The stated bound of weight_pow: within 1 ulp of the exact power (powl, 64
 * significant bits, as the reference) for w in (0, 1] (uniform, log-uniform
 * down to 2^-60 and just below 1) and the exponents of the scenes' range,
 * 300000 w per exponent. Measured when it was written: 0.67 ulp at most
 * (libm's pow, by comparison, is within 0.52). */
static void weight_pow_within_one_ulp(void **state)
{
    (void)state;
    const double ps[] = {0.05, 0.125, 0.21, 0.25, 0.5, 0.75, 0.9, 1.0, 1.5, 3.0, 7.9};
    for (size_t ip = 0; ip < sizeof ps / sizeof ps[0]; ip++) {
        double worst = 0.0, at = 0.0;
        for (int t = 0; t < 300000; t++) {
            const double w = t % 3 == 0 ? wp_uniform() : t % 3 == 1 ? exp2(-60.0 * wp_uniform()) : 1.0 - 1e-3 * wp_uniform();
            if (w == 0.0) continue;
            const long double ref = powl((long double)w, (long double)ps[ip]);
            const double rd = (double)ref, ulp = nextafter(rd, INFINITY) - rd;
            const double err = fabs((double)(((long double)weight_pow(w, ps[ip]) - ref) / ulp));
            if (err > worst) { worst = err; at = w; }
        }
        CHECK_TRUE(worst < 1.0, "w^%g: %.3f ulp from powl at w = %.17g", ps[ip], worst, at);
    }
}

/* weight_pow_batch gives weight_pow's bits at every level the CPU has, for
 * batches of every length mod 8, and libm's pow outside the lanes' domain
 * (w = 0, subnormal, negative, NaN, above 1; p = 0, above 8). */
static void weight_pow_same_bits_at_every_level(void **state)
{
    (void)state;
    enum { N = 203 };
    double w[N + 8], p[N + 8], out[N + 8];
    for (int q = 0; q < N + 8; q++) { w[q] = wp_uniform(); p[q] = q % 5 == 0 ? 0.75 : 0.21; }
    const double edge_w[] = {0.0, 1e-310, -0.5, NAN, 1.5, 1.0, 0x1p-1000};
    for (int q = 0; q < 7; q++) w[10 + q] = edge_w[q];
    p[20] = 0.0; p[21] = 9.0; p[22] = NAN;
    const int best = simd_cap(-1);
    for (int level = 0; level <= 2; level++) {
        if (simd_cap(level) != level) continue;
        for (int m = N - 8; m <= N; m++) {
            weight_pow_batch(w, p, out, m);
            for (int q = 0; q < m; q++) {
                const double one = weight_pow(w[q], p[q]);
                CHECK_TRUE(memcmp(&one, &out[q], sizeof one) == 0,
                           "level %d, m %d: w^p of entry %d (w %g, p %g) %.17g against %.17g one at a time",
                           level, m, q, w[q], p[q], out[q], one);
            }
        }
    }
    simd_cap(best);
    for (int q = 10; q < 17; q++) {
        const double a = weight_pow(w[q], p[q]), b = pow(w[q], p[q]);
        CHECK_TRUE(memcmp(&a, &b, sizeof a) == 0 || (isnan(a) && isnan(b)), "outside the domain (w %g): %g, libm %g", w[q], a, b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pair_magnitudes_hand_values),
        cmocka_unit_test(sigma_is_derived),
        cmocka_unit_test(zero_force_at_r0),
        cmocka_unit_test(zero_force_beyond_rc),
        cmocka_unit_test(newton_third_law),
        cmocka_unit_test(momentum_conserved),
        cmocka_unit_test(drift_is_not_heat),
        cmocka_unit_test(lees_edwards_min_image),
        cmocka_unit_test(lees_edwards_wrap),
        cmocka_unit_test(le_offset_increment),
        cmocka_unit_test(lees_edwards_unwrapped_continuous),
        cmocka_unit_test(sheared_state_feels_no_dissipative_force),
        cmocka_unit_test(neighbor_list_shear_vs_brute),
        cmocka_unit_test(neighbor_list_shear_dynamics),
        cmocka_unit_test(ik_distribute_hand),
        cmocka_unit_test(ik_bins_sum_to_virial),
        cmocka_unit_test(levels_same_forces),
        cmocka_unit_test(mixed_batches_of_one_parameter_set),
        cmocka_unit_test(weight_pow_within_one_ulp),
        cmocka_unit_test(weight_pow_same_bits_at_every_level),
    };
    return cmocka_run_group_tests_name("forces", tests, NULL, NULL);
}
