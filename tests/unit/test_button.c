/* The button state machine with made-up timestamps: bounce, long press,
 * hold-to-repeat, no hardware. */
#include "input/button.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#define MS 1000000ull

/* Everything a button said, in order. */
struct log {
	struct app_event ev[256];
	int n;
};

static void edge(struct button *b, struct log *l, uint64_t t_ms, bool down)
{
	l->n += button_edge(b, t_ms * MS, down, l->ev + l->n);
	assert_true(l->n < 200);
}

static void wait_until(struct button *b, struct log *l, uint64_t t_ms)
{
	/* As the main loop does: wake at each deadline, then at t. */
	for (uint64_t d; (d = button_deadline(b)) <= t_ms * MS;)
		l->n += button_timeout(b, d, l->ev + l->n);
	l->n += button_timeout(b, t_ms * MS, l->ev + l->n);
	assert_true(l->n < 200);
}

static int count(const struct log *l, enum app_action a, bool pressed)
{
	int c = 0;

	for (int i = 0; i < l->n; i++)
		c += l->ev[i].action == a && l->ev[i].pressed == pressed;
	return c;
}

static void expect(const struct log *l, int i, uint64_t t_ms, enum app_action a, bool pressed)
{
	assert_true(i < l->n);
	assert_int_equal(l->ev[i].time_ns, t_ms * MS);
	assert_int_equal(l->ev[i].action, a);
	assert_int_equal(l->ev[i].pressed, pressed);
}

static const struct button_config turn_left = {
    .press = ACTION_TURN_LEFT, .debounce_ns = 10 * MS, .long_ns = 800 * MS};
static const struct button_config select_button = {.press = ACTION_NEXT_MATCAP,
						   .long_press = ACTION_TOGGLE_CAMERA,
						   .debounce_ns = 10 * MS,
						   .long_ns = 800 * MS};

/* A real switch: several edges within a few ms, on press and on release. */
static void bounce_burst_is_one_press_and_one_release(void **state)
{
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &turn_left, false);
	edge(&b, &l, 1000, true);
	/* The first edge is reported at once: a press feels instant. */
	assert_int_equal(l.n, 1);
	expect(&l, 0, 1000, ACTION_TURN_LEFT, true);
	edge(&b, &l, 1001, false);
	edge(&b, &l, 1002, true);
	edge(&b, &l, 1004, false);
	edge(&b, &l, 1005, true);
	wait_until(&b, &l, 1500);
	assert_int_equal(l.n, 1);
	edge(&b, &l, 1500, false);
	edge(&b, &l, 1501, true);
	edge(&b, &l, 1503, false);
	edge(&b, &l, 1506, true);
	edge(&b, &l, 1509, false);
	wait_until(&b, &l, 3000);
	assert_int_equal(l.n, 2);
	expect(&l, 1, 1500, ACTION_TURN_LEFT, false);
	assert_int_equal(button_deadline(&b), CLOCK_NEVER);
}

/* The window counts from the last edge: a burst longer than the window,
 * with gaps shorter than it, is still one press. */
static void long_burst_with_short_gaps(void **state)
{
	struct button b;
	struct log l = {0};
	bool down = true;

	(void)state;
	button_init(&b, &turn_left, false);
	for (uint64_t t = 100; t <= 160; t += 6, down = !down)
		edge(&b, &l, t, down);
	wait_until(&b, &l, 400);
	assert_int_equal(count(&l, ACTION_TURN_LEFT, true), 1);
	/* The burst ended up (160 is the 11th edge: down), then a release. */
	assert_int_equal(count(&l, ACTION_TURN_LEFT, false), 0);
	edge(&b, &l, 400, false);
	assert_int_equal(count(&l, ACTION_TURN_LEFT, false), 1);
}

/* A tap shorter than the window, or a burst that ends on the other level:
 * the level is taken once the line has been quiet for the window. */
static void burst_ending_released_settles(void **state)
{
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &turn_left, false);
	edge(&b, &l, 50, true);
	edge(&b, &l, 52, false);
	edge(&b, &l, 53, true);
	edge(&b, &l, 55, false);
	assert_int_equal(l.n, 1);
	assert_int_equal(button_deadline(&b), 65 * MS);
	wait_until(&b, &l, 64);
	assert_int_equal(l.n, 1);
	wait_until(&b, &l, 65);
	assert_int_equal(l.n, 2);
	expect(&l, 1, 65, ACTION_TURN_LEFT, false);
	assert_int_equal(button_deadline(&b), CLOCK_NEVER);
}

/* Edges read late (the loop was drawing) settle what fell due before
 * them, in time order. */
static void late_edges_keep_time_order(void **state)
{
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &turn_left, false);
	edge(&b, &l, 0, true);
	edge(&b, &l, 3, false); /* ignored, settles at 13 */
	edge(&b, &l, 40, true); /* read late: the release at 13 comes first */
	assert_int_equal(l.n, 3);
	expect(&l, 1, 13, ACTION_TURN_LEFT, false);
	expect(&l, 2, 40, ACTION_TURN_LEFT, true);
}

static void no_debounce_counts_every_edge(void **state)
{
	struct button_config c = turn_left;
	struct button b;
	struct log l = {0};

	(void)state;
	c.debounce_ns = 0;
	button_init(&b, &c, false);
	edge(&b, &l, 0, true);
	edge(&b, &l, 1, false);
	edge(&b, &l, 2, true);
	edge(&b, &l, 2, true); /* same level again: nothing */
	assert_int_equal(l.n, 3);
}

static void long_press_fires_once_while_held(void **state)
{
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &select_button, false);
	edge(&b, &l, 0, true);
	assert_int_equal(l.n, 0); /* short or long: not known yet */
	assert_int_equal(button_deadline(&b), 800 * MS);
	wait_until(&b, &l, 799);
	assert_int_equal(l.n, 0);
	wait_until(&b, &l, 800);
	assert_int_equal(l.n, 2);
	expect(&l, 0, 800, ACTION_TOGGLE_CAMERA, true);
	expect(&l, 1, 800, ACTION_TOGGLE_CAMERA, false);
	wait_until(&b, &l, 5000);
	/* The release, bouncing, gives nothing more. */
	edge(&b, &l, 5000, false);
	edge(&b, &l, 5002, true);
	edge(&b, &l, 5004, false);
	wait_until(&b, &l, 6000);
	assert_int_equal(l.n, 2);
	assert_int_equal(count(&l, ACTION_NEXT_MATCAP, true), 0);
}

static void short_press_acts_on_release(void **state)
{
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &select_button, false);
	edge(&b, &l, 0, true);
	edge(&b, &l, 2, false);
	edge(&b, &l, 3, true); /* bounce */
	edge(&b, &l, 300, false);
	edge(&b, &l, 301, true);
	edge(&b, &l, 303, false);
	wait_until(&b, &l, 2000);
	assert_int_equal(l.n, 2);
	expect(&l, 0, 300, ACTION_NEXT_MATCAP, true);
	expect(&l, 1, 300, ACTION_NEXT_MATCAP, false);
	assert_int_equal(count(&l, ACTION_TOGGLE_CAMERA, true), 0);
	/* Just under the long press is still short. */
	edge(&b, &l, 3000, true);
	edge(&b, &l, 3799, false);
	wait_until(&b, &l, 5000);
	assert_int_equal(count(&l, ACTION_NEXT_MATCAP, true), 2);
	assert_int_equal(count(&l, ACTION_TOGGLE_CAMERA, true), 0);
}

/* A turn button held: one press, one release; the app turns meanwhile.
 * No repeats and no deadline while held. */
static void held_turn_is_press_then_release(void **state)
{
	struct button_config c = turn_left;
	struct button b;
	struct log l = {0};

	(void)state;
	c.repeat_ns = 100 * MS; /* repeats are for actions that are not turns */
	button_init(&b, &c, false);
	edge(&b, &l, 0, true);
	assert_int_equal(button_deadline(&b), CLOCK_NEVER);
	wait_until(&b, &l, 3000);
	edge(&b, &l, 3000, false);
	assert_int_equal(l.n, 2);
	expect(&l, 0, 0, ACTION_TURN_LEFT, true);
	expect(&l, 1, 3000, ACTION_TURN_LEFT, false);
}

static void hold_to_repeat(void **state)
{
	struct button_config c = {.press = ACTION_NEXT_MATCAP,
				  .debounce_ns = 10 * MS,
				  .long_ns = 500 * MS,
				  .repeat_ns = 200 * MS};
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &c, false);
	edge(&b, &l, 0, true);
	wait_until(&b, &l, 499);
	assert_int_equal(l.n, 1);
	wait_until(&b, &l, 1150);
	/* 0, then 500, 700, 900, 1100. */
	assert_int_equal(count(&l, ACTION_NEXT_MATCAP, true), 5);
	expect(&l, 1, 500, ACTION_NEXT_MATCAP, true);
	expect(&l, 4, 1100, ACTION_NEXT_MATCAP, true);
	assert_int_equal(button_deadline(&b), 1300 * MS);
	edge(&b, &l, 1150, false);
	assert_int_equal(count(&l, ACTION_NEXT_MATCAP, false), 1);
	assert_int_equal(button_deadline(&b), CLOCK_NEVER);
	/* A loop that fell far behind repeats once, not in a burst. */
	edge(&b, &l, 2000, true);
	l.n = 0;
	l.n += button_timeout(&b, 9000 * MS, l.ev);
	assert_int_equal(l.n, 1);
	assert_true(button_deadline(&b) > 9000 * MS);
}

static void down_at_start_does_nothing_until_released(void **state)
{
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &select_button, true);
	wait_until(&b, &l, 5000);
	edge(&b, &l, 5000, false);
	assert_int_equal(l.n, 0);
	edge(&b, &l, 6000, true);
	edge(&b, &l, 6100, false);
	assert_int_equal(count(&l, ACTION_NEXT_MATCAP, true), 1);

	button_init(&b, &turn_left, true);
	l.n = 0;
	edge(&b, &l, 100, false);
	assert_int_equal(l.n, 0);
}

static void lost_line_releases_a_held_turn(void **state)
{
	struct button b;
	struct log l = {0};

	(void)state;
	button_init(&b, &turn_left, false);
	edge(&b, &l, 0, true);
	l.n += button_lost(&b, 50 * MS, l.ev + l.n);
	assert_int_equal(l.n, 2);
	expect(&l, 1, 50, ACTION_TURN_LEFT, false);
	assert_int_equal(button_deadline(&b), CLOCK_NEVER);
}

/* Many bursts in a row, each of random-looking length within the window:
 * exactly one press and one release per burst. */
static void many_bursts(void **state)
{
	struct button b;
	struct log l;
	uint32_t seed = 12345;
	uint64_t t = 1000;
	int presses = 0, releases = 0;

	(void)state;
	button_init(&b, &turn_left, false);
	for (int burst = 0; burst < 2000; burst++) {
		bool level = burst % 2 == 0;
		int edges = 1 + 2 * (int)((seed = seed * 1103515245u + 12345u) >> 29);

		l.n = 0;
		for (int e = 0; e < edges; e++, level = !level) {
			edge(&b, &l, t, level);
			t += 1 + ((seed = seed * 1103515245u + 12345u) >> 29); /* 1..8 ms */
		}
		t += 50;
		wait_until(&b, &l, t);
		presses += count(&l, ACTION_TURN_LEFT, true);
		releases += count(&l, ACTION_TURN_LEFT, false);
	}
	assert_int_equal(presses, 1000);
	assert_int_equal(releases, 1000);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(bounce_burst_is_one_press_and_one_release),
	    cmocka_unit_test(long_burst_with_short_gaps),
	    cmocka_unit_test(burst_ending_released_settles),
	    cmocka_unit_test(late_edges_keep_time_order),
	    cmocka_unit_test(no_debounce_counts_every_edge),
	    cmocka_unit_test(long_press_fires_once_while_held),
	    cmocka_unit_test(short_press_acts_on_release),
	    cmocka_unit_test(held_turn_is_press_then_release),
	    cmocka_unit_test(hold_to_repeat),
	    cmocka_unit_test(down_at_start_does_nothing_until_released),
	    cmocka_unit_test(lost_line_releases_a_held_turn),
	    cmocka_unit_test(many_bursts),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
