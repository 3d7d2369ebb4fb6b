/* io.h - one traversal of a state that either writes it or reads it back
 * (the checkpoint, checkpoint.h). Each module lists its own fields once, in
 * order, in its xxx_io(Io *, state): writing and reading cannot drift apart,
 * and no other file needs to know the module's internals. */
#ifndef DPD_IO_H
#define DPD_IO_H

#include <stdio.h>
#include <stddef.h>
#include "blockavg.h"

typedef struct {
    int reading;
    FILE *out;                /* writing: the stream */
    const unsigned char *in;  /* reading: the bytes, their length and the position */
    size_t len, pos;
    int bad;
    const char *what;         /* first field that did not fit */
} Io;

/* len bytes at p, written or read in place. */
void io_bytes(Io *io, void *p, size_t len, const char *what);
/* An array whose length the scene fixes: the stored count must match. */
void io_array(Io *io, void *p, size_t count, size_t size, const char *what);
/* A series of any length (reading replaces its values). */
void io_series(Io *io, Series *s, const char *what);
/* Mark the traversal bad at `what` (a value read that cannot be right). */
void io_fail(Io *io, const char *what);

#endif
