/* box.h - periodic box with optional Lees-Edwards sliding images.
 * Shear flow u_x = rate * (y - L_y / 2): the periodic image above the box is
 * displaced by +offset in x and moves with +rate * L_y (Lees & Edwards 1972). */
#ifndef DPD_BOX_H
#define DPD_BOX_H

#include <math.h>
#include <stdint.h>
#include "modules.h"

typedef struct {
    int dim;                  /* 2 or 3 */
    double L[3], half[3], inv[3];
    double shear_rate;        /* 0: plain periodic */
    double le_offset;         /* current image offset in x, in [0, L_x) */
} Box;

void box_init(Box *b, int dim, const double L[3], double shear_rate);
/* Move the offset on by rate L_y dt; returns k, the whole L_x it dropped to
 * stay in [0, L_x) (0, or -1 / +1 when it wrapped): see box_offset_wrapped. */
int  box_advance(Box *b, double dt);
/* After the offset dropped by k L_x: img_x += k img_y for each of n particles,
 * so that their unwrapped x (box_image_shift) does not move. */
void box_offset_wrapped(int32_t *img, int n, int k);

/* The x velocity of the Lees-Edwards image of j nearest to i relative to j,
 * for wrapped positions with y_i - y_j = dy: +rate L_y when dy > L_y / 2 (the
 * nearest image is the row above, y_j + L_y), -rate L_y when dy < -L_y / 2,
 * else 0. The one copy of the image velocity (Lees & Edwards 1972): every pair
 * kernel subtracts it from v_i - v_j. */
static inline double box_image_vx(const Box *b, double dy)
{
    if (dy > b->half[1]) return b->shear_rate * b->L[1];
    if (dy < -b->half[1]) return -b->shear_rate * b->L[1];
    return 0.0;
}

/* Minimum-image separation r_i - r_j and, if dvx != NULL, the x velocity of i
 * relative to that image of j (*dvx -= box_image_vx). le = 0 (a constant in the
 * hot loops, which are compiled once per value) leaves out the Lees-Edwards
 * shift: only for boxes without shear, whose offset is 0. */
static inline void box_min_image_le(const Box *b, double d[3], double *dvx, const int le)
{
    /* positions are wrapped into [0, L), so one fold per direction suffices
     * (two in x after a Lees-Edwards shift); no rint(), which is a libm call
     * on baseline x86-64 */
    if (DPD_MODULES && le && dvx) *dvx -= box_image_vx(b, d[1]);
    if (d[1] > b->half[1]) {
        d[1] -= b->L[1];
        if (DPD_MODULES && le) d[0] -= b->le_offset;
    } else if (d[1] < -b->half[1]) {
        d[1] += b->L[1];
        if (DPD_MODULES && le) d[0] += b->le_offset;
    }
    if (d[0] > b->half[0]) { d[0] -= b->L[0]; if (d[0] > b->half[0]) d[0] -= b->L[0]; }
    else if (d[0] < -b->half[0]) { d[0] += b->L[0]; if (d[0] < -b->half[0]) d[0] += b->L[0]; }
    if (b->dim == 3) {
        if (d[2] > b->half[2]) d[2] -= b->L[2];
        else if (d[2] < -b->half[2]) d[2] += b->L[2];
    }
}

static inline void box_min_image(const Box *b, double d[3], double *dvx)
{
    box_min_image_le(b, d, dvx, 1);
}

/* Streaming velocity of the imposed shear at height y. */
static inline double box_stream_vx(const Box *b, double y)
{
    return DPD_MODULES ? b->shear_rate * (y - b->half[1]) : 0.0;
}

/* The displacement from the wrapped to the unwrapped position of a particle
 * with image counters img, and that position: what the measurements of
 * displacements (MSD, centre of mass, colloid centres) use. With shear it is
 * the position in the infinite sheared system (the image j rows up is
 * displaced by j x offset), continuous through the jumps of a y crossing:
 * x + img_x L_x + img_y offset. That needs the offset's wraps through L_x
 * counted in img_x (box_offset_wrapped): the image counter then holds the
 * x shift a particle accumulated at its crossings, in whole L_x (the
 * convention of a sheared triclinic cell of edges (L_x, 0, 0), (offset, L_y, 0),
 * (0, 0, L_z), as the trajectory's box stores it). */
static inline void box_image_shift(const Box *b, const int32_t img[3], double s[3])
{
    for (int d = 0; d < 3; d++) s[d] = img[d] * b->L[d];
    if (MOD_SHEAR(b)) s[0] += img[1] * b->le_offset;
}

static inline void box_unwrap(const Box *b, const double x[3], const int32_t img[3], double u[3])
{
    double s[3];
    box_image_shift(b, img, s);
    for (int d = 0; d < 3; d++) u[d] = x[d] + s[d];
}

/* Wrap one particle into the box; crossing y applies the Lees-Edwards shift
 * to x and to every velocity given. img counts crossings. Returns 1 if the
 * position is not finite (then left as it is: the run must stop), else 0. */
int box_wrap(const Box *b, double x[3], int img[3], double *vx1, double *vx2);
/* The same for a box with (shear) and without (plain) Lees-Edwards shear: the
 * integrator picks one per step, not per particle. */
int box_wrap_shear(const Box *b, double x[3], int img[3], double *vx1, double *vx2);
int box_wrap_plain(const Box *b, double x[3], int img[3], double *vx1, double *vx2);
/* x lies in [0, L) along every axis of the box: box_wrap would leave it as
 * it is (the integrator calls box_wrap only for the few that left) */
static inline int box_inside(const Box *b, const double x[3])
{
    return x[0] >= 0.0 && x[0] < b->L[0] && x[1] >= 0.0 && x[1] < b->L[1]
        && (b->dim < 3 || (x[2] >= 0.0 && x[2] < b->L[2]));
}

#endif
