/* neighbor.c - cell lists and the Verlet half list. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "neighbor.h"

static int cell_index(const NeighborList *nl, const double *x)
{
    int c[3] = {0, 0, 0};
    for (int d = 0; d < 3; d++) {
        if (nl->nc[d] == 1) continue;
        c[d] = (int)(x[d] / nl->cw[d]);
        if (c[d] >= nl->nc[d]) c[d] = nl->nc[d] - 1;
        if (c[d] < 0) c[d] = 0;
    }
    /* y slowest, so that the half stencil crosses the sheared boundary only
     * in +y */
    return c[0] + nl->nc[0] * (c[2] + nl->nc[2] * c[1]);
}

int neighbor_init(NeighborList *nl, const System *s, double skin)
{
    memset(nl, 0, sizeof *nl);
    nl->n = s->n;
    nl->skin = skin;
    nl->cutoff = s->rc_max + skin;
    const Box *b = &s->box;
    nl->brute_force = 0;
    for (int d = 0; d < 3; d++) {
        if (d >= b->dim) { nl->nc[d] = 1; nl->cw[d] = 1.0; continue; }
        nl->nc[d] = (int)floor(b->L[d] / nl->cutoff);
        if (nl->nc[d] < 3) nl->brute_force = 1;
        nl->cw[d] = b->L[d] / (nl->nc[d] > 0 ? nl->nc[d] : 1);
    }
    if (b->shear_rate != 0.0 && nl->nc[0] < 4) nl->brute_force = 1;
    if (nl->brute_force)
        for (int d = 0; d < 3; d++) { nl->nc[d] = 1; nl->cw[d] = d < b->dim ? b->L[d] : 1.0; }
    const int ncell = nl->nc[0] * nl->nc[1] * nl->nc[2];
    const size_t n = (size_t)s->n;
    nl->cell_start = calloc((size_t)ncell + 1, sizeof(int));
    nl->count = calloc((size_t)ncell, sizeof(int));
    nl->cell_of = calloc(n + 1, sizeof(int));
    nl->perm = calloc(n + 1, sizeof(int));
    nl->start = calloc(n + 1, sizeof(int));
    nl->x_ref = calloc(3 * n + 1, sizeof(double));
    nl->img_ref = calloc(n + 1, sizeof(int));
    nl->scratch = calloc(3 * n + 1, sizeof(double));
    nl->cap = 16 * n + 16;
    nl->nbr = malloc(nl->cap * sizeof(int));
    if (!nl->cell_start || !nl->count || !nl->cell_of || !nl->perm || !nl->start
        || !nl->x_ref || !nl->img_ref || !nl->scratch || !nl->nbr) {
        neighbor_free(nl);
        return -1;
    }
    return 0;
}

void neighbor_free(NeighborList *nl)
{
    free(nl->cell_start); free(nl->count); free(nl->cell_of); free(nl->perm);
    free(nl->start); free(nl->nbr); free(nl->x_ref); free(nl->img_ref); free(nl->scratch);
    memset(nl, 0, sizeof *nl);
}

/* Sort the particles by cell (counting sort), keeping the order within a cell. */
static void sort_by_cell(NeighborList *nl, System *s)
{
    const int ncell = nl->nc[0] * nl->nc[1] * nl->nc[2];
    memset(nl->count, 0, (size_t)ncell * sizeof(int));
    for (int i = 0; i < s->n; i++) {
        nl->cell_of[i] = cell_index(nl, s->x + 3 * i);
        nl->count[nl->cell_of[i]]++;
    }
    nl->cell_start[0] = 0;
    for (int c = 0; c < ncell; c++) nl->cell_start[c + 1] = nl->cell_start[c] + nl->count[c];
    memcpy(nl->count, nl->cell_start, (size_t)ncell * sizeof(int));
    for (int i = 0; i < s->n; i++) nl->perm[nl->count[nl->cell_of[i]]++] = i;
    system_permute(s, nl->perm, nl->scratch);
}

static int pair_wanted(const System *s, int i, int j, double cut2)
{
    const int ti = s->type[i], tj = s->type[j];
    if (!s->pair[ti][tj].active) return 0;
    if (s->types[ti].frozen && s->types[tj].frozen) return 0;
    double d[3] = {s->x[3 * i] - s->x[3 * j], s->x[3 * i + 1] - s->x[3 * j + 1],
                   s->x[3 * i + 2] - s->x[3 * j + 2]};
    box_min_image(&s->box, d, NULL);
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < cut2;
}

/* Cells that can hold neighbours of particles in cell (cx, cy, cz) through
 * the half stencil; returns their count. */
static int half_stencil(const NeighborList *nl, const Box *b, int cx, int cy, int cz, int *out)
{
    const int nx = nl->nc[0], ny = nl->nc[1], nz = nl->nc[2];
    int m = 0;
    const int zlo = nz > 1 ? -1 : 0, zhi = nz > 1 ? 1 : 0;
#define CELL(X, Y, Z) ((((X) % nx + nx) % nx) + nx * ((((Z) % nz + nz) % nz) + nz * (((Y) % ny + ny) % ny)))
    /* dy = +1 row */
    int xlo = cx - 1, xhi = cx + 1;
    if (cy == ny - 1 && b->shear_rate != 0.0) {
        /* the row above is row 0 seen through the Lees-Edwards image, shifted by +offset */
        xlo = (int)floor((cx * nl->cw[0] - b->le_offset - nl->cutoff) / nl->cw[0]);
        xhi = (int)floor(((cx + 1) * nl->cw[0] - b->le_offset + nl->cutoff) / nl->cw[0]);
        if (xhi - xlo + 1 > nx) xhi = xlo + nx - 1;
    }
    for (int dz = zlo; dz <= zhi; dz++)
        for (int X = xlo; X <= xhi; X++) out[m++] = CELL(X, cy + 1, cz + dz);
    /* dy = 0, dz = +1 */
    if (nz > 1)
        for (int dx = -1; dx <= 1; dx++) out[m++] = CELL(cx + dx, cy, cz + 1);
    /* dy = 0, dz = 0, dx = +1 */
    out[m++] = CELL(cx + 1, cy, cz);
#undef CELL
    return m;
}

static int ensure_capacity(NeighborList *nl, size_t need)
{
    if (need <= nl->cap) return 0;
    size_t cap = need + need / 4 + 16;
    int *p = realloc(nl->nbr, cap * sizeof(int));
    if (!p) return -1;
    nl->nbr = p;
    nl->cap = cap;
    return 0;
}

/* Visit the candidate neighbours of particle i; mode 0 counts, mode 1 fills. */
static int candidates(const NeighborList *nl, const System *s, int i, double cut2, int *fill)
{
    int cnt = 0;
    if (nl->brute_force) {
        for (int j = i + 1; j < s->n; j++)
            if (pair_wanted(s, i, j, cut2)) { if (fill) fill[cnt] = j; cnt++; }
        return cnt;
    }
    const int c = nl->cell_of[i];
    const int nx = nl->nc[0], nz = nl->nc[2];
    const int cx = c % nx, cz = (c / nx) % nz, cy = c / (nx * nz);
    for (int j = i + 1; j < nl->cell_start[c + 1]; j++)
        if (pair_wanted(s, i, j, cut2)) { if (fill) fill[cnt] = j; cnt++; }
    int cells[32];
    const int m = half_stencil(nl, &s->box, cx, cy, cz, cells);
    for (int k = 0; k < m; k++)
        for (int j = nl->cell_start[cells[k]]; j < nl->cell_start[cells[k] + 1]; j++)
            if (pair_wanted(s, i, j, cut2)) { if (fill) fill[cnt] = j; cnt++; }
    return cnt;
}

int neighbor_build(NeighborList *nl, System *s)
{
    const int n = s->n;
    sort_by_cell(nl, s);
    for (int i = 0; i < n; i++) nl->cell_of[i] = cell_index(nl, s->x + 3 * i);
    const double cut2 = nl->cutoff * nl->cutoff;
    /* pass 1: count */
    #pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; i++) nl->start[i + 1] = candidates(nl, s, i, cut2, NULL);
    nl->start[0] = 0;
    for (int i = 0; i < n; i++) nl->start[i + 1] += nl->start[i];
    if (ensure_capacity(nl, (size_t)nl->start[n])) return -1;
    /* pass 2: fill */
    #pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < n; i++) candidates(nl, s, i, cut2, nl->nbr + nl->start[i]);
    memcpy(nl->x_ref, s->x, 3 * (size_t)n * sizeof(double));
    for (int i = 0; i < n; i++) nl->img_ref[i] = s->img[3 * i + 1];
    nl->offset_moved = 0.0;
    nl->builds++;
    return 0;
}

void neighbor_note_shear(NeighborList *nl, double offset_increment)
{
    nl->offset_moved += fabs(offset_increment);
}

int neighbor_update(NeighborList *nl, System *s)
{
    double max2 = 0.0;
    const Box *b = &s->box;
    #pragma omp parallel for reduction(max:max2)
    for (int i = 0; i < s->n; i++) {
        double d[3];
        for (int k = 0; k < 3; k++) d[k] = s->x[3 * i + k] - nl->x_ref[3 * i + k];
        /* undo the Lees-Edwards shift of a y crossing, at the current offset;
         * the offset travelled since the build bounds the difference */
        d[0] += (s->img[3 * i + 1] - nl->img_ref[i]) * b->le_offset;
        /* a particle that crossed a boundary is compared through its image */
        for (int k = 0; k < b->dim; k++) d[k] -= b->L[k] * rint(d[k] * b->inv[k]);
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
