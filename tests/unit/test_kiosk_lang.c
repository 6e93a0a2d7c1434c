/* The live loop's language (kiosk_run through OSMesa, app/kiosk_lang.c):
 * a caption in two languages starts in the first; a next-language press
 * shows the second's picture (drawn on the worker before, swapped and
 * uploaded now); left idle for idle_seconds, the first comes back, as
 * attract mode starts its tour with it. Read from the content shown and
 * the frames drawn. */
#include "app/kiosk.h"
#include "app/signals.h"
#include "config/options.h"
#include "content/content.h"
#include "live_kiosk.h"
#include "util/log.h"

#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

enum step { FIRST, PRESSED, IDLE_FIRST, DONE };

struct script {
	struct input_source base; /* first: the loop hands this back */
	struct kiosk *k;
	struct content *content;
	enum step step;
	long ticks, frames;
	uint64_t next;
	int seen[DONE];	     /* the language each step ended on */
	int caption_w[DONE]; /* the caption's picture then */
};

static int press(struct app_event *out, uint64_t now)
{
	out[0] = (struct app_event){.time_ns = now, .action = ACTION_NEXT_LANGUAGE, .pressed = 1};
	out[1] = (struct app_event){.time_ns = now, .action = ACTION_NEXT_LANGUAGE};
	return 2;
}

/* Each step waits for its language and a frame drawn after it, then acts. */
static int script_read(struct input_source *src, uint64_t now, struct app_event *out, int max)
{
	static const int wanted[DONE] = {0, 1, 0};
	struct script *s = (struct script *)src;
	long frames = kiosk_frames_drawn(s->k);

	s->next = now + 1000000;
	if (max < 2 || s->step == DONE)
		return 0;
	if (++s->ticks > MAX_TICKS) {
		s->step = DONE;
		kill(getpid(), SIGTERM);
		return 0;
	}
	if (s->content->lang_shown != wanted[s->step] || frames <= s->frames)
		return 0;
	s->seen[s->step] = s->content->lang_shown;
	s->caption_w[s->step] = s->content->caption.width;
	s->frames = frames;
	switch (s->step++) {
	case FIRST:
		return press(out, now);
	case PRESSED:
		return 0; /* idle from here: attract mode after idle_seconds */
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

static void next_language_then_the_first_when_idle(void **state)
{
	char dir[] = "/tmp/mk-lang-XXXXXX", ini[64], model[64];
	struct script s = {.base = {.name = "language script",
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
	setenv("XDG_CACHE_HOME", dir, 1);
	live_kiosk_sphere(model);
	f = fopen(ini, "w");
	assert_non_null(f);
	/* Two texts of different widths: which picture is shown is seen. */
	fprintf(f,
		"[scene]\nmodel = %s\n[kiosk]\nidle_seconds = 1\n"
		"[caption]\nsize = 8\npadding = 0\nlanguages = en de\ntext = i\n"
		"text[de] = WWW\n",
		model);
	fclose(f);
	live_kiosk_start(&lk, ini, &s.base);
	s.k = lk.k;
	s.content = &lk.content;
	assert_int_equal(kiosk_run(s.k), 0);
	assert_int_equal(s.step, DONE);
	assert_int_equal(s.seen[PRESSED], 1);
	assert_true(s.caption_w[PRESSED] > s.caption_w[FIRST]); /* "WWW" over "i" */
	assert_int_equal(s.caption_w[IDLE_FIRST], s.caption_w[FIRST]);
	assert_int_equal(kiosk_app_state(s.k)->lang_step, 1);
	live_kiosk_stop(&lk);
	unsetenv("XDG_CACHE_HOME");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(next_language_then_the_first_when_idle),
	};

	/* Before the GL driver starts its threads, as main() does. */
	signals_block();
	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
