/* Tells the live loop that the matcaps on disk changed, through inotify:
 * a file written and closed, moved in or out, or deleted. A copy in
 * progress is not reported until its file is closed, and the loop waits
 * for a quiet moment before it acts on a burst of them. */
#ifndef MK_FOLDER_WATCH_H
#define MK_FOLDER_WATCH_H

#include <stdbool.h>
#include <time.h>

struct folder_watch;

/* path is a folder (any name in it counts) or a file (its folder is
 * watched, and only that name counts). Returns NULL after logging. */
struct folder_watch *folder_watch_new(const char *path);
/* A watch of one file: name (in the same folder) counts too (a model's
 * NAME.ini beside it). 0 (a folder's watch counts every name anyway), or
 * -ENOMEM. */
int folder_watch_also(struct folder_watch *w, const char *name);
void folder_watch_free(struct folder_watch *w);
int folder_watch_fd(const struct folder_watch *w);
/* Read what is ready; true when something of interest changed. */
bool folder_watch_read(struct folder_watch *w);
/* The same, and arrived(ctx, folder, name) for each file of interest that
 * was closed after writing or moved in: one that is whole now (a partial
 * name, util/file.h, never is: its file arrives when renamed into place). */
typedef void (*folder_watch_arrived_fn)(void *ctx, const char *folder, const char *name);
bool folder_watch_read_names(struct folder_watch *w, folder_watch_arrived_fn arrived, void *ctx);
/* Whether a sync tool is writing into the folder (or a subfolder of it):
 * a partial file (util/file.h: rsync's, Syncthing's temporary names)
 * written to within the last minute (now: time(NULL)). A model whose
 * companions (its .bin, textures/) are still on their way waits for it. */
bool folder_watch_sync_under_way(const struct folder_watch *w, time_t now);

#endif
