#include "app/options.h"
#include "app/app.h"
#include "util/log.h"

#include <errno.h>
#include <getopt.h>
#include <ini.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

enum kind { K_FLAG, K_STRING, K_INT, K_DOUBLE, K_SIZE, K_CHOICE };

struct option_def {
	const char *name; /* --name */
	char short_name;
	const char *section; /* in kiosk.ini; NULL: the command line only */
	const char *key;
	enum kind kind;
	size_t offset;
	double lo, hi, step; /* numbers: the accepted range (and step) */
	const char *const *choices;
	const char *arg;
	const char *help;
};

static const char *const backend_names[] = {"auto", "kms", "osmesa", "egl-headless", NULL};
static const char *const mode_names[] = {"normal", "view", "sem-vertex", "sem-fragment", NULL};
static const char *const level_names[] = {"error", "warning", "info", "debug", NULL};
static const char *const busy_names[] = {"wait", "exit", NULL};
static const char *const kms_api_names[] = {"auto", "atomic", "legacy", NULL};
static const char *const active_names[] = {"low", "high", NULL};
static const char *const bias_names[] = {"pull-up", "pull-down", "disable", "as-is", NULL};
static const char *const switch_names[] = {"auto", "off", "on", NULL}; /* enum material_switch */
static const char *const lit_names[] = {"off", "on", "beside", NULL};  /* enum material_lit */
static const char *const camera_names[] = {"off", "on", NULL};
static const char *const import_names[] = {"auto", "off", NULL};

#define OFF(f) offsetof(struct options, f)

static const struct option_def defs[] = {
    {"backend", 'b', "display", "backend", K_CHOICE, OFF(backend), 0, 0, 0, backend_names, "NAME",
     "auto, kms, osmesa or egl-headless; auto takes kms where there is a display output"},
    {"size", 's', "display", "size", K_SIZE, OFF(size), 16, 8192, 1, NULL, "WxH",
     "offscreen frame size"},
    {"rotate", 0, "display", "rotation", K_INT, OFF(rotation), 0, 270, 90, NULL, "DEG",
     "panel rotation: 0, 90, 180 or 270"},
    {"device", 0, "display", "device", K_STRING, OFF(device), 0, 0, 0, NULL, "PATH",
     "KMS: the DRM device (default: the first with a display)"},
    {"connector", 0, "display", "connector", K_STRING, OFF(connector), 0, 0, 0, NULL, "NAME",
     "KMS: the output, e.g. HDMI-A-1 or DSI-1 (default: the first connected)"},
    {"display-mode", 0, "display", "mode", K_STRING, OFF(display_mode), 0, 0, 0, NULL, "WxH[@HZ]",
     "KMS: the mode (default: the preferred, else the largest)"},
    {"on-busy", 0, "display", "on_busy", K_CHOICE, OFF(on_busy), 0, 0, 0, busy_names, "WHAT",
     "KMS: when another program holds the display: wait or exit"},
    {"kms-api", 0, "display", "kms_api", K_CHOICE, OFF(kms_api), 0, 0, 0, kms_api_names, "API",
     "KMS: auto (atomic where the driver has it), atomic or legacy; for testing"},
    {"model", 'm', "scene", "model", K_STRING, OFF(model), 0, 0, 0, NULL, "FILE",
     "a .gltf or .glb model (default: a built-in torus knot)"},
    {"matcap", 'c', "scene", "matcap", K_STRING, OFF(matcap), 0, 0, 0, NULL, "PATH",
     "a PNG/JPEG matcap, or a folder of them (cycled in name order)"},
    {"mode", 0, "scene", "mode", K_CHOICE, OFF(mode), 0, 0, 0, mode_names, "MODE",
     "normal, view, sem-vertex or sem-fragment"},
    {"ortho", 0, "scene", "ortho", K_FLAG, OFF(ortho), 0, 0, 0, NULL, NULL, "orthographic camera"},
    {"yaw", 0, "scene", "yaw", K_DOUBLE, OFF(yaw), -360, 360, 0, NULL, "DEG",
     "turn the model about the vertical axis"},
    {"pitch", 0, "scene", "pitch", K_DOUBLE, OFF(pitch), -360, 360, 0, NULL, "DEG",
     "tilt the model about the horizontal axis"},
    {"lod-pixels", 0, "scene", "lod_pixels", K_DOUBLE, OFF(lod_pixels), 0, 64, 0, NULL, "PX",
     "draw no detail under PX pixels: simplify smaller triangles to that; 0: never"},
    {"log-level", 0, "kiosk", "log_level", K_CHOICE, OFF(log_level), 0, 0, 0, level_names, "LEVEL",
     "error, warning, info or debug"},
    {"attract-after", 0, "kiosk", "attract_after", K_DOUBLE, OFF(attract_after), 0, 86400, 0, NULL,
     "S", "seconds without input before the model turns by itself; 0: never"},
    {"attract-speed", 0, "kiosk", "attract_speed", K_DOUBLE, OFF(attract_speed), 0, 360, 0, NULL,
     "DEG/S", "how fast it turns by itself"},
    {"turn-speed", 0, "kiosk", "turn_speed", K_DOUBLE, OFF(turn_speed), 1, 1440, 0, NULL, "DEG/S",
     "how fast a held button or arrow key turns the model"},
    {"turn-step", 0, "kiosk", "turn_step", K_DOUBLE, OFF(turn_step), 0, 90, 0, NULL, "DEG",
     "how far a short tap turns it"},
    {"gpio-chip", 0, "buttons", "chip", K_STRING, OFF(gpio_chip), 0, 0, 0, NULL, "CHIP",
     "GPIO chip by name, path or label (default: line names on every chip)"},
    {"button-active", 0, "buttons", "active", K_CHOICE, OFF(button_active), 0, 0, 0, active_names,
     "LEVEL", "low (a button that pulls the line to ground) or high"},
    {"button-bias", 0, "buttons", "bias", K_CHOICE, OFF(button_bias), 0, 0, 0, bias_names, "BIAS",
     "pull-up, pull-down, disable or as-is"},
    {"debounce-ms", 0, "buttons", "debounce_ms", K_INT, OFF(debounce_ms), 0, 100, 1, NULL, "MS",
     "edges this close to the one before are contact bounce"},
    {"long-press-ms", 0, "buttons", "long_press_ms", K_INT, OFF(long_press_ms), 100, 10000, 1, NULL,
     "MS", "a press held this long is a long press"},
    {"repeat-ms", 0, "buttons", "repeat_ms", K_INT, OFF(repeat_ms), 0, 5000, 1, NULL, "MS",
     "a held button with no long action repeats every MS (0: never)"},
    {"button-left", 0, "buttons", "left", K_STRING, OFF(button_line[0]), 0, 0, 0, NULL, "LINE",
     "the left button's line: a name (GPIO17) or an offset; none: not wired"},
    {"left-press", 0, "buttons", "left_press", K_CHOICE, OFF(button_press[0]), 0, 0, 0,
     app_action_names, "ACT", "what a press of left does"},
    {"left-long-press", 0, "buttons", "left_long_press", K_CHOICE, OFF(button_long[0]), 0, 0, 0,
     app_action_names, "ACT", "what a long press of left does (none: no long press)"},
    {"button-right", 0, "buttons", "right", K_STRING, OFF(button_line[1]), 0, 0, 0, NULL, "LINE",
     "the right button's line: a name (GPIO17) or an offset; none: not wired"},
    {"right-press", 0, "buttons", "right_press", K_CHOICE, OFF(button_press[1]), 0, 0, 0,
     app_action_names, "ACT", "what a press of right does"},
    {"right-long-press", 0, "buttons", "right_long_press", K_CHOICE, OFF(button_long[1]), 0, 0, 0,
     app_action_names, "ACT", "what a long press of right does (none: no long press)"},
    {"button-select", 0, "buttons", "select", K_STRING, OFF(button_line[2]), 0, 0, 0, NULL, "LINE",
     "the select button's line: a name (GPIO17) or an offset; none: not wired"},
    {"select-press", 0, "buttons", "select_press", K_CHOICE, OFF(button_press[2]), 0, 0, 0,
     app_action_names, "ACT", "what a press of select does"},
    {"select-long-press", 0, "buttons", "select_long_press", K_CHOICE, OFF(button_long[2]), 0, 0, 0,
     app_action_names, "ACT", "what a long press of select does (none: no long press)"},
    {"keyboard", 0, "keyboard", "device", K_STRING, OFF(keyboard), 0, 0, 0, NULL, "DEV",
     "auto (every keyboard under /dev/input), none, or one /dev/input/eventN"},
    {"iridescence", 0, "material", "iridescence", K_CHOICE, OFF(material.iridescence), 0, 0, 0,
     switch_names, "WHEN", "hue layer from the view angle: auto (when the glTF has it), off, on"},
    {"iridescence-range", 0, "material", "iridescence_range", K_DOUBLE, OFF(material.hue_range), -8,
     8, 0, NULL, "TURNS", "hue change from face-on to grazing"},
    {"iridescence-average", 0, "material", "iridescence_average", K_DOUBLE,
     OFF(material.hue_average), -8, 8, 0, NULL, "TURNS", "hue face-on (0 red, 1/3 green)"},
    {"iridescence-shift", 0, "material", "iridescence_shift", K_DOUBLE, OFF(material.hue_shift), -8,
     8, 0, NULL, "TURNS", "hue shift where the detail map's alpha is 0"},
    {"iridescence-opacity", 0, "material", "iridescence_opacity", K_DOUBLE, OFF(material.opacity),
     0, 1, 0, NULL, "A", "how much the hue layer covers the matcap"},
    {"iridescence-saturation", 0, "material", "iridescence_saturation", K_DOUBLE,
     OFF(material.saturation), 0, 1, 0, NULL, "S", "the hue layer's HSV saturation"},
    {"iridescence-value", 0, "material", "iridescence_value", K_DOUBLE, OFF(material.value), 0, 1,
     0, NULL, "V", "the hue layer's HSV value"},
    {"iridescence-ramp", 0, "material", "iridescence_ramp", K_STRING, OFF(material.ramp), 0, 0, 0,
     NULL, "FILE", "a PNG/JPEG colour ramp to use instead of HSV"},
    {"detail", 0, "material", "detail", K_CHOICE, OFF(material.detail), 0, 0, 0, switch_names,
     "WHEN", "detail map: auto (when one is given), off, on"},
    {"detail-map", 0, "material", "detail_map", K_STRING, OFF(material.detail_map), 0, 0, 0, NULL,
     "FILE", "packed map: normal xy (rg), occlusion (b), hue shift (a)"},
    {"displacement-map", 0, "material", "displacement_map", K_STRING, OFF(material.height_map), 0,
     0, 0, NULL, "FILE", "a height map: subdivide and displace the model"},
    {"displacement-scale", 0, "material", "displacement_scale", K_DOUBLE,
     OFF(material.displacement_scale), 0, 1, 0, NULL, "R", "height of white, in model radii"},
    {"displacement-pixels", 0, "material", "displacement_pixels", K_DOUBLE,
     OFF(material.displacement_pixels), 0.5, 64, 0, NULL, "PX", "edge length to subdivide to"},
    {"displacement-triangles", 0, "material", "displacement_triangles", K_INT,
     OFF(material.displacement_triangles), 1000, 16000000, 1, NULL, "N",
     "most triangles subdivision may make"},
    {"lit", 0, "material", "lit", K_CHOICE, OFF(material.lit), 0, 0, 0, lit_names, "HOW",
     "diffuse + Blinn-Phong instead of the matcap: off, on, beside (both)"},
    {"lit-shininess", 0, "material", "lit_shininess", K_DOUBLE, OFF(material.shininess), 1, 256, 0,
     NULL, "N", "the lit mode's specular exponent"},
    {"camera", 0, "camera", "enabled", K_CHOICE, OFF(camera), 0, 0, 0, camera_names, "WHEN",
     "on: a live camera is the matcap whenever one is there; off: never"},
    {"camera-id", 0, "camera", "id", K_STRING, OFF(camera_id), 0, 0, 0, NULL, "ID",
     "the camera, by libcamera id or by index (0: the first)"},
    {"camera-size", 0, "camera", "size", K_SIZE, OFF(camera_size), 16, 4096, 1, NULL, "WxH",
     "the frame size asked of the camera"},
    {"camera-crop-x", 0, "camera", "crop_x", K_DOUBLE, OFF(camera_crop[0]), 0, 1, 0, NULL, "X",
     "the ball's centre, 0 (left) to 1 (right) of the frame"},
    {"camera-crop-y", 0, "camera", "crop_y", K_DOUBLE, OFF(camera_crop[1]), 0, 1, 0, NULL, "Y",
     "the ball's centre, 0 (top) to 1 (bottom) of the frame"},
    {"camera-crop-radius", 0, "camera", "crop_radius", K_DOUBLE, OFF(camera_crop[2]), 0.01, 1, 0,
     NULL, "R", "the ball's radius, in shares of the frame's shorter side"},
    {"camera-mirror", 0, "camera", "mirror", K_FLAG, OFF(camera_mirror), 0, 0, 0, NULL, NULL,
     "mirror the camera picture left to right"},
    {"camera-stall", 0, "camera", "stall_timeout", K_DOUBLE, OFF(camera_stall), 0.2, 600, 0, NULL,
     "S", "seconds without a frame before the camera counts as lost"},
    {"camera-import", 0, "camera", "import", K_CHOICE, OFF(camera_import), 0, 0, 0, import_names,
     "HOW", "auto: frames as EGLImages where the driver takes them; off: always upload"},
    {"config", 'C', NULL, NULL, K_STRING, OFF(config), 0, 0, 0, NULL, "FILE",
     "read settings from an INI file first (see config/kiosk.ini)"},
    {"output", 'o', NULL, NULL, K_STRING, OFF(output), 0, 0, 0, NULL, "FILE",
     "draw offscreen and write the last frame as PNG"},
    {"frames", 0, NULL, NULL, K_INT, OFF(frames), 1, 1e8, 1, NULL, "N",
     "frames to draw offscreen (default 1)"},
    {"stats", 0, NULL, NULL, K_FLAG, OFF(stats), 0, 0, 0, NULL, NULL,
     "print frame timings and peak memory"},
    {"shader-dir", 0, NULL, NULL, K_STRING, OFF(shader_dir), 0, 0, 0, NULL, "DIR",
     "read shaders from DIR instead of the built-in copy"},
    {"help", 'h', NULL, NULL, K_FLAG, OFF(help), 0, 0, 0, NULL, NULL, "this text"},
    {"version", 'V', NULL, NULL, K_FLAG, OFF(version), 0, 0, 0, NULL, NULL, "the version"},
};

#define N_DEFS (sizeof(defs) / sizeof(defs[0]))

const char *backend_name(enum backend_kind kind)
{
	return backend_names[kind];
}

static void defaults(struct options *o)
{
	memset(o, 0, sizeof(*o));
	o->size[0] = 1280;
	o->size[1] = 720;
	o->mode = SHADING_VIEW;
	o->frames = 1;
	o->pitch = 20.0;
	o->yaw = -30.0;
	o->lod_pixels = 4.0;
	o->log_level = VERBOSITY_INFO;
	o->attract_after = 60;
	o->attract_speed = 15;
	o->turn_speed = 90;
	o->turn_step = 5;
	o->debounce_ms = 10;
	o->long_press_ms = 800;
	o->button_press[0] = ACTION_TURN_LEFT;
	o->button_press[1] = ACTION_TURN_RIGHT;
	o->button_press[2] = ACTION_NEXT_MATCAP;
	o->button_long[2] = ACTION_TOGGLE_CAMERA;
	material_config_defaults(&o->material);
	o->camera = 1;
	o->camera_size[0] = o->camera_size[1] = 512;
	o->camera_crop[0] = o->camera_crop[1] = o->camera_crop[2] = 0.5;
	o->camera_stall = 3;
}

void options_release(struct options *o)
{
	for (size_t i = 0; i < N_DEFS; i++)
		if (defs[i].kind == K_STRING) {
			char **p = (char **)((char *)o + defs[i].offset);

			free(*p);
			*p = NULL;
		}
}

/* What a setting accepts, for error messages and --help. */
static void accepted(const struct option_def *d, char *buf, size_t n)
{
	size_t len = 0;

	switch (d->kind) {
	case K_INT:
		if (d->step > 1)
			snprintf(buf, n, "a multiple of %g from %g to %g", d->step, d->lo, d->hi);
		else
			snprintf(buf, n, "a whole number from %g to %g", d->lo, d->hi);
		return;
	case K_DOUBLE:
		snprintf(buf, n, "a number from %g to %g", d->lo, d->hi);
		return;
	case K_SIZE:
		snprintf(buf, n, "WIDTHxHEIGHT, each from %g to %g", d->lo, d->hi);
		return;
	case K_FLAG:
		snprintf(buf, n, "true or false");
		return;
	case K_CHOICE:
		buf[0] = '\0';
		for (const char *const *c = d->choices; *c && len + 1 < n; c++)
			len += (size_t)snprintf(buf + len, n - len, "%s%s",
						c == d->choices ? "" : ", ", *c);
		return;
	default:
		snprintf(buf, n, "a path");
	}
}

static bool parse_number(const char *s, double lo, double hi, double step, double *out)
{
	char *end;

	errno = 0;
	*out = strtod(s, &end);
	if (errno || end == s || *end || !(*out >= lo && *out <= hi))
		return false;
	return step == 0 || (*out == (double)(long)*out && (long)*out % (long)step == 0);
}

static bool parse_size(const char *s, const struct option_def *d, int *out)
{
	char w[16], h[16];
	double a, b;
	const char *x = strchr(s, 'x');

	if (!x || x == s || (size_t)(x - s) >= sizeof(w) || strlen(x + 1) >= sizeof(h))
		return false;
	memcpy(w, s, (size_t)(x - s));
	w[x - s] = '\0';
	strcpy(h, x + 1);
	if (!parse_number(w, d->lo, d->hi, 1, &a) || !parse_number(h, d->lo, d->hi, 1, &b))
		return false;
	out[0] = (int)a;
	out[1] = (int)b;
	return true;
}

static bool parse_flag(const char *s, bool *out)
{
	static const char *const yes[] = {"true", "yes", "on", "1"}, *const no[] = {"false", "no",
										    "off", "0"};

	for (int i = 0; i < 4; i++) {
		if (strcmp(s, yes[i]) == 0 || strcmp(s, no[i]) == 0) {
			*out = strcmp(s, yes[i]) == 0;
			return true;
		}
	}
	return false;
}

/* Store value; false when it is not one the setting accepts. */
static bool set_value(struct options *o, const struct option_def *d, const char *value)
{
	void *p = (char *)o + d->offset;
	double v;

	switch (d->kind) {
	case K_FLAG:
		return parse_flag(value, p);
	case K_STRING:
		free(*(char **)p);
		*(char **)p = strdup(value);
		return *(char **)p != NULL;
	case K_INT:
		if (!parse_number(value, d->lo, d->hi, d->step ? d->step : 1, &v))
			return false;
		*(int *)p = (int)v;
		return true;
	case K_DOUBLE:
		if (!parse_number(value, d->lo, d->hi, 0, &v))
			return false;
		*(double *)p = v;
		return true;
	case K_SIZE:
		return parse_size(value, d, p);
	case K_CHOICE:
		for (int i = 0; d->choices[i]; i++)
			if (strcmp(value, d->choices[i]) == 0) {
				*(int *)p = i;
				return true;
			}
		return false;
	}
	return false;
}

/* The file: inih parses, a line reader of ours counts lines so that
 * every message names one, and each key may be set once. */
struct file_state {
	struct options *opts;
	const char *path;
	FILE *f;
	int line;
	int seen_line[N_DEFS];
	int errors;
};

/* Leading blanks are dropped: inih would take an indented key for the
 * continuation of the line above, and people indent INI files. */
static char *read_line(char *str, int num, void *stream)
{
	struct file_state *st = stream;
	char *r = fgets(str, num, st->f);
	size_t skip;

	if (!r)
		return NULL;
	st->line++;
	skip = strspn(r, " \t");
	if (skip)
		memmove(r, r + skip, strlen(r + skip) + 1);
	return r;
}

static const struct option_def *find_key(const char *section, const char *key)
{
	for (size_t i = 0; i < N_DEFS; i++)
		if (defs[i].section && !strcmp(defs[i].section, section) &&
		    !strcmp(defs[i].key, key))
			return &defs[i];
	return NULL;
}

static void list_keys(const char *section, char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (size_t i = 0; i < N_DEFS && len + 1 < n; i++)
		if (defs[i].section && !strcmp(defs[i].section, section))
			len += (size_t)snprintf(buf + len, n - len, "%s%s", len ? ", " : "",
						defs[i].key);
}

static int on_key(void *user, const char *section, const char *key, const char *value)
{
	struct file_state *st = user;
	const struct option_def *d = find_key(section, key);
	char what[256];

	st->errors++;
	if (!d) {
		list_keys(section, what, sizeof(what));
		if (what[0])
			log_err("%s:%d: unknown key '%s' in [%s]; expected one of: %s", st->path,
				st->line, key, section, what);
		else
			log_err("%s:%d: unknown section [%s]; expected [display], [scene], "
				"[kiosk], [buttons], [keyboard], [material] or [camera]",
				st->path, st->line, section);
	} else if (st->seen_line[d - defs]) {
		log_err("%s:%d: [%s] %s is set again (first on line %d)", st->path, st->line,
			section, key, st->seen_line[d - defs]);
	} else {
		/* Counted as set even when the value is bad, so a second line
		 * for the same key is reported too. */
		st->seen_line[d - defs] = st->line;
		if (set_value(st->opts, d, value)) {
			st->errors--;
		} else {
			accepted(d, what, sizeof(what));
			log_err("%s:%d: [%s] %s = '%s' is not valid; expected %s", st->path,
				st->line, section, key, value, what);
		}
	}
	return 1; /* go on, so every error in the file is reported at once */
}

static bool wired(const char *line)
{
	return line && *line && strcmp(line, "none") != 0;
}

/* The same name, or the same offset however written. (GPIO17 and 17 may
 * be one line too; only the chip can tell, and src/input/gpio.c asks it.) */
static bool same_line(const char *a, const char *b)
{
	char *end_a, *end_b;
	unsigned long x = strtoul(a, &end_a, 10), y = strtoul(b, &end_b, 10);

	if (end_a != a && !*end_a && end_b != b && !*end_b)
		return x == y;
	return strcmp(a, b) == 0;
}

/* Two buttons on one line would fight over it: the first such pair. */
static bool line_clash(const struct options *o, int *first, int *second)
{
	for (int i = 0; i < GPIO_BUTTONS; i++)
		for (int j = i + 1; j < GPIO_BUTTONS; j++)
			if (wired(o->button_line[i]) && wired(o->button_line[j]) &&
			    same_line(o->button_line[i], o->button_line[j])) {
				*first = i;
				*second = j;
				return true;
			}
	return false;
}

static int line_key_seen(const struct file_state *st, int button)
{
	return st->seen_line[find_key("buttons", gpio_button_names[button]) - defs];
}

/* Counts an error when this file put two buttons on one line. */
static void check_lines(struct file_state *st)
{
	int i, j, at_i, at_j;
	char first[32] = "";

	if (!line_clash(st->opts, &i, &j))
		return;
	at_i = line_key_seen(st, i);
	at_j = line_key_seen(st, j);
	if (!at_i && !at_j)
		return;
	if (!at_j) { /* name the key this file set */
		int t = i;

		i = j;
		j = t;
		at_j = at_i;
		at_i = 0;
	}
	if (at_i)
		snprintf(first, sizeof(first), " (line %d)", at_i);
	st->errors++;
	log_err("%s:%d: [buttons] %s = %s is the line of %s too%s; each button needs its own line",
		st->path, at_j, gpio_button_names[j], st->opts->button_line[j],
		gpio_button_names[i], first);
}

static int read_stream(struct options *o, const char *path, FILE *f)
{
	struct file_state st = {.opts = o, .path = path, .f = f};
	int ret = ini_parse_stream(read_line, &st, on_key, &st);

	check_lines(&st);
	if (ret > 0)
		log_err("%s:%d: not an INI line; expected [section], key = value or a comment",
			path, ret);
	return ret || st.errors ? OPTIONS_CONFIG : 0;
}

int options_read_file(struct options *o, const char *path)
{
	FILE *f = fopen(path, "r");
	int ret;

	if (!f) {
		log_err("%s: cannot open config file: %s", path, strerror(errno));
		return OPTIONS_CONFIG;
	}
	ret = read_stream(o, path, f);
	fclose(f);
	return ret;
}

int options_read_memory(struct options *o, const char *name, const char *text, size_t size)
{
	FILE *f;
	int ret;

	if (size == 0)
		return 0; /* an empty file sets nothing (fmemopen refuses size 0) */
	f = fmemopen((void *)text, size, "r");
	if (!f) {
		log_err("%s: cannot read the config: %s", name, strerror(errno));
		return OPTIONS_CONFIG;
	}
	ret = read_stream(o, name, f);
	fclose(f);
	return ret;
}

/* The command line: getopt_long, with its table built from defs. */
static void build_getopt(struct option *longs, char *shorts)
{
	char *s = shorts;

	for (size_t i = 0; i < N_DEFS; i++) {
		longs[i] = (struct option){defs[i].name,
					   defs[i].kind == K_FLAG ? no_argument : required_argument,
					   NULL, (int)(256 + i)};
		if (defs[i].short_name) {
			*s++ = defs[i].short_name;
			if (defs[i].kind != K_FLAG)
				*s++ = ':';
		}
	}
	strcpy(s, "qv");
	longs[N_DEFS] = (struct option){"quiet", no_argument, NULL, 'q'};
	longs[N_DEFS + 1] = (struct option){"verbose", no_argument, NULL, 'v'};
	longs[N_DEFS + 2] = (struct option){NULL, 0, NULL, 0};
}

static const struct option_def *def_for(int c)
{
	if (c >= 256 && c < 256 + (int)N_DEFS)
		return &defs[c - 256];
	for (size_t i = 0; i < N_DEFS; i++)
		if (defs[i].short_name && defs[i].short_name == c)
			return &defs[i];
	return NULL;
}

static int apply_arg(struct options *o, int c, const char *arg)
{
	const struct option_def *d = def_for(c);
	char what[256];

	if (c == 'q' || c == 'v') {
		o->log_level = c == 'q' ? VERBOSITY_WARNING : VERBOSITY_DEBUG;
		return 0;
	}
	if (!d)
		return OPTIONS_USAGE; /* getopt has said what was wrong */
	if (set_value(o, d, d->kind == K_FLAG ? "true" : arg))
		return 0;
	accepted(d, what, sizeof(what));
	log_err("--%s: '%s' is not valid; expected %s", d->name, arg, what);
	return OPTIONS_USAGE;
}

/* --config is read before the other options, which then override it. */
static int read_config_first(struct options *o, int argc, char **argv)
{
	for (int i = 1; i < argc; i++) {
		const char *v = NULL;

		if (!strcmp(argv[i], "--"))
			break;
		if ((!strcmp(argv[i], "--config") || !strcmp(argv[i], "-C")) && i + 1 < argc)
			v = argv[i + 1];
		else if (!strncmp(argv[i], "--config=", 9))
			v = argv[i] + 9;
		if (v)
			return options_read_file(o, v);
	}
	return 0;
}

int options_parse(struct options *o, int argc, char **argv)
{
	struct option longs[N_DEFS + 3];
	char shorts[2 * N_DEFS + 3];
	int c, ret, first, second;

	defaults(o);
	build_getopt(longs, shorts);
	ret = read_config_first(o, argc, argv);
	if (ret)
		return ret;
	optind = 1;
	opterr = 1;
	while ((c = getopt_long(argc, argv, shorts, longs, NULL)) != -1)
		if ((ret = apply_arg(o, c, optarg)))
			return ret;
	if (optind < argc) {
		log_err("unexpected argument '%s' (see --help)", argv[optind]);
		return OPTIONS_USAGE;
	}
	if (line_clash(o, &first, &second)) {
		log_err("--button-%s and --button-%s are both line %s; each button needs its own "
			"line",
			gpio_button_names[first], gpio_button_names[second],
			o->button_line[second]);
		return OPTIONS_USAGE;
	}
	return 0;
}

void options_usage(FILE *out)
{
	fputs("Usage: matcap-kiosk [OPTION]...\n"
	      "Show a glTF model shaded with a matcap, fullscreen on DRM/KMS or offscreen.\n"
	      "Settings marked [section] key can also be set in the config file.\n\n",
	      out);
	for (size_t i = 0; i < N_DEFS; i++) {
		const struct option_def *d = &defs[i];
		char left[64], ini[128] = "";

		snprintf(left, sizeof(left), "%c%c%c --%s%s%s", d->short_name ? '-' : ' ',
			 d->short_name ? d->short_name : ' ', d->short_name ? ',' : ' ', d->name,
			 d->arg ? "=" : "", d->arg ? d->arg : "");
		if (d->section)
			snprintf(ini, sizeof(ini), "\n%31s[%s] %s in the config file", "",
				 d->section, d->key);
		fprintf(out, "  %-28s %s%s\n", left, d->help, ini);
	}
	fputs("  -q, --quiet                  errors and warnings only\n"
	      "  -v, --verbose                debug messages too\n",
	      out);
}
