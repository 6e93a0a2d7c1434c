/* Reading the settings files: kiosk.ini, its drop-ins, the include, a
 * model's NAME.ini and a USB stick's files, all through util/ini.c and the
 * table in src/config/settings_table.c. Who wrote a file decides what it may
 * set (struct options_rules): a stick's files, and the include the import
 * wrote from them, take a stick's keys and paths only. */
#include "config/options.h"
#include "state/schedule.h"
#include "config/settings.h"
#include "config/hotspot_settings.h"
#include "config/output_settings.h"
#include "render/background.h"
#include "util/file.h"
#include "util/ini.h"
#include "util/log.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* One file being read: each message names its line, and each key may be
 * set once in it. */
struct file_state {
	struct options *opts;
	const char *path;
	const char *dir; /* relative paths are taken from here; NULL: as written */
	const struct options_rules *rules;
	int line;
	int seen_line[OPTION_DEFS];
	int errors;
	struct hotspot_read hot; /* its [hotspot.NAME] sections */
};

const struct options_rules options_rules_admin = {NULL, NULL, NULL, false};

/* What a stranger's stick may change: what is shown and how it turns,
 * never the display, the devices, the power schedule or the metrics. */
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

/* Two buttons on one line would fight over it: the first such pair (the
 * command line asks too, after the files: options.c). */
bool options_buttons_clash(const struct options *o, int *first, int *second)
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

static bool stick_may_set(const char *section, const char *key)
{
	if (!strcmp(section, "scene") || !strcmp(section, "material"))
		return true;
	return !strcmp(section, "kiosk") &&
	       (!strncmp(key, "attract_", 8) || !strncmp(key, "turn_", 5) ||
		!strcmp(key, "idle_seconds"));
}

const struct options_rules options_rules_stick = {
    stick_may_set, "[scene], [material] and [kiosk] attract_*, turn_* and idle_seconds",
    "a USB stick", true};

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

/* Why a stick's value that names files is refused, or NULL: each of its
 * (a list's) paths must be relative, without a ".." part, or lie inside
 * dir (the include the import wrote before it wrote relative paths). A
 * stick is a stranger's: its settings may show its own files only. */
static const char *stick_path_refused(const char *value, const char *dir, bool list)
{
	static const char *const why = "a USB stick's paths must be relative, inside its "
				       "folder, without '..'";
	size_t dir_len = dir ? strlen(dir) : 0;

	for (const char *p = value; *p;) {
		size_t n = list ? strcspn(p, ",") : strlen(p);
		const char *t = p + strspn(p, " \t");

		if (*t == '/' && !(dir && !strncmp(t, dir, dir_len) && t[dir_len] == '/'))
			return why;
		for (const char *c = t; c < p + n; c++)
			if ((c == t || c[-1] == '/') && c[0] == '.' && c[1] == '.' &&
			    (c + 2 == p + n || strchr("/ \t", c[2])))
				return why;
		p += n + (p[n] == ',');
	}
	return NULL;
}

/* A ';' after a blank started a comment when libinih read the settings;
 * now it is part of the value. Said, so that an old file's comment does
 * not turn up on the screen unexplained. */
static void old_comment(const struct file_state *st, const struct option_def *d, const char *value)
{
	const char *c = strstr(value, " ;");

	if (!c)
		c = strstr(value, "\t;");
	/* The include (and the import's staged copy of it) was a stick's
	 * file, and the import said so when it read that. */
	if (!d || !c || (st->rules == &options_rules_stick && st->dir))
		return;
	log_warn("%s:%d: [%s] %s: ' ;' is part of the value now ('%s'); a comment needs a line "
		 "of its own, starting with # or ;",
		 st->path, st->line, options_sections[d->section].name, d->key, value);
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

static int on_key(void *user, int line, const char *section, const char *key, const char *value)
{
	struct file_state *st = user;
	const struct option_def *d = find_key(section, key);
	char what[256], *resolved = NULL, base[64], lang[LANG_CODE_MAX];
	const char *why = NULL;
	bool translated = lang_key_split(key, base, sizeof(base), lang, sizeof(lang));

	st->line = line;
	st->errors++;
	if (st->rules->allowed && !st->rules->allowed(section, translated ? base : key)) {
		log_err("%s:%d: [%s] %s cannot be set from %s; it takes %s", st->path, st->line,
			section, key, st->rules->who, st->rules->allowed_text);
		return 0;
	}
	if (hotspot_settings_section(section)) { /* a bad one is dropped alone */
		st->errors--;
		hotspot_settings_key(&st->hot, st->path, line, section, key, value);
		return 0;
	}
	if (output_settings_section(section)) {
		st->errors -=
		    output_settings_key(&st->opts->outputs, st->path, line, section, key, value);
		return 0;
	}
	if (translated) {
		st->errors -=
		    !lang_text_read(&st->opts->content.texts, st->path, line, section, key, value);
		return 0;
	}
	if (d && st->rules->stick_paths && names_files(d, value) &&
	    (why = stick_path_refused(value, st->dir, !strcmp(key, "model")))) {
		log_err("%s:%d: [%s] %s = '%s': %s", st->path, st->line, section, key, value, why);
		seen(st, d);
		return 0;
	}
	old_comment(st, d, value);
	if (d && quoted(value)) {
		log_err("%s:%d: [%s] %s = %s: the quotes would be part of the value; write it "
			"without them (blanks inside a path are fine)",
			st->path, st->line, section, key, value);
		seen(st, d);
		return 0;
	}
	if (d && names_files(d, value) &&
	    !(resolved = resolve_paths(value, st->dir, !strcmp(key, "model"), &why))) {
		log_err("%s:%d: [%s] %s = '%s': %s", st->path, st->line, section, key, value, why);
		seen(st, d);
		return 0;
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
	return 0; /* go on, so every error in the file is reported at once */
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

	if (!options_buttons_clash(st->opts, &i, &j))
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

/* [display] outputs: names a connector may have, at most as many as the
 * kiosk drives (whether they exist is the display's to say, at start). */
static void check_outputs(struct file_state *st)
{
	const char *text = st->opts->display.outputs;
	int at = st->seen_line[find_key("display", "outputs") - option_defs];
	char err[160];

	if (!at || !strcmp(text, "all") ||
	    display_outputs_parse(text, NULL, KMS_OUTPUTS_MAX, err, sizeof(err)) > 0)
		return;
	st->errors++;
	log_err("%s:%d: [display] outputs = '%s': %s; expected connectors' names such as "
		"'HDMI-A-1, HDMI-A-2', or all",
		st->path, at, text, err);
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
	lang_list_check(c->languages, st->path,
			st->seen_line[find_key("caption", "languages") - option_defs], &st->errors);
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

static void on_bad(void *user, int line, const char *why)
{
	const struct file_state *st = user;

	log_err("%s:%d: %s", st->path, line, why);
}

enum options_status options_read_text(struct options *o, const char *path, const char *dir,
				      const char *text, size_t size,
				      const struct options_rules *rules)
{
	static const struct ini_handler handler = {on_key, on_bad};
	struct file_state st = {.opts = o, .path = path, .dir = dir, .rules = rules};
	int ret;

	if (!options_origin_file(o, path))
		return OPTIONS_CONFIG;
	ret = ini_parse(text, size, &handler, &st);
	if (ret == -ENOMEM)
		log_err("%s: cannot read the settings: %s", path, strerror(ENOMEM));
	check_lines(&st);
	check_schedule(&st);
	check_background(&st);
	check_outputs(&st);
	check_frame(&st);
	check_caption(&st);
	o->content.hotspots.dropped += hotspot_settings_finish(&st.hot, path, &o->content.hotspots);
	return ret || st.errors ? OPTIONS_CONFIG : OPTIONS_OK;
}

/* A settings file is a few KiB: a bound keeps a stranger's 1 GB file out
 * of memory. Documented in kiosk.ini(5) and the README. */
#define SETTINGS_MAX (1u << 20)

/* As sshd's StrictModes: a settings file anyone may write, or one in a
 * folder where anyone may replace it (not sticky, as /tmp is), is
 * anyone's settings. what: "file" or "folder of drop-in files". */
static bool refuse_writable(const char *path, bool folder)
{
	char dir[PATH_MAX];
	struct stat sb;

	if (stat(path, &sb))
		return false; /* the read says why */
	if (sb.st_mode & S_IWOTH) {
		log_err("%s: refused: anyone may write this %s (mode %03o); chmod o-w %s", path,
			folder ? "folder of settings files" : "settings file",
			(unsigned)(sb.st_mode & 0777), path);
		return true;
	}
	if (folder)
		return false;
	dir_of(path, dir, sizeof(dir));
	if (!stat(dir[0] ? dir : ".", &sb) && (sb.st_mode & S_IWOTH) && !(sb.st_mode & S_ISVTX)) {
		log_err("%s: refused: anyone may replace it, its folder %s is writable by all "
			"(mode %03o); chmod o-w %s",
			path, dir[0] ? dir : ".", (unsigned)(sb.st_mode & 0777),
			dir[0] ? dir : ".");
		return true;
	}
	return false;
}

static void say_unread(const char *path, int err)
{
	if (err == -EISDIR)
		log_err("%s: is a folder, not a settings file; expected an INI file like "
			"/etc/matcap-kiosk/kiosk.ini",
			path);
	else if (file_refusal(err))
		log_err("%s: %s; a settings file is a plain file", path, file_refusal(err));
	else if (err == -EFBIG)
		log_err("%s: over %u KiB; a settings file is a few KiB of text", path,
			SETTINGS_MAX >> 10);
	else
		log_err("%s: cannot open config file: %s", path, strerror(-err));
}

static enum options_status read_path(struct options *o, const char *path,
				     const struct options_rules *rules)
{
	enum options_status ret = OPTIONS_CONFIG;
	unsigned char *text = NULL;
	char dir[PATH_MAX];
	size_t size = 0;
	int err;

	if (refuse_writable(path, false))
		return OPTIONS_CONFIG;
	err = file_read_all(path, SETTINGS_MAX, &text, &size);
	if (err) {
		say_unread(path, err);
		goto out;
	}
	dir_of(path, dir, sizeof(dir));
	ret = options_read_text(o, path, dir[0] ? dir : NULL, (const char *)text, size, rules);
out:
	free(text);
	return ret;
}

/* The file, then its drop-ins: PATH.d/ *.ini in name order (the systemd and
 * Debian convention: what a package or Ansible role drops in). A key set
 * by a later file overrides an earlier one; within one file it is set once.
 * Every file is read, so all errors are reported at once. */
enum options_status options_read_installed(struct options *o, const char *path)
{
	static const char *const ini[] = {"ini", NULL};
	enum options_status ret = read_path(o, path, &options_rules_admin);
	char dropins[PATH_MAX];
	char **files = NULL;
	int n = 0, err;

	if (snprintf(dropins, sizeof(dropins), "%s.d", path) >= (int)sizeof(dropins))
		return ret;
	if (refuse_writable(dropins, true))
		return OPTIONS_CONFIG;
	err = file_list_folder(dropins, ini, &files, &n);
	if (err && err != -ENOENT && err != -ENOTDIR) {
		log_err("%s: cannot read the folder of drop-in files: %s", dropins, strerror(-err));
		return OPTIONS_CONFIG;
	}
	for (int i = 0; i < n; i++)
		if (read_path(o, files[i], &options_rules_admin) != OPTIONS_OK)
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
	/* The include is a stick's settings (the import wrote it): read with
	 * a stick's rules, whoever put it there. */
	ret = inc ? read_path(o, inc, &options_rules_stick) : OPTIONS_CONFIG;
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
	return options_read_text(o, name, NULL, text, size, &options_rules_admin);
}

enum options_status options_read_one(struct options *o, const char *path,
				     const struct options_rules *rules)
{
	return read_path(o, path, rules);
}
