/* The live kiosk's crash memory, the last defence when a model kills the
 * process (a signal: a fault in a parser, the kernel's OOM killer): before
 * a model is loaded its name is written to the state folder ("loading"),
 * and removed once the load ended, well or not. A marker still there at
 * the next load means the last process died loading that model: it goes
 * to the skip list ("skip"), and is passed over, with a journal line,
 * until the file changes (its size or modification time), instead of
 * killing each start until systemd gives up and the screen stays dark.
 * A marker from before a reboot (the power cut mid-load) is no proof and
 * is dropped: the boot is written in it.
 *
 * Every function takes the state folder: no state here. Loads must not
 * overlap (the kiosk's are one at a time: at start, then on the worker). */
#ifndef MK_LOAD_GUARD_H
#define MK_LOAD_GUARD_H

#include <stdbool.h>
#include <stddef.h>

#define LOAD_GUARD_MARKER "loading"
#define LOAD_GUARD_SKIP	  "skip"

/* The folder: $STATE_DIRECTORY (systemd's StateDirectory=, the first
 * where it lists several). 0, or -ENOENT when the kiosk runs without one
 * (started by hand): then nothing is remembered. */
int load_guard_dir(char *buf, size_t size);

/* A marker left by a process that died while loading: its model moved to
 * the skip list and one error logged; the marker removed. 1 when that was
 * so, 0 when no marker was there (or it was from an earlier boot). */
int load_guard_recover(const char *dir);

/* path, as it is now, is on the skip list. */
bool load_guard_skipped(const char *dir, const char *path);

/* Before path is loaded: load_guard_recover, then -ECANCELED (logged)
 * when path is skipped; otherwise its marker is written and 0 returned
 * (0 too when it cannot be: the model loads, unguarded, after a warning). */
int load_guard_enter(const char *dir, const char *path);

/* After the load, whatever it gave: the marker removed. */
void load_guard_leave(const char *dir);

#endif
