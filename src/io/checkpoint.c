/* checkpoint.c - save and restore the state of a run (see checkpoint.h).
 * The modules write and read their own state (measure_io, field_io, tcaf_io,
 * colloid_io, bonds_io; io.h); io_state fixes the order of the format. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/stat.h>
#include "checkpoint.h"
#include "io.h"
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
 * files have no box edges per frame, which run.h5's trajectory now has).
 * Version 5 appends the checksum of each trajectory segment file, which the
 * resume and the final assembly verify: an older checkpoint of a scene with a
 * trajectory is refused (its segments could not be verified); for any other
 * scene versions 4 and 5 are the same byte for byte. */
#define CHECKPOINT_VERSION 5u
#define CHECKPOINT_VERSION_OLDEST 1u

uint64_t checkpoint_hash(const void *data, size_t len, uint64_t h)
{
    return io_fnv1a(data, len, h ? h : IO_FNV_BASIS);
}

/* step, time, the Lees-Edwards offset and the particles in their current order */
static void system_io(Io *io, System *s)
{
    const size_t n = (size_t)s->n;
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
}

/* The pair list as built: a read one is checked (a checksum does not vouch
 * for indices that the force loop follows). */
static void neighbor_io(Io *io, NeighborList *nl, int np)
{
    const size_t n = (size_t)np;
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
            io_fail(io, "neighbor pairs");
            return;
        }
        if (npairs + 1 > nl->cap) {
            int *p = realloc(nl->nbr, ((size_t)npairs + 1) * sizeof(int));
            if (!p) { io_fail(io, "neighbor pairs"); return; }
            nl->nbr = p;
            nl->cap = (size_t)npairs + 1;
        }
    }
    io_bytes(io, nl->nbr, (size_t)npairs * sizeof(int), "neighbor list");
    if (!io->reading || io->bad) return;
    for (size_t i = 0; i < n; i++)
        if (nl->start[i + 1] < nl->start[i]) { io_fail(io, "neighbor start"); return; }
    for (uint64_t k = 0; k < npairs; k++)
        if (nl->nbr[k] < 0 || nl->nbr[k] >= np) { io_fail(io, "neighbor list"); return; }
}

/* timers, CPU and wall time so far, the m = 0 solver's statistics */
static void run_loop_io(Io *io, CheckpointExtra *x)
{
    io_array(io, x->timers, (size_t)x->ntimers, sizeof(double), "timers");
    io_bytes(io, &x->cpu_used, sizeof x->cpu_used, "cpu time");
    io_bytes(io, &x->wall_used, sizeof x->wall_used, "wall time");
    io_bytes(io, &x->prod_wall_used, sizeof x->prod_wall_used, "production wall time");
    io_bytes(io, &x->steps_done, sizeof x->steps_done, "steps done");
    for (int k = 0; k < x->nsolver; k++) io_series(io, x->solver[k], "solver statistics");
    io_bytes(io, x->unconverged, sizeof *x->unconverged, "solver unconverged");
}

/* spins, their Groot-Warren prediction, the torques of the step */
static void rotation_io(Io *io, System *s)
{
    const size_t n = (size_t)s->n;
    io_array(io, s->omega, 3 * n, sizeof(double), "angular velocity");
    io_array(io, s->omega_pred, 3 * n, sizeof(double), "predicted angular velocity");
    io_array(io, s->torque, 3 * n, sizeof(double), "torque");
}

/* the trajectory segment files complete at this checkpoint */
static void trajectory_io(Io *io, CheckpointExtra *x)
{
    int32_t seg = x->trajectory_segments;
    int64_t frames = x->trajectory_frames;
    io_bytes(io, &seg, sizeof seg, "trajectory segments");
    io_bytes(io, &frames, sizeof frames, "trajectory frames");
    if (io->reading && !io->bad && (seg < 0 || frames < 0)) io_fail(io, "trajectory segments");
    x->trajectory_segments = seg;
    x->trajectory_frames = frames;
}

/* the checksums of the trajectory segment files complete at this checkpoint */
static void trajectory_sums_io(Io *io, CheckpointExtra *x)
{
    const size_t n = x->trajectory_segments > 0 ? (size_t)x->trajectory_segments : 0;
    if (io->reading && !io->bad) {
        free(x->trajectory_sums);
        x->trajectory_sums = NULL;
        if (n > (io->len - io->pos) / sizeof(uint64_t)) { io_fail(io, "trajectory checksums"); return; }
        x->trajectory_sums = malloc(n * sizeof(uint64_t) + 1);
        if (!x->trajectory_sums) { io_fail(io, "trajectory checksums"); return; }
    }
    io_array(io, x->trajectory_sums, n, sizeof(uint64_t), "trajectory checksums");
}

/* The whole state in the order of the format: version 1, then what versions
 * 2 and 4 appended (each part only for a scene that has it). */
static void io_state(Io *io, System *s, NeighborList *nl, Measure *m, CheckpointExtra *x)
{
    system_io(io, s);
    neighbor_io(io, nl, s->n);
    measure_io(io, m);
    run_loop_io(io, x);
    if (x->bonds) bonds_io(io, x->bonds);   /* 2D spring colloids */
    /* version 2 from here */
    if (s->rotation) {
        rotation_io(io, s);
        measure_rotation_io(io, m);
    }
    if (x->colloids) colloid_io(io, x->colloids);   /* 3D spring colloids' rigid bodies */
    if (m->tcaf.on) {
        tcaf_io(io, &m->tcaf);
        int32_t threads = x->threads;   /* the TCAF current is summed per thread */
        io_bytes(io, &threads, sizeof threads, "threads");
        x->threads = threads;
    }
    if (x->trajectory) trajectory_io(io, x);
    /* version 4 from here */
    if (x->solver_cpu) io_series(io, x->solver_cpu, "solver cpu time");
    /* version 5 from here */
    if (x->trajectory) trajectory_sums_io(io, x);
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
    char path[1100], tmp[1100];
    snprintf(path, sizeof path, "%s/%s", dir, CHECKPOINT_FILE);
    snprintf(tmp, sizeof tmp, "%s/.%s.part", dir, CHECKPOINT_FILE);
    /* written straight to the file, its checksum summed on the way: a run's
     * series are held once, not copied into a buffer every checkpoint */
    FILE *f = fopen(tmp, "wb");
    int bad = !f;
    if (f) {
        Io io = {.reading = 0, .out = f, .sum = IO_FNV_BASIS};
        uint64_t h = scene_hash;
        uint32_t version = CHECKPOINT_VERSION, n = (uint32_t)s->n;
        char magic[8];
        memcpy(magic, MAGIC, 8);
        header(&io, &h, &version, &n, magic);
        /* the traversal only reads through these pointers when writing */
        io_state(&io, (System *)s, (NeighborList *)nl, (Measure *)m, (CheckpointExtra *)x);
        const uint64_t sum = io.sum;
        bad |= io.bad;
        bad |= fwrite(&sum, sizeof sum, 1, f) != 1;
        bad |= fflush(f) != 0;
        bad |= fsync(fileno(f)) != 0;
        bad |= fclose(f) != 0;
    }
    const int e = errno;
    if (bad || rename(tmp, path)) {
        snprintf(err, errlen, "cannot write the checkpoint %s: %s", path, strerror(bad ? e : errno));
        unlink(tmp);
        return -1;
    }
    int dfd = open(dir, O_RDONLY | O_DIRECTORY);   /* make the rename itself durable */
    if (dfd >= 0) { fsync(dfd); close(dfd); }
    return 0;
}

/* The content of the checkpoint file at path, its checksum verified and stripped: 0 (*buf malloc'd,
 * *len its bytes), 1 (no such file) or -1 with err set. The file is read once, in chunks: the
 * content is held once, and with keep < its length only its first keep bytes are
 * (checkpoint_info: the header of a checkpoint of any size), all of it summed. */
static int read_verified(const char *path, size_t keep, char **buf, size_t *len, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        if (errno == ENOENT) return 1;
        snprintf(err, errlen, "cannot open the checkpoint %s: %s", path, strerror(errno));
        return -1;
    }
    *buf = NULL;
    struct stat st;
    if (fstat(fileno(f), &st) != 0) {
        fclose(f);
        snprintf(err, errlen, "cannot read the checkpoint %s: %s", path, strerror(errno));
        return -1;
    }
    const size_t total = st.st_size > 0 ? (size_t)st.st_size : 0;
    uint64_t sum = 0;
    char magic[8] = {0};
    if (total < 8 || fread(magic, 1, 8, f) != 8 || memcmp(magic, MAGIC, 8)) {   /* another file: no advice to delete it */
        fclose(f);
        snprintf(err, errlen, "%s is not a dpd checkpoint", path);
        return -1;
    }
    if (total < sizeof sum + 8) {
        fclose(f);
        snprintf(err, errlen, "checkpoint %s is truncated (%zu bytes)", path, total);
        return -1;
    }
    /* one pass: the content summed in chunks, its first *len bytes kept as they go by (so the
     * bytes kept are the bytes summed), then the stored sum after it */
    const size_t content = total - sizeof sum;
    *len = keep < content ? keep : content;
    *buf = malloc(*len ? *len : 1);
    if (!*buf) { fclose(f); snprintf(err, errlen, "out of memory reading %s", path); return -1; }
    memcpy(*buf, magic, *len < 8 ? *len : 8);
    uint64_t h = io_fnv1a(magic, 8, IO_FNV_BASIS);
    unsigned char chunk[65536];
    size_t pos = 8;
    int rerr = 0;
    while (pos < content && !rerr) {
        const size_t want = content - pos < sizeof chunk ? content - pos : sizeof chunk;
        rerr = fread(chunk, 1, want, f) != want;
        h = io_fnv1a(chunk, want, h);
        if (pos < *len) memcpy(*buf + pos, chunk, *len - pos < want ? *len - pos : want);
        pos += want;
    }
    rerr = rerr || fread(&sum, sizeof sum, 1, f) != 1;
    fclose(f);
    if (rerr) {
        free(*buf);
        snprintf(err, errlen, "cannot read the checkpoint %s", path);
        return -1;
    }
    if (h != sum) {
        free(*buf);
        snprintf(err, errlen, "checkpoint %s is corrupt (checksum mismatch); delete it to start afresh", path);
        return -1;
    }
    return 0;
}

int checkpoint_info(const char *path, CheckpointInfo *ci, char *err, size_t errlen)
{
    char *buf;
    size_t len;
    const int got = read_verified(path, 64, &buf, &len, err, errlen);   /* header, step and time */
    if (got == 1) snprintf(err, errlen, "no checkpoint %s", path);
    if (got) return -1;
    Io io = {.reading = 1, .in = (const unsigned char *)buf, .len = len};
    uint64_t h = 0;
    char magic[8] = {0};
    header(&io, &h, &ci->version, &ci->particles, magic);
    io_bytes(&io, &ci->step, sizeof ci->step, "step");   /* system_io's first two fields */
    io_bytes(&io, &ci->time, sizeof ci->time, "time");
    free(buf);
    if (io.bad || memcmp(magic, MAGIC, 8)) { snprintf(err, errlen, "%s is not a dpd checkpoint", path); return -1; }
    return 0;
}

int checkpoint_read(const char *dir, uint64_t scene_hash, System *s, NeighborList *nl,
                    Measure *m, CheckpointExtra *x, char *err, size_t errlen)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/%s", dir, CHECKPOINT_FILE);
    char *buf;
    size_t len;
    const int got = read_verified(path, SIZE_MAX, &buf, &len, err, errlen);
    if (got) return got;
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
               || (version < 4 && (x->solver_cpu || s->box.shear_rate != 0.0))
               || (version < 5 && x->trajectory)) {
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
