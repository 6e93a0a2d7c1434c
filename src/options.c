#include "options.h"
#include "log.h"

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

#define OFF(f) offsetof(struct options, f)

static const struct option_def defs[] = {
    {"backend", 'b', "display", "backend", K_CHOICE, OFF(backend), 0, 0, 0, backend_names, "NAME",
     "auto, kms, osmesa or egl-headless; auto takes kms when a display is connected"},
    {"size", 's', "display", "size", K_SIZE, OFF(size), 16, 8192, 1, NULL, "WxH",
     "offscreen frame size"},
    {"rotate", 0, "display", "rotation", K_INT, OFF(rotation), 0, 270, 90, NULL, "DEG",
     "panel rotation: 0, 90, 180 or 270"},
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
    {"log-level", 0, "kiosk", "log_level", K_CHOICE, OFF(log_level), 0, 0, 0, level_names, "LEVEL",
     "error, warning, info or debug"},
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
	o->log_level = VERBOSITY_INFO;
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

static char *read_line(char *str, int num, void *stream)
{
	struct file_state *st = stream;
	char *r = fgets(str, num, st->f);

	if (r)
		st->line++;
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
			log_err("%s:%d: unknown section [%s]; expected [display], [scene] or "
				"[kiosk]",
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

int options_read_file(struct options *o, const char *path)
{
	struct file_state st = {.opts = o, .path = path};
	int ret;

	st.f = fopen(path, "r");
	if (!st.f) {
		log_err("%s: cannot open config file: %s", path, strerror(errno));
		return OPTIONS_CONFIG;
	}
	ret = ini_parse_stream(read_line, &st, on_key, &st);
	fclose(st.f);
	if (ret > 0)
		log_err("%s:%d: not an INI line; expected [section], key = value or a comment",
			path, ret);
	return ret || st.errors ? OPTIONS_CONFIG : 0;
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
	int c, ret;

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
