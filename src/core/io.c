/* io.c - the symmetric write/read traversal of the checkpoint (see io.h). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "io.h"

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
        if (n > 0) {
            s->v = malloc((size_t)n * sizeof(double));
            if (!s->v) { io_fail(io, what); return; }
            s->n = s->cap = (size_t)n;
        }
    }
    io_bytes(io, s->v, (size_t)n * sizeof(double), what);
}
