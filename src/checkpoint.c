/* checkpoint.c - save and restore the state of a run (see checkpoint.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <fcntl.h>
#include <unistd.h>
#include "checkpoint.h"
#include "bonds.h"
#include "colloid.h"

static const char MAGIC[8] = {'D', 'P', 'D', 'C', 'K', 'P', 'T', '\n'};
/* Version 2 appends the state of rotation scenes, 3D spring colloids, the
 * TCAF and the trajectory segments after the version 1 layout, each only for
 * a scene that has it: for any other scene the two layouts are the same
 * byte for byte, so a version 1 checkpoint of such a scene is still read.
 * Version 3 keeps the MSD curves per group of particles (their errors come
 * from the groups): a version 1 or 2 checkpoint of an MSD scene is refused.
 * Version 4 appends the m = 0 solver's CPU time per step: an older checkpoint
 * of an m = 0 scene is refused (its resume would lose those samples). In a
 * sheared box its x image counters also count the wraps of the Lees-Edwards
 * offset (box_offset_wrapped), which older ones did not: a version 1 to 3
 * checkpoint of a sheared scene is refused (its unwrapped positions would jump
 * where it resumed), and so is one of a scene with a trajectory (its segment
 * files have no box edges per frame, which run.h5's trajectory now has). */
#define CHECKPOINT_VERSION 4u
#define CHECKPOINT_VERSION_OLDEST 1u

uint64_t checkpoint_hash(const void *data, size_t len, uint64_t h)
{
    const unsigned char *p = data;
    if (h == 0) h = 1469598103934665603ULL;
    for (size_t k = 0; k < len; k++) { h ^= p[k]; h *= 1099511628211ULL; }
    return h;
}

/* One traversal of the state, writing or reading: the two cannot drift apart. */
typedef struct {
    int reading;
    FILE *out;
    const unsigned char *in;
    size_t len, pos;
    int bad;
    const char *what;         /* first field that did not fit */
} Io;

static void io_bytes(Io *io, void *p, size_t len, const char *what)
{
    if (io->bad || len == 0) return;
    if (!io->reading) {
        if (fwrite(p, 1, len, io->out) != len) { io->bad = 1; io->what = what; }
        return;
    }
    if (len > io->len - io->pos) { io->bad = 1; io->what = what; return; }
    memcpy(p, io->in + io->pos, len);
    io->pos += len;
}

/* An array whose length the scene fixes: the stored length must match. */
static void io_array(Io *io, void *p, size_t count, size_t size, const char *what)
{
    uint64_t c = count;
    io_bytes(io, &c, sizeof c, what);
    if (io->bad) return;
    if (c != count) { io->bad = 1; io->what = what; return; }
    io_bytes(io, p, count * size, what);
}

static void io_series(Io *io, Series *s, const char *what)
{
    uint64_t n = s->n;
    io_bytes(io, &n, sizeof n, what);
    if (io->bad) return;
    if (io->reading) {
        if (n > (io->len - io->pos) / sizeof(double)) { io->bad = 1; io->what = what; return; }
        series_free(s);
        if (n > 0) {
            s->v = malloc((size_t)n * sizeof(double));
            if (!s->v) { io->bad = 1; io->what = what; return; }
            s->n = s->cap = (size_t)n;
        }
    }
    io_bytes(io, s->v, (size_t)n * sizeof(double), what);
}

static void io_state(Io *io, System *s, NeighborList *nl, Measure *m, CheckpointExtra *x)
{
    const size_t n = (size_t)s->n;
    /* system */
    io_bytes(io, &s->step, sizeof s->step, "step");
    io_bytes(io, &s->time, sizeof s->time, "time");
    io_bytes(io, &s->box.le_offset, sizeof s->box.le_offset, "Lees-Edwards offset");
    io_array(io, s->x, 3 * n, sizeof(double), "x");
    io_array(io, s->v, 3 * n, sizeof(double), "v");
    io_array(io, s->f, 3 * n, sizeof(double), "f");
    io_array(io, s->v_pred, 3 * n, sizeof(double), "v_pred");
    io_array(io, s->img, 3 * n, sizeof(int32_t), "img");
    io_array(io, s->id, n, sizeof(uint32_t), "id");
    io_array(io, s->type, n, sizeof(uint8_t), "type");
    /* neighbour list as built */
    int64_t builds = nl->builds;
    io_bytes(io, &builds, sizeof builds, "neighbor builds");
    nl->builds = (long)builds;
    io_bytes(io, &nl->offset_moved, sizeof nl->offset_moved, "neighbor offset");
    io_array(io, nl->start, n + 1, sizeof(int), "neighbor start");
    io_array(io, nl->x_ref, 3 * n, sizeof(double), "neighbor x_ref");
    io_array(io, nl->img_ref, n, sizeof(int), "neighbor img_ref");
    uint64_t npairs = io->bad ? 0 : (uint64_t)nl->start[n];
    io_bytes(io, &npairs, sizeof npairs, "neighbor pairs");
    if (io->bad) return;
    if (io->reading) {
        if (nl->start[0] != 0 || npairs != (uint64_t)nl->start[n] || npairs > (io->len - io->pos) / sizeof(int)) {
            io->bad = 1; io->what = "neighbor pairs"; return;
        }
        if (npairs + 1 > nl->cap) {
            int *p = realloc(nl->nbr, ((size_t)npairs + 1) * sizeof(int));
            if (!p) { io->bad = 1; io->what = "neighbor pairs"; return; }
            nl->nbr = p;
            nl->cap = (size_t)npairs + 1;
        }
    }
    io_bytes(io, nl->nbr, (size_t)npairs * sizeof(int), "neighbor list");
    if (io->reading && !io->bad)
        for (size_t i = 0; i < n; i++)
            if (nl->start[i + 1] < nl->start[i]) { io->bad = 1; io->what = "neighbor start"; return; }
    if (io->reading && !io->bad)
        for (uint64_t k = 0; k < npairs; k++)
            if (nl->nbr[k] < 0 || nl->nbr[k] >= s->n) { io->bad = 1; io->what = "neighbor list"; return; }
    /* measurements */
    io_series(io, &m->temperature, "temperature");
    io_series(io, &m->pressure, "pressure");
    io_series(io, &m->epot, "epot");
    for (int p = 0; p < STRESS_PARTS; p++)
        for (int k = 0; k < 9; k++) io_series(io, &m->P[p][k], "pressure tensor");
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++) io_series(io, &m->frozen_force[t][d], "frozen force");
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
    if (m->prof_on && m->prof_tsum)
        io_array(io, m->prof_tsum, (size_t)m->nblocks, sizeof(double), "profile times");
    if (m->com_on) {
        for (int d = 0; d < 3; d++) {
            io_series(io, &m->com_v[d], "centre-of-mass velocity");
            io_series(io, &m->com_r[d], "centre-of-mass position");
        }
        io_bytes(io, m->com_r0, sizeof m->com_r0, "centre-of-mass start");
    }
    FieldMeasure *fm = &m->field;
    for (int t = 0; t < DPD_MAX_TYPES; t++)
        for (int d = 0; d < 3; d++) {
            io_series(io, &fm->mean_v[t][d], "mean velocity");
            io_series(io, &fm->torque[t][d], "body torque");
        }
    if (fm->p.around.on) {
        io_array(io, fm->around_hist, (size_t)fm->nblocks * fm->p.around.bins, sizeof(double), "around");
        io_array(io, fm->around_samples, (size_t)fm->nblocks, sizeof(long long), "around samples");
    }
    if (fm->p.map_on) {
        io_array(io, fm->map_hist, 3 * (size_t)fm->p.map_bins[0] * fm->p.map_bins[1], sizeof(double), "density map");
        io_bytes(io, &fm->map_samples, sizeof fm->map_samples, "density map samples");
    }
    /* run loop */
    io_array(io, x->timers, (size_t)x->ntimers, sizeof(double), "timers");
    io_bytes(io, &x->cpu_used, sizeof x->cpu_used, "cpu time");
    io_bytes(io, &x->wall_used, sizeof x->wall_used, "wall time");
    io_bytes(io, &x->prod_wall_used, sizeof x->prod_wall_used, "production wall time");
    io_bytes(io, &x->steps_done, sizeof x->steps_done, "steps done");
    for (int k = 0; k < x->nsolver; k++) io_series(io, x->solver[k], "solver statistics");
    io_bytes(io, x->unconverged, sizeof *x->unconverged, "solver unconverged");
    if (x->bonds) {   /* 2D spring colloids: centre trajectory and histograms */
        Bonds *b = x->bonds;
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
    /* version 2 from here */
    if (s->rotation) {   /* spins, their Groot-Warren prediction, the torques of the step */
        io_array(io, s->omega, 3 * n, sizeof(double), "angular velocity");
        io_array(io, s->omega_pred, 3 * n, sizeof(double), "predicted angular velocity");
        io_array(io, s->torque, 3 * n, sizeof(double), "torque");
        io_series(io, &m->rot_temperature, "rotational temperature");
        for (int t = 0; t < DPD_MAX_TYPES; t++)
            for (int d = 0; d < 3; d++) {
                io_series(io, &m->frozen_torque[t][d], "frozen torque");
                io_series(io, &m->frozen_drag[t][d], "frozen drag");
                io_series(io, &m->frozen_torque_random[t][d], "frozen random torque");
            }
    }
    if (x->colloids) {   /* 3D spring colloids: the rigid reference bodies */
        Colloids *c = x->colloids;
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
    if (m->tcaf.on) {   /* time origins in flight, their running sums, the block sums */
        Tcaf *t = &m->tcaf;
        io_array(io, t->origin, (size_t)t->nslots * t->nvec * 3, sizeof(double complex), "tcaf origins");
        io_array(io, t->origin_step, (size_t)t->nslots, sizeof(long long), "tcaf origin steps");
        io_array(io, t->origin_index, (size_t)t->nslots, sizeof(long long), "tcaf origin indices");
        io_array(io, t->curve, (size_t)t->nslots * t->nshell * t->nlags, sizeof(double), "tcaf curves");
        io_array(io, t->acc, (size_t)t->nblocks * t->nshell * t->nlags, sizeof(double), "tcaf blocks");
        io_array(io, t->acc_n, (size_t)t->nblocks, sizeof(long long), "tcaf block origins");
        io_bytes(io, &t->nstarted, sizeof t->nstarted, "tcaf origins started");
        io_bytes(io, &t->ndone, sizeof t->ndone, "tcaf origins done");
        int32_t threads = x->threads;
        io_bytes(io, &threads, sizeof threads, "threads");
        x->threads = threads;
    }
    if (x->trajectory) {   /* the trajectory segment files complete at this checkpoint */
        int32_t seg = x->trajectory_segments;
        int64_t frames = x->trajectory_frames;
        io_bytes(io, &seg, sizeof seg, "trajectory segments");
        io_bytes(io, &frames, sizeof frames, "trajectory frames");
        if (io->reading && !io->bad && (seg < 0 || frames < 0)) { io->bad = 1; io->what = "trajectory segments"; }
        x->trajectory_segments = seg;
        x->trajectory_frames = frames;
    }
    /* version 4 from here */
    if (x->solver_cpu) io_series(io, x->solver_cpu, "solver cpu time");
}

/* Does the scene have state that only version 2 stores? */
static int needs_version2(const System *s, const Measure *m, const CheckpointExtra *x)
{
    return s->rotation || x->colloids || m->tcaf.on || x->trajectory;
}

static void header(Io *io, uint64_t *hash, uint32_t *version, uint32_t *n, char magic[8])
{
    io_bytes(io, magic, 8, "magic");
    io_bytes(io, version, sizeof *version, "version");
    io_bytes(io, hash, sizeof *hash, "scene hash");
    io_bytes(io, n, sizeof *n, "particle count");
}

int checkpoint_write(const char *dir, uint64_t scene_hash, const System *s, const NeighborList *nl,
                     const Measure *m, const CheckpointExtra *x, char *err, size_t errlen)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&buf, &len);
    if (!mem) { snprintf(err, errlen, "out of memory for the checkpoint"); return -1; }
    Io io = {.reading = 0, .out = mem};
    uint64_t h = scene_hash;
    uint32_t version = CHECKPOINT_VERSION, n = (uint32_t)s->n;
    char magic[8];
    memcpy(magic, MAGIC, 8);
    header(&io, &h, &version, &n, magic);
    /* the traversal only reads through these pointers when writing */
    io_state(&io, (System *)s, (NeighborList *)nl, (Measure *)m, (CheckpointExtra *)x);
    if (fclose(mem) || io.bad) { free(buf); snprintf(err, errlen, "out of memory for the checkpoint"); return -1; }
    const uint64_t sum = checkpoint_hash(buf, len, 0);
    char path[1100], tmp[1100];
    snprintf(path, sizeof path, "%s/%s", dir, CHECKPOINT_FILE);
    snprintf(tmp, sizeof tmp, "%s/.%s.part", dir, CHECKPOINT_FILE);
    FILE *f = fopen(tmp, "wb");
    int bad = !f;
    if (f) {
        bad |= fwrite(buf, 1, len, f) != len;
        bad |= fwrite(&sum, sizeof sum, 1, f) != 1;
        bad |= fflush(f) != 0;
        bad |= fsync(fileno(f)) != 0;
        bad |= fclose(f) != 0;
    }
    const int e = errno;
    free(buf);
    if (bad || rename(tmp, path)) {
        snprintf(err, errlen, "cannot write the checkpoint %s: %s", path, strerror(bad ? e : errno));
        unlink(tmp);
        return -1;
    }
    int dfd = open(dir, O_RDONLY | O_DIRECTORY);   /* make the rename itself durable */
    if (dfd >= 0) { fsync(dfd); close(dfd); }
    return 0;
}

int checkpoint_read(const char *dir, uint64_t scene_hash, System *s, NeighborList *nl,
                    Measure *m, CheckpointExtra *x, char *err, size_t errlen)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/%s", dir, CHECKPOINT_FILE);
    FILE *f = fopen(path, "rb");
    if (!f) {
        if (errno == ENOENT) return 1;
        snprintf(err, errlen, "cannot open the checkpoint %s: %s", path, strerror(errno));
        return -1;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&buf, &len);
    if (!mem) { fclose(f); snprintf(err, errlen, "out of memory reading %s", path); return -1; }
    char chunk[65536];
    size_t got;
    while ((got = fread(chunk, 1, sizeof chunk, f)) > 0) fwrite(chunk, 1, got, mem);
    const int rerr = ferror(f);
    fclose(f);
    if (fclose(mem) || rerr) { free(buf); snprintf(err, errlen, "cannot read the checkpoint %s", path); return -1; }
    uint64_t sum;
    if (len < sizeof sum + 8) {
        free(buf);
        snprintf(err, errlen, "checkpoint %s is truncated (%zu bytes)", path, len);
        return -1;
    }
    memcpy(&sum, buf + len - sizeof sum, sizeof sum);
    len -= sizeof sum;
    if (checkpoint_hash(buf, len, 0) != sum) {
        free(buf);
        snprintf(err, errlen, "checkpoint %s is corrupt (checksum mismatch); delete it to start afresh", path);
        return -1;
    }
    Io io = {.reading = 1, .in = (const unsigned char *)buf, .len = len};
    uint64_t h = 0;
    uint32_t version = 0, n = 0;
    char magic[8] = {0};
    header(&io, &h, &version, &n, magic);
    int rc = 0;
    if (io.bad || memcmp(magic, MAGIC, 8)) {
        snprintf(err, errlen, "%s is not a dpd checkpoint", path);
        rc = -1;
    } else if (version < CHECKPOINT_VERSION_OLDEST || version > CHECKPOINT_VERSION
               || (version < 2 && needs_version2(s, m, x)) || (version < 3 && m->msd_on)
               || (version < 4 && (x->solver_cpu || s->box.shear_rate != 0.0 || x->trajectory))) {
        snprintf(err, errlen, "checkpoint %s has format version %u, which this dpd (format %u) cannot resume "
                 "for this scene; delete it to start afresh", path, version, CHECKPOINT_VERSION);
        rc = -1;
    } else if (h != scene_hash || n != (uint32_t)s->n) {
        snprintf(err, errlen, "checkpoint %s was written for another scene (or other --set values): "
                 "scene hash %016llx, this run %016llx; delete it or run the original scene",
                 path, (unsigned long long)h, (unsigned long long)scene_hash);
        rc = -1;
    } else {
        io_state(&io, s, nl, m, x);
        if (io.bad || io.pos != io.len) {
            snprintf(err, errlen, "checkpoint %s does not match this run (at '%s')", path,
                     io.what ? io.what : "end of file");
            rc = -1;
        }
    }
    free(buf);
    return rc;
}

double *checkpoint_final_state(const System *s)
{
    double *t = malloc((size_t)s->n * 10 * sizeof(double) + 1);
    if (!t) return NULL;
    for (int i = 0; i < s->n; i++) {
        double *r = t + 10 * (size_t)s->id[i];
        r[0] = s->id[i];
        for (int d = 0; d < 3; d++) {
            r[1 + d] = s->x[3 * i + d];
            r[4 + d] = s->img[3 * i + d];
            r[7 + d] = s->v[3 * i + d];
        }
    }
    return t;
}
