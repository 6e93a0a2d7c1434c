#include "config/options.h"
#include "config/settings.h"
#include "app/reload.h"
#include "util/log.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static int parse(struct options *o, int argc, const char **argv)
{
	return options_parse(o, argc, (char **)argv);
}

static char *write_ini(const char *text)
{
	static char path[64];
	int fd;

	strcpy(path, "/tmp/mk-ini-XXXXXX");
	fd = mkstemp(path);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
	close(fd);
	return path;
}

static void defaults(void **state)
{
	const char *argv[] = {"matcap-kiosk"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 1, argv), 0);
	assert_int_equal(o.backend, BACKEND_AUTO);
	assert_int_equal(o.display.width, 1280);
	assert_int_equal(o.display.height, 720);
	assert_int_equal(o.content.mode, SHADING_VIEW);
	assert_int_equal(o.frames, 1);
	assert_int_equal(o.log_level, LOG_INFO);
	assert_null(o.content.model);
	options_release(&o);
}

static void full_line(void **state)
{
	const char *argv[] = {"mk",	 "--backend",
			      "osmesa",	 "--model",
			      "m.glb",	 "--matcap",
			      "p.png",	 "--size",
			      "640x480", "--output",
			      "f.png",	 "--rotate",
			      "90",	 "--mode=sem-fragment",
			      "--ortho", "-q"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 16, argv), 0);
	assert_int_equal(o.backend, BACKEND_OSMESA);
	assert_string_equal(o.content.model, "m.glb");
	assert_string_equal(o.content.matcap, "p.png");
	assert_string_equal(o.output, "f.png");
	assert_int_equal(o.display.width, 640);
	assert_int_equal(o.display.height, 480);
	assert_int_equal(o.content.mode, SHADING_SEM_FRAGMENT);
	assert_int_equal(o.content.rotation, 90);
	assert_true(o.content.ortho);
	assert_int_equal(o.log_level, LOG_WARN);
	options_release(&o);
}

static void rejects_bad_values(void **state)
{
	static const char *bad[][3] = {
	    {"mk", "--size", "1280"}, {"mk", "--size", "0x720"},   {"mk", "--size", "12x9999"},
	    {"mk", "--size", "axb"},  {"mk", "--mode", "phong"},   {"mk", "--backend", "x11"},
	    {"mk", "--rotate", "45"}, {"mk", "--frames", "0"},	   {"mk", "--frames", "3x"},
	    {"mk", "--yaw", "north"}, {"mk", "stray", "argument"}, {"mk", "--no-such", "1"},
	};
	struct options o;

	(void)state;
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		assert_int_equal(parse(&o, 3, bad[i]), OPTIONS_USAGE);
		options_release(&o);
	}
}

static void config_file_then_command_line(void **state)
{
	const char *path = write_ini("; comment\n[display]\nbackend = osmesa\nrotation = 180\n"
				     "[scene]\nmodel = a.glb\nmode = sem-vertex\northo = yes\n"
				     "[kiosk]\nlog_level = debug\n");
	const char *argv[] = {"mk", "--mode", "normal", "--config", path};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 5, argv), 0);
	assert_int_equal(o.backend, BACKEND_OSMESA);
	assert_int_equal(o.content.rotation, 180);
	/* From the file's folder, not the current one. */
	assert_string_equal(o.content.model, "/tmp/a.glb");
	assert_true(o.content.ortho);
	assert_int_equal(o.log_level, LOG_DEBUG);
	/* The command line wins over the file, wherever --config stands. */
	assert_int_equal(o.content.mode, SHADING_NORMAL);
	options_release(&o);
	unlink(path);
}

/* Every class of config error stops the start with OPTIONS_CONFIG (78). */
static void config_errors(void **state)
{
	static const char *texts[] = {
	    "[scene]\nfoo = 1\n",			 /* unknown key */
	    "[screen]\nsize = 10x10\n",			 /* unknown section */
	    "[scene]\nmode = phong\n",			 /* bad choice */
	    "[display]\nrotation = 45\n",		 /* bad step */
	    "[display]\nsize = 100000x2\n",		 /* out of range */
	    "[scene]\northo = maybe\n",			 /* bad flag */
	    "[scene]\nmode = view\nmode = normal\n",	 /* duplicate */
	    "[scene]\nmode = phong\nmode = view\n",	 /* duplicate after a bad value */
	    "[scene\nmode = view\n",			 /* syntax */
	    "[display]\nbackend\n",			 /* no value */
	    "[power]\nschedule = Mon-Fir 08:00-20:00\n", /* a schedule that does not parse */
	    "[power]\nblank_after = -1\n",		 /* out of range */
	};
	struct options o;

	(void)state;
	for (size_t i = 0; i < sizeof(texts) / sizeof(texts[0]); i++) {
		const char *path = write_ini(texts[i]);
		const char *argv[] = {"mk", "--config", path};

		if (parse(&o, 3, argv) != OPTIONS_CONFIG)
			fail_msg("accepted: %s", texts[i]);
		options_release(&o);
		unlink(path);
	}
	const char *argv[] = {"mk", "--config", "/nonexistent/kiosk.ini"};
	assert_int_equal(parse(&o, 3, argv), OPTIONS_CONFIG);
	options_release(&o);
}

/* [power]: a good schedule is kept as written; --schedule is checked too. */
static void power_settings(void **state)
{
	const char *path = write_ini("[power]\nschedule = Mon-Fri 08:00-20:00, Sat 10:00-16:00\n"
				     "blank_after = 30\ncec = true\n");
	const char *argv[] = {"mk", "--config", path};
	const char *bad[] = {"mk", "--schedule", "Mon 8-20"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_string_equal(o.power.schedule, "Mon-Fri 08:00-20:00, Sat 10:00-16:00");
	assert_true(o.power.blank_after == 30.0);
	assert_true(o.power.cec);
	options_release(&o);
	unlink(path);
	assert_int_equal(parse(&o, 3, bad), OPTIONS_USAGE);
	options_release(&o);
}

/* idle_seconds is another name for attract_after (the one set last wins,
 * and an option over the file); attract_fps and attract_model_seconds. */
static void attract_settings(void **state)
{
	const char *path = write_ini("[kiosk]\nattract_after = 5\nidle_seconds = 20\n"
				     "attract_fps = 12.5\nattract_model_seconds = 8\n");
	const char *argv[] = {"mk", "--config", path};
	const char *over[] = {"mk", "--config", path, "--attract-after", "3"};
	const char *alias[] = {"mk", "--idle-seconds=0"};
	const char *bad[] = {"mk", "--attract-fps", "-1"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_float_equal(o.app.attract_after_s, 20, 0);
	assert_float_equal(o.app.attract_fps, 12.5, 0);
	assert_float_equal(o.app.attract_model_s, 8, 0);
	options_release(&o);
	assert_int_equal(parse(&o, 5, over), OPTIONS_OK);
	assert_float_equal(o.app.attract_after_s, 3, 0);
	options_release(&o);
	unlink(path);
	assert_int_equal(parse(&o, 2, alias), OPTIONS_OK);
	assert_float_equal(o.app.attract_after_s, 0, 0);
	options_release(&o);
	assert_int_equal(parse(&o, 3, bad), OPTIONS_USAGE);
	options_release(&o);
}

/* [knob]: 15 degrees a detent turning the model, its key selecting and
 * its long press the next language, by default; each key read. */
static void knob_settings(void **state)
{
	const char *path = write_ini("[knob]\ndevice = /dev/input/event7\nstep = 30\n"
				     "turns = stops\npress = next-stop\nlong_press = none\n");
	const char *argv[] = {"mk", "--config", path}, *plain[] = {"mk"};
	const char *bad[] = {"mk", "--knob-turns", "hotspot-ish"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 1, plain), OPTIONS_OK);
	assert_float_equal(o.knob.step, M_PI / 12, 1e-12);
	assert_int_equal(o.knob.turns, KNOB_TURNS_MODEL);
	assert_int_equal(o.knob.press, ACTION_SELECT);
	assert_int_equal(o.knob.long_press, ACTION_NEXT_LANGUAGE);
	assert_null(o.knob.device);
	options_release(&o);
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_string_equal(o.knob.device, "/dev/input/event7");
	assert_float_equal(o.knob.step, M_PI / 6, 1e-12);
	assert_int_equal(o.knob.turns, KNOB_TURNS_STOPS);
	assert_int_equal(o.knob.press, ACTION_NEXT_STOP);
	assert_int_equal(o.knob.long_press, ACTION_NONE);
	options_release(&o);
	unlink(path);
	assert_int_equal(parse(&o, 3, bad), OPTIONS_USAGE);
	options_release(&o);
	assert_int_equal(options_sections[OPTIONS_KNOB].reload, OPTIONS_REOPEN);
}

/* [kiosk] prepare_threads: auto (0, one a core) by default and in the
 * shipped kiosk.ini, or a whole number from 1 to 16. Its auto is the
 * first word for 0 of a whole number: kept as a double it would zero the
 * int beside it too (the panel's rotation). */
static void prepare_threads_setting(void **state)
{
	const char *path = write_ini("[kiosk]\nprepare_threads = 3\n");
	const char *argv[] = {"mk", "--config", path};
	const char *auto_[] = {"mk", "--rotate", "90", "--prepare-threads", "auto"};
	const char *bad[][3] = {{"mk", "--prepare-threads", "17"},
				{"mk", "--prepare-threads", "2.5"},
				{"mk", "--prepare-threads", "0"}};
	struct options o;

	(void)state;
	/* auto (0) unless asked. */
	assert_int_equal(parse(&o, 1, argv), OPTIONS_OK);
	assert_int_equal(o.content.prepare_threads, 0);
	options_release(&o);
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_int_equal(o.content.prepare_threads, 3);
	options_release(&o);
	unlink(path);
	assert_int_equal(parse(&o, 5, auto_), OPTIONS_OK);
	assert_int_equal(o.content.prepare_threads, 0);
	assert_int_equal(o.content.rotation, 90);
	options_release(&o);
	for (int i = 0; i < 3; i++) {
		assert_int_equal(parse(&o, 3, bad[i]), OPTIONS_USAGE);
		options_release(&o);
	}
}

/* Indented keys are keys, not continuations of the line above. */
static void indented_lines(void **state)
{
	const char *path = write_ini("[scene]\n  mode = normal\n\tyaw = 10\n  [kiosk]\n"
				     "    log_level = debug\n");
	const char *argv[] = {"mk", "--config", path};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 3, argv), 0);
	assert_int_equal(o.content.mode, SHADING_NORMAL);
	assert_true(o.content.yaw == 10.0);
	assert_int_equal(o.log_level, LOG_DEBUG);
	options_release(&o);
	unlink(path);
}

/* OPTION_DEFS is the table's true length: every entry is filled in. */
static void table_is_full(void **state)
{
	(void)state;
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		assert_non_null(option_defs[i].name);
		assert_non_null(option_defs[i].help);
		assert_true(option_defs[i].size > 0);
	}
}

/* [mqtt] into struct mqtt_config; no key takes a password (it comes from
 * systemd's credentials, never kiosk.ini in clear). */
static void mqtt_section(void **state)
{
	const char *path = write_ini("[mqtt]\nbroker = 127.0.0.1:1884\ntopic = kiosk/hall\n"
				     "tls = yes\nca_file = /etc/ssl/ca.pem\nhome_assistant = yes\n"
				     "sync = follower\ngroup = kiosk/wall\n");
	const char *argv[] = {"mk", "--config", path};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 3, argv), 0);
	assert_string_equal(o.mqtt.broker, "127.0.0.1:1884");
	assert_string_equal(o.mqtt.topic, "kiosk/hall");
	assert_true(o.mqtt.tls);
	assert_string_equal(o.mqtt.ca_file, "/etc/ssl/ca.pem");
	assert_true(o.mqtt.home_assistant);
	assert_int_equal(o.mqtt.sync, MQTT_SYNC_FOLLOWER);
	assert_string_equal(o.mqtt.group, "kiosk/wall");
	options_release(&o);
	unlink(path);
	/* write_ini's path is one buffer: argv[2] names the new file. */
	write_ini("[mqtt]\npassword = secret\n");
	assert_int_not_equal(parse(&o, 3, argv), 0);
	options_release(&o);
	unlink(path);
}

static void shipped_example_parses(void **state)
{
	const char *argv[] = {"mk", "--config", "config/kiosk.ini"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 3, argv), 0);
	options_release(&o);
}

/* Each [section] lands in its module's config, with real enum types and
 * the units the module works in. */
static void sections_into_module_configs(void **state)
{
	const char *path = write_ini(
	    "[display]\nsize = 320x200\non_busy = exit\nkms_api = legacy\nconnector = DSI-1\n"
	    "[kiosk]\nturn_speed = 180\nattract_after = 5\n"
	    "[buttons]\nchip = gpiochip1\nactive = high\nbias = disable\nleft = 5\n"
	    "left_press = reset\nselect_long_press = none\n"
	    "[keyboard]\ndevice = none\n"
	    "[material]\nlit = beside\n"
	    "[camera]\nenabled = off\nsize = 640x480\ncrop_x = 0.25\nmirror = true\n"
	    "import = off\n");
	const char *argv[] = {"mk", "--config", path, "--turn-step=90"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 4, argv), OPTIONS_OK);
	assert_int_equal(o.display.width, 320);
	assert_int_equal(o.display.height, 200);
	assert_true(o.display.exit_when_busy);
	assert_int_equal(o.display.kms_api, 2);
	assert_string_equal(o.display.connector, "DSI-1");
	assert_float_equal(o.app.turn_speed, M_PI, 1e-12);
	assert_float_equal(o.app.turn_step, M_PI / 2, 1e-12);
	assert_float_equal(o.app.attract_after_s, 5, 0);
	assert_float_equal(o.app.attract_fps, 30, 0); /* the default */
	assert_string_equal(o.buttons.chip, "gpiochip1");
	assert_int_equal(o.buttons.active, BUTTON_ACTIVE_HIGH);
	assert_int_equal(o.buttons.bias, BUTTON_BIAS_DISABLE);
	assert_string_equal(o.buttons.buttons[0].line, "5");
	assert_int_equal(o.buttons.buttons[0].press, ACTION_RESET);
	assert_int_equal(o.buttons.buttons[2].press, ACTION_NEXT_MATCAP);
	assert_int_equal(o.buttons.buttons[2].long_press, ACTION_NONE);
	assert_string_equal(o.keyboard.device, "none");
	assert_int_equal(o.content.material.lit, 2);
	assert_int_equal(o.camera.use, CAMERA_FEED_OFF);
	assert_int_equal(o.camera.width, 640);
	assert_int_equal(o.camera.height, 480);
	assert_float_equal(o.camera.view.cx, 0.25, 0);
	assert_float_equal(o.camera.view.cy, 0.5, 0);
	assert_true(o.camera.view.mirror);
	assert_int_equal(o.camera.import, CAMERA_FEED_IMPORT_OFF);
	options_release(&o);
	unlink(path);
}

/* The defaults of the modules' configs. */
static void module_defaults(void **state)
{
	const char *argv[] = {"mk"};
	struct options o;

	(void)state;
	assert_int_equal(parse(&o, 1, argv), OPTIONS_OK);
	assert_false(o.display.exit_when_busy);
	assert_float_equal(o.app.turn_speed, 90 * M_PI / 180, 0);
	assert_int_equal(o.buttons.active, BUTTON_ACTIVE_LOW);
	assert_int_equal(o.buttons.bias, BUTTON_BIAS_PULL_UP);
	assert_int_equal(o.buttons.buttons[0].press, ACTION_TURN_LEFT);
	assert_int_equal(o.buttons.buttons[2].long_press, ACTION_TOGGLE_CAMERA);
	assert_null(o.keyboard.device);
	assert_int_equal(o.camera.use, CAMERA_FEED_ON);
	assert_int_equal(o.camera.import, CAMERA_FEED_IMPORT_AUTO);
	assert_float_equal(o.camera.stall_s, 3, 0);
	options_release(&o);
}

/* A deep copy: the copy's strings are its own. */
static void copy_is_deep(void **state)
{
	const char *argv[] = {"mk", "--model", "m.glb", "--button-left", "GPIO5"};
	struct options o, c;

	(void)state;
	assert_int_equal(parse(&o, 5, argv), OPTIONS_OK);
	assert_int_equal(options_copy(&c, &o), 0);
	assert_ptr_not_equal(c.content.model, o.content.model);
	assert_string_equal(c.content.model, "m.glb");
	assert_string_equal(c.buttons.buttons[0].line, "GPIO5");
	assert_int_equal(options_changed(&o, &c), 0);
	options_release(&o);
	assert_string_equal(c.content.model, "m.glb");
	options_release(&c);
}

/* The content part alone, as the model worker copies it: deep too, its
 * material file names included, and nothing outside it touched. */
static void content_copy_is_deep(void **state)
{
	const char *argv[] = {"mk",   "--model", "m.glb", "--matcap", "mc", "--iridescence-ramp",
			      "r.png"};
	struct options o;
	struct content_config c;

	(void)state;
	assert_int_equal(parse(&o, 7, argv), OPTIONS_OK);
	assert_int_equal(content_config_copy(&c, &o.content), 0);
	assert_ptr_not_equal(c.model, o.content.model);
	assert_ptr_not_equal(c.matcap, o.content.matcap);
	assert_ptr_not_equal(c.material.ramp, o.content.material.ramp);
	assert_null(c.model_scene);
	assert_int_equal(c.mode, o.content.mode);
	options_release(&o);
	assert_string_equal(c.model, "m.glb");
	assert_string_equal(c.matcap, "mc");
	assert_string_equal(c.material.ramp, "r.png");
	content_config_release(&c);
	assert_null(c.model);
	assert_null(c.material.ramp);
}

static unsigned changed_by(const char *arg)
{
	const char *base[] = {"mk"}, *argv[] = {"mk", arg};
	struct options a, b;
	unsigned changed;

	assert_int_equal(parse(&a, 1, base), OPTIONS_OK);
	assert_int_equal(parse(&b, 2, argv), OPTIONS_OK);
	changed = options_changed(&a, &b);
	options_release(&a);
	options_release(&b);
	return changed;
}

#define BIT(s) (1u << (s))

/* One table says what a reload does with each section; a change is
 * found per section, and rotation is live in an at-start section. */
static void reload_table(void **state)
{
	(void)state;
	assert_int_equal(options_sections[OPTIONS_DISPLAY].reload, OPTIONS_AT_START);
	assert_int_equal(options_sections[OPTIONS_SCENE].reload, OPTIONS_LIVE);
	assert_int_equal(options_sections[OPTIONS_KIOSK].reload, OPTIONS_LIVE);
	assert_int_equal(options_sections[OPTIONS_BUTTONS].reload, OPTIONS_REOPEN);
	assert_int_equal(options_sections[OPTIONS_KEYBOARD].reload, OPTIONS_REOPEN);
	assert_int_equal(options_sections[OPTIONS_MATERIAL].reload, OPTIONS_LIVE);
	assert_int_equal(options_sections[OPTIONS_CAMERA].reload, OPTIONS_REOPEN);
	assert_int_equal(options_sections[OPTIONS_MQTT].reload, OPTIONS_AT_START);
	for (int i = 0; i < OPTIONS_SECTIONS; i++)
		assert_non_null(options_sections[i].says);
	assert_int_equal(changed_by("--size=100x100"), BIT(OPTIONS_DISPLAY));
	assert_int_equal(changed_by("--on-busy=exit"), BIT(OPTIONS_DISPLAY));
	assert_int_equal(changed_by("--rotate=90"), 0);
	assert_int_equal(changed_by("--yaw=3"), BIT(OPTIONS_SCENE));
	assert_int_equal(changed_by("--turn-step=1"), BIT(OPTIONS_KIOSK));
	assert_int_equal(changed_by("--button-left=GPIO5"), BIT(OPTIONS_BUTTONS));
	assert_int_equal(changed_by("--left-long-press=reset"), BIT(OPTIONS_BUTTONS));
	assert_int_equal(changed_by("--keyboard=none"), BIT(OPTIONS_KEYBOARD));
	assert_int_equal(changed_by("--lit=on"), BIT(OPTIONS_MATERIAL));
	assert_int_equal(changed_by("--camera-size=64x32"), BIT(OPTIONS_CAMERA));
	assert_int_equal(changed_by("--camera-mirror"), BIT(OPTIONS_CAMERA));
	assert_int_equal(changed_by("--stats"), 0);
}

/* A reload opens again what changed since the last one; what waits for
 * a restart is measured against the start. */
static void reload_reopens_what_changed(void **state)
{
	const char *start[] = {"mk"}, *last[] = {"mk", "--camera=off", "--size=80x80"},
		   *now[] = {"mk", "--camera=off", "--size=80x80", "--button-bias=disable",
			     "--keyboard=none"};
	struct options s, l, n;

	(void)state;
	assert_int_equal(parse(&s, 1, start), OPTIONS_OK);
	assert_int_equal(parse(&l, 3, last), OPTIONS_OK);
	assert_int_equal(parse(&n, 5, now), OPTIONS_OK);
	assert_int_equal(reload_reopen(&s, &l, &n), BIT(OPTIONS_BUTTONS) | BIT(OPTIONS_KEYBOARD));
	assert_int_equal(reload_reopen(&s, &s, &l), BIT(OPTIONS_CAMERA));
	assert_int_equal(reload_reopen(&s, &n, &n), 0);
	options_release(&s);
	options_release(&l);
	options_release(&n);
}

/* [kiosk] include: a second file over the first where it exists; it is a
 * USB stick's (--import writes it), so it may not include another; a
 * missing one is no error. */
static void include_file(void **state)
{
	char second[64], text[160];
	const char *argv[] = {"matcap-kiosk", "--config", NULL};
	struct options o;
	FILE *f;

	(void)state;
	snprintf(second, sizeof(second), "%s", write_ini("[scene]\nmode = normal\nyaw = 30\n"));
	snprintf(text, sizeof(text), "[scene]\nmode = view\n[kiosk]\ninclude = %s\n", second);
	argv[2] = write_ini(text);
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_int_equal(o.content.mode, SHADING_NORMAL);
	assert_true(fabs(o.content.yaw - 30) < 1e-9);
	assert_string_equal(o.include, second);
	options_release(&o);
	/* The include is a stick's: it may not include another file. */
	f = fopen(second, "w");
	assert_non_null(f);
	fputs("[scene]\nmode = normal\n[kiosk]\ninclude = /etc/x.ini\n", f);
	fclose(f);
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_int_equal(o.content.mode, SHADING_VIEW);
	assert_true(o.include_ignored);
	options_release(&o);
	unlink(second);
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_int_equal(o.content.mode, SHADING_VIEW);
	options_release(&o);
	unlink(argv[2]);
}

/* An included file that does not read leaves the installed settings alone
 * in force: the kiosk starts, and the include is not followed. */
static void broken_include_is_ignored(void **state)
{
	char bad[64], text[160];
	const char *argv[] = {"matcap-kiosk", "--config", NULL};
	struct options o;

	(void)state;
	snprintf(bad, sizeof(bad), "%s", write_ini("[scene]\nmode = sideways\nyaw = 90\n"));
	snprintf(text, sizeof(text), "[scene]\nmode = normal\nyaw = 30\n[kiosk]\ninclude = %s\n",
		 bad);
	argv[2] = write_ini(text);
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_int_equal(o.content.mode, SHADING_NORMAL);
	assert_true(fabs(o.content.yaw - 30) < 1e-9);
	assert_null(o.include);
	options_release(&o);
	unlink(argv[2]);
	unlink(bad);
}

/* [wall] read strictly: a 2x2 wall with a bezel as written; each hostile
 * value refused with its line and what was expected (the file then has
 * errors, as any bad value); a position outside the wall, or a bezel
 * without the screen's size, said with its file and line and the kiosk
 * shown without the wall (the whole picture), the bezel as 0. */
static void wall_section(void **state)
{
	static const char *const bad[] = {
	    "position = 3;1", "position = 0,1",	       "position = 1,17",  "position = 2",
	    "position = ,",   "position = 1,1,1",      "position = 1x1",   "position = -1,2",
	    "columns = 17",   "columns = 99999999999", "rows = 0",	   "columns = 1.5",
	    "bezel = nan",    "bezel = inf",	       "bezel = -1",	   "bezel = 201",
	    "bezel = 1e400",  "screen_size = 0x0",     "screen_size = 1x", "screen_size = 600x-340",
	    "rows = nan",     "screen_size = 99999x1"};
	const char *argv[] = {"mk", "--config", NULL};
	char text[200], last[400], *path;
	struct options o;

	(void)state;
	argv[2] = write_ini("[wall]\ncolumns = 2\nrows = 2\nposition = 2,1\nbezel = 12.5\n"
			    "screen_size = 598x336\n");
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	assert_int_equal(o.content.wall.columns, 2);
	assert_int_equal(o.content.wall.rows, 2);
	assert_int_equal(o.content.wall.column, 2);
	assert_int_equal(o.content.wall.row, 1);
	assert_true(o.content.wall.bezel == 12.5);
	assert_int_equal(o.content.wall.screen_w, 598);
	assert_int_equal(o.content.wall.screen_h, 336);
	assert_int_equal(o.wall_refused, 0);
	options_release(&o);
	unlink(argv[2]);
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		snprintf(text, sizeof(text), "[wall]\n; one bad line\n%s\n", bad[i]);
		argv[2] = path = write_ini(text);
		assert_int_equal(parse(&o, 3, argv), OPTIONS_CONFIG);
		log_last_error(last, sizeof(last));
		snprintf(text, sizeof(text), "%s:3: [wall]", path);
		assert_non_null(strstr(last, text));
		assert_non_null(strstr(last, "expected"));
		options_release(&o);
		unlink(path);
	}
	/* Outside the wall: said, and no wall. */
	argv[2] = path = write_ini("[wall]\ncolumns = 2\nposition = 3,1\n");
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	log_last_error(last, sizeof(last));
	snprintf(text, sizeof(text), "%s:3: [wall] position = 3,1 is outside", path);
	assert_non_null(strstr(last, text));
	assert_non_null(strstr(last, "expected COLUMN,ROW from 1,1 (top left) to 2,1"));
	assert_int_equal(o.content.wall.columns, 1);
	assert_int_equal(o.content.wall.column, 1);
	assert_int_equal(o.wall_refused, 1);
	options_release(&o);
	unlink(path);
	/* A bezel without the screen's size: said, taken as 0. */
	argv[2] = path = write_ini("[wall]\ncolumns = 2\nbezel = 10\n");
	assert_int_equal(parse(&o, 3, argv), OPTIONS_OK);
	log_last_error(last, sizeof(last));
	snprintf(text, sizeof(text), "%s:3: [wall] bezel = 10: a bezel needs [wall] screen_size",
		 path);
	assert_non_null(strstr(last, text));
	assert_true(o.content.wall.bezel == 0);
	assert_int_equal(o.content.wall.columns, 2);
	options_release(&o);
	unlink(path);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(defaults),
	    cmocka_unit_test(full_line),
	    cmocka_unit_test(rejects_bad_values),
	    cmocka_unit_test(config_file_then_command_line),
	    cmocka_unit_test(config_errors),
	    cmocka_unit_test(power_settings),
	    cmocka_unit_test(indented_lines),
	    cmocka_unit_test(shipped_example_parses),
	    cmocka_unit_test(table_is_full),
	    cmocka_unit_test(sections_into_module_configs),
	    cmocka_unit_test(mqtt_section),
	    cmocka_unit_test(wall_section),
	    cmocka_unit_test(module_defaults),
	    cmocka_unit_test(copy_is_deep),
	    cmocka_unit_test(content_copy_is_deep),
	    cmocka_unit_test(reload_table),
	    cmocka_unit_test(reload_reopens_what_changed),
	    cmocka_unit_test(attract_settings),
	    cmocka_unit_test(knob_settings),
	    cmocka_unit_test(prepare_threads_setting),
	    cmocka_unit_test(include_file),
	    cmocka_unit_test(broken_include_is_ignored),
	};
	return cmocka_run_group_tests_name("options", tests, NULL, NULL);
}
