/* Reading the settings: the config file (inih) and the command line
 * (getopt_long), both through the table in src/config/settings.c, and
 * --help from it. */
#include "config/options.h"
#include "state/schedule.h"
#include "config/settings.h"
#include "render/background.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <getopt.h>
#include <ini.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The file: inih parses, a line reader of ours counts lines so that
 * every message names one, and each key may be set once. */
struct file_state {
	struct options *opts;
	const char *path;
	const char *dir; /* relative paths are taken from here; NULL: as written */
	FILE *f;
	int line;
	int seen_line[OPTION_DEFS];
	int errors;
	/* A model's own file: the keys it may hold; NULL: any. */
	bool (*allowed)(const char *section, const char *key);
	const char *allowed_text;
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

static bool in_section(const struct option_def *d, const char *section)
{
	return d->section != OPTION_CLI && !strcmp(options_sections[d->section].name, section);
}

static const struct option_def *find_key(const char *section, const char *key)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (in_section(&option_defs[i], section) && !strcmp(option_defs[i].key, key))
			return &option_defs[i];
	return NULL;
}

static void list_keys(const char *section, char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (size_t i = 0; i < OPTION_DEFS && len + 1 < n; i++)
		if (in_section(&option_defs[i], section))
			len += (size_t)snprintf(buf + len, n - len, "%s%s", len ? ", " : "",
						option_defs[i].key);
}

/* "[display], [scene], ... or [camera]" */
static void list_sections(char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (int i = 0; i < OPTIONS_SECTIONS && len + 1 < n; i++)
		len += (size_t)snprintf(buf + len, n - len, "%s[%s]",
					!i			   ? ""
					: i + 1 < OPTIONS_SECTIONS ? ", "
								   : " or ",
					options_sections[i].name);
}

/* The settings that name files: read from the folder of the file that
 * names them. (Devices are absolute, under /dev.) */
/* value: [display] background names a file when it is a picture's name. */
static bool names_files(const struct option_def *d, const char *value)
{
	static const char *const keys[] = {"model",
					   "matcap",
					   "poster",
					   "include",
					   "detail_map",
					   "displacement_map",
					   "iridescence_ramp",
					   "font",
					   "logo",
					   NULL};

	if (d->kind != K_STRING || d->section == OPTION_CLI)
		return false;
	if (!strcmp(d->key, "background"))
		return background_names_image(value);
	for (const char *const *k = keys; *k; k++)
		if (!strcmp(d->key, *k))
			return true;
	return false;
}

static bool quoted(const char *v)
{
	size_t n = strlen(v);

	return n >= 2 && (v[0] == '"' || v[0] == '\'') && v[n - 1] == v[0];
}

/* A refused line still counts as the key's first, so that a second line
 * for it is reported too. */
static void seen(struct file_state *st, const struct option_def *d)
{
	if (!st->seen_line[d - option_defs])
		st->seen_line[d - option_defs] = st->line;
}

/* A value of a setting that names files, its relative paths taken from
 * dir: each of a list's (model = a, b) too. "~" is not the service's home
 * (it has none): refused. NULL with *why set, or the value (malloc'd). */
static char *resolve_paths(const char *value, const char *dir, bool list, const char **why)
{
	size_t cap = strlen(value) * 2 + 1, len = 0;
	char *out = NULL, *copy = strdup(value), *save = NULL;
	const char *sep = list ? "," : "";

	*why = "out of memory";
	if (!copy)
		return NULL;
	for (char *t = list ? strtok_r(copy, sep, &save) : copy; t;
	     t = list ? strtok_r(NULL, sep, &save) : NULL) {
		char *grown;
		bool rel;

		t += strspn(t, " \t");
		rel = dir && *t && *t != '/';
		if (*t == '~') {
			*why =
			    "'~' is not expanded here (the service has no home folder); write the "
			    "full path, e.g. /srv/matcap-kiosk/model.glb";
			goto fail;
		}
		cap += rel ? strlen(dir) + 1 : 0;
		if (!(grown = realloc(out, cap)))
			goto fail;
		out = grown;
		len += (size_t)snprintf(out + len, cap - len, "%s%s%s%s", len ? ", " : "",
					rel ? dir : "", rel ? "/" : "", t);
	}
	free(copy);
	return out ? out : strdup("");
fail:
	free(copy);
	free(out);
	return NULL;
}

static void dir_of(const char *path, char *dir, size_t n)
{
	const char *slash = strrchr(path, '/');

	if (!slash)
		dir[0] = '\0';
	else
		snprintf(dir, n, "%.*s", slash == path ? 1 : (int)(slash - path), path);
}

static int on_key(void *user, const char *section, const char *key, const char *value)
{
	struct file_state *st = user;
	const struct option_def *d = find_key(section, key);
	char what[256], *resolved = NULL;
	const char *why = NULL;

	st->errors++;
	if (st->allowed && !st->allowed(section, key)) {
		log_err("%s:%d: [%s] %s is not a setting a model's own file may hold; it takes %s",
			st->path, st->line, section, key, st->allowed_text);
		return 1;
	}
	if (d && quoted(value)) {
		log_err("%s:%d: [%s] %s = %s: the quotes would be part of the value; write it "
			"without them (blanks inside a path are fine)",
			st->path, st->line, section, key, value);
		seen(st, d);
		return 1;
	}
	if (d && names_files(d, value) &&
	    !(resolved = resolve_paths(value, st->dir, !strcmp(key, "model"), &why))) {
		log_err("%s:%d: [%s] %s = '%s': %s", st->path, st->line, section, key, value, why);
		seen(st, d);
		return 1;
	}
	if (resolved)
		value = resolved;
	if (!d) {
		list_keys(section, what, sizeof(what));
		if (what[0]) {
			log_err("%s:%d: unknown key '%s' in [%s]; expected one of: %s", st->path,
				st->line, key, section, what);
		} else {
			list_sections(what, sizeof(what));
			log_err("%s:%d: unknown section [%s]; expected %s", st->path, st->line,
				section, what);
		}
	} else if (st->seen_line[d - option_defs]) {
		log_err("%s:%d: [%s] %s is set again (first on line %d)", st->path, st->line,
			section, key, st->seen_line[d - option_defs]);
	} else {
		/* Counted as set even when the value is bad, so a second line
		 * for the same key is reported too. */
		st->seen_line[d - option_defs] = st->line;
		if (option_set_value(st->opts, d, value)) {
			st->errors--;
			if (options_origin_set(st->opts, d, st->path, st->line))
				st->errors++;
		} else {
			option_accepted(d, what, sizeof(what));
			log_err("%s:%d: [%s] %s = '%s' is not valid; expected %s", st->path,
				st->line, section, key, value, what);
		}
	}
	free(resolved);
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
			if (wired(o->buttons.buttons[i].line) &&
			    wired(o->buttons.buttons[j].line) &&
			    same_line(o->buttons.buttons[i].line, o->buttons.buttons[j].line)) {
				*first = i;
				*second = j;
				return true;
			}
	return false;
}

static int line_key_seen(const struct file_state *st, int button)
{
	return st->seen_line[find_key("buttons", gpio_button_names[button]) - option_defs];
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
		st->path, at_j, gpio_button_names[j], st->opts->buttons.buttons[j].line,
		gpio_button_names[i], first);
}

/* Counts an error when this file set a schedule that does not parse: the
 * kiosk must not start and sleep at the wrong hours. */
static void check_schedule(struct file_state *st)
{
	const char *text = st->opts->power.schedule;
	int at = st->seen_line[find_key("power", "schedule") - option_defs];
	struct schedule sch;
	char err[160];

	if (!at || !text || !*text || !schedule_parse(&sch, text, err, sizeof(err)))
		return;
	st->errors++;
	log_err("%s:%d: [power] schedule = '%s' is not valid: %s; expected days and spans like "
		"'Mon-Fri 08:00-20:00, Sat 10:00-16:00'",
		st->path, at, text, err);
}

/* Counts an error when this file set a background that does not parse
 * (an image that does not decode is the scene's to say, as a model's). */
static void check_background(struct file_state *st)
{
	const char *text = st->opts->content.background;
	int at = st->seen_line[find_key("display", "background") - option_defs];
	struct background_spec spec;
	char err[200];

	if (!at || !background_parse(text, &spec, err, sizeof(err)))
		return;
	st->errors++;
	log_err("%s:%d: [display] background = '%s' is not valid: %s; expected %s", st->path, at,
		text, err, BACKGROUND_EXPECTED);
}

/* Counts an error for each [caption] colour this file set that does not
 * parse (the font and the logo are the content's to load, as a model). */
static void check_caption(struct file_state *st)
{
	const struct caption_config *c = &st->opts->content.caption;
	const char *keys[2] = {"color", "box"}, *values[2] = {c->color, c->box};

	for (int i = 0; i < 2; i++) {
		int at = st->seen_line[find_key("caption", keys[i]) - option_defs];
		unsigned char rgba[4];

		if (!at || (i == 1 && !strcmp(values[i], "none")) ||
		    caption_parse_color(values[i], rgba))
			continue;
		st->errors++;
		log_err("%s:%d: [caption] %s = '%s' is not valid; expected %s%s", st->path, at,
			keys[i], values[i], i ? "none or " : "", CAPTION_COLOR_EXPECTED);
	}
}

static int frame_line(const struct file_state *st, const char *key)
{
	return st->seen_line[find_key("frame", key) - option_defs];
}

/* Counts an error for each [frame] setting of this file that does not
 * hold together: an orientation or stops that do not parse, a minimum
 * above its maximum (the line of the maximum). */
static void check_frame(struct file_state *st)
{
	const struct frame_config *f = &st->opts->content.frame;
	struct app_frame af;
	struct quat q;
	char err[200], key[16];
	const char *what;
	int at;

	if (frame_line(st, "orientation") && frame_base(f, &q, err, sizeof(err))) {
		st->errors++;
		log_err("%s:%d: [frame] orientation = '%s' is not valid: %s", st->path,
			frame_line(st, "orientation"), f->orientation, err);
	}
	if (!frame_to_app(f, 0, 0, &af, err, sizeof(err)))
		return;
	/* "yaw_min is above yaw_max": the line of either; else the stops. */
	what = strstr(err, "_min is above") ? err : NULL;
	snprintf(key, sizeof(key), "%.*s_max", what ? (int)strcspn(err, "_") : 0, err);
	at = what ? frame_line(st, key) : frame_line(st, "stops");
	if (what && !at) {
		key[strlen(key) - 3] = '\0';
		strcat(key, "min");
		at = frame_line(st, key);
	}
	if (!at)
		return;
	st->errors++;
	log_err("%s:%d: [frame] %s is not valid: %s", st->path, at, what ? key : "stops", err);
}

static enum options_status read_stream(struct options *o, const char *path, const char *dir,
				       FILE *f)
{
	return options_read_stream(o, path, dir, f, NULL, NULL);
}

enum options_status options_read_stream(struct options *o, const char *path, const char *dir,
					FILE *f, bool (*allowed)(const char *, const char *),
					const char *allowed_text)
{
	struct file_state st = {.opts = o,
				.path = path,
				.dir = dir,
				.f = f,
				.allowed = allowed,
				.allowed_text = allowed_text};
	int ret;

	if (!options_origin_file(o, path))
		return OPTIONS_CONFIG;
	ret = ini_parse_stream(read_line, &st, on_key, &st);
	check_lines(&st);
	check_schedule(&st);
	check_background(&st);
	check_frame(&st);
	check_caption(&st);
	if (ret > 0)
		log_err("%s:%d: not an INI line; expected [section], key = value or a comment",
			path, ret);
	return ret || st.errors ? OPTIONS_CONFIG : OPTIONS_OK;
}

static enum options_status read_path(struct options *o, const char *path)
{
	FILE *f = fopen(path, "r");
	enum options_status ret;
	char dir[PATH_MAX];
	struct stat sb;

	if (!f) {
		log_err("%s: cannot open config file: %s", path, strerror(errno));
		return OPTIONS_CONFIG;
	}
	if (fstat(fileno(f), &sb) == 0 && !S_ISREG(sb.st_mode)) {
		log_err("%s: is %s, not a settings file; expected an INI file like "
			"/etc/matcap-kiosk/kiosk.ini",
			path, S_ISDIR(sb.st_mode) ? "a folder" : "not a plain file");
		fclose(f);
		return OPTIONS_CONFIG;
	}
	dir_of(path, dir, sizeof(dir));
	ret = read_stream(o, path, dir[0] ? dir : NULL, f);
	fclose(f);
	return ret;
}

/* The file, then its drop-ins: PATH.d/ *.ini in name order (the systemd and
 * Debian convention: what a package or Ansible role drops in). A key set
 * by a later file overrides an earlier one; within one file it is set once.
 * Every file is read, so all errors are reported at once. */
enum options_status options_read_installed(struct options *o, const char *path)
{
	static const char *const ini[] = {"ini", NULL};
	enum options_status ret = read_path(o, path);
	char dropins[PATH_MAX];
	char **files = NULL;
	int n = 0, err;

	if (snprintf(dropins, sizeof(dropins), "%s.d", path) >= (int)sizeof(dropins))
		return ret;
	err = file_list_folder(dropins, ini, &files, &n);
	if (err && err != -ENOENT && err != -ENOTDIR) {
		log_err("%s: cannot read the folder of drop-in files: %s", dropins, strerror(-err));
		return OPTIONS_CONFIG;
	}
	for (int i = 0; i < n; i++)
		if (read_path(o, files[i]) != OPTIONS_OK)
			ret = OPTIONS_CONFIG;
	file_list_free(files, n);
	return ret;
}

/* The file and its drop-ins, then the one its include names where that
 * exists: a USB stick's settings (--import writes them) go over the
 * installed ones. The included file's own include is not followed. */
enum options_status options_read_file(struct options *o, const char *path)
{
	enum options_status ret = options_read_installed(o, path);
	char *inc;

	if (ret || !o->include || !*o->include || !strcmp(o->include, path))
		return ret;
	if (access(o->include, F_OK)) {
		log_debug("%s: include %s: none there", path, o->include);
		return ret;
	}
	inc = strdup(o->include);
	ret = inc ? read_path(o, inc) : OPTIONS_CONFIG;
	free(o->include);
	o->include = inc;
	if (ret == OPTIONS_CONFIG && inc) {
		/* A stick's settings that do not read (a key a later version
		 * renamed, a broken file) must not keep the kiosk down: the
		 * installed files alone, as if nothing were included. path is
		 * the caller's, never one of o's strings. */
		log_err("%s: ignored, for the error above; the settings of %s alone are used", inc,
			path);
		options_release(o);
		option_defaults(o);
		ret = options_read_installed(o, path);
		free(o->include);
		o->include = NULL;
		o->include_ignored = true;
	}
	return ret;
}

enum options_status options_read_memory(struct options *o, const char *name, const char *text,
					size_t size)
{
	FILE *f;
	enum options_status ret;

	if (size == 0)
		return OPTIONS_OK; /* an empty file sets nothing (fmemopen refuses size 0) */
	f = fmemopen((void *)text, size, "r");
	if (!f) {
		log_err("%s: cannot read the config: %s", name, strerror(errno));
		return OPTIONS_CONFIG;
	}
	ret = read_stream(o, name, NULL, f);
	fclose(f);
	return ret;
}

/* The command line: getopt_long, with its table built from option_defs. */
static void build_getopt(struct option *longs, char *shorts)
{
	char *s = shorts;

	for (size_t i = 0; i < OPTION_DEFS; i++) {
		longs[i] =
		    (struct option){option_defs[i].name,
				    option_defs[i].kind == K_FLAG ? no_argument : required_argument,
				    NULL, (int)(256 + i)};
		if (option_defs[i].short_name) {
			*s++ = option_defs[i].short_name;
			if (option_defs[i].kind != K_FLAG)
				*s++ = ':';
		}
	}
	strcpy(s, "qv");
	longs[OPTION_DEFS] = (struct option){"quiet", no_argument, NULL, 'q'};
	longs[OPTION_DEFS + 1] = (struct option){"verbose", no_argument, NULL, 'v'};
	longs[OPTION_DEFS + 2] = (struct option){NULL, 0, NULL, 0};
}

static const struct option_def *def_for(int c)
{
	if (c >= 256 && c < 256 + (int)OPTION_DEFS)
		return &option_defs[c - 256];
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].short_name && option_defs[i].short_name == c)
			return &option_defs[i];
	return NULL;
}

static enum options_status apply_arg(struct options *o, int c, const char *arg)
{
	const struct option_def *d = def_for(c);
	char what[256];

	if (c == 'q' || c == 'v') {
		o->log_level = c == 'q' ? LOG_WARN : LOG_DEBUG;
		return OPTIONS_OK;
	}
	if (!d)
		return OPTIONS_USAGE; /* getopt has said what was wrong */
	/* A path on the command line stays relative to the current folder. */
	if (option_set_value(o, d, d->kind == K_FLAG ? "true" : arg))
		return options_origin_set(o, d, NULL, 0) ? OPTIONS_USAGE : OPTIONS_OK;
	option_accepted(d, what, sizeof(what));
	log_err("--%s: '%s' is not valid; expected %s", d->name, arg, what);
	return OPTIONS_USAGE;
}

/* --config is read before the other options, which then override it. */
static enum options_status read_config_first(struct options *o, int argc, char **argv)
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
	return OPTIONS_OK;
}

static enum options_status check_command_line(const struct options *o, int argc, char **argv)
{
	struct schedule sch;
	struct background_spec bg;
	char err[200];
	int first, second;

	if (optind < argc) {
		log_err("unexpected argument '%s' (see --help)", argv[optind]);
		return OPTIONS_USAGE;
	}
	if (line_clash(o, &first, &second)) {
		log_err("--button-%s and --button-%s are both line %s; each button needs its own "
			"line",
			gpio_button_names[first], gpio_button_names[second],
			o->buttons.buttons[second].line);
		return OPTIONS_USAGE;
	}
	/* A file's bad schedule stopped its reading: this one is --schedule's. */
	if (o->power.schedule && *o->power.schedule &&
	    schedule_parse(&sch, o->power.schedule, err, sizeof(err))) {
		log_err("--schedule: '%s' is not valid: %s", o->power.schedule, err);
		return OPTIONS_USAGE;
	}
	if (background_parse(o->content.background, &bg, err, sizeof(err))) {
		log_err("--background: '%s' is not valid: %s; expected %s", o->content.background,
			err, BACKGROUND_EXPECTED);
		return OPTIONS_USAGE;
	}
	return OPTIONS_OK;
}

enum options_status options_parse(struct options *o, int argc, char **argv)
{
	struct option longs[OPTION_DEFS + 3];
	char shorts[2 * OPTION_DEFS + 3];
	enum options_status ret;
	int c;

	option_defaults(o);
	build_getopt(longs, shorts);
	ret = read_config_first(o, argc, argv);
	if (ret)
		return ret;
	optind = 1;
	opterr = 1;
	while ((c = getopt_long(argc, argv, shorts, longs, NULL)) != -1)
		if ((ret = apply_arg(o, c, optarg)))
			return ret;
	return check_command_line(o, argc, argv);
}

void options_usage(FILE *out)
{
	fputs("Usage: matcap-kiosk [OPTION]...\n"
	      "Show a glTF model shaded with a matcap, fullscreen on DRM/KMS or offscreen.\n"
	      "Settings marked [section] key can also be set in the config file, and in\n"
	      "FILE.d/*.ini beside it (read in name order after it; a later file's key\n"
	      "overrides). A relative path in a file is taken from that file's folder; on\n"
	      "the command line, from the current folder.\n\n",
	      out);
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		const struct option_def *d = &option_defs[i];
		char left[64], ini[128] = "";

		snprintf(left, sizeof(left), "%c%c%c --%s%s%s", d->short_name ? '-' : ' ',
			 d->short_name ? d->short_name : ' ', d->short_name ? ',' : ' ', d->name,
			 d->arg ? "=" : "", d->arg ? d->arg : "");
		if (d->section != OPTION_CLI)
			snprintf(ini, sizeof(ini), "\n%31s[%s] %s in the config file", "",
				 options_sections[d->section].name, d->key);
		fprintf(out, "  %-28s %s%s\n", left, d->help, ini);
	}
	fputs("  -q, --quiet                  errors and warnings only\n"
	      "  -v, --verbose                debug messages too\n\n"
	      "A reload (SIGHUP: systemctl reload matcap-kiosk) reads the config file again\n"
	      "and applies each section:\n",
	      out);
	for (int i = 0; i < OPTIONS_SECTIONS; i++)
		fprintf(out, "  [%s]%*s %s\n", options_sections[i].name,
			(int)(8 - strlen(options_sections[i].name)), "", options_sections[i].says);
}
