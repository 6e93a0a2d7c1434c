/* Kiosks in step ([kiosk] clock = shared): two app states started at
 * different times, on machines whose monotonic clocks differ, advanced
 * at different moments, show the same pose, stop and model at every
 * moment of the shared clock; a step of that clock, or a shared input,
 * keeps them so. */
#include "state/app.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#define MS  1000000ull
#define SEC 1000000000ull
#define DEG (M_PI / 180.0)
/* 2026-11-28 on the shared clock: its times are big. */
#define REAL0 (1795910400ull * SEC)

/* One kiosk: its monotonic clock reads mono0 when the shared one reads REAL0. */
struct kiosk_sim {
	struct app *app;
	uint64_t mono0;
};

static struct app_config config(int stops)
{
	struct app_config c = {.turn_speed = 90 * DEG,
			       .turn_step = 5 * DEG,
			       .attract_after_s = 20,
			       .attract_speed = 15 * DEG,
			       .attract_fps = 30,
			       .attract_model_s = 45,
			       .rest = {1, 0, 0, 0},
			       .mode = SHADING_VIEW,
			       .shared_clock = true};

	c.frame.stop_count = stops;
	c.frame.stop_seconds = stops ? 7 : 0;
	for (int i = 0; i < stops; i++) {
		c.frame.stops[i].yaw = (i * 70 - 60) * DEG;
		c.frame.stops[i].pitch = (i * 10 - 5) * DEG;
		c.frame.stops[i].zoom = 1 + 0.25 * i;
	}
	return c;
}

static int64_t offset(const struct kiosk_sim *k)
{
	return (int64_t)(REAL0 - k->mono0);
}

/* Started at `real` on the shared clock. */
static void start(struct kiosk_sim *k, const struct app_config *base, uint64_t mono0, uint64_t real)
{
	struct app_config c = *base;
	struct app_msg m = {.kind = APP_MODELS, .models = {4, 0}};

	k->mono0 = mono0;
	c.clock_offset_ns = offset(k);
	k->app = app_new(&c, 3, real - REAL0 + mono0);
	assert_non_null(k->app);
	app_apply(k->app, &m);
}

static void advance_to(struct kiosk_sim *k, uint64_t real)
{
	app_set_clock(k->app, offset(k));
	app_advance(k->app, real - REAL0 + k->mono0);
}

static void assert_same(const struct kiosk_sim *a, const struct kiosk_sim *b)
{
	const struct app_state *x = app_state(a->app), *y = app_state(b->app);

	assert_true(fabs(remainder(x->yaw - y->yaw, 2 * M_PI)) < 1e-6);
	assert_true(fabs(x->pitch - y->pitch) < 1e-9);
	assert_true(fabs(x->zoom - y->zoom) < 1e-9);
	assert_int_equal(x->stop, y->stop);
	assert_int_equal(x->model, y->model);
}

/* b starts 7.3 s after a; both advance on their own irregular beats,
 * then at common moments show the same. */
static void run_in_step(int stops)
{
	struct app_config c = config(stops);
	struct kiosk_sim a, b;
	uint64_t t = REAL0 + 8000 * MS; /* both running */
	double yaw0;
	int stops_seen = 0, models_seen = 0, last_stop = -2, last_model = -1;

	start(&a, &c, 5 * SEC, REAL0);
	start(&b, &c, 86400 * SEC + 17 * MS, REAL0 + 7300 * MS);
	for (uint64_t u = REAL0; u < REAL0 + 7300 * MS; u += 33 * MS)
		advance_to(&a, u);
	yaw0 = app_state(a.app)->yaw;
	for (int i = 0; i < 3000; i++, t += 97 * MS + (uint64_t)(i % 7) * MS) {
		advance_to(&a, t + 11 * MS * (uint64_t)(i % 3)); /* each looks when it does */
		advance_to(&b, t + 5 * MS * (uint64_t)(i % 5));
		advance_to(&a, t + 40 * MS); /* and then both at the same moment */
		advance_to(&b, t + 40 * MS);
		assert_same(&a, &b);
		stops_seen += app_state(a.app)->stop != last_stop;
		models_seen += app_state(a.app)->model != last_model;
		last_stop = app_state(a.app)->stop;
		last_model = app_state(a.app)->model;
	}
	assert_true(app_attracting(a.app) && app_attracting(b.app));
	/* Something moved, and the schedules ran: not two still states. */
	assert_true(fabs(app_state(a.app)->yaw - yaw0) > 1e-3 || stops);
	if (stops)
		assert_true(stops_seen > 10);
	assert_true(models_seen > 2);
	app_free(a.app);
	app_free(b.app);
}

static void turning_in_step(void **state)
{
	(void)state;
	run_in_step(0);
}

static void touring_in_step(void **state)
{
	(void)state;
	run_in_step(3);
}

/* Their own clocks ([kiosk] clock = own): the same two kiosks differ,
 * so the tests above see what sharing the clock does. */
static void own_clocks_differ(void **state)
{
	struct app_config c = config(0);
	struct kiosk_sim a, b;
	int differ = 0;

	(void)state;
	c.shared_clock = false;
	start(&a, &c, 5 * SEC, REAL0);
	start(&b, &c, 86400 * SEC, REAL0 + 7300 * MS);
	for (uint64_t t = REAL0 + 8 * SEC; t < REAL0 + 60 * SEC; t += 100 * MS) {
		advance_to(&a, t);
		advance_to(&b, t);
		differ +=
		    fabs(remainder(app_state(a.app)->yaw - app_state(b.app)->yaw, 2 * M_PI)) > 1e-3;
	}
	assert_true(differ > 100);
	app_free(a.app);
	app_free(b.app);
}

/* The same state as one started at that moment, whatever it showed. */
static void assert_fresh(struct kiosk_sim *a, uint64_t real, const struct app_config *c)
{
	struct kiosk_sim ref;

	start(&ref, c, 3 * SEC, real);
	advance_to(&ref, real + 500 * MS);
	advance_to(a, real + 500 * MS);
	assert_same(a, &ref);
	app_free(ref.app);
}

/* The shared clock stepped (chrony's first fix on a Pi with no battery
 * clock): back or forward, the kiosk is in step at once, never stuck
 * waiting for its old time. */
static void clock_steps(void **state)
{
	struct app_config c = config(3);
	struct kiosk_sim a;
	uint64_t t = REAL0 + 100 * SEC;

	(void)state;
	start(&a, &c, 100000 * SEC, REAL0); /* up a day and more */
	advance_to(&a, t);
	/* The shared clock goes back an hour: the same monotonic moment
	 * reads an hour less. */
	a.mono0 += 3600 * SEC;
	assert_int_equal(app_set_clock(a.app, offset(&a)), -(int64_t)(3600 * SEC));
	assert_fresh(&a, t + 1 * SEC, &c);
	/* Forward a day: the same moment reads a day more. */
	a.mono0 -= 86400 * SEC;
	assert_int_equal(app_set_clock(a.app, offset(&a)), (int64_t)(86400 * SEC));
	assert_fresh(&a, t + 86402 * SEC, &c);
	/* A slew (chrony's half a millisecond a second) is no step. */
	a.mono0 += 500000;
	assert_int_equal(app_set_clock(a.app, offset(&a)), 0);
	app_free(a.app);
}

/* A press of action at `real` on the shared clock, on k's own clock. */
static void press_at(struct kiosk_sim *k, uint64_t real, enum app_action action)
{
	struct app_msg m = {
	    .kind = APP_INPUT,
	    .input = {.time_ns = real - REAL0 + k->mono0, .action = action, .pressed = true}};

	app_apply(k->app, &m);
}

/* A visitor's press shown on both (the leader's step, at its time): both
 * stop attract mode then, and begin it again together. */
static void shared_input(void **state)
{
	struct app_config c = config(0);
	struct kiosk_sim a, b;
	uint64_t press = REAL0 + 300 * SEC;

	(void)state;
	start(&a, &c, 5 * SEC, REAL0);
	start(&b, &c, 9 * SEC, REAL0 + 40 * SEC);
	advance_to(&a, press - 2 * SEC);
	advance_to(&b, press - 1 * SEC);
	press_at(&a, press, ACTION_NEXT_MATCAP);
	press_at(&b, press, ACTION_NEXT_MATCAP);
	assert_int_equal(app_state(a.app)->last_input_ns, press);
	advance_to(&a, press + 10 * SEC);
	advance_to(&b, press + 10 * SEC);
	assert_false(app_attracting(a.app) || app_attracting(b.app));
	for (uint64_t t = press + 19 * SEC; t < press + 40 * SEC; t += 130 * MS) {
		advance_to(&a, t);
		advance_to(&b, t + 3 * MS);
		advance_to(&a, t + 3 * MS);
		assert_same(&a, &b);
	}
	assert_true(app_attracting(a.app));
	app_free(a.app);
	app_free(b.app);
}

/* The leader's press reaches a follower late: 30 ms (the network), and
 * 100 s later (a follower restarted, given the retained step). Taken from
 * the state as it was then (app_rewind), the follower is in step with the
 * leader from there on, exactly, in both cases. */
static void press_taken_late(void **state)
{
	struct app_config c = config(3);
	struct kiosk_sim lead, late, restarted;
	uint64_t press = REAL0 + 300 * SEC;

	(void)state;
	start(&lead, &c, 5 * SEC, REAL0);
	start(&late, &c, 9 * SEC, REAL0 + 40 * SEC);
	advance_to(&lead, press - 1 * SEC);
	advance_to(&late, press - 1 * SEC);
	press_at(&lead, press, ACTION_NEXT_STOP);
	advance_to(&late, press + 30 * MS); /* it looked on meanwhile, then the step came */
	app_rewind(late.app, press - REAL0 + late.mono0);
	press_at(&late, press, ACTION_NEXT_STOP);
	start(&restarted, &c, 11 * SEC, press + 100 * SEC);
	advance_to(&restarted, press + 100 * SEC + 20 * MS);
	app_rewind(restarted.app, press - REAL0 + restarted.mono0);
	press_at(&restarted, press, ACTION_NEXT_STOP);
	assert_int_equal(app_state(late.app)->last_input_ns, press);
	assert_int_equal(app_state(restarted.app)->last_input_ns, press);
	for (uint64_t t = press + 101 * SEC; t < press + 200 * SEC; t += 130 * MS) {
		advance_to(&lead, t);
		advance_to(&late, t);
		advance_to(&restarted, t);
		assert_same(&lead, &late);
		assert_same(&lead, &restarted);
	}
	assert_true(app_attracting(lead.app));
	app_free(lead.app);
	app_free(late.app);
	app_free(restarted.app);
}

/* Attract mode's frames fall on the shared clock's grid of 1/attract_fps. */
static void frames_on_the_grid(void **state)
{
	struct app_config c = config(0);
	struct kiosk_sim a;
	uint64_t period = (uint64_t)(1e9 / c.attract_fps);

	(void)state;
	start(&a, &c, 5 * SEC, REAL0 + 123 * MS);
	app_set_clock(a.app, offset(&a));
	for (uint64_t t = REAL0 + 30 * SEC + 7 * MS, n = 0; n < 20; n++) {
		uint64_t next = app_advance(a.app, t - REAL0 + a.mono0) - a.mono0 + REAL0;

		assert_true(next > t);
		if (n > 0)
			assert_int_equal(next % period, 0);
		t = next;
	}
	app_free(a.app);
}

/* The schedule's arithmetic. */
static void grid_steps(void **state)
{
	uint64_t at = 10;

	(void)state;
	assert_int_equal(steps_due(&at, 9, 5), 0);
	assert_int_equal(at, 10);
	assert_int_equal(steps_due(&at, 10, 5), 1);
	assert_int_equal(at, 15);
	assert_int_equal(steps_due(&at, 37, 5), 5); /* 15 20 25 30 35 */
	assert_int_equal(at, 40);
	assert_int_equal(steps_due(&at, 1000, 0), 0);
	assert_int_equal(steps_floor(1234, 100), 1200);
	assert_int_equal(steps_floor(1234, 0), 1234);
	/* Since the epoch, at 1/30 s: no overflow. */
	at = 20 * SEC;
	assert_int_equal(steps_due(&at, REAL0, 33333333), (REAL0 - 20 * SEC) / 33333333 + 1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(turning_in_step),	 cmocka_unit_test(touring_in_step),
	    cmocka_unit_test(own_clocks_differ), cmocka_unit_test(clock_steps),
	    cmocka_unit_test(shared_input),	 cmocka_unit_test(frames_on_the_grid),
	    cmocka_unit_test(press_taken_late),	 cmocka_unit_test(grid_steps),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
