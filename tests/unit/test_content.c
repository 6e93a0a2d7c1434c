/* The scene loader that the start and a reload share, the second parse of
 * the command line that a reload does, and the matcap folder watch. */
#include "util/folder_watch.h"
#include "util/log.h"
#include "config/options.h"
#include "content/content.h"
#include "state/app.h"

#include <errno.h>
#include <poll.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>

static char dir[64];

static int make_dir(void **state)
{
	(void)state;
	strcpy(dir, "/tmp/mk-scene-XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void copy_matcap(const char *from, const char *to)
{
	char cmd[256];

	snprintf(cmd, sizeof(cmd), "cp matcaps/%s %s/%s", from, dir, to);
	assert_int_equal(system(cmd), 0);
}

static void write_text(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	assert_non_null(f);
	fputs(text, f);
	fclose(f);
}

static void falls_back_unless_strict(void **state)
{
	struct content_config o = {.model = "/nonexistent/model.glb", .matcap = "/nonexistent/mc"};
	struct content s;

	(void)state;
	/* The kiosk keeps showing something: the knot and the clay. */
	assert_int_equal(content_load(&s, &o, false), 0);
	assert_true(s.mesh.index_count > 0);
	assert_null(s.set);
	assert_null(s.matcap_path);
	assert_int_equal(s.matcap.width, 256);
	content_release(&s);
	/* A reload (strict) refuses, and leaves nothing to free. */
	assert_int_not_equal(content_load(&s, &o, true), 0);
	assert_int_equal(s.mesh.index_count, 0);
	assert_null(s.set);
	o.model = NULL;
	assert_int_not_equal(content_load(&s, &o, true), 0);
	assert_null(s.matcap.rgba);
}

static void ends_with(const char *path, const char *tail)
{
	size_t n = strlen(path), t = strlen(tail);

	if (n < t || strcmp(path + n - t, tail))
		fail_msg("%s does not end with %s", path, tail);
}

/* A w x h matcap of one colour into dir/name. */
static void flat_matcap(const char *name, uint8_t r, uint8_t g, uint8_t b)
{
	struct image img;
	char path[128];

	assert_int_equal(image_alloc(&img, 32, 32), 0);
	for (int i = 0; i < 32 * 32; i++) {
		img.rgba[i * 4] = r, img.rgba[i * 4 + 1] = g, img.rgba[i * 4 + 2] = b;
		img.rgba[i * 4 + 3] = 255;
	}
	snprintf(path, sizeof(path), "%s/%s", dir, name);
	assert_int_equal(image_write_png(path, &img), 0);
	image_release(&img);
}

/* One triangle of baseColorFactor rgb ("" for no material) into dir/name. */
static void triangle_model(const char *name, const char *rgb)
{
	char path[128], json[1024], material[160] = "";

	if (*rgb)
		snprintf(material, sizeof(material),
			 ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[%s,1]}}]",
			 rgb);
	snprintf(json, sizeof(json),
		 "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":36,\"uri\":"
		 "\"data:application/octet-stream;base64,"
		 "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}],\"bufferViews\":[{"
		 "\"buffer\":0,\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,"
		 "\"componentType\":5126,\"count\":3,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":"
		 "[1,1,0]}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}%s}]}],"
		 "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0%s}",
		 *rgb ? ",\"material\":0" : "", material);
	snprintf(path, sizeof(path), "%s/%s", dir, name);
	write_text(path, json);
}

/* The chroma measure: a neutral grey has none, a gold tint much; the
 * corners outside the disk are not counted. */
static void matcap_chroma(void **state)
{
	struct image img;
	struct matcap_tint grey, gold;

	(void)state;
	assert_int_equal(image_alloc(&img, 16, 16), 0);
	for (int i = 0; i < 16 * 16; i++)
		memcpy(img.rgba + i * 4, (const uint8_t[4]){128, 128, 128, 255}, 4);
	img.rgba[3] = 0, img.rgba[0] = 255; /* a corner, never drawn */
	matcap_measure(&img, &grey);
	for (int i = 0; i < 16 * 16; i++)
		memcpy(img.rgba + i * 4, (const uint8_t[4]){230, 180, 60, 255}, 4);
	matcap_measure(&img, &gold);
	image_release(&img);
	assert_true(grey.chroma == 0 && grey.value == 128);
	assert_true(gold.chroma == 170 && gold.value == 230);
}

/* [scene] matcap_first = auto (the default): a coloured model starts on
 * the folder's least tinted matcap bright enough to show a colour (not
 * the dark grey, not the first by name, the gold one), or on one called
 * pearl; an uncoloured one (no material, or white) on the first by name;
 * a name set by hand wins. Gold used to multiply the blue: olive. */
static void matcap_first_auto(void **state)
{
	char blue[128], white[128];
	struct content_config o = {.matcap = dir, .model = blue};
	struct content s;

	(void)state;
	snprintf(blue, sizeof(blue), "%s/blue.gltf", dir);
	snprintf(white, sizeof(white), "%s/white.gltf", dir);
	triangle_model("blue.gltf", "0.1,0.2,0.9");
	triangle_model("white.gltf", "1,1,1");
	flat_matcap("a-gold.png", 230, 180, 60);
	flat_matcap("b-dark.png", 20, 20, 20);
	flat_matcap("c-grey.png", 200, 196, 190);
	flat_matcap("d-red.png", 200, 60, 50);
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/c-grey.png");
	ends_with(matcap_set_path(s.set, 1), "/d-red.png");
	/* A rescan starts where auto chose. */
	assert_int_equal(content_rescan_matcaps(&s), 0);
	ends_with(matcap_set_path(s.set, 0), "/c-grey.png");
	content_release(&s);
	o.matcap_first = "auto";
	o.model = white;
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/a-gold.png");
	content_release(&s);
	o.model = NULL; /* the knot */
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/a-gold.png");
	content_release(&s);
	o.model = blue;
	o.matcap_first = "d-red";
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/d-red.png");
	content_release(&s);
	/* [material] base_color = off: the colours are not drawn. */
	o.matcap_first = NULL;
	o.material.base_color = MATERIAL_OFF;
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/a-gold.png");
	content_release(&s);
	o.material.base_color = MATERIAL_AUTO;
	flat_matcap("pearl.png", 240, 200, 200);
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/pearl.png");
	content_release(&s);
	/* The shipped folder: pearl for the blue model. */
	o.matcap = NULL;
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/pearl.png");
	content_release(&s);
}

/* [scene] matcap_first: where a folder's cycle starts, the rest in name
 * order and round; a name that is not there starts at the first (and
 * says so); a rescan starts there again. The shipped folder starts at
 * gold, where nothing is set. */
static void matcap_first(void **state)
{
	struct content_config o = {.matcap = dir};
	struct content s;
	char path[128];

	(void)state;
	copy_matcap("gold.png", "a.png");
	copy_matcap("pearl.png", "b.png");
	copy_matcap("skin.png", "c.png");
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/a.png");
	content_release(&s);
	o.matcap_first = "c";
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/c.png");
	ends_with(matcap_set_path(s.set, 1), "/a.png");
	ends_with(matcap_set_path(s.set, 2), "/b.png");
	copy_matcap("clay-red.png", "0.png");
	assert_int_equal(content_rescan_matcaps(&s), 0);
	ends_with(matcap_set_path(s.set, 0), "/c.png");
	ends_with(matcap_set_path(s.set, 1), "/0.png");
	content_release(&s);
	snprintf(path, sizeof(path), "%s/0.png", dir);
	unlink(path);
	o.matcap_first = "b.png";
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/b.png");
	content_release(&s);
	o.matcap_first = "nothing-called-this";
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/a.png");
	content_release(&s);
	/* The shipped folder (the tests run from the source tree). */
	o = (struct content_config){0};
	assert_int_equal(content_load(&s, &o, true), 0);
	ends_with(matcap_set_path(s.set, 0), "/gold.png");
	content_release(&s);
}

static void rescans_the_folder(void **state)
{
	struct content_config o = {.matcap = dir};
	struct content s;
	char path[128];

	(void)state;
	copy_matcap("gold.png", "b.png");
	assert_int_equal(content_load(&s, &o, true), 0);
	assert_string_equal(s.matcap_path, dir);
	assert_int_equal(matcap_set_count(s.set), 1);
	copy_matcap("pearl.png", "a.png");
	assert_int_equal(content_rescan_matcaps(&s), 0);
	assert_int_equal(matcap_set_count(s.set), 2);
	snprintf(path, sizeof(path), "%s/a.png", dir);
	assert_string_equal(matcap_set_path(s.set, 0), path);
	/* An emptied folder keeps the set known before. */
	unlink(path);
	snprintf(path, sizeof(path), "%s/b.png", dir);
	unlink(path);
	assert_int_not_equal(content_rescan_matcaps(&s), 0);
	assert_int_equal(matcap_set_count(s.set), 2);
	content_release(&s);
}

/* A reload parses the same command line again over the file as it is
 * now: the file's new values show, the command line still wins. */
static void second_parse_sees_the_new_file(void **state)
{
	char ini[128];
	char *argv[] = {"mk", "--config", ini, "--mode", "normal", "-q", NULL};
	struct options a, b;

	(void)state;
	snprintf(ini, sizeof(ini), "%s/kiosk.ini", dir);
	write_text(ini, "[scene]\nyaw = 10\nmode = view\n");
	assert_int_equal(options_parse(&a, 6, argv), 0);
	write_text(ini, "[scene]\nyaw = 45\nmode = sem-vertex\nmodel = m.glb\n");
	assert_int_equal(options_parse(&b, 6, argv), 0);
	assert_true(a.content.yaw == 10 && b.content.yaw == 45);
	assert_int_equal(a.content.mode, SHADING_NORMAL);
	assert_int_equal(b.content.mode, SHADING_NORMAL);
	assert_int_equal(b.log_level, LOG_WARN);
	{ /* a relative path: the file's folder's */
		char want[160];

		snprintf(want, sizeof(want), "%s/m.glb", dir);
		assert_string_equal(b.content.model, want);
	}
	options_release(&a);
	options_release(&b);
	write_text(ini, "[scene]\nyaw = east\n");
	assert_int_equal(options_parse(&b, 6, argv), OPTIONS_CONFIG);
	options_release(&b);
}

static bool changed_within(struct folder_watch *w, int ms)
{
	struct pollfd p = {.fd = folder_watch_fd(w), .events = POLLIN};

	return poll(&p, 1, ms) > 0 && folder_watch_read(w);
}

static void watch_reports_written_and_moved_files(void **state)
{
	struct folder_watch *w = folder_watch_new(dir);
	char a[128], b[128];

	(void)state;
	assert_non_null(w);
	snprintf(a, sizeof(a), "%s/new.png", dir);
	write_text(a, "x");
	assert_true(changed_within(w, 1000));
	assert_false(changed_within(w, 50));
	snprintf(b, sizeof(b), "%s/moved.png", dir);
	assert_int_equal(rename(a, b), 0);
	assert_true(changed_within(w, 1000));
	unlink(b);
	assert_true(changed_within(w, 1000));
	folder_watch_free(w);
}

static void watch_of_one_file_ignores_the_others(void **state)
{
	char one[128], other[128];
	struct folder_watch *w;

	(void)state;
	snprintf(one, sizeof(one), "%s/one.png", dir);
	snprintf(other, sizeof(other), "%s/other.png", dir);
	write_text(one, "1");
	w = folder_watch_new(one);
	assert_non_null(w);
	write_text(other, "2");
	assert_false(changed_within(w, 200));
	write_text(one, "3");
	assert_true(changed_within(w, 1000));
	folder_watch_free(w);
	assert_null(folder_watch_new("/nonexistent/folder"));
}

static void note(void *ctx, const char *folder, const char *name)
{
	(void)folder;
	strcat(ctx, name);
	strcat(ctx, " ");
}

/* rsync and Syncthing write under a temporary name, then rename it into
 * place: the rename is the arrival, never the temporary file; while one
 * is being written, in the folder or below, a sync is under way. */
static void watch_takes_synced_files_once_renamed(void **state)
{
	struct folder_watch *w = folder_watch_new(dir);
	char tmp[128], sub[128], done[128], seen[512] = "";
	struct pollfd p = {.fd = w ? folder_watch_fd(w) : -1, .events = POLLIN};

	(void)state;
	assert_non_null(w);
	assert_false(folder_watch_sync_under_way(w, time(NULL)));
	snprintf(tmp, sizeof(tmp), "%s/.model.glb.x8Yz1Q", dir);
	write_text(tmp, "half");
	assert_true(folder_watch_sync_under_way(w, time(NULL)));
	/* One left by a sync cut short a while ago is not a sync under way. */
	assert_false(folder_watch_sync_under_way(w, time(NULL) + 120));
	snprintf(done, sizeof(done), "%s/model.glb", dir);
	assert_int_equal(rename(tmp, done), 0);
	assert_false(folder_watch_sync_under_way(w, time(NULL)));
	snprintf(sub, sizeof(sub), "%s/textures", dir);
	assert_int_equal(mkdir(sub, 0755), 0);
	snprintf(tmp, sizeof(tmp), "%s/textures/~syncthing~wood.png.tmp", dir);
	write_text(tmp, "half");
	assert_true(folder_watch_sync_under_way(w, time(NULL)));
	unlink(tmp);
	rmdir(sub);
	assert_true(poll(&p, 1, 1000) > 0);
	assert_true(folder_watch_read_names(w, note, seen));
	assert_string_equal(seen, "model.glb ");
	unlink(done);
	folder_watch_free(w);
}

static void step(struct app *a, uint64_t t, enum app_action act)
{
	struct app_msg m = {.kind = APP_INPUT, .input = {.time_ns = t, .action = act}};

	m.input.pressed = true;
	app_apply(a, &m);
	m.input.pressed = false;
	app_apply(a, &m);
}

/* [frame] stops: each stop's text drawn with the model, in the caption's
 * style; the app's stop picks its picture (content_caption, as the loop
 * thread does), a stop without text and no stop pick the caption. */
static void stop_captions(void **state)
{
	char stops[] = "90 10 1.5 \"The handle\"; -90 0 1 \"Maker's mark\"; 0 -20 2";
	struct content_config o = {.matcap = "/nonexistent/mc",
				   .caption = {.text = "Jug", .size = 20, .padding = 4}};
	struct app_config c = {.turn_speed = 1, .mode = SHADING_VIEW};
	struct content s;
	struct app *a;

	(void)state;
	frame_config_defaults(&o.frame);
	o.frame.stops = stops;
	assert_int_equal(content_load(&s, &o, false), 0);
	assert_non_null(s.caption.rgba);
	assert_non_null(s.stop_caption[0].rgba);
	assert_non_null(s.stop_caption[1].rgba);
	assert_null(s.stop_caption[2].rgba);
	/* Longer texts than "Jug", in the caption's size: wider boxes. */
	assert_true(s.stop_caption[0].width > s.caption.width);
	assert_true(s.stop_caption[1].width > s.caption.width);
	content_app_frame(&o, &c.frame, &c.rest);
	a = app_new(&c, 1, 0);
	assert_ptr_equal(content_caption(&s, app_state(a)->stop), &s.caption);
	step(a, 0, ACTION_NEXT_STOP);
	assert_ptr_equal(content_caption(&s, app_state(a)->stop), &s.stop_caption[0]);
	step(a, 1, ACTION_NEXT_STOP);
	assert_ptr_equal(content_caption(&s, app_state(a)->stop), &s.stop_caption[1]);
	step(a, 2, ACTION_NEXT_STOP);
	assert_int_equal(app_state(a)->stop, 2);
	assert_ptr_equal(content_caption(&s, app_state(a)->stop), &s.caption);
	step(a, 3, ACTION_PREV_STOP);
	assert_ptr_equal(content_caption(&s, app_state(a)->stop), &s.stop_caption[1]);
	app_free(a);
	content_release(&s);
	/* No [caption]: the stops' texts are still shown, the rest nothing. */
	o.caption = (struct caption_config){.padding = 4};
	assert_int_equal(content_load(&s, &o, false), 0);
	assert_null(s.caption.rgba);
	assert_non_null(s.stop_caption[0].rgba);
	assert_null(content_caption(&s, -1)->rgba);
	assert_ptr_equal(content_caption(&s, 0), &s.stop_caption[0]);
	content_release(&s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(falls_back_unless_strict),
	    cmocka_unit_test(stop_captions),
	    cmocka_unit_test_setup_teardown(rescans_the_folder, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(matcap_first, make_dir, remove_dir),
	    cmocka_unit_test(matcap_chroma),
	    cmocka_unit_test_setup_teardown(matcap_first_auto, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(second_parse_sees_the_new_file, make_dir, remove_dir),
	    cmocka_unit_test_setup_teardown(watch_reports_written_and_moved_files, make_dir,
					    remove_dir),
	    cmocka_unit_test_setup_teardown(watch_of_one_file_ignores_the_others, make_dir,
					    remove_dir),
	    cmocka_unit_test_setup_teardown(watch_takes_synced_files_once_renamed, make_dir,
					    remove_dir),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests_name("scene", tests, NULL, NULL);
}
