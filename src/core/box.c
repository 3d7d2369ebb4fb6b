/* box.c - periodic and Lees-Edwards boundaries. */
#include <limits.h>
#include "box.h"
#include <math.h>

void box_init(Box *b, int dim, const double L[3], double shear_rate)
{
    b->dim = dim;
    for (int d = 0; d < 3; d++) {
        b->L[d] = (d < dim) ? L[d] : 0.0;
        b->half[d] = 0.5 * b->L[d];
        b->inv[d] = (d < dim) ? 1.0 / L[d] : 0.0;
    }
    b->shear_rate = shear_rate;
    b->le_offset = 0.0;
}

int box_advance(Box *b, double dt)
{
    if (!MOD_SHEAR(b)) return 0;
    const double t = b->le_offset + b->shear_rate * b->L[1] * dt;
    b->le_offset = fmod(t, b->L[0]);
    if (b->le_offset < 0.0) b->le_offset += b->L[0];
    return (int)lround((t - b->le_offset) * b->inv[0]);
}

/* img += n, saturating: a runaway particle (which the stability check then
 * stops) can pile up more box crossings than an int holds */
static void add_images(int *img, double n)
{
    const double t = (double)*img + n;
    *img = t > (double)INT_MAX ? INT_MAX : (t < (double)INT_MIN ? INT_MIN : (int)t);
}

void box_offset_wrapped(int32_t *img, int n, int k)
{
    for (int i = 0; i < n; i++) add_images(&img[3 * i], (double)k * img[3 * i + 1]);
}

static int finite3(const double x[3])
{
    return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]);
}

/* le: the box has Lees-Edwards shear, a constant (compiled once per value).
 * Returns 1 if the position is not finite (left as it is), found on the
 * paths that handle positions outside the box: the fast path pays nothing. */
static inline __attribute__((always_inline))
int wrap(const Box *b, double x[3], int img[3], double *vx1, double *vx2, const int le)
{
    const double jump = b->shear_rate * b->L[1];
    if (!(x[1] > -b->L[1] && x[1] < 2.0 * b->L[1])) {
        /* far outside (a blow-up the stability check will stop) or not finite: jump
         * back in one go instead of one box length at a time */
        const double n = floor(x[1] * b->inv[1]);
        if (!isfinite(n) || fabs(n) > 1e9) return !finite3(x);   /* leave it: the run stops at the check */
        x[1] -= n * b->L[1]; add_images(&img[1], n);
        if (le) {
            x[0] -= n * b->le_offset;
            if (vx1) *vx1 -= n * jump;
            if (vx2) *vx2 -= n * jump;
        }
    }
    while (x[1] >= b->L[1]) {
        x[1] -= b->L[1]; add_images(&img[1], 1.0);
        if (le) { x[0] -= b->le_offset; if (vx1) *vx1 -= jump; if (vx2) *vx2 -= jump; }
    }
    while (x[1] < 0.0) {
        x[1] += b->L[1]; add_images(&img[1], -1.0);
        if (le) { x[0] += b->le_offset; if (vx1) *vx1 += jump; if (vx2) *vx2 += jump; }
    }
    int bad = 0;
    for (int d = 0; d < b->dim; d++) {
        if (d == 1) continue; /* y done above */
        if (x[d] >= 0.0 && x[d] < b->L[d]) continue;   /* inside: most particles, no floor call */
        double n = floor(x[d] * b->inv[d]);
        if (!isfinite(n) || fabs(n) > 1e9) { bad |= !isfinite(x[d]); continue; }   /* the run stops at the check */
        if (n != 0.0) { x[d] -= n * b->L[d]; add_images(&img[d], n); }
        if (x[d] >= b->L[d]) x[d] -= b->L[d]; /* round-off at the upper edge */
    }
    return bad;
}

int box_wrap_shear(const Box *b, double x[3], int img[3], double *vx1, double *vx2)
{
    return wrap(b, x, img, vx1, vx2, 1);
}

int box_wrap_plain(const Box *b, double x[3], int img[3], double *vx1, double *vx2)
{
    return wrap(b, x, img, vx1, vx2, 0);
}

int box_wrap(const Box *b, double x[3], int img[3], double *vx1, double *vx2)
{
    return MOD_SHEAR(b) ? wrap(b, x, img, vx1, vx2, 1) : wrap(b, x, img, vx1, vx2, 0);
}
