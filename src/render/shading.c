#include "render/shading.h"

#include <errno.h>
#include <string.h>

static const char *const mode_names[SHADING_MODE_COUNT] = {"normal", "view", "sem-vertex",
							   "sem-fragment"};
static const char *const mode_defines[SHADING_MODE_COUNT] = {
    "#define MODE_NORMAL 1\n", "#define MODE_VIEW 1\n", "#define MODE_SEM_VERTEX 1\n",
    "#define MODE_SEM_FRAGMENT 1\n"};

const char *shading_mode_name(enum shading_mode mode)
{
	return mode < SHADING_MODE_COUNT ? mode_names[mode] : "?";
}

const char *shading_mode_define(enum shading_mode mode)
{
	return mode < SHADING_MODE_COUNT ? mode_defines[mode] : "";
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
