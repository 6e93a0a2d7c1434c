/* Several models: the list a folder or a comma-separated list makes, its
 * cycling, passing over models that do not load (once logged, then
 * silently until the file changes), and a rescan that takes a new file
 * only once it arrived whole. The loader is a fake: no model is parsed. */
#include "content/model_list.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

static char dir[64];

static int make_dir(void **state)
{
	(void)state;
	strcpy(dir, "/tmp/mk-models-XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void touch(const char *name, const char *text)
{
	char path[256];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", dir, name);
	f = fopen(path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
}

static const char *name_of(const struct model_list *l, int i)
{
	return strrchr(model_list_path(l, i), '/') + 1;
}

/* The fake loader: a file whose text starts with "bad" does not load;
 * each try is counted. */
struct tries {
	int count;
};

static int fake_load(void *ctx, const char *path)
{
	struct tries *t = ctx;
	char text[8] = "";
	FILE *f = fopen(path, "r");

	t->count++;
	if (!f)
		return -2;
	if (!fgets(text, sizeof(text), f))
		text[0] = '\0';
	fclose(f);
	return strncmp(text, "bad", 3) == 0 ? -22 : 0;
}

static void folder_in_name_order(void **state)
{
	struct model_list *l;

	(void)state;
	touch("b.glb", "ok");
	touch("a.gltf", "ok");
	touch("c.GLB", "ok");
	touch("notes.txt", "not a model");
	touch(".hidden.glb", "ok");
	assert_true(model_spec_is_many(dir));
	l = model_list_new(dir);
	assert_non_null(l);
	assert_int_equal(model_list_count(l), 3);
	assert_string_equal(name_of(l, 0), "a.gltf");
	assert_string_equal(name_of(l, 1), "b.glb");
	assert_string_equal(name_of(l, 2), "c.GLB");
	/* Indices wrap both ways. */
	assert_string_equal(name_of(l, 3), "a.gltf");
	assert_string_equal(name_of(l, -1), "c.GLB");
	assert_int_equal(model_list_find(l, model_list_path(l, 1)), 1);
	assert_int_equal(model_list_find(l, "/nowhere.glb"), -1);
	model_list_free(l);
}

static void list_of_files_and_folders(void **state)
{
	char spec[512];
	struct model_list *l;

	(void)state;
	touch("a.glb", "ok");
	touch("z.glb", "ok");
	snprintf(spec, sizeof(spec), " %s/z.glb , %s,/x/y.gltf", dir, dir);
	assert_true(model_spec_is_many(spec));
	assert_false(model_spec_is_many("/x/one.glb"));
	assert_false(model_spec_is_many(NULL));
	l = model_list_new(spec);
	assert_non_null(l);
	/* In the list's order; a folder's files in name order where it is. */
	assert_int_equal(model_list_count(l), 4);
	assert_string_equal(name_of(l, 0), "z.glb");
	assert_string_equal(name_of(l, 1), "a.glb");
	assert_string_equal(name_of(l, 2), "z.glb");
	assert_string_equal(model_list_path(l, 3), "/x/y.gltf");
	model_list_free(l);
}

static void empty_folder_is_an_error(void **state)
{
	(void)state;
	assert_null(model_list_new(dir));
}

/* Three models, the middle one broken: next from the first passes over
 * it to the third; the broken one is tried once, then never again. */
static void broken_one_passed_over_once(void **state)
{
	struct tries t = {0};
	struct model_list *l;

	(void)state;
	touch("a.glb", "ok");
	touch("b.glb", "bad");
	touch("c.glb", "ok");
	l = model_list_new(dir);
	assert_int_equal(model_list_pick(l, 1, 1, 0, fake_load, &t), 2);
	assert_int_equal(t.count, 2);
	assert_true(model_list_bad(l, 1));
	/* Back from the third: passed over without a try. */
	t.count = 0;
	assert_int_equal(model_list_pick(l, 1, -1, 2, fake_load, &t), 0);
	assert_int_equal(t.count, 1);
	/* Round and round: the second never tried again. */
	t.count = 0;
	for (int i = 0; i < 6; i++)
		model_list_pick(l, i, 1, -1, fake_load, &t);
	assert_int_equal(t.count, 6);
	model_list_free(l);
}

/* Every other model broken: the walk ends at the one on screen, with
 * nothing loaded; with none on screen, -1. */
static void all_others_broken_keeps_the_shown(void **state)
{
	struct tries t = {0};
	struct model_list *l;

	(void)state;
	touch("a.glb", "ok");
	touch("b.glb", "bad");
	touch("c.glb", "bad");
	l = model_list_new(dir);
	assert_int_equal(model_list_pick(l, 1, 1, 0, fake_load, &t), 0);
	assert_int_equal(t.count, 2);
	model_list_set_bad(l, 0, true);
	assert_int_equal(model_list_pick(l, 0, 1, -1, fake_load, &t), -1);
	model_list_free(l);
}

static bool arrived_c(void *ctx, const char *path)
{
	(void)ctx;
	return strcmp(strrchr(path, '/'), "/c.glb") == 0;
}

/* A file that appears is taken only once it arrived whole; a broken file
 * that changed is tried again; one that did not change stays passed over. */
static void rescan_takes_whole_files(void **state)
{
	struct model_list *l, *n;
	int fresh;

	(void)state;
	touch("a.glb", "bad");
	touch("b.glb", "ok");
	l = model_list_new(dir);
	model_list_set_bad(l, 0, true);
	touch("c.glb", "ok");	/* closed: arrived */
	touch("d.glb", "half"); /* still being copied: no event yet */
	n = model_list_rescan(l, dir, arrived_c, NULL, &fresh);
	assert_non_null(n);
	assert_int_equal(model_list_count(n), 3);
	assert_string_equal(name_of(n, 2), "c.glb");
	assert_int_equal(fresh, 2);
	assert_true(model_list_bad(n, 0)); /* unchanged: still passed over */
	model_list_free(l);
	/* a.glb rewritten (another size): tried again. */
	touch("a.glb", "fixed now");
	l = model_list_rescan(n, dir, NULL, NULL, &fresh);
	assert_non_null(l);
	assert_false(model_list_bad(l, 0));
	assert_int_equal(fresh, -1);
	model_list_free(n);
	model_list_free(l);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test_setup_teardown(folder_in_name_order, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(list_of_files_and_folders, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(empty_folder_is_an_error, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(broken_one_passed_over_once, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(all_others_broken_keeps_the_shown, make_dir,
					    remove_dir),
	    cmocka_unit_test_setup_teardown(rescan_takes_whole_files, make_dir, remove_dir),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
