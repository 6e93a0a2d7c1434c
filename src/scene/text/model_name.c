/* [caption] text = auto: the generic names exporters write (every Blender
 * file's scene is "Scene") passed over for the file's own name. */
#include "scene/text/model_name.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Compared in any case, after a Blender-style ".001" and a ".fbx",
 * ".obj", ".blend" or ".dae" left by a conversion are taken off. */
static const char *const generic[] = {
    "scene",
    "root",
    "rootnode",
    "root node",
    "sketchfab_scene",
    "sketchfab_model",
    "gltf_scenerootnode",
    "auxscene",
    "world",
    "untitled",
    "default",
    "defaultscene",
    "scene root",
    "scene_root",
    "model",
    "mesh",
    "object",
    "node",
    "collada_visual_scene_group",
    "osg_root",
    "blender_default",
    "unnamed",
    NULL,
};

static const char *const conversions[] = {".fbx", ".obj", ".blend", ".dae", NULL};

/* len without a trailing ".digits" (Blender's duplicates). */
static size_t without_number(const char *s, size_t len)
{
	size_t i = len;

	while (i > 0 && isdigit((unsigned char)s[i - 1]))
		i--;
	return i < len && i > 0 && s[i - 1] == '.' ? i - 1 : len;
}

/* len without a conversion's extension. */
static size_t without_extension(const char *s, size_t len)
{
	for (int i = 0; conversions[i]; i++) {
		size_t n = strlen(conversions[i]);

		if (len > n && !strncasecmp(s + len - n, conversions[i], n))
			return len - n;
	}
	return len;
}

bool model_name_generic(const char *name)
{
	size_t len;

	while (name && isspace((unsigned char)*name))
		name++;
	if (!name || !*name)
		return true;
	len = strlen(name);
	while (len > 0 && isspace((unsigned char)name[len - 1]))
		len--;
	len = without_extension(name, without_number(name, len));
	for (int i = 0; generic[i]; i++)
		if (strlen(generic[i]) == len && !strncasecmp(name, generic[i], len))
			return true;
	return false;
}

char *model_name_from_file(const char *path)
{
	const char *base = path ? strrchr(path, '/') : NULL, *dot;
	size_t len;
	char *out, *o;

	base = base ? base + 1 : path;
	if (!base)
		return NULL;
	dot = strrchr(base, '.');
	len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
	out = o = malloc(len + 1);
	if (!out)
		return NULL;
	for (size_t i = 0; i < len; i++) {
		/* A hidden file's dot is no part of the name either. */
		char c = base[i] == '_' || base[i] == '-' || (base[i] == '.' && !i) ? ' ' : base[i];

		if (c == ' ' && (o == out || o[-1] == ' '))
			continue; /* no blank first, none twice */
		*o++ = c;
	}
	while (o > out && o[-1] == ' ')
		o--;
	*o = '\0';
	if (!*out) {
		free(out);
		return NULL;
	}
	out[0] = (char)toupper((unsigned char)out[0]);
	return out;
}
