/* test_bodies.c - frozen bodies in the m = 0 fluid (Phan-Thien et al. 2016,
 * section 4.2): the drag equals the body force on the fluid, torques about the
 * body centroid across periodic boundaries, and g(q) about a point. */
#include "runutil.h"
#include "measure_field.h"

/* 2D 6 x 6 cell, 144 m = 0 fluid particles, 4-particle cylinder, body force P. */
static const char *CYLINDER =
    "dimension = 2; box = [6.0, 6.0]; dt = 0.005; seed = 5; equilibration = 20; steps = 100;\n"
    "types = ( { name = \"fluid\"; count = 144; body_force = [0.3, 0.0]; },\n"
    "  { name = \"cyl\"; frozen = true; positions = ( [2.95, 2.95], [3.05, 2.95], [2.95, 3.05], [3.05, 3.05] ); } );\n"
    "pairs = ( { types = [\"fluid\", \"fluid\"]; a = 18.5; gamma = 4.5; s = 0.5; },\n"
    "  { types = [\"fluid\", \"cyl\"]; a = 18.5; gamma = 4.5; s = 0.5; },\n"
    "  { types = [\"cyl\", \"cyl\"]; a = 0.0; gamma = 0.0; interact = false; } );\n"
    "overdamped = { solver = \"pcg\"; stop = \"residual\"; tolerance = 1e-10; };\n"
    "measure = { every = 1; around = { centre = [3.0, 3.0]; type = \"fluid\"; dq = 0.05; qmax = 3.0; }; };\n";

/* At m = 0 every fluid particle carries zero net force, so the pair forces of
 * the fluid on the body sum to the body force on the fluid at every step; the
 * residual 1e-10 bounds the imbalance far below 1e-6 relative. */
static void drag_equals_body_force(void **state)
{
    (void)state;
    char dir[512], out[600];   /* an m = 0 scene: one thread by default */
    assert_int_equal(run_scene_text("bodies", CYLINDER, dir, sizeof dir, out, sizeof out), 0);
    double fx = 0, fxe = 0, fy = 0, fye = 0, u = 0, ue = 0, a = 0, ae = 0;
    assert_int_equal(summary_get(out, "force_on_cyl_x", &fx, &fxe), 0);
    assert_int_equal(summary_get(out, "force_on_cyl_y", &fy, &fye), 0);
    CHECK_REL("drag / (N P)", fx, 144 * 0.3, 1e-6);
    CHECK_ABS("transverse force", fy, 0.0, 1e-6 * 144 * 0.3);
    assert_int_equal(summary_get(out, "mean_velocity_fluid_x", &u, &ue), 0);
    CHECK_TRUE(u > 3.0 * ue, "the body force drives a mean flow: U = %g +- %g", u, ue);
    /* the fluid is kept out of the body: nothing within q = 0.1 of the centre */
    assert_int_equal(summary_get(out, "exclusion_radius", &a, &ae), 0);
    CHECK_TRUE(a >= 0.1 && a < 1.0, "exclusion radius %g outside (0.1, 1)", a);
    rm_rf(dir);
}

/* Torque about the centroid: two frozen particles straddling the periodic
 * boundary in x, centroid at x = 0 by minimum image, opposite forces along y. */
static void torque_about_centroid_across_boundary(void **state)
{
    (void)state;
    System s;
    memset(&s, 0, sizeof s);
    assert_int_equal(system_alloc(&s, 3), 0);
    const double L[3] = {6.0, 6.0, 0.0};
    box_init(&s.box, 2, L, 0.0);
    s.ntypes = 2;
    snprintf(s.types[0].name, sizeof s.types[0].name, "fluid");
    snprintf(s.types[1].name, sizeof s.types[1].name, "body");
    s.types[1].frozen = 1;
    s.n_frozen = 2;
    const double x[9] = {0.1, 1.0, 0.0, 5.9, 1.0, 0.0, 3.0, 3.0, 0.0};
    const double f[9] = {0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0};
    const uint8_t type[3] = {1, 1, 0};
    memcpy(s.x, x, sizeof x);
    memcpy(s.f, f, sizeof f);
    for (int i = 0; i < 3; i++) { s.type[i] = type[i]; s.id[i] = (uint32_t)i; }
    FieldMeasure fm;
    memset(&fm, 0, sizeof fm);
    assert_int_equal(field_init(&fm, &(FieldParams){0}, &s, 2), 0);
    field_sample(&fm, &s, 0);
    CHECK_ABS("centroid x (minimum image)", fmod(fm.centroid[1][0] + 6.0, 6.0), 0.0, 1e-12);
    /* r = (+0.1, 0) x (0, 1) + (-0.1, 0) x (0, -1) = 0.2 */
    CHECK_ABS("torque z", fm.torque[1][2].v[0], 0.2, 1e-12);
    field_free(&fm);
    system_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(drag_equals_body_force),
        cmocka_unit_test(torque_about_centroid_across_boundary),
    };
    return cmocka_run_group_tests_name("bodies", tests, NULL, NULL);
}
