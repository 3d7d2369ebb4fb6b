/* dirlock.h - one writer per output directory: `dpd run` holds an flock(2) on
 * DIR/.dpd-run.lock for the whole run, whatever HDF5's own file locking does
 * (HDF5_USE_FILE_LOCKING=FALSE, usual on cluster file systems, turns that off).
 * The file names its holder (pid, host, start time) for the refusal message of
 * a second writer; the kernel drops the lock when the holder ends, even by
 * SIGKILL, so a stale file never blocks a later run. */
#ifndef DPD_DIRLOCK_H
#define DPD_DIRLOCK_H

#include <stddef.h>

#define DIRLOCK_FILE ".dpd-run.lock"

/* Take the lock of dir. Returns the lock's descriptor (>= 0); -1 if another process holds it
 * (holder: "pid N on HOST since DATE"); -2 if the file system cannot lock (why: its error; the
 * caller may go on without a lock). */
int  dirlock_take(const char *dir, char *holder, size_t holderlen);
/* Release it (the file is removed first, then the lock dropped). */
void dirlock_release(const char *dir, int fd);

#endif
