/* The live loop's matcap (kiosk_run through OSMesa): the one asked for is
 * the app state's, the one in the texture is recorded where it was
 * uploaded (src/app/kiosk_content.c, kiosk_matcap_settled). A next-matcap
 * press shows the next image of the folder; the image shown, rewritten in
 * the folder, is decoded and shown again (the set read again makes the
 * record stale); a file that no longer decodes keeps the previous picture
 * and says so. Read from the frames drawn. */
#include "app/kiosk.h"
#include "app/signals.h"
#include "config/options.h"
#include "content/content.h"
#include "display/display.h"
#include "live_kiosk.h"
#include "render/render.h"
#include "scene/mesh/mesh.h"
#include "util/clock.h"
#include "util/image.h"
#include "util/log.h"

#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

/* OSMesa leaks a fixed few hundred bytes per process; see
 * tests/unit/test_camera_texture.c. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
	return "leak:libOSMesa\nleak:libLLVM\nleak:display_osmesa_new\n";
}

/* A hang guard, not a speed check: ticks of 1 ms while waiting. */
#define MAX_TICKS 60000

enum colour { NONE, RED, BLUE, GREEN, OTHER };
enum step { FIRST_RED, PRESSED, REWRITTEN, BROKEN, DONE };

struct script {
	struct input_source base; /* first: the loop hands this back */
	struct kiosk *k;
	struct display *d;
	const char *blue; /* the second image's path */
	enum step step;
	long ticks;
	uint64_t next;		/* the next tick */
	enum colour seen[DONE]; /* what each step ended on */
};

static void write_colour(const char *path, uint8_t r, uint8_t g, uint8_t b)
{
	uint8_t px[8 * 8 * 4];
	struct image img = {8, 8, px};

	for (int i = 0; i < 64; i++)
		memcpy(px + 4 * i, (uint8_t[]){r, g, b, 255}, 4);
	assert_int_equal(image_write_png(path, &img), 0);
}

/* The middle of the last frame: the sphere, the matcap's colour. */
static enum colour centre(struct display *d)
{
	struct image img = {0};
	enum colour c = OTHER;
	const uint8_t *p;

	if (d->read_frame(d, &img))
		return OTHER;
	p = img.rgba + 4 * (img.height / 2 * img.width + img.width / 2);
	if (p[0] > 128 && p[1] < 64 && p[2] < 64)
		c = RED;
	else if (p[2] > 128 && p[0] < 64 && p[1] < 64)
		c = BLUE;
	else if (p[1] > 128 && p[0] < 64 && p[2] < 64)
		c = GREEN;
	image_release(&img);
	return c;
}

static int press(struct app_event *out, uint64_t now)
{
	out[0] = (struct app_event){.time_ns = now, .action = ACTION_NEXT_MATCAP, .pressed = 1};
	out[1] = (struct app_event){.time_ns = now, .action = ACTION_NEXT_MATCAP};
	return 2;
}

/* Each step waits for its colour, then acts; past MAX_TICKS it stops. */
static int script_read(struct input_source *src, uint64_t now, struct app_event *out, int max)
{
	static const enum colour wanted[DONE] = {RED, BLUE, GREEN, GREEN};
	struct script *s = (struct script *)src;
	enum colour c = kiosk_frames_drawn(s->k) > 0 ? centre(s->d) : OTHER;

	s->next = now + 1000000;
	if (max < 2 || s->step == DONE)
		return 0;
	if (++s->ticks > MAX_TICKS) {
		s->step = DONE;
		kill(getpid(), SIGTERM);
		return 0;
	}
	/* The broken file: its decode failed (the journal says so), and
	 * the green picture stays. */
	if (s->step == BROKEN && log_last_error_time() == 0)
		return 0;
	if (c != wanted[s->step])
		return 0;
	s->seen[s->step] = c;
	switch (s->step++) {
	case FIRST_RED:
		return press(out, now);
	case PRESSED: /* the shown image rewritten: the folder watch reads it */
		write_colour(s->blue, 0, 255, 0);
		return 0;
	case REWRITTEN: {
		FILE *f = fopen(s->blue, "w");

		assert_non_null(f);
		fputs("not a PNG", f);
		fclose(f);
		log_clear_last_error();
		return 0;
	}
	default:
		kill(getpid(), SIGTERM);
		return 0;
	}
}

static uint64_t script_deadline(struct input_source *src)
{
	return ((struct script *)src)->next;
}

static void script_destroy(struct input_source *src)
{
	(void)src; /* on the test's stack */
}

static void next_matcap_and_a_rewritten_one_are_shown(void **state)
{
	char dir[] = "/tmp/mk-matcap-XXXXXX", ini[64], model[64], folder[64], red[80], blue[80];
	struct script s = {.base = {.name = "matcap script",
				    .fd = -1,
				    .read = script_read,
				    .deadline = script_deadline,
				    .destroy = script_destroy}};
	struct live_kiosk lk;
	FILE *f;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(ini, sizeof(ini), "%s/kiosk.ini", dir);
	snprintf(model, sizeof(model), "%s/sphere.glb", dir);
	snprintf(folder, sizeof(folder), "%s/matcaps", dir);
	snprintf(red, sizeof(red), "%s/a.png", folder);
	snprintf(blue, sizeof(blue), "%s/b.png", folder);
	assert_int_equal(mkdir(folder, 0755), 0);
	write_colour(red, 255, 0, 0);
	write_colour(blue, 0, 0, 255);
	s.blue = blue;
	setenv("XDG_CACHE_HOME", dir, 1);
	live_kiosk_sphere(model);
	f = fopen(ini, "w");
	assert_non_null(f);
	fprintf(f, "[scene]\nmodel = %s\nmatcap = %s\n", model, folder);
	fclose(f);
	live_kiosk_start(&lk, ini, &s.base);
	s.k = lk.k;
	s.d = lk.d;
	assert_int_equal(kiosk_run(s.k), 0);
	assert_int_equal(s.seen[FIRST_RED], RED);
	assert_int_equal(s.seen[PRESSED], BLUE);    /* the press: the next image */
	assert_int_equal(s.seen[REWRITTEN], GREEN); /* the shown one, decoded again */
	assert_int_equal(s.seen[BROKEN], GREEN);    /* refused: the previous stays */
	assert_int_equal(kiosk_app_state(s.k)->matcap, 1);
	live_kiosk_stop(&lk);
	unsetenv("XDG_CACHE_HOME");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(next_matcap_and_a_rewritten_one_are_shown),
	};

	/* Before the GL driver starts its threads, as main() does. */
	signals_block();
	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
