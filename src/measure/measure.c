/* measure.c - measurements and their block statistics. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "measure.h"
#include "rotation.h"
#include "colloid.h"

static int block_of(const Measure *m, long long sample)
{
    long long nb = m->nblocks, ns = m->nsamples_expected > 0 ? m->nsamples_expected : 1;
    long long b = sample * nb / ns;
    return (int)(b >= nb ? nb - 1 : b);
}

/* The selected particles (mobile, of the MSD type) by id; group of the k-th of
 * them (by id) k * G / count, G = min(blocks, count): sizes differ by at most
 * one and do not depend on the order particles are stored in. */
static int msd_groups_init(Measure *m, const System *s)
{
    const int n = s->n;
    m->msd_group_of_id = malloc((size_t)(n > 0 ? n : 1) * sizeof(int));
    if (!m->msd_group_of_id) return -1;
    for (int k = 0; k < n; k++) m->msd_group_of_id[k] = -1;
    m->msd_count = 0;
    for (int i = 0; i < n; i++)
        if (!s->types[s->type[i]].frozen && (m->msd_type < 0 || s->type[i] == m->msd_type)) {
            m->msd_group_of_id[s->id[i]] = 0;
            m->msd_count++;
        }
    int G = m->nblocks < m->msd_count ? m->nblocks : m->msd_count;
    if (G < 1) G = 1;
    m->msd_groups = G;
    m->msd_group_n = calloc((size_t)G, sizeof(int));
    m->msd_gsum = calloc((size_t)G, sizeof(double));
    if (!m->msd_group_n || !m->msd_gsum) return -1;
    long long rank = 0;
    for (int id = 0; id < n; id++) {
        if (m->msd_group_of_id[id] < 0) continue;
        const int g = (int)(rank++ * G / (m->msd_count > 0 ? m->msd_count : 1));
        m->msd_group_of_id[id] = g;
        m->msd_group_n[g]++;
    }
    return 0;
}

/* The series sampled every `every` production steps (sample_thermo, sample_com)
 * expect nsamples_expected values: each reserves them at its first sample. */
static void expect_samples(Measure *m)
{
    const size_t n = m->nsamples_expected > 0 ? (size_t)m->nsamples_expected : 0;
    m->temperature.expect = m->pressure.expect = m->epot.expect = m->rot_temperature.expect = n;
    for (int p = 0; p < STRESS_PARTS; p++)
        for (int k = 0; k < 9; k++) m->P[p][k].expect = n;
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++)
            m->frozen_force[t][d].expect = m->frozen_torque[t][d].expect = m->frozen_drag[t][d].expect =
                m->frozen_torque_random[t][d].expect = n;
    for (int d = 0; d < 3; d++) m->com_v[d].expect = m->com_r[d].expect = n;
}

int measure_init(Measure *m, const System *s)
{
    m->n = s->n;
    expect_samples(m);
    if (field_init(&m->field, &m->field_par, s, m->nblocks)) return -1;
    m->n_mobile = 0;
    for (int i = 0; i < s->n; i++) m->n_mobile += !s->types[s->type[i]].frozen;
    if (m->prof_on) {
        m->prof = calloc((size_t)m->nblocks * m->prof_bins * PROF_Q, sizeof(double));
        m->prof_samples = calloc((size_t)m->nblocks, sizeof(long long));
        if (!m->prof || !m->prof_samples) return -1;
        m->prof_tsum = calloc((size_t)m->nblocks, sizeof(double));
        if (!m->prof_tsum) return -1;
    }
    if (m->rdf_on) {
        m->rdf_hist = calloc((size_t)m->nblocks * m->rdf_bins, sizeof(double));
        m->rdf_samples = calloc((size_t)m->nblocks, sizeof(long long));
        if (!m->rdf_hist || !m->rdf_samples) return -1;
        long long na = 0, nb = 0;
        for (int i = 0; i < s->n; i++) {
            if (s->types[s->type[i]].frozen) continue;
            if (m->rdf_types[0] < 0 || s->type[i] == m->rdf_types[0]) na++;
            if (m->rdf_types[1] < 0 || s->type[i] == m->rdf_types[1]) nb++;
        }
        double V = s->box.L[0] * s->box.L[1] * (s->box.dim == 3 ? s->box.L[2] : 1.0);
        /* expected ordered pairs per unit volume of separation */
        m->rdf_norm_pairs = (double)na * (double)nb / V;
    }
    if (m->msd_on) {
        m->msd_nlags = m->msd_window / m->msd_every + 1;
        m->msd_norig = m->msd_window / m->msd_origin_every + 1;
        m->msd_origin_pos = calloc((size_t)m->msd_norig * 3 * s->n, sizeof(double));
        m->msd_origin_step = malloc((size_t)m->msd_norig * sizeof(long long));
        if (msd_groups_init(m, s)) return -1;
        m->msd_curve = calloc((size_t)m->msd_norig * m->msd_groups * m->msd_nlags, sizeof(double));
        if (!m->msd_origin_pos || !m->msd_origin_step || !m->msd_curve) return -1;
        for (int k = 0; k < m->msd_norig; k++) m->msd_origin_step[k] = -1;
    }
    if (m->tcaf_on && tcaf_init(&m->tcaf, &m->tcaf_par, s, m->nblocks, m->prod_steps)) return -1;
    return 0;
}

void measure_free(Measure *m)
{
    series_free(&m->temperature); series_free(&m->pressure); series_free(&m->epot);
    for (int p = 0; p < STRESS_PARTS; p++)
        for (int k = 0; k < 9; k++) series_free(&m->P[p][k]);
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++) {
            series_free(&m->frozen_force[t][d]); series_free(&m->frozen_torque[t][d]);
            series_free(&m->frozen_drag[t][d]); series_free(&m->frozen_torque_random[t][d]);
        }
    series_free(&m->rot_temperature);
    free(m->prof); free(m->prof_samples); free(m->prof_tsum);
    for (int d = 0; d < 3; d++) { series_free(&m->com_v[d]); series_free(&m->com_r[d]); }
    free(m->rdf_hist); free(m->rdf_samples);
    free(m->msd_origin_pos); free(m->msd_origin_step); free(m->msd_curve);
    free(m->msd_group_of_id); free(m->msd_group_n); free(m->msd_gsum);
    series_free(&m->msd_done);
    field_free(&m->field);
    if (m->tcaf.on) tcaf_free(&m->tcaf);
}

/* profile, rdf and msd accumulators */
static void binned_io(Io *io, Measure *m)
{
    const size_t n = (size_t)m->n;
    if (m->prof_on) {
        io_array(io, m->prof, (size_t)m->nblocks * m->prof_bins * PROF_Q, sizeof(double), "profile");
        io_array(io, m->prof_samples, (size_t)m->nblocks, sizeof(long long), "profile samples");
    }
    if (m->rdf_on) {
        io_array(io, m->rdf_hist, (size_t)m->nblocks * m->rdf_bins, sizeof(double), "rdf");
        io_array(io, m->rdf_samples, (size_t)m->nblocks, sizeof(long long), "rdf samples");
    }
    if (m->msd_on) {
        io_array(io, m->msd_origin_pos, (size_t)m->msd_norig * 3 * n, sizeof(double), "msd origins");
        io_array(io, m->msd_origin_step, (size_t)m->msd_norig, sizeof(long long), "msd origin steps");
        io_array(io, m->msd_curve, (size_t)m->msd_norig * m->msd_groups * m->msd_nlags, sizeof(double), "msd curves");
        io_series(io, &m->msd_done, "msd done");
        io_bytes(io, &m->msd_ndone, sizeof m->msd_ndone, "msd done count");
    }
}

void measure_io(Io *io, Measure *m)
{
    io_series(io, &m->temperature, "temperature");
    io_series(io, &m->pressure, "pressure");
    io_series(io, &m->epot, "epot");
    for (int p = 0; p < STRESS_PARTS; p++)
        for (int k = 0; k < 9; k++) io_series(io, &m->P[p][k], "pressure tensor");
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++) io_series(io, &m->frozen_force[t][d], "frozen force");
    binned_io(io, m);
    if (m->prof_on && m->prof_tsum)   /* its place in the format: after the MSD */
        io_array(io, m->prof_tsum, (size_t)m->nblocks, sizeof(double), "profile times");
    if (m->com_on) {
        for (int d = 0; d < 3; d++) {
            io_series(io, &m->com_v[d], "centre-of-mass velocity");
            io_series(io, &m->com_r[d], "centre-of-mass position");
        }
        io_bytes(io, m->com_r0, sizeof m->com_r0, "centre-of-mass start");
    }
    field_io(io, &m->field);
}

void measure_rotation_io(Io *io, Measure *m)
{
    io_series(io, &m->rot_temperature, "rotational temperature");
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++) {
            io_series(io, &m->frozen_torque[t][d], "frozen torque");
            io_series(io, &m->frozen_drag[t][d], "frozen drag");
            io_series(io, &m->frozen_torque_random[t][d], "frozen random torque");
        }
}

int measure_wants_virial(const Measure *m, long long step)
{
    return step >= 0 && step % m->every == 0;
}

static double volume(const Box *b)
{
    return b->L[0] * b->L[1] * (b->dim == 3 ? b->L[2] : 1.0);
}

static void sample_thermo(Measure *m, const System *s, const PairVirial *pv)
{
    double K[9] = {0};
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (MOD_FROZEN(t)) continue;
        const double c[3] = {s->v[3 * i] - box_stream_vx(&s->box, s->x[3 * i + 1]), s->v[3 * i + 1], s->v[3 * i + 2]};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) K[3 * a + b] += t->mass * c[a] * c[b];
    }
    if (MOD_ON(m->colloids)) colloid_kinetic(m->colloids, &s->box, K);   /* the rigid bodies' momentum flux */
    const double V = volume(&s->box);
    for (int k = 0; k < 9; k++) {
        series_push(&m->P[STRESS_KINETIC][k], K[k] / V);
        for (int p = 0; p < PAIR_PARTS; p++) series_push(&m->P[1 + p][k], pv->W[p][k / 3][k % 3] / V);
    }
    const int dim = s->box.dim;
    double tr = 0.0;
    for (int a = 0; a < dim; a++) {
        tr += K[4 * a];
        for (int p = 0; p < PAIR_PARTS; p++) tr += pv->W[p][a][a];
    }
    series_push(&m->pressure, tr / (dim * V));
    series_push(&m->temperature, system_kinetic_temperature(s));
    series_push(&m->epot, pv->epot / s->n);
    for (int t = 0; t < s->ntypes; t++)
        if (MOD_FROZEN(&s->types[t]))
            for (int d = 0; d < 3; d++) series_push(&m->frozen_force[t][d], pv->frozen_force[t][d]);
    if (MOD_ROTATION(s)) {
        series_push(&m->rot_temperature, rotation_temperature(s));
        for (int t = 0; t < s->ntypes; t++)
            if (s->types[t].frozen)
                for (int d = 0; d < 3; d++) {
                    series_push(&m->frozen_torque[t][d], pv->frozen_torque[t][d]);
                    series_push(&m->frozen_drag[t][d], pv->frozen_drag[t][d]);
                    series_push(&m->frozen_torque_random[t][d], pv->frozen_torque_random[t][d]);
                }
    }
}

static void sample_profile(Measure *m, const System *s, const PairVirial *pv, int blk)
{
    const int ax = m->prof_axis, nb = m->prof_bins;
    const double h = s->box.L[ax] / nb;
    double *P = m->prof + (size_t)blk * nb * PROF_Q;
    for (int i = 0; i < s->n; i++) {
        const ParticleType *t = &s->types[s->type[i]];
        if (t->frozen) continue;
        int b = (int)(s->x[3 * i + ax] / h);
        if (b >= nb) b = nb - 1;
        if (b < 0) b = 0;
        double *q = P + (size_t)b * PROF_Q;
        const double *v = s->v + 3 * i;
        q[0] += 1.0;
        q[1] += t->mass;
        for (int a = 0; a < 3; a++) q[PROF_SUMV + a] += v[a];
        for (int a = 0; a < 3; a++) q[2 + a] += t->mass * v[a];
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) q[5 + 3 * a + c] += t->mass * v[a] * v[c];
    }
    for (int p = 0; p < PAIR_PARTS; p++)
        for (int b = 0; b < nb; b++)
            for (int k = 0; k < 9; k++)
                P[(size_t)b * PROF_Q + 14 + 9 * p + k] += pv->Wbin[((size_t)p * nb + b) * 9 + k];
    m->prof_samples[blk]++;
}

static void sample_rdf(Measure *m, const System *s, const NeighborList *nl, int blk)
{
    double *H = m->rdf_hist + (size_t)blk * m->rdf_bins;
    const double dr = m->rdf_rmax / m->rdf_bins, r2max = m->rdf_rmax * m->rdf_rmax;
    const int ta = m->rdf_types[0], tb = m->rdf_types[1];
    for (int i = 0; i < s->n; i++) {
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++) {
            const int j = nl->nbr[k];
            const int ti = s->type[i], tj = s->type[j];
            if (s->types[ti].frozen || s->types[tj].frozen) continue;
            /* count ordered pairs (a in A, b in B) */
            const int w = ((ta < 0 || ti == ta) && (tb < 0 || tj == tb)) + ((ta < 0 || tj == ta) && (tb < 0 || ti == tb));
            if (!w) continue;
            double d[3] = {s->x[3 * i] - s->x[3 * j], s->x[3 * i + 1] - s->x[3 * j + 1], s->x[3 * i + 2] - s->x[3 * j + 2]};
            box_min_image(&s->box, d, NULL);
            const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if (r2 >= r2max) continue;
            int b = (int)(sqrt(r2) / dr);
            if (b < m->rdf_bins) H[b] += w;
        }
    }
    m->rdf_samples[blk]++;
}

static void sample_msd(Measure *m, const System *s, long long step)
{
    const int n = s->n, G = m->msd_groups, L = m->msd_nlags;
    /* start an origin */
    if (step % m->msd_origin_every == 0) {
        const int slot = (int)((step / m->msd_origin_every) % m->msd_norig);
        double *o = m->msd_origin_pos + (size_t)slot * 3 * n;
        for (int i = 0; i < n; i++) box_unwrap(&s->box, s->x + 3 * i, s->img + 3 * i, o + 3 * s->id[i]);
        m->msd_origin_step[slot] = step;
        memset(m->msd_curve + (size_t)slot * G * L, 0, (size_t)G * L * sizeof(double));
    }
    for (int slot = 0; slot < m->msd_norig; slot++) {
        const long long t0 = m->msd_origin_step[slot];
        if (t0 < 0 || step - t0 > m->msd_window || (step - t0) % m->msd_every) continue;
        const int lag = (int)((step - t0) / m->msd_every);
        const double *o = m->msd_origin_pos + (size_t)slot * 3 * n;
        memset(m->msd_gsum, 0, (size_t)G * sizeof(double));
        for (int i = 0; i < n; i++) {
            const int g = m->msd_group_of_id[s->id[i]];
            if (g < 0) continue;
            double u[3];
            box_unwrap(&s->box, s->x + 3 * i, s->img + 3 * i, u);
            for (int d = 0; d < s->box.dim; d++) {
                const double dd = u[d] - o[3 * s->id[i] + d];
                m->msd_gsum[g] += dd * dd;
            }
        }
        double *curve = m->msd_curve + (size_t)slot * G * L;
        for (int g = 0; g < G; g++) curve[(size_t)g * L + lag] = m->msd_gsum[g] / m->msd_group_n[g];
        if (step - t0 == m->msd_window) {
            for (size_t k = 0; k < (size_t)G * L; k++) series_push(&m->msd_done, curve[k]);
            m->msd_ndone++;
            m->msd_origin_step[slot] = -1;
        }
    }
}

/* Centre of mass of the mobile particles (eq. 32, number-weighted so that it
 * also holds at m = 0) from unwrapped positions, and their mean velocity. */
static void sample_com(Measure *m, const System *s, long long sample)
{
    double r[3] = {0, 0, 0}, v[3] = {0, 0, 0};
    long long cnt = 0;
    for (int i = 0; i < s->n; i++) {
        if (s->types[s->type[i]].frozen) continue;
        double u[3];
        box_unwrap(&s->box, s->x + 3 * i, s->img + 3 * i, u);
        for (int d = 0; d < 3; d++) {
            r[d] += u[d];
            v[d] += s->v[3 * i + d];
        }
        cnt++;
    }
    if (!cnt) return;
    for (int d = 0; d < 3; d++) {
        r[d] /= cnt; v[d] /= cnt;
        if (sample == 0) m->com_r0[d] = r[d];
        series_push(&m->com_v[d], v[d]);
        series_push(&m->com_r[d], r[d] - m->com_r0[d]);
    }
}

void measure_sample(Measure *m, const System *s, const NeighborList *nl, const PairVirial *pv,
                    long long prod_step)
{
    if (prod_step < 0) return;
    if (MOD_ON(m->msd_on) && prod_step % m->msd_every == 0) sample_msd(m, s, prod_step);
    if (MOD_ON(m->tcaf.on) && prod_step % m->tcaf.p.every == 0) tcaf_sample(&m->tcaf, s, prod_step);
    if (MOD_ON(m->rdf_on) && prod_step % m->rdf_every == 0)
        sample_rdf(m, s, nl, block_of(m, prod_step / m->every));
    if (prod_step % m->every) return;
    const long long sample = prod_step / m->every;
    sample_thermo(m, s, pv);
    field_sample(&m->field, s, block_of(m, sample));
    if (MOD_ON(m->com_on)) sample_com(m, s, sample);
    if (MOD_ON(m->prof_on)) {
        sample_profile(m, s, pv, block_of(m, sample));
        m->prof_tsum[block_of(m, sample)] += prod_step * s->dt;
    }
}

static void row(FILE *f, const char *name, double v, double se)
{
    fprintf(f, "%s\t%.10g\t%.4g\n", name, v, se);
}

/* Mean and standard error over blocks of per-block values. */
static void over_blocks(const double *v, int nb, double *mean, double *se)
{
    block_stats(v, (size_t)nb, nb, mean, se);
}

static int write_profile(const Measure *m, const System *s, const char *dir)
{
    if (m->nblocks > MAX_BLOCKS) return -1;   /* more than col[] below holds */
    char path[1024];
    snprintf(path, sizeof path, "%s/profile.tsv", dir);
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    const int nb = m->prof_bins, ax = m->prof_axis, B = m->nblocks;
    const double h = s->box.L[ax] / nb, Vbin = volume(&s->box) / nb;
    const int flow = ax == 0 ? 1 : 0;
    fprintf(f, "# bins along %c; stress = -P[%c][%c] (momentum flux of %c across planes normal to %c),\n"
               "# kinetic + conservative + dissipative; the random part (zero mean) is its own column\n",
            "xyz"[ax], "xyz"[ax], "xyz"[flow], "xyz"[flow], "xyz"[ax]);
    fprintf(f, "pos\tdensity\tdensity_se\tvx\tvx_se\tvy\tvy_se\tvz\tvz_se\ttemperature\ttemperature_se"
               "\tstress\tstress_se\tstress_kinetic\tstress_conservative\tstress_dissipative\tstress_random\n");
    double *tmp = malloc((size_t)B * 10 * sizeof(double));
    if (!tmp) { fclose(f); return -1; }
    for (int b = 0; b < nb; b++) {
        int nbk = 0;
        for (int k = 0; k < B; k++) {
            const double *q = m->prof + ((size_t)k * nb + b) * PROF_Q;
            const double S = (double)m->prof_samples[k];
            if (S <= 0 || q[0] <= 0) continue;
            double *o = tmp + 10 * nbk++;
            o[0] = q[0] / (S * Vbin);
            /* mass-weighted velocity; number-weighted for massless (m = 0) particles */
            for (int a = 0; a < 3; a++) o[1 + a] = q[1] > 0 ? q[2 + a] / q[1] : q[PROF_SUMV + a] / q[0];
            /* kinetic P_ab = (sum m v_a v_b - M u_a u_b) / (S V); zero when m = 0 */
            double Kab[9] = {0}, trK = 0.0;
            if (q[1] > 0)
                for (int a = 0; a < 3; a++)
                    for (int c = 0; c < 3; c++) Kab[3 * a + c] = (q[5 + 3 * a + c] - q[2 + a] * q[2 + c] / q[1]) / (S * Vbin);
            for (int a = 0; a < s->box.dim; a++) trK += Kab[4 * a];
            o[4] = trK * S * Vbin / (s->box.dim * q[0]);
            const int comp = 3 * ax + flow;
            o[6] = -Kab[comp];
            for (int p = 0; p < PAIR_PARTS; p++) o[7 + p] = -q[14 + 9 * p + comp] / (S * Vbin);
            o[5] = o[6] + o[7] + o[8];   /* the zero-mean random part is kept apart */
        }
        double mean[10], se[10];
        for (int c = 0; c < 10; c++) {
            double col[MAX_BLOCKS];
            for (int k = 0; k < nbk; k++) col[k] = tmp[10 * k + c];
            over_blocks(col, nbk, &mean[c], &se[c]);
        }
        fprintf(f, "%.6g\t%.8g\t%.3g\t%.8g\t%.3g\t%.8g\t%.3g\t%.8g\t%.3g\t%.8g\t%.3g\t%.8g\t%.3g\t%.6g\t%.6g\t%.6g\t%.6g\n",
                (b + 0.5) * h, mean[0], se[0], mean[1], se[1], mean[2], se[2], mean[3], se[3],
                mean[4], se[4], mean[5], se[5], mean[6], mean[7], mean[8], mean[9]);
    }
    free(tmp);
    return fclose(f);
}

/* Per-block profiles (blocks are contiguous in time): density and mean
 * velocity per bin and block, with the mean production time of the block. */
static int write_profile_blocks(const Measure *m, const System *s, const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/profile_blocks.tsv", dir);
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    const int nb = m->prof_bins, ax = m->prof_axis;
    const double h = s->box.L[ax] / nb, Vbin = volume(&s->box) / nb;
    fprintf(f, "block\tt\tpos\tdensity\tvx\tvy\n");
    for (int k = 0; k < m->nblocks; k++) {
        const double S = (double)m->prof_samples[k];
        if (S <= 0) continue;
        for (int b = 0; b < nb; b++) {
            const double *q = m->prof + ((size_t)k * nb + b) * PROF_Q;
            double u[2] = {NAN, NAN};
            for (int a = 0; a < 2 && q[0] > 0; a++) u[a] = q[1] > 0 ? q[2 + a] / q[1] : q[PROF_SUMV + a] / q[0];
            fprintf(f, "%d\t%.6g\t%.6g\t%.6g\t%.6g\t%.6g\n", k, m->prof_tsum[k] / S, (b + 0.5) * h,
                    q[0] / (S * Vbin), u[0], u[1]);
        }
    }
    return fclose(f);
}

/* Centre-of-mass record: com.tsv and the extremes of the run (no error bar:
 * one run's extremes; experiments take the scatter over independent runs). */
static int write_com(const Measure *m, const System *s, FILE *summary, const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/com.tsv", dir);
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    const size_t ns = m->com_v[0].n;
    const int dim = s->box.dim;
    fprintf(f, "t\tvx\tvy\tx\ty\n");
    double vmin[3] = {0}, vmax[3] = {0}, rmin[3] = {0}, rmax[3] = {0}, speed = 0.0, disp = 0.0, vsum = 0.0;
    for (size_t k = 0; k < ns; k++) {
        double v2 = 0.0, r2 = 0.0;
        for (int d = 0; d < dim; d++) {
            const double v = m->com_v[d].v[k], r = m->com_r[d].v[k];
            vmin[d] = k ? fmin(vmin[d], v) : v; vmax[d] = k ? fmax(vmax[d], v) : v;
            rmin[d] = k ? fmin(rmin[d], r) : r; rmax[d] = k ? fmax(rmax[d], r) : r;
            v2 += v * v; r2 += r * r;
            vsum = fmax(vsum, fabs(v) * m->n_mobile);
        }
        speed = fmax(speed, sqrt(v2));
        disp = fmax(disp, sqrt(r2));
        fprintf(f, "%.6g\t%.6g\t%.6g\t%.6g\t%.6g\n", (double)k * m->every * s->dt,
                m->com_v[0].v[k], m->com_v[1].v[k], m->com_r[0].v[k], m->com_r[1].v[k]);
    }
    for (int d = 0; d < dim; d++) {
        char name[64];
        snprintf(name, sizeof name, "com_v%c_min", "xyz"[d]); row(summary, name, vmin[d], 0);
        snprintf(name, sizeof name, "com_v%c_max", "xyz"[d]); row(summary, name, vmax[d], 0);
        snprintf(name, sizeof name, "com_%c_min", "xyz"[d]); row(summary, name, rmin[d], 0);
        snprintf(name, sizeof name, "com_%c_max", "xyz"[d]); row(summary, name, rmax[d], 0);
    }
    row(summary, "com_speed_max", speed, 0);
    row(summary, "com_displacement_max", disp, 0);
    row(summary, "velocity_sum_max", vsum, 0);   /* largest |sum_i v_i,a| over samples and axes */
    return fclose(f);
}

static int write_rdf(const Measure *m, const System *s, const char *dir)
{
    if (m->nblocks > MAX_BLOCKS) return -1;   /* more than g[] below holds */
    char path[1024];
    snprintf(path, sizeof path, "%s/rdf.tsv", dir);
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "r\tg\tg_se\n");
    const double dr = m->rdf_rmax / m->rdf_bins;
    const int B = m->nblocks;
    for (int b = 0; b < m->rdf_bins; b++) {
        const double r0 = b * dr, r1 = r0 + dr;
        const double shell = s->box.dim == 3 ? 4.0 / 3.0 * M_PI * (r1 * r1 * r1 - r0 * r0 * r0)
                                             : M_PI * (r1 * r1 - r0 * r0);
        double g[MAX_BLOCKS];
        int nbk = 0;
        for (int k = 0; k < B; k++) {
            if (m->rdf_samples[k] == 0) continue;
            g[nbk++] = m->rdf_hist[(size_t)k * m->rdf_bins + b] / (m->rdf_samples[k] * m->rdf_norm_pairs * shell);
        }
        double mean, se;
        over_blocks(g, nbk, &mean, &se);
        fprintf(f, "%.6g\t%.6g\t%.3g\n", r0 + 0.5 * dr, mean, se);
    }
    return fclose(f);
}

/* msd of group g after lag l, averaged over the completed origins */
static double msd_group_mean(const Measure *m, int g, int l)
{
    const size_t G = (size_t)m->msd_groups, L = (size_t)m->msd_nlags;
    double sum = 0.0;
    for (long long o = 0; o < m->msd_ndone; o++) sum += m->msd_done.v[((size_t)o * G + (size_t)g) * L + (size_t)l];
    return sum / (double)m->msd_ndone;
}

/* Mean over all selected particles of a per-group value y_g and its standard
 * error from the scatter of the groups (ratio estimator for groups of sizes
 * n_g: var = sum_g (n_g / nbar)^2 (y_g - mean)^2 / (G (G - 1))). */
static void over_groups(const Measure *m, const double *y, double *mean, double *se)
{
    const int G = m->msd_groups;
    double sum = 0.0;
    for (int g = 0; g < G; g++) sum += m->msd_group_n[g] * y[g];
    *mean = sum / m->msd_count;
    *se = NAN;
    if (G < 2) return;
    const double nbar = (double)m->msd_count / G;
    double v = 0.0;
    for (int g = 0; g < G; g++) {
        const double w = m->msd_group_n[g] / nbar, d = y[g] - *mean;
        v += w * w * d * d;
    }
    *se = sqrt(v / ((double)G * (G - 1)));
}

static int write_msd(const Measure *m, const System *s, FILE *summary, const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/msd.tsv", dir);
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    const int L = m->msd_nlags, dim = s->box.dim, G = m->msd_groups;
    const long long no = m->msd_ndone;
    fprintf(f, "# %lld time origins; errors from %d groups of particles (%d particles)\n", no, G, m->msd_count);
    fprintf(f, "t\tmsd\tmsd_se\tD\tD_se\n");
    /* per group: msd at every lag in turn, then at T/2 (half) and T (late); nan without origins */
    double *y = malloc((size_t)G * sizeof(double)), *half = malloc((size_t)G * sizeof(double)),
           *late = malloc((size_t)G * sizeof(double));
    if (!y || !half || !late) { free(y); free(half); free(late); fclose(f); return -1; }
    double mean = NAN, se = NAN;
    for (int l = 1; l < L && no > 0; l++) {
        const double t = (double)l * m->msd_every * s->dt;
        for (int g = 0; g < G; g++) y[g] = msd_group_mean(m, g, l);
        over_groups(m, y, &mean, &se);
        fprintf(f, "%.6g\t%.8g\t%.3g\t%.8g\t%.3g\n", t, mean, se, mean / (2 * dim * t), se / (2 * dim * t));
    }
    const int l1 = L - 1, l0 = (L - 1) / 2;
    const double T1 = l1 * m->msd_every * s->dt, T0 = l0 * m->msd_every * s->dt;
    for (int g = 0; g < G; g++) { half[g] = msd_group_mean(m, g, l0); late[g] = msd_group_mean(m, g, l1); }
    /* D from the slope over the second half of the window */
    for (int g = 0; g < G; g++) y[g] = (late[g] - half[g]) / (2 * dim * (T1 - T0));
    over_groups(m, y, &mean, &se);
    row(summary, "D", mean, se);
    /* flatness of D(t) = msd / (2 d t): late over half-window */
    for (int g = 0; g < G; g++) y[g] = (late[g] / T1) / (half[g] / T0);
    over_groups(m, y, &mean, &se);
    row(summary, "D_t_ratio_late_half", mean, se);
    free(y); free(half); free(late);
    return fclose(f);
}

/* Shear stress T_xy = -P_yx (x momentum carried across planes normal to y),
 * with the viscosity and its parts under shear. */
static int write_shear_stress(const Measure *m, const System *s, FILE *summary)
{
    static const char *part[STRESS_PARTS] = {"kinetic", "conservative", "dissipative", "random"};
    const int B = m->nblocks;
    const size_t ns = m->P[0][3].n;
    if (ns == 0) return 0;
    /* The random part of the stress has zero mean exactly (F_R at a step is
     * independent of the positions it is paired with) but a variance of order
     * 1/dt; the estimators without it have the same mean and far smaller
     * errors. Both are reported. */
    double v, se;
    double *tot = malloc(ns * sizeof(double)), *all = malloc(ns * sizeof(double));
    if (!tot || !all) { free(tot); free(all); return -1; }
    for (size_t k = 0; k < ns; k++) {
        tot[k] = -(m->P[STRESS_KINETIC][3].v[k] + m->P[STRESS_CONSERVATIVE][3].v[k]
                   + m->P[STRESS_DISSIPATIVE][3].v[k]);
        all[k] = tot[k] - m->P[STRESS_RANDOM][3].v[k];
    }
    block_stats(tot, ns, B, &v, &se);
    row(summary, "stress_xy", v, se);
    block_stats(all, ns, B, &v, &se);
    row(summary, "stress_xy_with_random", v, se);
    const double rate = s->box.shear_rate;
    if (rate != 0.0) {
        for (size_t k = 0; k < ns; k++) { tot[k] /= rate; all[k] /= rate; }
        block_stats(tot, ns, B, &v, &se);
        row(summary, "viscosity", v, se);
        block_stats(all, ns, B, &v, &se);
        row(summary, "viscosity_with_random", v, se);
        for (int p = 0; p < STRESS_PARTS; p++) {
            char name[64];
            for (size_t k = 0; k < ns; k++) tot[k] = -m->P[p][3].v[k] / rate;
            block_stats(tot, ns, B, &v, &se);
            snprintf(name, sizeof name, "viscosity_%s", part[p]);
            row(summary, name, v, se);
        }
    }
    free(tot);
    free(all);
    return 0;
}

/* The row `prefix`_`type`_`axis` of a series. */
static void series_row(FILE *summary, const char *prefix, const char *type, int axis, const Series *x, int nblocks)
{
    char name[96];
    double v, se;
    snprintf(name, sizeof name, "%s_%s_%c", prefix, type, "xyz"[axis]);
    series_stats(x, nblocks, &v, &se);
    row(summary, name, v, se);
}

/* Force on each frozen type and, in rotation scenes, the eq. 1 torques and drag. */
static void write_frozen_bodies(const Measure *m, const System *s, FILE *summary)
{
    const int B = m->nblocks;
    for (int t = 0; t < s->ntypes; t++) {
        if (!s->types[t].frozen) continue;
        const char *tn = s->types[t].name;
        for (int d = 0; d < s->box.dim; d++) series_row(summary, "force_on", tn, d, &m->frozen_force[t][d], B);
        if (s->rotation)
            for (int d = 0; d < 3; d++) {
                series_row(summary, "torque_on", tn, d, &m->frozen_torque[t][d], B);
                series_row(summary, "torque_random_on", tn, d, &m->frozen_torque_random[t][d], B);
                series_row(summary, "drag_on", tn, d, &m->frozen_drag[t][d], B);
            }
    }
}

int measure_write(const Measure *m, const System *s, FILE *summary, const char *dir)
{
    double v, se;
    const int B = m->nblocks;
    series_stats(&m->temperature, B, &v, &se);
    row(summary, "temperature", v, se);
    series_stats(&m->pressure, B, &v, &se);
    row(summary, "pressure", v, se);
    series_stats(&m->epot, B, &v, &se);
    row(summary, "potential_energy_per_particle", v, se);
    if (write_shear_stress(m, s, summary)) return -1;
    write_frozen_bodies(m, s, summary);
    if (s->rotation) {
        series_stats(&m->rot_temperature, B, &v, &se);
        row(summary, "rotational_temperature", v, se);
    }
    if (field_write(&m->field, s, summary, dir)) return -1;
    if (m->prof_on && write_profile(m, s, dir)) return -1;
    if (m->prof_on && m->prof_per_block && write_profile_blocks(m, s, dir)) return -1;
    if (m->com_on && write_com(m, s, summary, dir)) return -1;
    if (m->rdf_on && write_rdf(m, s, dir)) return -1;
    if (m->msd_on && write_msd(m, s, summary, dir)) return -1;
    if (m->tcaf.on && tcaf_write(&m->tcaf, s, summary, dir)) return -1;
    return 0;
}
