/* rotation.c - the angular velocities of rotating particles (Pan, Pivkin &
 * Karniadakis 2008): initial spins and their Groot-Warren integration. Their
 * pair forces and torques are the pair style of src/pair/pair_pan2008.c. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "rotation.h"
#include "random.h"

int rotation_alloc(System *s)
{
    const size_t n3 = 3 * (size_t)s->n;
    s->omega = calloc(n3 + 1, sizeof(double));
    s->omega_pred = calloc(n3 + 1, sizeof(double));
    s->torque = calloc(n3 + 1, sizeof(double));
    if (!s->omega || !s->omega_pred || !s->torque) return -1;
    s->rotation = 1;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        double *w = s->omega + 3 * i;
        if (t->frozen) { for (int d = 0; d < 3; d++) w[d] = t->spin[d]; continue; }
        philox4x32_ctr_t r = rng_block(s->seed, STREAM_INIT_SPIN, s->id[i], 0, 0);
        double z[4];
        rng_normal2(r.v[0], r.v[1], &z[0], &z[1]);
        rng_normal2(r.v[2], r.v[3], &z[2], &z[3]);
        const double sd = sqrt(s->kBT / t->inertia);   /* equipartition: I <w_a^2> = kBT */
        for (int d = 0; d < 3; d++) w[d] = sd * z[d];
    }
    memcpy(s->omega_pred, s->omega, n3 * sizeof(double));
    return 0;
}

/* One type, not frozen (the Pan 2008 fluids): the loops below component by
 * component, with their expressions, so the same bits; they vectorise. */
static int one_free_type(const System *s) { return s->ntypes == 1 && !s->types[0].frozen; }

/* Called inside integrate_predict after the positions: same scheme as the
 * velocities, Omega_pred = Omega + lambda dt T / I, Omega += dt T / (2 I). */
void rotation_predict(System *s)
{
    const double dt = s->dt, lam = s->lambda;
    if (one_free_type(s)) {
        const double iI = 1.0 / s->types[0].inertia;
        double *restrict w = s->omega, *restrict wp = s->omega_pred;
        const double *restrict T = s->torque;
        #pragma omp parallel for simd schedule(static)
        for (long k = 0; k < 3 * (long)s->n; k++) {
            wp[k] = w[k] + lam * dt * T[k] * iI;
            w[k] += 0.5 * dt * T[k] * iI;
        }
        return;
    }
    #pragma omp parallel for schedule(static)
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        double *w = s->omega + 3 * i, *wp = s->omega_pred + 3 * i;
        const double *T = s->torque + 3 * i;
        if (t->frozen) { for (int d = 0; d < 3; d++) w[d] = wp[d] = t->spin[d]; continue; }
        const double iI = 1.0 / t->inertia;
        for (int d = 0; d < 3; d++) {
            wp[d] = w[d] + lam * dt * T[d] * iI;
            w[d] += 0.5 * dt * T[d] * iI;
        }
    }
}

void rotation_correct(System *s)
{
    const double dt = s->dt;
    if (one_free_type(s)) {
        const double h = 0.5 * dt / s->types[0].inertia;
        double *restrict w = s->omega;
        const double *restrict T = s->torque;
        #pragma omp parallel for simd schedule(static)
        for (long k = 0; k < 3 * (long)s->n; k++) w[k] += h * T[k];
        return;
    }
    #pragma omp parallel for schedule(static)
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (t->frozen) continue;
        const double h = 0.5 * dt / t->inertia;
        for (int d = 0; d < 3; d++) s->omega[3 * i + d] += h * s->torque[3 * i + d];
    }
}

double rotation_temperature(const System *s)
{
    double sum = 0.0;
    long long nm = 0;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (t->frozen) continue;
        const double *w = s->omega + 3 * i;
        sum += t->inertia * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
        nm++;
    }
    return nm > 0 ? sum / (3.0 * nm) : 0.0;
}
