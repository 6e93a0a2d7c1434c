/* Every text in each language (config/lang_text.h): KEY[LANG] = read
 * from a settings file and a model's NAME.ini, the text of a language
 * that lacks one falling back to the first language's, then to the plain
 * KEY's; the stops' texts by their place; what is refused, with the file
 * and line (a key a visitor never reads, a word that is no language). */
#include "config/lang_text.h"
#include "config/model_settings.h"
#include "config/options.h"
#include "config/settings.h"
#include "util/log.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static enum options_status read_text(struct options *o, const char *text)
{
	option_defaults(o);
	return options_read_memory(o, "test.ini", text, strlen(text));
}

static const char *caption_in(const struct options *o, const char *lang)
{
	char codes[LANG_MAX][LANG_CODE_MAX], err[128];
	int n = lang_list_parse(o->content.caption.languages, codes, err, sizeof(err));
	const char *t =
	    lang_text_get(&o->content.texts, "caption", "text", lang, n > 0 ? codes[0] : NULL);

	return t ? t : o->content.caption.text;
}

static void fallback_language(void **state)
{
	struct options o;

	(void)state;
	assert_int_equal(read_text(&o, "[caption]\nlanguages = en de fr ja\n"
				       "text = Vase\ntext[de] = Vase (Leihgabe)\n"
				       "text[ja] = 花瓶\n"),
			 OPTIONS_OK);
	assert_string_equal(caption_in(&o, "de"), "Vase (Leihgabe)");
	assert_string_equal(caption_in(&o, "ja"), "花瓶");
	/* fr has none: the first language's, the plain text. */
	assert_string_equal(caption_in(&o, "fr"), "Vase");
	assert_string_equal(caption_in(&o, "en"), "Vase");
	assert_string_equal(caption_in(&o, NULL), "Vase");
	options_release(&o);

	/* The first language named with its code stands in for the others. */
	assert_int_equal(read_text(&o, "[caption]\nlanguages = de en\ntext = plain\n"
				       "text[de] = Deutsch\n"),
			 OPTIONS_OK);
	assert_string_equal(caption_in(&o, "en"), "Deutsch");
	/* An empty text is a missing one. */
	options_release(&o);
	assert_int_equal(read_text(&o, "[caption]\nlanguages = en de\ntext = Vase\ntext[de] =\n"),
			 OPTIONS_OK);
	assert_string_equal(caption_in(&o, "de"), "Vase");
	options_release(&o);
}

static void stop_texts_by_place(void **state)
{
	struct options o;
	const char *t;
	char *s;

	(void)state;
	assert_int_equal(read_text(&o,
				   "[frame]\nstops = 0 0 1 \"Front\"; 90 0 1 \"Mark\"; 180 0 1\n"
				   "stops[de] = \"Die Front\"; ; \"Hinten\"\n"),
			 OPTIONS_OK);
	t = lang_text_get(&o.content.texts, "frame", "stops", "de", NULL);
	assert_non_null(t);
	s = lang_stop_text(t, 0);
	assert_string_equal(s, "Die Front");
	free(s);
	/* The second is left out: the stop's own text is shown. */
	assert_null(lang_stop_text(t, 1));
	s = lang_stop_text(t, 2);
	assert_string_equal(s, "Hinten");
	free(s);
	assert_null(lang_stop_text(t, 3));
	options_release(&o);
}

/* The later file wins, as for any key; a copy is a deep one, and a
 * change of a text alone is a change of [caption] (applied at once). */
static void copied_and_compared(void **state)
{
	struct options a, b;

	(void)state;
	assert_int_equal(read_text(&a, "[caption]\ntext[de] = eins\n"), OPTIONS_OK);
	assert_int_equal(options_copy(&b, &a), 0);
	assert_int_equal(options_changed(&a, &b), 0);
	assert_int_equal(lang_texts_set(&b.content.texts, "caption", "text", "de", "zwei"), 0);
	assert_string_equal(lang_text_get(&a.content.texts, "caption", "text", "de", NULL), "eins");
	assert_true(options_changed(&a, &b) & (1u << OPTIONS_CAPTION));
	options_release(&a);
	options_release(&b);
}

static void refused_with_line(void **state)
{
	struct options o;

	(void)state;
	/* A key a visitor never reads. */
	assert_int_equal(read_text(&o, "[scene]\nfit = 0.5\nmodel[de] = x.glb\n"), OPTIONS_CONFIG);
	options_release(&o);
	/* Not a language code. */
	assert_int_equal(read_text(&o, "[caption]\ntext[d] = x\n"), OPTIONS_CONFIG);
	options_release(&o);
	assert_int_equal(read_text(&o, "[caption]\ntext[de;rm] = x\n"), OPTIONS_CONFIG);
	options_release(&o);
	assert_int_equal(read_text(&o, "[caption]\nlanguages = en, deutsch\n"), OPTIONS_CONFIG);
	options_release(&o);
	assert_int_equal(read_text(&o, "[caption]\nlanguages = en de fr it es pt nl\n"),
			 OPTIONS_CONFIG);
	options_release(&o);
	assert_int_equal(read_text(&o, "[caption]\nlanguages = en, de pt-BR zh-Hant\n"),
			 OPTIONS_OK);
	options_release(&o);
}

/* A model's NAME.ini gives its own texts over the kiosk's. */
static void model_file(void **state)
{
	char dir[] = "/tmp/mk-lang-XXXXXX", path[128], model[128];
	struct options o;
	FILE *f;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/vase.ini", dir);
	snprintf(model, sizeof(model), "%s/vase.glb", dir);
	f = fopen(path, "w");
	assert_non_null(f);
	fputs("[caption]\ntext[de] = Vase des Modells\n", f);
	fclose(f);
	assert_int_equal(read_text(&o, "[caption]\ntext[de] = Kiosk\ntext[fr] = Kiosque\n"),
			 OPTIONS_OK);
	assert_int_equal(model_settings_read(&o.content, model), OPTIONS_OK);
	assert_string_equal(lang_text_get(&o.content.texts, "caption", "text", "de", NULL),
			    "Vase des Modells");
	assert_string_equal(lang_text_get(&o.content.texts, "caption", "text", "fr", NULL),
			    "Kiosque");
	options_release(&o);
	unlink(path);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(fallback_language),   cmocka_unit_test(stop_texts_by_place),
	    cmocka_unit_test(copied_and_compared), cmocka_unit_test(refused_with_line),
	    cmocka_unit_test(model_file),
	};

	log_set_level(LOG_ERR);
	return cmocka_run_group_tests(tests, NULL, NULL);
}
