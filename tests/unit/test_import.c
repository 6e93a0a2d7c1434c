/* ops/import_copy.c: which names of a USB stick are taken and how the
 * journal shows the others; the stick sized before a byte is copied, and
 * what is not a plain file passed over without being opened. */
#include "ops/import_copy.h"

#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <cmocka.h>

static void names_of_printable_text_only(void **state)
{
	(void)state;
	assert_true(import_name_printable("scene.gltf"));
	assert_true(import_name_printable("été ☀ 🙂.png")); /* UTF-8: 2, 3 and 4 bytes */
	assert_true(import_name_printable("a;b=[c].png")); /* INI's own rules are not these */
	assert_false(import_name_printable("x\n<0>forged.png"));
	assert_false(import_name_printable("tab\there"));
	assert_false(import_name_printable("del\x7f"));
	assert_false(import_name_printable("c1\xc2\x85nel"));	 /* U+0085, a C1 control */
	assert_false(import_name_printable("latin1 \xe9t\xe9")); /* not UTF-8 */
	assert_false(import_name_printable("over\xc0\xaflong")); /* '/' overlong */
	assert_false(import_name_printable("surrogate\xed\xa0\x80"));
	assert_false(import_name_printable("cut\xe2\x98"));
}

static void names_escaped_in_one_line(void **state)
{
	char buf[64];

	(void)state;
	assert_string_equal(import_name_escape("x\n<0>forged", buf, sizeof(buf)), "x\\n<0>forged");
	assert_string_equal(import_name_escape("a\x01\t\r\\\x7f", buf, sizeof(buf)),
			    "a\\x01\\t\\r\\\\\\x7f");
	assert_string_equal(import_name_escape("\xe9t\xc3\xa9", buf, sizeof(buf)),
			    "\\xe9t\xc3\xa9");
	/* Cut to the buffer, never inside an escape. */
	assert_string_equal(import_name_escape("ab\x01", buf, 6), "ab");
	assert_string_equal(import_name_escape("abcdefgh", buf, 4), "abc");
}

struct stick {
	char dir[64];	   /* matcap-kiosk/ */
	char staging[128]; /* the copy */
	struct import_files f;
};

static void put(const struct stick *s, const char *name, off_t size)
{
	char path[256];
	int fd;

	snprintf(path, sizeof(path), "%s/%s", s->dir, name);
	fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
	assert_true(fd >= 0);
	assert_int_equal(ftruncate(fd, size), 0); /* sparse: nothing is written */
	close(fd);
}

static int setup(void **state)
{
	struct stick *s = calloc(1, sizeof(*s));
	char sub[128];

	if (!s)
		return -1;
	snprintf(s->dir, sizeof(s->dir), "/tmp/mk-import-XXXXXX");
	if (!mkdtemp(s->dir))
		return -1;
	snprintf(s->staging, sizeof(s->staging), "%s/.staging", s->dir);
	snprintf(sub, sizeof(sub), "%s/matcaps", s->dir);
	if (mkdir(sub, 0755))
		return -1;
	snprintf(sub, sizeof(sub), "%s/textures", s->dir);
	if (mkdir(sub, 0755))
		return -1;
	s->f.from = s->dir;
	s->f.from_fd = open(s->dir, O_RDONLY | O_DIRECTORY);
	s->f.to = s->staging;
	s->f.budget = 10ll << 20;
	*state = s;
	return s->f.from_fd < 0 ? -1 : 0;
}

static int teardown(void **state)
{
	struct stick *s = *state;
	char cmd[128];
	int ret;

	close(s->f.from_fd);
	snprintf(cmd, sizeof(cmd), "rm -rf %s", s->dir);
	ret = system(cmd);
	free(s);
	return ret;
}

/* Over the budget: refused by the sizing walk, which writes nothing, and
 * names the largest files; a file it does not take is not counted. */
static void sized_before_a_byte_is_copied(void **state)
{
	struct stick *s = *state;

	put(s, "a.glb", 1000);
	put(s, "textures/big.png", 6 << 20);
	put(s, "matcaps/big.png", 5 << 20);
	put(s, "huge.iso", 1ll << 30); /* not taken */
	assert_int_equal(import_files_size(&s->f), -EFBIG);
	assert_int_equal(s->f.total, (11 << 20) + 1000);
	assert_string_equal(s->f.largest[0].path, "textures/big.png");
	assert_string_equal(s->f.largest[1].path, "matcaps/big.png");
	assert_string_equal(s->f.largest[2].path, "a.glb");
	assert_int_equal(access(s->staging, F_OK), -1);
	/* Under the budget: sized, then copied, the same files. */
	s->f.budget = 12ll << 20;
	assert_int_equal(import_files_size(&s->f), 0);
	assert_int_equal(mkdir(s->staging, 0755), 0);
	assert_int_equal(import_files_copy(&s->f), 0);
	assert_int_equal(s->f.files, 2);
	assert_int_equal(s->f.matcaps, 1);
	assert_string_equal(s->f.model, "a.glb");
	assert_int_equal(s->f.total, (11 << 20) + 1000);
}

/* A file that grew between the sizing and the copy: the copy stops at
 * the budget too. */
static void copy_stops_at_the_budget(void **state)
{
	struct stick *s = *state;

	put(s, "a.glb", 1000);
	put(s, "textures/big.png", 6 << 20);
	assert_int_equal(import_files_size(&s->f), 0);
	put(s, "textures/big.png", 12 << 20);
	assert_int_equal(mkdir(s->staging, 0755), 0);
	assert_int_equal(import_files_copy(&s->f), -EFBIG);
	assert_int_equal(s->f.files, 1); /* a.glb, before it */
}

/* A pipe under each folder, a link and a control character in a name:
 * passed over (a pipe opened for reading would wait for a writer), the
 * rest copied. */
static void only_plain_files_with_printable_names(void **state)
{
	struct stick *s = *state;
	char path[256];
	struct stat st;

	put(s, "a.glb", 100);
	put(s, "matcaps/x\n<0>.png", 100);
	put(s, "textures/ok.png", 100);
	snprintf(path, sizeof(path), "%s/b.bin", s->dir);
	assert_int_equal(mkfifo(path, 0644), 0);
	snprintf(path, sizeof(path), "%s/matcaps/p.png", s->dir);
	assert_int_equal(mkfifo(path, 0644), 0);
	snprintf(path, sizeof(path), "%s/textures/l.png", s->dir);
	assert_int_equal(symlink("/etc/passwd", path), 0);
	assert_int_equal(import_files_size(&s->f), 0);
	assert_int_equal(s->f.skipped, 4);
	assert_int_equal(mkdir(s->staging, 0755), 0);
	assert_int_equal(import_files_copy(&s->f), 0);
	assert_int_equal(s->f.files, 2);
	assert_int_equal(s->f.matcaps, 0);
	snprintf(path, sizeof(path), "%s/model/textures/ok.png", s->staging);
	assert_int_equal(stat(path, &st), 0);
	snprintf(path, sizeof(path), "%s/model/b.bin", s->staging);
	assert_int_equal(lstat(path, &st), -1);
	snprintf(path, sizeof(path), "%s/matcaps/x\n<0>.png", s->staging);
	assert_int_equal(lstat(path, &st), -1);
}

/* A device node is passed over by its type alone (on a stick mounted
 * nodev, as the import unit mounts it, opening it fails: that refused the
 * whole stick). mknod needs root: skipped otherwise. */
static void devices_passed_over(void **state)
{
	struct stick *s = *state;
	char path[256];

	snprintf(path, sizeof(path), "%s/matcaps/null.png", s->dir);
	if (mknod(path, S_IFCHR | 0644, makedev(1, 3)))
		skip();
	put(s, "matcaps/ok.png", 100);
	assert_int_equal(import_files_size(&s->f), 0);
	assert_int_equal(s->f.skipped, 1);
	assert_int_equal(s->f.total, 100);
	assert_int_equal(mkdir(s->staging, 0755), 0);
	assert_int_equal(import_files_copy(&s->f), 0);
	assert_int_equal(s->f.matcaps, 1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(names_of_printable_text_only),
	    cmocka_unit_test(names_escaped_in_one_line),
	    cmocka_unit_test_setup_teardown(sized_before_a_byte_is_copied, setup, teardown),
	    cmocka_unit_test_setup_teardown(copy_stops_at_the_budget, setup, teardown),
	    cmocka_unit_test_setup_teardown(only_plain_files_with_printable_names, setup, teardown),
	    cmocka_unit_test_setup_teardown(devices_passed_over, setup, teardown),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
