/* integrator.c - Groot-Warren velocity Verlet. The particle loops are compiled
 * once per module state (constants `walls` and `le`, Lees-Edwards): a scene
 * without frozen particles or shear runs no test for them (src/core/modules.h). */
#include <math.h>
#include "integrator.h"
#include "rotation.h"

/* Returns the number of particles whose position is not finite (box_wrap). */
static inline __attribute__((always_inline)) int predict_loop(System *s, const int walls, const int le)
{
    const double dt = s->dt, lam = s->lambda;
    double inv_mass[DPD_MAX_TYPES];   /* per type, not per particle */
    for (int t = 0; t < s->ntypes; t++) inv_mass[t] = 1.0 / s->types[t].mass;
    int bad = 0;
    #pragma omp parallel for schedule(static) reduction(+:bad)
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        double *x = s->x + 3 * i, *v = s->v + 3 * i, *vp = s->v_pred + 3 * i;
        const double *f = s->f + 3 * i;
        if (walls && t->frozen) {
            for (int d = 0; d < 3; d++) { x[d] += dt * t->wall_velocity[d]; v[d] = vp[d] = t->wall_velocity[d]; }
        } else {
            const double im = inv_mass[s->type[i]];
            for (int d = 0; d < 3; d++) {
                x[d] += dt * v[d] + 0.5 * dt * dt * f[d] * im;
                vp[d] = v[d] + lam * dt * f[d] * im;
                v[d] += 0.5 * dt * f[d] * im;
            }
        }
        if (box_inside(&s->box, x)) continue;
        if (le) bad += box_wrap_shear(&s->box, x, s->img + 3 * i, &v[0], &vp[0]);
        else bad += box_wrap_plain(&s->box, x, s->img + 3 * i, &v[0], &vp[0]);
    }
    return bad;
}
static int predict_plain(System *s) { return predict_loop(s, 0, 0); }

/* One type, no walls, no shear: predict_loop's operations component by
 * component over blocks of particles (the same bits, in vector lanes), then
 * the wrap of the block's particles that left the box. */
#define INTEGRATE_BLOCK 64
static inline int block_count(int n) { return (n + INTEGRATE_BLOCK - 1) / INTEGRATE_BLOCK; }
/* the particles [*i0, *i1) of block b */
static inline void block_range(int b, int n, int *i0, int *i1)
{
    *i0 = b * INTEGRATE_BLOCK;
    *i1 = *i0 + INTEGRATE_BLOCK < n ? *i0 + INTEGRATE_BLOCK : n;
}
static int predict_one_type(System *s)
{
    const double dt = s->dt, lam = s->lambda, im = 1.0 / s->types[0].mass;
    const int n = s->n, nblk = block_count(n);
    double *restrict x = s->x, *restrict v = s->v, *restrict vp = s->v_pred;
    const double *restrict f = s->f;
    int bad = 0;
    #pragma omp parallel for schedule(static) reduction(+:bad)
    for (int b = 0; b < nblk; b++) {
        int i0, i1;
        block_range(b, n, &i0, &i1);
        #pragma omp simd
        for (int k = 3 * i0; k < 3 * i1; k++) {
            x[k] += dt * v[k] + 0.5 * dt * dt * f[k] * im;
            vp[k] = v[k] + lam * dt * f[k] * im;
            v[k] += 0.5 * dt * f[k] * im;
        }
        for (int i = i0; i < i1; i++)
            if (!box_inside(&s->box, x + 3 * i)) bad += box_wrap_plain(&s->box, x + 3 * i, s->img + 3 * i, &v[3 * i], &vp[3 * i]);
    }
    return bad;
}
static int predict_walls(System *s) { return predict_loop(s, 1, 0); }
static int predict_shear(System *s) { return predict_loop(s, 0, 1); }
static int predict_walls_shear(System *s) { return predict_loop(s, 1, 1); }

double integrate_advance_offset(System *s)
{
    const double old_offset = s->box.le_offset;
    const int k = box_advance(&s->box, s->dt);
    if (MOD_ON(k != 0)) box_offset_wrapped(s->img, s->n, k);
    return s->box.le_offset - old_offset + k * s->box.L[0];
}

double integrate_predict(System *s)
{
    const double dt = s->dt;
    const double doff = integrate_advance_offset(s);
    const int walls = MOD_ON(s->n_frozen > 0), le = MOD_SHEAR(&s->box);
    /* a non-finite x means a non-finite v or f: the run stops (run.c) */
    if (walls && le) s->nonfinite = predict_walls_shear(s);
    else if (walls) s->nonfinite = predict_walls(s);
    else if (le) s->nonfinite = predict_shear(s);
    else s->nonfinite = s->ntypes == 1 ? predict_one_type(s) : predict_plain(s);
    if (MOD_ROTATION(s)) rotation_predict(s);
    s->step++;
    s->time += dt;
    return doff;
}

/* Returns the number of particles whose velocity is not finite. */
static inline __attribute__((always_inline)) int correct_loop(System *s, const int walls)
{
    const double dt = s->dt;
    double half_dt_inv_mass[DPD_MAX_TYPES];   /* per type, not per particle */
    for (int t = 0; t < s->ntypes; t++) half_dt_inv_mass[t] = 0.5 * dt / s->types[t].mass;
    int bad = 0;
    #pragma omp parallel for schedule(static) reduction(+:bad)
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (walls && t->frozen) continue;
        const double h = half_dt_inv_mass[s->type[i]];
        double *v = s->v + 3 * i;
        for (int d = 0; d < 3; d++) v[d] += h * s->f[3 * i + d];
        bad += !isfinite(v[0] + v[1] + v[2]);   /* a nan or inf in any; or an overflow, a blow-up too */
    }
    return bad;
}
static int correct_walls(System *s) { return correct_loop(s, 1); }
static int correct_plain(System *s) { return correct_loop(s, 0); }
/* One type, no walls: correct_loop component by component (the same bits) */
static int correct_one_type(System *s)
{
    const double h = 0.5 * s->dt / s->types[0].mass;
    const int n = s->n, nblk = block_count(n);
    double *restrict v = s->v;
    const double *restrict f = s->f;
    int bad = 0;
    #pragma omp parallel for schedule(static) reduction(+:bad)
    for (int b = 0; b < nblk; b++) {
        int i0, i1;
        block_range(b, n, &i0, &i1);
        #pragma omp simd
        for (int k = 3 * i0; k < 3 * i1; k++) v[k] += h * f[k];
        for (int i = i0; i < i1; i++) bad += !isfinite(v[3 * i] + v[3 * i + 1] + v[3 * i + 2]);
    }
    return bad;
}

/* hold_mean_velocity: each holding type's velocities shifted by one vector so
 * that their mean is the held one (a uniform force on the type, whatever the
 * frozen particles take from it). Summed in particle order: the same on any
 * thread count. */
static void hold_mean_velocities(System *s)
{
    for (int t = 0; t < s->ntypes; t++) {
        const ParticleType *pt = &s->types[t];
        if (!pt->hold_velocity) continue;
        double sum[3] = {0.0, 0.0, 0.0};
        long count = 0;
        for (int i = 0; i < s->n; i++)
            if (s->type[i] == t) { for (int d = 0; d < 3; d++) sum[d] += s->v[3 * i + d]; count++; }
        if (count == 0) continue;
        double shift[3];
        for (int d = 0; d < 3; d++) shift[d] = d < s->box.dim ? pt->held_velocity[d] - sum[d] / count : 0.0;
        #pragma omp parallel for schedule(static)
        for (int i = 0; i < s->n; i++)
            if (s->type[i] == t) for (int d = 0; d < 3; d++) s->v[3 * i + d] += shift[d];
    }
}

void integrate_correct(System *s)
{
    s->nonfinite += MOD_ON(s->n_frozen > 0) ? correct_walls(s) : s->ntypes == 1 ? correct_one_type(s) : correct_plain(s);
    if (MOD_ROTATION(s)) rotation_correct(s);
    if (MOD_ON(s->has_held_velocity)) hold_mean_velocities(s);
}

void integrate_confine(System *s, int a, double lo, double hi)
{
    if (!MOD_ON(a >= 0)) return;
    #pragma omp parallel for schedule(static)
    for (int i = 0; i < s->n; i++) {
        if (s->types[s->type[i]].frozen) continue;
        double *x = s->x + 3 * i, *v = s->v + 3 * i, *vp = s->v_pred + 3 * i;
        if (x[a] < lo) { x[a] = 2.0 * lo - x[a]; v[a] = -v[a]; vp[a] = -vp[a]; }
        else if (x[a] > hi) { x[a] = 2.0 * hi - x[a]; v[a] = -v[a]; vp[a] = -vp[a]; }
    }
}
