/* colloid.c - spring-model colloids (Mai-Duy et al. 2019, eq. 30). See colloid.h. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "colloid.h"
#include "forces.h"

/* v' = R(q) v for a unit quaternion q = (w, x, y, z) */
static void rotate(const double q[4], const double v[3], double out[3])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    /* t = 2 (q_vec x v); v' = v + w t + q_vec x t */
    const double t[3] = {2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])};
    out[0] = v[0] + w * t[0] + (y * t[2] - z * t[1]);
    out[1] = v[1] + w * t[1] + (z * t[0] - x * t[2]);
    out[2] = v[2] + w * t[2] + (x * t[1] - y * t[0]);
}

Colloids *colloid_new(const ColloidParams *p)
{
    Colloids *c = calloc(1, sizeof *c);
    if (!c) return NULL;
    c->p = *p;
    c->ncol = p->per_axis * p->per_axis * p->per_axis;
    /* octahedron: +-x, +-y, +-z */
    static const double OCT[COLLOID_P][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int k = 0; k < COLLOID_P; k++)
        for (int d = 0; d < 3; d++) c->body[k][d] = p->d * OCT[k][d];
    const size_t nc = (size_t)c->ncol;
    c->R = calloc(3 * nc, sizeof(double)); c->V = calloc(3 * nc, sizeof(double));
    c->q = calloc(4 * nc, sizeof(double)); c->L = calloc(3 * nc, sizeof(double));
    c->F = calloc(3 * nc, sizeof(double)); c->T = calloc(3 * nc, sizeof(double));
    c->ids = calloc(nc * COLLOID_P, sizeof(uint32_t));
    if (!c->R || !c->V || !c->q || !c->L || !c->F || !c->T || !c->ids) {
        colloid_free(c);
        return NULL;
    }
    return c;
}

void colloid_free(Colloids *c)
{
    if (!c) return;
    free(c->R); free(c->V); free(c->q); free(c->L); free(c->F); free(c->T); free(c->ids); free(c->index);
    series_free(&c->ext2);
    free(c);
}

void colloid_io(Io *io, Colloids *c)
{
    const size_t nc = (size_t)c->ncol;
    io_array(io, c->R, 3 * nc, sizeof(double), "colloid body centres");
    io_array(io, c->V, 3 * nc, sizeof(double), "colloid body velocities");
    io_array(io, c->q, 4 * nc, sizeof(double), "colloid body quaternions");
    io_array(io, c->L, 3 * nc, sizeof(double), "colloid body angular momenta");
    io_array(io, c->F, 3 * nc, sizeof(double), "colloid body forces");
    io_array(io, c->T, 3 * nc, sizeof(double), "colloid body torques");
    io_series(io, &c->ext2, "colloid spring extension");
    io_bytes(io, &c->nsteps, sizeof c->nsteps, "colloid steps");
}

void colloid_site(const Colloids *c, int b, int k, const Box *box, double out[3])
{
    double r[3];
    int img[3] = {0, 0, 0};
    rotate(c->q + 4 * b, c->body[k], r);
    for (int d = 0; d < 3; d++) out[d] = c->R[3 * b + d] + r[d];
    box_wrap(box, out, img, NULL, NULL);   /* a site across y: the Lees-Edwards shift in x */
}

int colloid_place(Colloids *c, System *s)
{
    c->index = calloc((size_t)s->n + 1, sizeof(int));
    c->nparticles = s->n;
    if (!c->index) return -1;
    const int k = c->p.per_axis;
    for (int b = 0; b < c->ncol; b++) {
        const int ix = b % k, iy = (b / k) % k, iz = b / (k * k);
        const int ia[3] = {ix, iy, iz};
        for (int d = 0; d < 3; d++) c->R[3 * b + d] = (ia[d] + 0.5) * s->box.L[d] / k;
        c->q[4 * b] = 1.0;
        /* under shear the body starts with the flow: the streaming velocity at
         * its centre and the flow's spin, omega_z = -rate / 2 */
        c->V[3 * b] = box_stream_vx(&s->box, c->R[3 * b + 1]);
        c->L[3 * b + 2] = -0.5 * s->box.shear_rate * c->p.inertia;
    }
    /* the particles of the colloid type, in array order at set-up, fill the sites */
    int j = 0;
    for (int i = 0; i < s->n; i++) {
        if (s->type[i] != c->p.type) continue;
        const int b = j / COLLOID_P, site = j % COLLOID_P;
        c->ids[j] = s->id[i];
        colloid_site(c, b, site, &s->box, s->x + 3 * i);   /* velocities (with the flow) are drawn after */
        j++;
    }
    return 0;
}

void colloid_body_advance(Colloids *c, int b, const double F[3], const double T[3], double dt, const Box *box)
{
    double *R = c->R + 3 * b, *V = c->V + 3 * b, *q = c->q + 4 * b, *L = c->L + 3 * b;
    /* Newton: symplectic Euler for the centre */
    (void)box;
    for (int d = 0; d < 3; d++) {
        V[d] += dt * F[d] / c->p.mass;
        R[d] += dt * V[d];   /* wrapped by colloid_step, with the offset of the time R belongs to */
    }
    /* Euler, isotropic inertia: dL/dt = T, omega = L / I; the orientation turns
     * by the exact rotation of angle |omega| dt about omega */
    double w[3], wn = 0.0;
    for (int d = 0; d < 3; d++) { L[d] += dt * T[d]; w[d] = L[d] / c->p.inertia; wn += w[d] * w[d]; }
    wn = sqrt(wn);
    if (wn * dt > 1e-300) {
        const double h = 0.5 * wn * dt, sh = sin(h) / wn;
        const double r[4] = {cos(h), w[0] * sh, w[1] * sh, w[2] * sh};
        const double p[4] = {q[0], q[1], q[2], q[3]};
        /* q <- r (x) q */
        q[0] = r[0] * p[0] - r[1] * p[1] - r[2] * p[2] - r[3] * p[3];
        q[1] = r[0] * p[1] + r[1] * p[0] + r[2] * p[3] - r[3] * p[2];
        q[2] = r[0] * p[2] - r[1] * p[3] + r[2] * p[0] + r[3] * p[1];
        q[3] = r[0] * p[3] + r[1] * p[2] - r[2] * p[1] + r[3] * p[0];
        const double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (int a = 0; a < 4; a++) q[a] /= n;
    }
}

void colloid_step(Colloids *c, System *s, PairVirial *pv)
{
    for (int i = 0; i < s->n; i++) c->index[s->id[i]] = i;
    /* the centres moved last step belong to this step: wrap them now, with this
     * step's Lees-Edwards offset (the shift of x and of V_x across y) */
    for (int b = 0; b < c->ncol; b++) {
        int img[3] = {0, 0, 0};
        box_wrap(&s->box, c->R + 3 * b, img, &c->V[3 * b], NULL);
    }
    double ext2 = 0.0;
    for (int b = 0; b < c->ncol; b++) {
        double *F = c->F + 3 * b, *T = c->T + 3 * b;
        const double *R = c->R + 3 * b;
        for (int d = 0; d < 3; d++) F[d] = T[d] = 0.0;
        for (int k = 0; k < COLLOID_P; k++) {
            const int i = c->index[c->ids[b * COLLOID_P + k]];
            double arm[3], dr[3], fs[3];
            rotate(c->q + 4 * b, c->body[k], arm);
            /* r_i - r_bar_i, minimum image (Lees-Edwards aware): the site R + arm
             * need not be wrapped */
            for (int d = 0; d < 3; d++) dr[d] = s->x[3 * i + d] - (R[d] + arm[d]);
            box_min_image(&s->box, dr, NULL);
            for (int d = 0; d < 3; d++) {
                fs[d] = -c->p.H * dr[d];               /* eq. 30: F_S = -H (r_i - r_bar_i) */
                s->f[3 * i + d] += fs[d];
                F[d] -= fs[d];                       /* reaction on the reference body */
            }
            /* torque of the reaction about the centre: arm x (H dr) */
            T[0] += c->p.H * (arm[1] * dr[2] - arm[2] * dr[1]);
            T[1] += c->p.H * (arm[2] * dr[0] - arm[0] * dr[2]);
            T[2] += c->p.H * (arm[0] * dr[1] - arm[1] * dr[0]);
            ext2 += dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2];
            if (!pv) continue;
            /* Spring virial. The body carries its momentum at its centre R, so the
             * momentum a spring passes from particle i to body b travels from R to
             * r_i: the pair (i, b) adds (r_i - R) F_S = (dr + arm) F_S (the
             * molecular virial of the body; the site form dr F_S alone misses the
             * stresslet arm F_S). With sum_b M V'V' in the kinetic part, d/dt of
             * sum m r v + sum M R V is exactly (kinetic + virial) V, so the mean
             * stress is the momentum flux (tests/test_colloid.c). */
            double t[9];
            for (int a = 0; a < 3; a++)
                for (int e = 0; e < 3; e++) t[3 * a + e] = (dr[a] + arm[a]) * fs[e];
            for (int q = 0; q < 9; q++) pv->W[PART_CONSERVATIVE][q / 3][q % 3] += t[q];
            pv->epot += 0.5 * c->p.H * (dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]);
            if (pv->nbins > 0)
                ik_distribute(pv->Wbin + (size_t)PART_CONSERVATIVE * 9 * pv->nbins, pv->nbins, pv->bin_axis,
                              s->box.L[pv->bin_axis], s->x[3 * i + pv->bin_axis], dr[pv->bin_axis] + arm[pv->bin_axis], t);
        }
    }
    if (c->record && c->nsteps++ % 10 == 0) series_push(&c->ext2, ext2 / (c->ncol * COLLOID_P));
    /* the sites of the next step, from this step's reactions */
    for (int b = 0; b < c->ncol; b++) colloid_body_advance(c, b, c->F + 3 * b, c->T + 3 * b, s->dt, &s->box);
}

void colloid_kinetic(const Colloids *c, const Box *box, double K[9])
{
    for (int b = 0; b < c->ncol; b++) {
        const double *V = c->V + 3 * b;
        const double u[3] = {V[0] - box_stream_vx(box, c->R[3 * b + 1]), V[1], V[2]};
        for (int a = 0; a < 3; a++)
            for (int e = 0; e < 3; e++) K[3 * a + e] += c->p.mass * u[a] * u[e];
    }
}

void colloid_write(const Colloids *c, const System *s, FILE *summary, int nblocks)
{
    double v, se;
    series_stats(&c->ext2, nblocks, &v, &se);
    fprintf(summary, "colloids\t%d\t0\n", c->ncol);
    fprintf(summary, "colloid_spring_extension_rms\t%.10g\t%.4g\n", sqrt(v), v > 0 ? 0.5 * se / sqrt(v) : NAN);
    /* a particle on a spring to a fixed site: <|r - r_bar|^2> = 3 kBT / H */
    fprintf(summary, "colloid_spring_extension_rms_equipartition\t%.10g\t0\n", sqrt(3.0 * s->kBT / c->p.H));
}
