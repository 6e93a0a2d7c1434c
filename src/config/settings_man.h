/* The manual pages, written from the settings table (settings.h), the
 * rules of who may set what (options.h, model_settings.h) and the exit
 * statuses (exit_codes.h) at build time, so that they cannot drift from
 * the program: matcap-kiosk(1) and kiosk.ini(5). Not part of the kiosk:
 * the build's tool tests/tools/mkman.c calls these. */
#ifndef MK_SETTINGS_MAN_H
#define MK_SETTINGS_MAN_H

#include <stdio.h>

/* What a page says that the build decides. */
struct settings_man_info {
	const char *version;		  /* "0.1.0" */
	const char *date;		  /* YYYY-MM-DD, the source's date (reproducible) */
	const char *sysconfdir, *datadir; /* /etc, /usr/share/matcap-kiosk */
};

/* matcap-kiosk(1): every option, the exit statuses, files, environment. */
void settings_man_page1(FILE *out, const struct settings_man_info *info);
/* kiosk.ini(5): every key with its type, default, range and who may set it. */
void settings_man_page5(FILE *out, const struct settings_man_info *info);
/* One line per exit status, "CODE<TAB>NAME<TAB>WORDS" (exit_codes.h), for
 * tests/e2e/exit_claims.sh. */
void settings_man_exit_table(FILE *out);
/* One line per config key, "SECTION KEY", for tests/e2e/config_doc.sh. */
void settings_man_keys(FILE *out);

/* Shared by the two pages (settings_man.c). */
/* s as roff text on a line of its own: backslashes and option dashes
 * escaped, a leading '.' or '\'' made literal. */
void man_text(FILE *out, const char *s);
/* The same, ended with a full stop where it has none. */
void man_sentence(FILE *out, const char *s);
/* s inside a text line (no line start handling). */
void man_inline(FILE *out, const char *s);
/* "\-\-name=ARG" or "\-x, \-\-name=ARG", bold name, italic ARG. */
struct option_def;
void man_option(FILE *out, const struct option_def *d);
/* A key's type, accepted values and default, one line. */
struct options;
void man_value_line(FILE *out, const struct options *defaults, const struct option_def *d);
/* The exit statuses, as .TP paragraphs. */
void man_exit_status(FILE *out);

#endif
