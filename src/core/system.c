/* system.c - particle storage. */
#include <stdlib.h>
#include <string.h>
#include "system.h"

int system_alloc(System *s, int n)
{
    s->n = n;
    s->x = calloc(3 * (size_t)n, sizeof *s->x);
    s->v = calloc(3 * (size_t)n, sizeof *s->v);
    s->f = calloc(3 * (size_t)n, sizeof *s->f);
    s->v_pred = calloc(3 * (size_t)n, sizeof *s->v_pred);
    s->img = calloc(3 * (size_t)n, sizeof *s->img);
    s->id = calloc((size_t)n, sizeof *s->id);
    s->type = calloc((size_t)n, sizeof *s->type);
    if (n > 0 && !(s->x && s->v && s->f && s->v_pred && s->img && s->id && s->type)) {
        system_free(s);
        return -1;
    }
    return 0;
}

void system_free(System *s)
{
    free(s->x); free(s->v); free(s->f); free(s->v_pred);
    free(s->img); free(s->id); free(s->type);
    free(s->omega); free(s->omega_pred); free(s->torque);
    s->omega = s->omega_pred = s->torque = NULL;
    s->x = s->v = s->f = s->v_pred = NULL;
    s->img = NULL; s->id = NULL; s->type = NULL;
    s->n = 0;
}

/* a[k] = a[perm[k]] through scratch; called inside a parallel region (both
 * the gather and the copy back are shared out, each ends with a barrier) */
#define PERMUTE_THROUGH(type, a, width, perm, n, tmp) do {                        \
        type *t_ = (type *)(tmp);                                                 \
        _Pragma("omp for schedule(static)")                                       \
        for (int k = 0; k < (n); k++)                                             \
            for (int d = 0; d < (width); d++) t_[(width) * k + d] = (a)[(width) * (perm)[k] + d]; \
        _Pragma("omp for schedule(static)")                                       \
        for (int k = 0; k < (n); k++)                                             \
            for (int d = 0; d < (width); d++) (a)[(width) * k + d] = t_[(width) * k + d]; \
    } while (0)

/* The 3-vectors are gathered into the spare buffer, which then takes the
 * array's place (the array's memory becomes the spare): one pass over
 * memory, not two (at 1e6 particles the permutation is memory bound). Every
 * buffer holds at least 3 n doubles. Called inside a parallel region. */
static void permute_vec3(double **a, const int *perm, int n, double **spare)
{
    double *t = *spare;
    const double *src = *a;
    #pragma omp for schedule(static)
    for (int k = 0; k < n; k++)
        for (int d = 0; d < 3; d++) t[3 * k + d] = src[3 * perm[k] + d];
    #pragma omp single
    { *spare = *a; *a = t; }   /* implicit barrier: every thread sees the swap */
}

void system_permute(System *s, const int *perm, double **spare)
{
    const int n = s->n;
    double **vec3[7] = {&s->x, &s->v, &s->f, &s->v_pred, &s->omega, &s->omega_pred, &s->torque};
    const int nvec = s->omega ? 7 : 4;
    #pragma omp parallel
    {
        for (int q = 0; q < nvec; q++) permute_vec3(vec3[q], perm, n, spare);
        PERMUTE_THROUGH(int32_t, s->img, 3, perm, n, *spare);
        PERMUTE_THROUGH(uint32_t, s->id, 1, perm, n, *spare);
        PERMUTE_THROUGH(uint8_t, s->type, 1, perm, n, *spare);
    }
}

/* Momentum is conserved only without walls, body forces and held mean velocities. */
static int momentum_conserved(const System *s)
{
    return !MOD_ON(s->n_frozen != 0 || s->has_body_force || s->has_held_velocity);
}

int system_dof(const System *s)
{
    const int mobile = s->n - s->n_frozen;
    return mobile > 0 ? s->box.dim * (mobile - 1) : 0;
}

/* Kinetic temperature of the peculiar velocities: relative to the
 * Lees-Edwards streaming profile and to the mobile particles' centre-of-mass
 * velocity, so that a uniform flow (a body force past frozen particles) is
 * not counted as heat. Where momentum is conserved the centre of mass does
 * not move and is not subtracted (its d degrees of freedom are still left
 * out). A non-uniform flow (Poiseuille) is still counted: use the profile's
 * temperature there. */
double system_kinetic_temperature(const System *s)
{
    double vcm[3] = {0.0, 0.0, 0.0};
    if (!momentum_conserved(s)) {
        double mtot = 0.0;
        for (int i = 0; i < s->n; i++) {
            const ParticleType *t = &s->types[s->type[i]];
            if (MOD_FROZEN(t)) continue;
            vcm[0] += t->mass * (s->v[3 * i] - box_stream_vx(&s->box, s->x[3 * i + 1]));
            vcm[1] += t->mass * s->v[3 * i + 1];
            vcm[2] += t->mass * s->v[3 * i + 2];
            mtot += t->mass;
        }
        for (int d = 0; d < 3; d++) vcm[d] = mtot > 0.0 ? vcm[d] / mtot : 0.0;
    }
    double sum = 0.0;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (MOD_FROZEN(t)) continue;
        const double *v = s->v + 3 * i;
        const double vx = v[0] - box_stream_vx(&s->box, s->x[3 * i + 1]) - vcm[0];
        const double vy = v[1] - vcm[1], vz = v[2] - vcm[2];
        sum += t->mass * (vx * vx + vy * vy + vz * vz);
    }
    const int dof = system_dof(s);
    return dof > 0 ? sum / dof : 0.0;
}

/* The same parameters, bit for bit (field by field: a struct's padding is not a value) */
static int pair_params_same(const PairParams *a, const PairParams *b)
{
    return a->active == b->active && memcmp(&a->a, &b->a, sizeof a->a) == 0
        && memcmp(&a->gamma, &b->gamma, sizeof a->gamma) == 0 && memcmp(&a->sigma, &b->sigma, sizeof a->sigma) == 0
        && memcmp(&a->s, &b->s, sizeof a->s) == 0 && memcmp(&a->gamma_shear, &b->gamma_shear, sizeof a->gamma_shear) == 0
        && memcmp(&a->sigma_shear, &b->sigma_shear, sizeof a->sigma_shear) == 0
        && memcmp(&a->rc, &b->rc, sizeof a->rc) == 0 && memcmp(&a->rc2, &b->rc2, sizeof a->rc2) == 0
        && memcmp(a->coef, b->coef, sizeof a->coef) == 0;
}

void system_set_pair(System *s, int ti, int tj, PairParams p)
{
    p.sigma = sqrt(2.0 * p.gamma * s->kBT); /* eq. 7: sigma from gamma, never read */
    p.sigma_shear = sqrt(2.0 * p.gamma_shear * s->kBT); /* Pan 2008 eq. 15: sigma^S from gamma^S */
    p.rc2 = p.rc * p.rc;
    s->pair[ti][tj] = p;
    s->pair[tj][ti] = p;
    if (p.active && p.rc > s->rc_max) s->rc_max = p.rc;
    /* the classes anew (a few hundred comparisons, at set-up) */
    for (int k = 0; k < DPD_MAX_TYPES * DPD_MAX_TYPES; k++) {
        const PairParams *q = &s->pair[k / DPD_MAX_TYPES][k % DPD_MAX_TYPES];
        int c = 0;
        while (!pair_params_same(&s->pair[c / DPD_MAX_TYPES][c % DPD_MAX_TYPES], q)) c++;
        s->pair_class[k / DPD_MAX_TYPES][k % DPD_MAX_TYPES] = (uint8_t)c;
    }
}
