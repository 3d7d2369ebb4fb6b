/* stability.c - the blow-up check of a run: what ran away, its value and the
 * limit it broke, reported with a smaller dt to try. */
#include <stdio.h>
#include <string.h>
#include <math.h>
#include "run_context.h"
#include "rotation.h"
#include "output.h"

/* What ran away: quantity, value and the limit it broke. */
typedef struct {
    char what[64];
    double value, limit;
} Instability;

/* After a step whose particle loops counted a non-finite position or velocity
 * (s->nonfinite): the first non-finite position (velocities: the checks of
 * check_stable). Returns 1 if there is one. */
static int find_nonfinite_position(const System *s, Instability *u)
{
    for (int i = 0; i < s->n; i++)
        for (int d = 0; d < 3; d++) {
            const double x = s->x[3 * i + d];
            if (isfinite(x)) continue;
            snprintf(u->what, sizeof u->what, "position %c of particle %u", "xyz"[d], s->id[i]);
            u->value = x;
            u->limit = s->box.L[d];   /* positions are wrapped into [0, L) */
            return 1;
        }
    return 0;
}

/* Blow-up detection. Returns 1 if the state is sound; else *u names the
 * quantity that ran away, its value and the limit it broke. Checks: the kinetic
 * (and rotational) temperature against max_temperature_ratio x kBT (inertial
 * runs), and in every run the largest displacement per step of a mobile
 * particle against half the smallest box side (beyond it the minimum image
 * and the pair forces lose their meaning; m = 0 runs have no temperature), and
 * after a step that made a position or velocity non-finite, that value.
 * spins_only: the rotational temperature alone. */
static int check_stable(const System *s, const RunConfig *rc, Instability *u, int spins_only)
{
    const double kT = s->kBT > 0 ? s->kBT : 1.0;
    if (spins_only) {
        snprintf(u->what, sizeof u->what, "rotational temperature");
        u->value = rotation_temperature(s);
        u->limit = rc->max_temperature_ratio * kT;
        return isfinite(u->value) && u->value <= u->limit;
    }
    if (!rc->overdamped) {
        snprintf(u->what, sizeof u->what, "kinetic temperature");
        u->value = system_kinetic_temperature(s);
        u->limit = rc->max_temperature_ratio * kT;
        if (!isfinite(u->value) || u->value > u->limit) return 0;
        if (MOD_ROTATION(s)) {   /* spins can blow up first (too small an inertia for the step) */
            snprintf(u->what, sizeof u->what, "rotational temperature");
            u->value = rotation_temperature(s);
            if (!isfinite(u->value) || u->value > u->limit) return 0;
        }
    }
    double v2max = 0.0, lmin = INFINITY;
    for (int i = 0; i < s->n; i++) {
        if (MOD_FROZEN(&s->types[s->type[i]])) continue;
        const double *v = s->v + 3 * i;
        const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (!(v2 <= v2max)) v2max = v2;   /* NaN propagates */
    }
    for (int d = 0; d < s->box.dim; d++) lmin = fmin(lmin, s->box.L[d]);
    snprintf(u->what, sizeof u->what, "largest displacement per step");
    u->value = sqrt(v2max) * s->dt;
    u->limit = 0.5 * lmin;
    if (!isfinite(u->value) || u->value > u->limit) return 0;
    return !(s->nonfinite && find_nonfinite_position(s, u));
}

int run_stop_if_unstable(const Run *r, int spins_only)
{
    const System *s = &r->s;
    const RunOptions *opt = r->opt;
    Instability u;
    if (check_stable(s, &r->rc, &u, spins_only)) return 0;
    if (r->show) fputc('\n', stderr);
    char why[512];
    snprintf(why, sizeof why, "unstable at step %llu (t = %g): %s %g is %s (limit %g); reduce dt "
             "(now %g), e.g. to %g\n", (unsigned long long)s->step, s->time, u.what, u.value,
             isfinite(u.value) ? "too high" : "not finite", u.limit, s->dt, 0.5 * s->dt);
    fprintf(stderr, "dpd: %s", why);
    fprintf(stderr, "dpd: the output written so far is kept; '%s' is marked incomplete (INCOMPLETE)\n",
            opt->outdir);
    write_file_atomic(opt->outdir, "INCOMPLETE", why, strlen(why));   /* the reason, for the record */
    return 3;
}

