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

/* The cells of the thermal temperature: nc[d] of side >= cut per dimension (at least one);
 * returns their number (at most the neighbour list's, whose cells are the same). */
static size_t thermal_grid(const System *s, double cut, int nc[3])
{
    size_t total = 1;
    for (int d = 0; d < 3; d++) {
        const double q = d < s->box.dim ? floor(s->box.L[d] / cut) : 1.0;
        nc[d] = q >= 1.0 ? (int)q : 1;
        total *= (size_t)nc[d];
    }
    return total;
}

/* The thermal temperature: the kinetic temperature of the mobile particles' velocities
 * relative to the mean velocity of their cell (cells of side >= rc_max + skin; the
 * Lees-Edwards streaming velocity taken off first), each cell's mass-weighted mean taking
 * dim of its degrees of freedom:
 *   T_th = sum_c sum_{i in c} m_i |v_i - V_c|^2 / (dim sum_c (n_c - 1)),
 * whose mean is kBT for any flow uniform over a cell. The kinetic energy of a driven flow
 * (walls, body forces: 13 to 16 kBT in the whole-system temperature of phan-thien-2016 fig04
 * and fig08) is not heat; an integrator that runs hot heats this. *dof: the degrees of
 * freedom it had (0: none, then 0 returned). cells: 5 doubles per cell, ncells of them. */
static double thermal_temperature(const System *s, double cut, double *cells, size_t ncells, long long *dof)
{
    const Box *b = &s->box;
    int nc[3] = {1, 1, 1};
    const size_t total = thermal_grid(s, cut, nc);
    *dof = 0;
    if (total > ncells) return 0.0;   /* (the scratch is sized by the same rule) */
    memset(cells, 0, total * 5 * sizeof *cells);
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (MOD_FROZEN(t)) continue;
        const double *x = s->x + 3 * i, *v = s->v + 3 * i;
        size_t c = 0;
        for (int d = b->dim - 1; d >= 0; d--) {
            const double q = x[d] / b->L[d] * nc[d];
            const int k = !(q >= 0.0) ? 0 : q >= nc[d] ? nc[d] - 1 : (int)q;
            c = c * (size_t)nc[d] + (size_t)k;
        }
        const double u[3] = {v[0] - box_stream_vx(b, x[1]), v[1], v[2]};
        double *cl = cells + 5 * c;
        cl[0] += t->mass;
        for (int d = 0; d < 3; d++) cl[1 + d] += t->mass * u[d];
        cl[4] += t->mass * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    }
    double heat = 0.0;
    for (size_t c = 0; c < total; c++) {
        const double *cl = cells + 5 * c;
        if (cl[0] > 0.0) heat += cl[4] - (cl[1] * cl[1] + cl[2] * cl[2] + cl[3] * cl[3]) / cl[0];
    }
    long long occupied = 0;
    for (size_t c = 0; c < total; c++) occupied += cells[5 * c] > 0.0;
    const long long mobile = s->n - s->n_frozen;
    *dof = (long long)b->dim * (mobile - occupied);
    return *dof > 0 ? heat / (double)*dof : 0.0;
}

size_t run_thermal_cells(const System *s, double cut)
{
    int nc[3];
    return thermal_grid(s, cut, nc);
}

/* Fewer thermal degrees of freedom than this: no thermal check (the temperature of a few
 * particles fluctuates by sqrt(2 / dof) and may reach the limit by chance: at 3 degrees of
 * freedom 5 kBT is exceeded in 0.2 % of the checks; at 100, P(chi2_100 > 500) < 1e-50). */
#define THERMAL_MIN_DOF 100

/* Blow-up detection. Returns 1 if the state is sound; else *u names the
 * quantity that ran away, its value and the limit it broke. Checks: the kinetic
 * (and rotational) temperature against max_temperature_ratio x kBT (inertial
 * runs; default 100) and, unless the scene sets that ratio, the thermal
 * temperature against DEFAULT_MAX_THERMAL_RATIO x kBT (setup.h; with at least
 * THERMAL_MIN_DOF degrees of freedom), and in every run the largest displacement per step of a mobile
 * particle against half the smallest box side (beyond it the minimum image
 * and the pair forces lose their meaning; m = 0 runs have no temperature), and
 * after a step that made a position or velocity non-finite, that value.
 * spins_only: the rotational temperature alone. */
static int check_stable(const Run *r, Instability *u, int spins_only)
{
    const System *s = &r->s;
    const RunConfig *rc = &r->rc;
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
        if (rc->max_thermal_ratio > 0.0 && r->thermal_cells) {
            long long dof;
            const double T = thermal_temperature(s, s->rc_max + rc->skin, r->thermal_cells, r->thermal_ncells, &dof);
            if (dof >= THERMAL_MIN_DOF) {
                snprintf(u->what, sizeof u->what, "thermal temperature");
                u->value = T;
                u->limit = rc->max_thermal_ratio * kT;
                if (!isfinite(u->value) || u->value > u->limit) return 0;
            }
        }
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
    if (check_stable(r, &u, spins_only)) return 0;
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

