#include "util/folder_watch.h"
#include "util/file.h"
#include "util/log.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <libgen.h>
#include <stdlib.h>
#include <string.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

/* Written files count when closed, not on every write, so a slow copy is
 * one event at its end; renames cover editors and rsync, which write a
 * hidden temporary file and move it over the real name. */
#define WATCH_EVENTS                                                                               \
	(IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_DELETE | IN_DELETE_SELF | IN_MOVE_SELF)
/* A partial file (file_name_is_partial) written to within this long is a
 * sync under way; one older is what an interrupted sync left. */
#define PARTIAL_STALE_S 60
/* Subfolders looked into for partial files (textures/, as exporters
 * write them; deeper is no model's layout). */
#define PARTIAL_DEPTH 8

struct folder_watch {
	int fd;
	char *folder;
	char *name; /* the one file that counts, or NULL for all */
	char *also; /* a second name that counts with it (folder_watch_also) */
};

void folder_watch_free(struct folder_watch *w)
{
	if (!w)
		return;
	if (w->fd >= 0)
		close(w->fd);
	free(w->folder);
	free(w->name);
	free(w->also);
	free(w);
}

/* Split path into the folder to watch and the name that counts. */
static int split_path(struct folder_watch *w, const char *path)
{
	struct stat st;
	char *a, *b;

	if (stat(path, &st))
		return -errno;
	if (S_ISDIR(st.st_mode)) {
		w->folder = strdup(path);
		return w->folder ? 0 : -ENOMEM;
	}
	a = strdup(path);
	b = strdup(path);
	if (a && b) {
		w->folder = strdup(dirname(a));
		w->name = strdup(basename(b));
	}
	free(a);
	free(b);
	return w->folder && w->name ? 0 : -ENOMEM;
}

struct folder_watch *folder_watch_new(const char *path)
{
	struct folder_watch *w = calloc(1, sizeof(*w));
	int ret;

	if (!w)
		return NULL;
	w->fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
	ret = w->fd < 0 ? -errno : split_path(w, path);
	if (!ret && inotify_add_watch(w->fd, w->folder, WATCH_EVENTS) < 0)
		ret = -errno;
	if (ret) {
		log_warn("%s: cannot watch for new files (%s); a change needs a reload", path,
			 strerror(-ret));
		folder_watch_free(w);
		return NULL;
	}
	log_debug("watching %s for changes", w->folder);
	return w;
}

int folder_watch_fd(const struct folder_watch *w)
{
	return w->fd;
}

static bool counts(const struct folder_watch *w, const struct inotify_event *ev)
{
	/* A lost queue or a gone folder: look at everything. */
	return (ev->mask & (IN_Q_OVERFLOW | IN_DELETE_SELF | IN_MOVE_SELF)) || !w->name ||
	       (ev->len &&
		(strcmp(ev->name, w->name) == 0 || (w->also && strcmp(ev->name, w->also) == 0)));
}

int folder_watch_also(struct folder_watch *w, const char *name)
{
	if (!w->name)
		return 0;
	free(w->also);
	w->also = strdup(name);
	return w->also ? 0 : -ENOMEM;
}

bool folder_watch_read_names(struct folder_watch *w, folder_watch_arrived_fn arrived, void *ctx)
{
	/* Aligned as inotify(7) asks: events are read in place. */
	char buf[4096] __attribute__((aligned(__alignof__(struct inotify_event))));
	bool changed = false;
	ssize_t n;

	while ((n = read(w->fd, buf, sizeof(buf))) > 0) {
		for (char *p = buf; p < buf + n;) {
			const struct inotify_event *ev = (const struct inotify_event *)p;

			if (counts(w, ev)) {
				changed = true;
				/* A partial file is not whole: it arrives when
				 * it is renamed into place. */
				if (arrived && ev->len && !file_name_is_partial(ev->name) &&
				    (ev->mask & (IN_CLOSE_WRITE | IN_MOVED_TO)))
					arrived(ctx, w->folder, ev->name);
			}
			p += sizeof(*ev) + ev->len;
		}
	}
	return changed;
}

bool folder_watch_read(struct folder_watch *w)
{
	return folder_watch_read_names(w, NULL, NULL);
}

/* A partial file written to since `since`, in the folder open as fd or in
 * its subfolders (not through links); closes fd. */
static bool partial_in(int fd, time_t since, int depth)
{
	DIR *d = fdopendir(fd);
	struct dirent *e;
	struct stat st;
	bool found = false;

	if (!d) {
		close(fd);
		return false;
	}
	while (!found && (e = readdir(d))) {
		int sub;

		if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") ||
		    fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW))
			continue;
		if (S_ISREG(st.st_mode) && file_name_is_partial(e->d_name))
			found = st.st_mtime >= since;
		else if (S_ISDIR(st.st_mode) && e->d_name[0] != '.' && depth < PARTIAL_DEPTH &&
			 (sub = openat(dirfd(d), e->d_name,
				       O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC)) >= 0)
			found = partial_in(sub, since, depth + 1);
	}
	closedir(d);
	return found;
}

bool folder_watch_sync_under_way(const struct folder_watch *w, time_t now)
{
	int fd = open(w->folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);

	return fd >= 0 && partial_in(fd, now - PARTIAL_STALE_S, 0);
}
