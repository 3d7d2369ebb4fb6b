/* timers.h - wall-clock time per phase of a step. */
#ifndef DPD_TIMERS_H
#define DPD_TIMERS_H

#include <time.h>

enum { T_NEIGHBOR, T_FORCE, T_INTEGRATE, T_MEASURE, T_OUTPUT, T_COUNT };
static const char *const TIMER_NAMES[T_COUNT] = {"neighbor", "force", "integrate", "measure", "output"};

static inline double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static inline double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

#endif
