/* util/file.c: whole files read (and what is not a file refused without
 * blocking), and files replaced whole or not at all. */
#include "util/file.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>
#include <cmocka.h>

static int setup(void **state)
{
	char *dir = strdup("/tmp/mk-file-XXXXXX");

	if (!dir || !mkdtemp(dir))
		return -1;
	*state = dir;
	return 0;
}

static int teardown(void **state)
{
	char cmd[64];

	snprintf(cmd, sizeof(cmd), "rm -rf %s", (char *)*state);
	free(*state);
	return system(cmd);
}

static int entries(const char *dir)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	int n = 0;

	while (d && (e = readdir(d)))
		n += e->d_name[0] != '.' || (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."));
	if (d)
		closedir(d);
	return n;
}

static void expect_text(const char *path, const char *text)
{
	unsigned char *data;
	size_t size;

	assert_int_equal(file_read_all(path, 1 << 20, &data, &size), 0);
	assert_int_equal(size, strlen(text));
	assert_string_equal((const char *)data, text); /* one NUL past the end */
	free(data);
}

/* Committed: the new bytes with the mode asked, nothing else left in the
 * folder. Failed: the old file untouched, no temporary file left. */
static void replaced_whole_or_not_at_all(void **state)
{
	const char *dir = *state;
	char path[128];
	struct file_atomic a;
	struct stat st;

	snprintf(path, sizeof(path), "%s/state.json", dir);
	assert_int_equal(file_atomic_begin(&a, path, 0600), 0);
	assert_int_equal(write(a.fd, "one", 3), 3);
	assert_int_equal(entries(dir), 1); /* only the temporary file so far */
	assert_int_equal(access(path, F_OK), -1);
	assert_int_equal(file_atomic_end(&a, 0, true), 0);
	expect_text(path, "one");
	assert_int_equal(stat(path, &st), 0);
	assert_int_equal(st.st_mode & 0777, 0600);
	assert_int_equal(entries(dir), 1);

	assert_int_equal(file_atomic_begin(&a, path, 0644), 0);
	assert_int_equal(write(a.fd, "two!", 4), 4);
	assert_int_equal(file_atomic_end(&a, -EIO, true), -EIO);
	expect_text(path, "one");
	assert_int_equal(entries(dir), 1);

	/* A writer that takes a path writes the temporary file by name. */
	assert_int_equal(file_atomic_begin(&a, path, 0644), 0);
	{
		FILE *f = fopen(a.tmp, "w");

		fputs("three", f);
		fclose(f);
	}
	assert_int_equal(file_atomic_end(&a, 0, false), 0);
	expect_text(path, "three");
	assert_int_equal(entries(dir), 1);

	snprintf(path, sizeof(path), "%s/missing/x", dir);
	assert_int_equal(file_atomic_begin(&a, path, 0644), -ENOENT);
}

static void read_refuses(void **state)
{
	const char *dir = *state;
	unsigned char *data;
	size_t size;

	assert_int_equal(file_read_all(dir, 1 << 20, &data, &size), -EISDIR);
	assert_null(data);
	assert_int_equal(file_read_all("/nonexistent/m.glb", 1, &data, &size), -ENOENT);
	assert_int_equal(file_read_all("/proc/self/exe", 16, &data, &size), -EFBIG);
}

/* What a stranger may leave where a model or a picture is expected: each
 * refused at once, saying what it is. The old open() of a FIFO blocked
 * until a writer came: the alarm ends such a test instead of hanging. */
static void refuses_what_is_not_a_file(void **state)
{
	const char *dir = *state;
	struct sockaddr_un sa = {.sun_family = AF_UNIX};
	char fifo[128], link[128], file[128];
	unsigned char *data = (unsigned char *)"x";
	size_t size = 1;
	int sock = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0), fd;

	snprintf(fifo, sizeof(fifo), "%s/m.glb", dir);
	snprintf(link, sizeof(link), "%s/link.png", dir);
	snprintf(file, sizeof(file), "%s/real.png", dir);
	snprintf(sa.sun_path, sizeof(sa.sun_path), "%s/s.png", dir);
	assert_int_equal(mkfifo(fifo, 0600), 0);
	assert_int_equal(bind(sock, (struct sockaddr *)&sa, sizeof(sa)), 0);
	fclose(fopen(file, "w"));
	assert_int_equal(symlink(file, link), 0);
	alarm(10);
	assert_int_equal(file_read_all(fifo, 1 << 20, &data, &size), -ESPIPE);
	assert_null(data);
	assert_int_equal(size, 0);
	assert_string_equal(file_refusal(-ESPIPE), "is a FIFO, not a file");
	assert_int_equal(file_read_all("/dev/null", 1 << 20, &data, &size), -ENODEV);
	assert_string_equal(file_refusal(-ENODEV), "is a device node, not a file");
	assert_int_equal(file_read_all(sa.sun_path, 1 << 20, &data, &size), -ENXIO);
	assert_int_equal(file_open_read(fifo, FILE_NOFOLLOW, NULL), -ESPIPE);
	alarm(0);
	assert_null(file_refusal(-ENOENT));
	/* A link: refused where asked, followed otherwise. */
	assert_int_equal(file_open_read(link, FILE_NOFOLLOW, NULL), -ELOOP);
	fd = file_open_read(link, 0, NULL);
	assert_true(fd >= 0);
	assert_true(fcntl(fd, F_GETFL) & O_NONBLOCK);
	assert_true(fcntl(fd, F_GETFD) & FD_CLOEXEC);
	close(fd);
	expect_text(link, "");
	close(sock);
}

/* A FIFO named like a picture in a folder is passed over (with a warning),
 * not listed for a reader to open. */
static void lists_no_fifo(void **state)
{
	static const char *const exts[] = {"png", NULL};
	const char *dir = *state;
	char path[128], **paths;
	int n;

	snprintf(path, sizeof(path), "%s/a.png", dir);
	assert_int_equal(mkfifo(path, 0600), 0);
	snprintf(path, sizeof(path), "%s/b.png", dir);
	fclose(fopen(path, "w"));
	snprintf(path, sizeof(path), "%s/c.png", dir);
	assert_int_equal(mkdir(path, 0700), 0);
	assert_int_equal(file_list_folder(dir, exts, &paths, &n), 0);
	assert_int_equal(n, 1);
	snprintf(path, sizeof(path), "%s/b.png", dir);
	assert_string_equal(paths[0], path);
	file_list_free(paths, n);
}

/* A folder's files of some kinds, hidden ones left out, in name order. */
static void lists_a_folder(void **state)
{
	static const char *const exts[] = {"png", "jpg", NULL};
	static const char *const names[] = {
	    "b.PNG",	  "a.jpg",	   ".hidden.png",      "c.txt",
	    "d.png.part", ".e.png.x8Yz1Q", "~syncthing~f.png", ".syncthing.g.png.tmp"};
	const char *dir = *state;
	char path[128], **paths;
	int n;

	for (size_t i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
		snprintf(path, sizeof(path), "%s/%s", dir, names[i]);
		fclose(fopen(path, "w"));
	}
	assert_int_equal(file_list_folder(dir, exts, &paths, &n), 0);
	assert_int_equal(n, 2);
	snprintf(path, sizeof(path), "%s/a.jpg", dir);
	assert_string_equal(paths[0], path);
	snprintf(path, sizeof(path), "%s/b.PNG", dir);
	assert_string_equal(paths[1], path);
	file_list_free(paths, n);
	assert_true(file_name_has_ext("x.JPG", exts));
	/* rsync's, Syncthing's (Linux, and where dot files are not hidden). */
	assert_true(file_name_is_partial(".model.glb.x8Yz1Q"));
	assert_true(file_name_is_partial(".syncthing.model.glb.tmp"));
	assert_true(file_name_is_partial("~syncthing~model.glb.tmp"));
	assert_false(file_name_is_partial("model.glb"));
	assert_false(file_name_is_partial("syncthing.glb"));
	assert_false(file_name_has_ext("png", exts));
	/* A folder of our own that is not there (/nonexistent may be: it is
	 * nobody's home, and a program run as nobody makes its caches there). */
	snprintf(path, sizeof(path), "%s/missing", dir);
	assert_int_equal(file_list_folder(path, exts, &paths, &n), -ENOENT);
	assert_null(paths);
	assert_int_equal(n, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(replaced_whole_or_not_at_all),
	    cmocka_unit_test(read_refuses),
	    cmocka_unit_test(lists_a_folder),
	    cmocka_unit_test_setup_teardown(refuses_what_is_not_a_file, setup, teardown),
	    cmocka_unit_test_setup_teardown(lists_no_fifo, setup, teardown),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
