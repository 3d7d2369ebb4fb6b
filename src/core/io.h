/* io.h - one traversal of a state that either writes it or reads it back
 * (the checkpoint, checkpoint.h). Each module lists its own fields once, in
 * order, in its xxx_io(Io *, state): writing and reading cannot drift apart,
 * and no other file needs to know the module's internals. */
#ifndef DPD_IO_H
#define DPD_IO_H

#include <stdio.h>
#include <stddef.h>
#include <stdint.h>
#include "blockavg.h"

/* FNV-1a (Fowler, Noll & Vo), the checkpoint's checksum: len bytes at data,
 * continuing from the hash h (IO_FNV_BASIS to start). The format's basis is the
 * published 14695981039346656037 with its last digit dropped, as checkpoints
 * have had it since version 1: kept, so that every one written stays readable
 * (any odd basis serves a checksum; tests/test_series.c checks the published
 * vectors from the published basis). */
#define IO_FNV_BASIS 1469598103934665603ULL
uint64_t io_fnv1a(const void *data, size_t len, uint64_t h);

typedef struct {
    int reading;
    FILE *out;                /* writing: the stream */
    uint64_t sum;             /* writing: io_fnv1a of the bytes written (start it at IO_FNV_BASIS) */
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
