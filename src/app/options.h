/* Every setting, from the command line and from kiosk.ini. One table
 * (src/app/options.c) names each setting's option, its [section] key, its
 * type and range, and its help: the two sources cannot drift apart. */
#ifndef MK_OPTIONS_H
#define MK_OPTIONS_H

#include "input/gpio.h"
#include "scene/material.h"
#include "render/shading.h"

#include <stdbool.h>
#include <stdio.h>

enum backend_kind { BACKEND_AUTO, BACKEND_KMS, BACKEND_OSMESA, BACKEND_EGL_HEADLESS };
enum verbosity { VERBOSITY_ERROR, VERBOSITY_WARNING, VERBOSITY_INFO, VERBOSITY_DEBUG };

/* Status of options_parse() besides 0. */
#define OPTIONS_USAGE  (-1000) /* a bad command line: exit 2 */
#define OPTIONS_CONFIG (-1001) /* a bad config file: exit 78, EX_CONFIG */

struct options {
	/* [display] */
	int backend; /* enum backend_kind */
	int size[2]; /* offscreen width, height */
	int rotation;
	char *device;	    /* KMS: /dev/dri/cardN; NULL: the first with a display */
	char *connector;    /* KMS: HDMI-A-1; NULL: the first connected */
	char *display_mode; /* KMS: WxH or WxH@Hz; NULL: the preferred */
	int on_busy;	    /* KMS: 0 wait, 1 exit when another program holds it */
	int kms_api;	    /* KMS: 0 auto, 1 atomic, 2 legacy (for tests) */
	/* [scene] */
	char *model;  /* NULL: the built-in torus knot */
	char *matcap; /* a file or a folder; NULL: the shipped folder */
	int mode;     /* enum shading_mode */
	bool ortho;
	double yaw, pitch;
	double lod_pixels; /* simplify to this error on the display; 0: off */
	/* [kiosk] */
	int log_level;	      /* enum verbosity */
	double attract_after; /* seconds idle before turning by itself; 0: never */
	double attract_speed; /* degrees per second */
	double turn_speed;    /* degrees per second while a turn is held */
	double turn_step;     /* degrees a tap turns */
	/* [buttons] */
	char *gpio_chip;   /* NULL or "": line names are looked for on every chip */
	int button_active; /* enum button_active */
	int button_bias;   /* enum button_bias */
	int debounce_ms, long_press_ms, repeat_ms;
	char *button_line[GPIO_BUTTONS]; /* GPIO17, 17...; NULL, "" or "none": not wired */
	int button_press[GPIO_BUTTONS];	 /* enum app_action */
	int button_long[GPIO_BUTTONS];	 /* enum app_action; 0 (none): no long press */
	/* [keyboard] */
	char *keyboard; /* NULL or "auto": every keyboard; "none"; or one device */
	/* [material] */
	struct material_config material;
	/* [camera] */
	int camera;	       /* 0 off, 1 on: the live camera as a matcap */
	char *camera_id;       /* a libcamera id or an index; NULL: the first */
	int camera_size[2];    /* asked of the camera */
	double camera_crop[3]; /* the ball's centre x, y and radius, 0..1 */
	bool camera_mirror;
	double camera_stall; /* seconds without a frame: the camera is lost */
	int camera_import;   /* 0 auto: import dmabufs where the driver can; 1 off */
	/* the command line only */
	char *config;
	char *output;
	char *shader_dir;
	int frames;
	bool stats;
	bool help, version;
};

/* Defaults, then the file named by --config, then the rest of the command
 * line over it. Returns 0, OPTIONS_USAGE or OPTIONS_CONFIG;
 * every error is one line naming the option, or the file, line and key,
 * and what is accepted. */
int options_parse(struct options *opts, int argc, char **argv);
/* Read one INI file over opts (used by options_parse and by reload). */
int options_read_file(struct options *opts, const char *path);
/* The same from memory (for the fuzzer); name is used in messages only. */
int options_read_memory(struct options *opts, const char *name, const char *text, size_t size);
void options_release(struct options *opts);
void options_usage(FILE *out);
const char *backend_name(enum backend_kind kind);

#endif
