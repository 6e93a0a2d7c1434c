/* What visitors did: a scripted visit (knob detents, a press, a touch,
 * time at stops, idle, attract mode) and the counts and seconds it must
 * give, to the nanosecond the script says. */
#include "state/visits.h"
#include "state/view.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <cmocka.h>

#define S 1000000000ull

static void press(struct visits *v, enum input_kind kind, uint64_t t, enum app_action a)
{
	struct app_event ev = {.time_ns = t, .action = a, .pressed = true};

	visits_press(v, kind, &ev, 30);
	ev.pressed = false;
	visits_press(v, kind, &ev, 30);
}

static void observe(struct visits *v, uint64_t t, int stop, bool attract)
{
	struct visit_view w = {.stop = stop, .attract = attract};

	visits_observe(v, t, &w);
}

static void gesture(struct visits *v, uint64_t t, enum gesture_kind kind)
{
	struct gesture g = {.kind = kind, .time_ns = t};

	visits_touch(v, &g, ACTION_NEXT_MATCAP, 30);
}

/* One visitor: three detents, a press of the knob that goes to stop 1,
 * 20 s there, next-stop by a key, 10 s there, a drag of four moves; then
 * idle: attract mode from 100 s to 160 s; a second visitor taps. */
static void a_scripted_visit(void **unused)
{
	struct visits v = {0};

	(void)unused;
	observe(&v, 1 * S, -1, false);
	for (int i = 0; i < 3; i++)
		press(&v, INPUT_KIND_KNOB, (2 + i) * S, ACTION_TURN_RIGHT);
	press(&v, INPUT_KIND_KNOB, 5 * S, ACTION_SELECT);
	observe(&v, 5 * S, 0, false);
	observe(&v, 15 * S, 0, false);
	press(&v, INPUT_KIND_KEY, 25 * S, ACTION_NEXT_STOP);
	observe(&v, 25 * S, 1, false);
	for (int i = 0; i < 4; i++)
		gesture(&v, 35 * S + i, GESTURE_DRAG);
	gesture(&v, 35 * S + 4, GESTURE_END);
	observe(&v, 40 * S, 1, false);
	observe(&v, 100 * S, 1, true); /* attract from 100 s */
	observe(&v, 130 * S, -1, true);
	gesture(&v, 160 * S, GESTURE_TAP);
	observe(&v, 161 * S, -1, false);

	assert_int_equal(v.presses[INPUT_KIND_KNOB][ACTION_TURN_RIGHT], 3);
	assert_int_equal(v.presses[INPUT_KIND_KNOB][ACTION_SELECT], 1);
	assert_int_equal(v.presses[INPUT_KIND_KEY][ACTION_NEXT_STOP], 1);
	assert_int_equal(v.presses[INPUT_KIND_TOUCH][VISITS_DRAG], 1);
	assert_int_equal(v.presses[INPUT_KIND_TOUCH][VISITS_TAP], 1);
	assert_int_equal(v.presses[INPUT_KIND_BUTTON][ACTION_SELECT], 0);
	/* The knob at 2 s, and the tap after attract mode. */
	assert_int_equal(v.count, 2);
	assert_float_equal(visits_seconds(&v, "stop", "1"), 20, 1e-9);
	/* 25..100 s at the second stop, minus nothing: the drag is at it. */
	assert_float_equal(visits_seconds(&v, "stop", "2"), 75, 1e-9);
	assert_float_equal(visits_seconds(&v, "attract", ""), 60, 1e-9);
	assert_string_equal(visits_action_name(VISITS_DRAG), "drag");
	assert_string_equal(visits_action_name(ACTION_NEXT_LANGUAGE), "next-language");
}

/* An input after idle_s of none is a new visit; sooner, the same one.
 * Without attract mode (idle_s 0) the idle is VISITS_IDLE_S. */
static void visits_start_after_idle(void **unused)
{
	struct visits v = {0};
	struct app_event ev = {.action = ACTION_NEXT_MATCAP, .pressed = true};

	(void)unused;
	ev.time_ns = 10 * S;
	visits_press(&v, INPUT_KIND_BUTTON, &ev, 30);
	ev.time_ns = 39 * S;
	visits_press(&v, INPUT_KIND_BUTTON, &ev, 30);
	assert_int_equal(v.count, 1);
	ev.time_ns = 69 * S;
	visits_press(&v, INPUT_KIND_BUTTON, &ev, 30);
	assert_int_equal(v.count, 2);
	ev.time_ns = 69 * S + 59 * S;
	visits_press(&v, INPUT_KIND_BUTTON, &ev, 0);
	assert_int_equal(v.count, 2);
	ev.time_ns += 61 * S;
	visits_press(&v, INPUT_KIND_BUTTON, &ev, 0);
	assert_int_equal(v.count, 3);
	assert_int_equal(v.presses[INPUT_KIND_BUTTON][ACTION_NEXT_MATCAP], 5);
}

/* The generic slot: hotspots and languages feed it; more kinds than
 * there is room for are dropped, and their time said. */
static void generic_slots(void **unused)
{
	struct visits v = {0};
	char name[16];

	(void)unused;
	assert_int_equal(visit_time_add(&v, "language", "de", 2.5), 0);
	assert_int_equal(visit_time_add(&v, "language", "de", 1.5), 0);
	assert_int_equal(visit_time_add(&v, "hotspot", "valve", 3), 0);
	assert_float_equal(visits_seconds(&v, "language", "de"), 4, 1e-12);
	assert_float_equal(visits_seconds(&v, "hotspot", "valve"), 3, 1e-12);
	assert_float_equal(visits_seconds(&v, "language", "fr"), 0, 0);
	for (int i = 0; i < VISITS_SLOTS; i++) {
		snprintf(name, sizeof(name), "h%d", i);
		visit_time_add(&v, "hotspot", name, 1);
	}
	assert_int_equal(v.slot_count, VISITS_SLOTS);
	assert_float_equal(v.dropped_s, 2, 1e-12);
}

static void show(struct visits *v, uint64_t t, int stop, const char *hotspot, const char *lang)
{
	struct visit_view w = {.stop = stop, .hotspot = hotspot, .lang = lang};

	visits_observe(v, t, &w);
}

/* The visit with languages and hotspots: en shown 10 s, the
 * visitor steps to hotspot 1's view (FRAME_STOPS + 1: "valve") for 5 s,
 * switches to de, 7 s more there, back to stop 1 (which turns to
 * "signature") for 3 s; then attract mode's tour of languages and stops
 * (40 s) is attract's alone. A hotspot's view is no stop: no stop "10". */
static void time_per_language_and_hotspot(void **unused)
{
	struct visits v = {0};
	struct visit_view tour = {.stop = 0, .attract = true, .hotspot = "signature", .lang = "fr"};
	char name[16];

	(void)unused;
	show(&v, 1 * S, -1, NULL, "en");
	show(&v, 11 * S, FRAME_STOPS + 1, "valve", "en");
	show(&v, 16 * S, FRAME_STOPS + 1, "valve", "de");
	show(&v, 23 * S, 0, "signature", "de");
	visits_observe(&v, 26 * S, &tour);
	visits_observe(&v, 66 * S, &tour);

	assert_float_equal(visits_seconds(&v, "language", "en"), 15, 1e-9);
	assert_float_equal(visits_seconds(&v, "language", "de"), 10, 1e-9);
	assert_float_equal(visits_seconds(&v, "language", "fr"), 0, 0);
	assert_float_equal(visits_seconds(&v, "hotspot", "valve"), 12, 1e-9);
	assert_float_equal(visits_seconds(&v, "hotspot", "signature"), 3, 1e-9);
	assert_float_equal(visits_seconds(&v, "stop", "1"), 3, 1e-9);
	snprintf(name, sizeof(name), "%d", FRAME_STOPS + 2);
	assert_float_equal(visits_seconds(&v, "stop", name), 0, 0);
	assert_float_equal(visits_seconds(&v, "attract", ""), 40, 1e-9);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(a_scripted_visit),
	    cmocka_unit_test(visits_start_after_idle),
	    cmocka_unit_test(generic_slots),
	    cmocka_unit_test(time_per_language_and_hotspot),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
