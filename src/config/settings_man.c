/* kiosk.ini(5) from the settings table, and the roff both pages share.
 * Each key's type, range and default come from the row and from
 * option_defaults; who may set it from the same rules the readers apply
 * (options_rules_stick, model_settings_allowed); the reload rule of each
 * section from options_sections. */
#include "config/settings_man.h"
#include "config/exit_codes.h"
#include "config/model_settings.h"
#include "config/options.h"
#include "config/settings.h"

#include <math.h>
#include <string.h>

void man_inline(FILE *out, const char *s)
{
	char prev = ' ';

	for (; *s; prev = *s++) {
		if (*s == '\\')
			fputs("\\e", out);
		/* A dash that starts a word is an option's or a minus sign:
		 * roff's \- keeps it a hyphen-minus to copy; Mon-Fri stays. */
		else if (*s == '-' && strchr(" (-'\"[,=", prev))
			fputs("\\-", out);
		else
			fputc(*s, out);
	}
}

void man_text(FILE *out, const char *s)
{
	if (*s == '.' || *s == '\'')
		fputs("\\&", out);
	man_inline(out, s);
	fputc('\n', out);
}

void man_sentence(FILE *out, const char *s)
{
	size_t n = strlen(s);

	if (*s == '.' || *s == '\'')
		fputs("\\&", out);
	man_inline(out, s);
	fputs(n && s[n - 1] == '.' ? "\n" : ".\n", out);
}

void man_option(FILE *out, const struct option_def *d)
{
	if (d->short_name)
		fprintf(out, "\\fB\\-%c\\fR, ", d->short_name);
	fputs("\\fB\\-\\-", out);
	man_inline(out, d->name);
	fputs("\\fR", out);
	if (d->arg) {
		fputs("=\\fI", out);
		man_inline(out, d->arg);
		fputs("\\fR", out);
	}
}

#define EXIT_CODE_DOC(name, number, means, words) {number, means},
static const struct {
	int code;
	const char *means;
} exit_docs[] = {EXIT_CODE_ROWS(EXIT_CODE_DOC)};
#undef EXIT_CODE_DOC
#define EXIT_DOCS (sizeof(exit_docs) / sizeof(exit_docs[0]))

void man_exit_status(FILE *out)
{
	for (size_t i = 0; i < EXIT_DOCS; i++) {
		fprintf(out, ".TP\n.B %d\n", exit_docs[i].code);
		man_sentence(out, exit_docs[i].means);
	}
}

void settings_man_exit_table(FILE *out)
{
#define EXIT_CODE_LINE(name, number, means, words)                                                 \
	fprintf(out, "%d\t%s\t%s\n", number, #name, words);
	EXIT_CODE_ROWS(EXIT_CODE_LINE)
#undef EXIT_CODE_LINE
}

void settings_man_keys(FILE *out)
{
	for (size_t i = 0; i < OPTION_DEFS; i++)
		if (option_defs[i].section != OPTION_CLI)
			fprintf(out, "%s %s\n", options_sections[option_defs[i].section].name,
				option_defs[i].key);
}

static const char *type_word(const struct option_def *d)
{
	static const char *const words[] = {
	    [K_FLAG] = "boolean (true, yes, on, 1; false, no, off, 0)",
	    [K_STRING] = "text",
	    [K_INT] = "whole number",
	    [K_DOUBLE] = "number",
	    [K_DEGREES] = "number, in degrees",
	    [K_SIZE] = "size",
	    [K_PAIR] = "two whole numbers",
	    [K_CHOICE] = "one word of a list",
	    [K_LEVEL] = "one word of a list",
	};
	return words[d->kind];
}

/* The default, as the file would write it; "" when there is none (the
 * help then says what stands in). */
static void default_text(const struct options *o, const struct option_def *d, char *buf, size_t n)
{
	const char *p = (const char *)o + d->offset;
	double x;
	int i;

	buf[0] = '\0';
	switch (d->kind) {
	case K_FLAG:
		snprintf(buf, n, "%s", *(const bool *)p ? "true" : "false");
		break;
	case K_STRING:
		memcpy(&p, p, sizeof(p));
		snprintf(buf, n, "%s", p ? p : "");
		break;
	case K_INT:
		if (d->choices && *(const int *)p == 0)
			snprintf(buf, n, "%s", d->choices[0]);
		else
			snprintf(buf, n, "%d", *(const int *)p);
		break;
	case K_SIZE:
	case K_PAIR:
		snprintf(buf, n, d->kind == K_SIZE ? "%dx%d" : "%d,%d", ((const int *)p)[0],
			 ((const int *)p)[1]);
		break;
	case K_LEVEL:
		for (i = 0; i < LOG_LEVELS && log_levels[i] != *(const enum log_level *)p; i++)
			;
		snprintf(buf, n, "%s", i < LOG_LEVELS ? d->choices[i] : "");
		break;
	case K_CHOICE:
		i = d->size == sizeof(bool) ? *(const bool *)p : *(const int *)p;
		snprintf(buf, n, "%s", d->choices[i]);
		break;
	default:
		x = *(const double *)p;
		if (d->kind == K_DEGREES)
			x = x * 180 / M_PI;
		if (d->choices && x == 0)
			snprintf(buf, n, "%s", d->choices[0]);
		else if (isfinite(x) && x >= d->lo && x <= d->hi)
			snprintf(buf, n, "%g", x);
	}
}

/* Type, accepted values and default: one line. */
void man_value_line(FILE *out, const struct options *defaults, const struct option_def *d)
{
	char what[400], def[256];

	option_accepted(d, what, sizeof(what));
	default_text(defaults, d, def, sizeof(def));
	fputs("Type: ", out);
	man_inline(out, type_word(d));
	if (d->kind != K_STRING && d->kind != K_FLAG) {
		fputs("; accepts: ", out);
		man_inline(out, what);
	}
	fputs(". Default: ", out);
	man_inline(out, *def ? def : "not set");
	fputs(".\n", out);
}

static void who_may_set(FILE *out, const struct option_def *d)
{
	const char *section = options_sections[d->section].name;

	fprintf(
	    out,
	    "Who may set it: kiosk.ini, kiosk.ini.d: yes; a model's NAME.ini: %s; a USB stick: %s; "
	    "the command line: ",
	    model_settings_allowed(section, d->key) ? "yes" : "no",
	    options_rules_stick.allowed(section, d->key) ? "yes" : "no");
	man_option(out, d);
	fputs(".\n", out);
}

static void page5_key(FILE *out, const struct options *defaults, const struct option_def *d)
{
	fputs(".TP\n\\fB", out);
	man_inline(out, d->key);
	fputs("\\fR = \\fI", out);
	man_inline(out, d->arg ? d->arg : "BOOLEAN");
	fputs("\\fR\n", out);
	man_sentence(out, d->help);
	fputs(".br\n", out);
	man_value_line(out, defaults, d);
	fputs(".br\n", out);
	who_may_set(out, d);
}

static void page5_sections(FILE *out)
{
	struct options defaults;

	option_defaults(&defaults);
	for (int s = 0; s < OPTIONS_SECTIONS; s++) {
		fprintf(out, ".SS [%s]\n", options_sections[s].name);
		fputs("On reload: ", out);
		man_inline(out, options_sections[s].says);
		fputs(".\n", out);
		for (size_t i = 0; i < OPTION_DEFS; i++)
			if ((int)option_defs[i].section == s)
				page5_key(out, &defaults, &option_defs[i]);
	}
	options_release(&defaults);
}

static void page5_head(FILE *out, const struct settings_man_info *info)
{
	fprintf(out,
		".\\\" Written by tests/tools/mkman from src/config/settings_table.c: edit\n"
		".\\\" the table (or src/config/settings_man.c), not this page.\n"
		".TH KIOSK.INI 5 %s \"matcap-kiosk %s\" \"File Formats\"\n"
		".SH NAME\nkiosk.ini \\- the settings of matcap-kiosk\n"
		".SH SYNOPSIS\n.I %s/matcap-kiosk/kiosk.ini\n.br\n"
		".I %s/matcap-kiosk/kiosk.ini.d/*.ini\n.br\n"
		".IR MODEL .ini\nbeside\n.IR MODEL .glb\n.br\n"
		".I matcap-kiosk/kiosk.ini\non a USB stick\n",
		info->date, info->version, info->sysconfdir, info->sysconfdir);
}

/* Written once here: the reading rules config/kiosk.ini's head states. */
static const char *const file_rules[] = {
    "A file is a list of [section] lines, each followed by key = value lines. Lines that start "
    "with ; or # are comments; a comment needs a line of its own: a ; or # inside a value is "
    "part of it. A key may appear once in a file; an unknown key or a bad value stops the "
    "kiosk with a message naming the file and the line (exit status 78). A file is at most "
    "1 MiB; a settings file, or its folder, that anyone may write is refused.",
    "A relative path is taken from the folder of the file it is written in, not from the "
    "current folder (the service's is /). Write a value without quotes (they would be part "
    "of it) and without ~ (the service has no home folder): both are refused.",
    "The files are read in this order, a later one overriding a key an earlier one set: "
    "kiosk.ini; every *.ini file of kiosk.ini.d/ beside it, in name order (what a package or "
    "an Ansible role drops in); the file named by [kiosk] include (a USB stick's settings, "
    "as --import installed them), read with a USB stick's rules. The command line overrides "
    "them all. While a model is shown, its own NAME.ini beside NAME.glb (or NAME.gltf) is "
    "read over them.",
    NULL,
};

void settings_man_page5(FILE *out, const struct settings_man_info *info)
{
	page5_head(out, info);
	fputs(".SH DESCRIPTION\nThe settings of\n.BR matcap\\-kiosk (1),\n"
	      "read at its start and again on a reload (SIGHUP:\n"
	      ".BR \"systemctl reload matcap\\-kiosk\" ).\n",
	      out);
	for (const char *const *r = file_rules; *r; r++) {
		fputs(".PP\n", out);
		man_text(out, *r);
	}
	fputs(".SS Who may set what\nEach key below says who may set it.\n.TP\n"
	      ".BR kiosk.ini \", \" kiosk.ini.d/*.ini\nany key, any path.\n.TP\n"
	      ".IR NAME .ini\nbeside a model: the keys that make sense per model, marked so "
	      "below; what stays with the kiosk (the display, the devices, attract mode's "
	      "timing) is refused.\n.TP\na USB stick\n(its kiosk.ini, and the include "
	      "\\-\\-import writes from it):\n",
	      out);
	man_text(out, options_rules_stick.allowed_text);
	fputs("; every path relative, inside the stick's folder, without \"..\".\n", out);
	fputs(".SH SECTIONS AND KEYS\n", out);
	page5_sections(out);
	fprintf(out,
		".SH FILES\n.TP\n.I %s/matcap-kiosk/kiosk.ini\nthe service's settings.\n"
		".TP\n.I %s/kiosk.ini.example\nthe documented example, every key in place.\n"
		".SH SEE ALSO\n.BR matcap\\-kiosk (1),\n.BR systemctl (1)\n",
		info->sysconfdir, info->datadir);
}
