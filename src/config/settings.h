/* Every setting, and what is done with one: struct options (the config
 * structs of the modules that use the settings, plus the command line's
 * own), the one table that names each setting's option, its [section]
 * key, its type, range and help, and the reload rules of each section.
 * src/config/options.c reads the command line and kiosk.ini through it, so
 * the two sources cannot drift apart. */
#ifndef MK_SETTINGS_H
#define MK_SETTINGS_H

#include "camera/camera_feed.h"
#include "config/content_config.h"
#include "config/mqtt_config.h"
#include "config/screen_config.h"
#include "display/display.h"
#include "input/gpio.h"
#include "input/keyboard.h"
#include "input/knob.h"
#include "input/touch.h"
#include "render/output_view.h"
#include "state/app.h"
#include "util/log.h"

#include <stdbool.h>
#include <stddef.h>

enum backend_kind { BACKEND_AUTO, BACKEND_KMS, BACKEND_OSMESA, BACKEND_EGL_HEADLESS };

/* The config file's sections, in the order kiosk.ini has them. */
enum options_section {
	OPTIONS_DISPLAY,
	OPTIONS_SCENE,
	OPTIONS_KIOSK,
	OPTIONS_BUTTONS,
	OPTIONS_KEYBOARD,
	OPTIONS_MATERIAL,
	OPTIONS_CAMERA,
	OPTIONS_POWER,
	OPTIONS_TOUCH,
	OPTIONS_STATUS,
	OPTIONS_FRAME,
	OPTIONS_CAPTION,
	OPTIONS_KNOB,
	OPTIONS_MQTT,
	OPTIONS_WALL,
	OPTIONS_SECTIONS
};

/* What a reload does with a section's settings. */
enum options_reload {
	OPTIONS_AT_START, /* read once (the display is opened once): a restart applies them */
	OPTIONS_LIVE,	  /* applied with the new content and a fresh app state */
	OPTIONS_REOPEN,	  /* applied live: its devices are opened again when they changed */
};

struct options_section_rule {
	const char *name;
	enum options_reload reload;
	const char *live_key; /* a key applied live in an at-start section, or NULL */
	const char *says;     /* what --help and kiosk.ini say a reload does */
};

/* The reload rules, by enum options_section. */
extern const struct options_section_rule options_sections[OPTIONS_SECTIONS];

struct options {
	/* [display] */
	enum backend_kind backend;
	struct display_config display; /* size, device, connector, mode, on_busy, kms_api */
	/* [scene], [display] rotation and [material] */
	struct content_config content;
	/* [kiosk] */
	enum log_level log_level;
	struct app_config app; /* turning and attract mode; the kiosk adds the rest */
	/* [buttons] */
	struct gpio_config buttons;
	/* [keyboard] */
	struct keyboard_config keyboard;
	/* [camera] */
	struct camera_feed_config camera;
	/* [power] */
	struct screen_config power;
	/* [touch]; its gestures' settings are in app */
	struct touch_config touch;
	/* [knob] */
	struct knob_config knob;
	/* [mqtt] */
	struct mqtt_config mqtt;
	/* [output.NAME]: what each of several outputs shows */
	struct output_views outputs;
	char *poster;  /* [display] poster */
	char *include; /* [kiosk] include */
	char *metrics; /* [status] metrics */
	/* Where each setting came from (file and line), and the files read,
	 * for --check-config and the messages; NULL: none recorded. Owned;
	 * options_copy does not copy it (a copy has none). */
	struct options_origins *origins;
	bool include_ignored; /* the include had errors: the installed files alone */
	/* [wall] settings that did not hold together, said and put back
	 * (config/wall_settings.h): --check-config's verdict counts them. */
	int wall_refused;
	/* the command line only */
	char *config;
	char *import;
	char *output;
	char *as_output; /* --as-output NAME: the still as that output shows it */
	char *shader_dir;
	int frames;
	int hotspot; /* --hotspot N: the still faces hotspot N; 0: none */
	bool stats;
	bool help, version;
	bool status, check_config;
	/* --stop N (1 the first; 0: none) and --at SECONDS (< 0: none): the
	 * moment an offscreen still shows (app/preview.h). */
	int preview_stop;
	double preview_at;
};

/* K_DEGREES: read in degrees, kept in radians. K_LEVEL: a log level by
 * its name. A K_DOUBLE with choices takes its first word for 0 (auto).
 * K_CHOICE: an index into choices, kept as an enum (or a bool
 * for a choice of two). */
enum option_kind {
	K_FLAG,
	K_STRING,
	K_INT,
	K_DOUBLE,
	K_DEGREES,
	K_SIZE,
	K_CHOICE,
	K_LEVEL,
	K_PAIR /* two ints as A,B ([wall] position), kept side by side as K_SIZE's */
};
/* Whether d's value is two ints side by side (WxH, or A,B). */
#define OPTION_TWO_INTS(d) ((d)->kind == K_SIZE || (d)->kind == K_PAIR)

/* The command line only: no [section] key. */
#define OPTION_CLI OPTIONS_SECTIONS

struct option_def {
	const char *name; /* --name */
	char short_name;
	enum options_section section; /* in kiosk.ini; OPTION_CLI: the command line only */
	const char *key;
	enum option_kind kind;
	size_t offset, size;
	double lo, hi, step; /* numbers: the accepted range (and step) */
	const char *const *choices;
	const char *arg;
	const char *help;
};

/* The table's length: the compiler refuses an entry more, and
 * tests/unit/test_options.c one less. */
#define OPTION_DEFS 153
extern const struct option_def option_defs[OPTION_DEFS];

void option_defaults(struct options *o);
/* What a setting accepts, for error messages and --help. */
void option_accepted(const struct option_def *d, char *buf, size_t n);
/* Store value; false when it is not one the setting accepts. */
bool option_set_value(struct options *o, const struct option_def *d, const char *value);

/* A deep copy; 0 or -ENOMEM (dst then holds nothing to release). */
int options_copy(struct options *dst, const struct options *src);
void options_release(struct options *opts);
/* The same for the content part alone (struct options' content), for
 * whoever needs only that, such as the model worker. */
int content_config_copy(struct content_config *dst, const struct content_config *src);
void content_config_release(struct content_config *c);
/* Bit (1u << enum options_section) for each section whose settings
 * differ; an at-start section's live_key is not counted. */
unsigned options_changed(const struct options *a, const struct options *b);
const char *backend_name(enum backend_kind kind);

/* One setting's origin: a file and line, "the command line" (line 0), or
 * NULL when it has its default. */
struct options_origin {
	const char *file;
	int line;
};

/* The origin of d's value in o (files as they were named). */
struct options_origin options_origin(const struct options *o, const struct option_def *d);
/* Note that d was set by file at line (file NULL: the command line). */
int options_origin_set(struct options *o, const struct option_def *d, const char *file, int line);
/* Add file to the list of those read; its copy, or NULL on -ENOMEM. */
const char *options_origin_file(struct options *o, const char *file);
/* The files read, in order: the count, and each through *files. */
int options_files_read(const struct options *o, const char *const **files);
/* options_release does this; for a reader that starts over. */
void options_origins_free(struct options *o);
/* Whether the command line set d (a setting kept in struct content_config). */
bool content_config_from_cli(const struct content_config *c, const struct option_def *d);
/* The one precedence: each setting of dst that the command line set in
 * cli is cli's again (a model's NAME.ini read over dst does not override
 * the command line). 0, or -ENOMEM. */
int content_config_keep_cli(struct content_config *dst, const struct content_config *cli);
/* d's value in o as a settings file would write it ("45", "top",
 * "640x480"; a string as it is, "" when none). */
void option_value_text(const struct options *o, const struct option_def *d, char *buf, size_t n);

#endif
