/* pair_styles.c - the registry of pair styles (pair_style.h): the built-in
 * ones, those a program or test adds, and the style of a System. */
#include <string.h>
#include "pair_style.h"

/* The built-in styles: each one's registration is its line here, naming the
 * PairStyle pair_style_NAME that its file pair_NAME.c defines. */
#define PAIR_BUILTIN_STYLES(X)                                                  \
    X(dpd)       /* standard DPD, Mai-Duy et al. 2019 eqs 2-7 */                \
    X(pan2008)   /* rotating particles, Pan et al. 2008 eqs 1, 13-15 */

#define PAIR_STYLE_DECLARE(name) extern const PairStyle pair_style_##name;
#define PAIR_STYLE_ENTRY(name) &pair_style_##name,
PAIR_BUILTIN_STYLES(PAIR_STYLE_DECLARE)

static const PairStyle *const builtin[] = {PAIR_BUILTIN_STYLES(PAIR_STYLE_ENTRY)};
enum { NBUILTIN = sizeof builtin / sizeof builtin[0], PAIR_STYLES_ADDED = 16 };
static const PairStyle *added[PAIR_STYLES_ADDED];   /* pair_style_register, before any run */
static int nadded;

static const PairStyle *style_at(int k) { return k < NBUILTIN ? builtin[k] : added[k - NBUILTIN]; }

const PairStyle *pair_style_find(const char *name)
{
    for (int k = 0; k < NBUILTIN + nadded; k++)
        if (!strcmp(style_at(k)->name, name)) return style_at(k);
    return NULL;
}

int pair_style_register(const PairStyle *st)
{
    if (nadded == PAIR_STYLES_ADDED || pair_style_find(st->name)) return -1;
    added[nadded++] = st;
    return 0;
}

const PairStyle *pair_style_of(const System *s)
{
    if (s->pair_style) return s->pair_style;
    for (int k = 0; k < NBUILTIN + nadded; k++)
        if (style_at(k)->serves && style_at(k)->serves(s)) return style_at(k);
    return NULL;
}
