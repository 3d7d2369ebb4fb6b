/* scene.c - libconfig scene loading, overrides and validation. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <math.h>
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/stat.h>
#include "scene.h"

/* The largest scene file or @include read (the largest scene of the package has 4.5 kB;
 * a list of positions for 1e5 particles some 4 MB). */
#define SCENE_MAX_BYTES (16L << 20)
/* libconfig's own limit of nested @include files (scanctx.h, MAX_INCLUDE_DEPTH) */
#define SCENE_MAX_INCLUDE_DEPTH 10

static char READ_MARK;

static void mark(config_setting_t *s) { if (s) config_setting_set_hook(s, &READ_MARK); }
static int marked(const config_setting_t *s) { return config_setting_get_hook(s) == &READ_MARK; }

void scene_path(const config_setting_t *s, char *buf, size_t len)
{
    const config_setting_t *chain[64];
    int n = 0;
    for (const config_setting_t *p = s; p && !config_setting_is_root(p) && n < 64;
         p = config_setting_parent(p))
        chain[n++] = p;
    size_t used = 0;
    buf[0] = '\0';
    for (int k = n - 1; k >= 0; k--) {
        const char *name = config_setting_name(chain[k]);
        int w;
        if (name) w = snprintf(buf + used, len - used, "%s%s", used ? "." : "", name);
        else w = snprintf(buf + used, len - used, "%s[%d]", used ? "." : "", config_setting_index(chain[k]));
        if (w < 0 || (size_t)w >= len - used) break;
        used += (size_t)w;
    }
}

static int line_of(const config_setting_t *s)
{
    for (const config_setting_t *p = s; p; p = config_setting_parent(p)) {
        int l = config_setting_source_line(p);
        if (l > 0) return l;
    }
    return 0;
}

int scene_fail(Scene *sc, const config_setting_t *at, const char *fmt, ...)
{
    if (sc->failed) return -1;
    char msg[600], path[256] = "";
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (at) scene_path(at, path, sizeof path);
    const int line = at ? config_setting_source_line(at) : 0;
    if (at && line > 0)
        snprintf(sc->error, sizeof sc->error, "%s:%d: key '%s': %s", sc->file, line, path, msg);
    else if (at && line_of(at) > 0)
        snprintf(sc->error, sizeof sc->error, "%s: key '%s' (set on the command line, near line %d): %s",
                 sc->file, path, line_of(at), msg);
    else if (at)
        snprintf(sc->error, sizeof sc->error, "%s: key '%s' (set on the command line): %s",
                 sc->file, path, msg);
    else
        snprintf(sc->error, sizeof sc->error, "%s: %s", sc->file, msg);
    sc->failed = 1;
    return -1;
}

static void remember(Scene *sc, const config_setting_t *parent, const char *key)
{
    for (int k = 0; k < sc->nasked; k++)
        if (sc->asked[k].parent == parent && strcmp(sc->asked[k].key, key) == 0) return;
    if (sc->nasked == sc->capasked) {
        int cap = sc->capasked ? 2 * sc->capasked : 64;
        void *p = realloc(sc->asked, (size_t)cap * sizeof *sc->asked);
        if (!p) return;
        sc->asked = p;
        sc->capasked = cap;
    }
    sc->asked[sc->nasked].parent = parent;
    snprintf(sc->asked[sc->nasked].key, sizeof sc->asked[0].key, "%s", key);
    sc->nasked++;
}

static config_setting_t *lookup(Scene *sc, const config_setting_t *grp, const char *key)
{
    if (!grp) grp = config_root_setting(&sc->cfg);
    remember(sc, grp, key);
    config_setting_t *s = config_setting_get_member(grp, key);
    mark(s);
    return s;
}

static int is_number(const config_setting_t *s)
{
    int t = config_setting_type(s);
    return t == CONFIG_TYPE_INT || t == CONFIG_TYPE_INT64 || t == CONFIG_TYPE_FLOAT;
}

static double number_of(const config_setting_t *s)
{
    switch (config_setting_type(s)) {
    case CONFIG_TYPE_INT: return config_setting_get_int(s);
    case CONFIG_TYPE_INT64: return (double)config_setting_get_int64(s);
    default: return config_setting_get_float(s);
    }
}

static const char *type_name(int t)
{
    switch (t) {
    case CONFIG_TYPE_INT: case CONFIG_TYPE_INT64: return "integer";
    case CONFIG_TYPE_FLOAT: return "number";
    case CONFIG_TYPE_STRING: return "string";
    case CONFIG_TYPE_BOOL: return "boolean";
    case CONFIG_TYPE_ARRAY: return "array";
    case CONFIG_TYPE_LIST: return "list";
    case CONFIG_TYPE_GROUP: return "group";
    default: return "unknown";
    }
}

static int check_range(Scene *sc, const config_setting_t *s, double v, double lo, double hi)
{
    if (!isfinite(v)) return scene_fail(sc, s, "value %g is not finite; allowed [%g, %g]", v, lo, hi);
    if (v < lo || v > hi) return scene_fail(sc, s, "value %g out of range; allowed [%g, %g]", v, lo, hi);
    return 0;
}

static int edit_distance(const char *a, const char *b)
{
    int la = (int)strlen(a), lb = (int)strlen(b);
    if (la > 63 || lb > 63) return 99;
    int d[64][64];
    for (int i = 0; i <= la; i++) d[i][0] = i;
    for (int j = 0; j <= lb; j++) d[0][j] = j;
    for (int i = 1; i <= la; i++)
        for (int j = 1; j <= lb; j++) {
            int c = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < c) c = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < c) c = d[i][j - 1] + 1;
            d[i][j] = c;
        }
    return d[la][lb];
}


/* A required key is absent: say what it must be, and point at a sibling key
 * whose name is one or two edits away (a likely typo). */
static int missing(Scene *sc, const config_setting_t *grp, const char *key, const char *what)
{
    const config_setting_t *g = grp ? grp : config_root_setting(&sc->cfg);
    char hint[160] = "";
    for (int k = 0; k < config_setting_length(g); k++) {
        const config_setting_t *c = config_setting_get_elem(g, (unsigned)k);
        const char *name = config_setting_name(c);
        if (name && strcmp(name, key) && edit_distance(name, key) <= 2) {
            snprintf(hint, sizeof hint, "; '%s' at line %d looks like a typo for it", name,
                     config_setting_source_line(c));
            break;
        }
    }
    char path[256] = "";
    if (grp && !config_setting_is_root(grp)) scene_path(grp, path, sizeof path);
    return scene_fail(sc, grp && !config_setting_is_root(grp) ? grp : NULL,
                      "required key '%s%s%s' is missing (%s)%s", path, path[0] ? "." : "", key, what, hint);
}

int scene_double(Scene *sc, const config_setting_t *grp, const char *key, double *out,
                 double def, double lo, double hi, int required)
{
    config_setting_t *s = lookup(sc, grp, key);
    if (!s) {
        if (required) {
            char what[96];
            snprintf(what, sizeof what, "a number in [%g, %g]", lo, hi);
            return missing(sc, grp, key, what);
        }
        *out = def;
        return 0;
    }
    if (!is_number(s))
        return scene_fail(sc, s, "expected a number in [%g, %g], found a %s", lo, hi,
                          type_name(config_setting_type(s)));
    *out = number_of(s);
    return check_range(sc, s, *out, lo, hi) ? -1 : 1;
}

int scene_int(Scene *sc, const config_setting_t *grp, const char *key, long long *out,
              long long def, long long lo, long long hi, int required)
{
    config_setting_t *s = lookup(sc, grp, key);
    if (!s) {
        if (required) {
            char what[96];
            snprintf(what, sizeof what, "an integer in [%lld, %lld]", lo, hi);
            return missing(sc, grp, key, what);
        }
        *out = def;
        return 0;
    }
    int t = config_setting_type(s);
    if (t != CONFIG_TYPE_INT && t != CONFIG_TYPE_INT64)
        return scene_fail(sc, s, "expected an integer in [%lld, %lld], found a %s", lo, hi, type_name(t));
    *out = t == CONFIG_TYPE_INT ? config_setting_get_int(s) : config_setting_get_int64(s);
    if (*out < lo || *out > hi)
        return scene_fail(sc, s, "value %lld out of range; allowed [%lld, %lld]", *out, lo, hi);
    return 1;
}

int scene_bool(Scene *sc, const config_setting_t *grp, const char *key, int *out, int def)
{
    config_setting_t *s = lookup(sc, grp, key);
    if (!s) { *out = def; return 0; }
    if (config_setting_type(s) != CONFIG_TYPE_BOOL)
        return scene_fail(sc, s, "expected true or false, found a %s", type_name(config_setting_type(s)));
    *out = config_setting_get_bool(s);
    return 1;
}

int scene_string(Scene *sc, const config_setting_t *grp, const char *key, const char **out,
                 const char *def, const char *const *allowed, int required)
{
    config_setting_t *s = lookup(sc, grp, key);
    if (!s) {
        if (required) return missing(sc, grp, key, "a string");
        *out = def;
        return 0;
    }
    if (config_setting_type(s) != CONFIG_TYPE_STRING)
        return scene_fail(sc, s, "expected a string, found a %s", type_name(config_setting_type(s)));
    *out = config_setting_get_string(s);
    if (allowed) {
        char list[300] = "";
        for (int k = 0; allowed[k]; k++) {
            if (strcmp(allowed[k], *out) == 0) return 1;
            strncat(list, k ? ", " : "", sizeof list - strlen(list) - 1);
            strncat(list, allowed[k], sizeof list - strlen(list) - 1);
        }
        return scene_fail(sc, s, "value \"%s\" not allowed; allowed: %s", *out, list);
    }
    return 1;
}

int scene_vector(Scene *sc, const config_setting_t *grp, const char *key, double *out, int n,
                 int *got, double lo, double hi, int required)
{
    config_setting_t *s = lookup(sc, grp, key);
    if (!s) {
        if (required) return missing(sc, grp, key, "an array of numbers");
        return 0;
    }
    int t = config_setting_type(s);
    if (t != CONFIG_TYPE_ARRAY && t != CONFIG_TYPE_LIST)
        return scene_fail(sc, s, "expected an array of numbers [...], found a %s", type_name(t));
    const int len = config_setting_length(s);
    if ((n >= 0 && len != n) || (n < 0 && (len < 1 || len > -n)))
        return scene_fail(sc, s, "expected %s%d numbers, found %d", n < 0 ? "1 to " : "", n < 0 ? -n : n, len);
    for (int k = 0; k < len; k++) {
        config_setting_t *e = config_setting_get_elem(s, (unsigned)k);
        if (!is_number(e)) return scene_fail(sc, s, "element %d is a %s, expected a number", k, type_name(config_setting_type(e)));
        out[k] = number_of(e);
        if (check_range(sc, s, out[k], lo, hi)) return -1;
    }
    if (got) *got = len;
    return 1;
}

config_setting_t *scene_child(Scene *sc, const config_setting_t *grp, const char *key, int want_type)
{
    config_setting_t *s = lookup(sc, grp, key);
    if (!s) return NULL;
    if (config_setting_type(s) != want_type) {
        scene_fail(sc, s, "expected a %s, found a %s", type_name(want_type), type_name(config_setting_type(s)));
        return NULL;
    }
    return s;
}

static int walk_unknown(Scene *sc, config_setting_t *s)
{
    const int t = config_setting_type(s);
    if (!config_setting_is_root(s) && !marked(s)) {
        const config_setting_t *parent = config_setting_parent(s);
        const char *name = config_setting_name(s);
        if (!name) return scene_fail(sc, s, "this element is not read by anything");
        const char *best = NULL;
        int bestd = 99;
        char known[400] = "";
        for (int k = 0; k < sc->nasked; k++) {
            if (sc->asked[k].parent != parent) continue;
            int dd = edit_distance(name, sc->asked[k].key);
            if (dd < bestd) { bestd = dd; best = sc->asked[k].key; }
            if (strlen(known) + strlen(sc->asked[k].key) + 3 < sizeof known) {
                if (known[0]) strcat(known, ", ");
                strcat(known, sc->asked[k].key);
            }
        }
        if (best && bestd <= 3)
            return scene_fail(sc, s, "unknown key; did you mean '%s'? (known here: %s)", best, known);
        return scene_fail(sc, s, "unknown key (known here: %s)", known[0] ? known : "none");
    }
    if (t == CONFIG_TYPE_GROUP || t == CONFIG_TYPE_LIST) {
        const int len = config_setting_length(s);
        for (int k = 0; k < len; k++) {
            config_setting_t *c = config_setting_get_elem(s, (unsigned)k);
            if (t == CONFIG_TYPE_LIST) mark(c);   /* list elements are read as a whole */
            if (walk_unknown(sc, c)) return -1;
        }
    }
    return 0;
}

int scene_check_unknown(Scene *sc)
{
    return walk_unknown(sc, config_root_setting(&sc->cfg));
}

/* Deep copy of src into a new member/element of dst. */
static int copy_setting(config_setting_t *dst_parent, const char *name, const config_setting_t *src)
{
    const int t = config_setting_type(src);
    config_setting_t *d = config_setting_add(dst_parent, name, t);
    if (!d) return -1;
    switch (t) {
    case CONFIG_TYPE_INT: config_setting_set_int(d, config_setting_get_int(src)); break;
    case CONFIG_TYPE_INT64: config_setting_set_int64(d, config_setting_get_int64(src)); break;
    case CONFIG_TYPE_FLOAT: config_setting_set_float(d, config_setting_get_float(src)); break;
    case CONFIG_TYPE_BOOL: config_setting_set_bool(d, config_setting_get_bool(src)); break;
    case CONFIG_TYPE_STRING: config_setting_set_string(d, config_setting_get_string(src)); break;
    default: {
        const int len = config_setting_length(src);
        for (int k = 0; k < len; k++) {
            const config_setting_t *e = config_setting_get_elem(src, (unsigned)k);
            if (copy_setting(d, config_setting_name(e), e)) return -1;
        }
    }
    }
    return 0;
}

/* libconfig 1.5 reads an integer literal without the L suffix into an int
 * and silently wraps one beyond 32 bits (4294967296 becomes 0). Find such a
 * literal (outside strings and comments) before parsing; returns its line
 * (and the literal in lit) or 0. */
static int int_overflow_line(const char *t, char *lit, size_t litlen)
{
    int line = 1;
    for (const char *p = t; *p; p++) {
        if (*p == '\n') { line++; continue; }
        if (*p == '"') {                                   /* string */
            for (p++; *p && *p != '"'; p++) {
                if (*p == '\\' && p[1]) p++;
                else if (*p == '\n') line++;
            }
            if (!*p) break;
            continue;
        }
        if (*p == '#' || (*p == '/' && p[1] == '/')) {    /* line comment */
            while (p[1] && p[1] != '\n') p++;
            continue;
        }
        if (*p == '/' && p[1] == '*') {                    /* block comment */
            for (p += 2; *p && !(*p == '*' && p[1] == '/'); p++) if (*p == '\n') line++;
            if (!*p) break;
            p++;
            continue;
        }
        if (*p < '0' || *p > '9') continue;
        if (p > t && (isalnum((unsigned char)p[-1]) || p[-1] == '_' || p[-1] == '.')) {
            while (isalnum((unsigned char)p[1]) || p[1] == '_') p++;   /* part of a name or number */
            continue;
        }
        const char *q = p;
        const int hex = p[0] == '0' && (p[1] == 'x' || p[1] == 'X');
        if (hex) q += 2;
        while (hex ? isxdigit((unsigned char)*q) : isdigit((unsigned char)*q)) q++;
        const int is_float = !hex && (*q == '.' || *q == 'e' || *q == 'E');
        if (!is_float && *q != 'L') {
            const char *d = hex ? p + 2 : p;
            while (*d == '0' && d + 1 < q) d++;              /* leading zeros */
            const size_t nd = (size_t)(q - d);
            const char *max = hex ? "7fffffff" : p > t && p[-1] == '-' ? "2147483648" : "2147483647";
            int over = nd > strlen(max);
            if (nd == strlen(max)) {
                char low[16];
                for (size_t k = 0; k < nd; k++) low[k] = (char)tolower((unsigned char)d[k]);
                low[nd] = '\0';
                over = strcmp(low, max) > 0;
            }
            if (over) {
                snprintf(lit, litlen, "%.*s", (int)(q - p), p);
                return line;
            }
        }
        p = q - 1;
        while (isalnum((unsigned char)p[1]) || p[1] == '.' || p[1] == '_' ||
               ((p[1] == '-' || p[1] == '+') && (p[0] == 'e' || p[0] == 'E'))) p++;   /* rest of the token */
    }
    return 0;
}

static int apply_override(Scene *sc, const char *spec)
{
    char path[512];
    const char *eq = strchr(spec, '=');
    if (!eq || eq == spec || (size_t)(eq - spec) >= sizeof path) {
        snprintf(sc->error, sizeof sc->error, "--set '%s': expected key=value", spec);
        return -1;
    }
    memcpy(path, spec, (size_t)(eq - spec));
    path[eq - spec] = '\0';
    /* parse the value with libconfig itself */
    config_t tmp;
    config_init(&tmp);
    size_t len = strlen(eq + 1) + 16;
    char *text = malloc(len);
    if (!text) { config_destroy(&tmp); return -1; }
    snprintf(text, len, "v = %s;", eq + 1);
    char lit[64];
    if (int_overflow_line(text, lit, sizeof lit)) {
        snprintf(sc->error, sizeof sc->error, "--set '%s': integer %s does not fit in 32 bits; "
                 "allowed -2147483648 to 2147483647, or append L for a 64-bit integer", spec, lit);
        free(text);
        config_destroy(&tmp);
        return -1;
    }
    int ok = config_read_string(&tmp, text);
    free(text);
    if (!ok) {
        snprintf(sc->error, sizeof sc->error, "--set '%s': cannot parse the value: %s", spec, config_error_text(&tmp));
        config_destroy(&tmp);
        return -1;
    }
    const config_setting_t *val = config_lookup(&tmp, "v");
    config_setting_t *cur = config_root_setting(&sc->cfg);
    char *save = NULL, *tok = strtok_r(path, ".", &save);
    int rc = 0;
    while (tok) {
        char *next = strtok_r(NULL, ".", &save);
        const int t = config_setting_type(cur);
        if (tok[0] == '[') {
            int idx = atoi(tok + 1);
            if ((t != CONFIG_TYPE_LIST && t != CONFIG_TYPE_ARRAY) || idx < 0 || idx >= config_setting_length(cur)) {
                snprintf(sc->error, sizeof sc->error, "--set '%s': no element %s here", spec, tok);
                rc = -1; break;
            }
            if (!next) {
                snprintf(sc->error, sizeof sc->error, "--set '%s': replace whole elements by their key", spec);
                rc = -1; break;
            }
            cur = config_setting_get_elem(cur, (unsigned)idx);
        } else {
            if (t != CONFIG_TYPE_GROUP) {
                snprintf(sc->error, sizeof sc->error, "--set '%s': '%s' is inside a %s, not a group", spec, tok, type_name(t));
                rc = -1; break;
            }
            config_setting_t *m = config_setting_get_member(cur, tok);
            if (!next) {
                if (m) config_setting_remove(cur, tok);
                if (copy_setting(cur, tok, val)) {
                    snprintf(sc->error, sizeof sc->error, "--set '%s': invalid key name", spec);
                    rc = -1;
                }
                break;
            }
            if (!m) m = config_setting_add(cur, tok, CONFIG_TYPE_GROUP);
            if (!m) { snprintf(sc->error, sizeof sc->error, "--set '%s': invalid key '%s'", spec, tok); rc = -1; break; }
            cur = m;
        }
        tok = next;
    }
    config_destroy(&tmp);
    return rc;
}

/* What a file that is no regular file is, in words. */
static const char *file_kind(mode_t m)
{
    return S_ISDIR(m) ? "a directory" : S_ISCHR(m) ? "a character device" : S_ISBLK(m) ? "a block device"
         : S_ISFIFO(m) ? "a FIFO" : S_ISSOCK(m) ? "a socket" : "not a regular file";
}

/* The bytes of a scene file or an @include, NUL-terminated (malloc'd), or NULL with `why`
 * ("'PATH' is a directory, ..."). Only a regular file of at most SCENE_MAX_BYTES is read, and
 * it is opened without waiting: libconfig ends the process on a read error (a directory:
 * "input in flex scanner failed"), reads /dev/zero for ever, and a FIFO would block the open. */
static char *read_scene_file(const char *path, size_t *len, char *why, size_t whylen)
{
    const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(why, whylen, "'%s': cannot open: %s", path, strerror(errno));
        return NULL;
    }
    struct stat st;
    char *buf = NULL;
    if (fstat(fd, &st)) {
        snprintf(why, whylen, "'%s': cannot stat: %s", path, strerror(errno));
    } else if (!S_ISREG(st.st_mode)) {
        snprintf(why, whylen, "'%s' is %s, not a regular file (a scene is a text file)", path, file_kind(st.st_mode));
    } else if (st.st_size > SCENE_MAX_BYTES) {
        snprintf(why, whylen, "'%s' has %lld bytes; a scene file may have at most %ld (16 MiB)", path,
                 (long long)st.st_size, SCENE_MAX_BYTES);
    } else if (!(buf = malloc((size_t)st.st_size + 1))) {
        snprintf(why, whylen, "'%s': out of memory", path);
    } else {
        size_t got = 0;
        ssize_t r = 1;
        while (got < (size_t)st.st_size && (r = read(fd, buf + got, (size_t)st.st_size - got)) > 0) got += (size_t)r;
        if (r < 0) {
            snprintf(why, whylen, "'%s': cannot read: %s", path, strerror(errno));
            free(buf);
            buf = NULL;
        } else {
            buf[got] = '\0';   /* a file that shrank meanwhile: what was there */
            *len = got;
        }
    }
    close(fd);
    return buf;
}

/* A NUL byte would end a string where libconfig reads it (a name "w\0x" becomes "w"):
 * the line of the first one (0: none). */
static int nul_line(const char *t, size_t len, size_t *at)
{
    const char *nul = memchr(t, '\0', len);
    if (!nul) return 0;
    int line = 1;
    for (const char *p = t; p < nul; p++) line += *p == '\n';
    *at = (size_t)(nul - t);
    return line;
}

/* The @include directives of a scene text as libconfig 1.5's scanner finds them (a line
 * that starts with optional blanks, then @include, blanks and a quoted file name; not
 * inside a comment or a string), each read with read_scene_file and checked in turn,
 * before libconfig opens it. 0, or -1 with sc->error naming the file and line. */
static int check_includes(Scene *sc, const char *file, const char *t, int depth)
{
    int line = 1, at_start = 1, block = 0, str = 0;
    for (const char *p = t; *p; p++) {
        if (*p == '\n') { line++; at_start = 1; continue; }
        if (block) { if (p[0] == '*' && p[1] == '/') { block = 0; p++; } continue; }
        if (str) { if (*p == '\\' && p[1]) p++; else if (*p == '"') str = 0; continue; }
        if (*p == ' ' || *p == '\t') continue;
        const int first = at_start;
        at_start = 0;
        if (*p == '#' || (p[0] == '/' && p[1] == '/')) { while (p[1] && p[1] != '\n') p++; continue; }
        if (p[0] == '/' && p[1] == '*') { block = 1; p++; continue; }
        if (*p == '"') { str = 1; continue; }
        if (!first || strncmp(p, "@include", 8) || (p[8] != ' ' && p[8] != '\t')) continue;
        const char *q = p + 8;
        while (*q == ' ' || *q == '\t') q++;
        if (*q != '"') continue;   /* libconfig's syntax error */
        char path[1024];
        size_t n = 0;
        for (q++; *q && *q != '"' && *q != '\n'; q++) {
            char c = *q;
            if (c == '\\' && q[1]) {
                q++;
                c = *q == 'n' ? '\n' : *q == 't' ? '\t' : *q == 'r' ? '\r' : *q == 'f' ? '\f' : *q;
            }
            if (n + 1 < sizeof path) path[n++] = c;
        }
        path[n] = '\0';
        p = *q ? q : q - 1;   /* on to the end of the directive */
        if (depth >= SCENE_MAX_INCLUDE_DEPTH) continue;   /* libconfig: "include file nesting too deep" */
        char why[1400];
        size_t len = 0, nul_at = 0;
        char *inc = read_scene_file(path, &len, why, sizeof why);
        if (!inc) {
            snprintf(sc->error, sizeof sc->error, "%s:%d: @include %s", file, line, why);
            return -1;
        }
        const int nl = nul_line(inc, len, &nul_at);
        int rc = 0;
        if (nl) {
            snprintf(sc->error, sizeof sc->error, "%s:%d: @include '%s': line %d has a NUL byte (at byte %zu): "
                     "a scene is text, and a string would end there; remove it", file, line, path, nl, nul_at);
            rc = -1;
        } else rc = check_includes(sc, path, inc, depth + 1);
        free(inc);
        if (rc) return -1;
    }
    return 0;
}

int scene_load(Scene *sc, const char *file, char *const *overrides, int noverrides)
{
    memset(sc, 0, sizeof *sc);
    snprintf(sc->file, sizeof sc->file, "%s", file);
    config_init(&sc->cfg);
    /* the scene and its includes are checked first; libconfig parses the bytes checked */
    char why[1400];
    size_t rawlen = 0, nul_at = 0;
    char *raw = read_scene_file(file, &rawlen, why, sizeof why);
    if (!raw) {
        snprintf(sc->error, sizeof sc->error, "the scene %s", why);
        sc->failed = 1;
        return -1;
    }
    const int nl = nul_line(raw, rawlen, &nul_at);
    if (nl) {
        snprintf(sc->error, sizeof sc->error, "%s:%d: a NUL byte (at byte %zu): a scene is text, and a string "
                 "would end there; remove it", file, nl, nul_at);
        free(raw);
        sc->failed = 1;
        return -1;
    }
    char lit[64];
    const int bad_line = int_overflow_line(raw, lit, sizeof lit);
    if (bad_line) {
        snprintf(sc->error, sizeof sc->error, "%s:%d: integer %s does not fit in 32 bits; allowed "
                 "-2147483648 to 2147483647, or append L for a 64-bit integer (e.g. %sL)", file, bad_line, lit, lit);
        free(raw);
        sc->failed = 1;
        return -1;
    }
    if (check_includes(sc, file, raw, 0)) {
        free(raw);
        sc->failed = 1;
        return -1;
    }
    const int ok = config_read_string(&sc->cfg, raw);
    free(raw);
    if (!ok) {
        const char *in = config_error_file(&sc->cfg);
        snprintf(sc->error, sizeof sc->error, "%s:%d: %s", in ? in : file,
                 config_error_line(&sc->cfg), config_error_text(&sc->cfg));
        sc->failed = 1;
        return -1;
    }
    for (int k = 0; k < noverrides; k++)
        if (apply_override(sc, overrides[k])) { sc->failed = 1; return -1; }
    return 0;
}

void scene_free(Scene *sc)
{
    config_destroy(&sc->cfg);
    free(sc->asked);
    sc->asked = NULL;
}

char *scene_text(Scene *sc)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *m = open_memstream(&buf, &len);
    if (!m) return NULL;
    config_write(&sc->cfg, m);
    fclose(m);
    return buf;
}
