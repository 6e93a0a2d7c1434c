/* The live loop (kiosk_run, the code the kiosk runs) through OSMesa while
 * a reload's content is prepared on the content worker: a key press that
 * comes during the reload is applied at once (the app state changes and
 * a frame shows it while the reload still runs), frames go on being
 * drawn, and the new model is on screen after. The preparation is held
 * by the test hook MK_TEST_PREPARE_GATE (src/app/reload.c; this
 * test is built with MK_TEST_HOOKS, as every sanitizer build is). */
#include "app/kiosk.h"
#include "app/signals.h"
#include "config/options.h"
#include "content/content.h"
#include "display/display.h"
#include "live_kiosk.h"
#include "render/render.h"
#include "scene/mesh/mesh.h"
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

/* OSMesa leaks a fixed few hundred bytes per process; kept loaded (the
 * display is never freed) they are suppressed by library: see
 * tests/unit/test_camera_texture.c. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
	return "leak:libOSMesa\nleak:libLLVM\nleak:display_osmesa_new\n";
}

enum step { WAIT_FIRST_FRAMES, ASKED_RELOAD, PRESSED, DONE };

struct script {
	struct input_source base; /* first: the loop hands this back */
	struct kiosk *k;
	enum step step;
	enum shading_mode mode_before;
	long pressed_frame;
	long frames_seen_changed;  /* frames drawn with the new mode while reloading */
	long frames_during_reload; /* from the press to the reload's end */
	bool reload_ended;
	/* The reload's preparation waits until this file exists (the test
	 * hook MK_TEST_PREPARE_GATE): made once three frames showed the key,
	 * so that no machine is too slow for the window, as a fixed delay was
	 * for qemu-user on a loaded CI. */
	const char *gate;
};

static int script_read(struct input_source *src, uint64_t now, struct app_event *out, int max)
{
	struct script *s = (struct script *)src;
	const struct app_state *st = kiosk_app_state(s->k);
	long f = kiosk_frames_drawn(s->k);

	if (max < 2)
		return 0;
	switch (s->step) {
	case WAIT_FIRST_FRAMES:
		if (f >= 3) {
			s->step = ASKED_RELOAD;
			kill(getpid(), SIGHUP);
		}
		break;
	case ASKED_RELOAD:
		if (!kiosk_reloading(s->k))
			break;
		/* The reload runs: the key now. */
		s->mode_before = st->mode;
		s->pressed_frame = f;
		s->step = PRESSED;
		out[0] =
		    (struct app_event){.time_ns = now, .action = ACTION_NEXT_MODE, .pressed = 1};
		out[1] = (struct app_event){.time_ns = now, .action = ACTION_NEXT_MODE};
		return 2;
	case PRESSED:
		if (kiosk_reloading(s->k)) {
			if (st->mode != s->mode_before && f > s->pressed_frame)
				s->frames_seen_changed = f - s->pressed_frame;
			s->frames_during_reload = f - s->pressed_frame;
			if (s->frames_seen_changed >= 3) {
				FILE *g = fopen(s->gate, "w");

				if (g)
					fclose(g);
			}
			break;
		}
		s->reload_ended = true;
		s->step = DONE;
		kill(getpid(), SIGTERM);
		break;
	case DONE:
		break;
	}
	/* A small turn each pass, so that every pass draws. */
	out[0] = (struct app_event){.time_ns = now, .action = ACTION_TURN_LEFT, .pressed = 1};
	out[1] = (struct app_event){.time_ns = now, .action = ACTION_TURN_LEFT};
	return 2;
}

static uint64_t script_deadline(struct input_source *src)
{
	(void)src;
	return 0; /* always: the loop never sleeps */
}

static void script_destroy(struct input_source *src)
{
	(void)src; /* on the test's stack */
}

static void a_key_during_a_reload_is_applied_at_once(void **state)
{
	char dir[] = "/tmp/mk-reload-XXXXXX", ini[64], model[64], gate[64];
	struct script s = {.base = {.name = "reload script",
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
	fprintf(f, "[scene]\nmode = view\n");
	fclose(f);
	live_kiosk_start(&lk, ini, &s.base);
	assert_null(lk.content.model_path); /* the built-in knot first */
	s.k = lk.k;
	/* The reload reads the new model; its preparation waits at the gate
	 * (MK_TEST_PREPARE_GATE) until the script has seen the key applied. */
	f = fopen(ini, "w");
	assert_non_null(f);
	fprintf(f, "[scene]\nmode = view\nmodel = %s\n", model);
	fclose(f);
	snprintf(gate, sizeof(gate), "%s/gate", dir);
	s.gate = gate;
	setenv("MK_TEST_PREPARE_GATE", gate, 1);
	assert_int_equal(kiosk_run(s.k), 0);
	unsetenv("MK_TEST_PREPARE_GATE");
	unlink(gate);
	assert_true(s.reload_ended);
	/* Drawn with the key's mode while the reload still ran. */
	assert_true(s.frames_seen_changed >= 3);
	assert_true(s.frames_during_reload >= s.frames_seen_changed);
	/* And the new model on screen after. */
	assert_non_null(lk.content.model_path);
	assert_string_equal(lk.content.model_path, model);
	live_kiosk_stop(&lk);
	unsetenv("XDG_CACHE_HOME");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(a_key_during_a_reload_is_applied_at_once),
	};

	/* Before the GL driver starts its threads, as main() does. */
	signals_block();
	log_set_level(LOG_WARN);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
