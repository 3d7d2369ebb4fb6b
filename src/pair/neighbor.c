/* neighbor.c - cell lists and the Verlet half list. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <stdint.h>
#include <limits.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "neighbor.h"
#include "simd.h"

#define CELLS_PER_CUTOFF 1   /* R: cell width >= cutoff / R */

static int cell_index(const NeighborList *nl, const double *x)
{
    int c[3] = {0, 0, 0};
    for (int d = 0; d < 3; d++) {
        if (nl->nc[d] == 1) continue;
        const double q = x[d] / nl->cw[d];   /* clamped before the cast: a blown-up x stays defined */
        c[d] = !(q >= 0.0) ? 0 : q >= nl->nc[d] ? nl->nc[d] - 1 : (int)q;
    }
    /* y slowest, so that the half stencil crosses the sheared boundary only
     * in +y */
    return c[0] + nl->nc[0] * (c[2] + nl->nc[2] * c[1]);
}

/* The number of cells; at most NEIGHBOR_MAX_CELLS (neighbor_init), so that it and every
 * cell index fit the int arrays of the list. */
static size_t cell_count(const NeighborList *nl)
{
    return (size_t)nl->nc[0] * (size_t)nl->nc[1] * (size_t)nl->nc[2];
}

int neighbor_init(NeighborList *nl, const System *s, double skin)
{
    memset(nl, 0, sizeof *nl);
    nl->n = s->n;
    nl->skin = skin;
    nl->cutoff = s->rc_max + skin;
    const Box *b = &s->box;
    /* R cells per cutoff. R = 2 was measured (callgrind, 24000 particles): 27 %
     * fewer distance tests, but with 0.8 particles per cell the per-cell
     * stencil set-up cost more than it saved; R = 1 with the cells of a row
     * merged into one run is 12 % cheaper than cell-by-cell. */
    const int R = CELLS_PER_CUTOFF;
    nl->per_cutoff = R;
    nl->brute_force = 0;
    /* the cells are counted in size_t: a box of 2000^3 at a cutoff of 1.3 has 3.6e9 of them,
     * beyond the int indices of the cell list (cell_start, cell_of), which the caller reports */
    size_t ncells = 1;
    for (int d = 0; d < 3; d++) {
        if (d >= b->dim) { nl->nc[d] = 1; nl->cw[d] = 1.0; continue; }
        const double q = floor(b->L[d] * R / nl->cutoff);
        if (!(q <= (double)NEIGHBOR_MAX_CELLS) || (ncells *= (size_t)(q > 1.0 ? q : 1.0)) > NEIGHBOR_MAX_CELLS) {
            memset(nl, 0, sizeof *nl);
            return NEIGHBOR_TOO_MANY_CELLS;
        }
        nl->nc[d] = (int)q;
        if (nl->nc[d] < 2 * R + 1) nl->brute_force = 1;
        nl->cw[d] = b->L[d] / (nl->nc[d] > 0 ? nl->nc[d] : 1);
    }
    /* the Lees-Edwards rows span up to 2R + 2 cells in x */
    if (b->shear_rate != 0.0 && nl->nc[0] < 2 * R + 2) nl->brute_force = 1;
    if (nl->brute_force)
        for (int d = 0; d < 3; d++) { nl->nc[d] = 1; nl->cw[d] = d < b->dim ? b->L[d] : 1.0; }
    const size_t ncell = cell_count(nl);
    const size_t n = (size_t)s->n;
    nl->cell_start = calloc(ncell + 1, sizeof(int));
    nl->cell_of = calloc(n + 1, sizeof(int));
    nl->perm = calloc(n + 1, sizeof(int));
    nl->start = calloc(n + 1, sizeof(int));
    nl->x_ref = calloc(3 * n + 1, sizeof(double));
    nl->img_ref = calloc(n + 1, sizeof(int));
    nl->scratch = calloc(3 * n + 1, sizeof(double));
    nl->cap = 16 * n + 16;
    nl->nbr = malloc(nl->cap * sizeof(int));
    if (!nl->cell_start || !nl->cell_of || !nl->perm || !nl->start
        || !nl->x_ref || !nl->img_ref || !nl->scratch || !nl->nbr) {
        neighbor_free(nl);
        return -1;
    }
    return 0;
}

void neighbor_free(NeighborList *nl)
{
    free(nl->cell_start); free(nl->tcount); free(nl->cell_of); free(nl->perm);
    for (int c = 0; c < NL_MAX_CHUNKS; c++) free(nl->tbuf[c]);
    free(nl->start); free(nl->nbr); free(nl->x_ref); free(nl->img_ref); free(nl->scratch);
    free(nl->tmpl_start); free(nl->tmpl);
    memset(nl, 0, sizeof *nl);
}

/* Sort the particles by cell (counting sort), keeping the order within a cell:
 * the permutation does not depend on the thread count. Each thread counts the
 * cells of a contiguous range of particles; then each thread places the
 * particles of a contiguous range of cells (about n / threads particles),
 * scanning all particles in order, so that no two threads write next to each
 * other in perm (placing by particle range interleaved the threads' writes
 * within every cell: false sharing). */
/* The first cell whose particles start at or after sorted position k. */
static int first_cell_at(const NeighborList *nl, int ncell, int k)
{
    int lo = 0, hi = ncell;
    while (lo < hi) { const int mid = (lo + hi) / 2; if (nl->cell_start[mid] < k) lo = mid + 1; else hi = mid; }
    return lo;
}

static int sort_by_cell(NeighborList *nl, System *s)
{
    const int ncell = (int)cell_count(nl), n = s->n;
    int maxth = 1;
#ifdef _OPENMP
    maxth = omp_get_max_threads();
#endif
    if (maxth > NL_MAX_THREADS) maxth = NL_MAX_THREADS;
    if (nl->tcount_threads < maxth) {
        free(nl->tcount);
        nl->tcount = malloc((size_t)ncell * (size_t)maxth * sizeof(int));
        nl->tcount_threads = nl->tcount ? maxth : 0;
        if (!nl->tcount) return -1;
    }
    #pragma omp parallel num_threads(maxth)
    {
        int tid = 0, nth = 1;
#ifdef _OPENMP
        tid = omp_get_thread_num();
        nth = omp_get_num_threads();
#endif
        const int i0 = (int)((long long)n * tid / nth), i1 = (int)((long long)n * (tid + 1) / nth);
        int *cnt = nl->tcount + (size_t)tid * (size_t)ncell;
        memset(cnt, 0, (size_t)ncell * sizeof(int));
        for (int i = i0; i < i1; i++) { const int c = cell_index(nl, s->x + 3 * i); nl->cell_of[i] = c; cnt[c]++; }
        #pragma omp barrier
        #pragma omp single
        {
            int run = 0;
            for (int c = 0; c < ncell; c++) {
                nl->cell_start[c] = run;
                for (int t = 0; t < nth; t++) run += nl->tcount[(size_t)t * (size_t)ncell + c];
            }
            nl->cell_start[ncell] = run;
            /* thread 0's counts become the cursors */
            memcpy(nl->tcount, nl->cell_start, (size_t)ncell * sizeof(int));
        }   /* implicit barrier */
        int *cur = nl->tcount;
        const int c0 = first_cell_at(nl, ncell, (int)((long long)n * tid / nth));
        const int c1 = tid == nth - 1 ? ncell : first_cell_at(nl, ncell, (int)((long long)n * (tid + 1) / nth));
        for (int i = 0; i < n; i++) {
            const int c = nl->cell_of[i];
            if (c >= c0 && c < c1) nl->perm[cur[c]++] = i;
        }
    }
    system_permute(s, nl->perm, &nl->scratch);
    return 0;
}

/* A stencil segment: a run of particles (consecutive cells of one row, x
 * fastest) holding possible partners of the particles of a cell, and the shift
 * that brings them next to that cell (periodic images, Lees-Edwards offset). */
typedef struct { int j0, j1; double shift[3]; int c0, c1; } Segment;   /* c0 .. c1: its cells */

#define MAX_SEGMENTS 32   /* (2R + 1)^2 / 2 + 1 rows, each split at most once */

/* Cells ux_lo..ux_hi (unwrapped x indices, span at most nx) of row (wy, wz),
 * split where the row wraps; shift_y/z and the extra x shift are already known. */
static void add_row(const NeighborList *nl, const Box *b, int ux_lo, int ux_hi, int wy, int wz,
                    double extra_x, double shift_y, double shift_z, Segment *out, int *m)
{
    const int nx = nl->nc[0];
    const int base = nx * (wz + nl->nc[2] * wy);
    /* floor(ux_lo / nx) in integers (a libm floor call per row cost 1.5 % of a run) */
    const int q0 = ux_lo >= 0 ? ux_lo / nx : -((nx - 1 - ux_lo) / nx);
    for (int q = q0; q * nx <= ux_hi; q++) {
        const int lo = (ux_lo > q * nx ? ux_lo : q * nx) - q * nx;
        const int hi = (ux_hi < q * nx + nx - 1 ? ux_hi : q * nx + nx - 1) - q * nx;
        Segment *g = &out[(*m)++];
        g->c0 = base + lo; g->c1 = base + hi;
        g->j0 = nl->cell_start[g->c0];
        g->j1 = nl->cell_start[g->c1 + 1];
        g->shift[0] = q * b->L[0] + extra_x;
        g->shift[1] = shift_y;
        g->shift[2] = shift_z;
    }
}

/* Half stencil of cell c, R = nl->per_cutoff cells per cutoff: rows above in y
 * (all z), then rows above in z of the same y, then the rest of the own row.
 * The first segment is the own row starting at cell c; the caller starts it
 * after particle i. */
static int stencil_segments(const NeighborList *nl, const Box *b, int c, Segment *out)
{
    const int nx = nl->nc[0], ny = nl->nc[1], nz = nl->nc[2], R = nl->per_cutoff;
    const int cx = c % nx, cz = (c / nx) % nz, cy = c / (nx * nz);
    const int Rz = nz > 1 ? R : 0;
    const double Lz = b->dim == 3 ? b->L[2] : 0.0;
    int m = 0;
    add_row(nl, b, cx, cx + R, cy, cz, 0.0, 0.0, 0.0, out, &m);
    for (int dz = 1; dz <= Rz; dz++) {
        const int uz = cz + dz, wz = uz >= nz ? uz - nz : uz;   /* R <= nz: one wrap at most */
        add_row(nl, b, cx - R, cx + R, cy, wz, 0.0, 0.0, uz >= nz ? Lz : 0.0, out, &m);
    }
    for (int dy = 1; dy <= R; dy++) {
        const int uy = cy + dy, wy = uy >= ny ? uy - ny : uy;
        const int across = uy >= ny;
        int xlo = cx - R, xhi = cx + R;
        double extra = 0.0;
        if (across && b->shear_rate != 0.0) {
            /* row wy seen through the Lees-Edwards image above, shifted by +offset */
            xlo = (int)floor((cx * nl->cw[0] - b->le_offset - nl->cutoff) / nl->cw[0]);
            xhi = (int)floor(((cx + 1) * nl->cw[0] - b->le_offset + nl->cutoff) / nl->cw[0]);
            if (xhi - xlo + 1 > nx) xhi = xlo + nx - 1;
            extra = b->le_offset;
        }
        for (int dz = -Rz; dz <= Rz; dz++) {
            const int uz = cz + dz, wz = uz < 0 ? uz + nz : uz >= nz ? uz - nz : uz;
            add_row(nl, b, xlo, xhi, wy, wz, extra, across ? b->L[1] : 0.0,
                    uz >= nz ? Lz : (uz < 0 ? -Lz : 0.0), out, &m);
        }
    }
    return m;
}

/* Without shear the stencil of a cell does not change between builds: its
 * segments' cells and shifts are made once, the particle ranges at each build
 * (stencil_segments' integer arithmetic per cell was 3 % of a run). */
static int stencil_templates(NeighborList *nl, const Box *b)
{
    const int ncell = (int)cell_count(nl);
    nl->tmpl_start = malloc(((size_t)ncell + 1) * sizeof(int));
    if (!nl->tmpl_start) return -1;
    Segment seg[MAX_SEGMENTS], *all = NULL;
    size_t len = 0, cap = 0;
    for (int c = 0; c < ncell; c++) {
        nl->tmpl_start[c] = (int)len;
        const int m = stencil_segments(nl, b, c, seg);
        if (len + (size_t)m > cap) {
            cap = 2 * (len + (size_t)m) + 64;
            Segment *p = realloc(all, cap * sizeof *all);
            if (!p) { free(all); free(nl->tmpl_start); nl->tmpl_start = NULL; return -1; }
            all = p;
        }
        memcpy(all + len, seg, (size_t)m * sizeof *seg);
        len += (size_t)m;
    }
    nl->tmpl_start[ncell] = (int)len;
    nl->tmpl = all;
    return 0;
}

static int ensure_capacity(int **buf, size_t *cap, size_t need)
{
    if (need <= *cap) return 0;
    size_t nc = need + need / 2 + 1024;
    int *p = realloc(*buf, nc * sizeof(int));
    if (!p) return -1;
    *buf = p;
    *cap = nc;
    return 0;
}

static inline int keep_pair(const System *s, int filter, int i, int j)
{
    if (!filter) return 1;
    const int ti = s->type[i], tj = s->type[j];
    return s->pair[ti][tj].active && !(s->types[ti].frozen && s->types[tj].frozen);
}

/* The candidates j0..j1 - 1 of a stencil segment within the list cutoff of
 * (sx, sy, sz) (particle i less the segment's shift), appended to buf from
 * len: the distance test of build_range, branch free (the test result
 * advances the write index, one slot is written past the last kept). */
static inline __attribute__((always_inline))
size_t scan_segment(const double *x, int j0, int j1, double sx, double sy, double sz, double cut2,
                    int *buf, size_t len)
{
    for (int j = j0; j < j1; j++) {
        const double dx = sx - x[3 * j], dy = sy - x[3 * j + 1], dz = sz - x[3 * j + 2];
        buf[len] = j;
        len += (dx * dx + dy * dy + dz * dz < cut2);
    }
    return len;
}

/* SCAN_SLACK: the slots past the last kept entry that a scan may write (the
 * backend's, simd.h SimdKernels.nl_scan, stores sixteen at a time). */
#define SCAN_SLACK 16

/* The stencil segments of cell c with their particle ranges (m returned),
 * and the particles they hold in *span: room one particle of c can need. */
static int cell_segments(const NeighborList *nl, const Box *b, int c, Segment *seg, size_t *span)
{
    int m;
    if (nl->tmpl_start) {   /* without shear: the cells and shifts made once (stencil_templates) */
        m = nl->tmpl_start[c + 1] - nl->tmpl_start[c];
        memcpy(seg, (const Segment *)nl->tmpl + nl->tmpl_start[c], (size_t)m * sizeof *seg);
        for (int k = 0; k < m; k++) { seg[k].j0 = nl->cell_start[seg[k].c0]; seg[k].j1 = nl->cell_start[seg[k].c1 + 1]; }
    } else m = stencil_segments(nl, b, c, seg);
    *span = 0;
    for (int k = 0; k < m; k++) *span += (size_t)(seg[k].j1 - seg[k].j0);
    return m;
}

/* Neighbours of the particles [i0, i1) appended to the chunk's buffer *buf_out
 * (capacity *cap_out, length *len_out); counts in start[i+1]. The buffer, its
 * capacity and length are kept in locals and written back at the end: the
 * chunks' entries share cache lines, and writing them for every particle made
 * the two threads fight over those lines (the build ran 1.2-1.6x slower per
 * thread on 2 threads than on 1). */
static inline __attribute__((always_inline))
int build_range(const NeighborList *nl, const System *s, int i0, int i1, int filter,
                int **buf_out, size_t *cap_out, size_t *len_out)
{
    int *buf = *buf_out;
    size_t cap = *cap_out, len = *len_out;
    int rc = 0;
    const double cut2 = nl->cutoff * nl->cutoff;
    const double *x = s->x;
    Segment seg[MAX_SEGMENTS];
    int cur_cell = -1, m = 0;
    size_t span = 0;   /* particles in the current cell's stencil: room one i can need */
    for (int i = i0; i < i1; i++) {
        size_t before = len;
        if (nl->brute_force) {
            if (ensure_capacity(&buf, &cap, len + (size_t)(s->n - i) + 64)) { rc = -1; break; }
            for (int j = i + 1; j < s->n; j++) {
                if (!keep_pair(s, filter, i, j)) continue;
                double d[3] = {x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1], x[3 * i + 2] - x[3 * j + 2]};
                box_min_image(&s->box, d, NULL);
                if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < cut2) buf[len++] = j;
            }
            nl->start[i + 1] = (int)(len - before);
            continue;
        }
        const int c = nl->cell_of[i];
        if (c != cur_cell) {
            cur_cell = c;
            m = cell_segments(nl, &s->box, c, seg, &span);
        }
        if (ensure_capacity(&buf, &cap, len + span + SCAN_SLACK)) { rc = -1; break; }
        const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
        for (int k = 0; k < m; k++) {
            const double sx = xi - seg[k].shift[0], sy = yi - seg[k].shift[1], sz = zi - seg[k].shift[2];
            /* segment 0 is the own row from cell c: partners after i only */
            const int j0 = k == 0 ? i + 1 : seg[k].j0;
            len = scan_segment(x, j0, seg[k].j1, sx, sy, sz, cut2, buf, len);
        }
        if (filter) {   /* drop frozen-frozen and non-interacting pairs */
            size_t w = before;
            for (size_t q = before; q < len; q++)
                if (keep_pair(s, 1, i, buf[q])) buf[w++] = buf[q];
            len = w;
        }
        nl->start[i + 1] = (int)(len - before);
    }
    *buf_out = buf; *cap_out = cap; *len_out = len;
    return rc;
}

static int build_range_portable(const NeighborList *nl, const System *s, int i0, int i1, int filter,
                                int **buf, size_t *cap, size_t *len)
{ return build_range(nl, s, i0, i1, filter, buf, cap, len); }
/* build_range for the particles of one cell at a time (at most CELL_BLOCK),
 * with the backend's distance test (3D; simd.h SimdKernels.nl_scan,
 * nl_scan_block): each group of eight candidates of a shared stencil segment
 * is loaded and sorted into lanes once and tested against every particle of
 * the block, each writing into a region of its own; the regions are then
 * closed up in particle order. Every particle's entries are those of
 * build_range, in its order (its own row first, then the segments in order). */
#define CELL_BLOCK 32
static int build_cells(const NeighborList *nl, const System *s, int i0, int i1, int filter, int **buf_out,
                       size_t *cap_out, size_t *len_out)
{
    const SimdKernels *sk = simd_kernels();
    int *buf = *buf_out;
    size_t cap = *cap_out, len = *len_out;
    const double cut2 = nl->cutoff * nl->cutoff, *x = s->x;
    Segment seg[MAX_SEGMENTS];
    size_t at[CELL_BLOCK], end[CELL_BLOCK];
    int rc = 0;
    for (int ia = i0; ia < i1;) {
        const int c = nl->cell_of[ia];
        int ib = nl->cell_start[c + 1] < i1 ? nl->cell_start[c + 1] : i1;
        if (ib - ia > CELL_BLOCK) ib = ia + CELL_BLOCK;
        const int nb = ib - ia;
        size_t span;
        const int m = cell_segments(nl, &s->box, c, seg, &span);
        const size_t room = span + SCAN_SLACK;
        if (ensure_capacity(&buf, &cap, len + (size_t)nb * room)) { rc = -1; break; }
        for (int q = 0; q < nb; q++) {   /* the own row, from the particle after i */
            const int i = ia + q;
            at[q] = len + (size_t)q * room;
            end[q] = sk->nl_scan(x, i + 1, seg[0].j1, x[3 * i] - seg[0].shift[0], x[3 * i + 1] - seg[0].shift[1],
                                 x[3 * i + 2] - seg[0].shift[2], cut2, buf, at[q]);
        }
        for (int k = 1; k < m; k++) {
            double sp[CELL_BLOCK][3];
            for (int q = 0; q < nb; q++)
                for (int a = 0; a < 3; a++) sp[q][a] = x[3 * (ia + q) + a] - seg[k].shift[a];
            sk->nl_scan_block(x, seg[k].j0, seg[k].j1, nb, (const double (*)[3])sp, cut2, buf, end);
        }
        for (int q = 0; q < nb; q++) {   /* close up, in particle order (len <= at[q]: moves go down) */
            const int i = ia + q;
            size_t w = at[q];
            if (filter) {   /* drop frozen-frozen and non-interacting pairs */
                for (size_t r = at[q]; r < end[q]; r++)
                    if (keep_pair(s, 1, i, buf[r])) buf[w++] = buf[r];
            } else w = end[q];
            const size_t cnt = w - at[q];
            memmove(buf + len, buf + at[q], cnt * sizeof *buf);
            len += cnt;
            nl->start[i + 1] = (int)cnt;
        }
        ia = ib;
    }
    *buf_out = buf; *cap_out = cap; *len_out = len;
    return rc;
}
/* 3D boxes (2D ones keep z = 0 but are few and small) */
static int build_range_cells(const NeighborList *nl, const System *s, int i0, int i1, int filter, int **buf,
                             size_t *cap, size_t *len)
{
    if (!nl->brute_force) return build_cells(nl, s, i0, i1, filter, buf, cap, len);
    return build_range(nl, s, i0, i1, filter, buf, cap, len);   /* all pairs: the scalar test */
}

/* Particles per build chunk on more than one thread: small enough that a
 * thread on a slower (shared) core takes fewer chunks, large enough that a
 * chunk's stencil set-up and buffer stay cheap. */
#define BUILD_CHUNKS_PER_THREAD 8

int neighbor_build(NeighborList *nl, System *s)
{
    const int n = s->n;
    if (sort_by_cell(nl, s)) return -1;
    if (!nl->brute_force && s->box.shear_rate == 0.0 && !nl->tmpl_start && stencil_templates(nl, &s->box)) return -1;
    /* sorted: the particles of cell c are cell_start[c] .. cell_start[c + 1] - 1
     * (the cells cell_index gives them; no second pass of divisions) */
    const int ncell = (int)cell_count(nl);
    #pragma omp parallel for schedule(static)
    for (int c = 0; c < ncell; c++)
        for (int k = nl->cell_start[c]; k < nl->cell_start[c + 1]; k++) nl->cell_of[k] = c;
    int filter = s->n_frozen > 0;
    for (int a = 0; a < s->ntypes; a++)
        for (int b = 0; b < s->ntypes; b++) if (!s->pair[a][b].active) filter = 1;
    int maxth = 1;
#ifdef _OPENMP
    maxth = omp_get_max_threads();
#endif
    /* Contiguous particle ranges (chunks), each listed into its own buffer by
     * whichever thread takes it next, then concatenated in chunk order: the
     * list does not depend on the thread count or on which thread built what.
     * One thread: one chunk, whose buffer becomes the list (no copy). */
    int nchunk = maxth == 1 ? 1 : BUILD_CHUNKS_PER_THREAD * maxth;
    if (nchunk > NL_MAX_CHUNKS) nchunk = NL_MAX_CHUNKS;
    if (nchunk > n) nchunk = n > 0 ? n : 1;
    int failed = 0;
    size_t at[NL_MAX_CHUNKS + 1];
    int (*range_fn)(const NeighborList *, const System *, int, int, int, int **, size_t *, size_t *) = build_range_portable;
    if (s->box.dim == 3 && simd_kernels()->nl_scan_block) range_fn = build_range_cells;
    #pragma omp parallel
    {
        #pragma omp for schedule(dynamic, 1)
        for (int c = 0; c < nchunk; c++) {
            const int i0 = (int)((long long)n * c / nchunk), i1 = (int)((long long)n * (c + 1) / nchunk);
            nl->tlen[c] = 0;
            if (range_fn(nl, s, i0, i1, filter, &nl->tbuf[c], &nl->tcap[c], &nl->tlen[c])) {
                #pragma omp atomic write
                failed = 1;
            }
        }   /* implicit barrier */
        #pragma omp single
        {
            nl->nchunks_used = nchunk;
            at[0] = 0;
            for (int c = 0; c < nchunk; c++) at[c + 1] = at[c] + nl->tlen[c];
            if (!failed && at[nchunk] > (size_t)INT32_MAX) failed = 1;
            if (!failed && nchunk == 1) {
                int *p = nl->nbr; size_t cp = nl->cap;
                nl->nbr = nl->tbuf[0]; nl->cap = nl->tcap[0];
                nl->tbuf[0] = p; nl->tcap[0] = cp;
            } else if (!failed && ensure_capacity(&nl->nbr, &nl->cap, at[nchunk] + 1)) {
                failed = 1;
            }
        }   /* implicit barrier */
        if (!failed) {
            #pragma omp for schedule(dynamic, 1)
            for (int c = 0; c < nchunk; c++) {
                const int i0 = (int)((long long)n * c / nchunk), i1 = (int)((long long)n * (c + 1) / nchunk);
                if (nchunk > 1) memcpy(nl->nbr + at[c], nl->tbuf[c], nl->tlen[c] * sizeof(int));
                int run = (int)at[c];   /* start[i + 1] holds the count of i: make it the offset */
                for (int i = i0; i < i1; i++) { run += nl->start[i + 1]; nl->start[i + 1] = run; }
                memcpy(nl->x_ref + 3 * (size_t)i0, s->x + 3 * (size_t)i0, 3 * (size_t)(i1 - i0) * sizeof(double));
                for (int i = i0; i < i1; i++) nl->img_ref[i] = s->img[3 * i + 1];
            }
        }
    }
    if (failed) return -1;
    nl->start[0] = 0;
    nl->offset_moved = 0.0;
    nl->builds++;
    return 0;
}

void neighbor_note_shear(NeighborList *nl, double offset_increment)
{
    nl->offset_moved += fabs(offset_increment);
}

/* The largest squared displacement since the build of a box without shear:
 * neighbor_update's folds as selects, so that the loop vectorises (the same
 * r^2, so the same decision) */
static double max_displacement2_plain(const NeighborList *nl, const System *s)
{
    const Box *b = &s->box;
    const double *restrict x = s->x, *restrict x0 = nl->x_ref;
    double max2 = 0.0;
    #pragma omp parallel for simd reduction(max:max2)
    for (int i = 0; i < s->n; i++) {
        double r2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double d = x[3 * i + k] - x0[3 * i + k];
            if (k < b->dim) d = d > b->half[k] ? d - b->L[k] : d < -b->half[k] ? d + b->L[k] : d;
            r2 += d * d;
        }
        max2 = r2 > max2 ? r2 : max2;
    }
    return max2;
}

int neighbor_update(NeighborList *nl, System *s)
{
    double max2 = 0.0;
    const Box *b = &s->box;
    if (b->shear_rate == 0.0) max2 = max_displacement2_plain(nl, s);
    else
    #pragma omp parallel for reduction(max:max2)
    for (int i = 0; i < s->n; i++) {
        double d[3];
        for (int k = 0; k < 3; k++) d[k] = s->x[3 * i + k] - nl->x_ref[3 * i + k];
        /* undo the Lees-Edwards shift of a y crossing, at the current offset;
         * the offset travelled since the build bounds the difference */
        d[0] += (s->img[3 * i + 1] - nl->img_ref[i]) * b->le_offset;
        /* a particle that crossed a boundary is compared through its image; a
         * move of more than half a box (a blow-up) stays large and forces a
         * rebuild either way, so one box length is enough (no rint call) */
        for (int k = 0; k < b->dim; k++) {
            if (d[k] > b->half[k]) d[k] -= b->L[k];
            else if (d[k] < -b->half[k]) d[k] += b->L[k];
        }
        const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (r2 > max2) max2 = r2;
    }
    if (2.0 * (sqrt(max2) + nl->offset_moved) + nl->offset_moved < nl->skin) return 0;
    if (neighbor_build(nl, s)) return -1;
    return 1;
}

size_t neighbor_pairs(const NeighborList *nl)
{
    return (size_t)nl->start[nl->n];
}
