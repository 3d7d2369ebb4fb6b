/* random.c - Philox counter blocks as a GSL generator, for GSL's ziggurat. */
#include <string.h>
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

/* ---- batches ------------------------------------------------------------ */
#include <threads.h>
#include "simd.h"

/* Philox4x32-10 (Salmon et al. 2011), Random123's philox4x32 round for round:
 * out = (hi(M1 c2) ^ c1 ^ k0, lo(M1 c2), hi(M0 c0) ^ c3 ^ k1, lo(M0 c0)), the
 * key bumped by the Weyl constants between rounds. One lane per pair; the key
 * and the step words are the same for every lane. The portable loop below is
 * the reference; on x86-64 an AVX-512 or AVX2 version of the same rounds is
 * chosen at run time (one binary for any x86-64), its 32 x 32 -> 64 bit
 * products from the even and odd lanes (vpmuludq), which GCC's vectoriser
 * does not find. tests/test_random.c checks every lane against philox4x32. */
static void philox_portable(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
                            const uint32_t *restrict c2, const uint32_t *restrict c3,
                            uint32_t (*restrict w)[RNG_BATCH], int q0)
{
    for (int q = q0; q < m; q++) {
        uint32_t x0 = c0, x1 = c1, x2 = c2[q], x3 = c3[q], a = k0, b = k1;
        for (int r = 0; r < 10; r++) {
            const uint64_t p0 = (uint64_t)PHILOX_M4x32_0 * x0, p1 = (uint64_t)PHILOX_M4x32_1 * x2;
            x0 = (uint32_t)(p1 >> 32) ^ x1 ^ a;
            x1 = (uint32_t)p1;
            x2 = (uint32_t)(p0 >> 32) ^ x3 ^ b;
            x3 = (uint32_t)p0;
            a += PHILOX_W32_0; b += PHILOX_W32_1;
        }
        w[0][q] = x0; w[1][q] = x1; w[2][q] = x2; w[3][q] = x3;
    }
}

static void philox_lanes(int m, uint32_t k0, uint32_t k1, uint32_t c0, uint32_t c1,
                         const uint32_t *c2, const uint32_t *c3, uint32_t (*w)[RNG_BATCH])
{
    const SimdKernels *k = simd_kernels();
    const int q0 = k->philox ? k->philox(m, k0, k1, c0, c1, c2, c3, w) : 0;
    philox_portable(m, k0, k1, c0, c1, c2, c3, w, q0);
}

static once_flag batch_once = ONCE_FLAG_INIT;
static void batch_init(void);

/* ordered: id_a[q] <= id_b[q] already (the pair driver's candidate pass) */
static void pair_blocks(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                        const int ordered, uint32_t w[4][RNG_BATCH])
{
    call_once(&batch_once, batch_init);
    if (ordered) {
        philox_lanes(m, seed, STREAM_PAIR_NOISE, (uint32_t)step, (uint32_t)(step >> 32), id_a, id_b, w);
        return;
    }
    uint32_t lo[RNG_BATCH], hi[RNG_BATCH];
    for (int q = 0; q < m; q++) {
        lo[q] = id_a[q] < id_b[q] ? id_a[q] : id_b[q];
        hi[q] = id_a[q] < id_b[q] ? id_b[q] : id_a[q];
    }
    philox_lanes(m, seed, STREAM_PAIR_NOISE, (uint32_t)step, (uint32_t)(step >> 32), lo, hi, w);
}

void rng_pair_blocks(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                     uint32_t w[4][RNG_BATCH])
{
    pair_blocks(seed, step, m, id_a, id_b, 0, w);
}

/* GSL's strip tables, read out of GSL itself (no copy of its constants): per
 * strip i, the word (j << 8 | 0x80 | i) is accepted at once iff j < zig.k[i],
 * and then gives j * zig.w[i]. Probed with a generator that counts its calls:
 * one call = accepted at once; later words (0x81: strip 1, j = 0) end any
 * further attempt. */
static ZigTables zig;   /* k, w here; wedge_a, wedge_b below (wedge_init) */
typedef struct { uint32_t first, second; int calls; } ZigProbe;
static unsigned long probe_get(void *vs)
{
    ZigProbe *p = vs;
    const int c = p->calls++;
    return c == 0 ? p->first : c == 1 ? p->second : 0x81u;
}
static double probe_get_double(void *vs) { return probe_get(vs) * (1.0 / 4294967296.0); }
static void probe_set(void *vs, unsigned long seed) { (void)vs; (void)seed; }
static const gsl_rng_type probe_type = {"ziggurat-probe", 0xffffffffUL, 0, sizeof(ZigProbe),
                                        &probe_set, &probe_get, &probe_get_double};
/* GSL's variate from the words first, second, then 0x81...: the words it took */
static int probe_words(uint32_t first, uint32_t second, double *x)
{
    ZigProbe p = {first, second, 0};
    gsl_rng r = {&probe_type, &p};
    *x = gsl_ran_gaussian_ziggurat(&r, 1.0);
    return p.calls;
}
static int probe(uint32_t i, uint32_t j, double *x)
{
    return probe_words((j << 8) | 0x80u | i, 0x81u, x) == 1;
}

/* GSL's wedge test, for a word k = (j << 8 | 0x80 | i) of strip i < 127 not
 * accepted at once: with U1 from the next word, y = y1 + (y0 - y1) U1
 * (y0, y1 = ytab[i], ytab[i + 1], table heights GSL does not export), kept
 * iff y < exp(-x^2 / 2), x = j wtab[i]. y is linear in U1, so it is
 * bracketed at two points, U1 = 1/4 and 3/4, by probing: GSL keeps the word
 * for j < J and not from J on, so exp(-x_J^2 / 2) <= y < exp(-x_{J-1}^2 / 2)
 * (x_j = j wtab[i]: GSL's own x and exp). Per strip: y(1/4) in
 * [zig.wedge_a[0], zig.wedge_a[1]], the slope in [zig.wedge_b[0], zig.wedge_b[1]]. The
 * brackets are about 1e-7 wide; a bound not found stays 0 or 1 (y is in
 * (0, 1]), and the test is then left to GSL. */
static int wedge_kept(uint32_t i, uint32_t j, uint32_t u)
{
    double x;
    return probe_words((j << 8) | 0x80u | i, u, &x) == 2;   /* k and U1: kept by the wedge; more: a new attempt */
}
static void wedge_bracket(uint32_t i, uint32_t u, double *lo_y, double *hi_y)
{
    const uint32_t j0 = zig.k[i];
    uint32_t lo = j0, hi = 1u << 24;   /* J: the first j not kept, in [j0, 2^24] */
    while (lo < hi) {
        const uint32_t mid = lo + (hi - lo) / 2;
        if (wedge_kept(i, mid, u)) lo = mid + 1; else hi = mid;
    }
    const double xJ = lo * zig.w[i], xJ1 = (lo - 1) * zig.w[i];
    *lo_y = lo < (1u << 24) ? exp(-0.5 * xJ * xJ) : 0.0;
    *hi_y = lo > j0 ? exp(-0.5 * xJ1 * xJ1) : 1.0;
}
static void wedge_init(void)
{
    for (uint32_t i = 0; i < 128; i++) {
        double alo = 0.0, ahi = 1.0, blo = 0.0, bhi = 1.0;   /* strip 127 (the tail): open */
        if (i < 127) {
            wedge_bracket(i, 1u << 30, &alo, &ahi);   /* U1 = 1/4 */
            wedge_bracket(i, 3u << 30, &blo, &bhi);   /* U1 = 3/4 */
        }
        zig.wedge_a[0][i] = alo; zig.wedge_a[1][i] = ahi;
        zig.wedge_b[0][i] = (blo - ahi) / 0.5; zig.wedge_b[1][i] = (bhi - alo) / 0.5;   /* slope dy / dU1 */
    }
}

int rng_ziggurat_wedge_brackets(double width)
{
    call_once(&batch_once, batch_init);
    int n = 0;
    for (int i = 0; i < 128; i++) n += zig.wedge_a[1][i] - zig.wedge_a[0][i] < width && zig.wedge_b[1][i] - zig.wedge_b[0][i] < 4 * width;
    return n;
}
static void zig_init(void)
{
    for (uint32_t i = 0; i < 128; i++) {
        uint32_t lo = 0, hi = 1u << 24;   /* accepted at once iff j < k: find k in [0, 2^24] */
        while (lo < hi) {
            const uint32_t mid = lo + (hi - lo) / 2;
            double x;
            if (probe(i, mid, &x)) lo = mid + 1; else hi = mid;
        }
        zig.k[i] = lo;
        /* j = 1: x = wtab[i], accepted at once or, in a strip that never is
         * (strip 0, the top one: zig.k = 0), kept by the wedge test with
         * U1 = 0 (y = ytab[1] < exp(-wtab[0]^2 / 2)) */
        double x;
        zig.w[i] = probe_words((1u << 8) | 0x80u | i, 0u, &x) <= 2 ? x : NAN;   /* NAN: the wedge test then stays open (GSL's) */
    }
}

static inline int zig_accept(uint32_t k, double *z)
{
    const uint32_t i = k & 0x7f, j = k >> 8;
    const double x = j * zig.w[i];
    /* GSL: sign * sigma * x, sigma = 1; x >= 0, so -x is x with its sign bit
     * set, here without a branch (the sign is a fair coin: a branch on it is
     * guessed wrong half the time) */
    uint64_t b;
    memcpy(&b, &x, sizeof b);
    b ^= (uint64_t)(~k & 0x80u) << 56;
    memcpy(z, &b, sizeof b);
    return j < zig.k[i];
}

/* once per process: the strip tables */
static void batch_init(void)
{
    zig_init();
    wedge_init();
}

int rng_ziggurat_fast(uint32_t k, double *z)
{
    call_once(&batch_once, batch_init);
    return zig_accept(k, z);
}

int rng_ziggurat_wedge(uint32_t k, uint32_t u)
{
    call_once(&batch_once, batch_init);
    const SimdKernels *sk = simd_kernels();
    if (sk->zig_wedge) {
        uint32_t kw[8] = {k}, uw[8] = {u};
        uint8_t out[8];
        sk->zig_wedge(1, kw, uw, out, &zig);
        return out[0];
    }
    return -1;
}

/* A pair's sequence from a given word on, as a GSL generator: its first
 * eight words (blocks 0 and 1) in an array, so that a resumed pair's words
 * are read without a test per word; a word past them (1.4e-4 of the pairs of
 * four variates, 1.7e-4 of those of one, which have four words) from its
 * Philox block, computed then. */
typedef struct {
    uint32_t w[8];
    int pos, lim;                 /* next word; words in w (4: block 1 not drawn) */
    philox4x32_ctr_t ctr;         /* block 0's counter (rng_pair_start's) */
    philox4x32_key_t key;
} PairWords;

static unsigned long words_get(void *vs)
{
    PairWords *c = vs;
    const int p = c->pos++;
    if (__builtin_expect(p < c->lim, 1)) return c->w[p];
    philox4x32_ctr_t ctr = c->ctr;
    ctr.v[1] += (uint32_t)(p >> 2) << 24;   /* block p / 4, as counter_get counts them */
    return philox4x32(ctr, c->key).v[p & 3];
}
static double words_get_double(void *vs) { return words_get(vs) * (1.0 / 4294967296.0); }
static const gsl_rng_type words_type = {
    "philox4x32-10-pair-words", 0xffffffffUL, 0, sizeof(PairWords),
    &counter_set, &words_get, &words_get_double
};

/* One normal from the pair's words at c->pos on, as gsl_ran_gaussian_ziggurat draws it */
static double words_normal(PairWords *c)
{
    gsl_rng r = {&words_type, c};
    return gsl_ran_gaussian_ziggurat(&r, 1.0);
}

/* One pair whose variate v0 the ziggurat did not accept at once: variates
 * 0 ... v0 - 1 (in z already) took its first v0 words. Where the batch's
 * wedge test settled variate v0 (wedge_avx512), it is z's value (kept: the
 * first step's x, as GSL returns it) or GSL's next attempt (not kept: the
 * word after U1, nearly always accepted at once); where it did not, GSL draws
 * it from word v0 on (not testing that word first: a test known to fail is a
 * branch the predictor gets wrong). The later variates resume where variate
 * v0 stopped; they too are nearly always accepted at once (97.2 % each): all
 * their first steps are taken before one test decides (one predictable
 * branch, where a loop of its own per variate was one wrong guess per pair:
 * the number of variates left is v0's, random). Anything else (one pair in
 * about 30) goes to GSL variate by variate. */
static void pair_resume_one(PairWords *c, int v0, int nvar, double *z, int q, int wedge)
{
    double t[4];   /* t[u]: variate v0 + u */
    unsigned all;
    int pos;
    if (__builtin_expect(wedge == WEDGE_OPEN, 0)) {
        c->pos = v0;
        t[0] = words_normal(c);
        pos = c->pos;
        all = 1;
    } else {   /* no branch on which: kept and not kept are even odds */
        const unsigned again = wedge == WEDGE_NOT_KEPT;
        double x;
        const unsigned ok = (unsigned)zig_accept(c->w[v0 + 2 < 8 ? v0 + 2 : 7], &x) & (unsigned)(v0 + 2 < c->lim);
        const double kept = z[v0 * RNG_BATCH + q];
        t[0] = again ? x : kept;
        all = (unsigned)!again | ok;
        pos = v0 + 2 + (int)again;
    }
    for (int u = 1; u < 4; u++) {   /* the next three words' first steps (a word past the eight: GSL below) */
        const int p = pos + u - 1, needed = v0 + u < nvar;
        all &= (unsigned)(zig_accept(c->w[p < 8 ? p : 7], &t[u]) & (p < c->lim)) | (unsigned)!needed;
    }
    if (__builtin_expect(all, 1)) {   /* stores at indices, not branches on v0 (the fastest of three forms) */
        double zz[7];
        for (int v = 0; v < nvar; v++) zz[v] = z[v * RNG_BATCH + q];
        for (int u = 0; u < 4; u++) zz[v0 + u] = t[u];
        for (int v = 0; v < nvar; v++) z[v * RNG_BATCH + q] = zz[v];
        return;
    }
    c->pos = v0;   /* rare: from variate v0 on, variate by variate */
    for (int v = v0; v < nvar; v++) {
        double x;
        if (v > v0 && c->pos < c->lim && zig_accept(c->w[c->pos], &x)) { c->pos++; z[v * RNG_BATCH + q] = x; }
        else z[v * RNG_BATCH + q] = words_normal(c);
    }
}

/* The pairs of a batch whose variate v0[k] the ziggurat did not accept at
 * once (bad[k]: their index in the batch). The first block is the batch's and
 * the second, which most pairs of several variates reach (GSL's path takes a
 * second word), is drawn for all of them at once. */
static void pair_normals_resume(uint32_t seed, uint64_t step, const uint32_t *id_a, const uint32_t *id_b,
                                const uint32_t (*w)[RNG_BATCH], int nbad, const int *bad, const int *v0,
                                int nvar, double *z)
{
    uint32_t lo[RNG_BATCH], hi[RNG_BATCH], w1[4][RNG_BATCH];
    for (int k = 0; k < nbad; k++) {
        const uint32_t a = id_a[bad[k]], b = id_b[bad[k]];
        lo[k] = a < b ? a : b; hi[k] = a < b ? b : a;
    }
    /* one variate rarely reaches the second block (its first has four words) */
    const int next = nvar > 1;
    if (next) philox_lanes(nbad, seed, STREAM_PAIR_NOISE, (uint32_t)step, (uint32_t)(step >> 32) + (1u << 24), lo, hi, w1);
    /* the wedge test of each pair's variate v0, all pairs at once: its word and U1's */
    uint8_t wedge[RNG_BATCH + 8];
    memset(wedge, WEDGE_OPEN, (size_t)nbad);
    const SimdKernels *sk = simd_kernels();
    if (sk->zig_wedge) {
        uint32_t kw[RNG_BATCH + 8], uw[RNG_BATCH + 8];
        for (int k = 0; k < nbad; k++) {
            const int q = bad[k], v = v0[k];
            kw[k] = w[v][q];
            uw[k] = v + 1 < 4 ? w[v + 1 < 4 ? v + 1 : 3][q] : w1[0][k];   /* nvar 1: v = 0 */
        }
        for (int k = nbad; k < ((nbad + 7) & ~7); k++) kw[k] = uw[k] = 0;
        sk->zig_wedge(nbad, kw, uw, wedge, &zig);
    }
    PairWords c;   /* rng_pair_start's counter and key */
    c.ctr.v[0] = (uint32_t)step; c.ctr.v[1] = (uint32_t)(step >> 32);
    c.key.v[0] = seed; c.key.v[1] = STREAM_PAIR_NOISE;
    c.lim = next ? 8 : 4;
    for (int k = 0; k < nbad; k++) {
        const int q = bad[k];
        c.ctr.v[2] = lo[k]; c.ctr.v[3] = hi[k];
        for (int u = 0; u < 4; u++) { c.w[u] = w[u][q]; c.w[4 + u] = next ? w1[u][k] : 0; }
        pair_resume_one(&c, v0[k], nvar, z, q, wedge[k]);
    }
}

static void pair_normals(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                         const int ordered, int nvar, double *z)
{
    uint32_t w[4][RNG_BATCH];
    pair_blocks(seed, step, m, id_a, id_b, ordered, w);
    int q0 = 0, nbad = 0, bad[RNG_BATCH + 16], v0[RNG_BATCH + 16];   /* + 16: the backend's zig_bad_pairs stores 16 at a time */
    const SimdKernels *sk = simd_kernels();
    if (sk->zig_first) {   /* 16 pairs at a time, variate by variate, then the pairs not accepted at once */
        uint16_t ok[4][RNG_BATCH / 16];
        for (int v = 0; v < nvar; v++) q0 = sk->zig_first(m, w[v], z + v * RNG_BATCH, ok[v], &zig);
        if (sk->zig_bad_pairs) nbad = sk->zig_bad_pairs((q0 + 15) / 16, (const uint16_t (*)[RNG_BATCH / 16])ok, nvar, bad, v0);
        else
            for (int g = 0; g < (q0 + 15) / 16; g++) {
                unsigned all = ok[0][g];
                for (int v = 1; v < nvar; v++) all &= ok[v][g];
                for (unsigned b = (uint16_t)~all; b; b &= b - 1) {
                    const int l = __builtin_ctz(b);
                    unsigned not_ok = 0;   /* bit v: variate v not accepted (no branch on which) */
                    for (int v = 0; v < nvar; v++) not_ok |= (~(unsigned)ok[v][g] >> l & 1u) << v;
                    bad[nbad] = 16 * g + l; v0[nbad++] = __builtin_ctz(not_ok);   /* the first variate not accepted */
                }
            }
    }
    for (int q = q0; q < m; q++) {
        int v = 0;
        while (v < nvar && zig_accept(w[v][q], &z[v * RNG_BATCH + q])) v++;
        if (v < nvar) { bad[nbad] = q; v0[nbad++] = v; }
    }
    if (nbad > 0) pair_normals_resume(seed, step, id_a, id_b, (const uint32_t (*)[RNG_BATCH])w, nbad, bad, v0, nvar, z);
}

void rng_pair_normals(uint32_t seed, uint64_t step, int m, const uint32_t *id_a, const uint32_t *id_b,
                      int nvar, double *z)
{
    pair_normals(seed, step, m, id_a, id_b, 0, nvar, z);
}

void rng_pair_normals_ordered(uint32_t seed, uint64_t step, int m, const uint32_t *lo, const uint32_t *hi,
                              int nvar, double *z)
{
    pair_normals(seed, step, m, lo, hi, 1, nvar, z);
}
