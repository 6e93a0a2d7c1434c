/* Every setting, from the command line and from kiosk.ini, parsed into
 * the config structs of the modules that use them. One table
 * (src/app/options.c) names each setting's option, its [section] key, its
 * type and range, and its help: the two sources cannot drift apart. A
 * second table says what a reload (SIGHUP) does with each section. */
#ifndef MK_OPTIONS_H
#define MK_OPTIONS_H

#include "app/app.h"
#include "app/content.h"
#include "camera/camera_feed.h"
#include "display/display.h"
#include "input/gpio.h"
#include "input/keyboard.h"
#include "util/log.h"

#include <stdbool.h>
#include <stdio.h>

enum backend_kind { BACKEND_AUTO, BACKEND_KMS, BACKEND_OSMESA, BACKEND_EGL_HEADLESS };

enum options_status {
	OPTIONS_OK,
	OPTIONS_USAGE,	/* a bad command line: exit 2 */
	OPTIONS_CONFIG, /* a bad config file: exit 78, EX_CONFIG */
};

/* The config file's sections, in the order kiosk.ini has them. */
enum options_section {
	OPTIONS_DISPLAY,
	OPTIONS_SCENE,
	OPTIONS_KIOSK,
	OPTIONS_BUTTONS,
	OPTIONS_KEYBOARD,
	OPTIONS_MATERIAL,
	OPTIONS_CAMERA,
	OPTIONS_SECTIONS
};

/* What a reload does with a section's settings. */
enum options_reload {
	OPTIONS_AT_START, /* read once (the display is opened once): a restart applies them */
	OPTIONS_LIVE,	  /* applied with the new scene and a fresh app state */
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
	/* the command line only */
	char *config;
	char *output;
	char *shader_dir;
	int frames;
	bool stats;
	bool help, version;
};

/* Defaults, then the file named by --config, then the rest of the command
 * line over it. Every error is one line naming the option, or the file,
 * line and key, and what is accepted. opts is to be released whatever
 * the status. */
enum options_status options_parse(struct options *opts, int argc, char **argv);
/* Read one INI file over opts. */
enum options_status options_read_file(struct options *opts, const char *path);
/* The same from memory (for the fuzzer); name is used in messages only. */
enum options_status options_read_memory(struct options *opts, const char *name, const char *text,
					size_t size);
/* A deep copy; 0 or -ENOMEM (dst then holds nothing to release). */
int options_copy(struct options *dst, const struct options *src);
void options_release(struct options *opts);
/* Bit (1u << enum options_section) for each section whose settings
 * differ; an at-start section's live_key is not counted. */
unsigned options_changed(const struct options *a, const struct options *b);
void options_usage(FILE *out);
const char *backend_name(enum backend_kind kind);

#endif
