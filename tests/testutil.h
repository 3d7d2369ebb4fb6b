/* testutil.h - small helpers shared by the cmocka tests.
 * Every check prints what it compared, so a failure says by how much. */
#ifndef DPD_TESTUTIL_H
#define DPD_TESTUTIL_H

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include <cmocka.h>

/* |got - want| <= tol, with a message naming the quantity. */
#define CHECK_ABS(what, got, want, tol) do {                                          \
        const double g_ = (got), w_ = (want), t_ = (tol);                             \
        if (!(fabs(g_ - w_) <= t_))                                                   \
            fail_msg("%s: got %.17g, want %.17g, |diff| %.3g > tol %.3g",             \
                     (what), g_, w_, fabs(g_ - w_), t_);                              \
    } while (0)

/* |got - want| <= rel * |want| */
#define CHECK_REL(what, got, want, rel) do {                                          \
        const double w2_ = (want);                                                    \
        CHECK_ABS(what, got, w2_, (rel) * fabs(w2_));                                 \
    } while (0)

#define CHECK_TRUE(cond, ...) do { if (!(cond)) fail_msg(__VA_ARGS__); } while (0)

/* Deterministic uniform numbers for building test configurations (splitmix64). */
static inline uint64_t tu_next(uint64_t *st)
{
    uint64_t z = (*st += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}
static inline double tu_uniform(uint64_t *st)
{
    return (double)(tu_next(st) >> 11) * (1.0 / 9007199254740992.0);
}

#endif
