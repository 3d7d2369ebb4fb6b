/* io.c - the symmetric write/read traversal of the checkpoint (see io.h). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "io.h"

uint64_t io_fnv1a(const void *data, size_t len, uint64_t h)
{
    const unsigned char *p = data;
    for (size_t k = 0; k < len; k++) { h ^= p[k]; h *= 1099511628211ULL; }
    return h;
}

void io_fail(Io *io, const char *what)
{
    io->bad = 1;
    io->what = what;
}

void io_bytes(Io *io, void *p, size_t len, const char *what)
{
    if (io->bad || len == 0) return;
    if (!io->reading) {
        if (fwrite(p, 1, len, io->out) != len) io_fail(io, what);
        io->sum = io_fnv1a(p, len, io->sum);
        return;
    }
    if (len > io->len - io->pos) { io_fail(io, what); return; }
    memcpy(p, io->in + io->pos, len);
    io->pos += len;
}

void io_array(Io *io, void *p, size_t count, size_t size, const char *what)
{
    uint64_t c = count;
    io_bytes(io, &c, sizeof c, what);
    if (io->bad) return;
    if (c != count) { io_fail(io, what); return; }
    io_bytes(io, p, count * size, what);
}

void io_series(Io *io, Series *s, const char *what)
{
    uint64_t n = s->n;
    io_bytes(io, &n, sizeof n, what);
    if (io->bad) return;
    if (io->reading) {
        if (n > (io->len - io->pos) / sizeof(double)) { io_fail(io, what); return; }
        series_free(s);
        if (n > 0) {   /* room for the samples still to come, as series_push would reserve */
            const size_t cap = s->expect > n ? s->expect : (size_t)n;
            s->v = malloc(cap * sizeof(double));
            if (!s->v) { io_fail(io, what); return; }
            s->n = (size_t)n;
            s->cap = cap;
        }
    }
    io_bytes(io, s->v, (size_t)n * sizeof(double), what);
}
