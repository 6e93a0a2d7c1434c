/* The touchscreen layer without a touchscreen: which made-up devices
 * (libevdev's own, no kernel) count as touchscreens, and that touch off,
 * a missing device or one that is no input device leave the kiosk
 * running with nothing to read. */
#include "input/touch.h"
#include "util/clock.h"

#include <libevdev/libevdev.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

static struct libevdev *fake(void)
{
	struct libevdev *d = libevdev_new();

	assert_non_null(d);
	return d;
}

static void abs_axis(struct libevdev *d, unsigned int code, int max)
{
	struct input_absinfo info = {.minimum = 0, .maximum = max};

	assert_int_equal(libevdev_enable_event_code(d, EV_ABS, code, &info), 0);
}

static void key(struct libevdev *d, unsigned int code)
{
	assert_int_equal(libevdev_enable_event_code(d, EV_KEY, code, NULL), 0);
}

static bool is_touch(struct libevdev *d, bool *mt)
{
	bool r = touch_is_touchscreen(d, mt);

	libevdev_free(d);
	return r;
}

static void multitouch_screen(void **state)
{
	struct libevdev *d = fake();
	bool mt = false;

	(void)state;
	abs_axis(d, ABS_MT_SLOT, 9);
	abs_axis(d, ABS_MT_TRACKING_ID, 65535);
	abs_axis(d, ABS_MT_POSITION_X, 4095);
	abs_axis(d, ABS_MT_POSITION_Y, 4095);
	abs_axis(d, ABS_X, 4095);
	abs_axis(d, ABS_Y, 4095);
	key(d, BTN_TOUCH);
	libevdev_enable_property(d, INPUT_PROP_DIRECT);
	assert_true(is_touch(d, &mt));
	assert_true(mt);
}

static void single_touch_screen(void **state)
{
	struct libevdev *d = fake();
	bool mt = true;

	(void)state;
	abs_axis(d, ABS_X, 1023);
	abs_axis(d, ABS_Y, 1023);
	key(d, BTN_TOUCH);
	/* Old resistive drivers do not say "direct". */
	assert_true(is_touch(d, &mt));
	assert_false(mt);
}

static void touchpad_mouse_keyboard_are_not(void **state)
{
	struct libevdev *d = fake();
	bool mt;

	(void)state;
	abs_axis(d, ABS_MT_SLOT, 4);
	abs_axis(d, ABS_MT_POSITION_X, 1000);
	abs_axis(d, ABS_MT_POSITION_Y, 1000);
	key(d, BTN_TOUCH);
	key(d, BTN_TOOL_FINGER);
	libevdev_enable_property(d, INPUT_PROP_POINTER);
	assert_false(is_touch(d, &mt));

	d = fake();
	abs_axis(d, ABS_X, 1000);
	abs_axis(d, ABS_Y, 1000);
	key(d, BTN_TOUCH);
	key(d, BTN_TOOL_PEN); /* a graphics tablet beside the screen */
	assert_false(is_touch(d, &mt));

	d = fake();
	libevdev_enable_event_code(d, EV_REL, REL_X, NULL);
	libevdev_enable_event_code(d, EV_REL, REL_Y, NULL);
	key(d, BTN_LEFT);
	assert_false(is_touch(d, &mt));

	d = fake();
	key(d, KEY_A);
	key(d, KEY_Z);
	key(d, KEY_SPACE);
	assert_false(is_touch(d, &mt));
}

static void off_missing_and_wrong_devices(void **state)
{
	struct touch_config off = {.device = (char *)"off"};
	struct touch_config missing = {.device = (char *)"/dev/input/no-such-event9"};
	struct touch_config wrong = {.device = (char *)"/dev/null"};
	struct gesture g[4];
	struct touch *t;

	(void)state;
	assert_null(touch_new(&off, 0));
	t = touch_new(&missing, 90);
	assert_non_null(t);
	assert_int_equal(touch_count(t), 0);
	assert_true(touch_fd(t) >= 0);
	assert_int_equal(touch_deadline(t), CLOCK_NEVER);
	assert_int_equal(touch_dispatch(t, 0, g, 4), 0);
	touch_set_rotation(t, 180);
	touch_free(t);
	t = touch_new(&wrong, 0);
	assert_non_null(t);
	assert_int_equal(touch_count(t), 0);
	touch_free(t);
	touch_free(NULL);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(multitouch_screen),
	    cmocka_unit_test(single_touch_screen),
	    cmocka_unit_test(touchpad_mouse_keyboard_are_not),
	    cmocka_unit_test(off_missing_and_wrong_devices),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
