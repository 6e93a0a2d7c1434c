/* The knob: recorded evdev sequences through the decoder (detents, a
 * wobble, half steps, the key's press and long press), which devices are
 * knobs (a mouse is not), and what a detent does to the app state. */
#include "input/knob.h"
#include "input/knob_device.h"
#include "state/app.h"

#include <libevdev/libevdev.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#define MS 1000000ull

/* One recorded event: its time in ms, type, code and value. */
struct rec {
	uint64_t ms;
	unsigned type, code;
	int value;
};

struct log {
	struct app_event ev[128];
	int n;
};

static void play(struct knob_decoder *d, const struct rec *r, size_t n, struct log *l)
{
	for (size_t i = 0; i < n; i++) {
		/* As the loop does: a long press due before the event fires first. */
		uint64_t due = knob_decoder_deadline(d);

		if (due <= r[i].ms * MS)
			l->n += knob_decoder_timeout(d, due, l->ev + l->n);
		l->n += knob_decoder_event(d, r[i].ms * MS, r[i].type, r[i].code, r[i].value,
					   l->ev + l->n);
		assert_true(l->n < 100);
	}
}

static int count(const struct log *l, enum app_action a, bool pressed)
{
	int c = 0;

	for (int i = 0; i < l->n; i++)
		c += l->ev[i].action == a && l->ev[i].pressed == pressed;
	return c;
}

static struct knob_config config(enum knob_turns turns)
{
	return (struct knob_config){.step = 15 * M_PI / 180,
				    .turns = turns,
				    .press = ACTION_SELECT,
				    .long_press = ACTION_NEXT_LANGUAGE};
}

#define REL(ms, axis, v)                                                                           \
	{                                                                                          \
		ms, EV_REL, axis, v                                                                \
	}
#define SYN(ms)                                                                                    \
	{                                                                                          \
		ms, EV_SYN, SYN_REPORT, 0                                                          \
	}
#define KEY(ms, v)                                                                                 \
	{                                                                                          \
		ms, EV_KEY, KEY_ENTER, v                                                           \
	}

/* rotary-encoder with relative-axis: one count and a report a detent. */
static void detents_turn_the_model(void **unused)
{
	static const struct rec r[] = {REL(0, REL_X, 1),  SYN(0),  REL(40, REL_X, 1),	SYN(40),
				       REL(80, REL_X, 1), SYN(80), REL(300, REL_X, -1), SYN(300)};
	struct knob_config c = config(KNOB_TURNS_MODEL);
	struct knob_decoder d;
	struct log l = {0};

	(void)unused;
	knob_decoder_init(&d, &c, REL_X, 1);
	play(&d, r, sizeof(r) / sizeof(r[0]), &l);
	assert_int_equal(l.n, 4);
	assert_int_equal(count(&l, ACTION_TURN_RIGHT, true), 3);
	assert_int_equal(count(&l, ACTION_TURN_LEFT, true), 1);
	for (int i = 0; i < l.n; i++)
		assert_true(fabs(l.ev[i].angle - c.step) < 1e-12);
	assert_int_equal(l.ev[3].time_ns, 300 * MS);
}

/* Steps of a stop: next clockwise, previous anticlockwise; no angle. */
static void detents_step_the_stops(void **unused)
{
	static const struct rec r[] = {REL(0, REL_DIAL, 2), SYN(0), REL(50, REL_DIAL, -1), SYN(50)};
	struct knob_config c = config(KNOB_TURNS_STOPS);
	struct knob_decoder d;
	struct log l = {0};

	(void)unused;
	knob_decoder_init(&d, &c, REL_DIAL, 1);
	play(&d, r, sizeof(r) / sizeof(r[0]), &l);
	assert_int_equal(count(&l, ACTION_NEXT_STOP, true), 2);
	assert_int_equal(count(&l, ACTION_PREV_STOP, true), 1);
	assert_int_equal(l.n, 3);
	assert_true(l.ev[0].angle == 0);
}

/* Two counts a detent: halves add up; a half back and forth is nothing;
 * another device axis (a REL_WHEEL beside the dial) is not counted. */
static void half_steps_and_wobble(void **unused)
{
	static const struct rec r[] = {REL(0, REL_DIAL, 1),
				       SYN(0),
				       REL(10, REL_DIAL, 1),
				       SYN(10),
				       REL(20, REL_DIAL, 1),
				       SYN(20),
				       REL(30, REL_DIAL, -1),
				       SYN(30),
				       REL(40, REL_DIAL, 1),
				       SYN(40),
				       REL(50, REL_WHEEL, 5),
				       SYN(50),
				       REL(60, REL_DIAL, -1),
				       REL(60, REL_DIAL, -1),
				       SYN(60)};
	struct knob_config c = config(KNOB_TURNS_MODEL);
	struct knob_decoder d;
	struct log l = {0};

	(void)unused;
	knob_decoder_init(&d, &c, REL_DIAL, 2);
	play(&d, r, sizeof(r) / sizeof(r[0]), &l);
	/* 1+1: a detent; +1 -1 +1: a wobble, no detent; -2: one back. */
	assert_int_equal(count(&l, ACTION_TURN_RIGHT, true), 1);
	assert_int_equal(count(&l, ACTION_TURN_LEFT, true), 1);
	assert_int_equal(l.n, 2);
}

/* A fast spin in one report is capped, never past the caller's buffer. */
static void a_spin_is_capped(void **unused)
{
	static const struct rec r[] = {REL(0, REL_X, 100), SYN(0)};
	struct knob_config c = config(KNOB_TURNS_STOPS);
	struct knob_decoder d;
	struct log l = {0};

	(void)unused;
	knob_decoder_init(&d, &c, REL_X, 1);
	play(&d, r, 2, &l);
	assert_int_equal(l.n, KNOB_MAX_EVENTS);
}

/* The key: a short press selects on release; held 800 ms, the language. */
static void key_press_and_long_press(void **unused)
{
	static const struct rec r[] = {KEY(0, 1),    SYN(0),	KEY(120, 0),  SYN(120),
				       KEY(1000, 1), SYN(1000), KEY(1010, 2), SYN(1010),
				       KEY(2500, 0), SYN(2500)};
	struct knob_config c = config(KNOB_TURNS_MODEL);
	struct knob_decoder d;
	struct log l = {0};

	(void)unused;
	knob_decoder_init(&d, &c, REL_X, 1);
	play(&d, r, sizeof(r) / sizeof(r[0]), &l);
	assert_int_equal(count(&l, ACTION_SELECT, true), 1);
	assert_int_equal(count(&l, ACTION_NEXT_LANGUAGE, true), 1);
	/* The long press came at its time, not at the release. */
	for (int i = 0; i < l.n; i++)
		if (l.ev[i].action == ACTION_NEXT_LANGUAGE && l.ev[i].pressed)
			assert_int_equal(l.ev[i].time_ns, 1800 * MS);
	assert_int_equal(knob_decoder_deadline(&d), CLOCK_NEVER);
}

static struct libevdev *fake(const unsigned *rel, int n_rel, bool left)
{
	struct libevdev *dev = libevdev_new();

	assert_non_null(dev);
	for (int i = 0; i < n_rel; i++)
		libevdev_enable_event_code(dev, EV_REL, rel[i], NULL);
	if (left)
		libevdev_enable_event_code(dev, EV_KEY, BTN_LEFT, NULL);
	return dev;
}

/* The rotary-encoder's REL_X, a dial, a wheel: knobs; a mouse is not. */
static void which_devices_are_knobs(void **unused)
{
	static const unsigned encoder[] = {REL_X}, dial[] = {REL_DIAL, REL_WHEEL},
			      mouse[] = {REL_X, REL_Y, REL_WHEEL}, none[] = {REL_MISC};
	struct libevdev *d[4] = {fake(encoder, 1, false), fake(dial, 2, false),
				 fake(mouse, 3, true), fake(none, 1, false)};

	(void)unused;
	assert_int_equal(knob_device_axis(d[0]), REL_X);
	assert_int_equal(knob_device_axis(d[1]), REL_DIAL);
	assert_int_equal(knob_device_axis(d[2]), -1);
	assert_int_equal(knob_device_axis(d[3]), -1);
	for (int i = 0; i < 4; i++)
		libevdev_free(d[i]);
}

/* An app with three stops (0, 30 and 60 degrees) or none. */
static struct app *new_app(bool stops)
{
	struct app_config cfg = {.turn_speed = 1, .turn_step = 0.1, .mode = SHADING_NORMAL};
	struct frame_config f;
	char err[200];

	cfg.rest = (struct quat){0, 0, 0, 1};
	frame_config_defaults(&f);
	f.stops = stops ? "0 0 1; 30 0 1; 60 0 1" : NULL;
	assert_int_equal(frame_to_app(&f, 0, 0, &cfg.frame, err, sizeof(err)), 0);
	return app_new(&cfg, 1, 0);
}

static void send(struct app *a, uint64_t t, enum app_action act, double angle)
{
	struct app_msg m = {
	    .kind = APP_INPUT,
	    .input = {.time_ns = t, .action = act, .pressed = true, .angle = angle}};

	app_apply(a, &m);
	app_advance(a, t);
}

/* A detent turns by its angle at once, with nothing left held. */
static void a_detent_turns_the_app_by_the_step(void **unused)
{
	struct app *a = new_app(false);

	(void)unused;
	send(a, 1 * MS, ACTION_TURN_RIGHT, 0.25);
	send(a, 2 * MS, ACTION_TURN_RIGHT, 0.25);
	send(a, 3 * MS, ACTION_TURN_LEFT, 0.25);
	assert_true(fabs(app_state(a)->yaw - 0.25) < 1e-9);
	assert_false(app_moving(a));
	app_free(a);
}

/* select steps the stops (next-stop) on a model without hotspots (with
 * them, the hotspots: test_hotspot's select_steps_hotspots). */
static void select_steps_the_stops(void **unused)
{
	struct app *a = new_app(true);

	(void)unused;
	send(a, 1 * MS, ACTION_SELECT, 0);
	assert_int_equal(app_state(a)->stop, 0);
	send(a, 2 * MS, ACTION_SELECT, 0);
	assert_int_equal(app_state(a)->stop, 1);
	send(a, 3 * MS, ACTION_NEXT_LANGUAGE, 0); /* nothing yet */
	assert_int_equal(app_state(a)->stop, 1);
	app_free(a);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(detents_turn_the_model),
	    cmocka_unit_test(detents_step_the_stops),
	    cmocka_unit_test(half_steps_and_wobble),
	    cmocka_unit_test(a_spin_is_capped),
	    cmocka_unit_test(key_press_and_long_press),
	    cmocka_unit_test(which_devices_are_knobs),
	    cmocka_unit_test(a_detent_turns_the_app_by_the_step),
	    cmocka_unit_test(select_steps_the_stops),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
