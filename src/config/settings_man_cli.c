/* matcap-kiosk(1) from the settings table: every option, the command
 * line's own first, then each section's (with its kiosk.ini key and
 * default); the exit statuses from config/exit_codes.h. */
#include "config/settings_man.h"
#include "config/settings.h"

#include <string.h>

/* What the page says of an option beyond its --help line. */
static const struct {
	const char *name, *more;
} notes[] = {
    {"config", "Then every FILE.d/*.ini beside it is read, in name order, and the file its "
	       "[kiosk] include names (kiosk.ini(5))."},
    {"model", "A model's own settings may sit beside it, in NAME.ini (kiosk.ini(5))."},
    {"output", "With --frames=N, N frames are drawn first."},
    {"import", "The USB stick's udev rule runs this, then reloads the kiosk "
	       "(matcap-kiosk-import@.service)."},
    {"help", "Prints the options, with their [section] keys, and exits."},
    {"version", "Prints it and exits."},
};

static void page1_note(FILE *out, const char *name)
{
	for (size_t i = 0; i < sizeof(notes) / sizeof(notes[0]); i++)
		if (!strcmp(notes[i].name, name)) {
			fputs(".br\n", out);
			man_text(out, notes[i].more);
		}
}

static void page1_option(FILE *out, const struct options *defaults, const struct option_def *d)
{
	fputs(".TP\n", out);
	man_option(out, d);
	fputc('\n', out);
	man_sentence(out, d->help);
	page1_note(out, d->name);
	if (d->section == OPTION_CLI)
		return;
	fputs(".br\n", out);
	fprintf(out, "In the config file: [%s] ", options_sections[d->section].name);
	man_inline(out, d->key);
	fputs(". ", out);
	man_value_line(out, defaults, d);
}

static void page1_options(FILE *out)
{
	struct options defaults;

	option_defaults(&defaults);
	fputs(".SH OPTIONS\n"
	      "Every setting of the config file has a command-line option; an option given on "
	      "the command line wins over the file. A relative path on the command line is taken "
	      "from the current folder.\n"
	      ".BR kiosk.ini (5)\nsays who else may set each one.\n"
	      ".SS The command line's own\n",
	      out);
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].section == OPTION_CLI)
			page1_option(out, &defaults, &option_defs[i]);
	fputs(".TP\n\\fB\\-q\\fR, \\fB\\-\\-quiet\\fR\nerrors and warnings only.\n"
	      ".TP\n\\fB\\-v\\fR, \\fB\\-\\-verbose\\fR\ndebug messages too.\n",
	      out);
	for (int s = 0; s < OPTIONS_SECTIONS; s++) {
		fprintf(out, ".SS [%s]\n", options_sections[s].name);
		for (size_t i = 0; i < OPTION_DEFS; i++)
			if ((int)option_defs[i].section == s)
				page1_option(out, &defaults, &option_defs[i]);
	}
	options_release(&defaults);
}

static void page1_head(FILE *out, const struct settings_man_info *info)
{
	fprintf(out,
		".\\\" Written by tests/tools/mkman from src/config/settings_table.c and\n"
		".\\\" src/config/exit_codes.h: edit those (or src/config/settings_man_cli.c),\n"
		".\\\" not this page.\n"
		".TH MATCAP\\-KIOSK 1 %s \"matcap-kiosk %s\" \"User Commands\"\n"
		".SH NAME\nmatcap\\-kiosk \\- show a 3D model shaded with a matcap, fullscreen, "
		"for months\n",
		info->date, info->version);
	fputs(".SH SYNOPSIS\n.B matcap\\-kiosk\n.RI [ OPTION ]...\n.br\n"
	      ".B matcap\\-kiosk \\-\\-check\\-config\n.RB [ \\-C\n.IR FILE ]\n.br\n"
	      ".B matcap\\-kiosk \\-\\-output\n.I FILE.png\n.RI [ OPTION ]...\n.br\n"
	      ".B matcap\\-kiosk \\-\\-status\n.br\n.B matcap\\-kiosk \\-\\-import\n.I DIR\n",
	      out);
	fputs(
	    ".SH DESCRIPTION\n.B matcap\\-kiosk\n"
	    "draws a glTF 2.0 model (.glb or .gltf) shaded with a matcap image, fullscreen on the "
	    "Linux display (DRM/KMS, no desktop needed) or offscreen into a PNG. GPIO buttons, a "
	    "keyboard and a touchscreen turn the model and step through matcaps and models; with "
	    "no input for a while it turns by itself. It is meant to run as the systemd service\n"
	    ".B matcap\\-kiosk.service\non a small board such as a Raspberry Pi.\n.PP\n"
	    "With no display (no DRM output, or\n.BR \\-\\-output ),\n"
	    "it draws offscreen and writes the last frame as a PNG.\n",
	    out);
}

static void page1_signals(FILE *out)
{
	fputs(".SH SIGNALS\n.TP\n\\fBSIGHUP\\fR (\\fBsystemctl reload matcap\\-kiosk\\fR)\n"
	      "read the config file again and load the new content while the old picture stays "
	      "on screen; a reload that fails keeps what is shown. Each section is applied:\n"
	      ".RS\n",
	      out);
	for (int s = 0; s < OPTIONS_SECTIONS; s++) {
		fprintf(out, ".TP\n.B [%s]\n", options_sections[s].name);
		man_sentence(out, options_sections[s].says);
	}
	fputs(".RE\n.TP\n.BR SIGTERM \", \" SIGINT\nend cleanly and give the display back.\n", out);
}

static void page1_tail(FILE *out, const struct settings_man_info *info)
{
	const char *etc = info->sysconfdir, *data = info->datadir;

	fputs(".SH ENVIRONMENT\nThe service's unit sets the first four.\n"
	      ".TP\n.B STATE_DIRECTORY\nwhere imported content is kept (content/ in it) and what "
	      "a crash was loading (default /var/lib/matcap\\-kiosk).\n"
	      ".TP\n.B RUNTIME_DIRECTORY\nthe socket \\-\\-status asks (default "
	      "/run/matcap\\-kiosk).\n"
	      ".TP\n.B CACHE_DIRECTORY\nthe prepared-mesh cache; else "
	      "$XDG_CACHE_HOME/matcap\\-kiosk, else $HOME/.cache/matcap\\-kiosk.\n"
	      ".TP\n.B MESA_SHADER_CACHE_DIR\nMesa's shader cache: turned off when its file system "
	      "has under 16 MiB free.\n"
	      ".TP\n.B JOURNAL_STREAM\nset by systemd when standard error is the journal: each "
	      "line then carries its syslog priority.\n"
	      ".TP\n.BR NOTIFY_SOCKET \", \" WATCHDOG_USEC\nsystemd's readiness and watchdog "
	      "(Type=notify).\n",
	      out);
	fprintf(out,
		".SH FILES\n.TP\n.I %s/matcap-kiosk/kiosk.ini\n"
		"the service's settings, every key documented in place\n.RB ( kiosk.ini (5)).\n"
		".TP\n.I %s/matcap-kiosk/kiosk.ini.d/*.ini\n"
		"settings in pieces (packages, Ansible), read after kiosk.ini.\n"
		".TP\n.I /srv/matcap-kiosk/\nthe content folder: models, matcaps, posters.\n"
		".TP\n.I /var/lib/matcap-kiosk/content/\ncontent imported from USB sticks.\n"
		".TP\n.I %s/matcaps/\nthe shipped matcaps.\n"
		".TP\n.I %s/kiosk.ini.example\nthe documented example settings.\n",
		etc, etc, data, data);
	fprintf(out,
		".SH EXAMPLES\nCheck the settings, then start the service and keep it across "
		"reboots:\n.PP\n.nf\n.RS\n"
		"matcap\\-kiosk \\-\\-check\\-config \\-C %s/matcap\\-kiosk/kiosk.ini\n"
		"sudo systemctl enable \\-\\-now matcap\\-kiosk\n.RE\n.fi\n.PP\n"
		"A picture of a model without a display:\n.PP\n.nf\n.RS\n"
		"matcap\\-kiosk \\-m product.glb \\-\\-output product.png\n.RE\n.fi\n",
		etc);
	fputs(".SH SEE ALSO\n.BR kiosk.ini (5),\n.BR systemctl (1),\n.BR journalctl (1),\n"
	      ".BR systemd.service (5)\n",
	      out);
}

void settings_man_page1(FILE *out, const struct settings_man_info *info)
{
	page1_head(out, info);
	page1_options(out);
	page1_signals(out);
	fputs(".SH EXIT STATUS\n", out);
	man_exit_status(out);
	page1_tail(out, info);
}
