/* pair_walk.h - the walk over the neighbour list, written once for every pair
 * style (pair_style.h) and compiled into each style's file with its
 * evaluator (PAIR_STYLE_WALKS): the entries of consecutive particles are
 * gathered up to PAIR_BATCH at a time; those inside the largest cutoff get
 * their noise in one call (Philox lanes: a particle alone has only a few
 * pairs) and go to the style's evaluator particle by particle, in list
 * order, so that every sum is formed in the same order as one pair at a
 * time. A particle with more than PAIR_BATCH entries is walked in batches of
 * its own. The list holds interacting type pairs only (neighbor.c
 * keep_pair). The evaluator and le (Lees-Edwards shear) are constants: the
 * walk is compiled once per style and box, so that a scene without shear
 * runs no test for it, and no pair is evaluated through a pointer; the
 * vector kernels (PairKernels) are called once per batch. */
#ifndef DPD_PAIR_WALK_H
#define DPD_PAIR_WALK_H

#include "pair_style.h"
#include "random.h"

#define PAIR_INLINE static inline __attribute__((always_inline))

/* The stable ids of pair (i, j), ordered (the key of its noise) */
PAIR_INLINE void pair_ids(const System *s, int i, int j, uint32_t *lo, uint32_t *hi)
{
    const uint32_t a = s->id[i], b = s->id[j];
    *lo = a < b ? a : b;
    *hi = a < b ? b : a;
}

/* Pass 1 of a walk batch: from particle i on (before i1), the list entries
 * of consecutive particles inside the largest cutoff, as long as the next
 * particle's whole list fits in the PAIR_BATCH slots (the caller has taken a
 * longer one alone): near, dd and the ids of each pair, count[p - i] entries
 * of particle p. Returns the end particle ie; *np the entries. */
PAIR_INLINE int walk_gather(const System *s, const NeighborList *nl, int i, int i1, int *near, double (*dd)[4],
                            int *count, uint32_t *id_a, uint32_t *id_b, int *np_out, const int le)
{
    int np = 0, ie = i;
    while (ie < i1 && ie - i < PAIR_BATCH && nl->start[ie + 1] - nl->start[ie] <= PAIR_BATCH - np) {
        const int c = pairs_in_range(s, nl, ie, nl->start[ie], nl->start[ie + 1], near + np, dd + np, le);
        for (int q = np; q < np + c; q++) pair_ids(s, ie, near[q], id_a + q, id_b + q);
        count[ie - i] = c;
        np += c;
        ie++;
    }
    *np_out = np;
    return ie;
}

/* After particle i's last pair: its own sums into the chunk's buffers (and
 * its torque, for a style with spins). */
PAIR_INLINE void pair_close_spins(const int spins, int i, PairAcc *acc)
{
    force_claim(acc->f, acc->tq, acc->touched, i, acc->n);
    for (int a = 0; a < 3; a++) acc->f[3 * i + a] += acc->fi[a];
    if (spins)
        for (int a = 0; a < 3; a++) acc->tq[3 * i + a] += acc->ti[a];
    for (int a = 0; a < 3; a++) acc->fi[a] = acc->ti[a] = 0.0;
}
PAIR_INLINE void pair_close(const PairEvaluator *ev, int i, PairAcc *acc) { pair_close_spins(ev->spins, i, acc); }

/* One batch of particle i's pairs (pairs_in_range) through the style's
 * evaluator, pair by pair: F_ij on i into acc->fi, -F_ij on j into the
 * chunk's buffer, the torques likewise; pv != NULL: the virial too. noise:
 * rng_pair_normals' planes from entry 0; prep: the batch's prepared values
 * from entry 0, or NULL. */
PAIR_INLINE void pair_batch(const PairEvaluator *ev, const System *s, int i, const int *near, const double (*dd)[4],
                            const double *noise, const double *prep, int m, PairAcc *acc, PairVirial *pv, const int le)
{
    const double *v = s->v_pred, *w = s->omega_pred;
    const int ti = s->type[i];
    /* i's sums in registers across the batch (acc->fi could alias the
     * buffers for all the compiler knows) */
    double fi[3] = {acc->fi[0], acc->fi[1], acc->fi[2]}, tqi[3] = {acc->ti[0], acc->ti[1], acc->ti[2]};
    const int record = pv != NULL;
    for (int q = 0; q < m; q++) {
        const int j = near[q];
        const PairParams *p = &s->pair[ti][s->type[j]];
        const double r2 = dd[q][3];
        if (!pair_interacts(p, r2)) continue;
        /* component by component, written out: a loop over a would keep
         * the sums and the pair's force in memory */
        PairIn in;
        in.d[0] = dd[q][0]; in.d[1] = dd[q][1]; in.d[2] = dd[q][2];
        double dvx = v[3 * i] - v[3 * j];
        if (le) dvx -= pair_image_vx(s, i, j, le);     /* relative to j's Lees-Edwards image */
        in.dv[0] = dvx; in.dv[1] = v[3 * i + 1] - v[3 * j + 1]; in.dv[2] = v[3 * i + 2] - v[3 * j + 2];
        in.r = sqrt(r2);
        in.inv_r = 1.0 / in.r;
        in.e[0] = in.d[0] * in.inv_r; in.e[1] = in.d[1] * in.inv_r; in.e[2] = in.d[2] * in.inv_r;
        if (ev->spins) {
            in.wsum[0] = w[3 * i] + w[3 * j];
            in.wsum[1] = w[3 * i + 1] + w[3 * j + 1];
            in.wsum[2] = w[3 * i + 2] + w[3 * j + 2];
        }
        in.noise = noise + q;
        in.prep = prep ? prep + q : NULL;
        in.inv_sqrt_dt = acc->inv_sqrt_dt;
        PairOut out;   /* the parts a style may leave unset outside record: zero */
        out.mag[0] = out.mag[1] = out.mag[2] = out.energy = 0.0;
        ev->pair(p, &in, &out, record);
        const double fx = out.F[0], fy = out.F[1], fz = out.F[2];
        fi[0] += fx; fi[1] += fy; fi[2] += fz;
        force_claim(acc->f, ev->spins ? acc->tq : NULL, acc->touched, j, acc->n);
        acc->f[3 * j] -= fx; acc->f[3 * j + 1] -= fy; acc->f[3 * j + 2] -= fz;
        if (ev->spins) {
            const double tx = out.tau[0], ty = out.tau[1], tz = out.tau[2];
            tqi[0] += tx; tqi[1] += ty; tqi[2] += tz;
            acc->tq[3 * j] += tx; acc->tq[3 * j + 1] += ty; acc->tq[3 * j + 2] += tz;
        }
        if (record) {   /* copies of what the recorder reads: the pair's own in and out stay in registers */
            PairIn rin;
            PairOut rout;
            rin.d[0] = in.d[0]; rin.d[1] = in.d[1]; rin.d[2] = in.d[2]; rin.r = in.r;
            rout.energy = out.energy;
            if (ev->central) {
                rout.F[0] = fx; rout.F[1] = fy; rout.F[2] = fz;
                rout.mag[0] = out.mag[0]; rout.mag[1] = out.mag[1]; rout.mag[2] = out.mag[2];
                pair_record_central(pv, s, i, j, &rin, &rout);
            } else {
                rout.tau[0] = out.tau[0]; rout.tau[1] = out.tau[1]; rout.tau[2] = out.tau[2];
                for (int k = 0; k < PAIR_PARTS; k++) {
                    rout.part[k][0] = out.part[k][0]; rout.part[k][1] = out.part[k][1]; rout.part[k][2] = out.part[k][2];
                }
                pair_record_eq1(pv, s, i, j, &rin, &rout);
            }
        }
    }
    acc->fi[0] = fi[0]; acc->fi[1] = fi[1]; acc->fi[2] = fi[2];
    if (ev->spins) { acc->ti[0] = tqi[0]; acc->ti[1] = tqi[1]; acc->ti[2] = tqi[2]; }
}

/* The pairs of particles [i, ie) of a walk batch (count[p - i] entries each,
 * from entry 0 of near, dd and the noise planes), each particle closed after
 * its pairs (the last one only if close_last: a long list comes in several
 * batches). Steps without the virial of a style with lanes: lane by lane
 * (PairEvaluator.batch_lanes). prepare: the style's prepare is needed. */
PAIR_INLINE void pair_evaluate_batch(const PairEvaluator *ev, const System *s, int i, int ie, int *near,
                                     double (*dd)[4], const double *noise, const int *count, PairAcc *acc,
                                     PairVirial *pv, const PairKernels *k, const int le, const int close_last,
                                     const int prepare)
{
    if (ev->batch_lanes && !pv && k->lanes) {
        ev->batch_lanes(s, i, ie, near, dd, noise, count, acc, le, close_last, k->lanes);
        return;
    }
    double prep[PAIR_BATCH + 8];
    if (ev->prepare && prepare) ev->prepare(s, i, ie, (const double (*)[4])dd, near, count, prep);
    for (int p = i, off = 0; p < ie; off += count[p - i], p++) {
        pair_batch(ev, s, p, near + off, (const double (*)[4])dd + off, noise + off,
                   ev->prepare && prepare ? prep + off : NULL, count[p - i], acc, pv, le);
        if (p + 1 < ie || close_last) pair_close(ev, p, acc);
    }
}

/* The parameters of a walk batch whose pairs (particles [i, ie), count[p - i]
 * partners near[] each) all have the same parameters, bit for bit
 * (s->pair_class): the pair table's entry of the first; NULL if they differ.
 * Types that differ only in name or mass (a wall of the fluid's particles, a
 * second colloid species) then go to the one-type kernels as one type does;
 * the kernels record the force on frozen types as the recorder does. A batch
 * without pairs: its first particle's own type pair. */
PAIR_INLINE const PairParams *batch_one_type(const System *s, int i, int ie, const int *near, const int *count)
{
    const unsigned t = s->type[i];
    if (s->ntypes == 1) return &s->pair[t][t];
    int c0 = -1;
    const PairParams *u = &s->pair[t][t];
    for (int p = i, off = 0; p < ie; off += count[p - i], p++) {
        const unsigned tp = s->type[p];
        const uint8_t *cls = s->pair_class[tp];
        for (int q = off; q < off + count[p - i]; q++) {
            const int c = cls[s->type[near[q]]];
            if (c0 < 0) { c0 = c; u = &s->pair[tp][s->type[near[q]]]; }
            else if (c != c0) return NULL;
        }
    }
    return u;
}

/* A batch's planes (x, y, z, r^2, PAIR_PLANE apart) as the rows dd[q] of the pair-by-pair evaluators */
PAIR_INLINE void planes_to_rows(const double *pl, int np, double (*dd)[4])
{
    for (int q = 0; q < np; q++)
        for (int c = 0; c < 4; c++) dd[q][c] = pl[c * PAIR_PLANE + q];
}

/* The walk over the particles [i0, i1) of one chunk, with the kernels of k:
 * the AVX-512 candidate pass into planes, then each batch of one type pair
 * to the style's one-type kernel (k->gather_planes, k->one_type: 3D, no
 * shear, no binned virial), or into rows (k->gather_rows), or the scalar
 * pass (walk_gather); then pair by pair, or lane by lane (k->lanes). */
PAIR_INLINE void pair_walk(const PairEvaluator *ev, const System *s, const NeighborList *nl, int i0, int i1,
                           PairAcc *acc, PairVirial *pv, const PairKernels *k, const int le)
{
    const int nvar = ev->nvar;
    _Static_assert(PAIR_BATCH <= RNG_BATCH, "a batch's noise fits rng_pair_normals' planes");
    int near[PAIR_BATCH + RANGE_SLACK], count[PAIR_BATCH];
    double dd[PAIR_BATCH + RANGE_SLACK][4], noise[4 * RNG_BATCH];   /* variate v of entry q at noise[v * RNG_BATCH + q] */
    uint32_t id_a[PAIR_BATCH + RANGE_SLACK], id_b[PAIR_BATCH + RANGE_SLACK];
    double pl[4 * PAIR_PLANE];
    const int prepare = ev->prepare && ev->prepare_needed(s);
    for (int a = 0; a < 3; a++) acc->fi[a] = acc->ti[a] = 0.0;
    for (int i = i0; i < i1;) {
        if (nl->start[i + 1] - nl->start[i] > PAIR_BATCH) {   /* a long list: batches of its own */
            for (int k0 = nl->start[i]; k0 < nl->start[i + 1]; k0 += PAIR_BATCH) {
                const int k1 = k0 + PAIR_BATCH < nl->start[i + 1] ? k0 + PAIR_BATCH : nl->start[i + 1];
                const int m = pairs_in_range(s, nl, i, k0, k1, near, dd, le);
                for (int q = 0; q < m; q++) pair_ids(s, i, near[q], id_a + q, id_b + q);
                rng_pair_normals_ordered(s->seed, s->step, m, id_a, id_b, nvar, noise);
                pair_evaluate_batch(ev, s, i, i + 1, near, dd, noise, &m, acc, pv, k, le, 0, prepare);
            }
            pair_close(ev, i, acc);
            i++;
            continue;
        }
        int np, ie;
        if (!le && k->gather_planes) {
            ie = k->gather_planes(s, nl, i, i1, near, pl, count, id_a, id_b, &np, k->ahead);
            rng_pair_normals_ordered(s->seed, s->step, np, id_a, id_b, nvar, noise);
            const PairParams *u = k->one_type ? batch_one_type(s, i, ie, near, count) : NULL;
            if (!u || !k->one_type(s, i, ie, near, pl, noise, count, acc, u, pv)) {
                /* several type pairs, or a type pair the kernel does not take: pair by pair */
                planes_to_rows(pl, np, dd);
                pair_evaluate_batch(ev, s, i, ie, near, dd, noise, count, acc, pv, k, le, 1, prepare);
            }
            i = ie;
            continue;
        }
        if (!le && k->gather_rows) ie = k->gather_rows(s, nl, i, i1, near, dd, count, id_a, id_b, &np, k->ahead);
        else ie = walk_gather(s, nl, i, i1, near, dd, count, id_a, id_b, &np, le);
        rng_pair_normals_ordered(s->seed, s->step, np, id_a, id_b, nvar, noise);
        pair_evaluate_batch(ev, s, i, ie, near, dd, noise, count, acc, pv, k, le, 1, prepare);
        i = ie;
    }
}

/* A style's two walks (PairStyle.walk): periodic and Lees-Edwards. */
#define PAIR_STYLE_WALKS(name, evaluator)                                                                      \
    static void name##_walk_plain(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc,      \
                                  PairVirial *pv, const PairKernels *k)                                         \
    { pair_walk(&(evaluator), s, nl, i0, i1, acc, pv, k, 0); }                                                  \
    static void name##_walk_shear(const System *s, const NeighborList *nl, int i0, int i1, PairAcc *acc,      \
                                  PairVirial *pv, const PairKernels *k)                                         \
    { pair_walk(&(evaluator), s, nl, i0, i1, acc, pv, k, 1); }

#endif
