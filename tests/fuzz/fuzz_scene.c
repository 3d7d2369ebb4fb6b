/* fuzz_scene.c - libFuzzer target for the scene parser and validator.
 * Input: optional leading lines "@set key=value" (--set overrides, up to 8),
 * then a libconfig scene. It is loaded and validated exactly as `dpd run`
 * does (scene_load + setup_from_scene), minus the particle allocation
 * (setup_validate_only), and the accepted scene is written back as text.
 * Any crash, leak or sanitizer report is a bug; error returns are fine. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <unistd.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include "scene.h"
#include "setup.h"
#include "colloid.h"
#include "bonds.h"

static int memfd = -1;
static char path[64];
static unsigned long long inputs;

/* CPU time actually spent (the machine is shared, so wall time overstates it) */
static void report(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    fprintf(stderr, "fuzz_scene: %llu inputs, %.1f CPU seconds (user %.1f + system %.1f)\n", inputs,
            ru.ru_utime.tv_sec + ru.ru_stime.tv_sec + 1e-6 * (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec),
            ru.ru_utime.tv_sec + 1e-6 * ru.ru_utime.tv_usec, ru.ru_stime.tv_sec + 1e-6 * ru.ru_stime.tv_usec);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (memfd < 0) {
        memfd = memfd_create("scene", 0);
        if (memfd < 0) abort();
        snprintf(path, sizeof path, "/proc/self/fd/%d", memfd);
        setup_validate_only = 1;
        atexit(report);
    }
    inputs++;
    char *buf = malloc(size + 1);
    if (!buf) return 0;
    memcpy(buf, data, size);
    buf[size] = '\0';
    char *sets[8];
    int nsets = 0;
    char *body = buf;
    while (nsets < 8 && strncmp(body, "@set ", 5) == 0) {
        char *nl = strchr(body, '\n');
        if (!nl) break;
        *nl = '\0';
        sets[nsets++] = body + 5;
        body = nl + 1;
    }
    const size_t blen = size - (size_t)(body - buf);
    if (ftruncate(memfd, 0) || pwrite(memfd, body, blen, 0) != (ssize_t)blen) abort();
    Scene sc;
    System s;
    Measure m;
    RunConfig rc;
    memset(&rc, 0, sizeof rc);
    if (scene_load(&sc, path, sets, nsets) == 0 && setup_from_scene(&sc, &s, &m, &rc) == 0) {
        char *text = scene_text(&sc);
        free(text);
    }
    /* the bodies' parameter blocks, read before the validate-only return (and
     * kept by a failure after them), belong to the caller, as in dpd run */
    colloid_free(rc.colloids);
    bonds_free(rc.bonds);
    if (sc.failed && sc.error[0] == '\0') abort();   /* every failure must explain itself */
    scene_free(&sc);
    free(buf);
    return 0;
}
