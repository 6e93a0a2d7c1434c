/* [caption] text = auto (issue 33, point 7): the names exporters give
 * every file passed over ("Scene": every Blender file, and most of
 * Khronos' samples, showed "Scene"), and the file's name made readable. */
#include "scene/text/model_name.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <cmocka.h>

static void generic_names(void **state)
{
	static const char *const generic[] = {
	    "Scene",
	    "scene",
	    "SCENE",
	    "Scene.001",
	    "Scene.12",
	    "Root",
	    "RootNode",
	    "rootnode",
	    "Sketchfab_Scene",
	    "Sketchfab_model",
	    "RootNode.fbx",
	    "GLTF_SceneRootNode",
	    "AuxScene",
	    "Root Node",
	    "Untitled",
	    "World",
	    "Model",
	    "Scene.obj",
	    " Scene ",
	    "",
	    "   ",
	    "defaultScene",
	    "OSG_Root",
	    "Collada_visual_scene_group",
	};
	static const char *const own[] = {
	    "Amphora", "Old radio", "Scene of the crime", "Rooted", "Sketchfab", "Pan Am 747",
	    "Scene.",  "Scene.1a",  "Vase.fbx",		  "Modell", "Weltkugel", "\xe5\xa3\xba",
	};

	(void)state;
	for (size_t i = 0; i < sizeof(generic) / sizeof(generic[0]); i++)
		if (!model_name_generic(generic[i]))
			fail_msg("'%s' is an exporter's name, not the model's", generic[i]);
	for (size_t i = 0; i < sizeof(own) / sizeof(own[0]); i++)
		if (model_name_generic(own[i]))
			fail_msg("'%s' is the model's own name", own[i]);
	assert_true(model_name_generic(NULL));
}

static void file_names(void **state)
{
	static const char *const cases[][2] = {
	    {"old_radio-v2.glb", "Old radio v2"},
	    {"/srv/models/old_radio-v2.glb", "Old radio v2"},
	    {"vase.gltf", "Vase"},
	    {"__a--b__.glb", "A b"},
	    {"NASA_rover.glb", "NASA rover"},
	    {"amphore-\xc3\xa9t\xc3\xa9.glb", "Amphore \xc3\xa9t\xc3\xa9"},
	    {"noext", "Noext"},
	    {".hidden", "Hidden"},
	};
	char *got;

	(void)state;
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		got = model_name_from_file(cases[i][0]);
		assert_non_null(got);
		assert_string_equal(got, cases[i][1]);
		free(got);
	}
	assert_null(model_name_from_file("/m/_-_.glb"));
	assert_null(model_name_from_file(NULL));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(generic_names),
	    cmocka_unit_test(file_names),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
