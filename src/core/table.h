/* table.h - the result tables of the physics modules (the m = 0 solver's
 * record, the 2D colloids' MSD, RDF and g(q)): each a file name and its text
 * (comment lines, a header, rows), printed into memory. A module never opens a
 * file: it hands its tables to io/ (output_write_tables), which writes each
 * into the run's directory (temporary name, fsync, rename) and alone knows
 * paths and file errors (tests/layers.sh checks that no physics layer writes). */
#ifndef DPD_TABLE_H
#define DPD_TABLE_H

#include <stdio.h>
#include <stddef.h>

typedef struct {
    char name[64];            /* the file name in the run's directory, e.g. "solver.tsv" */
    char *text;
    size_t len;
} Table;

typedef struct {
    Table **t;
    int n, cap;
} Tables;

/* A new table NAME: the stream to print it into, to be closed with table_end;
 * NULL if out of memory. */
FILE *tables_add(Tables *ts, const char *name);
/* Close the stream of the last table added; 0, or -1 (out of memory). */
int   table_end(Tables *ts, FILE *f);
void  tables_free(Tables *ts);

#endif
