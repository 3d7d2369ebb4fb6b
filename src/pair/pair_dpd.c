/* pair_dpd.c - the pair style of standard DPD (Groot & Warren 1997) with the
 * general weight exponent of Mai-Duy et al. 2019 (eqs 2-7): its evaluator,
 * its walks, its m = 0 terms and its registration. Its AVX-512 evaluator of
 * one-type batches (src/simd/pair_avx512.c dpd_one_type_avx512) performs this
 * evaluator's operations in its order, eight pairs at a time. */
#include "pair_walk.h"
#include "pair_avx512.h"
#include "simd.h"

/* F_ij = [a w_C + (-gamma w_R^2 e.v_ij) + sigma w_R theta / sqrt(dt)] e_ij,
 * the three terms summed in this order. w_R of a general exponent comes
 * prepared with the batch's (weight_general: pair_random_weights). */
static inline __attribute__((always_inline))
void dpd_pair(const PairParams *p, const PairIn *in, PairOut *out, int record)
{
    const double *e = in->e, *dv = in->dv;
    const double edv = e[0] * dv[0] + e[1] * dv[1] + e[2] * dv[2];
    const double wc = 1.0 - in->r / p->rc;                                             /* w_C, eq. 5 */
    const double wr = in->prep && weight_general(p->s) ? *in->prep : random_weight(wc, p->s);   /* w_R, eq. 7 */
    const double fc = p->a * wc;                                                       /* conservative, eq. 2 */
    const double fd = -p->gamma * wr * wr * edv;                                       /* dissipative, eq. 3 */
    const double fr = p->sigma * wr * in->noise[0] * in->inv_sqrt_dt;                  /* random, eq. 4 */
    const double ft = fc + fd + fr;
    out->F[0] = ft * e[0]; out->F[1] = ft * e[1]; out->F[2] = ft * e[2];
    out->mag[PART_CONSERVATIVE] = fc; out->mag[PART_DISSIPATIVE] = fd; out->mag[PART_RANDOM] = fr;
    if (record) out->energy = pair_energy(p, wc);
}

static const PairEvaluator dpd_evaluator = {
    .nvar = 1, .spins = 0, .central = 1, .pair = dpd_pair,
    .prepare_needed = scene_weights_general, .prepare = pair_random_weights,
};

PAIR_STYLE_WALKS(dpd, dpd_evaluator)

static void dpd_one(const PairParams *p, const PairIn *in, PairOut *out)
{
    dpd_pair(p, in, out, 1);
}

/* m = 0 (Phan-Thien et al. 2016 eqs 16, 18): the known force a w_C + sigma
 * w_R theta / sqrt(dt) and the friction gamma w_D, with w_D = (1 - r/rc)^s
 * formed directly (dissipative_weight; for s = 2, 1, 0.5 its square root is
 * w_R bit for bit). */
static void dpd_overdamped(const PairParams *p, double r, double theta, double inv_sqrt_dt, double *fcr, double *g)
{
    const double wc = 1.0 - r / p->rc;                          /* w_C, eq. 5 */
    const double wd = dissipative_weight(wc, p->s);             /* w_D, eq. 6 */
    const double wr = random_weight(wc, p->s);                  /* w_R = sqrt(w_D), eq. 7 */
    *fcr = p->a * wc + p->sigma * wr * theta * inv_sqrt_dt;     /* eq. 18, first part */
    *g = p->gamma * wd;
}

static int dpd_serves(const System *s) { return !MOD_ROTATION(s); }

const PairStyle pair_style_dpd = {
    .name = "dpd", .nvar = 1, .spins = 0, .central = 1, .serves = dpd_serves,
    .walk = {dpd_walk_plain, dpd_walk_shear}, .one = dpd_one, .overdamped = dpd_overdamped,
    .accel = {[SIMD_AVX512] = {.one_type = SIMD_X86(dpd_one_type_avx512)}},
};
