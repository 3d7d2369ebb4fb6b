/* table.c - tables printed into memory (table.h). */
#include <stdlib.h>
#include <string.h>
#include "table.h"

FILE *tables_add(Tables *ts, const char *name)
{
    if (ts->n == ts->cap) {
        const int cap = ts->cap ? 2 * ts->cap : 8;
        Table **p = realloc(ts->t, (size_t)cap * sizeof *p);
        if (!p) return NULL;
        ts->t = p;
        ts->cap = cap;
    }
    Table *t = calloc(1, sizeof *t);   /* each its own: the stream keeps pointers into it */
    if (!t) return NULL;
    snprintf(t->name, sizeof t->name, "%s", name);
    FILE *f = open_memstream(&t->text, &t->len);
    if (!f) { free(t); return NULL; }
    ts->t[ts->n++] = t;
    return f;
}

int table_end(Tables *ts, FILE *f)
{
    (void)ts;
    return fclose(f) ? -1 : 0;
}

void tables_free(Tables *ts)
{
    for (int k = 0; k < ts->n; k++) { free(ts->t[k]->text); free(ts->t[k]); }
    free(ts->t);
    memset(ts, 0, sizeof *ts);
}
