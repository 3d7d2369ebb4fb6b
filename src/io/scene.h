/* scene.h - scene files (libconfig) with strict validation.
 * Every key read is checked for type and range; a key that nothing reads is
 * an error, with the nearest known key suggested. Messages name the file,
 * the line, the key, the value and what is allowed. */
#ifndef DPD_SCENE_H
#define DPD_SCENE_H

#include <libconfig.h>

typedef struct {
    config_t cfg;
    char file[512];
    char error[2048];         /* first error */
    int failed;
    /* keys asked for, for "did you mean" */
    struct { const config_setting_t *parent; char key[64]; } *asked;
    int nasked, capasked;
} Scene;

/* Load a file and apply --set overrides ("path=value", path like
 * "pairs.[0].a" or "measure.profile.bins"). Returns 0 or -1 with sc->error. */
int  scene_load(Scene *sc, const char *file, char *const *overrides, int noverrides);
void scene_free(Scene *sc);

/* Typed getters. grp NULL = root. Return 1 if present, 0 if absent (default
 * stored), -1 on error (sc->error set, sc->failed = 1). */
int scene_double(Scene *sc, const config_setting_t *grp, const char *key, double *out,
                 double def, double lo, double hi, int required);
int scene_int(Scene *sc, const config_setting_t *grp, const char *key, long long *out,
              long long def, long long lo, long long hi, int required);
int scene_bool(Scene *sc, const config_setting_t *grp, const char *key, int *out, int def);
int scene_string(Scene *sc, const config_setting_t *grp, const char *key, const char **out,
                 const char *def, const char *const *allowed, int required);
/* Numeric array of exactly n elements (n < 0: any length up to -n, count returned in *got). */
int scene_vector(Scene *sc, const config_setting_t *grp, const char *key, double *out, int n,
                 int *got, double lo, double hi, int required);
/* Group or list child (marked as read); NULL if absent. */
config_setting_t *scene_child(Scene *sc, const config_setting_t *grp, const char *key, int want_type);
/* Report an error at a setting: "file:line: key 'path': message". */
int scene_fail(Scene *sc, const config_setting_t *at, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* After everything is read: unknown keys are errors. */
int scene_check_unknown(Scene *sc);
/* The full path of a setting, e.g. "pairs.[0].gamma". */
void scene_path(const config_setting_t *s, char *buf, size_t len);
/* The scene after overrides, as libconfig text (malloc'd). */
char *scene_text(Scene *sc);

#endif
