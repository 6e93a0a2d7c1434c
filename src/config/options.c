/* Reading the settings: the config file (inih) and the command line
 * (getopt_long), both through the table in src/config/settings.c, and
 * --help from it. */
#include "config/options.h"
#include "state/schedule.h"
#include "config/settings.h"
#include "util/log.h"

#include <errno.h>
#include <getopt.h>
#include <ini.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The file: inih parses, a line reader of ours counts lines so that
 * every message names one, and each key may be set once. */
struct file_state {
	struct options *opts;
	const char *path;
	FILE *f;
	int line;
	int seen_line[OPTION_DEFS];
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

static int on_key(void *user, const char *section, const char *key, const char *value)
{
	struct file_state *st = user;
	const struct option_def *d = find_key(section, key);
	char what[256];

	st->errors++;
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
		} else {
			option_accepted(d, what, sizeof(what));
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

static enum options_status read_stream(struct options *o, const char *path, FILE *f)
{
	struct file_state st = {.opts = o, .path = path, .f = f};
	int ret = ini_parse_stream(read_line, &st, on_key, &st);

	check_lines(&st);
	check_schedule(&st);
	if (ret > 0)
		log_err("%s:%d: not an INI line; expected [section], key = value or a comment",
			path, ret);
	return ret || st.errors ? OPTIONS_CONFIG : OPTIONS_OK;
}

static enum options_status read_path(struct options *o, const char *path)
{
	FILE *f = fopen(path, "r");
	enum options_status ret;

	if (!f) {
		log_err("%s: cannot open config file: %s", path, strerror(errno));
		return OPTIONS_CONFIG;
	}
	ret = read_stream(o, path, f);
	fclose(f);
	return ret;
}

/* The file, then the one its include names where that exists: a USB
 * stick's settings (--import writes them) go over the installed ones. The
 * included file's own include is not followed. */
enum options_status options_read_file(struct options *o, const char *path)
{
	enum options_status ret = read_path(o, path);
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
		 * installed file alone, as if nothing were included. path is
		 * the caller's, never one of o's strings. */
		log_err("%s: ignored, for the error above; the settings of %s alone are used", inc,
			path);
		options_release(o);
		option_defaults(o);
		ret = read_path(o, path);
		free(o->include);
		o->include = NULL;
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
	ret = read_stream(o, name, f);
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
	if (option_set_value(o, d, d->kind == K_FLAG ? "true" : arg))
		return OPTIONS_OK;
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
	char err[160];
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
	      "Settings marked [section] key can also be set in the config file.\n\n",
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
