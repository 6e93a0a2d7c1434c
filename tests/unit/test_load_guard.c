/* The live kiosk's crash memory (content/load_guard.h), as a restart meets
 * it: a marker left by a process that died loading a model puts that model
 * on the skip list; a changed file is tried again; a marker from before a
 * reboot proves nothing. */
#include "content/load_guard.h"
#include "util/log.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

struct fixture {
	char dir[64];	   /* the models */
	char state[80];	   /* the state folder */
	char a[96], b[96]; /* two models */
	char marker[128];  /* state/loading */
	char skip[128];	   /* state/skip */
};

static void put(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	assert_non_null(f);
	fputs(text, f);
	assert_int_equal(fclose(f), 0);
}

/* The file's text, or "" when absent. */
static const char *text_of(const char *path)
{
	static char buf[4096];
	FILE *f = fopen(path, "r");
	size_t n = f ? fread(buf, 1, sizeof(buf) - 1, f) : 0;

	if (f)
		fclose(f);
	buf[n] = '\0';
	return buf;
}

static int lines_of(const char *path)
{
	int n = 0;

	for (const char *t = text_of(path); *t; t++)
		n += *t == '\n';
	return n;
}

static int setup(void **state)
{
	struct fixture *f = calloc(1, sizeof(*f));

	strcpy(f->dir, "/tmp/mk-guard-XXXXXX");
	if (!mkdtemp(f->dir))
		return -1;
	snprintf(f->state, sizeof(f->state), "%s/state", f->dir);
	snprintf(f->a, sizeof(f->a), "%s/a.glb", f->dir);
	snprintf(f->b, sizeof(f->b), "%s/b.glb", f->dir);
	snprintf(f->marker, sizeof(f->marker), "%s/%s", f->state, LOAD_GUARD_MARKER);
	snprintf(f->skip, sizeof(f->skip), "%s/%s", f->state, LOAD_GUARD_SKIP);
	if (mkdir(f->state, 0755))
		return -1;
	put(f->a, "model a");
	put(f->b, "model b");
	*state = f;
	return 0;
}

static int teardown(void **state)
{
	struct fixture *f = *state;
	char cmd[128];

	snprintf(cmd, sizeof(cmd), "rm -rf %s", f->dir);
	free(f);
	return system(cmd);
}

/* A load that ends (well or not) leaves nothing behind. */
static void a_load_that_ends_leaves_no_marker(void **state)
{
	struct fixture *f = *state;

	assert_int_equal(load_guard_enter(f->state, f->a), 0);
	assert_non_null(strstr(text_of(f->marker), f->a));
	assert_int_equal(strncmp(text_of(f->marker), "boot ", 5), 0);
	load_guard_leave(f->state);
	assert_int_equal(access(f->marker, F_OK), -1);
	assert_int_equal(load_guard_recover(f->state), 0);
	assert_false(load_guard_skipped(f->state, f->a));
	assert_int_equal(lines_of(f->skip), 0);
}

/* The process died loading a: the next start passes it over, with one
 * error naming it, and loads b. */
static void a_marker_left_at_start_skips_its_model(void **state)
{
	struct fixture *f = *state;
	char err[512], want[512];

	assert_int_equal(load_guard_enter(f->state, f->a), 0);
	/* ... killed here: no load_guard_leave. The next process: */
	log_clear_last_error();
	assert_int_equal(load_guard_recover(f->state), 1);
	log_last_error(err, sizeof(err));
	snprintf(want, sizeof(want),
		 "%s: the last start died while loading it (the process was killed); skipped "
		 "until it changes",
		 f->a);
	assert_string_equal(err, want);
	assert_int_equal(access(f->marker, F_OK), -1);
	assert_true(load_guard_skipped(f->state, f->a));
	assert_false(load_guard_skipped(f->state, f->b));
	assert_int_equal(load_guard_enter(f->state, f->a), -ECANCELED);
	log_last_error(err, sizeof(err));
	assert_non_null(strstr(err, "skipped: the kiosk died while loading it before"));
	assert_int_equal(access(f->marker, F_OK), -1);
	assert_int_equal(load_guard_enter(f->state, f->b), 0);
	load_guard_leave(f->state);
	/* Every start after passes it over too. */
	assert_int_equal(load_guard_recover(f->state), 0);
	assert_int_equal(load_guard_enter(f->state, f->a), -ECANCELED);
	assert_int_equal(lines_of(f->skip), 1);
}

/* The marker is found at the next load too (load_guard_enter recovers):
 * the start needs no step of its own. */
static void the_next_load_finds_the_marker(void **state)
{
	struct fixture *f = *state;

	assert_int_equal(load_guard_enter(f->state, f->a), 0);
	assert_int_equal(load_guard_enter(f->state, f->b), 0);
	load_guard_leave(f->state);
	assert_true(load_guard_skipped(f->state, f->a));
	assert_false(load_guard_skipped(f->state, f->b));
}

/* The file replaced (another size) or rewritten (another mtime, same
 * size): tried again. */
static void a_changed_file_is_tried_again(void **state)
{
	struct fixture *f = *state;
	struct timespec t[2] = {{0, UTIME_OMIT}, {1000000000, 5}};

	assert_int_equal(load_guard_enter(f->state, f->a), 0);
	assert_int_equal(load_guard_recover(f->state), 1);
	assert_true(load_guard_skipped(f->state, f->a));
	put(f->a, "model a, fixed");
	assert_false(load_guard_skipped(f->state, f->a));
	assert_int_equal(load_guard_enter(f->state, f->a), 0);
	assert_int_equal(load_guard_recover(f->state), 1);
	assert_true(load_guard_skipped(f->state, f->a));
	assert_int_equal(utimensat(AT_FDCWD, f->a, t, 0), 0);
	assert_false(load_guard_skipped(f->state, f->a));
	assert_int_equal(load_guard_enter(f->state, f->a), 0);
	load_guard_leave(f->state);
	/* The list dropped the entries of files that changed since. */
	assert_int_equal(lines_of(f->skip), 1);
}

/* The power cut while a model loaded: the marker is from another boot,
 * no proof against the model. */
static void a_marker_from_an_earlier_boot_is_dropped(void **state)
{
	struct fixture *f = *state;
	char text[512];
	struct stat st;

	assert_int_equal(stat(f->a, &st), 0);
	snprintf(text, sizeof(text),
		 "boot 00000000-0000-0000-0000-000000000000\n%lld %lld.%09ld %s\n",
		 (long long)st.st_size, (long long)st.st_mtim.tv_sec, st.st_mtim.tv_nsec, f->a);
	put(f->marker, text);
	assert_int_equal(load_guard_recover(f->state), 0);
	assert_int_equal(access(f->marker, F_OK), -1);
	assert_false(load_guard_skipped(f->state, f->a));
	/* Something else there: removed, nothing skipped. */
	put(f->marker, "garbage");
	assert_int_equal(load_guard_recover(f->state), 0);
	assert_int_equal(access(f->marker, F_OK), -1);
}

/* A name with a newline stays one record, and what the journal shows of
 * it is escaped. */
static void a_name_with_a_newline_is_one_record(void **state)
{
	struct fixture *f = *state;
	char odd[128], err[512];

	snprintf(odd, sizeof(odd), "%s/x\n<0>forged%%.glb", f->dir);
	put(odd, "model x");
	assert_int_equal(load_guard_enter(f->state, odd), 0);
	assert_int_equal(load_guard_recover(f->state), 1);
	log_last_error(err, sizeof(err));
	assert_null(strchr(err, '\n'));
	assert_non_null(strstr(err, "x%0A<0>forged%25.glb"));
	assert_true(load_guard_skipped(f->state, odd));
	assert_int_equal(lines_of(f->skip), 1);
	/* Pruning reads it back as the same file. */
	assert_int_equal(load_guard_enter(f->state, f->b), 0);
	assert_int_equal(load_guard_recover(f->state), 1);
	assert_true(load_guard_skipped(f->state, odd));
	assert_int_equal(lines_of(f->skip), 2);
}

/* Without $STATE_DIRECTORY (started by hand) nothing is remembered; the
 * first folder of a list is the one. */
static void the_folder_is_systemds(void **state)
{
	char buf[64];

	(void)state;
	unsetenv("STATE_DIRECTORY");
	assert_int_equal(load_guard_dir(buf, sizeof(buf)), -ENOENT);
	setenv("STATE_DIRECTORY", "/var/lib/a:/var/lib/b", 1);
	assert_int_equal(load_guard_dir(buf, sizeof(buf)), 0);
	assert_string_equal(buf, "/var/lib/a");
	unsetenv("STATE_DIRECTORY");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test_setup_teardown(a_load_that_ends_leaves_no_marker, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_marker_left_at_start_skips_its_model, setup,
					    teardown),
	    cmocka_unit_test_setup_teardown(the_next_load_finds_the_marker, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_changed_file_is_tried_again, setup, teardown),
	    cmocka_unit_test_setup_teardown(a_marker_from_an_earlier_boot_is_dropped, setup,
					    teardown),
	    cmocka_unit_test_setup_teardown(a_name_with_a_newline_is_one_record, setup, teardown),
	    cmocka_unit_test(the_folder_is_systemds),
	};
	return cmocka_run_group_tests_name("load_guard", tests, NULL, NULL);
}
