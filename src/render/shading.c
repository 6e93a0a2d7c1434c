#include "render/shading.h"

#include <errno.h>
#include <string.h>

static const char *const mode_names[SHADING_MODE_COUNT] = {"normal", "view", "sem-vertex",
							   "sem-fragment"};
static const char *const mode_macros[SHADING_MODE_COUNT] = {"MODE_NORMAL", "MODE_VIEW",
							    "MODE_SEM_VERTEX", "MODE_SEM_FRAGMENT"};

const char *shading_mode_name(enum shading_mode mode)
{
	return mode < SHADING_MODE_COUNT ? mode_names[mode] : "?";
}

const char *shading_mode_macro(enum shading_mode mode)
{
	return mode < SHADING_MODE_COUNT ? mode_macros[mode] : "MODE_UNKNOWN";
}

int shading_mode_parse(const char *name, enum shading_mode *out)
{
	for (int i = 0; i < SHADING_MODE_COUNT; i++)
		if (strcmp(name, mode_names[i]) == 0) {
			*out = (enum shading_mode)i;
			return 0;
		}
	return -EINVAL;
}
