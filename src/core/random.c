/* random.c - Philox counter blocks as a GSL generator, for GSL's ziggurat. */
#include <gsl/gsl_rng.h>
#include <gsl/gsl_randist.h>
#include "random.h"

static unsigned long counter_get(void *vs)
{
    CounterRng *c = vs;
    if (c->used == 4) {
        c->ctr.v[1] += 1u << 24;   /* next block of the same pair and step */
        c->out = philox4x32(c->ctr, c->key);
        c->used = 0;
    }
    return c->out.v[c->used++];
}

static double counter_get_double(void *vs)
{
    return counter_get(vs) * (1.0 / 4294967296.0);   /* [0, 1) as GSL requires */
}

static void counter_set(void *vs, unsigned long seed)
{
    (void)vs; (void)seed;   /* state is set by rng_counter_start */
}

static const gsl_rng_type counter_type = {
    "philox4x32-10-counter", 0xffffffffUL, 0, sizeof(CounterRng),
    &counter_set, &counter_get, &counter_get_double
};

double rng_counter_normal(CounterRng *c)
{
    gsl_rng r = {&counter_type, c};
    return gsl_ran_gaussian_ziggurat(&r, 1.0);
}
