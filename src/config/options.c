/* Reading the settings from the command line (getopt_long), through the
 * table in src/config/settings_table.c, and --help from it. The files are
 * options_file.c's. */
#include "config/options.h"
#include "state/schedule.h"
#include "config/settings.h"
#include "config/wall_settings.h"
#include "render/background.h"
#include "util/log.h"

#include <getopt.h>
#include <stdlib.h>
#include <string.h>

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

/* --as-output NAME: a still drawn as an output of [display] outputs (or
 * of an [output.NAME] section) shows it; a name of neither is a typo that
 * would draw the plain view in silence. */
static enum options_status check_as_output(const struct options *o)
{
	char names[KMS_OUTPUTS_MAX][32], err[160];
	const char *list = o->display.outputs;
	int n = list ? display_outputs_parse(list, names, KMS_OUTPUTS_MAX, err, sizeof(err)) : 0;

	if (!o->as_output)
		return OPTIONS_OK;
	if (!o->output) {
		log_err("--as-output %s: draws a still, so it needs --output FILE", o->as_output);
		return OPTIONS_USAGE;
	}
	for (int i = 0; i < n; i++)
		if (!strcmp(names[i], o->as_output))
			return OPTIONS_OK;
	if (output_view_find(&o->outputs, o->as_output) || (list && !strcmp(list, "all")))
		return OPTIONS_OK;
	log_err("--as-output %s: no such output; [display] outputs names %s, and there is no "
		"[output.%s] section",
		o->as_output, list ? list : "none", o->as_output);
	return OPTIONS_USAGE;
}

static enum options_status check_command_line(const struct options *o, int argc, char **argv)
{
	struct schedule sch;
	struct background_spec bg;
	struct app_frame frame;
	char err[200];
	int first, second;

	if (optind < argc) {
		log_err("unexpected argument '%s' (see --help)", argv[optind]);
		return OPTIONS_USAGE;
	}
	if (options_buttons_clash(o, &first, &second)) {
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
	/* A file's [frame] that does not hold together stopped its reading:
	 * this is the command line's (nine --stops were dropped in silence,
	 * and the whole [frame] with them). */
	if (frame_to_app(&o->content.frame, 0, 0, &frame, err, sizeof(err))) {
		log_err("--stops, --yaw-min ... ([frame]): not valid: %s", err);
		return OPTIONS_USAGE;
	}
	if (background_parse(o->content.background, &bg, err, sizeof(err))) {
		log_err("--background: '%s' is not valid: %s; expected %s", o->content.background,
			err, BACKGROUND_EXPECTED);
		return OPTIONS_USAGE;
	}
	return check_as_output(o);
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
	/* Said, and shown without the wall: not a reason to stay dark. */
	o->wall_refused = wall_settings_check(o);
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
