/* bonds.c - massless spring colloids in 2D (Phan-Thien et al. 2016, eqs
 * 50-52). See bonds.h. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "bonds.h"
#include "random.h"

#define STREAM_BOND_ORIENT 5 /* Philox stream of the initial orientations */

static const int PAIRS[3][2] = {{0, 1}, {1, 2}, {2, 0}};

Bonds *bonds_new(const BondParams *p, int nblocks, long long steps)
{
    Bonds *b = calloc(1, sizeof *b);
    if (!b) return NULL;
    b->p = *p;
    b->nblocks = nblocks;
    b->nsamples_expected = steps / p->every + 1;
    const size_t nc = (size_t)p->ncol;
    b->ids = calloc(nc * BOND_P, sizeof(uint32_t));
    if (p->around.on) {
        b->around_hist = calloc((size_t)nblocks * p->around.bins, sizeof(double));
        b->around_samples = calloc((size_t)nblocks, sizeof(long long));
    }
    if (p->rdf_on) {
        b->rdf_hist = calloc((size_t)nblocks * p->rdf_bins, sizeof(double));
        b->rdf_samples = calloc((size_t)nblocks, sizeof(long long));
    }
    if (!b->ids || (p->around.on && (!b->around_hist || !b->around_samples))
        || (p->rdf_on && (!b->rdf_hist || !b->rdf_samples))) {
        bonds_free(b);
        return NULL;
    }
    return b;
}

void bonds_free(Bonds *b)
{
    if (!b) return;
    free(b->ids); free(b->index);
    free(b->around_hist); free(b->around_samples); free(b->rdf_hist); free(b->rdf_samples);
    series_free(&b->traj); series_free(&b->ext2); series_free(&b->spring_wyx);
    free(b);
}

void bonds_io(Io *io, Bonds *b)
{
    io_series(io, &b->traj, "colloid centres");
    io_series(io, &b->ext2, "colloid spring extension");
    io_series(io, &b->spring_wyx, "colloid spring stress");
    io_bytes(io, &b->ext_max, sizeof b->ext_max, "colloid largest extension");
    if (b->p.around.on) {
        io_array(io, b->around_hist, (size_t)b->nblocks * b->p.around.bins, sizeof(double), "colloid around");
        io_array(io, b->around_samples, (size_t)b->nblocks, sizeof(long long), "colloid around samples");
    }
    if (b->p.rdf_on) {
        io_array(io, b->rdf_hist, (size_t)b->nblocks * b->p.rdf_bins, sizeof(double), "colloid rdf");
        io_array(io, b->rdf_samples, (size_t)b->nblocks, sizeof(long long), "colloid rdf samples");
    }
}

int bonds_place(Bonds *b, System *s)
{
    b->index = calloc((size_t)s->n + 1, sizeof(int));
    b->nparticles = s->n;
    if (!b->index) return -1;
    if (b->p.around.on) {   /* eq. 48's N / A */
        long long cnt = 0;
        for (int i = 0; i < s->n; i++) cnt += s->type[i] == b->p.around.type;
        b->around_density = cnt / (s->box.L[0] * s->box.L[1]);
    }
    const int m = (int)ceil(sqrt((double)b->p.ncol));
    const double R = b->p.side / sqrt(3.0);   /* circumradius of the triangle */
    int j = 0;
    for (int i = 0; i < s->n; i++) {
        if (s->type[i] != b->p.type) continue;
        const int c = j / BOND_P, k = j % BOND_P;
        const double cx = (c % m + 0.5) * s->box.L[0] / m, cy = (c / m + 0.5) * s->box.L[1] / m;
        philox4x32_ctr_t r = rng_block(s->seed, STREAM_BOND_ORIENT, (uint64_t)c, 0, 0);
        const double phi = 2.0 * M_PI * rng_u01(r.v[0]) + k * 2.0 * M_PI / 3.0;
        s->x[3 * i] = cx + R * cos(phi);
        s->x[3 * i + 1] = cy + R * sin(phi);
        s->x[3 * i + 2] = 0.0;
        for (int d = 0; d < 2; d++) {
            if (s->x[3 * i + d] >= s->box.L[d]) s->x[3 * i + d] -= s->box.L[d];
            if (s->x[3 * i + d] < 0.0) s->x[3 * i + d] += s->box.L[d];
        }
        b->ids[j++] = s->id[i];
    }
    return 0;
}

void bonds_spring(double H, double rbar, const double d[3], double F[3])
{
    const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    F[0] = F[1] = F[2] = 0.0;
    if (r < PAIR_R_EPSILON) return;                /* no direction (pair.h) */
    const double g = -H * (r - rbar) / r;          /* eq. 50: -H (r - r_bar) r_ab / r_ab */
    for (int a = 0; a < 3; a++) F[a] = g * d[a];
}

static void refresh_index(Bonds *b, const System *s)
{
    for (int i = 0; i < s->n; i++) b->index[s->id[i]] = i;
}

/* Spring p of colloid c: the separation d = x_a - x_b (minimum image, z = 0) and the
 * force F on a (-F on b). */
static void spring_of(const Bonds *b, const System *s, int c, int p, int *ia, int *ib, double d[3],
                      double F[3])
{
    *ia = b->index[b->ids[BOND_P * c + PAIRS[p][0]]];
    *ib = b->index[b->ids[BOND_P * c + PAIRS[p][1]]];
    for (int a = 0; a < 3; a++) d[a] = s->x[3 * *ia + a] - s->x[3 * *ib + a];
    box_min_image(&s->box, d, NULL);
    d[2] = 0.0;
    bonds_spring(b->p.H, b->p.side, d, F);
}

/* One spring's virial r_ab F_ab (as the pairs', through the pair driver's
 * pair_virial_add) and energy H (r - side)^2 / 2. */
static void spring_virial(const Bonds *b, const System *s, PairVirial *pv, int ia, const double d[3], const double F[3])
{
    double t[9];
    for (int a = 0; a < 3; a++)
        for (int e = 0; e < 3; e++) t[3 * a + e] = d[a] * F[e];
    pair_virial_add(pv, s, ia, PART_CONSERVATIVE, d, t);
    const double r = sqrt(d[0] * d[0] + d[1] * d[1]);
    pv->epot += 0.5 * b->p.H * (r - b->p.side) * (r - b->p.side);
}

/* Every spring's force (eqs 50-51) added to its particle a and subtracted from
 * b in out, 3 doubles per slot: slot[i] for particle i (the rows of the m = 0
 * system) or i itself (slot NULL); pv != NULL: the virial too. */
static void add_springs(Bonds *b, const System *s, double *out, const int *slot, PairVirial *pv)
{
    refresh_index(b, s);
    for (int c = 0; c < b->p.ncol; c++)
        for (int p = 0; p < 3; p++) {
            int ia, ib;
            double d[3], F[3];
            spring_of(b, s, c, p, &ia, &ib, d, F);
            const int sa = slot ? slot[ia] : ia, sb = slot ? slot[ib] : ib;
            for (int a = 0; a < 2; a++) { out[3 * sa + a] += F[a]; out[3 * sb + a] -= F[a]; }
            if (pv) spring_virial(b, s, pv, ia, d, F);
        }
}

void bonds_rhs(Bonds *b, const System *s, OdSystem *od)
{
    add_springs(b, s, od->f, od->row_of, NULL);   /* eq. 18 with eqs 50-51 */
    double n2 = 0.0;
    for (int k = 0; k < 3 * od->nm; k++) n2 += od->f[k] * od->f[k];
    od->fnorm = sqrt(n2);
}

void bonds_forces(Bonds *b, System *s, PairVirial *pv)
{
    add_springs(b, s, s->f, NULL, pv);
}

static int block_of(const Bonds *b, long long sample)
{
    long long nb = b->nblocks, ns = b->nsamples_expected > 0 ? b->nsamples_expected : 1;
    long long k = sample * nb / ns;
    return (int)(k >= nb ? nb - 1 : k);
}

/* Centre of colloid c: particle 0 unwrapped plus the mean minimum-image
 * offset of the three; wrapped copy in w. */
static void centre(const Bonds *b, const System *s, int c, double u[2], double w[2])
{
    const int i0 = b->index[b->ids[BOND_P * c]];
    double off[3] = {0, 0, 0};
    for (int k = 1; k < BOND_P; k++) {
        const int i = b->index[b->ids[BOND_P * c + k]];
        double d[3] = {s->x[3 * i] - s->x[3 * i0], s->x[3 * i + 1] - s->x[3 * i0 + 1], 0.0};
        box_min_image(&s->box, d, NULL);
        off[0] += d[0]; off[1] += d[1];
    }
    double shift[3];
    box_image_shift(&s->box, s->img + 3 * i0, shift);
    for (int a = 0; a < 2; a++) {
        w[a] = s->x[3 * i0 + a] + off[a] / BOND_P;
        u[a] = w[a] + shift[a];
        w[a] -= floor(w[a] / s->box.L[a]) * s->box.L[a];
    }
}

void bonds_sample(Bonds *b, const System *s, long long prod_step)
{
    if (prod_step < 0 || prod_step % b->p.every) return;
    refresh_index(b, s);
    const long long sample = prod_step / b->p.every;
    const int blk = block_of(b, sample);
    double *wc = malloc(2 * (size_t)b->p.ncol * sizeof(double) + 1);
    if (!wc) return;
    double e2 = 0.0, wyx = 0.0;
    for (int c = 0; c < b->p.ncol; c++) {
        double u[2];
        centre(b, s, c, u, wc + 2 * c);
        series_push(&b->traj, u[0]);
        series_push(&b->traj, u[1]);
        for (int p = 0; p < 3; p++) {
            int ia, ib;
            double d[3], F[3];
            spring_of(b, s, c, p, &ia, &ib, d, F);
            const double r = sqrt(d[0] * d[0] + d[1] * d[1]);
            e2 += (r - b->p.side) * (r - b->p.side);
            b->ext_max = fmax(b->ext_max, fabs(r - b->p.side) / b->p.side);
            wyx += d[1] * F[0];
        }
    }
    series_push(&b->ext2, e2 / (3.0 * b->p.ncol));
    series_push(&b->spring_wyx, wyx);
    if (b->p.around.on) {   /* eq. 48 about every centre */
        double *h = b->around_hist + (size_t)blk * b->p.around.bins;
        for (int c = 0; c < b->p.ncol; c++)
            for (int i = 0; i < s->n; i++) {
                if (s->type[i] != b->p.around.type) continue;
                double d[3] = {s->x[3 * i] - wc[2 * c], s->x[3 * i + 1] - wc[2 * c + 1], 0.0};
                box_min_image(&s->box, d, NULL);
                const int k = (int)(sqrt(d[0] * d[0] + d[1] * d[1]) / b->p.around.dq);
                if (k < b->p.around.bins) h[k] += 1.0;
            }
        b->around_samples[blk] += b->p.ncol;
    }
    if (b->p.rdf_on && b->p.ncol > 1) {
        double *h = b->rdf_hist + (size_t)blk * b->p.rdf_bins;
        for (int c = 0; c < b->p.ncol; c++)
            for (int e = c + 1; e < b->p.ncol; e++) {
                double d[3] = {wc[2 * c] - wc[2 * e], wc[2 * c + 1] - wc[2 * e + 1], 0.0};
                box_min_image(&s->box, d, NULL);
                const int k = (int)(sqrt(d[0] * d[0] + d[1] * d[1]) / (b->p.rdf_rmax / b->p.rdf_bins));
                if (k < b->p.rdf_bins) h[k] += 2.0;   /* ordered pairs */
            }
        b->rdf_samples[blk]++;
    }
    free(wc);
}

/* ------------------------------------------------------------- output */

static double annulus(double q0, double q1) { return M_PI * (q1 * q1 - q0 * q0); }

static int write_around(const Bonds *b, FILE *summary, Tables *ts)
{
    FILE *out = tables_add(ts, "colloid_around.tsv");
    if (!out) return -1;
    const AroundHist a = {.hist = b->around_hist, .samples = b->around_samples, .nblocks = b->nblocks,
                          .bins = b->p.around.bins, .dim = 2, .dq = b->p.around.dq,
                          .density = b->around_density, .threshold = b->p.around.threshold};
    const int bad = around_write(&a, out, summary, "colloid_radius");
    return table_end(ts, out) || bad ? -1 : 0;
}

static int write_rdf(const Bonds *b, const System *s, Tables *ts)
{
    FILE *out = tables_add(ts, "colloid_rdf.tsv");
    if (!out) return -1;
    const double dr = b->p.rdf_rmax / b->p.rdf_bins;
    const double pairs = (double)b->p.ncol * (b->p.ncol - 1) / (s->box.L[0] * s->box.L[1]);
    double *g = malloc((size_t)b->nblocks * sizeof(double) + 1);   /* per block */
    if (!g) { table_end(ts, out); return -1; }
    fprintf(out, "r\tg\tg_se\n");
    for (int q = 0; q < b->p.rdf_bins; q++) {
        int used = 0;
        for (int k = 0; k < b->nblocks; k++)
            if (b->rdf_samples[k] > 0 && pairs > 0)
                g[used++] = b->rdf_hist[(size_t)k * b->p.rdf_bins + q] / (b->rdf_samples[k] * pairs * annulus(q * dr, (q + 1) * dr));
        double mean = NAN, se = NAN;
        if (used > 0) block_stats(g, (size_t)used, used, &mean, &se);
        fprintf(out, "%.6g\t%.6g\t%.3g\n", (q + 0.5) * dr, mean, se);
    }
    free(g);
    return table_end(ts, out);
}

/* MSD of the centres (eq. 52), time average over every sample as origin;
 * errors from blocks of consecutive origins, each at least two windows long
 * (origins closer than a window share their trajectory: shorter blocks would
 * be correlated and understate the error), at most nblocks of them. */
static int write_msd(const Bonds *b, const System *s, FILE *summary, Tables *ts)
{
    const int nc = b->p.ncol, W = b->p.msd_window;
    const long long ns = (long long)(b->traj.n / (2 * (size_t)nc)), no = ns - W;
    const double *T = b->traj.v;
    const double dts = b->p.every * s->dt;
    if (no < 1) { fprintf(summary, "D_colloid\tnan\tnan\n"); return 0; }
    int nb = b->nblocks;
    if (no / (2LL * W) < nb) nb = (int)(no / (2LL * W));
    if (nb < 1) nb = 1;   /* one block: the error is nan */
    /* per block of origins: the mean MSD at every lag */
    double *blk = calloc((size_t)nb * (W + 1), sizeof(double));
    long long *cnt = calloc((size_t)nb, sizeof(long long));
    if (!blk || !cnt) { free(blk); free(cnt); return -1; }
    for (long long o = 0; o < no; o++) {
        const int k = (int)(o * nb / no);
        cnt[k]++;
        for (int l = 1; l <= W; l++) {
            double sum = 0.0;
            for (int c = 0; c < nc; c++)
                for (int a = 0; a < 2; a++) {
                    const double d = T[2 * ((o + l) * nc + c) + a] - T[2 * (o * nc + c) + a];
                    sum += d * d;
                }
            blk[(size_t)k * (W + 1) + l] += sum / nc;
        }
    }
    FILE *out = tables_add(ts, "colloid_msd.tsv");
    if (!out) { free(blk); free(cnt); return -1; }
    fprintf(out, "# %lld time origins, errors from %d blocks of consecutive origins\n", no, nb);
    fprintf(out, "t\tmsd\tmsd_se\tD\tD_se\n");
    double *col = malloc((size_t)nb * sizeof(double) + 1);
    for (int l = 1; l <= W && col; l++) {
        for (int k = 0; k < nb; k++) col[k] = blk[(size_t)k * (W + 1) + l] / cnt[k];
        double mean, se;
        block_stats(col, (size_t)nb, nb, &mean, &se);
        fprintf(out, "%.6g\t%.8g\t%.3g\t%.8g\t%.3g\n", l * dts, mean, se, mean / (4 * l * dts), se / (4 * l * dts));
    }
    /* D = (1/4) d MSD / dt (eq. 52) over the second half of the window */
    const int l0 = W / 2 > 0 ? W / 2 : 1;
    double D = NAN, Dse = NAN;
    if (col && W > l0) {
        for (int k = 0; k < nb; k++)
            col[k] = (blk[(size_t)k * (W + 1) + W] - blk[(size_t)k * (W + 1) + l0]) / cnt[k] / (4.0 * (W - l0) * dts);
        block_stats(col, (size_t)nb, nb, &D, &Dse);
    }
    fprintf(summary, "D_colloid\t%.10g\t%.4g\n", D, Dse);
    free(col); free(blk); free(cnt);
    return table_end(ts, out);
}

int bonds_write(const Bonds *b, const System *s, FILE *summary, Tables *ts)
{
    double v, se;
    fprintf(summary, "colloids\t%d\t0\n", b->p.ncol);
    series_stats(&b->ext2, b->nblocks, &v, &se);
    fprintf(summary, "colloid_spring_extension_rms\t%.10g\t%.4g\n", sqrt(v), v > 0 ? 0.5 * se / sqrt(v) : NAN);
    fprintf(summary, "colloid_spring_extension_max_relative\t%.10g\t0\n", b->ext_max);
    /* spring part of the shear stress T_xy = -P_yx (virial / area) */
    Series t = {0};
    const double A = s->box.L[0] * s->box.L[1];
    for (size_t k = 0; k < b->spring_wyx.n; k++) series_push(&t, -b->spring_wyx.v[k] / A);
    series_stats(&t, b->nblocks, &v, &se);
    fprintf(summary, "stress_xy_spring\t%.10g\t%.4g\n", v, se);
    if (s->box.shear_rate != 0.0)
        fprintf(summary, "viscosity_spring\t%.10g\t%.4g\n", v / s->box.shear_rate, se / fabs(s->box.shear_rate));
    series_free(&t);
    if (write_msd(b, s, summary, ts)) return -1;
    if (b->p.around.on && write_around(b, summary, ts)) return -1;
    if (b->p.rdf_on && write_rdf(b, s, ts)) return -1;
    return 0;
}
