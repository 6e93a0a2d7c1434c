#include "config/model_settings.h"
#include "util/log.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The keys a model's own file may hold; key NULL: the whole section. What
 * stays with the kiosk (the display, the devices, attract mode's timing)
 * is not here. Its matcaps and background are decoded with the model on
 * the worker where they differ from those on screen (content_look.c).
 * A section of another feature that is per model is one more line
 * ({"caption", NULL}), and the error messages list it too. */
static const struct {
	const char *section, *key;
} model_keys[] = {
    {"frame", NULL},	     {"material", NULL},	{"scene", "mode"},
    {"scene", "fit"},	     {"scene", "yaw"},		{"scene", "pitch"},
    {"scene", "base_color"}, {"scene", "model_scene"},	{"scene", "lod_pixels"},
    {"scene", "matcap"},     {"scene", "matcap_first"}, {"display", "background"},
    {"scene", "normals"},    {"caption", NULL},		{"scene", "variant"},
};

#define MODEL_KEYS (sizeof(model_keys) / sizeof(model_keys[0]))

/* "[frame], [material], [scene] mode, [scene] fit, ...": from the table. */
static void keys_text(char *buf, size_t n)
{
	size_t len = 0;

	buf[0] = '\0';
	for (size_t i = 0; i < MODEL_KEYS && len + 1 < n; i++)
		len += (size_t)snprintf(buf + len, n - len, "%s[%s]%s%s", i ? ", " : "",
					model_keys[i].section, model_keys[i].key ? " " : "",
					model_keys[i].key ? model_keys[i].key : "");
}

bool model_settings_allowed(const char *section, const char *key)
{
	for (size_t i = 0; i < MODEL_KEYS; i++)
		if (!strcmp(model_keys[i].section, section) &&
		    (!model_keys[i].key || !strcmp(model_keys[i].key, key)))
			return true;
	return false;
}

static bool ends_with(const char *s, size_t len, const char *tail)
{
	size_t n = strlen(tail);

	return len >= n && !strcasecmp(s + len - n, tail);
}

bool model_settings_path(const char *model, char *out, size_t n)
{
	size_t len = model ? strlen(model) : 0, stem;

	if (ends_with(model, len, ".glb"))
		stem = len - 4;
	else if (ends_with(model, len, ".gltf"))
		stem = len - 5;
	else
		return false;
	return (size_t)snprintf(out, n, "%.*s.ini", (int)stem, model) < n;
}

/* Each setting the model's file holds, with its line, on out: in effect,
 * or under the command line's value (--check-config -v). */
static void list_set(struct options *o, const char *path, const struct content_config *c, FILE *out)
{
	for (size_t i = 0; i < OPTION_DEFS; i++) {
		const struct option_def *d = &option_defs[i];
		struct options_origin at = options_origin(o, d);
		char value[256];

		if (!at.file || !at.line)
			continue;
		option_value_text(o, d, value, sizeof(value));
		if (content_config_from_cli(c, d))
			fprintf(out, "    [%s] %s = %s (the command line, over %s:%d)\n",
				options_sections[d->section].name, d->key, value, path, at.line);
		else
			fprintf(out, "    [%s] %s = %s (%s:%d)\n",
				options_sections[d->section].name, d->key, value, path, at.line);
	}
}

/* The file over c, then c's command-line settings over the file's: the
 * command line wins (README: options override the files). */
static enum options_status read_with(struct content_config *c, const char *model, bool stick,
				     FILE *out)
{
	char path[PATH_MAX], keys[400];
	struct options_rules rules = {model_settings_allowed, keys, "a model's own file", stick};
	enum options_status ret = OPTIONS_CONFIG;
	struct options o;

	if (!model_settings_path(model, path, sizeof(path)))
		return OPTIONS_OK;
	if (access(path, F_OK) && errno == ENOENT)
		return OPTIONS_OK;
	option_defaults(&o);
	if (content_config_copy(&o.content, c))
		goto out;
	keys_text(keys, sizeof(keys));
	ret = options_read_one(&o, path, &rules);
	if (ret == OPTIONS_OK && content_config_keep_cli(&o.content, c))
		ret = OPTIONS_CONFIG;
	if (ret == OPTIONS_OK) {
		if (out)
			list_set(&o, path, c, out);
		content_config_release(c);
		*c = o.content;
		memset(&o.content, 0, sizeof(o.content));
		log_debug("%s: the model's own settings", path);
	}
out:
	options_release(&o);
	return ret;
}

enum options_status model_settings_read(struct content_config *c, const char *model)
{
	return read_with(c, model, false, NULL);
}

enum options_status model_settings_read_stick(struct content_config *c, const char *model)
{
	return read_with(c, model, true, NULL);
}

enum options_status model_settings_read_listed(struct content_config *c, const char *model,
					       bool stick, FILE *out)
{
	return read_with(c, model, stick, out);
}
