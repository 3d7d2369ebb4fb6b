/* dirlock.c - the output directory's lock (dirlock.h). */
#include <stdio.h>
#include <string.h>
#include <errno.h>
#include <time.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/file.h>
#include <sys/stat.h>
#include "dirlock.h"

int dirlock_take(const char *dir, char *holder, size_t holderlen)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/%s", dir, DIRLOCK_FILE);
    /* a holder that ends removes the file before it unlocks: a process that opened the old file
     * meanwhile gets its lock on a file no longer there, sees that and tries again */
    for (int attempt = 0; attempt < 100; attempt++) {
        const int fd = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0) {
            snprintf(holder, holderlen, "cannot open %s: %s", path, strerror(errno));
            return -2;
        }
        if (flock(fd, LOCK_EX | LOCK_NB)) {
            const int e = errno;
            if (e == EWOULDBLOCK) {
                ssize_t n = pread(fd, holder, holderlen - 1, 0);
                holder[n > 0 ? n : 0] = '\0';
                holder[strcspn(holder, "\n")] = '\0';
                if (!holder[0]) snprintf(holder, holderlen, "a process that has not yet said who it is");
            } else {
                snprintf(holder, holderlen, "cannot lock %s: %s", path, strerror(e));
            }
            close(fd);
            return e == EWOULDBLOCK ? -1 : -2;
        }
        struct stat a, b;
        if (fstat(fd, &a) == 0 && stat(path, &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
            char host[256] = "unknown", date[64];
            gethostname(host, sizeof host - 1);
            time_t now = time(NULL);
            strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
            char text[512];
            const int len = snprintf(text, sizeof text, "pid %ld on %s since %s\n", (long)getpid(), host, date);
            /* who holds it, for a second writer's message (the lock does not depend on it) */
            if (ftruncate(fd, 0) == 0 && pwrite(fd, text, (size_t)len, 0) == len) fsync(fd);
            return fd;
        }
        close(fd);
    }
    snprintf(holder, holderlen, "%s keeps being replaced", path);
    return -2;
}

void dirlock_release(const char *dir, int fd)
{
    if (fd < 0) return;
    char path[1100];
    snprintf(path, sizeof path, "%s/%s", dir, DIRLOCK_FILE);
    unlink(path);
    close(fd);
}
